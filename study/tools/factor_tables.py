"""The factor tables of the answer page (study/VALIDATION.md): the protocol block, the preset's
differences from the paper's stated protocol one at a time by the paper's clock (issue 51), and the
coupling screen, the intruder's coupling to its grains as the paper's LAMMPS body had it (issue 79);
each change in standard errors of the shape's sigma by the paper's clock, and which way it moves
the cell against the paper's side there. The changes here are what the answer's sentences
(answer_sentences.py) say of them.
"""
import math
from typing import NamedTuple
from dataclasses import dataclass

import findings
from cases import (COUPLING, PAPER_BOX, PAPER_RANGE, SHAPES, SO_FAR_FROM, T1000_BEDS, T1000_WINDOWS, WINDOW_FROM, beds,
                   cases_of, cell_text, chord, committed, head_lines, key_of, paper_observed, row_line, select, so_far,
                   unfinished)
from findings import RESOLVED
from scatter import LOCKED_BODY, PAPER_SIDE, SHAPE_NAMES, beds_z_text, clock_sigma, scatter_words
from table1_blocks import against_paper, bracket_text
from table_kinds import windows

# The paper's own protocol (issue 51): the preset's differences from the paper's stated protocol,
# one at a time at t = 1000, for the two cells that disagree most with the paper (the square at T = 3
# rises where the paper's Table 1 has it not rising yet; the triangle at T = 5 sinks where the paper's
# rises), then all of them together in the preset's 60 d box and in the paper's own 300 d box.
PROTOCOL_FOLDERS = ["results/paper_depth/mass_t1000", "results/paper_depth/factors_t1000"] + PAPER_BOX
PRESET_PROTOCOL = {"intruder.surface": "smooth", "bed.pour": "lattice", "intruder.mass_rule": "disk_area"}
PAPER_PROTOCOL = {"intruder.surface": "glued", "bed.pour": "random", "intruder.mass_rule": "glued_disk"}
# (what changes from the preset, in the table and in a sentence; its cases: folders and the keys that
# differ; paired: run on the baseline's own beds, so compared with the baseline's runs of the same seeds only)
PROTOCOL_ROWS = [
    ("none: the preset (baseline)", "the preset", T1000_BEDS, {}, False),
    ("the glued disk's mass, 9.88 (on the baseline's own bed)", "the glued disk's mass (9.88 against 25.66, same bed)",
     ["results/paper_depth/mass_t1000"], {"intruder.mass_rule": "glued_disk"}, True),
    ("the glued 0.5 d surface (new pour)", "the glued 0.5 d surface", ["results/paper_depth/factors_t1000"],
     {"intruder.surface": "glued"}, False),
    ("the random pour (new pour)", "the random pour", ["results/paper_depth/factors_t1000"], {"bed.pour": "random"}, False),
    ("all three: the paper's protocol in the 60 d box", "the paper's protocol in the 60 d box",
     ["results/paper_depth/factors_t1000"], PAPER_PROTOCOL, False),
    ("the paper's protocol in its own 300 d box", "the paper's protocol in its own 300 d box", PAPER_BOX,
     PAPER_PROTOCOL, False),
]
# shape, T, the paper's sign of V_y there
PROTOCOL_CELLS = [(shape, t, findings.paper_side(t, PAPER_RANGE[shape])) for shape, t in [("square", 3.0), ("triangle", 5.0)]]
# The box's width alone: the last row (the paper's protocol in its 300 d box) against the row before
# it (the same protocol in the 60 d box), said beside the last row's change from the preset.
BOX_ROW, BOX_AGAINST = len(PROTOCOL_ROWS) - 1, len(PROTOCOL_ROWS) - 2
BOX_ALONE = "the 300 d box alone (against the paper's protocol in the 60 d box)"
PROTOCOL_CELL_KEYS = [(shape, period) for shape, period, _ in PROTOCOL_CELLS]


def protocol_beds(folders, where):
    """{seed: V_y} of a protocol row's cell (only the folders committed so far)."""
    present = committed(folders)
    return {c.get("box.seed"): float(c.get("vy")) for c in beds(select(present, where), f"{present} {where}")}


def protocol_cell(shape, period):
    """The keys of one of PROTOCOL_CELLS' cases (A = 5)."""
    return {"intruder.shape": shape, "drive.amplitude": 5.0, "drive.period": period}


def row_where(row, shape, period):
    """The keys of a case of PROTOCOL_ROWS[row] in the cell (shape, T)."""
    return dict(PRESET_PROTOCOL, **PROTOCOL_ROWS[row][3], **protocol_cell(shape, period))


