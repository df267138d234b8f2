"""The answer's sentences: the prose blocks of study/VALIDATION.md's opening page ("Does wiggle
reproduce the paper?": each difference from the paper, each shape in the paper's own box, the drive
read as a velocity) and the README's paragraph "Does it reproduce the paper?". Each sentence is made
from the numbers of the tables beside it (table1_blocks.py, findings_table.py, factor_tables.py);
where it picks its words from the numbers (which way a rate goes, whether a factor moved a cell,
what is left unexplained), the choice is a small function of its own, tested on made-up cells in
study/tests/test_study_sentences.py.
"""
import textwrap

import findings
from cases import (CLOCK_A3, CLOCK_A5, COUPLING, DEPTH_A5, PAPER_RANGE, SHAPES, SMALL_TODAY, SMALL_TODAY_WHERE,
                   T1000_BEDS, Cell, beds, beds_count, beds_text, by_period, cell_text, committed, count_range, load,
                   cases_of, head_lines, mean, paper_observed, row_line, select, so_far, unfinished)
from factor_tables import (BOX_ALONE, BOX_ROW, COUPLING_CELLS, COUPLING_ROWS, PAPER_BOX_COUPLING, PROTOCOL_CELLS,
                           PROTOCOL_FOLDERS, PROTOCOL_ROWS, box_alone_change, change_text, coupling_change, coupling_periods,
                           coupling_screen_run, most_of_it, paper_box_change, paper_box_coupling, protocol_beds,
                           protocol_change, row_where, straying)
from findings import RESOLVED
from findings_table import FINDING_SOURCES, against_findings, paper_findings
from scatter import (PAPER_SIDE, SHAPE_NAMES, beds_z_text, clock_scatter, clock_sigma, depth_sigma,
                     findings_clock_sigma, paper_reading, scatter_text, scatter_words, short_name, student_note,
                     z_of)
from table1_blocks import (paper_box_shapes, CROSSING_WORDS, HALVES, PAPER_BOX_FIGURE, against_paper, bracket_text, course, crossings,
                           first_rise, halves_text, paper_box_cases, paper_box_cells)

# The paper's own words on its triangle, beside its Table 1's 4-5: (quoted, where they stand in the paper)
PAPER_TRIANGLE_WORDS = [("is noticed to sink always irrespective of the time periods", "its section 3.1, of figure 2e at A = 3"),
                        ("is observed to have a negligible rise even when it is oscillated at a high time period",
                         "its conclusions, section 4.1")]


def paper_triangle_text():
    """The paper's words on its triangle, quoted, each with where it stands."""
    return " and ".join(f'"{words}" ({where})' for words, where in PAPER_TRIANGLE_WORDS)


OWN_SCATTER_WORDS = " of the scatter its own runs show"  # after "by 2 standard errors", where a change is judged by it
STALL = 4.0   # the second half's rate under 1/STALL of the first's: "then stalls"


def course_words(first, second):
    """How the second half's rate follows the first's: 'then stalls' (under 1/STALL of it), 'then turns
    back' (the other sign), 'then faster', 'then slower'."""
    if abs(second) < abs(first) / STALL:
        return "then stalls"
    if (second > 0) != (first > 0):
        return "then turns back"
    return "then faster" if abs(second) > abs(first) else "then slower"


def courses_text(shape, by_t, only=None):
    """'the square climbs over t = 100-500 (+0.070 at T = 3, +0.114 at T = 4), then stalls over
    t = 500-1000 (+0.008, +0.004)': a shape's cells ({T: cases}) by the halves of the window, periods
    that go alike in one clause; only: the words to keep (None: all)."""
    groups = {}
    for t, cases in by_t.items():
        first, second = course(cases)
        words = ("climbs" if first > 0 else "sinks", course_words(first, second))
        if only is None or words[1] in only:
            groups.setdefault(words, []).append((t, first, second, len(cases)))
    (t0, t1), (t2, t3) = HALVES
    return [f"the {shape} {verb} over t = {t0:g}-{t1:g} (" + ", ".join(f"{a:+.3f} at T = {t:g}" for t, a, _, _ in runs)
            + f"), {words} over t = {t2:g}-{t3:g} (" + ", ".join(f"{b:+.3f}" for _, _, b, _ in runs) + ")"
            for (verb, words), runs in groups.items()]


def crossings_sentence(found, rest_too=True):
    """Where the sign crossings (table1_blocks.crossings) lie against the paper's ranges, in a sentence;
    its first words say whether every crossing the runs place lies at or below the paper's lower end;
    rest_too: also the shapes whose crossing the periods run do not place."""
    placed = [x for x in found if x[3] is not None and x[2] is not None]
    below = [x for x in placed if x[3] == -1]
    listed = ", ".join(f"{short_name(s)} {lo:g}-{hi:g} against {paper_observed(s)}" for s, lo, hi, _, _ in placed)
    rest = [f"the {short_name(s)}'s mean " + (f"is > 0 already at T = {hi:g}, its shortest period run (paper: "
                                              f"{paper_observed(s)})" if hi is not None else
                                              f"stays <= 0 up to T = {cells[-1][0]:g} (paper: {paper_observed(s)})")
            for s, lo, hi, side_, cells in found if not (side_ is not None and hi is not None)]
    if placed and len(below) == len(placed):
        head = (f"every crossing the runs place lies at or below the paper's lower end ({listed}): a shift to "
                "shorter periods")
    else:
        head = "the crossings the runs place: " + "; ".join(f"{short_name(s)} {lo:g}-{hi:g}, {CROSSING_WORDS[side_]}"
                                                            for s, lo, hi, side_, _ in placed)
    return head + ("; " + " and ".join(rest) if rest and rest_too else "")


