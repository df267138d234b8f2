"""One bed's scatter as the documents take it, and a cell read against it in words.

Two rules, both findings.py's statistics: the findings (study/FINDINGS.md) take one sigma per scale,
the largest standard deviation over the scale's cells of two beds (findings.largest_sd); the
answer's tables by the paper's clock take each shape's own, pooled over its cells of two beds
(findings.shape_scatter). Here the cells are gathered from the committed results and the numbers
put into the words the blocks share.
"""
import functools

import findings
from cases import (CLOCK_A5, COUPLING, PAPER_RANGE, SHAPES, Cell, beds, beds_count, committed, load, mean)
from findings import RESOLVED


# ---- the findings' one sigma per scale

def sigma(cells):
    """One bed's standard deviation at a scale: the largest over the given cells, each of several beds."""
    return findings.largest_sd([c.values() for c in cells])


def cells_with_beds(sources):
    """Every (shape, A, T) cell of these sources that has two or more beds."""
    keys = {(c.get("intruder.shape"), c.get("drive.amplitude"), c.get("drive.period")) for s in sources for c in load(s)}
    cells = [Cell(sources, intruder__shape=s, drive__amplitude=a, drive__period=t) for s, a, t in sorted(keys)]
    return [c for c in cells if len(c.values()) >= 2]


def depth_sigma():
    """One bed's standard deviation at the paper's depth: the disk at A = 3, T = 3 on the box study's beds."""
    return sigma([Cell(["results/paper_depth/box", "results/paper_depth/seeds"], intruder__shape="disk",
                       box__width=60.0, drive__period=3.0)])


def findings_clock_sigma():
    """The findings' one sigma by the paper's clock (study/FINDINGS.md's rule: the largest over its cells
    of two beds, for every shape)."""
    return sigma(cells_with_beds(CLOCK_A5))


# ---- each shape's own sigma by the paper's clock

SHAPE_NAMES = {"disk": "disk (OS1)", "square": "square (OS2)", "rect_narrow": "narrow rectangle (OS3)",
               "rect_wide": "wide rectangle (OS4)", "triangle": "triangle (OS5)"}


def short_name(shape):
    return SHAPE_NAMES[shape].split(" (")[0]


# One bed's scatter by the paper's clock, shape by shape (issue 79): pooled over the shape's cells of
# two beds or more among the clock's runs in the 60 d box on beds poured for them: Table 1's
# (CLOCK_A5), the factor screen's (each of its rows a new pour) and the coupling screen's new pours of
# a locked body (its baseline's extra beds: those cases of COUPLING with no bed.file and the coupling
# keys at LOCKED_BODY; its other cases ran on the screen's beds, or turn, whose scatter is their own).
# Left out: the glued mass's runs (results/paper_depth/mass_t1000), on the baseline's own beds, whose
# deviations from their mean repeat the baseline's beds' (counted twice they would count as
# independent); the paper's 300 d box, one bed a cell. A shape without a cell of two beds takes the
# pool over every shape's cells (findings.shape_scatter), and the text says so.
CLOCK_SCATTER = CLOCK_A5 + ["results/paper_depth/factors_t1000"] + COUPLING
SCATTER_KEYS = ("intruder.shape", "drive.amplitude", "drive.period", "intruder.surface", "bed.pour",
                "intruder.mass_rule", "box.width")   # what makes a cell besides its bed
LOCKED_BODY = {"intruder.contact_mass": "body", "intruder.rotation": "locked", "drive.form": "displacement"}


def scatter_cases(source):
    """The finished cases of a source that count in the clock's scatter: every one, but of the coupling
    screen only its new pours of a locked body (CLOCK_SCATTER's note)."""
    if source not in COUPLING:
        return load(source)
    return [c for c in load(source) if c.pours_own_bed() and all(c.get(k) == v for k, v in LOCKED_BODY.items())]