def protocol_so_far_cell(row, shape, period):
    """A cell of PROTOCOL_ROWS[row] not finished yet whose case is on its way: its rate so far, by the
    paper's rule over t = 100 to its last committed sample, beside the baseline's over the same window
    (and, in the 300 d box's row, the 60 d box's: BOX_ALONE); "" when none."""
    compared = [(0, "the baseline")] + ([(BOX_AGAINST, "the 60 d box's")] if row == BOX_ROW else [])
    on_way = [c for f in committed(PROTOCOL_ROWS[row][2]) for c in unfinished(f)
              if all(c.get(k) == v for k, v in row_where(row, shape, period).items())]
    parts = []
    for c in on_way:
        t_now, rate = so_far(c)
        if rate is None:
            continue
        window = chord(WINDOW_FROM, t_now)
        beside = []
        for i, name in compared:
            keys = row_where(i, shape, period)
            done = beds(select(committed(PROTOCOL_ROWS[i][2]), keys), f"{name} {keys}")
            if done:
                beside.append(f"{name} {cell_text([window(b) for b in done])}")
        parts.append(f"not finished, t = {t_now:g} of 1000 so far: over t = 100-{t_now:g} {cell_text([rate])}, "
                     + ", ".join(beside))
    return "; ".join(parts)


# Which way a change moves a cell, by the side of zero of its standard errors the paper's way
TOWARD = {+1: "toward the paper", -1: "away from the paper", 0: "within the scatter"}


def protocol_change(row, shape, period, paper_sign, sig, against=0):
    """One cell of PROTOCOL_ROWS[row]: (its V_y values, or [] when none is committed; the change from
    row `against` (the baseline unless said), its size in standard errors and which way it moves the
    cell), the change None for the compared row itself or while that row has no values."""
    def row_beds(i):
        return protocol_beds(PROTOCOL_ROWS[i][2], row_where(i, shape, period))
    beds_of_row = row_beds(row)
    values = list(beds_of_row.values())
    if not values or row == against:
        return values, None
    compared = row_beds(against)
    paired = PROTOCOL_ROWS[row][4]
    base = [v for seed, v in compared.items() if seed in beds_of_row] if paired else list(compared.values())
    if not base:
        return values, None
    return values, judged_change(findings.Comparison(shape, values, base, paper_sign), sig)


def judged_change(comparison, sig):
    """(the change, its size in standard errors, which way it moves the cell, the caveat or "") of a
    protocol row's comparison with the row it is compared with: the caveat of its own beds' scatter,
    else of its shape's paired runs' (own_scatter_caveat, straying_caveat)."""
    diff, z, _ = findings.judged(comparison, sig)
    caveat = own_scatter_caveat(comparison, z, sig) or straying_caveat(comparison, z, sig)
    return diff, abs(z), toward_words(z, caveat), caveat


def toward_words(z, caveat=""):
    """Which way a change of z standard errors (the paper's way) moves its cell; within the scatter,
    whatever z, where a caveat says its own beds do not resolve it."""
    return TOWARD[0 if caveat else findings.resolved_side(z)]


def own_scatter_caveat(comparison, z, sig):
    """The words that say a change resolved on the scale's sigma is not resolved by its own beds'
    larger scatter (findings.own_scatter_judged), else ""."""
    doubt = findings.own_scatter_judged(comparison, z, sig)
    if doubt is None:
        return ""
    side, n, own, z_own = doubt
    whose = {"a": "its", "b": "the compared row's"}[side]
    return (f"{abs(z_own):.1f} se by {whose} {n} beds' own scatter, one bed's standard deviation {own:.4f} "
            f"against sigma {sig:.4f}")


def paired_runs_z(comparison):
    """(the comparison's standard errors by one run's standard deviation as its shape's paired runs show it
    (the paired changes' over sqrt 2), that deviation, its degrees of freedom) where those runs stray more
    than the shape's sigma allows (straying); None where they do not."""
    found = straying([comparison.label])
    if not found:
        return None
    _, paired_sd, dof, _ = found[0]
    run_sd = paired_sd / math.sqrt(2.0)
    return findings.judged(comparison, run_sd)[1], run_sd, dof


def by_runs_words(comparison):
    """', N se by the scatter the shape's paired runs show' of a change, where the shape's paired runs stray
    more than its sigma allows (paired_runs_z); "" where they do not."""
    by_runs = paired_runs_z(comparison)
    return f", {abs(by_runs[0]):.1f} se by the scatter the {comparison.label}'s paired runs show" if by_runs else ""


