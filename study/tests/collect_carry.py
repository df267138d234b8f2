#!/usr/bin/python3
"""study/tools/collect.py --carry on a made-up sweep directory (no wiggle run; about a second).

A sweep of three cases (one finished, one stopped with its checkpoint, one not started) and two
beds in a private cache (one made, one part-made): collecting with --carry keeps the stopped case's
checkpoint, the part-made bed and the made one (a case is unfinished), and the finished case's
stale checkpoint goes; once the bed and every case are done, the partial file and the made bed go
too, and a bed log continued in a new sweep directory goes on from the collected one; a plain collect
(no --carry) removes the checkpoint of a case finished since it was carried."""
import json
import os
import subprocess
import sys
import tempfile

ROOT = os.path.dirname(os.path.dirname(os.path.dirname(os.path.abspath(__file__))))
COLLECT = os.path.join(ROOT, "study", "tools", "collect.py")
failures = []


def write(path, text):
    os.makedirs(os.path.dirname(path), exist_ok=True)
    with open(path, "w") as f:
        f.write(text)


def read(path):
    if not os.path.exists(path):
        return None
    with open(path) as f:
        return f.read()


def check(what, ok):
    if not ok:
        failures.append(what)
        print(f"FAIL: {what}")


def collect(src, dest, cache, carry=True):
    env = dict(os.environ, WIGGLE_CACHE=cache)
    out = subprocess.run([sys.executable, COLLECT, src, dest] + (["--carry"] if carry else []), env=env,
                         capture_output=True, text=True)
    check(f"collect exits 0 ({out.stderr.strip()})", out.returncode == 0)


with tempfile.TemporaryDirectory() as tmp:
    src, dest, cache = (os.path.join(tmp, d) for d in ("sweep", "results", "cache"))
    write(os.path.join(src, "results.csv"),
          "case,run_dir,status,vy\ndone,cases/done,ok,0.1\nstopped,cases/stopped,running,\nlater,cases/later,pending,\n")
    write(os.path.join(src, "sweep.log"), "start\n")
    write(os.path.join(src, "cases/done/summary.json"), json.dumps({"status": "ok"}))
    write(os.path.join(src, "cases/done/config.toml"), "")
    write(os.path.join(src, "cases/stopped/config.toml"), "")
    write(os.path.join(src, "cases/stopped/checkpoint.bin"), "state at t = 300")
    write(os.path.join(dest, "cases/done/checkpoint.bin"), "committed while it ran")
    for key in ("made", "part"):
        write(os.path.join(src, f"beds/bed-{key}.toml"), "[bed]\n")
        write(os.path.join(src, f"beds/bed-{key}.log"), f"[bed] {key}: pouring batch 1\n")
    write(os.path.join(cache, "bed-made.bin"), "bed")
    write(os.path.join(cache, "bed-part.partial.bin"), "half a bed")
    write(os.path.join(dest, "beds/bed-made.partial.bin"), "committed while it poured")
    collect(src, dest, cache)
    check("the stopped case's checkpoint is carried",
          read(os.path.join(dest, "cases/stopped/checkpoint.bin")) == "state at t = 300")
    check("the finished case's checkpoint is removed", not os.path.exists(os.path.join(dest, "cases/done/checkpoint.bin")))
    check("the made bed is carried while cases are unfinished", os.path.exists(os.path.join(dest, "beds/bed-made.bin")))
    check("the made bed's partial file is removed", not os.path.exists(os.path.join(dest, "beds/bed-made.partial.bin")))
    check("the part-made bed is carried", read(os.path.join(dest, "beds/bed-part.partial.bin")) == "half a bed")
    check("the beds' logs are carried", os.path.exists(os.path.join(dest, "beds/bed-part.log")))
    check("nothing half-written is left", not any(n.endswith(".tmp") for _, _, ns in os.walk(dest) for n in ns))

    # The sweep goes on in a new directory on another machine: the bed is made there, every case ends.
    src2 = os.path.join(tmp, "sweep2")
    write(os.path.join(src2, "results.csv"),
          "case,run_dir,status,vy\ndone,cases/done,ok,0.1\nstopped,cases/stopped,ok,0.2\nlater,cases/later,ok,0.3\n")
    for case in ("done", "stopped", "later"):
        write(os.path.join(src2, f"cases/{case}/summary.json"), json.dumps({"status": "ok"}))
        write(os.path.join(src2, f"cases/{case}/checkpoint.bin"), "final state")
    for key in ("made", "part"):
        write(os.path.join(src2, f"beds/bed-{key}.toml"), "[bed]\n")
    write(os.path.join(src2, "beds/bed-part.log"), "[bed] part: relaxing batch 9\n")
    os.remove(os.path.join(cache, "bed-part.partial.bin"))
    write(os.path.join(cache, "bed-part.bin"), "bed")
    collect(src2, dest, cache)
    check("a finished case's checkpoint is not carried", not os.path.exists(os.path.join(dest, "cases/later/checkpoint.bin")))
    check("checkpoints of cases since finished are removed",
          not os.path.exists(os.path.join(dest, "cases/stopped/checkpoint.bin")))
    check("made beds are removed once every case is done",
          not os.path.exists(os.path.join(dest, "beds/bed-made.bin")) and not os.path.exists(os.path.join(dest, "beds/bed-part.bin")))
    check("the bed made since has no partial file left", not os.path.exists(os.path.join(dest, "beds/bed-part.partial.bin")))
    check("its log goes on from the collected one",
          read(os.path.join(dest, "beds/bed-part.log")) == "[bed] part: pouring batch 1\n[bed] part: relaxing batch 9\n")
    check("a bed log with nothing new stays as it was", read(os.path.join(dest, "beds/bed-made.log")) == "[bed] made: pouring batch 1\n")

    # A plain collect (no --carry) of a case finished since its checkpoint was carried removes that checkpoint too.
    write(os.path.join(dest, "cases/done/checkpoint.bin"), "carried while it ran")
    collect(src2, dest, cache, carry=False)
    check("a plain collect removes a finished case's carried checkpoint",
          not os.path.exists(os.path.join(dest, "cases/done/checkpoint.bin")))

print(f"collect --carry: {len(failures)} failures")
sys.exit(1 if failures else 0)
