#!/usr/bin/python3
"""V_y per shape and period of one amplitude as a markdown table, from a sweep's results: Table 1
(A = 5) and figure 5 (A = 3) of the paper alike, for a sweep directory while it runs (the documents'
tables are made by study/tools/vy_tables.py; this uses its Table 1 kind, table_kinds.shape_by_period).
Per shape: the cavity model's T_rise and T_max (its saturation period, where its V_y(T) stops
growing), the paper's observed Table 1 range (A = 5 only: the paper tabulates no other amplitude),
V_y at every period (one bed's, or the mean +- standard error over the beds), wiggle's T_rising (the
paper's reading: the last period with V_y <= 0 and the next, interpolated; wiggleplot's t_rising)
and the period of the largest V_y.

    study/tools/table1_markdown.py SWEEP_DIR_OR_RESULTS_FOLDER

The model's periods come from each case's model.json. A folder whose finished cases mix amplitudes
is refused: one table, one amplitude.
"""
import os
import sys

sys.path.insert(0, os.path.dirname(os.path.abspath(__file__)))
from cases import load  # noqa: E402
from table_kinds import pivot, shape_by_period  # noqa: E402

PAPER_AMPLITUDE = 5.0   # the amplitude of the paper's Table 1


def table(folder):
    folder = os.path.abspath(folder)
    amplitudes = {c.get("drive.amplitude") for c in load(folder)}
    if len(amplitudes) > 1:
        raise ValueError(f"{folder}: cases at amplitudes {sorted(amplitudes)}; one table is one amplitude")
    spec = shape_by_period("table1_markdown", [folder], {}, amplitudes == {PAPER_AMPLITUDE})
    return "\n".join(pivot(spec)[0])


def main():
    if len(sys.argv) != 2:
        usage = next(line.strip() for line in __doc__.splitlines() if "table1_markdown.py" in line)
        print("usage: " + usage, file=sys.stderr)
        sys.exit(2)
    try:
        print(table(sys.argv[1]))
    except (OSError, ValueError, KeyError) as e:
        print(f"table1_markdown: {e}", file=sys.stderr)
        sys.exit(2)


if __name__ == "__main__":
    main()