def straying_caveat(comparison, z, sig):
    """The words that say a change resolved on sig is not resolved by the larger scatter its shape's paired
    runs show (paired_runs_z), else "". As with its own beds' scatter, a change is never shown as better
    known than its shape's runs show."""
    by_runs = paired_runs_z(comparison)
    if findings.resolved_side(z) == 0 or by_runs is None:
        return ""
    z_run, run_sd, dof = by_runs
    if findings.resolved_side(z_run) != 0:
        return ""
    return (f"{abs(z_run):.1f} se by the scatter the {comparison.label}'s paired runs show, one run's standard "
            f"deviation {run_sd:.4f} ({dof} dof) against sigma {sig:.4f}")


def protocol_row(case):
    """(shape, T, the index of its PROTOCOL_ROWS row) of a case of one of the protocol block's cells,
    None for any other case of its folders."""
    cell = (case.get("intruder.shape"), case.get("drive.period"))
    if cell not in PROTOCOL_CELL_KEYS:
        return None
    for i, (_, _, folders, keys, _) in enumerate(PROTOCOL_ROWS):
        if case.source in folders and all(case.get(k) == v for k, v in dict(PRESET_PROTOCOL, **keys).items()):
            return cell + (i,)
    return None


def box_alone_change(shape, period, paper_sign, sig):
    """BOX_ALONE's change in one cell, as protocol_change gives it; None while either row has no value."""
    return protocol_change(BOX_ROW, shape, period, paper_sign, sig, against=BOX_AGAINST)[1]


def change_text(change):
    diff, z, toward, caveat = change
    return f"{diff:+.4f} ({z:.1f} se, {toward}" + (f": {caveat}" if caveat else "") + ")"


def protocol_cells_text():
    """'the square not rising at T = 3 (the lower end of its 3-4) and ...': what the paper's Table 1 says
    at the protocol block's cells."""
    return " and ".join(f"the {shape} {PAPER_SIDE[sign]} at T = {period:g} ({range_end(period, PAPER_RANGE[shape])} "
                        f"its {paper_observed(shape)})" for shape, period, sign in PROTOCOL_CELLS)


def range_end(period, paper_range):
    """Where a period stands in the paper's range (lo, hi): 'the lower end of', 'the upper end of', 'beside'."""
    lo, hi = paper_range
    return "the lower end of" if period == lo else "the upper end of" if period == hi else "beside"


def answer_protocol(spec):
    """The factor table: each row's V_y per cell, its change from the baseline in standard errors of
    the paper's clock (one bed's sigma of that shape there), and whether it moves the cell toward the
    paper's side."""
    lines = head_lines(["what changes"] + [f"{s}, A = 5, T = {t:g}: V_y; change (se)" for s, t, _ in PROTOCOL_CELLS])
    for row, (label, *_) in enumerate(PROTOCOL_ROWS):
        cells = []
        for shape, period, paper_sign in PROTOCOL_CELLS:
            sig = clock_sigma(shape)
            values, change = protocol_change(row, shape, period, paper_sign, sig)
            box = box_alone_change(shape, period, paper_sign, sig) if row == BOX_ROW else None
            if not values:
                cells.append(protocol_so_far_cell(row, shape, period) or "not run yet")
            elif change is None:
                cells.append(cell_text(values))
            else:
                cells.append(f"{cell_text(values)}; {change_text(change)}"
                             + (f"; the box alone: {change_text(box)}" if box else ""))
        lines.append(row_line([label] + cells))
    few = findings.OWN_SCATTER_BEDS - 1
    few_beds = f"2 to {few} beds" if few > 2 else "2 beds"
    shapes = list(dict.fromkeys(s for s, _, _ in PROTOCOL_CELLS))
    lines += ["", f"(V_y over t = 100-1000 of runs to t = 1000, A = 5 d. The paper's Table 1 has {protocol_cells_text()}. "
              f"A change is the row's mean minus the baseline's, in standard errors se = sigma sqrt(1/n_row + 1/n_baseline), "
              "sigma " + scatter_words(shapes) + ". The mass's change is against the baseline's run on the same bed, "
              "with the same sigma (the coupling screen's paired changes, below, measure how far such a pair "
              "strays); the 300 d box's sigma is taken as the 60 d box's (one bed per cell there, so not measured); the box alone is the "
              "300 d box's row against the 60 d box's row of the same protocol; a change moves the "
              f"cell toward the paper's side when >= {RESOLVED:g} se that way, also by the own standard deviation of "
              f"a side of {few_beds} where that is larger than sigma (from "
              f"{findings.OWN_SCATTER_BEDS} beds on, a side's own scatter counts in its se as everywhere on this page), "
              "and by one run's standard deviation of its shape where the coupling screen's paired changes show it "
              "larger than sigma (their standard deviation over sqrt 2). "
              f"A case not finished yet is shown by the paper's rule over t = 100 to its last committed sample, beside "
              f"the baseline's over the same window (and the 60 d box's, in the 300 d box's row), once that window spans "
              f"{SO_FAR_FROM:g}: a rate so far, not judged)"]
    return lines, committed(PROTOCOL_FOLDERS + T1000_BEDS)


