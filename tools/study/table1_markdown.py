#!/usr/bin/python3
"""V_y per shape and period of one amplitude as a markdown table, from a sweep's results: Table 1
(A = 5) and figure 5 (A = 3) of the paper alike. Per shape: the cavity model's T_rise and T_max
(its saturation period, where its V_y(T) stops growing), the paper's observed Table 1 range (A = 5
only: the paper tabulates no other amplitude), V_y at every period, wiggle's T_rising (the paper's
reading: the last period with V_y <= 0 and the next, interpolated; wiggleplot's t_rising) and the
period of the largest V_y.

    tools/study/table1_markdown.py SWEEP_DIR_OR_RESULTS_FOLDER

The model's periods come from each case's model.json. Beds (seeds) of one (shape, period) are
averaged; the cell says how many when more than one. A folder whose finished cases mix amplitudes
is refused: one table, one amplitude.
"""
import csv
import json
import os
import sys

sys.path.insert(0, os.path.join(os.path.dirname(os.path.abspath(__file__)), "..", "..", "python"))
from wiggleplot import prepare  # noqa: E402

PAPER_AMPLITUDE = 5.0   # the amplitude of the paper's Table 1
PAPER = {"disk": "2.5-3.0", "square": "3.0-4.0", "rect_narrow": "3.0-4.0", "rect_wide": "2.0-3.0",
         "triangle": "4.0-5.0"}
ORDER = ["disk", "square", "rect_narrow", "rect_wide", "triangle"]


def read_rates(folder):
    """{shape: {period: [V_y of each bed]}}, {shape: model.json}, the amplitude; finished cases only."""
    rates, model, amplitudes = {}, {}, set()
    with open(os.path.join(folder, "results.csv"), newline="") as f:
        for row in csv.DictReader(f):
            if row["status"] != "ok":
                continue
            shape, period = row["intruder.shape"], float(row["drive.period"])
            amplitudes.add(float(row["drive.amplitude"]))
            rates.setdefault(shape, {}).setdefault(period, []).append(float(row["vy"]))
            path = os.path.join(folder, row["run_dir"], "model.json")
            if shape not in model and os.path.exists(path):
                with open(path) as m:
                    model[shape] = json.load(m)
    if len(amplitudes) > 1:
        raise ValueError(f"{folder}: cases at amplitudes {sorted(amplitudes)}; one table is one amplitude")
    return rates, model, amplitudes.pop() if amplitudes else float("nan")


def table(folder):
    rates, model, amplitude = read_rates(folder)
    with_paper = amplitude == PAPER_AMPLITUDE
    periods = sorted({p for s in rates.values() for p in s})
    head = (["shape", "model T_rise", "model T_max"] + (["paper (observed)"] if with_paper else [])
            + [f"T = {p:g}" for p in periods] + ["wiggle T_rising", "bracket", "largest V_y at T"])
    lines = ["| " + " | ".join(head) + " |", "|" + "---|" * len(head)]
    for shape in [s for s in ORDER if s in rates] + sorted(set(rates) - set(ORDER)):
        by_t = rates[shape]
        means = {p: sum(v) / len(v) for p, v in by_t.items()}
        cells = [f"{means[p]:+.3f}" + (f" ({len(by_t[p])} beds)" if len(by_t[p]) > 1 else "") if p in means else ""
                 for p in periods]
        ts = sorted(means)
        t, lo, hi, note = prepare.t_rising(ts, [means[p] for p in ts])
        bracket = f"{lo:g}-{hi:g}" if lo == lo and hi == hi else note
        t_text = f"{t:.2f}" if t == t else "-"
        m = model.get(shape, {})
        model_cells = [f"{m[k]:.2f}" if k in m else "" for k in ("T_rise", "T_max")]
        paper = [PAPER.get(shape, "")] if with_paper else []
        largest = max(ts, key=lambda p: means[p])
        lines.append("| " + " | ".join([shape] + model_cells + paper + cells + [t_text, bracket, f"{largest:g}"]) + " |")
    return "\n".join(lines)


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
