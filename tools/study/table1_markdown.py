#!/usr/bin/python3
"""Table 1 as a markdown table from a sweep's results: V_y per shape and period, wiggle's T_rising
(the paper's reading: the last period with V_y <= 0 and the next, interpolated; wiggleplot's
t_rising) beside the cavity model's and the paper's observed range (its Table 1, A = 5).

    tools/study/table1_markdown.py SWEEP_DIR_OR_RESULTS_FOLDER

The cavity model's T_rise comes from each case's model.json. Beds (seeds) of one (shape, period)
are averaged; the cell says how many when more than one.
"""
import csv
import json
import os
import sys

sys.path.insert(0, os.path.join(os.path.dirname(os.path.abspath(__file__)), "..", "..", "python"))
from wiggleplot import prepare  # noqa: E402

PAPER = {"disk": "2.5-3.0", "square": "3.0-4.0", "rect_narrow": "3.0-4.0", "rect_wide": "2.0-3.0",
         "triangle": "4.0-5.0"}
ORDER = ["disk", "square", "rect_narrow", "rect_wide", "triangle"]


def main():
    if len(sys.argv) < 2:
        sys.exit("usage: " + __doc__.strip().splitlines()[4].strip())
    folder = sys.argv[1]
    rates, model = {}, {}
    with open(os.path.join(folder, "results.csv"), newline="") as f:
        for row in csv.DictReader(f):
            if row["status"] != "ok":
                continue
            shape, period = row["intruder.shape"], float(row["drive.period"])
            rates.setdefault(shape, {}).setdefault(period, []).append(float(row["vy"]))
            path = os.path.join(folder, row["run_dir"], "model.json")
            if shape not in model and os.path.exists(path):
                with open(path) as m:
                    model[shape] = json.load(m).get("T_rise")
    periods = sorted({p for s in rates.values() for p in s})
    head = ["shape", "model T_rise", "paper (observed)"] + [f"T = {p:g}" for p in periods] + ["wiggle T_rising", "bracket"]
    print("| " + " | ".join(head) + " |")
    print("|" + "---|" * len(head))
    for shape in [s for s in ORDER if s in rates] + sorted(set(rates) - set(ORDER)):
        by_t = rates[shape]
        means = {p: sum(v) / len(v) for p, v in by_t.items()}
        cells = [f"{means[p]:+.3f}" + (f" ({len(by_t[p])} beds)" if len(by_t[p]) > 1 else "") if p in means else ""
                 for p in periods]
        ts = sorted(means)
        t, lo, hi, note = prepare.t_rising(ts, [means[p] for p in ts])
        bracket = f"{lo:g}-{hi:g}" if lo == lo and hi == hi else note
        t_text = f"{t:.2f}" if t == t else "-"
        m = model.get(shape)
        print("| " + " | ".join([shape, f"{m:.2f}" if m else "", PAPER.get(shape, "")] + cells + [t_text, bracket]) + " |")


if __name__ == "__main__":
    main()