# ---- the coupling screen

# The coupling screen (issue 79): each factor on the factor screen's beds of the paper's protocol in the
# 60 d box, paired bed by bed with that protocol's own run there (its `*_paper` cases; the square at
# T = 4, the control, and the triangle at T = 4, the lattice body's other side of the paper's bracket,
# have their baselines in COUPLING; the triangle at T = 3, where the lattice body's bracket lies if it
# rises at T = 4 too, has none).
COUPLING_CELLS = [("square", 3.0), ("triangle", 5.0), ("square", 4.0), ("triangle", 4.0), ("triangle", 3.0)]
COUPLING_BASE = dict(PAPER_PROTOCOL, **LOCKED_BODY)
COUPLING_ROWS = [('the atoms\' mass in the contacts (intruder.contact_mass = "atom")', {"intruder.contact_mass": "atom"}),
                 ('the lattice body (intruder.surface = "lattice", on the same bed)', {"intruder.surface": "lattice"}),
                 ('turning (intruder.rotation = "free")', {"intruder.rotation": "free"}),
                 ('the drive read as a velocity (drive.form = "velocity")', {"drive.form": "velocity"})]


COUPLING_SOURCES = COUPLING + ["results/paper_depth/factors_t1000"]   # the screen's cases and its baselines'
# The two cells the paper's protocol leaves on the other side from the paper, which every row is run on.
DISPUTED_CELLS = COUPLING_CELLS[:2]


def coupling_where(shape, changes):
    """The keys of the coupling screen's cases of `shape` with `changes` from the paper's protocol, at any period."""
    return dict(COUPLING_BASE, **changes, **{"intruder.shape": shape, "drive.amplitude": 5.0, "box.width": 60.0})


def coupling_cases(shape, period, changes):
    """{seed: case} of the coupling screen's cell with `changes` from the paper's protocol (none: its baseline)."""
    where = dict(coupling_where(shape, changes), **{"drive.period": period})
    present = committed(COUPLING_SOURCES)
    return {c.get("box.seed"): c for c in beds(select(present, where), f"{present} {where}")}


def coupling_beds(shape, period, changes):
    """{seed: V_y} of the coupling screen's cell with `changes` from the paper's protocol (none: its baseline)."""
    return {seed: float(c.get("vy")) for seed, c in coupling_cases(shape, period, changes).items()}


def shared_beds(shape, period, changes):
    """The seeds on which a coupling row's case ran on its baseline's very bed (the same bed key): the beds
    its change pairs over."""
    cases, base = coupling_cases(shape, period, changes), coupling_cases(shape, period, {})
    return sorted(seed for seed in set(cases) & set(base) if cases[seed].bed_key() == base[seed].bed_key())


def poured_around(shape, period, changes):
    """The beds (seeds) of a coupling row's cell poured around the changed body itself, rather than a baseline's
    bed (at any period) with that body swapped in: no baseline ran on them, so they pair with none."""
    baseline_beds = {c.bed_key() for c in select(committed(COUPLING_SOURCES), coupling_where(shape, {}))}
    return {seed for seed, c in coupling_cases(shape, period, changes).items() if c.bed_key() not in baseline_beds}


def coupling_periods(shape, changes):
    """[(T, [V_y per bed])] of a coupling row's cases of `shape` at every period the screen has run it, in
    ascending T (on the factor screen's beds, or on a bed poured around the changed body)."""
    ran = sorted({c.get("drive.period") for c in select(committed(COUPLING_SOURCES), coupling_where(shape, changes))})
    return [(period, list(coupling_beds(shape, period, changes).values())) for period in ran]


def coupling_paired(shape, period, changes):
    """([V_y with `changes`], [the baseline's V_y]) over the beds both ran on (shared_beds), in bed order."""
    values, base = coupling_beds(shape, period, changes), coupling_beds(shape, period, {})
    paired = shared_beds(shape, period, changes)
    return [values[b] for b in paired], [base[b] for b in paired]