def answer_differences(spec):
    """Each difference from the paper, with what was measured about its cause."""
    def cell(sources, **where):
        return beds_text(Cell(sources, **where).values())
    glued = ["results/paper_depth/glued"]
    tri = ["results/paper_depth/triangle"]
    sq_lo, sq_hi, sq_cells = first_rise(CLOCK_A5, "square", clock_sigma("square"))
    sq_rise = dict(sq_cells)[sq_hi]
    _, _, tri_cells = first_rise(CLOCK_A5, "triangle", clock_sigma("triangle"))
    tri_a3 = list(by_period(CLOCK_A3, intruder__shape="triangle", drive__amplitude=3.0).items())
    tri_against = against_findings("triangle")
    small = SMALL_TODAY
    scatter = clock_scatter()
    quiet, loud = min(SHAPES, key=lambda s: scatter[s].sigma), max(SHAPES, key=lambda s: scatter[s].sigma)
    lines = [
        f"- **The square's bracket, {bracket_text(sq_lo, sq_hi, sq_cells)} against the paper's {paper_observed('square')}: "
        f"{against_paper(sq_lo, sq_hi, 'square').split(': ', 1)[-1]}**: by the paper's clock it rises at T = {sq_hi:g}, "
        f"{beds_z_text(sq_rise, 'square')}, on each bed (" + ", ".join(f"{v:+.3f}" for v in sq_rise)
        + "). Cause not known. Tried without a change of sign (t = 100, one bed): the paper's glued intruder (T = 3: "
        f"{cell(glued, intruder__shape='square', drive__period=3.0)}). " + protocol_so_far("square", 3.0),
        f"- **The triangle does not rise** (the paper's Table 1: from T = {paper_observed('triangle')}; its text: its "
        f"triangle {paper_triangle_text()}): by the paper's clock, at A = 5, "
        + ", ".join(f"{beds_z_text(vs, 'triangle')} at T = {t:g}" for t, vs in tri_cells)
        + (", not rising at any period run"
           if all(findings.cell_side(vs, clock_sigma("triangle")) <= 0 for _, vs in tri_cells) else "")
        + ("; at A = 3 (figure 2's periods, its scatter there not measured) "
           + ", ".join(f"{beds_text(vs)} at T = {t:g}" for t, vs in tri_a3)
           + (", each below zero" if all(mean(vs) < 0 for _, vs in tri_a3) else "") if tri_a3 else "")
        + ": the paper's text, not its Table 1"
        + (f" (by study/FINDINGS.md's rule, against finding{'s' if len(tri_against) > 1 else ''} "
           + " and ".join(str(n) for n in tri_against) + ")" if tri_against else "")
        + ". Cause not known. Tried without a change of sign (t = 100, one bed "
        "each, T = 4; 6): "
        f"the paper's glued intruder ({cell(tri, intruder__shape='triangle', intruder__surface='glued', drive__period=4.0)}; "
        f"{cell(tri, intruder__shape='triangle', intruder__surface='glued', drive__period=6.0)}) and a random pour "
        f"({cell(tri, intruder__shape='triangle', bed__pour='random', drive__period=4.0)}; "
        f"{cell(tri, intruder__shape='triangle', bed__pour='random', drive__period=6.0)}): all sink. "
        + protocol_so_far("triangle", 5.0),
        "- **Where the mean turns positive** (the paper's own reading of T_rising, by the sign of the mean, without "
        "standard errors): " + crossings_sentence(crossings()) + ".",
        "- **The small preset crosses late** (findings 2 and 7 there): its bed is 25 d deep, the paper's 105 d. At A = 5 "
        f"its disk still sinks at T = 3.5, {cell(small, intruder__shape='disk', drive__amplitude=5.0, drive__period=3.5, **SMALL_TODAY_WHERE)}, "
        f"where at the paper's depth it rises at T = 3, {cell(DEPTH_A5, intruder__shape='disk', drive__period=3.0)}; "
        "the two presets differ only in depth, so depth is the measured cause. The small preset is for trying things, "
        "not for the paper's numbers.",
        f"- **Not resolved is mostly scatter**: at t = 100 one bed tells V_y to about +-{depth_sigma():.3f} (one figure "
        "for every shape) and most cells have one bed, so differences between shapes (finding 4), amplitudes (3) and "
        f"frictions (6) stay within {RESOLVED:g} standard errors; by the paper's clock one bed tells it to "
        f"+-{scatter[quiet].sigma:.4f} ({short_name(quiet)}, {scatter[quiet].dof} dof) to +-{scatter[loud].sigma:.4f} "
        f"({short_name(loud)}, {scatter[loud].dof} dof), each shape's own, but only Table 1's periods and "
        "figure 2's (A = 3, T = 1 and 5) have run that long.",
    ]
    return lines, spec["sources"]


