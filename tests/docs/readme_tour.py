#!/usr/bin/python3
"""The README's "5-minute tour", run as written and timed: the source of the costs the README
quotes for it.

    readme_tour.py SOURCE_DIR BUILD_DIR

Copies the tree's tracked files (as a clone has them), links BUILD_DIR as its build/release, and
runs the tour's shell block line by line from the copy's root, as a user who has just run
`tools/bootstrap.sh run` would: the default bed must already be in the cache ($WIGGLE_CACHE, or a
temporary one where this script makes it first, timed apart). Prints each line's wall time, the
total and the load average; exits 1 when a line fails. Label `slow` (minutes): `ctest -L slow`.
"""
import os
import re
import subprocess
import sys
import tempfile
import time

sys.path.insert(0, os.path.dirname(os.path.abspath(__file__)))
from python_routes import fresh_copy  # noqa: E402


def tour_lines(readme):
    with open(readme, encoding="utf-8") as f:
        text = f.read()
    block = re.search(r"## A 5-minute tour.*?```sh\n(.*?)```", text, re.S).group(1)
    return [line for line in block.splitlines() if line.strip() and not line.lstrip().startswith("#")]


def main():
    source, build = os.path.abspath(sys.argv[1]), os.path.abspath(sys.argv[2])
    work = tempfile.mkdtemp(prefix="wiggle-tour-")
    tree = os.path.join(work, "clone")
    fresh_copy(source, tree)
    os.makedirs(os.path.join(tree, "build"))
    os.symlink(build, os.path.join(tree, "build", "release"))
    env = dict(os.environ, WIGGLE_CACHE=os.environ.get("WIGGLE_CACHE") or os.path.join(work, "cache"))
    print(f"load average at the start: {os.getloadavg()[0]:.1f} on {os.cpu_count()} cores", flush=True)
    started = time.monotonic()
    # What tools/bootstrap.sh run leaves: the default bed in the cache (nothing more when cached).
    subprocess.run([os.path.join(build, "wiggle"), "run", "--out", os.path.join(work, "default"), "--no-plot",
                    "--set", "run.duration=0.1"], env=env, check=True, capture_output=True)
    print(f"{time.monotonic() - started:7.1f} s  (the default bed, as tools/bootstrap.sh run leaves it cached)")
    lines = tour_lines(os.path.join(tree, "README.md"))
    script = ""
    total = 0.0
    failed = False
    for line in lines:
        script_line = line.split("  #")[0].rstrip()
        t0 = time.monotonic()
        done = subprocess.run(["/bin/bash", "-c", script + script_line], cwd=tree, env=env,
                              capture_output=True, text=True)
        spent = time.monotonic() - t0
        if script_line.startswith("B="):
            script += script_line + "\n"
            continue
        total += spent
        print(f"{spent:7.1f} s  {script_line}", flush=True)
        if done.returncode != 0:
            failed = True
            print(f"  FAILED (exit {done.returncode}): {done.stderr.strip().splitlines()[-1:]}", flush=True)
    print(f"{total:7.1f} s  the tour ({total / 60:.1f} min); load average at the end: {os.getloadavg()[0]:.1f}")
    subprocess.run(["rm", "-rf", work])
    return 1 if failed else 0


if __name__ == "__main__":
    sys.exit(main())