class CouplingChange(NamedTuple):
    """A coupling row's change in one cell, over the beds it shares with the baseline."""
    diff: float      # the row's mean minus the baseline's
    z: float         # in standard errors of the shape's sigma
    toward: str      # which way it moves the cell (toward_words')
    name: str        # the factor's short name
    cell: str        # "the square at T = 3"
    paired: int      # how many beds are paired
    by_runs: str = ""   # by_runs_words' of the change, where the shape's paired runs stray


def coupling_change(shape, period, changes):
    """CouplingChange of a coupling row in one cell; None while it shares no bed with the baseline."""
    values, base = coupling_paired(shape, period, changes)
    if not values:
        return None
    paper_sign = findings.paper_side(period, PAPER_RANGE[shape])
    comparison = findings.Comparison(shape, values, base, paper_sign)
    sig = clock_sigma(shape)
    diff, z, _ = findings.judged(comparison, sig)
    # paired bed by bed, the sides' own beds' scatter is no yardstick (answer_coupling's note); the scatter the
    # shape's paired changes show is, as for the protocol block's changes
    toward = toward_words(z, straying_caveat(comparison, z, sig))
    name = next(label.split(" (")[0] for label, c in COUPLING_ROWS if c == changes)
    return CouplingChange(diff, z, toward, name, f"the {shape} at T = {period:g}", len(values),
                          by_runs_words(comparison))


def disputed_cases_waiting():
    """The names of the coupling screen's cases at a disputed cell that have not finished (in its results.csv,
    pending, running or carried part-way)."""
    return [c.row["case"] for source in committed(COUPLING) for c in cases_of(source, finished=False)
            if (c.get("intruder.shape"), c.get("drive.period")) in DISPUTED_CELLS]


def coupling_screen_run():
    """Whether every coupling row has its change measured at both disputed cells and no case there is still to
    finish: the screen is run, not being run (its other cells follow the rows that move a disputed cell)."""
    measured = all(coupling_change(shape, period, changes)
                   for _, changes in COUPLING_ROWS for shape, period in DISPUTED_CELLS)
    return measured and not disputed_cases_waiting()


def paired_changes(shape):
    """{(the factor's short name, the cell): [its change on each paired bed]} of `shape`'s coupling changes."""
    return {(label.split(" (")[0], f"the {shape} at T = {period:g}"):
            [a - b for a, b in zip(*coupling_paired(shape, period, changes))]
            for s, period in COUPLING_CELLS if s == shape for label, changes in COUPLING_ROWS}


def paired_scatter(shape):
    """(one bed's standard deviation of a paired change, its degrees of freedom) of `shape`, pooled over the
    coupling screen's changes measured on two beds or more: how far one bed's change strays from the
    cell's mean change. dof 0 while no change has two beds."""
    sigma, dof, _ = findings.pooled_sd(list(paired_changes(shape).values()))
    return sigma, dof


def largest_share(shape):
    """(the factor's short name, the cell, its share) of the change whose beds' spread makes the largest share
    of `shape`'s pooled paired scatter (its sum of squares); None while no change has two beds."""
    squares = {key: sum((x - findings.mean(d)) ** 2 for x in d)
               for key, d in paired_changes(shape).items() if len(d) >= 2}
    total = sum(squares.values())
    if not total:
        return None
    (name, cell), most = max(squares.items(), key=lambda item: item[1])
    return name, cell, most / total


def most_of_it(shape):
    """', N % of it from <factor> at <cell>' where one change's two beds make most of a shape's paired scatter
    (its sum of squares), "" where none does: one pair that splits is not a scatter every change shares."""
    largest = largest_share(shape)
    if largest is None or largest[2] <= 0.5:
        return ""
    name, cell, share = largest
    return f", {share:.0%} of it from {name} at {cell}"


def rule_change_sd(shape):
    """One bed's standard deviation of a change between two runs as the rule has it: sigma sqrt 2, sigma the
    shape's (the two runs independent)."""
    return clock_sigma(shape) * math.sqrt(2.0)


def straying(shapes):
    """[(shape, its paired changes' own scatter, dof, the rule's sigma sqrt 2)] of the shapes whose paired
    changes stray more than the rule allows: there the counts of standard errors overstate a change."""
    return [(shape, sd, dof, rule_change_sd(shape)) for shape in shapes
            for sd, dof in [paired_scatter(shape)] if dof and sd > rule_change_sd(shape)]


