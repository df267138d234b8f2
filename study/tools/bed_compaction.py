#!/usr/bin/python3
"""How a bed has changed under the drive: its surface and area fraction at the start of each case
and at the case's newest checkpoint, through the engine's Python module.

    PYTHONPATH=build/release/python:python study/tools/bed_compaction.py SWEEP_DIR [CASE ...] [--csv OUT.csv]
        [--times T1,T2,...]

For each case directory of SWEEP_DIR (all, or the CASEs named) that holds a checkpoint: the case at
t = 0 (`wiggle.Case(config.toml)`: its bed from the cache, the drive not started) and at its newest
checkpoint (`wiggle.Case.load`). With --times, when the compaction happens: each case is run again
from its bed by the engine (its config.toml; no checkpoint needed, none written) and measured at
each of the times as it passes them, at the cost of the run up to the last one. Measured: the
surface (the median over 2 d columns of the highest grain centre), the bulk area fraction (grains
centred between 10 d above the base and 10 d below the surface, farther than 15 d from the
intruder's centre) and the area fraction of the annulus 4-9 d from the intruder's centre, with the
intruder's height. Checkpoints are not committed with the results (collect.py leaves them behind); a
case run again writes the same ones, bit for bit.
"""
import argparse
import csv
import math
import os
import sys

import numpy as np

import wiggle

BAND_MARGIN = 10.0         # d above the base and below the surface
INTRUDER_EXCLUSION = 15.0  # d: the bulk leaves out a disc of this radius around the intruder
ANNULUS = (4.0, 9.0)       # d from the intruder's centre
COLUMN = 2.0               # d: the surface's columns


def bed_state(frame, width):
    """(surface, bulk area fraction, annulus area fraction, intruder height) of a dump frame."""
    x, y, r, kind = (np.asarray(frame[k]) for k in ("x", "y", "radius", "type"))
    grain = kind == 1
    xi, yi = frame["intruder"][0], frame["intruder"][1]
    columns = np.floor(x[grain] / COLUMN).astype(int)
    surface = float(np.median([y[grain][columns == c].max() for c in np.unique(columns)]))
    dx = (x - xi + width / 2) % width - width / 2
    distance = np.hypot(dx, y - yi)
    disc_area = np.pi * r ** 2
    bulk = grain & (y > BAND_MARGIN) & (y < surface - BAND_MARGIN) & (distance > INTRUDER_EXCLUSION)
    bulk_area = width * (surface - 2 * BAND_MARGIN) - math.pi * INTRUDER_EXCLUSION ** 2
    near = grain & (distance > ANNULUS[0]) & (distance < ANNULUS[1])
    near_area = math.pi * (ANNULUS[1] ** 2 - ANNULUS[0] ** 2)
    return surface, float(disc_area[bulk].sum() / bulk_area), float(disc_area[near].sum() / near_area), yi


def times_list(text):
    """--times: increasing positive times."""
    try:
        times = [float(v) for v in text.split(",")]
    except ValueError:
        raise argparse.ArgumentTypeError(f"{text}: not a comma-separated list of numbers")
    if any(t <= 0 for t in times) or times != sorted(set(times)):
        raise argparse.ArgumentTypeError(f"{text}: the times must be positive and increasing")
    return times


def main():
    parser = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    parser.add_argument("sweep_dir")
    parser.add_argument("cases", nargs="*")
    parser.add_argument("--csv", help="also write the rows to this CSV file")
    parser.add_argument("--times", type=times_list,
                        help="comma-separated times: run each case from its bed and measure it at each")
    args = parser.parse_args()
    cases_dir = os.path.join(args.sweep_dir, "cases")
    names = args.cases or sorted(os.listdir(cases_dir))
    header = ["case", "t", "surface_0", "surface_t", "bulk_phi_0", "bulk_phi_t", "annulus_phi_0", "annulus_phi_t",
              "y_0", "y_t"]
    rows = []
    print(" ".join(f"{h:>13}" for h in header))
    for name in names:
        d = os.path.join(cases_dir, name)
        if not args.times and not os.path.exists(os.path.join(d, "checkpoint.bin")):
            print(f"{name}: no checkpoint, left out", file=sys.stderr)
            continue
        start = wiggle.Case(os.path.join(d, "config.toml"), threads=1)
        width = start.frame()["box"][0][1]  # ((0, W), (y_lo, y_hi), ...)
        s0 = bed_state(start.frame(), width)
        if args.times:
            later = []
            for t in args.times:  # the same Case, advanced: one run, measured on its way
                start.advance(t)
                later.append((start.t, bed_state(start.frame(), width)))
        else:
            now = wiggle.Case.load(d, threads=1)
            later = [(now.t, bed_state(now.frame(), width))]
        for t, s1 in later:
            row = [name, f"{t:.6g}"] + [f"{v:.4f}" for pair in zip(s0, s1) for v in pair]
            rows.append(row)
            print(" ".join(f"{v:>13}" for v in row), flush=True)
    if args.csv:
        with open(args.csv, "w", newline="") as f:
            w = csv.writer(f)
            w.writerow(header)
            w.writerows(rows)


if __name__ == "__main__":
    main()
