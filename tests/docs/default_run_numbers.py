#!/usr/bin/python3
"""The documents' numbers of the default run, checked against a fresh default run.

    default_run_numbers.py WIGGLE [RUN_DIR]

Runs `WIGGLE run` with no config (the default case, t = 100; its bed comes from the cache or is made)
into RUN_DIR (default: a temporary directory), reads its summary.json, and checks every place in
the README and docs/ that quotes that run: each claim below is a pattern whose numbers must be the
run's, to the digits the text gives. A claim whose text is no longer found fails too: reworded
documents must say where their numbers went. Exits 1 with one line per mismatch.
"""
import json
import os
import re
import subprocess
import sys
import tempfile

ROOT = os.path.dirname(os.path.dirname(os.path.dirname(os.path.abspath(__file__))))
NUMBER = r"([+-]?\d+\.\d+)"
HASH = r"([0-9a-f]{16})"

# (file, pattern, the summary key of each group). A number is compared rounded to its own digits.
CLAIMS = [
    ("README.md", r"V_y = " + NUMBER + r" d per time unit on this engine's bed", ["vy"]),
    ("study/VALIDATION.md", r"since\s+session 3, gives " + NUMBER + r" with state hash " + HASH,
     ["vy", "state_hash"]),
    ("study/VALIDATION.md", r"freshly made\s+bed gives V_y = \*\*" + NUMBER + r"\*\* \(slope " + NUMBER +
     r"; y " + NUMBER + r" -> " + NUMBER + r"\)", ["vy", "vy_slope", "y_start", "y_final"]),
    ("docs/RELIABILITY.md", r"The default case \(`wiggle run`\) ends with " + NUMBER + r" and " + NUMBER +
     r" \(state\s+hash " + HASH, ["overlap_margin", "speed_margin", "state_hash"]),
]


def agrees(text, value):
    """Whether the quoted text is the value: equal hashes, or the value rounded to the text's digits."""
    if isinstance(value, str):
        return text == value
    digits = len(text.split(".")[1])
    return abs(float(text) - value) <= 0.5 * 10 ** -digits + 1e-12


def check(summary):
    problems = []
    for name, pattern, keys in CLAIMS:
        with open(os.path.join(ROOT, name), encoding="utf-8") as f:
            match = re.search(pattern, f.read())
        if match is None:
            problems.append(f"{name}: the text /{pattern}/ is not there any more (update tests/docs/default_run_numbers.py)")
            continue
        for text, key in zip(match.groups(), keys):
            if not agrees(text, summary[key]):
                problems.append(f"{name}: says {key} = {text}, the default run gives {summary[key]}")
    return problems


def main():
    if len(sys.argv) not in (2, 3):
        sys.exit(__doc__.strip().splitlines()[2].strip())
    wiggle = sys.argv[1]
    with tempfile.TemporaryDirectory() as scratch:
        run_dir = sys.argv[2] if len(sys.argv) == 3 else os.path.join(scratch, "run")
        if not os.path.exists(os.path.join(run_dir, "summary.json")):
            subprocess.run([wiggle, "run", "--out", run_dir, "--threads", "1", "--set", "run.plot=false"], check=True,
                           stdout=subprocess.DEVNULL)
        with open(os.path.join(run_dir, "summary.json"), encoding="utf-8") as f:
            summary = json.load(f)
    problems = check(summary)
    for p in problems:
        print(p)
    print(f"{len(CLAIMS)} claims checked against the default run (state {summary['state_hash']}): "
          f"{len(problems)} problems")
    sys.exit(1 if problems else 0)


if __name__ == "__main__":
    main()