def paired_scatter_words(shapes):
    """The measured scatter of the paired changes, shape by shape, beside the rule's sigma (no claim which is
    smaller: a few pairs tell little, and a change of the body on the same bed may stray as far as another bed),
    and where it is the larger, that the rule's standard errors understate it."""
    measured = [(shape, *paired_scatter(shape)) for shape in shapes]
    each = ", ".join(f"{shape} {sigma:.4f} ({dof} dof{most_of_it(shape)})" if dof else f"{shape} not measured yet"
                     for shape, sigma, dof in measured)
    larger = "; ".join(f"the {shape}'s is {sd / rule:.1f} x the rule's sigma sqrt 2 ({rule:.4f}): its changes' counts "
                       "of standard errors overstate them by as much" for shape, sd, _, rule in straying(shapes))
    return ("A change's own scatter, paired bed by bed: one bed's standard deviation of a change, pooled over this "
            f"table's changes of two beds or more, {each}; the rule takes the shape's sigma"
            + (f"; {larger}" if larger else ""))


# Where a coupling factor moves a 60 d cell toward the paper, it is run in the paper's own box
# (issue 79, item 5; study/sweeps/paper_box_lattice_t1000.toml), each case on paper_box_t1000's bed of
# its shape.
PAPER_BOX_COUPLING = ["results/paper_box/lattice_t1000"]


@dataclass
class PaperBoxReading:
    """A coupling row's case in the paper's own box beside the paper's protocol on the same bed (one bed
    each), the shape at the period, V_y by the paper's rule over the same window: t = 100-1000 once it
    has finished (t_now None), else t = 100 to its last committed sample, t_now, of its duration (vy and
    base None while that spans < SO_FAR_FROM)."""
    shape: str
    period: float
    vy: float | None
    base: float | None
    t_now: float | None = None
    duration: float | None = None


def paper_box_coupling(shape, period, changes):
    """PaperBoxReading of a coupling row's case in the paper's own box; None while none is committed."""
    where = dict(COUPLING_BASE, **{"intruder.shape": shape, "drive.period": period, "drive.amplitude": 5.0,
                                   "box.width": 300.0})
    changed, base = protocol_beds(PAPER_BOX_COUPLING, dict(where, **changes)), protocol_beds(PAPER_BOX, where)
    paired = sorted(set(changed) & set(base))
    if paired:
        return PaperBoxReading(shape, period, changed[paired[0]], base[paired[0]])
    on_way = [c for f in committed(PAPER_BOX_COUPLING) for c in unfinished(f)
              if all(key_of(c, k) == v for k, v in dict(where, **changes).items())]
    if not on_way:
        return None
    case = on_way[0]
    t_now, rate = so_far(case)
    duration = float(case.get("run.duration"))
    baseline = [b for b in select(committed(PAPER_BOX), where) if b.get("box.seed") == case.get("box.seed")]
    if rate is None or not baseline:
        return PaperBoxReading(shape, period, None, None, t_now, duration)
    return PaperBoxReading(shape, period, rate, chord(WINDOW_FROM, t_now)(baseline[0]), t_now, duration)


def paper_box_change(reading):
    """(change, z, which way) of a finished PaperBoxReading against the protocol's run on the same bed, in
    standard errors of its shape's sigma (one bed each side), judged as the screen's changes are."""
    paper_sign = findings.paper_side(reading.period, PAPER_RANGE[reading.shape])
    comparison = findings.Comparison(reading.shape, [reading.vy], [reading.base], paper_sign)
    diff, z, _ = findings.judged(comparison, clock_sigma(reading.shape))
    return diff, z, toward_words(z)


TURNING = {"intruder.rotation": "free"}
# After how many degrees of turning each outline (docs/SHAPES.md) is the same again.
REPEATS_EVERY = {"square": 90, "rect_narrow": 180, "rect_wide": 180, "triangle": 120}


def turning_extent(case):
    """(the largest |angle| over the paper's window, the angle at the end), in degrees turned since t = 0,
    of a turning intruder's case."""
    ts, angles = case.turn()
    window = [a for t, a in zip(ts, angles) if t >= WINDOW_FROM - 1e-9]
    return math.degrees(max(abs(a) for a in window)), math.degrees(angles[-1])


# How each outline stands half a repeat from its start (docs/SHAPES.md's orientations): the other way it can
# meet the grains.
HALF_TURNED = {"square": "on a corner", "rect_narrow": "lying on its long side",
               "rect_wide": "standing on its short side", "triangle": "apex down"}


def half_turned(angle, shape):
    """Whether an angle (radians turned since the start) stands the outline half-turned: within a quarter
    repeat of half a repeat from its start (HALF_TURNED)."""
    repeat = REPEATS_EVERY[shape]
    return repeat / 4 < math.degrees(angle) % repeat < 3 * repeat / 4


