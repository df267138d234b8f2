"""The statistics behind the paper's findings (docs/PHYSICS.md §12, study/FINDINGS.md): pure functions
of the beds' V_y values, no files read. study/tools/vy_tables.py's modules gather the values from
results/ and print what these decide; study/tests/test_findings.py tests them on small made-up
tables. Every number the documents' blocks compute from the values (a mean, a standard error, a
scatter, a change in standard errors, a slope, a phase profile's harmonics) is computed here.

A cell is the beds of one case, a list of V_y values (one per bed). A comparison is a cell against
another cell or against zero, with the direction the paper's finding predicts. Its difference is
counted in standard errors, se = sigma sqrt(1/n_a + 1/n_b) (n: beds; 1/n_b = 0 against zero), where
sigma is one bed's standard deviation: for the findings, one per scale (largest_sd over the scale's
cells of several beds); for a comparison within one shape, that shape's (shape_scatter: pooled over
its cells of several beds, with its degrees of freedom); or a cell's own when it has
OWN_SCATTER_BEDS beds or more and they scatter more. A comparison
goes "for" the paper at >= RESOLVED standard errors its way (as printed, to 0.1), "against" at
>= RESOLVED the other way, else "within". A finding at a scale is "reproduced" when every comparison
goes for it, "not reproduced" when one goes against, "not resolved" otherwise, "not judged" when a
note says why it has no comparisons, "not measured" when nothing bears on it.

    comparison = compare(label, a, b, direction)      # b None: against zero; None when a cell is empty
    difference, z, outcome = judged(comparison, sigma)
    finding_verdict(sigma, [comparison, ...], note)   # 'reproduced', 'not reproduced', ...
    shape_scatter({shape: [cell, ...]})               # {shape: Scatter(sigma, dof, cells, own)}

The rule stays RESOLVED = 2 standard errors whatever sigma's degrees of freedom. With few of them
2 se is a weaker test than it reads (a sigma from 2 degrees of freedom: Student's t puts the
two-sided 95 % at 4.30 se, from 5 at 2.57); t_critical(dof) gives that value, for the documents to
print beside a sigma and its degrees of freedom.
"""
import math
from typing import NamedTuple

RESOLVED = 2.0          # standard errors
OWN_SCATTER_BEDS = 3    # a cell of this many beds or more also has a standard deviation of its own


# ---- a cell's numbers

def mean(values):
    return sum(values) / len(values)


def sd(values):
    """The standard deviation of a sample (n - 1)."""
    m = mean(values)
    return math.sqrt(sum((v - m) ** 2 for v in values) / (len(values) - 1))


def stats(values):
    """mean, standard error of the mean (nan for one value)."""
    return mean(values), sd(values) / math.sqrt(len(values)) if len(values) > 1 else float("nan")


def largest_sd(cells):
    """One bed's standard deviation at a scale: the largest over the given cells, each of several beds."""
    return max(sd(values) for values in cells)


def side_sigma(values, sig):
    """One bed's standard deviation for a cell: the scale's sigma, or the cell's own when it has
    OWN_SCATTER_BEDS beds or more and they scatter more (a cell never counts as better known than
    its own beds show)."""
    return max(sig, sd(values)) if len(values) >= OWN_SCATTER_BEDS else sig


# ---- comparisons and their outcomes

class Comparison(NamedTuple):
    """a's beds against b's (b empty: against zero); direction +1 when the paper has a > b."""
    label: str
    a: list
    b: list
    direction: int


def compare(label, a, b, direction):
    """A comparison of cell a with cell b (b None: with zero); None when a cell has no results."""
    if not a or (b is not None and not b):
        return None
    return Comparison(label, list(a), list(b) if b is not None else [], direction)


def resolved_side(z):
    """+1 when z standard errors are at least RESOLVED above zero, -1 at least RESOLVED below, else 0."""
    return +1 if z >= RESOLVED else -1 if z <= -RESOLVED else 0


