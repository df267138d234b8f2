"""The answer page's Table 1 blocks (study/VALIDATION.md, "Does wiggle reproduce the paper?"): Table 1
(A = 5) by the paper's clock beside the paper's observed range and the cavity model, and Table 1 in
the paper's own box; with what they share with the answer's sentences (answer_sentences.py): the
first rise and its bracket, where the mean turns positive, the paper's box's cells and the halves
of the window.

Table 1 read by the findings' rule: a period's V_y is "rising" when it is at least RESOLVED
standard errors above zero (findings.first_rise); wiggle's bracket is the first period that rises
and the period run below it. By the paper's clock each shape is judged by its own scatter
(scatter.clock_scatter); the findings (study/FINDINGS.md) keep their one sigma per scale.
"""
import json
import os

import findings
from cases import (CLOCK_A5, DEPTH_A5, PAPER_BOX, PAPER_RANGE, SHAPES, SO_FAR_FROM, T1000_BEDS, beds, by_period,
                   chord, committed, count_range, head_lines, load, mean, paper_observed, row_line, select, so_far,
                   unfinished)
from findings import RESOLVED
from scatter import (CLOCK_SCATTER, SHAPE_NAMES, beds_z_text, clock_sigma, depth_sigma, paper_reading,
                     scatter_words)
from table_kinds import paper_crossing

MODEL_T_RISE = {}   # from the cases' model.json: the cavity model's T_rise per shape


def model_t_rise(shape):
    """The cavity model's T_rise (paper section 3.5) for a shape, from a committed case's model.json."""
    if shape not in MODEL_T_RISE:
        case = next(c for c in load(T1000_BEDS[0]) if c.get("intruder.shape") == shape)
        with open(os.path.join(case.dir, "model.json")) as f:
            MODEL_T_RISE[shape] = json.load(f)["T_rise"]
    return MODEL_T_RISE[shape]


# ---- the first period that rises by the rule, and its bracket

def first_rise(sources, shape, sig):
    """(T below, T above, [(T, values)]) of a shape's A = 5 cells: the first period whose V_y rises by
    the rule, and the period run below it (None when it is the shortest run, or when none rises)."""
    cells = list(by_period(sources, intruder__shape=shape, drive__amplitude=5.0).items())
    return (*findings.first_rise(cells, sig), cells)


def against_paper(lo, hi, shape):
    return findings.against_range(lo, hi, PAPER_RANGE[shape])


def bracket_text(lo, hi, cells):
    if hi is None:
        if not cells:
            return "not run"
        run = f"{cells[0][0]:g}" + (f"-{cells[-1][0]:g}" if len(cells) > 1 else "")
        return f"none: not rising at T = {run}"
    return f"{lo:g}-{hi:g}" if lo is not None else f"<= {hi:g}"


# ---- where the mean V_y turns positive, the paper's own reading (no standard errors)

CROSSING_WORDS = {-1: "at or below the paper's lower end", 0: "overlaps the paper's range",
                  +1: "above the paper's range", None: "not placed by the periods run"}


def sign_crossing(cells):
    """(T below, T above) of [(T, values)]: the last period whose mean V_y <= 0 and the next, as the
    paper reads its T_rising (prepare.t_rising); T below None when the mean is positive already at the
    shortest period run, T above None when it never turns positive."""
    _, lo, hi, _ = paper_crossing(cells)
    return (None if lo != lo else lo), (None if hi != hi else hi)


def crossing_text(lo, hi, cells):
    if hi is None:
        return f"none: mean <= 0 up to T = {cells[-1][0]:g}"
    return f"{lo:g}-{hi:g}" if lo is not None else f"> 0 already at T = {hi:g}, the shortest run"


def crossings():
    """[(shape, T below, T above, findings.crossing_against_range, [(T, values)])] by the paper's clock
    at A = 5, every shape run (sign_crossing)."""
    out = []
    for shape in SHAPES:
        cells = list(by_period(CLOCK_A5, intruder__shape=shape, drive__amplitude=5.0).items())
        if cells:
            lo, hi = sign_crossing(cells)
            out.append((shape, lo, hi, findings.crossing_against_range(lo, hi, PAPER_RANGE[shape]), cells))
    return out


def answer_table1(spec):
    """Table 1 (A = 5): the paper's observed range, the cavity model's T_rise, wiggle's bracket by the
    paper's clock with the V_y either side (each shape judged by its own scatter), where the mean turns
    positive (the paper's reading), and the bracket by the preset's t = 100 window."""
    depth = depth_sigma()
    head = ["shape", "paper, observed", "cavity model T_rise", "wiggle, paper's clock", "V_y there (below; first rising)",
            "the paper's range?", "the mean turns > 0 (paper's reading)", "wiggle, t = 100"]
    lines = head_lines(head)
    all_cells = []
    for shape in SHAPES:
        lo, hi, cells = first_rise(CLOCK_A5, shape, clock_sigma(shape))
        all_cells += cells
        values = dict(cells)
        there = "; ".join(beds_z_text(values[t], shape) for t in (lo, hi) if t is not None) if hi is not None else \
            ", ".join(f"{beds_z_text(vs, shape)} at T = {t:g}" for t, vs in cells)
        slo, shi = sign_crossing(cells)
        crossing = (f"{crossing_text(slo, shi, cells)}: "
                    f"{CROSSING_WORDS[findings.crossing_against_range(slo, shi, PAPER_RANGE[shape])]}")
        dlo, dhi, dcells = first_rise(DEPTH_A5, shape, depth)
        lines.append(row_line([SHAPE_NAMES[shape], paper_observed(shape),
                                 f"{model_t_rise(shape):.2f}", bracket_text(lo, hi, cells), there,
                                 against_paper(lo, hi, shape), crossing, bracket_text(dlo, dhi, dcells)]))
    lines += ["", f"(T in sqrt(d/g); A = 5 d. The paper's clock: V_y over t = 100-1000 of runs to t = 1000 on the "
              f"paper-depth preset, {count_range(len(v) for _, v in all_cells)} beds a period. A period rises when its V_y is >= "
              f"{RESOLVED:g} sigma / sqrt(beds) above zero (se: its standard errors from zero), sigma "
              + scatter_words(SHAPES) + ". The bracket is the first period that rises and the period run below it. "
              "The mean turns > 0: the last period whose mean V_y <= 0 and the next, the paper's own reading of "
              f"T_rising, without standard errors. t = 100: V_y over t = 10-100, one sigma for every shape, {depth:.3f} "
              "(study/FINDINGS.md's at the paper's depth))"]
    return lines, spec["sources"]


