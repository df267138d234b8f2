#!/usr/bin/python3
"""Copy a sweep's results (not its checkpoints or dumps) into the repository, so they outlive the machine.

    study/tools/collect.py SWEEP_DIR DEST [--fields] [--phase] [--carry]

Copies SWEEP_DIR/results.csv, cells.csv (where the sweep wrote one) and sweep.log, and for every case directory the files that are the
result and how it was made: config.toml, summary.json, trajectory.csv and log.txt (a case still running
has no summary.json yet, and its trajectory.csv goes to its last checkpoint; model.json, the cavity
model's, `wiggle model` remakes from the config); with --phase also each case's phase_rates.csv, for a study whose tables read the phase
profile (figure 8); with --fields also each case's
fields.csv (about 2 MB at the default grid), for a study whose result is its field maps. Checkpoints, dumps and beds
stay behind: they are large and any of them can be made again from the config, bit for bit.
Run it again as the sweep goes on; it overwrites what it copied before, except that DEST/sweep.log
keeps the lines of earlier sweep directories: a later session continues the sweep from the sweep
directory if the machine still has it, else in a new one with DEST's cases copied in (cases whose
summary.json says ok are never rerun), and that new directory's log starts afresh.

With --carry, for a study whose cases and beds take hours (the paper box's), also what a stopped
sweep needs to go on elsewhere without redoing them: each unfinished case's checkpoint.bin (into
DEST/cases/NAME), and from the bed cache (bed.cache_dir of the bed's config, else $WIGGLE_CACHE,
else ~/.cache/wiggle), for each bed the sweep began (SWEEP_DIR/beds/bed-KEY.toml), its maker's log,
its partial file while it is not made, and the made bed while a case of the sweep is unfinished
(which case needs which bed is not recorded before the case starts, so every made bed stays until
the sweep is done). What no longer serves is removed from DEST: a made bed's partial file, the made
beds once every case is done; and, with or without --carry, the checkpoint of a case that has
finished since it was carried. Continuing: copy DEST/beds/*.bin
into the bed cache and DEST/cases into the new sweep directory, then run the same sweep command.
"""
import csv
import json
import os
import shutil
import sys
import tomllib

CASE_FILES = ("config.toml", "summary.json", "trajectory.csv", "log.txt")


def merged_log(earlier, current):
    """The log of every sweep directory the study (or a bed) ran in: `earlier` (DEST's lines) up to
    where `current` (this directory's log) begins, then `current`."""
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


def write_lines_atomically(path, lines):
    os.makedirs(os.path.dirname(path), exist_ok=True)
    with open(path + ".tmp", "w") as f:
        f.writelines(lines)
    os.replace(path + ".tmp", path)


def copy_atomically(src, dst):
    """dst as a whole copy of src or as it was: never a half-written file in the repository."""
    os.makedirs(os.path.dirname(dst), exist_ok=True)
    shutil.copy2(src, dst + ".tmp")
    os.replace(dst + ".tmp", dst)


def remove(path):
    if os.path.exists(path):
        os.remove(path)
        return 1
    return 0


def case_finished(case_dir):
    """summary.json reads whole and says ok: the sweep's own rule for a case it will not run again."""
    try:
        with open(os.path.join(case_dir, "summary.json")) as f:
            return json.load(f).get("status") == "ok"
    except (OSError, ValueError):
        return False


def bed_cache(bed_toml):
    """Where the bed maker keeps the bed of this config: bed.cache_dir, else $WIGGLE_CACHE, else ~/.cache/wiggle."""
    with open(bed_toml, "rb") as f:
        cache_dir = tomllib.load(f).get("bed", {}).get("cache_dir", "")
    return cache_dir or os.environ.get("WIGGLE_CACHE") or os.path.join(os.path.expanduser("~"), ".cache", "wiggle")


