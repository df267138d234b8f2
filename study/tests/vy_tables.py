#!/usr/bin/python3
"""The documents' V_y tables are what study/tools/vy_tables.py makes from the committed results.

    vy_tables.py

Fails (exit 1, one line per changed table line) when a table between `<!-- vy_tables: NAME -->`
markers in the documents of vy_tables.DOCUMENTS (study/VALIDATION.md, study/FINDINGS.md,
docs/PERFORMANCE.md, README.md, results/*/README.md) differs from what the script makes from
results/, when a marker names no declared table or a declared table has no markers. Fix: run
`study/tools/vy_tables.py` and commit the documents. First it checks that the check can fail: a
document with one digit of a table changed must be reported, and the phase profile's harmonics
must give back those of a made-up profile, a change resolved on sigma but not on its own beds'
larger scatter must be shown within the scatter, and the words for the paper's side and for a rate
through its window must follow their rules.
"""
import math
import os
import sys

ROOT = os.path.dirname(os.path.dirname(os.path.dirname(os.path.abspath(__file__))))
sys.path.insert(0, os.path.join(ROOT, "study", "tools"))
import vy_tables  # noqa: E402


def check_can_fail():
    """A changed digit inside a marked table must be replaced by the regeneration."""
    spec = vy_tables.TABLES[0]
    table = vy_tables.render(spec)
    text = "\n".join([f"<!-- vy_tables: {spec['name']} -->"] + table + [f"<!-- /vy_tables: {spec['name']} -->"])
    row = next(i for i, line in enumerate(table) if line.startswith("| ") and any(ch.isdigit() for ch in line))
    digit = next(ch for ch in table[row] if ch.isdigit())
    changed = text.replace(table[row], table[row].replace(digit, str((int(digit) + 1) % 10), 1))
    tables = {spec["name"]: table}
    again, problems = vy_tables.marked.regenerate(changed, tables, "self-test", "vy_tables")
    return [] if again == text and again != changed and not problems else ["self-test: a changed table went unnoticed"]


class MadeUpProfile:
    """A stand-in case whose phase_rates.csv is 0.05 + 0.2 cos(2 (phi - peak)) + 0.1 cos(phi - 1), 20 bins."""
    peak = 3.3   # 10 phi / pi

    def phase_rates(self):
        centres = [k + 0.5 for k in range(20)]
        peak = self.peak * math.pi / 10
        return centres, [0.05 + 0.2 * math.cos(2 * (c * math.pi / 10 - peak)) + 0.1 * math.cos(c * math.pi / 10 - 1)
                         for c in centres]


def check_phase_profile():
    p = vy_tables.PhaseProfile(MadeUpProfile())
    got = (p.mean, p.half, p.half_peak, p.whole, p.rest)
    want = (0.05, 0.2, MadeUpProfile.peak, 0.1, 0.0)
    return [] if all(abs(a - b) < 1e-12 for a, b in zip(got, want)) else [f"PhaseProfile: {got}, not {want}"]


def check_own_scatter():
    """A change of 0.0205 is 2.6 se on sigma 0.008 (2 beds a side); when one side's 2 beds scatter by a
    standard deviation of 0.019 the change is not resolved (1.1 se by that) and is shown within the
    scatter; when they agree it stands."""
    problems = []
    base = [-0.047, -0.039]
    scattered = vy_tables.findings.Comparison("t", [-0.036, -0.009], base, +1)
    agreeing = vy_tables.findings.Comparison("t", [-0.022, -0.023], base, +1)
    for comparison, want in ((scattered, "1.1 se by its 2 beds' own scatter"), (agreeing, "")):
        z = vy_tables.findings.judged(comparison, 0.008)[1]
        got = vy_tables.own_scatter_caveat(comparison, z, 0.008)
        if z < 2.0 or (want not in got if want else got):
            problems.append(f"own_scatter_caveat: {comparison.a} against {base}: z = {z}, {got!r}")
    return problems


def check_words():
    """The paper's Table 1 says "not rising" at or below its range, not "sinking": a cell level within
    the scatter there is on the paper's side, and not where the paper has it rising; a rate that falls
    under a quarter of the first half's in the second is said to stall."""
    problems = []
    for values, paper, want in (([-0.001], -1, True), ([-0.05], -1, True), ([0.05], -1, False),
                                ([-0.001], +1, False), ([0.05], +1, True)):
        if vy_tables.on_paper_side(values, 0.01, paper) != want:
            problems.append(f"on_paper_side({values}, 0.01, {paper}) is not {want}")
    for first, second, want in ((0.070, 0.008, "then stalls"), (-0.026, -0.056, "then faster"),
                                (0.05, 0.03, "then slower"), (0.05, -0.03, "then turns back")):
        if vy_tables.course_words(first, second) != want:
            problems.append(f"course_words({first}, {second}) is not {want!r}")
    return problems


def main():
    problems = (check_can_fail() + check_phase_profile() + check_own_scatter() + check_words()
                + vy_tables.run(check=True))
    for p in problems:
        print(p)
    print(f"vy_tables: {len(problems)} differences between the documents' tables and results/")
    sys.exit(1 if problems else 0)


if __name__ == "__main__":
    main()
