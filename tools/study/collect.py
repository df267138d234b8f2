#!/usr/bin/python3
"""Copy a sweep's results (not its checkpoints or dumps) into the repository, so they outlive the machine.

    tools/study/collect.py SWEEP_DIR DEST

Copies SWEEP_DIR/results.csv and sweep.log, and for every case directory the files that are the
result and how it was made: config.toml, summary.json, trajectory.csv, phase_rates.csv, model.json,
log.txt (a case still running contributes its config and log only). Checkpoints, dumps and beds
stay behind: they are large and any of them can be made again from the config, bit for bit.
Run it again as the sweep goes on; it overwrites what it copied before. A later session continues
the sweep from the sweep directory if the machine still has it, else from scratch: cases whose
summary.json says ok are never rerun when DEST is used as the sweep's --out (the sweep skips them).
"""
import os
import shutil
import sys

CASE_FILES = ("config.toml", "summary.json", "trajectory.csv", "phase_rates.csv", "model.json", "log.txt")
SWEEP_FILES = ("results.csv", "sweep.log")


def main():
    if len(sys.argv) != 3:
        sys.exit(__doc__.strip().splitlines()[2].strip())
    src, dest = sys.argv[1], sys.argv[2]
    if not os.path.isfile(os.path.join(src, "results.csv")):
        sys.exit(f"collect: {src} is not a sweep directory (no results.csv)")
    os.makedirs(dest, exist_ok=True)
    for name in SWEEP_FILES:
        if os.path.exists(os.path.join(src, name)):
            shutil.copy2(os.path.join(src, name), os.path.join(dest, name))
    copied = 0
    cases = os.path.join(src, "cases")
    for case in sorted(os.listdir(cases)) if os.path.isdir(cases) else []:
        for name in CASE_FILES:
            path = os.path.join(cases, case, name)
            if os.path.exists(path):
                os.makedirs(os.path.join(dest, "cases", case), exist_ok=True)
                shutil.copy2(path, os.path.join(dest, "cases", case, name))
                copied += name == "summary.json"
    print(f"collect: {dest}: results.csv and {copied} finished cases")


if __name__ == "__main__":
    main()