def bracket_kind(lo, hi, paper_range):
    """Which of the README's lists a shape's bracket (first_rise's, by the paper's clock) goes in, by
    findings.against_range: 'agrees' (the paper's bracket or inside it), 'never rises', 'differs'
    (outside the paper's range), else 'not placed' (rising already at the shortest period run)."""
    verdict = findings.against_range(lo, hi, paper_range)
    if verdict.startswith("**yes"):
        return "agrees"
    if hi is None:
        return "never rises"
    return "differs" if verdict.startswith("**no") else "not placed"


def straying_note():
    """Where the coupling screen's paired runs of a shape stray more than its sigma allows, a clause that says
    so ("" where none does)."""
    found = straying(SHAPES)
    return ("; " + "; ".join(f"the {short_name(shape)}'s paired runs on one bed stray {sd / rule:.1f} x as far as its "
                             f"sigma allows ({dof} dof{most_of_it(shape)})" for shape, sd, dof, rule in found)
            + ": study/VALIDATION.md, \"The intruder's coupling\"") if found else ""


def readme_answer(spec):
    """The README's paragraph "Does it reproduce the paper?": the page above in a few lines. The same
    paragraph opens study/README.md (spec "within": "study/"), its paths to the study's pages written
    from there."""
    agree, differ, unplaced, never = [], [], [], []
    scatter = clock_scatter()
    cells_all = []
    for shape in SHAPES:
        lo, hi, cells = first_rise(CLOCK_A5, shape, clock_sigma(shape))
        cells_all += cells
        kind = bracket_kind(lo, hi, PAPER_RANGE[shape])
        name = short_name(shape)
        if kind == "agrees":
            agree.append(f"{name} {bracket_text(lo, hi, cells)}")
        elif kind == "never rises":
            never.append(f"the {name} does not rise at any period run (T = {cells[0][0]:g}-{cells[-1][0]:g}), where the "
                         f"paper's Table 1 has it rising from {paper_observed(shape)}"
                         + (f" and its text says it {paper_triangle_text()}" if shape == "triangle" else ""))
        elif kind == "differs":
            differ.append(f"the {name} rises from {bracket_text(lo, hi, cells)} (paper: {paper_observed(shape)})")
        else:
            z = z_of(dict(cells)[hi], shape)
            note = student_note(z, shape)
            unplaced.append(f"the {name} rises already at T = {hi:g}, its shortest period run ({z:.1f} se"
                            + (f", {note}" if note else "") + f"; paper: {paper_observed(shape)})")
    sigmas = sorted(scatter[s].sigma for s in SHAPES)
    dofs = sorted(scatter[s].dof for s in SHAPES)
    # the verdicts of study/FINDINGS.md's table, by its rule
    verdicts = [findings.finding_verdict(*by_scale.get("paper's clock", (0.0, []))) for _, _, by_scale in paper_findings()]
    text = (f"Partly. By the paper's clock (runs to t = 1000, V_y over t = 100-1000; {count_range(len(v) for _, v in cells_all)} beds a "
            f"period) at its depth in a 60 d box, each shape judged at {RESOLVED:g} standard errors of its own scatter "
            f"(one bed's sigma {sigmas[0]:.4f}-{sigmas[-1]:.4f}, {dofs[0]}-{dofs[-1]} degrees of freedom{straying_note()}), Table 1's "
            f"bracket is the paper's for {len(agree)} of 5 shapes (" + ", ".join(agree) + "); "
            + "; ".join(differ + unplaced + never) + ". By the sign of the mean, as the paper reads it, "
            + crossings_sentence(crossings(), rest_too=False) + ". " + paper_box_summary() + protocol_summary()
            + f"Left unexplained: {unmeasured(short=True)}. Of the seven findings by that clock (study/FINDINGS.md's rule, one "
            f"sigma for every shape, {findings_clock_sigma():.3f}): "
            + ", ".join(f"{verdicts.count(v)} {v}" for v in findings.VERDICTS) + ". In full: "
            "[study/VALIDATION.md](study/VALIDATION.md#does-wiggle-reproduce-the-paper).")
    within = spec.get("within", "")
    if within:
        text = text.replace(within + "VALIDATION.md", "VALIDATION.md").replace(within + "FINDINGS.md", "FINDINGS.md")
    return textwrap.wrap(text, 104, break_on_hyphens=False, break_long_words=False), spec["sources"]