def judged(comparison, sig):
    """(difference a - b, standard errors in the paper's direction, 'for' / 'against' / 'within')."""
    _, a, b, direction = comparison
    diff = mean(a) - (mean(b) if b else 0.0)
    se = math.sqrt(side_sigma(a, sig) ** 2 / len(a) + (side_sigma(b, sig) ** 2 / len(b) if b else 0.0))
    z = round(direction * diff / se, 1)   # judged as printed, to 0.1
    return diff, z, {+1: "for", -1: "against", 0: "within"}[resolved_side(z)]


def z_from_zero(values, sig):
    """A cell's mean in standard errors from zero (positive: rising), as judged() prints it."""
    return judged(Comparison(None, values, [], 1), sig)[1]


def cell_side(values, sig):
    """A cell's side of zero by the rule: +1 rising, -1 sinking, 0 within the scatter."""
    return resolved_side(z_from_zero(values, sig))


def on_paper_side(values, sig, paper_sign):
    """Whether a cell says what the paper's Table 1 says at its period (paper_sign, paper_side's):
    rising where the paper has it rising (+1), not rising (sinking or level within the scatter) where
    the paper has it not rising (-1); the paper's Table 1 says "not rising" at or below its range,
    not "sinking"."""
    return (cell_side(values, sig) > 0) == (paper_sign > 0)


def own_scatter_judged(comparison, z, sig):
    """A change resolved on sig (z: its standard errors, judged()'s) whose side of 2 to
    OWN_SCATTER_BEDS - 1 beds, too few for judged() to count their own scatter, scatters more than
    sig and by that larger standard deviation would not be resolved: (that side, "a" or "b"; its beds;
    its standard deviation; the change's standard errors by it). None otherwise. Such a change is
    shown within the scatter: a cell is never shown as better known than its own beds show, even
    before judged() counts them."""
    few = [(sd(v), side, len(v)) for v, side in ((comparison.a, "a"), (comparison.b, "b"))
           if 2 <= len(v) < OWN_SCATTER_BEDS]
    own, side, n = max(few, default=(0.0, "", 0))
    if resolved_side(z) == 0 or own <= sig:
        return None
    z_own = judged(comparison, own)[1]
    if resolved_side(z_own) != 0:
        return None
    return side, n, own, z_own


VERDICTS = ("reproduced", "not reproduced", "not resolved", "not judged", "not measured")


def verdict(outcomes):
    """A finding's verdict from its comparisons' outcomes."""
    if not outcomes:
        return "not measured"
    if "against" in outcomes:
        return "not reproduced"
    return "reproduced" if all(o == "for" for o in outcomes) else "not resolved"


def verdict_words(outcomes):
    """The verdict with the counts that decide it, so that it reads as its rule: 'not reproduced: 2 of 20
    against (12 for, 6 within)', 'reproduced: all 4 for', 'not resolved: none against, 3 of 8 within
    (5 for)'; the bare verdict without outcomes."""
    said = verdict(outcomes)
    n, f, w, a = len(outcomes), outcomes.count("for"), outcomes.count("within"), outcomes.count("against")
    if said == "not reproduced":
        return f"{said}: {a} of {n} against ({f} for, {w} within)"
    if said == "reproduced":
        return f"{said}: all {n} for"
    if said == "not resolved":
        return f"{said}: none against, {w} of {n} within ({f} for)"
    return said


def finding_verdict(sig, comparisons, note=None):
    """The verdict of a finding at one scale: its comparisons (None for a cell without results is
    left out) judged with that scale's sigma; "not judged" when it has none and a note says why."""
    outcomes = [judged(c, sig)[2] for c in comparisons if c]
    return "not judged" if note and not outcomes else verdict(outcomes)


# ---- the findings' comparisons, from a shape's cells by period ({T: values}, T ascending)

def sinks_then_rises(label, shape, by_period):
    """Finding 1: it sinks at its shortest period run and rises at the period of its largest rate
    among the longer ones (the largest of several: a selection that favours rising)."""
    ts = sorted(by_period)
    if len(ts) < 2:
        return []
    top = max(ts[1:], key=lambda t: mean(by_period[t]))
    largest = f", its largest of T = {ts[1]:g}-{ts[-1]:g}" if len(ts) > 2 else ""
    return [compare(f"{shape}, {label}: sinks at T = {ts[0]:g}, its shortest", by_period[ts[0]], None, -1),
            compare(f"{shape}, {label}: rises at T = {top:g}{largest}", by_period[top], None, +1)]


