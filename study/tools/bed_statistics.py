#!/usr/bin/python3
"""Beds of a sweep compared by how they were poured: structure at t = 0 and the rise rate.

    study/tools/bed_statistics.py SWEEP_DIR --out PREFIX [--key bed.pour] [--dump LABEL=FILE ...]

For every case of the sweep whose dump holds a frame at step 0 (set run.dump_interval), the bed as
the drive starts: the area fraction against height (grains' disc areas over the box's area in 2 d
bands, away from the intruder: |x - W/2| > 8 d), the coordination number Z (touching neighbours
per grain, grains and base, for grains 3 d above the base to 3 d below the surface and 8 d from
the intruder) and the free surface (median and standard deviation of the highest grain top in
2 d wide columns, as wiggle measures it); around the intruder, the grains touching it and the area
fraction of the 16 d wide strip's grains in the 16 d above its top. Cases sharing a bed (same protocol and seed) are
counted once. The V_y of every case comes from results.csv. --dump adds a bed from any dump file
(its first frame; e.g. LAMMPS's fix pour bed from tools/validation/lammps_fix_pour.py) under the
protocol name LABEL; repeat it for several seeds (LABEL=FILE, the seeds numbered in order).

Writes PREFIX.csv (one row per bed), PREFIX_vy.csv (mean and standard error of V_y over the beds,
per protocol and period) and PREFIX.png (area fraction profiles), and prints the tables.
"""
import argparse
import csv
import math
import os
import sys

import numpy as np

# the dump reader the program's LAMMPS comparisons share (tools/validation/dumps.py)
sys.path.insert(0, os.path.join(os.path.dirname(os.path.abspath(__file__)), "..", "..", "tools", "validation"))
from dumps import BASE, GRAIN, INTRUDER, pair_overlaps, read_dump  # noqa: E402

BAND = 2.0          # [d] height of the area-fraction bands and width of the surface columns
CLEAR = 8.0         # [d] half-width of the strip around the intruder left out of the statistics
BULK_MARGIN = 3.0   # [d] from the base and from the surface, for Z


def bed_statistics(frame):
    step, width, xlo, atoms = frame
    kind = atoms[:, 1].astype(int)
    x = np.mod(atoms[:, 2] - xlo, width)
    y, r = atoms[:, 3], atoms[:, 4]
    grain = kind == GRAIN
    away = np.abs(x - 0.5 * width) > CLEAR
    # Free surface: per column, the highest grain top; its median and spread.
    columns = max(1, int(width / BAND))
    col = np.minimum(columns - 1, (x / width * columns).astype(int))
    tops = np.full(columns, 0.5)
    np.maximum.at(tops, col[grain], (y + r)[grain])
    surface = float(np.median(tops))
    # Area fraction in bands (grain centres in the band, the strip around the intruder excluded).
    edges = np.arange(0.0, surface + BAND, BAND)
    sel = grain & away
    area, _ = np.histogram(y[sel], bins=edges, weights=math.pi * r[sel] ** 2)
    phi = area / ((width - 2 * CLEAR) * BAND)
    # Coordination: touching neighbours of bulk grains.
    i, j, overlap = pair_overlaps(width, xlo, atoms)
    touch = overlap > 0
    counts = np.bincount(np.concatenate([i[touch], j[touch]]), minlength=len(atoms))
    bulk = grain & away & (y > BULK_MARGIN) & (y < surface - BULK_MARGIN)
    bulk_band = (edges[:-1] > BULK_MARGIN) & (edges[1:] < surface - BULK_MARGIN)
    # Around the intruder (where a carved bed and a poured one can differ): the grains touching it,
    # and the area fraction of the strip's grains in the 2 CLEAR above its top.
    intruder = kind == INTRUDER
    on_intruder = touch & (intruder[i] | intruder[j]) & (grain[i] | grain[j])
    contacts = len(set(np.where(grain[i[on_intruder]], i[on_intruder], j[on_intruder]).tolist()))
    top = float((y + r)[intruder].max()) if intruder.any() else float("nan")
    above = grain & ~away & (y >= top) & (y < top + 2 * CLEAR)
    phi_above = float((math.pi * r[above] ** 2).sum() / (4 * CLEAR * CLEAR))
    return {"surface": surface, "surface_sd": float(np.std(tops)), "z": float(counts[bulk].mean()),
            "phi_bulk": float(phi[bulk_band].mean()), "rattlers": float((counts[bulk] < 2).mean()),
            "intruder_contacts": contacts, "phi_above": phi_above,
            "grains": int(grain.sum()), "profile": (0.5 * (edges[1:] + edges[:-1]), phi)}


