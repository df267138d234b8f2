"""The paper's findings (docs/PHYSICS.md §12) judged by a rule from comparisons of cells: the
comparisons gathered from the committed results at each scale, and the blocks that print them
(study/FINDINGS.md's table and its evidence, the answer page's verdicts). The rule (comparisons in
standard errors of one bed's sigma at a scale, the verdicts) is findings.py's; here the cells'
values are gathered and the outcomes put into words.
"""
import findings
from cases import (CLOCK_A3, CLOCK_A5, DEPTH_A3, DEPTH_A5, DEPTH_FRICTION, DEPTH_SMALL_A, PAPER_RANGE, SHAPES,
                   SMALL_FRICTION, SMALL_MAP, SMALL_POUR, SMALL_SESSION2, SMALL_TODAY, SMALL_TODAY_WHERE, Cell,
                   beds_count, by_period, cell_text, head_lines, load, periods, row_line)
from findings import RESOLVED
from measured_tables import FRICTION_ROWS
from scatter import cells_with_beds, depth_sigma, findings_clock_sigma, sigma

SMALL_MAP_SHAPES = ["disk", "triangle"]
SMALL_MAP_AMPLITUDES = [3.0, 4.0, 5.0]   # the findings for A >= 3
PAPER_ORDER = ["disk", "rect_narrow", "square", "rect_wide", "triangle"]   # the paper's order of rise rates


# ---- the comparisons of each finding, from the cells of a scale's folders

def sinks_then_rises(sources, label, shapes, **where):
    """Finding 1 for each shape (findings.sinks_then_rises)."""
    return [c for shape in shapes
            for c in findings.sinks_then_rises(label, shape, by_period(sources, intruder__shape=shape, **where))]


def has_maximum(sources, label, shapes, **where):
    """Finding 2 for each shape that rises somewhere (findings.has_maximum)."""
    return [c for shape in shapes
            for c in findings.has_maximum(label, shape, by_period(sources, intruder__shape=shape, **where))]


def in_order(sources, label, ts, **where):
    """Finding 4 at each period: every pair of neighbours in the paper's order that has results."""
    return [c for t in ts for c in findings.in_order(
        label, t, {s: Cell(sources, intruder__shape=s, drive__period=t, **where).values() for s in PAPER_ORDER})]


def sinks(sources, label, shape, **where):
    return findings.sinks(label, shape, by_period(sources, intruder__shape=shape, **where))


def friction(sources, label, shape, **where):
    """Finding 6: each step up in mu raises the rate, over every mu the shape was run at in these sources."""
    mus = sorted({c.get("contact.mu") for s in sources for c in load(s) if c.get("intruder.shape") == shape})
    return findings.friction_steps(label, {mu: Cell(sources, intruder__shape=shape, contact__mu=mu, **where).values()
                                           for mu in mus})


def table1_range(sources, **where):
    """Finding 7 for each of the paper's shapes (findings.table1_range)."""
    return [c for shape, paper_range in PAPER_RANGE.items()
            for c in findings.table1_range(shape, by_period(sources, intruder__shape=shape, **where), paper_range)]


def small_amplitudes(sources, shape, t, direction, **where):
    """Finding 3 (findings.small_amplitudes) for a shape at period t."""
    return findings.small_amplitudes(shape, t, {a: Cell(sources, intruder__shape=shape, drive__amplitude=a, drive__period=t,
                                                        **where).values() for a in (3.0, 1.0, 0.5)}, direction)


_FINDINGS = []