def has_maximum(label, shape, by_period):
    """Finding 2, for a shape that rises somewhere: its largest rate over the shorter periods above
    its rate at the longest period run (when the longest has the largest rate, the comparison goes
    against the finding, as it should, instead of comparing a cell with itself)."""
    ts = sorted(by_period)
    if len(ts) < 2 or not max(mean(by_period[t]) for t in ts) > 0:
        return []
    top = max(ts[:-1], key=lambda t: mean(by_period[t]))
    return [compare(f"{shape}, {label}: largest of the shorter periods, at T = {top:g}, above T = {ts[-1]:g}, "
                    "the longest", by_period[top], by_period[ts[-1]], +1)]


def small_amplitudes(shape, t, by_amplitude, direction):
    """Finding 3: A = 3 moves the intruder further than A = 1 and 0.5 do, the way (direction) it goes
    at A = 3 in the paper; by_amplitude {A: values} at period t."""
    way = "above" if direction > 0 else "below"
    return [compare(f"{shape}, T = {t:g}: A = 3 {way} A = {a:g}", by_amplitude.get(3.0, []), by_amplitude.get(a, []),
                    direction) for a in (1.0, 0.5)]


def in_order(label, t, by_shape):
    """Finding 4 at one period: every pair of neighbours that has results, by_shape {shape: values}
    in the paper's order of rise rates."""
    present = [s for s, values in by_shape.items() if values]
    return [compare(f"{label}, T = {t:g}: {a} above {b}", by_shape[a], by_shape[b], +1)
            for a, b in zip(present, present[1:])]


def sinks(label, shape, by_period):
    """Finding 5: it sinks at every period run."""
    return [compare(f"{shape}, {label}: sinks at T = {t:g}", by_period[t], None, -1) for t in sorted(by_period)]


def friction_steps(label, by_mu):
    """Finding 6: each step up in mu raises the rate; by_mu {mu: values} (empty where not run)."""
    mus = sorted(by_mu)
    return [compare(f"{label}: mu = {b:g} above mu = {a:g}", by_mu[b], by_mu[a], +1) for a, b in zip(mus, mus[1:])]


def paper_side(period, paper_range):
    """The side of zero on which the paper's Table 1 puts V_y at a period: -1 (not rising) at or below
    its observed range (lo, hi), +1 (rising) at or above it, 0 inside it (the paper does not say)."""
    lo, hi = paper_range
    return -1 if period <= lo else +1 if period >= hi else 0


def table1_range(shape, by_period, paper_range):
    """Finding 7: not rising at the paper's lower end, rising at its upper end (paper_range (lo, hi));
    where a scale did not run that period, the nearest period it ran on the far side of the range
    (below the lower end, above the upper), where the paper's range says the same."""
    lo, hi = paper_range
    ts = sorted(by_period)
    below, above = [t for t in ts if paper_side(t, paper_range) < 0], [t for t in ts if paper_side(t, paper_range) > 0]
    out = []
    if below:
        t = below[-1]
        end = "the paper's lower end" if t == lo else f"below the paper's lower end, {lo:g}"
        out.append(compare(f"{shape}: not rising at T = {t:g} ({end})", by_period[t], None, -1))
    if above:
        t = above[0]
        end = "the paper's upper end" if t == hi else f"above the paper's upper end, {hi:g}"
        out.append(compare(f"{shape}: rising at T = {t:g} ({end})", by_period[t], None, +1))
    return out


# ---- brackets: where V_y leaves zero, against the paper's range

def first_rise(cells, sig):
    """(T below, T) for cells [(T, values)] in ascending T: the first period whose V_y is >= RESOLVED
    standard errors above zero and the period run below it (None when it is the shortest run);
    (None, None) when none rises."""
    for i, (t, values) in enumerate(cells):
        if z_from_zero(values, sig) >= RESOLVED:
            return (cells[i - 1][0] if i else None), t
    return None, None


