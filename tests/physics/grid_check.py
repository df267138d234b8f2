#!/usr/bin/python3
"""Every point of the paper's grid runs: configs/sweeps/grid_check_small.toml must end with every case ok.

    tests/physics/grid_check.py WIGGLE [--out DIR] [--jobs N]

Runs the sweep (resumable: the same --out continues it), then checks results.csv: 200 cases, each
with status ok and a summary.json. Prints the sweep's wall time, the slowest case, and how close
the cases came to the blow-up detector's bounds (summary.json's overlap_margin and speed_margin:
1 would have stopped the run). Exit 0 when every case is ok, 1 otherwise. ctest runs it as
slow_paper_grid_runs (label slow, about 40 minutes on 2 cores).
"""
import argparse
import csv
import json
import os
import subprocess
import sys
import time

ROOT = os.path.abspath(os.path.join(os.path.dirname(os.path.abspath(__file__)), "..", ".."))
SWEEP = os.path.join(ROOT, "configs", "sweeps", "grid_check_small.toml")
EXPECTED_CASES = 5 * 4 * 10  # shapes x amplitudes x periods


def main():
    p = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    p.add_argument("wiggle")
    p.add_argument("--out", default=os.path.join(os.getcwd(), "grid_check_small"))
    p.add_argument("--jobs", type=int, default=os.cpu_count() or 1)
    args = p.parse_args()

    start = time.monotonic()
    sweep = subprocess.run([args.wiggle, "sweep", SWEEP, "--out", args.out, "--jobs", str(args.jobs),
                            "--threads", "1"], stdout=subprocess.DEVNULL, stderr=subprocess.PIPE, text=True)
    wall = time.monotonic() - start
    with open(os.path.join(args.out, "results.csv"), newline="") as f:
        rows = list(csv.DictReader(f))

    failures = [f"{r['case']}: {r['status']} {r['error']}" for r in rows if r["status"] != "ok"]
    if len(rows) != EXPECTED_CASES:
        failures.append(f"results.csv has {len(rows)} cases, expected {EXPECTED_CASES}")
    margins = []
    for r in rows:
        if r["status"] != "ok":
            continue
        with open(os.path.join(args.out, r["run_dir"], "summary.json")) as f:
            s = json.load(f)
        margins.append((s["overlap_margin"], s["speed_margin"], float(r["wall_s"]), r["case"]))

    print(f"grid check: {len(rows) - len(failures)} of {EXPECTED_CASES} cases ok, sweep wall time {wall:.0f} s "
          f"({args.jobs} jobs; cases done in an earlier call are not timed again)")
    if margins:
        for i, what in ((0, "overlap"), (1, "speed")):
            worst = max(margins, key=lambda m: m[i])
            print(f"  largest {what} margin: {worst[i]:.3f} of the bound ({worst[3]})")
        slowest = max(margins, key=lambda m: m[2])
        print(f"  slowest case: {slowest[2]:.0f} s ({slowest[3]})")
    for line in failures:
        print("  FAILED", line)
    if sweep.returncode not in (0, 1):
        print("wiggle sweep:", sweep.stderr.strip().splitlines()[-1:])
        return 1
    return 1 if failures else 0


if __name__ == "__main__":
    sys.exit(main())