def first_half_turned(case, shape, period):
    """When a turning intruder's case first stood half-turned for a whole drive period on end (from t = 0), or
    None: a turn it holds, not a rock within one swing of the drive. Each sample interval counts where it
    began, as in orientation_rates."""
    ts, angles = case.turn()
    since = None
    for i in range(len(ts) - 1):
        if not half_turned(angles[i], shape):
            since = None
            continue
        since = ts[i] if since is None else since
        if ts[i + 1] - since >= period - 1e-9:
            return since
    return None


def orientation_rates(case, shape):
    """[(time, rate of rise)] over the paper's window of a turning intruder's case, split by how it stood:
    half-turned (within a quarter repeat of half a repeat from its start: HALF_TURNED), then as it started
    (within a quarter repeat of its start); rate None for no time. Each sample interval counts where it began."""
    ts, angles = case.turn()
    ys = case.trajectory()[1]
    split = [[0.0, 0.0], [0.0, 0.0]]
    for i in range(len(ts) - 1):
        if ts[i] < WINDOW_FROM - 1e-9:
            continue
        part = split[0 if half_turned(angles[i], shape) else 1]
        part[0] += ts[i + 1] - ts[i]
        part[1] += ys[i + 1] - ys[i]
    return [(time, rise / time if time else None) for time, rise in split]


# A rate of rise is read over RATE_PERIODS drive periods at least: over fewer, a period's own up and down
# moves it more than the rise it measures.
RATE_PERIODS = 10


def orientation_words(case, shape, period):
    """How a turning case's rise split by how it stood, in words: 'apex down for 333 of the window's 900 (first
    for a whole period from t = 200), at +0.353; as started at -0.016' (a rate only over RATE_PERIODS drive periods or more)."""
    (half, rate_half), (started, rate_started) = orientation_rates(case, shape)
    shortest = RATE_PERIODS * period
    words = f"{HALF_TURNED[shape]} for {half:.0f} of the window's {half + started:.0f}"
    first = first_half_turned(case, shape, period)
    if first is not None:
        words += f" (first for a whole period from t = {first:.0f})"
    if half >= shortest:
        words += f", at {rate_half:+.3f}"
    return words + (f"; as started at {rate_started:+.3f}" if started >= shortest else "")


def turning_words():
    """How far the screen's turning bodies turned, cell by cell and bed by bed; "" while none has finished."""
    cells, shapes = [], []
    for shape, period in COUPLING_CELLS:
        cases = beds(select(committed(COUPLING), dict(coupling_where(shape, TURNING), **{"drive.period": period})),
                     f"turning {shape} T = {period:g}")
        each = ", ".join(f"{most:.1f} (bed {c.get('box.seed'):g}, {end:+.1f} at the end"
                         + (f"; {orientation_words(c, shape, period)})" if shape in REPEATS_EVERY else ")")
                         for c in cases for most, end in [turning_extent(c)])
        if each:
            cells.append(f"the {shape} at T = {period:g} {each}")
            shapes.append(shape)
    if not cells:
        return ""
    repeats = ", ".join(f"the {shape}'s every {REPEATS_EVERY[shape]}" for shape in dict.fromkeys(shapes)
                        if shape in REPEATS_EVERY)
    return ("How far the turning bodies turned: the largest angle over t = 100-1000, in degrees turned since t = 0 "
            "(trajectory.csv's angle, counter-clockwise positive" + (f"; the outline repeats itself, {repeats}" if repeats
                                                                    else "") + "), with the time it stood half-turned "
            "(within a quarter repeat of half a repeat from its start) and its rate of rise then and the rest of the "
            "time: " + "; ".join(cells))