# The drive read as a velocity (study/VALIDATION.md, figure 5's section): what its one bed a cell at
# t = 100 can say of a crossing at A = 5.
def drive_form_words(spec):
    """A sentence on the velocity reading at A = 5: its V_y per shape and period, each in standard
    errors of the t = 100 window's one sigma, and whether one bed tells where, or whether, it crosses."""
    cells = {shape: list(by_period(["results/paper_depth/velocity"], intruder__shape=shape, drive__amplitude=5.0,
                                   drive__form="velocity").items()) for shape in ("disk", "square")}
    text = velocity_sentence(cells, depth_sigma())
    return textwrap.wrap(text, 100, break_on_hyphens=False, break_long_words=False), spec["sources"]


def velocity_sentence(cells_by_shape, sig):
    """drive_form_words' sentence from {shape: [(T, values)]} and the t = 100 window's sigma ("" when
    no shape has a cell): whether any cell is RESOLVED standard errors from zero either way."""
    parts, resolved = [], False
    for shape, cells in cells_by_shape.items():
        if not cells:
            continue
        zs = [findings.z_from_zero(vs, sig) for _, vs in cells]
        resolved = resolved or any(findings.resolved_side(z) != 0 for z in zs)
        parts.append(f"the {shape} gives " + ", ".join(f"{mean(vs):+.3f}" for _, vs in cells)
                     + " at T = " + ", ".join(f"{t:g}" for t, _ in cells)
                     + f" ({beds_count(len(vs) for _, vs in cells)} each: "
                     + ", ".join(f"{z:+.1f}" for z in zs) + " se)")
    if not parts:
        return ""
    return ("At A = 5, read as a velocity, " + " and ".join(parts) + f", in standard errors of one bed's sigma at t = 100, "
            f"{sig:.3f} (study/FINDINGS.md's at the paper's depth): "
            + (f"some are {RESOLVED:g} se or more from zero, as the table above shows." if resolved else
               f"none is {RESOLVED:g} se from zero, so one bed each does not tell whether, or where, either crosses "
               "over the periods run."))


def paper_box_summary():
    """What the paper's protocol in its own box gives so far, cell by cell, against the paper's Table 1,
    and where a rate stalls or turns within the window, in sentences for the README ("" before any of
    its cases has finished)."""
    parts = [f"the {shape} at T = {t:g} {beds_z_text(vs, shape)}: {paper_reading(vs, shape, t)}"
             for shape in SHAPES for t, vs in paper_box_cells(shape)[0].items()]
    if not parts:
        return ""
    turns = [text for shape in SHAPES for text in courses_text(shape, paper_box_cases(shape), ("then stalls", "then turns back"))]
    short = PROTOCOL_ROWS[BOX_ROW][1]
    return (short[0].upper() + short[1:] + " (one bed a cell, judged by the 60 d box's scatter) leaves " + "; ".join(parts)
            + ". " + (f"There {'; '.join(turns)}: its V_y over t = 100-1000 averages the two ({PAPER_BOX_FIGURE}). "
                      if turns else ""))


def protocol_summary():
    """The protocol table so far in a sentence for the README ("" before any of its cells has a case)."""
    measured, toward, own_scatter = [], [], []
    for row in range(1, len(PROTOCOL_ROWS)):
        name = PROTOCOL_ROWS[row][1].split(" (")[0]
        for shape, period, paper_sign in PROTOCOL_CELLS:
            sig = clock_sigma(shape)
            values, change = protocol_change(row, shape, period, paper_sign, sig)
            if values:
                measured.append((name, len(values)))
                said = [(name, change)]
                if row == BOX_ROW:
                    said.append((BOX_ALONE.split(" (")[0], box_alone_change(shape, period, paper_sign, sig)))
                # The 300 d box has one bed a cell: its changes are counted in the 60 d box's scatter.
                scale = " of the 60 d box's scatter, the 300 d box's own not measured" if row == BOX_ROW else ""
                toward += [f"{who} moves the {shape} at T = {period:g} {c[2]} ({c[1]:.1f} se{scale})"
                           for who, c in said if c and c[2] != "within the scatter"]
                own_scatter += [f"{who} moves the {shape} at T = {period:g} by {c[1]:.1f} se of sigma, {c[3]}"
                                for who, c in said if c and c[3]]
    if not measured:
        return ""
    names = list(dict.fromkeys(name for name, _ in measured))
    cells = len(PROTOCOL_CELLS) * (len(PROTOCOL_ROWS) - 1)
    on = " and ".join(f"the {shape} at T = {period:g}" for shape, period, _ in PROTOCOL_CELLS)
    return (f"Of the preset's differences from the paper's stated protocol, measured so far by that clock on {on} "
            f"({', '.join(names)}: {len(measured)} of {cells} cells, {beds_count(n for _, n in measured)} "
            f"each), {moved_text(toward, own_scatter)}. ")