def mean_sem(values):
    v = np.asarray(values, float)
    return v.mean(), (v.std(ddof=1) / math.sqrt(len(v)) if len(v) > 1 else float("nan"))


def main():
    p = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    p.add_argument("sweep")
    p.add_argument("--out", required=True, help="prefix of the files written")
    p.add_argument("--key", default="bed.pour", help="the results.csv column that names the protocol")
    p.add_argument("--dump", action="append", default=[], metavar="LABEL=FILE", help="another bed to compare")
    args = p.parse_args()
    with open(os.path.join(args.sweep, "results.csv"), newline="") as f:
        rows = list(csv.DictReader(f))

    beds, rates = {}, {}
    for row in rows:
        protocol, seed, period = row[args.key], row["box.seed"], row["drive.period"]
        if row["status"] == "ok":
            rates.setdefault((protocol, period), []).append(float(row["vy"]))
        dump = os.path.join(args.sweep, row["run_dir"], "dumps", "dump.lammpstrj")
        if (protocol, seed) in beds or not os.path.exists(dump):
            continue
        frames = read_dump(dump)
        if frames and frames[0][0] == 0:
            beds[(protocol, seed)] = bed_statistics(frames[0])

    for spec in args.dump:
        label, path = spec.split("=", 1)
        beds[(label, str(sum(1 for k in beds if k[0] == label) + 1))] = bed_statistics(read_dump(path)[0])

    fields = ["protocol", "seed", "grains", "intruder_contacts", "surface", "surface_sd", "phi_bulk", "z",
              "rattlers", "phi_above"]
    with open(args.out + ".csv", "w", newline="") as f:
        w = csv.writer(f)
        w.writerow(fields)
        for (protocol, seed), s in sorted(beds.items()):
            w.writerow([protocol, seed, s["grains"], s["intruder_contacts"]] + [f"{s[k]:.4f}" for k in fields[4:]])
    with open(args.out + "_vy.csv", "w", newline="") as f:
        w = csv.writer(f)
        w.writerow(["protocol", "period", "beds", "vy_mean", "vy_sem", "vy_values"])
        for (protocol, period), v in sorted(rates.items()):
            m, e = mean_sem(v)
            w.writerow([protocol, period, len(v), f"{m:.4f}", f"{e:.4f}", " ".join(f"{x:+.4f}" for x in v)])
    for path in (args.out + ".csv", args.out + "_vy.csv"):
        print(open(path).read())

    import matplotlib
    matplotlib.use("Agg")
    import matplotlib.pyplot as plt
    fig, ax = plt.subplots(figsize=(5.5, 4.5))
    colours = {}
    for (protocol, seed), s in sorted(beds.items()):
        colour = colours.setdefault(protocol, f"C{len(colours)}")
        h, phi = s["profile"]
        ax.plot(phi, h, color=colour, lw=1.0, label=protocol if seed == min(k[1] for k in beds if k[0] == protocol) else None)
    ax.set_xlabel("area fraction (2 d bands, intruder strip excluded)")
    ax.set_ylabel("height y [d]")
    ax.set_xlim(0.5, 0.95)
    ax.legend(title=args.key)
    fig.tight_layout()
    fig.savefig(args.out + ".png", dpi=120)
    print("figure:", args.out + ".png")


if __name__ == "__main__":
    main()