def first_resolved(cells, sig):
    """(key below, key, +1 rising / -1 sinking) for cells [(key, values)] in ascending key: the first
    whose V_y is >= RESOLVED standard errors from zero either way, and the key measured below it (None
    when it is the first); None when none is."""
    for i, (key, values) in enumerate(cells):
        if abs(z_from_zero(values, sig)) >= RESOLVED:
            return (cells[i - 1][0] if i else None), key, (+1 if mean(values) > 0 else -1)
    return None


def against_range(lo, hi, paper_range):
    """How a bracket (lo, hi) of first_rise stands against the paper's range: text, "**yes**..." when
    it agrees, "**no**..." when it does not."""
    plo, phi = paper_range
    if hi is None:
        return "**no**: no rise at any period run"
    if lo is None:
        # Rising at the shortest period run: below the paper's range when the paper's intruder does not
        # rise there yet; otherwise the runs do not tell where the rise begins.
        return "**no**: below the paper's range" if hi <= plo else "rises already at the shortest period run"
    if (lo, hi) == (plo, phi):
        return "**yes**: the paper's range"
    if lo >= plo and hi <= phi:
        return "**yes**: inside the paper's range"
    if max(lo, plo) < min(hi, phi):
        return "overlaps the paper's range"
    return "**no**: below the paper's range" if hi <= plo else "**no**: above the paper's range"


# ---- paired changes (the same bed at two values of a key)

def pooled_sd(changes):
    """(one bed's standard deviation of a change pooled over the groups of two or more changes, its
    degrees of freedom, the number of such groups); the deviation is 0.0 when no group has two."""
    groups = [d for d in changes if len(d) >= 2]
    dof = sum(len(d) - 1 for d in groups)
    return (math.sqrt(sum((x - mean(d)) ** 2 for d in groups for x in d) / dof) if dof else 0.0), dof, len(groups)


def change_z(changes, spread):
    """A cell's mean change in standard errors (spread / sqrt(beds)) from zero."""
    return mean(changes) / (spread / math.sqrt(len(changes)))


def change_resolved(changes, spread):
    """Whether a cell's mean change is >= RESOLVED standard errors (spread / sqrt(beds)) from zero."""
    return bool(changes) and abs(mean(changes)) >= RESOLVED * spread / math.sqrt(len(changes))


# ---- one bed's scatter per shape

def pooled_scatter(cells):
    """(sigma, degrees of freedom, cells counted) of one bed, pooled over the cells of two beds or
    more: sigma = sqrt(sum over cells of sum (x - the cell's mean)^2 / dof), dof = sum (n_cell - 1);
    (nan, 0, 0) when no cell has two beds (cells of one bed tell nothing of the scatter)."""
    sigma, dof, counted = pooled_sd(cells)
    return (sigma if dof else math.nan), dof, counted


class Scatter(NamedTuple):
    """One bed's standard deviation for a shape: sigma, its degrees of freedom, the cells pooled, and
    own: True when pooled over the shape's own cells, False when the shape has no cell of two beds
    and takes the pool over every shape's cells."""
    sigma: float
    dof: int
    cells: int
    own: bool


def shape_scatter(cells_by_shape):
    """{shape: Scatter} from {shape: [cell, ...]} (a cell: its beds' values): each shape's
    pooled_scatter over its own cells of two beds or more; a shape with none takes the pool over
    every shape's cells (own False), nan with 0 degrees of freedom when no shape has one. Unlike
    largest_sd, which takes the most scattered cell of a scale for every shape, a shape that scatters
    little is not judged by another shape's scatter, nor one that scatters much by the scale's
    quietest cells."""
    every = pooled_scatter([cell for cells in cells_by_shape.values() for cell in cells])
    scatter = {}
    for shape, cells in cells_by_shape.items():
        own = pooled_scatter(cells)
        scatter[shape] = Scatter(*own, True) if own[1] else Scatter(*every, False)
    return scatter


