#!/usr/bin/python3
"""The most violent points of the paper's grid, wiggle against LAMMPS on the same bed.

    tools/validation/fast_drive_lammps.py --out DIR [--wiggle BIN] [--duration 3] [--cases disk:0.25,...]

For each case (shape:period at A = 5 on configs/small.toml; default disk and triangle at T = 0.25
and 0.5) it runs `wiggle run`, exports the same case with `wiggle export-lammps` and runs the deck
with Debian's `lmp` twice: on 1 rank and on 2 MPI ranks. The two LAMMPS runs differ only in the
order of floating-point sums, so how far apart they drift is what chaos alone does to this case
in this time. LAMMPS starts every contact with its tangential spring unloaded (a data file cannot
carry the history; docs/LAMMPS-EXPORT.md), wiggle with the bed's; so wiggle also runs once with
`run.bed_history = false`, started exactly as the deck is: the like-for-like comparison, which
agrees "to the level chaos allows" when it is no farther from the 1-rank run than the 2-rank run is.
The distance between the two wiggle runs shows how much the start alone moves the case.

From the dumps (every --dump time units, the same frames for all three) it measures, per frame,
the largest overlap of any grain with a grain, the base or the intruder, and the number of touching
pairs (the same analysis for all three runs), and from trajectory.csv the intruder's y(t). Writes
DIR/fast_drive_lammps.csv (one row per case and run: means over frames and the y difference to
LAMMPS 1 rank) and DIR/fast_drive_lammps.png, and prints the table.
"""
import argparse
import csv
import os
import shutil
import subprocess
import sys

import numpy as np

sys.path.insert(0, os.path.join(os.path.dirname(os.path.abspath(__file__)), "..", "..", "python"))
from wiggleplot import readers  # noqa: E402

sys.path.insert(0, os.path.dirname(os.path.abspath(__file__)))
from dumps import contacts, read_dump  # noqa: E402

DT = 1e-4  # configs/small.toml's run.dt: dump steps to time
ROOT = os.path.abspath(os.path.join(os.path.dirname(os.path.abspath(__file__)), "..", ".."))


def measure(run_dir, dump):
    frames = read_dump(dump)
    steps = np.array([f[0] for f in frames])
    stats = np.array([contacts(f[1], f[2], f[3]) for f in frames])
    traj = readers.read_trajectory(run_dir)
    return {"step": steps, "max_overlap": stats[:, 0], "contacts": stats[:, 1],
            "t": np.asarray(traj["t"], float), "y": np.asarray(traj["y"], float)}


def run(cmd, cwd=None, log=None):
    with open(log, "w") if log else open(os.devnull, "w") as out:
        subprocess.run(cmd, cwd=cwd, check=True, stdout=out, stderr=subprocess.STDOUT)


