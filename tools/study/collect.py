#!/usr/bin/python3
"""Copy a sweep's results (not its checkpoints or dumps) into the repository, so they outlive the machine.

    tools/study/collect.py SWEEP_DIR DEST [--fields]

Copies SWEEP_DIR/results.csv and sweep.log, and for every case directory the files that are the
result and how it was made: config.toml, summary.json, trajectory.csv, phase_rates.csv, model.json,
log.txt (a case still running contributes its config and log only); with --fields also each case's
fields.csv (about 2 MB at the default grid), for a study whose result is its field maps. Checkpoints, dumps and beds
stay behind: they are large and any of them can be made again from the config, bit for bit.
Run it again as the sweep goes on; it overwrites what it copied before, except that DEST/sweep.log
keeps the lines of earlier sweep directories: a later session continues the sweep from the sweep
directory if the machine still has it, else in a new one with DEST's cases copied in (cases whose
summary.json says ok are never rerun), and that new directory's log starts afresh.
"""
import os
import shutil
import sys

CASE_FILES = ("config.toml", "summary.json", "trajectory.csv", "phase_rates.csv", "model.json", "log.txt")


def merged_log(earlier, current):
    """The log of every sweep directory the study ran in: `earlier` (DEST's lines) up to where
    `current` (this directory's log) begins, then `current`."""
    if current and current[0] in earlier:
        earlier = earlier[:earlier.index(current[0])]
    if earlier and not earlier[-1].endswith("\n"):
        earlier[-1] += "\n"
    return earlier + current


def read_lines(path):
    if not os.path.exists(path):
        return []
    with open(path) as f:
        return f.read().splitlines(keepends=True)


def main():
    args = sys.argv[1:]
    with_fields = "--fields" in args
    args = [a for a in args if a != "--fields"]
    if len(args) != 2:
        print("usage: " + __doc__.strip().splitlines()[2].strip(), file=sys.stderr)
        sys.exit(2)
    src, dest = args
    files = CASE_FILES + (("fields.csv",) if with_fields else ())
    if not os.path.isfile(os.path.join(src, "results.csv")):
        print(f"collect: {src} is not a sweep directory (no results.csv)", file=sys.stderr)
        sys.exit(2)
    os.makedirs(dest, exist_ok=True)
    shutil.copy2(os.path.join(src, "results.csv"), os.path.join(dest, "results.csv"))
    log = merged_log(read_lines(os.path.join(dest, "sweep.log")), read_lines(os.path.join(src, "sweep.log")))
    with open(os.path.join(dest, "sweep.log.tmp"), "w") as f:
        f.writelines(log)
    os.replace(os.path.join(dest, "sweep.log.tmp"), os.path.join(dest, "sweep.log"))
    copied = 0
    cases = os.path.join(src, "cases")
    for case in sorted(os.listdir(cases)) if os.path.isdir(cases) else []:
        for name in files:
            path = os.path.join(cases, case, name)
            if os.path.exists(path):
                os.makedirs(os.path.join(dest, "cases", case), exist_ok=True)
                shutil.copy2(path, os.path.join(dest, "cases", case, name))
                copied += name == "summary.json"
    print(f"collect: {dest}: results.csv and {copied} finished cases")


if __name__ == "__main__":
    main()