def carry(src, dest):
    """Checkpoints of unfinished cases and the beds a stopped sweep needs; what no longer serves removed."""
    with open(os.path.join(src, "results.csv"), newline="") as f:
        run_dirs = [row["run_dir"] for row in csv.DictReader(f)]  # every case of the sweep, pending ones too
    unfinished = [d for d in run_dirs if not case_finished(os.path.join(src, d))]
    copied = removed = 0
    for run_dir in run_dirs:
        checkpoint = os.path.join(src, run_dir, "checkpoint.bin")
        kept = os.path.join(dest, run_dir, "checkpoint.bin")
        if run_dir in unfinished and os.path.exists(checkpoint):
            copy_atomically(checkpoint, kept)
            copied += 1
    beds = os.path.join(src, "beds")
    for name in sorted(os.listdir(beds)) if os.path.isdir(beds) else []:
        if not (name.startswith("bed-") and name.endswith(".toml")):
            continue
        key = name[len("bed-"):-len(".toml")]
        cache = bed_cache(os.path.join(beds, name))
        made, partial = (os.path.join(cache, f"bed-{key}{ext}") for ext in (".bin", ".partial.bin"))
        log = os.path.join(beds, f"bed-{key}.log")
        kept = os.path.join(dest, "beds", f"bed-{key}")
        if os.path.exists(log):  # a bed continued in another sweep directory: its log goes on from DEST's
            write_lines_atomically(kept + ".log", merged_log(read_lines(kept + ".log"), read_lines(log)))
        if os.path.exists(made):
            removed += remove(kept + ".partial.bin")
            if unfinished:
                copy_atomically(made, kept + ".bin")
                copied += 1
            else:
                removed += remove(kept + ".bin")
        elif os.path.exists(partial):
            copy_atomically(partial, kept + ".partial.bin")
            copied += 1
    return copied, removed


def main():
    args = sys.argv[1:]
    with_fields = "--fields" in args
    with_phase = "--phase" in args
    with_carry = "--carry" in args
    args = [a for a in args if a not in ("--fields", "--phase", "--carry")]
    if len(args) != 2:
        print("usage: " + __doc__.strip().splitlines()[2].strip(), file=sys.stderr)
        sys.exit(2)
    src, dest = args
    files = CASE_FILES + (("phase_rates.csv",) if with_phase else ()) + (("fields.csv",) if with_fields else ())
    if not os.path.isfile(os.path.join(src, "results.csv")):
        print(f"collect: {src} is not a sweep directory (no results.csv)", file=sys.stderr)
        sys.exit(2)
    os.makedirs(dest, exist_ok=True)
    shutil.copy2(os.path.join(src, "results.csv"), os.path.join(dest, "results.csv"))
    if os.path.isfile(os.path.join(src, "cells.csv")):  # a sweep of this wiggle: its cells beside the rows
        shutil.copy2(os.path.join(src, "cells.csv"), os.path.join(dest, "cells.csv"))
    write_lines_atomically(os.path.join(dest, "sweep.log"),
                           merged_log(read_lines(os.path.join(dest, "sweep.log")), read_lines(os.path.join(src, "sweep.log"))))
    copied = dropped = 0
    cases = os.path.join(src, "cases")
    for case in sorted(os.listdir(cases)) if os.path.isdir(cases) else []:
        for name in files:
            path = os.path.join(cases, case, name)
            if os.path.exists(path):
                os.makedirs(os.path.join(dest, "cases", case), exist_ok=True)
                shutil.copy2(path, os.path.join(dest, "cases", case, name))
                copied += name == "summary.json"
        if case_finished(os.path.join(cases, case)):  # a checkpoint carried before it finished no longer serves
            dropped += remove(os.path.join(dest, "cases", case, "checkpoint.bin"))
    print(f"collect: {dest}: results.csv and {copied} finished cases"
          + (f"; removed the checkpoints of {dropped} carried before they finished" if dropped else ""))
    if with_carry:
        carried, removed = carry(src, dest)
        print(f"collect: {dest}: carried {carried} checkpoints and beds, removed {removed} that no longer serve")


if __name__ == "__main__":
    main()