def paper_findings():
    """[(number, the finding, {scale: (sigma, [comparisons])})], docs/PHYSICS.md §12."""
    if _FINDINGS:
        return _FINDINGS
    depth = depth_sigma()
    # The paper's clock: the largest standard deviation of its cells of two beds.
    clock = sigma(cells_with_beds(CLOCK_A5))
    small = sigma([Cell(SMALL_POUR, bed__pour="lattice", drive__period=t) for t in (1.0, 5.0)])
    today = SMALL_TODAY_WHERE
    _FINDINGS.extend([
        (1, "for A >= 3 the intruder sinks at short periods and rises at long ones", {
            "paper's depth": (depth, sinks_then_rises(DEPTH_A5, "A = 5", SHAPES) + sinks_then_rises(DEPTH_A3, "A = 3", SHAPES)),
            "paper's clock": (clock, sinks_then_rises(CLOCK_A5, "A = 5", SHAPES) + sinks_then_rises(CLOCK_A3, "A = 3", SHAPES)),
            "small preset": (small, [c for a in SMALL_MAP_AMPLITUDES
                                     for c in sinks_then_rises(SMALL_TODAY, f"A = {a:g}", SMALL_MAP_SHAPES,
                                                               drive__amplitude=a, **today)])}),
        (2, "the rise rate has a maximum in T", {
            "paper's depth": (depth, has_maximum(DEPTH_A5, "A = 5", SHAPES) + has_maximum(DEPTH_A3, "A = 3", SHAPES)),
            # Table 1's t = 1000 periods stop at T = 3-4, below the t = 100 grid's maxima, and figure 2's are 1 and 5
            "paper's clock": (clock, [], "not judged: its periods stop below the maxima"),
            "small preset": (small, [c for a in SMALL_MAP_AMPLITUDES
                                     for c in has_maximum(SMALL_TODAY, f"A = {a:g}", SMALL_MAP_SHAPES, drive__amplitude=a, **today)]
                             + has_maximum(SMALL_SESSION2, "A = 3 (session 2)", ["disk"]))}),
        (3, "at A = 0.5 and 1 the intruder hardly moves", {
            # the paper's way at A = 3: every shape sinks at T = 1 (finding 1); at T = 5 the disk rises and
            # the triangle sinks (findings 1 and 5)
            "paper's depth": (depth, [c for shape in SHAPES for c in small_amplitudes(DEPTH_SMALL_A + DEPTH_A3, shape, 1.0, -1)]
                              + small_amplitudes(DEPTH_SMALL_A + DEPTH_A3, "disk", 5.0, +1)
                              + small_amplitudes(DEPTH_SMALL_A + DEPTH_A3, "triangle", 5.0, -1)),
            # at A = 3 on this bed the disk sinks at T = 2 and rises at T = 5 (finding 1), the triangle sinks at both
            "small preset": (small, small_amplitudes(SMALL_TODAY, "disk", 2.0, -1, **today)
                             + small_amplitudes(SMALL_TODAY, "disk", 5.0, +1, **today)
                             + small_amplitudes(SMALL_TODAY, "triangle", 2.0, -1, **today)
                             + small_amplitudes(SMALL_TODAY, "triangle", 5.0, -1, **today))}),
        (4, "rise rates order the shapes disk > narrow rectangle > square > wide rectangle > triangle", {
            "paper's depth": (depth, in_order(DEPTH_A5, "A = 5", [3.0, 4.0, 5.0, 6.0])
                              + in_order(DEPTH_A3, "A = 3", [3.0, 4.0, 5.0, 6.0, 8.0])),
            "paper's clock": (clock, in_order(CLOCK_A5, "A = 5", [3.0, 4.0, 5.0, 6.0])
                              + in_order(CLOCK_A3, "A = 3", [3.0, 4.0, 5.0, 6.0, 8.0])),
            "small preset": (small, [c for a in SMALL_MAP_AMPLITUDES
                                     for c in in_order(SMALL_TODAY, f"A = {a:g}",
                                                       [t for t in periods(SMALL_TODAY, drive__amplitude=a, **today) if t >= 3],
                                                       drive__amplitude=a, **today)],
                             "the disk and the triangle, and at A = 3, T = 5 the square (one bed)")}),
        (5, "the triangle sinks in most of the grid", {
            "paper's depth": (depth, sinks(DEPTH_A5, "A = 5", "triangle") + sinks(DEPTH_A3, "A = 3", "triangle")),
            "paper's clock": (clock, sinks(CLOCK_A5, "A = 5", "triangle") + sinks(CLOCK_A3, "A = 3", "triangle")),
            "small preset": (small, [c for a in SMALL_MAP_AMPLITUDES
                                     for c in sinks(SMALL_TODAY, f"A = {a:g}", "triangle", drive__amplitude=a, **today)])}),
        (6, "more friction, faster rise", {
            "paper's depth": (depth, [step for shape, t in FRICTION_ROWS
                                      for step in friction(DEPTH_FRICTION, f"{shape}, A = 3, T = {t:g}", shape,
                                                           drive__period=t)]),
            "small preset": (small, friction(SMALL_FRICTION, "disk, A = 3, T = 5", "disk", drive__amplitude=3.0)
                             + friction(SMALL_FRICTION, "square, A = 3, T = 5", "square"))}),
        (7, "each shape starts rising where the paper's Table 1 says (A = 5)", {
            "paper's depth": (depth, table1_range(DEPTH_A5)),
            "paper's clock": (clock, table1_range(CLOCK_A5)),
            "small preset": (small, table1_range(SMALL_TODAY, drive__amplitude=5.0, **today))}),
    ])
    return _FINDINGS


FINDING_SOURCES = DEPTH_A5 + DEPTH_A3 + ["results/paper_depth/box", "results/paper_depth/seeds"] + CLOCK_A5 + CLOCK_A3 \
    + SMALL_POUR + SMALL_MAP \
    + DEPTH_FRICTION + DEPTH_SMALL_A + SMALL_FRICTION + SMALL_SESSION2


# ---- the blocks

def mean_text(values):
    return cell_text(values) if values else "0"


def evidence_table(spec):
    """Every comparison of every finding: the cells, the difference and its standard errors."""
    head = ["finding", "scale", "comparison (the paper's way)", "a", "b", "a - b", "standard errors, the paper's way"]
    lines = head_lines(head)
    for number, finding, scales in spec["findings"]():
        for scale, (sig, comparisons, *_) in scales.items():
            for c in filter(None, comparisons):
                diff, z, _ = findings.judged(c, sig)
                lines.append(row_line([str(number), scale, c[0], mean_text(c[1]), mean_text(c[2]),
                                         f"{diff:+.3f}", f"{z:+.1f}"]))
    return lines, spec["sources"]