def main():
    p = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    p.add_argument("--out", required=True)
    p.add_argument("--wiggle", default=os.path.join(ROOT, "build", "release", "wiggle"))
    p.add_argument("--lmp", default="lmp")
    p.add_argument("--duration", type=float, default=3.0)
    p.add_argument("--dump", type=float, default=0.01, help="dump interval [sqrt(d/g)]")
    p.add_argument("--amplitude", type=float, default=5.0)
    p.add_argument("--cases", default="disk:0.25,disk:0.5,triangle:0.25,triangle:0.5")
    args = p.parse_args()
    os.makedirs(args.out, exist_ok=True)
    mpirun = ["mpirun", "-np", "2", "--oversubscribe"] + (["--allow-run-as-root"] if os.geteuid() == 0 else [])

    results = {}
    for case in args.cases.split(","):
        shape, period = case.split(":")
        name = f"{shape}_T{period}"
        sets = [f"intruder.shape={shape}", f"drive.amplitude={args.amplitude}", f"drive.period={period}",
                f"run.duration={args.duration}", f"run.dump_interval={args.dump}", "fields.enabled=false"]
        config = os.path.join(ROOT, "configs", "small.toml")
        set_args = [a for s in sets for a in ("--set", s)]
        os.makedirs(os.path.join(args.out, name), exist_ok=True)
        runs = {}
        # wiggle as a user runs it (the bed's contact history), and started as the LAMMPS deck is
        # (every tangential spring unloaded): the second is the like-for-like comparison.
        for label, extra in (("wiggle", []), ("wiggle_fresh", ["--set", "run.bed_history=false"])):
            wdir = os.path.join(args.out, name, label)
            if not os.path.exists(os.path.join(wdir, "summary.json")):
                shutil.rmtree(wdir, ignore_errors=True)
                run([args.wiggle, "run", config, *set_args, *extra, "--out", wdir, "--threads", "1", "--no-plot"],
                    log=os.path.join(args.out, name, label + ".log"))
            runs[label] = (wdir, os.path.join(wdir, "dumps", "dump.lammpstrj"))
        deck = os.path.join(args.out, name, "deck")
        if not os.path.exists(os.path.join(deck, "in.wiggle")):
            run([args.wiggle, "export-lammps", config, *set_args, "--out", deck, "--threads", "1"])
        for label, prefix in (("lammps_1", []), ("lammps_2", mpirun)):
            ldir = os.path.join(args.out, name, label)
            if not os.path.exists(os.path.join(ldir, "trajectory.csv")):
                shutil.rmtree(ldir, ignore_errors=True)
                shutil.copytree(deck, ldir)
                run(prefix + [args.lmp, "-in", "in.wiggle", "-log", "log.lammps", "-screen", "none"], cwd=ldir)
            runs[label] = (ldir, os.path.join(ldir, "dump.lammpstrj"))
        results[name] = {label: measure(d, dump) for label, (d, dump) in runs.items()}
        print(f"{name}: measured", flush=True)

    rows = []
    for name, r in results.items():
        ref = r["lammps_1"]
        for label, m in r.items():
            n = min(len(m["y"]), len(ref["y"]))
            dy = np.abs(m["y"][:n] - ref["y"][:n])
            rows.append({"case": name, "run": label,
                         "mean_max_overlap": m["max_overlap"].mean(), "peak_max_overlap": m["max_overlap"].max(),
                         "mean_contacts": m["contacts"].mean(),
                         "y_end": m["y"][-1], "mean_abs_dy_vs_lammps_1": dy.mean(), "max_abs_dy_vs_lammps_1": dy.max()})
    table = os.path.join(args.out, "fast_drive_lammps.csv")
    with open(table, "w", newline="") as f:
        w = csv.DictWriter(f, fieldnames=list(rows[0]))
        w.writeheader()
        for row in rows:
            w.writerow({k: (f"{v:.5g}" if isinstance(v, float) else v) for k, v in row.items()})
    print(open(table).read())
    plot(results, os.path.join(args.out, "fast_drive_lammps.png"), args)


LABELS = {"wiggle": "wiggle (bed's contact history)", "wiggle_fresh": "wiggle (springs unloaded, as LAMMPS)",
          "lammps_1": "LAMMPS 1 rank", "lammps_2": "LAMMPS 2 ranks"}


def plot(results, path, args):
    import matplotlib
    matplotlib.use("Agg")
    import matplotlib.pyplot as plt
    names = list(results)
    fig, axes = plt.subplots(3, len(names), figsize=(4.2 * len(names), 8.5), squeeze=False, sharex=True)
    colours = {"wiggle": "C3", "wiggle_fresh": "C1", "lammps_1": "C0", "lammps_2": "C2"}
    for c, name in enumerate(names):
        for label, m in results[name].items():
            t_dump = m["step"] * DT
            kw = dict(color=colours[label], lw=1.0, label=LABELS[label])
            axes[0, c].plot(m["t"], m["y"], **kw)
            axes[1, c].plot(t_dump, m["max_overlap"], **kw)
            axes[2, c].plot(t_dump, m["contacts"], **kw)
        axes[0, c].set_title(name.replace("_T", ", T = ") + f", A = {args.amplitude:g}")
        axes[2, c].set_xlabel("t [sqrt(d/g)]")
    axes[0, 0].set_ylabel("intruder y [d]")
    axes[1, 0].set_ylabel("largest overlap [d]")
    axes[2, 0].set_ylabel("touching pairs")
    axes[0, 0].legend(fontsize=8)
    fig.tight_layout()
    fig.savefig(path, dpi=110)
    print("figure:", path)


if __name__ == "__main__":
    main()