# ---- the paper's protocol in its own box

def paper_box_cases(shape):
    """{T: the finished cases (beds)} of a shape at A = 5 in the paper's box."""
    cases = {}
    for c in select(committed(PAPER_BOX), {"intruder.shape": shape, "drive.amplitude": 5.0}):
        cases.setdefault(c.get("drive.period"), []).append(c)
    return {t: beds(cases[t], f"{PAPER_BOX} {shape} {t:g}") for t in sorted(cases)}


def paper_box_cells(shape):
    """({T: the beds' V_y} of a shape's finished cases in the paper's box, [its unfinished cases whose
    trajectory so far is committed])."""
    box = committed(PAPER_BOX)
    return (by_period(box, intruder__shape=shape, drive__amplitude=5.0),
            [c for f in box for c in unfinished(f) if c.get("intruder.shape") == shape and c.get("drive.amplitude") == 5.0])


def paper_box_shapes():
    """(shape, finished cells, unfinished cases) for each shape with a case in the paper's box, in
    SHAPES' order."""
    for shape in SHAPES:
        done, on_way = paper_box_cells(shape)
        if done or on_way:
            yield shape, done, on_way


# How a run's rate holds through the paper's window: V_y by the paper's rule over its halves
HALVES = ((100.0, 500.0), (500.0, 1000.0))
PAPER_BOX_FIGURE = ("the trajectories: study/figures/paper_box_t1000_trajectories.png, redrawn by "
                    "`wiggle plot results/paper_box/t1000 --out DIR` as DIR/trajectories.png")


def halves_text():
    return " and ".join(f"t = {t0:g}-{t1:g}" for t0, t1 in HALVES)


def course(cases):
    """(mean V_y over the first half of the window, over the second) of a cell's beds."""
    return tuple(mean([chord(t0, t1)(c) for c in cases]) for t0, t1 in HALVES)


def answer_paper_box(spec):
    """Table 1 in the paper's own box: each period run per shape read against the paper's Table 1, its
    rate over the halves of the window, the bracket by the answer's rule and how it stands against the
    paper's range, beside the 60 d preset's bracket by the same clock."""
    head = ["shape", "paper, observed", "60 d preset, paper's clock", "the paper's box: V_y at each period run",
            f"the paper's box: V_y over {halves_text()}", "the paper's box: bracket", "the paper's range?"]
    lines = head_lines(head)
    shown = []
    for shape, done, on_way in paper_box_shapes():
        shown.append(shape)
        sig = clock_sigma(shape)
        periods_run = [(t, f"{beds_z_text(vs, shape)}, {paper_reading(vs, shape, t)}") for t, vs in done.items()]
        for c in on_way:
            t_now, rate = so_far(c)
            periods_run.append((c.get("drive.period"), f"not finished, t = {t_now:g} of {c.get('run.duration'):g}"
                                + (f" (over t = 100-{t_now:g} {rate:+.3f} so far)" if rate is not None else "")))
        halves = "; ".join(f"T = {t:g}: " + ", ".join(f"{v:+.3f}" for v in course(cases))
                           for t, cases in paper_box_cases(shape).items())
        cells = list(done.items())
        lo, hi = findings.first_rise(cells, sig)
        plo, phi, pcells = first_rise(CLOCK_A5, shape, sig)
        lines.append(row_line([SHAPE_NAMES[shape], paper_observed(shape), bracket_text(plo, phi, pcells),
                                 "; ".join(f"T = {t:g}: {text}" for t, text in sorted(periods_run)), halves,
                                 bracket_text(lo, hi, cells) if cells else "none finished yet",
                                 against_paper(lo, hi, shape) if cells else "not judged yet"]))
    lines += ["", f"(T in sqrt(d/g); A = 5 d; one bed per shape, poured around it. V_y over t = 100-1000 of runs to "
              "t = 1000 in the paper's 300 x 195 d box by its protocol (configs/paper.toml), judged as the answer's "
              f"Table 1 above: a period rises when its V_y is >= {RESOLVED:g} sigma above zero (se: its standard errors "
              "from zero), sigma " + scatter_words(shown) + "; the 300 d box's own is "
              "not measured (one bed per cell). The paper's side at a period: not rising at or below its observed range, "
              f"rising at or above it. The halves: V_y by the paper's rule over {halves_text()} ({PAPER_BOX_FIGURE}). "
              "A case not finished is shown by its rate so far over t = 100 to its last committed sample once that "
              f"spans {SO_FAR_FROM:g}, and not judged)"]
    return lines, committed(PAPER_BOX) + committed(CLOCK_SCATTER)


TABLES = [
    {"name": "answer_table1", "kind": answer_table1, "sources": CLOCK_SCATTER + DEPTH_A5},
    {"name": "answer_paper_box", "kind": answer_paper_box, "sources": PAPER_BOX + CLOCK_SCATTER},
]