def moved_text(toward, own_scatter):
    """protocol_summary's words for what the factors moved: each move toward or away from the paper
    (toward: their words), else that none moves a cell by RESOLVED standard errors, "of the scatter its
    own runs show" where some change resolved on sigma is not by that (own_scatter: their words, after)."""
    if toward:
        return "; ".join(toward) + (f"; not by the scatter its own runs show, {'; '.join(own_scatter)}"
                                    if own_scatter else "")
    return (f"none moves a cell by {RESOLVED:g} standard errors" + (OWN_SCATTER_WORDS if own_scatter else "")
            + (f" ({'; '.join(own_scatter)})" if own_scatter else ""))


def protocol_so_far(shape, period):
    """What the one-factor screen of the protocol block has measured of one cell so far, in a sentence."""
    sig = clock_sigma(shape)
    paper_sign = next(sign for s, t, sign in PROTOCOL_CELLS if (s, t) == (shape, period))
    done, left = [], []
    for row in range(1, len(PROTOCOL_ROWS)):
        short = PROTOCOL_ROWS[row][1]
        values, change = protocol_change(row, shape, period, paper_sign, sig)
        if values:
            box = box_alone_change(shape, period, paper_sign, sig) if row == BOX_ROW else None
            compared = f"a change of {change_text(change)}" if change else "no baseline on its beds yet"
            done.append(f"{short}: {cell_text(values)}, {compared}"
                        + (f", of which {BOX_ALONE} {change_text(box)}" if box else ""))
        else:
            left.append(short)
    sentences = []
    if done:
        sentences.append(f"By the paper's clock, one factor at a time (the protocol block below; se of the {shape}'s "
                         f"sigma, {scatter_text(shape)}): " + "; ".join(done) + ".")
    if left:
        sentences.append("Not yet measured at t = 1000: " + ", ".join(left) + " (issue 51).")
    return " ".join(sentences)


# What is left when no measured factor accounts for a difference: the intruder's coupling to its grains
# as the paper's LAMMPS body had it (issue 79, study/sweeps/paper_depth_coupling_t1000.toml, its
# results to come in COUPLING), what the paper leaves open and the protocol block did not vary
# (docs/PHYSICS.md, "The paper's stated protocol"), and the paper's own scatter.
UNMEASURED = ("what the paper leaves open and the screen did not vary (the grains' diameter distribution, the "
              "pour's batch height and fill fraction), and the paper's own scatter, which it does not report (no "
              "repeated beds, no error bars)")


UNMEASURED_SHORT = ("what the paper leaves open (the grains' diameter distribution, the pour's batch height and fill "
                    "fraction) and its own scatter (no repeated beds, no error bars)")


def unmeasured(short=False, cell=None):
    """What is left unexplained, in words: the coupling (as far as its screen has gone; at `cell`, (shape,
    period), what it measured there), then UNMEASURED (short: UNMEASURED_SHORT)."""
    done = [c for f in committed(COUPLING) for c in load(f)]
    if not done:
        status = "its screen, study/sweeps/paper_depth_coupling_t1000.toml, being run, no results committed yet"
    elif cell:
        status = cell_coupling_status(coupling_at(cell), coupling_screen_run())
    else:
        status = coupling_status([(change, paper_box_coupling(shape, period, changes) if change else None,
                                   coupling_bracket_short(shape, coupling_periods(shape, changes)))
                                  for _, changes in COUPLING_ROWS for shape, period in COUPLING_CELLS
                                  for change in [coupling_change(shape, period, changes)]], coupling_screen_run())
    if short:
        return f"how the paper's glued LAMMPS body met its grains ({status}), " + UNMEASURED_SHORT
    return ("how the paper's glued LAMMPS body met its grains (its atoms' masses in the contacts' damping, a body "
            f"built on a lattice, its rotation; {status}), " + UNMEASURED)


def coupling_at(cell):
    """[(the factor's short name, coupling_change's change at cell, (shape, period), or None)] of every
    coupling row."""
    return [(label.split(" (")[0], coupling_change(*cell, changes)) for label, changes in COUPLING_ROWS]


def measured_words(measured):
    """([each change of [(the factor's name, coupling_change's change or None)] and which way, in words],
    [the names not run there yet])."""
    done = [f"{name} {c.diff:+.4f} ({abs(c.z):.1f} se{c.by_runs}, {c.toward}; {beds_count([c.paired])} paired)"
            for name, c in measured if c]
    return done, [name for name, c in measured if not c]


def screen_words(run):
    """The coupling screen's state in a few words: run (coupling_screen_run's) or still being run."""
    return "its screen run" if run else "its screen being run"


def cell_coupling_status(measured, run=False):
    """What the coupling screen measured at one cell, from [(the factor's name, coupling_change's change
    there or None)]: each change and which way, then the factors not run there yet (run:
    coupling_screen_run's)."""
    done, left = measured_words(measured)
    return (f"{screen_words(run)}, " + (f"at this cell {'; '.join(done)}" if done else "not at this cell yet")
            + (f"; not run here yet: {', '.join(left)}" if done and left else "")
            + "; study/VALIDATION.md, \"The intruder's coupling\"")