def findings_table(spec):
    """One row per finding: per scale, how its comparisons came out, and the verdict by the rule."""
    scales = spec["scales"]
    head = ["paper's finding"] + [f"{s}: comparisons" for s in scales] + [f"verdict, {s}" for s in scales]
    lines = head_lines(head)
    for number, finding, by_scale in spec["findings"]():
        counts, verdicts = [], []
        for s in scales:
            sig, comparisons, *note = by_scale.get(s, (0.0, []))
            counts.append(comparisons_text(sig, comparisons, note))
            verdicts.append(findings.finding_verdict(sig, [c for c in comparisons if c], *note))
        lines.append(row_line([f"{number}. {finding}"] + counts + verdicts))
    sigmas = {s: v[0] for _, _, by_scale in spec["findings"]() for s, v in by_scale.items()}
    lines += ["", "One bed's standard deviation, sigma: " + ", ".join(f"{s} {sigmas[s]:.3f}" for s in scales) + "."]
    return lines, spec["sources"]


def comparison_beds(comparisons):
    """'1-2 beds': the fewest and most beds of the cells compared (zero, an empty b, is no cell)."""
    return beds_count([len(c.a) for c in comparisons] + [len(c.b) for c in comparisons if c.b])


def comparisons_text(sig, comparisons, note):
    """findings_table's cell: how a finding's comparisons at one scale came out by the rule (None for
    a cell without results left out), each one against named with its standard errors; the note
    after, or alone when there is no comparison."""
    comparisons = [c for c in comparisons if c]
    if not comparisons:
        return note[0] if note else "no committed results"
    outcomes = [findings.judged(c, sig) for c in comparisons]
    kinds = [o[2] for o in outcomes]
    against = [f"{c.label} ({o[1]:+.1f})" for c, o in zip(comparisons, outcomes) if o[2] == "against"]
    return (f"{len(kinds)} comparison{'s' if len(kinds) > 1 else ''} of cases of {comparison_beds(comparisons)}: "
            f"{kinds.count('for')} the paper's way by >= {RESOLVED:g} standard errors, "
            f"{kinds.count('within')} within {RESOLVED:g}, {kinds.count('against')} against"
            + (": " + "; ".join(against) if against else "") + (f" ({note[0]})" if note else ""))


def verdict_cell(sig, comparisons, note):
    """The answer page's cell of a finding at one scale: its verdict, bold, with the counts that decide
    it (findings.verdict_words) and the beds of its cells."""
    comparisons = [c for c in comparisons if c]
    verdict = findings.finding_verdict(sig, comparisons, *note)
    if not comparisons:
        return verdict
    kinds = [findings.judged(c, sig)[2] for c in comparisons]
    assert findings.verdict(kinds) == verdict, (verdict, kinds)
    said = findings.verdict_words(kinds)
    return f"**{verdict}**{said[len(verdict):]} ({comparison_beds(comparisons)})"


def answer_findings(spec):
    """The paper's findings: the verdict at each scale with its count of comparisons."""
    scales = [("paper's clock", "paper's clock (t = 100-1000)"), ("paper's depth", "paper's depth (t = 10-100)"),
              ("small preset", "small preset (25 d deep)")]
    head = ["the paper's finding"] + [label for _, label in scales]
    lines = head_lines(head)
    for number, finding, by_scale in paper_findings():
        row = [f"{number}. {finding}"]
        for scale, _ in scales:
            sig, comparisons, *note = by_scale.get(scale, (0.0, []))
            row.append(verdict_cell(sig, comparisons, note))
        lines.append(row_line(row))
    lines += ["", f"(a comparison counts for or against the paper at >= {RESOLVED:g} standard errors; by study/FINDINGS.md's "
              f"rule one sigma per scale serves every shape, by the paper's clock {findings_clock_sigma():.3f}, the largest "
              "over its cells of two beds, where the tables above take each shape's own; the rule and every comparison: "
              "study/FINDINGS.md)"]
    return lines, spec["sources"]


def against_findings(shape):
    """The numbers of the findings that a comparison of this shape goes against by the paper's clock
    (study/FINDINGS.md's rule)."""
    numbers = []
    for number, _, by_scale in paper_findings():
        sig, comparisons, *_ = by_scale.get("paper's clock", (0.0, []))
        if any(c.label.startswith(shape) and findings.judged(c, sig)[2] == "against" for c in comparisons if c):
            numbers.append(number)
    return numbers


TABLES = [
    {"name": "findings", "kind": findings_table, "findings": paper_findings, "scales": ["paper's depth", "paper's clock", "small preset"],
     "sources": FINDING_SOURCES},
    {"name": "findings_evidence", "kind": evidence_table, "findings": paper_findings, "sources": FINDING_SOURCES},
    {"name": "answer_findings", "kind": answer_findings, "sources": FINDING_SOURCES},
]
