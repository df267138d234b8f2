#!/usr/bin/python3
"""y(t) of several runs of the same case in one figure, with the rise rate of each.

    tools/validation/compare_trajectories.py --out FIG.png [--title T] [--csv TABLE.csv] LABEL=DIR [LABEL=DIR ...]

DIR is a `wiggle run` directory or a directory where an exported LAMMPS deck ran (`wiggle
export-lammps`: the deck writes the same trajectory.csv columns). Prints, per run, the chord over
[t_i, t_f] = [0.1 t_end, t_end] (no plateau rule), the least-squares slope over the same window, the
final height and, when DIR holds the case's config.toml (every wiggle run, and every deck exported
since config.toml is written beside it), V_y by wiggle's own rules as `wiggle rate DIR` measures
it: the run's rule (the chord, or the plateau rule when the intruder surfaced) and the paper's t_f
rule (vy_settled). No rule is written here: those columns come from the wiggle program (found as
the plotting package finds it; --wiggle PATH to choose). --csv writes the same rows as a table
(label, dir, vy_chord, vy_slope, y_end, vy_rule, vy_settled; the last two empty without config.toml).
A run whose intruder turns (intruder.rotation = "free": trajectory.csv's angle column) has its angle
drawn in a second panel under y(t), in its curve's colour.
"""

import argparse
import csv
import io
import os
import subprocess
import sys

sys.path.insert(0, os.path.join(os.path.dirname(os.path.abspath(__file__)), "..", "..", "python"))

import numpy as np  # noqa: E402

from wiggleplot import data, readers, style  # noqa: E402


def rates(traj):
    t = np.asarray(traj["t"], dtype=float)
    y = np.asarray(traj["y"], dtype=float)
    window = t >= 0.1 * t[-1] - 1e-9
    first = int(np.argmax(window))
    chord = (y[-1] - y[first]) / (t[-1] - t[first])
    slope = np.polyfit(t[window], y[window], 1)[0]
    return chord, slope, y[-1]


def rule_rates(wiggle, path):
    """(vy, vy_settled) by wiggle's rules (`wiggle rate DIR`), or None without the case's config.toml."""
    if not os.path.isfile(os.path.join(path, "config.toml")):
        return None
    done = subprocess.run([wiggle or data.find_wiggle(), "rate", path], capture_output=True, text=True)
    if done.returncode != 0:
        sys.exit(f"compare_trajectories: {done.stderr.strip() or 'wiggle rate failed'}")
    row = next(csv.DictReader(io.StringIO(done.stdout)))
    return float(row["vy"]), float(row["vy_settled"])


def read_runs(specs):
    """[(label, dir, trajectory)] of the LABEL=DIR arguments; exits naming a malformed one."""
    runs = []
    for spec in specs:
        label, sep, path = spec.partition("=")
        if not sep:
            sys.exit(f"compare_trajectories: '{spec}' is not LABEL=DIR")
        if not os.path.isfile(os.path.join(path, "trajectory.csv")):
            sys.exit(f"compare_trajectories: no trajectory.csv in '{path}' (the label ends at the first '=')")
        runs.append((label, path, readers.read_trajectory(path)))
    return runs


def draw(curves, title):
    """The figure of [(label, trajectory, its chord)]: y(t) - y(0) of each, and under it, where any run's
    intruder turns (intruder.rotation = "free": trajectory.csv's angle column), a panel of the angle in
    degrees, each in its curve's colour."""
    import matplotlib.pyplot as plt

    many = len(curves) > 6  # then the legend goes beside the axes, where it hides no curve
    width = 9 if many else 7
    turning = any("angle" in traj for _, traj, _ in curves)
    if turning:
        fig, (ax, ax_angle) = plt.subplots(2, 1, sharex=True, figsize=(width, 6), height_ratios=(2, 1))
    else:
        fig, ax = plt.subplots(figsize=(width, 4))
    for index, (label, traj, chord) in enumerate(curves):
        # Past the colour cycle's ten colours, a new dash pattern, so that no two curves look alike.
        dashes = ("-", "--", "-.", ":")[index // 10 % 4]
        line, = ax.plot(traj["t"], np.asarray(traj["y"]) - traj["y"][0], lw=0.8, ls=dashes,
                        label=f"{label}: V_y = {chord:+.3f}")
        if "angle" in traj:
            ax_angle.plot(traj["t"], np.degrees(traj["angle"]), lw=0.6, ls=dashes, color=line.get_color())
    ax.axhline(0.0, color="0.6", lw=0.5)
    if turning:
        ax_angle.axhline(0.0, color="0.6", lw=0.5)
        ax_angle.set_ylabel("turned [degrees]")
    (ax_angle if turning else ax).set_xlabel("t [sqrt(d/g)]")
    ax.set_ylabel("y - y(0) [d]")
    ax.set_title(title)
    if many:
        ax.legend(fontsize=8, loc="upper left", bbox_to_anchor=(1.01, 1.0))
    else:
        ax.legend(fontsize=8)
    fig.tight_layout()
    return fig


def main():
    parser = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    parser.add_argument("runs", nargs="+", metavar="LABEL=DIR")
    parser.add_argument("--out", required=True)
    parser.add_argument("--title", default="")
    parser.add_argument("--csv", help="also write the rows to this CSV file")
    parser.add_argument("--wiggle", help="the wiggle program for the rule columns (default: as wiggleplot finds it)")
    args = parser.parse_args()
    style.apply()
    print(f"{'run':24} {'V_y chord':>10} {'LSQ slope':>10} {'y_end':>8} {'V_y rule':>9} {'vy_settled':>10}")
    rows, curves = [], []
    for label, path, traj in read_runs(args.runs):
        chord, slope, y_end = rates(traj)
        rule = rule_rates(args.wiggle, path)
        shown = f"{rule[0]:+9.4f} {rule[1]:+10.4f}" if rule else f"{'-':>9} {'-':>10}"
        print(f"{label:24} {chord:+10.4f} {slope:+10.4f} {y_end:8.2f} {shown}")
        rows.append([label, path, f"{chord:.6f}", f"{slope:.6f}", f"{y_end:.4f}"] +
                    ([f"{rule[0]:.6f}", f"{rule[1]:.6f}"] if rule else ["", ""]))
        curves.append((label, traj, chord))
    if args.csv:
        with open(args.csv, "w", newline="") as f:
            w = csv.writer(f)
            w.writerow(["label", "dir", "vy_chord", "vy_slope", "y_end", "vy_rule", "vy_settled"])
            w.writerows(rows)
    fig = draw(curves, args.title)
    tmp = args.out + ".tmp.png"
    fig.savefig(tmp, dpi=120)
    os.replace(tmp, args.out)


if __name__ == "__main__":
    main()