def coupling_status(measured, run=False):
    """How far the coupling screen has gone, from its cells' (change, paper-box reading, bracket)
    (coupling_change's, None for a cell not measured yet; paper_box_coupling's; coupling_bracket_short's):
    how many changes, on how many beds, and which move a cell by RESOLVED standard errors, with where the
    factor by itself starts the shape rising and, for a move toward the paper (the ones the paper's box is
    run for: issue 79, item 5), what it gives in the paper's box (run: coupling_screen_run's; "so far" while
    it is not); then those resolved on sigma but not by the scatter their shape's paired runs show."""
    changes = [(c, box, bracket) for c, box, bracket in measured if c]
    moved = [(c, box, bracket) for c, box, bracket in changes if c.toward != "within the scatter"]
    so_far = "" if run else " so far"
    return (f"{screen_words(run)}, {len(changes)} change{'s' if len(changes) > 1 else ''} measured{so_far}, on "
            f"{beds_count(c.paired for c, _, _ in changes)} each: "
            + (f"none moves a cell by {RESOLVED:g} standard errors{so_far}" if not moved else
               "; ".join(f"{c.name} moves {c.cell} {c.toward} ({c.diff:+.3f}, {abs(c.z):.1f} se{c.by_runs}, in the 60 d "
                         f"box{bracket}" + (f"; {paper_box_short(box)}" if c.toward == "toward the paper" else "") + ")"
                         for c, box, bracket in moved))
            + "".join(f"; {c.name} moves {c.cell} by {abs(c.z):.1f} se of sigma ({c.diff:+.3f}) but{c.by_runs[1:]}: "
                      "not resolved" for c, _, _ in changes if c.toward == "within the scatter" and c.by_runs
                      and findings.resolved_side(c.z) != 0)
            + "; study/VALIDATION.md, \"The intruder's coupling\"")


def paper_box_short(reading):
    """What a coupling row gives in the paper's own box, in a few words (reading: paper_box_coupling's)."""
    if reading is None:
        return "not run in the paper's box yet"
    if reading.t_now is not None:
        return "being run in the paper's box"
    return (f"in the paper's box {beds_z_text([reading.vy], reading.shape)}: "
            f"{paper_reading([reading.vy], reading.shape, reading.period)}")


def factor_changes(shape, period, paper_sign, sig):
    """([(what changed, its change as protocol_change gives it)] of every protocol row measured in one
    cell, the box alone beside the 300 d box's row; [the rows not measured there yet])."""
    changes, left = [], []
    for row in range(1, len(PROTOCOL_ROWS)):
        name = PROTOCOL_ROWS[row][1]
        change = protocol_change(row, shape, period, paper_sign, sig)[1]
        if not change:
            left.append(name)
            continue
        changes.append((name, change))
        box = box_alone_change(shape, period, paper_sign, sig) if row == BOX_ROW else None
        if box:
            changes.append((BOX_ALONE, box))
    return changes, left


def factors_text(shape, period, paper_sign, sig, box_values):
    """What the protocol block measured in one of its cells, and what is left of the difference from the
    paper there, in sentences; box_values: the paper's box's V_y in the cell ([] while not finished)."""
    changes, left = factor_changes(shape, period, paper_sign, sig)
    base = list(protocol_beds(PROTOCOL_ROWS[0][2], row_where(0, shape, period)).values())
    text = (f"At T = {period:g}, where the paper has it {PAPER_SIDE[paper_sign]}, the preset gives {beds_z_text(base, shape)}; "
            "changed one at a time and together, " + "; ".join(f"{name} {change_text(c)}" for name, c in changes) + ". ")
    if left:
        text += "Not measured there yet: " + ", ".join(left) + ". "
    text += what_moved(changes)
    if box_values:
        on_side = findings.on_paper_side(box_values, sig, paper_sign)
        coupling = coupling_toward(shape, period)
        others = [(name, c) for name, c in coupling_at((shape, period)) if not (c and c.toward == "toward the paper")]
        text += what_is_left(changes, on_side, "" if on_side else UNMEASURED if coupling else
                             unmeasured(cell=(shape, period)), coupling, others)
    return text


def coupling_toward(shape, period):
    """[(coupling_change's change, its paper-box reading: paper_box_coupling's, where the row by itself starts
    the shape rising in the 60 d box: coupling_bracket_words')] of the coupling rows that move the cell
    toward the paper by RESOLVED standard errors in the 60 d box."""
    found = []
    for _, changes in COUPLING_ROWS:
        change = coupling_change(shape, period, changes)
        if change and change.toward == "toward the paper":
            found.append((change, paper_box_coupling(shape, period, changes),
                          coupling_bracket_words(shape, coupling_periods(shape, changes))))
    return found


def coupling_bracket_words(shape, periods):
    """Where a coupling row by itself starts the shape rising in the 60 d box, by the Table 1's rule, from
    its cells at two periods or more (periods: coupling_periods'); "" with fewer."""
    if len(periods) < 2:
        return ""
    lo, hi = findings.first_rise(periods, clock_sigma(shape))
    each = ", ".join(f"T = {t:g} {beds_z_text(values, shape)}" for t, values in periods)
    return f"; by itself there {each}: its bracket {bracket_text(lo, hi, periods)}, {against_paper(lo, hi, shape)}"