def _t_within(t, dof):
    """P(|T| < t) for Student's t with an integer number of degrees of freedom (Abramowitz and
    Stegun 26.7.3 and 26.7.4, exact)."""
    theta = math.atan(t / math.sqrt(dof))
    c2, s = math.cos(theta) ** 2, math.sin(theta)
    if dof % 2 == 0:
        term = total = 1.0
        for k in range(1, dof // 2):
            term *= c2 * (2 * k - 1) / (2 * k)
            total += term
        return s * total
    if dof == 1:
        return 2 * theta / math.pi
    term = total = 1.0
    for k in range(1, (dof - 1) // 2):
        term *= c2 * (2 * k) / (2 * k + 1)
        total += term
    return 2 / math.pi * (theta + s * math.cos(theta) * total)


def t_critical(dof, level=0.95):
    """Student's t two-sided critical value: |T| < t_critical with probability `level` for dof
    degrees of freedom (inf for none). What 2 standard errors would have to be to hold at `level`
    with a sigma estimated from dof degrees of freedom: 12.71 for 1, 4.30 for 2, 2.57 for 5."""
    if dof < 1:
        return math.inf
    lo, hi = 0.0, 1.0
    while _t_within(hi, dof) < level:
        lo, hi = hi, 2 * hi
    for _ in range(100):
        mid = (lo + hi) / 2
        lo, hi = (mid, hi) if _t_within(mid, dof) < level else (lo, mid)
    return (lo + hi) / 2


def below_student(z, dof, level=0.95):
    """Student's two-sided critical value for dof degrees of freedom when |z| standard errors are
    resolved by the rule (>= RESOLVED) yet below it, else None: a difference the rule counts that a
    sigma from so few degrees of freedom does not hold at `level`."""
    t = t_critical(dof, level)
    return t if RESOLVED <= abs(z) < t else None


# ---- where V_y changes sign, as the paper reads it (by the mean, not by standard errors)

def crossing_against_range(lo, hi, paper_range):
    """How a sign crossing (lo: the last period with mean V_y <= 0, hi: the next; lo None when V_y is
    positive already at the shortest period run, hi None when it never turns positive) stands against
    the paper's observed range (plo, phi): -1 at or below the paper's lower end (hi <= plo), +1 at or
    above its upper end (lo >= phi, or no crossing at periods reaching phi), 0 overlapping the range,
    None when the runs cannot tell (positive already at a shortest period above plo, or never positive
    at periods that stop below phi)."""
    plo, phi = paper_range
    if hi is None:
        return +1 if lo is not None and lo >= phi else None
    if hi <= plo:
        return -1
    if lo is None:
        return None
    return +1 if lo >= phi else 0


# ---- a run's rate and its phase profile

def least_squares_slope(ts, ys):
    """The least-squares slope of ys against ts."""
    n = len(ts)
    mt, my = sum(ts) / n, sum(ys) / n
    return sum((t - mt) * (y - my) for t, y in zip(ts, ys)) / sum((t - mt) ** 2 for t in ts)


class Harmonics(NamedTuple):
    """A phase profile v(phi) = mean + whole cos(phi - a1) + half cos(2 phi - a2) + the rest: `half`
    largest at `half_peak` and half_peak + 10 (in 10 phi / pi); `rest`, the rms per bin of what the
    mean and the first two harmonics leave."""
    mean: float
    whole: float
    half: float
    half_peak: float
    rest: float


def phase_harmonics(centres, bins):
    """The Harmonics of mean v_y per phase bin, bins at centres given as 10 phi / pi over a whole cycle."""
    n = len(bins)
    phis = [c * math.pi / 10 for c in centres]
    average = sum(bins) / n

    def harmonic(k):
        return complex(sum(v * math.cos(k * p) for v, p in zip(bins, phis)),
                       sum(v * math.sin(k * p) for v, p in zip(bins, phis))) * 2 / n
    h1, h2 = harmonic(1), harmonic(2)
    half_peak = (10 / math.pi * math.atan2(h2.imag, h2.real) / 2) % 10
    fit = [average + abs(h1) * math.cos(p - math.atan2(h1.imag, h1.real))
           + abs(h2) * math.cos(2 * p - math.atan2(h2.imag, h2.real)) for p in phis]
    rest = math.sqrt(sum((v - f) ** 2 for v, f in zip(bins, fit)) / n)
    return Harmonics(average, abs(h1), abs(h2), half_peak, rest)