@functools.lru_cache(maxsize=None)
def clock_scatter():
    """{shape: findings.Scatter}: one bed's V_y standard deviation by the paper's clock per shape."""
    groups = {}
    for source in committed(CLOCK_SCATTER):
        for c in scatter_cases(source):
            groups.setdefault(tuple(c.get(k) for k in SCATTER_KEYS), []).append(c)
    cells = {shape: [] for shape in SHAPES}
    for key in sorted(groups, key=str):
        cells.setdefault(key[0], []).append([float(c.get("vy")) for c in beds(groups[key], f"{CLOCK_SCATTER} {key}")])
    return findings.shape_scatter(cells)


def clock_sigma(shape):
    """One bed's sigma of a shape by the paper's clock (clock_scatter)."""
    return clock_scatter()[shape].sigma


def scatter_text(shape):
    """'0.0024 (5 dof)': a shape's sigma by the paper's clock and its degrees of freedom."""
    s = clock_scatter()[shape]
    return f"{s.sigma:.4f} ({s.dof} dof" + ("" if s.own else ": no cell of its own with two beds, every shape's pool") + ")"


def scatter_words(shapes):
    """How the clock's sigma of these shapes is made, each value with its degrees of freedom, and what
    2 standard errors are worth with so few: words for a caption."""
    scatter = clock_scatter()
    dofs = sorted({scatter[s].dof for s in shapes})
    student = ", ".join(f"{findings.t_critical(d):.2f} se for {d} dof" for d in dofs)
    return ("one bed's standard deviation of the shape by the paper's clock, pooled over the shape's cells "
            "of two beds or more (Table 1's runs, the factor screen's new pours and the coupling screen's new pours "
            "of the locked body in the 60 d box; the glued "
            "mass's runs, on the baseline's own beds, left out; dof: its degrees of freedom, the beds less one "
            "per cell): " + ", ".join(f"{short_name(s)} {scatter_text(s)}" for s in shapes)
            + f". The rule stays {RESOLVED:g} se whatever the dof; with so few it is a weaker test than it reads "
            f"(Student's t puts the two-sided 95 % at {student})")


# ---- a cell in standard errors of its shape's sigma, and its side of zero against the paper's

def z_of(values, shape):
    """A cell's V_y in standard errors from zero by its shape's sigma (findings.z_from_zero)."""
    return findings.z_from_zero(values, clock_sigma(shape))


def student_note(z, shape):
    """'under Student's t 4.30 for its 2 dof' where |z| is resolved by the rule yet below Student's
    two-sided 95 % value for the shape's sigma's degrees of freedom, else ''."""
    s = clock_scatter()[shape]
    t = findings.below_student(z, s.dof)
    return f"under Student's t {t:.2f} for its {s.dof} dof" if t is not None else ""


def beds_z_text(values, shape):
    """'+0.019 (2 beds, +11.2 se)': a cell's mean, its beds and its standard errors from zero by its
    shape's sigma by the paper's clock."""
    z = z_of(values, shape)
    note = student_note(z, shape)
    return (f"{mean(values):+.3f} ({beds_count([len(values)])}, {z:+.1f} se"
            + (f"; {note})" if note else ")"))


SIDE = {+1: "rising", -1: "sinking", 0: "level within the scatter"}   # a cell's side of zero
# The paper's Table 1 at a period (findings.paper_side): rising at or above its observed range, not
# rising at or below it (its bracket says where rising starts, not that the intruder sinks below it)
PAPER_SIDE = {+1: "rising", -1: "not rising"}


def paper_reading(values, shape, period):
    """'rising, where the paper has it not rising', 'not rising, as the paper': a cell of the paper's clock
    read against the paper's Table 1 at its period, by its shape's sigma; inside the paper's range,
    where the paper does not say, the cell's side of zero."""
    return reading_words(values, clock_sigma(shape), findings.paper_side(period, PAPER_RANGE[shape]))


def reading_words(values, sig, paper):
    """paper_reading's words for a cell judged by sig where the paper's Table 1 is on side `paper`
    (findings.paper_side: +1 rising, -1 not rising, 0 inside its range)."""
    side = findings.cell_side(values, sig)
    if paper == 0:
        return f"{SIDE[side]}, inside the paper's range"
    mine = "rising" if side > 0 else "not rising"
    return f"{mine}, " + ("as the paper" if findings.on_paper_side(values, sig, paper)
                          else f"where the paper has it {PAPER_SIDE[paper]}")