def coupling_bracket_short(shape, periods):
    """coupling_bracket_words' bracket in a few words: ', its bracket there <= 4 (the paper's 4-5)'; "" with
    cells at fewer than two periods."""
    if len(periods) < 2:
        return ""
    lo, hi = findings.first_rise(periods, clock_sigma(shape))
    return f", its bracket there {bracket_text(lo, hi, periods)} (the paper's {paper_observed(shape)})"


def coupling_words(change, paper_box, bracket=""):
    """One coupling factor that moves a cell toward the paper, in words: its change on the 60 d box's
    paired beds, where it starts the shape rising there (bracket: coupling_bracket_words') and what it
    gives in the paper's own box (paper_box: a PaperBoxReading, or None)."""
    return (f"{change.name} moves it {change.diff:+.4f} ({abs(change.z):.1f} se{change.by_runs}, toward the paper; "
            f"{beds_count([change.paired])} paired) in the 60 d box{bracket}; in the paper's box: "
            f"{paper_box_words(paper_box)}")


def paper_box_words(reading):
    """What a coupling factor gives in the paper's own box, against the protocol on the same bed (reading: a
    PaperBoxReading, or None): judged once finished, else how far it has run and its rate so far."""
    if reading is None:
        return "not run yet"
    if reading.t_now is None:
        diff, z, toward = paper_box_change(reading)
        return (f"V_y {beds_z_text([reading.vy], reading.shape)}, {paper_reading([reading.vy], reading.shape, reading.period)}; "
                f"against the protocol's {reading.base:+.4f} on the same bed, {diff:+.4f} ({abs(z):.1f} se, {toward})")
    if reading.vy is None:
        return f"being run (t = {reading.t_now:g} of {reading.duration:g} committed)"
    return (f"being run, so far (t = 100-{reading.t_now:g}, not judged) {reading.vy:+.4f} against the "
            f"protocol's {reading.base:+.4f} on the same bed over the same window (one bed)")


def answer_paper_box_coupling(spec):
    """Every case run in the paper's own box for a coupling factor (issue 79, item 5), cell by cell, in
    paper_box_words' words; then the cases of those sweeps not begun yet."""
    lines = head_lines(["shape", "T", "what changes", "in the paper's box, against the protocol on the same bed"])
    waiting = []
    for folder in committed(PAPER_BOX_COUPLING):
        begun = load(folder) + tuple(unfinished(folder))
        for case in begun:
            shape, period = case.get("intruder.shape"), float(case.get("drive.period"))
            for label, changes in COUPLING_ROWS:
                if all(case.get(k) == v for k, v in changes.items()):
                    lines.append(row_line([SHAPE_NAMES[shape], f"{period:g}", label.split(" (")[0],
                                           paper_box_words(paper_box_coupling(shape, period, changes))]))
        names = {c.row["case"] for c in begun}
        waiting += [f"the {c.get('intruder.shape')} at T = {float(c.get('drive.period')):g}"
                    for c in cases_of(folder, finished=False) if c.row["case"] not in names]
    lines += ["", "(V_y by the paper's rule over t = 100-1000 in the paper's 300 d box by its protocol, one bed a "
              "side: the paper box's own bed of the shape, the changed body in the glued shell's place; se: standard "
              "errors by the shape's sigma, as the per-shape answer's; a case not finished is shown by its rate so "
              "far over t = 100 to its last committed sample once that spans 200, and not judged"
              + (f"; not begun yet: {', '.join(waiting)}" if waiting else "") + ")"]
    return lines, committed(PAPER_BOX_COUPLING)


def what_moved(changes):
    """After a cell's changes [(what changed, protocol_change's change)]: those resolved by RESOLVED
    standard errors and which way, else that none is ("of the scatter its own runs show" where one shown
    within the scatter was resolved on sigma, as the README's sentence says); "" when none was measured."""
    moved = [f"{name}, {c[2]}" for name, c in changes if c[2] != "within the scatter"]
    if moved:
        return f"Resolved by {RESOLVED:g} standard errors: " + "; ".join(moved) + ". "
    if changes:
        own_scatter = any(c[3] for _, c in changes)
        return f"No measured factor moves it by {RESOLVED:g} standard errors" + (OWN_SCATTER_WORDS if own_scatter else "") + ". "
    return ""