def answer_coupling(spec):
    """The coupling screen: each factor's V_y per bed and its change from the paper's protocol on the
    same beds, in standard errors of the shape's sigma by the paper's clock, and which way it moves the
    cell against the paper's side there."""
    lines = head_lines(["what changes"] + [f"{s}, A = 5, T = {t:g}: V_y; change (se)" for s, t in COUPLING_CELLS])
    rows = [("none: the paper's protocol in the 60 d box (baseline)", {})] + COUPLING_ROWS
    for label, changes in rows:
        cells = []
        for shape, period in COUPLING_CELLS:
            values = coupling_beds(shape, period, changes)
            if not values:
                cells.append("not run")
                continue
            own = poured_around(shape, period, changes) if changes else set()
            each = ", ".join(f"{v:+.4f} (bed {seed:g}{', poured around it' if seed in own else ''})"
                             for seed, v in sorted(values.items()))
            change = coupling_change(shape, period, changes) if changes else None
            if not change:
                cells.append(each)
                continue
            cells.append(f"{each}; {change.diff:+.4f} ({abs(change.z):.1f} se{change.by_runs}, {change.toward}; "
                         f"{change.paired} bed{'s' if change.paired > 1 else ''} paired)")
        lines.append(row_line([label] + cells))
    shapes = list(dict.fromkeys(s for s, _ in COUPLING_CELLS))
    lines += ["", "(V_y over t = 100-1000 of runs to t = 1000, A = 5 d, on the factor screen's beds of the paper's "
              "protocol in the 60 d box (random pour, glued 0.5 d shell, the glued disk's mass 9.88; bed = box.seed); "
              "study/sweeps/paper_depth_coupling_t1000.toml. The paper's side: not rising at T = 3 for the square "
              "(the lower end of its 3-4), rising at T = 4; rising at T = 5 for the triangle (the upper end of its 4-5), "
              "not rising at T = 3-4. "
              "A change is the row's mean minus the baseline's over the beds both have, in standard errors se = sigma "
              "sqrt(1/n + 1/n), sigma " + scatter_words(shapes) + f" (from {findings.OWN_SCATTER_BEDS} beds on, a side's own "
              "standard deviation takes sigma's place in its se where larger, as everywhere on this page). "
              + paired_scatter_words(shapes) + ". A change "
              f"moves the cell toward the paper's side when >= {RESOLVED:g} se that way, also by one run's standard deviation "
              "of its shape where the paired changes show it larger than sigma (their standard deviation over sqrt 2: "
              "'N se by the scatter ... paired runs show')"
              + (f". {turned}" if (turned := turning_words()) else "") + ")"]
    return lines, committed(COUPLING_SOURCES)


# The lattice body by itself (issue 79): where it starts each shape rising, from every lattice case of
# the coupling screen, whichever bed it ran on.
LATTICE = {"intruder.surface": "lattice"}


def answer_lattice(spec):
    """Each shape run on the lattice body: its V_y per period in the 60 d box, where it starts rising by
    the Table 1's rule, and that against the paper's range."""
    lines = head_lines(["shape", "the paper's T_rising", "V_y on the lattice body, A = 5", "its bracket",
                        "the paper's range?"])
    shown = [shape for shape in SHAPES if coupling_periods(shape, LATTICE)]
    stray = "".join(f"; the {shape}'s paired runs stray {sd / rule:.1f} x as far as its sigma allows ({dof} dof): its "
                    "counts of standard errors overstate it by as much" for shape, sd, dof, rule in straying(shown))
    for shape in SHAPES:
        cells = coupling_periods(shape, LATTICE)
        if not cells:
            continue
        lo, hi = findings.first_rise(cells, clock_sigma(shape))
        each = "; ".join(f"T = {period:g} {beds_z_text(values, shape)}" for period, values in cells)
        lines.append(row_line([SHAPE_NAMES[shape], paper_observed(shape), each, bracket_text(lo, hi, cells),
                               against_paper(lo, hi, shape)]))
    lines += ["", "(V_y over t = 100-1000 of runs to t = 1000 in the 60 d box by the paper's protocol but for the "
              "body: the outline filled with touching 0.5 d spheres on a square lattice; on the factor screen's "
              "beds with the lattice body in the glued shell's place (`bed.swap_intruder`), or on a bed poured "
              "around the lattice body itself; study/sweeps/paper_depth_coupling_t1000.toml. se: standard errors "
              "from zero by the shape's sigma, " + scatter_words(shown) + stray
              + ". The bracket is the first period that rises and the period run below it, as in Table 1)"]
    return lines, committed(COUPLING)


TABLES = [
    {"name": "answer_protocol", "kind": answer_protocol, "sources": PROTOCOL_FOLDERS + T1000_BEDS},
    {"name": "answer_coupling", "kind": answer_coupling, "sources": COUPLING_SOURCES},
    {"name": "answer_lattice", "kind": answer_lattice, "sources": COUPLING},
    # The protocol block's cases in the thirds of the paper's window, as depth_t1000_windows the preset's
    {"name": "protocol_windows", "kind": windows, "sources": T1000_BEDS + PROTOCOL_FOLDERS,
     "where": {"drive.amplitude": 5.0}, "row": protocol_row,
     "row_sort": lambda r: (PROTOCOL_CELL_KEYS.index(r[:2]), r[2]),
     "row_head": ["shape", "T", "what changes"],
     "row_label": lambda r: (r[0], f"{r[1]:g}", PROTOCOL_ROWS[r[2]][1]), "windows": T1000_WINDOWS},
]