def what_is_left(changes, on_side, unmeasured_words, coupling=(), others=()):
    """Whether a cell's changes account for the paper's box differing from the paper there: nothing to
    account for when the box's cell is on the paper's side (on_side); else none of the difference
    (no change moves it toward the paper) or not all, and what is left (unmeasured_words). Where a
    coupling factor moves the cell toward the paper (coupling: coupling_toward's), it is named as what
    may account for the difference, with where it has been run, and the screen's other factors at the
    cell after it (others: coupling_at's less those), measured or not run yet."""
    if on_side:
        return "In the paper's box by its protocol the cell is on the paper's side."
    toward = any(c[2] == "toward the paper" for _, c in changes)
    if coupling:
        done, left = measured_words(others)
        parts = ([f"The screen's other factors at this cell: {'; '.join(done)}"] if done else []) + \
                ([f"{'not' if done else 'Not'} run here yet: {', '.join(left)}"] if left else [])
        beside = f" {'; '.join(parts)}." if parts else ""
        return (f"So the protocol's factors account for {'none' if not toward else 'not all'} of the difference; "
                "the intruder's coupling may: " + "; ".join(coupling_words(*c) for c in coupling)
                + f".{beside} Left beside it: {unmeasured_words}.")
    return ("So " + ("none" if not toward else "not all") + " of the difference is accounted for: what is left "
            f"is {'all of it' if not toward else 'the rest'}: {unmeasured_words}.")


def answer_per_shape(spec):
    """Item 4 of issue 51 per shape run in the paper's box: does the paper's own protocol give the
    paper's Table 1 bracket; if not, what each measured factor moved at the cell that disagrees, and
    what is left; and how its rates hold through the window."""
    lines, shown = [], []
    for shape, done, on_way in paper_box_shapes():
        shown.append(shape)
        sig = clock_sigma(shape)
        runs = [(t, f"T = {t:g} {beds_z_text(vs, shape)}, {paper_reading(vs, shape, t)}") for t, vs in done.items()]
        runs += [(c.get("drive.period"), f"T = {c.get('drive.period'):g} not finished "
                  f"(t = {so_far(c)[0]:g} of {c.get('run.duration'):g})") for c in on_way]
        text = (f"- **{SHAPE_NAMES[shape]}**, the paper's T_rising {paper_observed(shape)}: in the paper's own protocol "
                "and box, by its clock, " + "; ".join(said for _, said in sorted(runs)) + ". ")
        cells = list(done.items())
        if on_way:
            text += "Not answered yet: a period is still running. "
        elif cells:
            lo, hi = findings.first_rise(cells, sig)
            plo, phi, pcells = first_rise(CLOCK_A5, shape, sig)
            text += (f"Its bracket by the rule of the Table 1 below, {bracket_text(lo, hi, cells)}; "
                     f"{against_paper(lo, hi, shape)} (the 60 d preset's by the same clock, "
                     f"{bracket_text(plo, phi, pcells)}). ")
            text += ("The paper's protocol, as far as the paper states it, gives the paper's bracket. "
                     if bracket_kind(lo, hi, PAPER_RANGE[shape]) == "agrees" else
                     "**The paper's protocol, as far as the paper states it, does not give the paper's bracket.** ")
        box_cases = paper_box_cases(shape)
        if box_cases:
            preset = {t: beds(select(T1000_BEDS, {"intruder.shape": shape, "drive.amplitude": 5.0, "drive.period": t}),
                              f"{T1000_BEDS} {shape} {t:g}") for t in box_cases}
            preset = {t: cs for t, cs in preset.items() if cs}
            text += ("Through the window: " + "; ".join(courses_text(shape, box_cases))
                     + (" (the 60 d preset by the same halves: " + "; ".join(
                         f"T = {t:g} " + ", then ".join(f"{v:+.3f}" for v in course(cs)) + f" ({beds_count([len(cs)])})"
                         for t, cs in preset.items()) + ")" if preset else "")
                     + f"; {PAPER_BOX_FIGURE}. ")
        text += "".join(factors_text(shape, period, paper_sign, sig, done.get(period, []))
                        for s, period, paper_sign in PROTOCOL_CELLS if s == shape)
        lines.append(text.rstrip())
    lines += ["", "(A = 5 d; one bed per cell in the paper's box, judged as the Table 1 below (se: standard errors from "
              "zero, or of a change) with sigma " + scatter_words(shown)
              + f"; the halves: V_y by the paper's rule over {halves_text()}; the changes are the protocol block's "
              "below, where each case and its beds are listed)"]
    return lines, committed(PROTOCOL_FOLDERS + T1000_BEDS)


ANSWER_SOURCES = FINDING_SOURCES + ["results/paper_depth/glued", "results/paper_depth/triangle"] + PROTOCOL_FOLDERS
TABLES = [
    {"name": "answer_differences", "kind": answer_differences, "sources": ANSWER_SOURCES},
    {"name": "answer_per_shape", "kind": answer_per_shape, "sources": PROTOCOL_FOLDERS + T1000_BEDS},
    {"name": "readme_answer", "kind": readme_answer, "sources": CLOCK_A5 + PROTOCOL_FOLDERS, "bare": True},
    {"name": "study_answer", "kind": readme_answer, "sources": CLOCK_A5 + PROTOCOL_FOLDERS, "bare": True,
     "within": "study/"},
    {"name": "answer_paper_box_coupling", "kind": answer_paper_box_coupling, "sources": PAPER_BOX_COUPLING},
    {"name": "depth_drive_form_words", "kind": drive_form_words, "sources": ["results/paper_depth/velocity"], "bare": True},
]
