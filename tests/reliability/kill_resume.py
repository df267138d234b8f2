#!/usr/bin/python3
"""Kill-and-resume harness (docs/RELIABILITY.md): SIGKILLs `wiggle run` and `wiggle sweep` at random
and at chosen moments, resumes them, and checks that the outputs are bitwise identical to an
uninterrupted run's.

    tests/reliability/kill_resume.py WIGGLE_BINARY [--seed N] [--run-kills K] [--work DIR] [--keep]

One run (a 20 x 14 bed, about 250 grains, with its own empty bed cache so that the bed is made):
  1. killed while it makes its bed (at its partial file's k-th save);
  2. killed the moment the bed cache file is being written (a watcher polls for the temporary file);
  3. resumed and killed K times at drawn moments of the run (checkpoints every 200 steps);
  4. killed the moment a checkpoint is being written (the watcher polls for checkpoint.bin.tmp.*
     or for the gap between moving checkpoint.bin aside and writing the new one);
  5. resumed to the end; every output (trajectory, phase rates, fields, dumps, model, summary
     without its wall times) and the cached bed's bytes must equal the uninterrupted run's.
One sweep (3 cases, 2 jobs, each case twice as long as the run): one worker process SIGKILLed at a
drawn step of its case while the sweep goes on (recorded as failed, exit 1), then the coordinator alone
SIGKILLed (its children get SIGTERM and checkpoint), then the coordinator and all its children
SIGKILLed at once, each at a drawn step of a running case; rerun to the end; results.csv (status, vy, state_hash)
and every case's outputs must equal the uninterrupted sweep's.

Every kill waits for an event, never for a time measured beforehand, so a loaded or an idle
machine cannot make it miss its window (until session 29 the moments were wall-clock fractions of
the reference's times, and a kill could come after the stage it meant had ended): the bed's
partial file saved the k-th time, a checkpoint at or past a drawn step (the log's "checkpoint at
step S"), a worker's case past a drawn step. After the event a kill may wait a drawn fraction of
one checkpoint interval's wall time of the reference, so that it lands at any point of a step,
not only just after a checkpoint. The draws come from --seed (printed, with each kill and what the
process was doing when it died), so a failing schedule can be replayed. Exit status 0 when
everything matches.
"""
import argparse
import json
import os
import random
import shutil
import signal
import subprocess
import sys
import tempfile
import time

VOLATILE_SUMMARY_KEYS = {"wall_s", "run_wall_s", "bed_wall_s", "ns_per_particle_step", "bed_from_cache"}
RUN_OUTPUTS = ["trajectory.csv", "phase_rates.csv", "fields.csv", "model.json", "dumps/dump.lammpstrj",
               "config.toml"]

RUN_CONFIG = """\
[box]
width = 20.0
bed_height = 14.0
[intruder]
shape = "polygon"
vertices = [[-1.5, -1.5], [1.5, -1.5], [1.5, 1.5], [-1.5, 1.5]]
y0 = 7.0
[drive]
amplitude = 1.0
period = 0.5
[bed]
rest_energy = 1e-4
max_time = 100.0
[run]
dt = 0.0001
duration = {duration}
sample_interval = 0.01
dump_interval = 0.1
checkpoint_interval = 0.001
plot = false
[fields]
radius = 4.0
"""

SWEEP_FILE = """\
[sweep]
name = "kill"
[base.box]
width = 20.0
bed_height = 14.0
[base.intruder]
shape = "polygon"
vertices = [[-1.5, -1.5], [1.5, -1.5], [1.5, 1.5], [-1.5, 1.5]]
y0 = 7.0
[base.drive]
amplitude = 1.0
[base.bed]
rest_energy = 1e-4
max_time = 100.0
[base.run]
dt = 0.0001
duration = {duration}
sample_interval = 0.01
dump_interval = 0.0
checkpoint_interval = 0.001
plot = false
[base.fields]
enabled = false
[grid.drive]
period = [0.5, 1.0, 2.0]
"""

class Reporter:
    """One script's log lines (prefixed with its name) and the failed checks it collects."""

    def __init__(self, name):
        self.name = name
        self.failures = []

    def log(self, text):
        print(f"{self.name}: {text}", flush=True)

    def check(self, ok, text):
        if not ok:
            self.failures.append(text)
            self.log("FAIL: " + text)
        return ok


_report = Reporter("kill_resume")
log, check, failures = _report.log, _report.check, _report.failures


def read(path):
    with open(path, "rb") as f:
        return f.read()


def summary_without_wall_times(path):
    s = json.loads(read(path))
    return {k: v for k, v in s.items() if k not in VOLATILE_SUMMARY_KEYS}


def compare_run_dirs(ref, got, label):
    same = True
    for name in RUN_OUTPUTS:
        a, b = os.path.join(ref, name), os.path.join(got, name)
        if os.path.exists(a) or os.path.exists(b):
            same &= check(os.path.exists(b) and read(a) == read(b), f"{label}: {name} differs from the reference")
    same &= check(summary_without_wall_times(os.path.join(ref, "summary.json")) ==
                  summary_without_wall_times(os.path.join(got, "summary.json")),
                  f"{label}: summary.json differs from the reference (beyond wall times)")
    return same


def cache_beds(cache):
    """(finished beds, temporary files, partial beds: the bed in the making, saved as it goes)."""
    names = os.listdir(cache) if os.path.isdir(cache) else []
    return (sorted(n for n in names if n.endswith(".bin") and not n.endswith(".partial.bin")),
            sorted(n for n in names if ".tmp." in n), sorted(n for n in names if n.endswith(".partial.bin")))


class Harness:
    def __init__(self, wiggle, work, seed):
        self.wiggle, self.work, self.rng = wiggle, work, random.Random(seed)
        self.env = dict(os.environ, OMP_NUM_THREADS="1", OMP_WAIT_POLICY="PASSIVE")

    def start(self, args, cache):
        env = dict(self.env, WIGGLE_CACHE=cache)
        out = open(os.path.join(self.work, "processes.log"), "ab")
        out.write(("$ " + " ".join(args) + "\n").encode())
        out.flush()
        return subprocess.Popen([self.wiggle] + args, env=env, stdout=out, stderr=out)

    def kill_after(self, proc, seconds):
        """SIGKILL at `seconds` after start; returns True when the kill landed (the process was alive)."""
        try:
            proc.wait(timeout=seconds)
            return False
        except subprocess.TimeoutExpired:
            proc.send_signal(signal.SIGKILL)
            proc.wait()
            return True

    def kill_after_event(self, proc, event, delay, timeout=300.0):
        """SIGKILL `delay` seconds after `event()` first holds; True when the kill landed (the process
        was alive). Polls every millisecond; the process ending first is a miss."""
        end = time.monotonic() + timeout
        while proc.poll() is None and not event() and time.monotonic() < end:
            time.sleep(0.001)
        if proc.poll() is not None or not event():
            proc.wait() if proc.poll() is None else None
            return False
        return self.kill_after(proc, delay)

    def kill_when(self, proc, condition, timeout=120.0):
        """SIGKILL as soon as `condition()` holds (polled in a tight loop); True when it landed."""
        end = time.monotonic() + timeout
        while time.monotonic() < end and proc.poll() is None:
            if condition():
                proc.send_signal(signal.SIGKILL)
                proc.wait()
                return True
        proc.wait() if proc.poll() is None else None
        return False


def run_trials(h, run_kills, duration):
    cfg = os.path.join(h.work, "run.toml")
    with open(cfg, "w") as f:
        f.write(RUN_CONFIG.format(duration=duration))
    ref, ref_cache = os.path.join(h.work, "run-ref"), os.path.join(h.work, "cache-ref")
    t0 = time.monotonic()
    p = h.start(["run", cfg, "--out", ref, "--threads", "1"], ref_cache)
    check(p.wait() == 0, "the reference run failed (see processes.log)")
    wall = time.monotonic() - t0
    s = json.loads(read(os.path.join(ref, "summary.json")))
    bed_s, run_s = s["bed_wall_s"], s["run_wall_s"]
    log(f"run: reference {s['n_grains']} grains, {s['steps']} steps, bed {bed_s:.2f} s, run {run_s:.2f} s, "
        f"{wall:.2f} s in all, state {s['state_hash']}")

    out, cache = os.path.join(h.work, "run-killed"), os.path.join(h.work, "cache-killed")
    kills = 0
    # 1. During bed making: when the bed in the making has been saved the k-th time (its partial
    # file written anew k times, as the watcher sees it).
    saves = h.rng.randint(1, 3)
    p = h.start(["run", cfg, "--out", out, "--threads", "1"], cache)
    landed = h.kill_after_event(p, PartialSaves(cache, saves), 0.0)
    beds, temps, partials = cache_beds(cache)
    log(f"run kill 1 at the bed's partial save {saves} (bed making): {'killed' if landed else 'had finished'}; "
        f"cache holds {beds or 'no bed'}, partial {partials or 'none'}, temporary files {temps or 'none'}")
    check(landed and not beds and not os.path.exists(os.path.join(out, "checkpoint.bin")),
          "kill 1 did not land during bed making (bed making too fast for the schedule?)")
    kills += landed
    # 2. While the bed cache file is written: a half-written bed must never be found under its name.
    p = h.start(["run", "--out", out, "--resume", "--threads", "1"], cache)
    mine = f".bin.tmp.{p.pid}"
    # On a loaded machine the watcher may miss the short write: then it kills as soon as the
    # cached bed appears (just after the write), so the run phase is still ahead. (The bed in the
    # making is saved as it goes: those files, *.partial.bin, are not the bed.)
    landed = h.kill_when(p, lambda: os.path.isdir(cache) and any(
        (n.endswith(mine) or n.endswith(".bin")) and ".partial.bin" not in n for n in os.listdir(cache)))
    beds, temps, _ = cache_beds(cache)
    caught = any(t.endswith(mine) for t in temps)
    log(f"run kill 2 when the bed cache file was being written: "
        f"{'killed during the write' if caught else 'killed just after the write' if landed else 'missed'}; "
        f"cache holds {beds or 'no bed'}, temporary files {temps or 'none'}")
    check(landed, "kill 2 missed the bed cache write")
    kills += landed
    for b in beds:  # if the rename beat the kill, the bed there must be whole
        check(read(os.path.join(cache, b)) == read(os.path.join(ref_cache, b)),
              f"kill 2 left a cached bed {b} that differs from the reference's")
    # 3. At drawn moments of the run (each resume first loads the bed or a checkpoint): the first
    # once the run phase has begun, the others at a checkpoint at or past a drawn step of the first
    # 30 % of the run (which leaves most of it for the checkpoint-write kill); each then waits a
    # drawn fraction of one checkpoint interval (CHECKPOINT_STEPS steps at the reference's speed).
    interval_s = run_s * CHECKPOINT_STEPS / s["steps"]
    targets = sorted(h.rng.uniform(0.0, 0.3) * s["steps"] for _ in range(max(run_kills - 1, 0)))
    for k in range(run_kills):
        target = None if k == 0 else targets[k - 1]
        delay = h.rng.uniform(0.0, 1.0) * interval_s
        logged = len(log_lines(out))
        p = h.start(["run", "--out", out, "--resume", "--threads", "1"], cache)
        if target is None:
            event = lambda: any(w in l for l in log_lines(out)[logged:] for w in ("resumed from", "bed made", "bed loaded"))
        else:
            event = lambda: any(step >= target for step in checkpoint_steps(log_lines(out)[logged:]))
        landed = h.kill_after_event(p, event, delay)
        new = log_lines(out)[logged:]
        begun = next((l for l in new if "resumed from" in l or "bed made" in l or "bed loaded" in l), "?")
        last = checkpoint_steps(new)
        what = "once the run began" if target is None else f"at a checkpoint at or past step {target:.0f}"
        log(f"run kill {3 + k} {what}, {delay:.3f} s after: {'killed' if landed else 'had finished'} "
            f"(it began: {begun.split('  ', 1)[-1].strip()}; last checkpoint: "
            f"{f'step {last[-1]}' if last else 'none'})")
        check(landed, f"run kill {3 + k} missed: the run ended before its event")
        kills += landed
        if not landed:
            break
    # 4. While a checkpoint is written.
    done = os.path.exists(os.path.join(out, "summary.json"))
    check(not done, "the run finished before the checkpoint-write kill (kill moments too late?)")
    if not done:
        had_checkpoint = os.path.exists(os.path.join(out, "checkpoint.bin"))
        p = h.start(["run", "--out", out, "--resume", "--threads", "1"], cache)
        mine = f"checkpoint.bin.tmp.{p.pid}"

        def in_checkpoint_write():  # writing the new file, or between moving the old aside and that
            names = os.listdir(out)
            return mine in names or (had_checkpoint and "checkpoint.bin" not in names)
        landed = h.kill_when(p, in_checkpoint_write)
        names = sorted(os.listdir(out))
        hit = [n for n in names if n.startswith("checkpoint")]
        log(f"run kill during a checkpoint write: {'killed' if landed else 'missed'}; run dir has {hit}")
        check(landed, "never caught a checkpoint write in progress")
        kills += landed
    # 5. To the end.
    p = h.start(["run", "--out", out, "--resume", "--threads", "1"], cache)
    check(p.wait() == 0, "the final resume failed (see processes.log)")
    same = compare_run_dirs(ref, out, "run")
    same &= check(not [n for n in os.listdir(out) if ".tmp." in n], "the resumed run left temporary files")
    beds, _, partials = cache_beds(cache)
    same &= check(not partials, f"the bed's partial file outlived it: {partials}")
    for b in beds:
        same &= check(read(os.path.join(cache, b)) == read(os.path.join(ref_cache, b)),
                      f"the re-made bed {b} differs from the reference's")
    log(f"run: {kills} kills survived; outputs {'identical' if same else 'DIFFERENT'} "
        f"(state {summary_without_wall_times(os.path.join(out, 'summary.json'))['state_hash']})")
    return kills


# The run loop checks the wall clock for a checkpoint every this many steps (src/scenario/run/
# Experiment.cpp); with run.checkpoint_interval = 0.001 s every check writes one.
CHECKPOINT_STEPS = 200


class PartialSaves:
    """True once the bed's partial file in `cache` has been seen written anew `count` times."""

    def __init__(self, cache, count):
        self.cache, self.count, self.seen, self.last = cache, count, 0, None

    def __call__(self):
        for name in cache_beds(self.cache)[2]:
            try:
                st = os.stat(os.path.join(self.cache, name))
            except OSError:
                continue
            if (st.st_ino, st.st_mtime_ns) != self.last:
                self.last = (st.st_ino, st.st_mtime_ns)
                self.seen += 1
        return self.seen >= self.count


def wait_for_checkpoint(case, target, timeout=300.0):
    """Waits until the case process (pid, run directory) has logged a checkpoint at or past step
    `target`, or has ended."""
    end = time.monotonic() + timeout
    while (not is_zombie(case[0]) and time.monotonic() < end and
           not any(step >= target for step in checkpoint_steps(log_lines(case[1])))):
        time.sleep(0.001)


def checkpoint_steps(lines):
    """The steps of the log's "checkpoint at step S" lines."""
    return [int(l.rsplit(" ", 1)[1]) for l in lines if "checkpoint at step " in l]


def log_lines(run_dir):
    path = os.path.join(run_dir, "log.txt")
    if not os.path.exists(path):
        return []
    with open(path, errors="replace") as f:
        return f.readlines()


def children_of(pid):
    kids = []
    for entry in os.listdir("/proc"):
        if entry.isdigit():
            try:
                with open(f"/proc/{entry}/stat") as f:
                    fields = f.read().rsplit(")", 1)[1].split()
                if int(fields[1]) == pid:
                    kids.append(int(entry))
            except (OSError, IndexError):
                pass
    return kids


def wait_gone(pids, timeout=60.0):
    end = time.monotonic() + timeout
    while time.monotonic() < end:
        alive = [p for p in pids if os.path.exists(f"/proc/{p}") and not is_zombie(p)]
        if not alive:
            return True
        time.sleep(0.02)
    return False


def is_zombie(pid):
    try:
        with open(f"/proc/{pid}/stat") as f:
            return f.read().rsplit(")", 1)[1].split()[0] == "Z"
    except OSError:
        return True


def results(path):
    import csv
    with open(path) as f:
        return {r["case"]: r for r in csv.DictReader(f)}


def sweep_trials(h, duration):
    sweep = os.path.join(h.work, "sweep.toml")
    with open(sweep, "w") as f:
        f.write(SWEEP_FILE.format(duration=duration))
    args = lambda out: ["sweep", sweep, "--out", out, "--local", "--jobs", "2", "--threads", "1"]
    ref = os.path.join(h.work, "sweep-ref")
    t0 = time.monotonic()
    p = h.start(args(ref), os.path.join(h.work, "cache-sweep-ref"))
    check(p.wait() == 0, "the reference sweep failed (see processes.log)")
    wall = time.monotonic() - t0
    case_steps = min(int(r["steps"]) for r in results(os.path.join(ref, "results.csv")).values())
    log(f"sweep: reference {len(results(os.path.join(ref, 'results.csv')))} cases in {wall:.2f} s (2 jobs), "
        f"the shortest case {case_steps} steps")

    out, cache = os.path.join(h.work, "sweep-killed"), os.path.join(h.work, "cache-sweep-killed")
    kills = 0

    def running_case(p):
        """Waits until the sweep runs a case in a child process: (pid, case dir), or None."""
        end = time.monotonic() + 120
        while time.monotonic() < end and p.poll() is None:
            for k in children_of(p.pid):
                try:
                    cmd = read(f"/proc/{k}/cmdline").split(b"\0")
                except OSError:
                    continue
                if b"--run-case" in cmd:
                    return k, cmd[cmd.index(b"--out") + 1].decode()
            time.sleep(0.005)
        return None

    # 1. One worker process, while the sweep goes on: recorded as failed, retried by the rerun. It
    # is killed at its case's checkpoint at or past a drawn step of the first half of the case.
    p = h.start(args(out), cache)
    victim = running_case(p)
    target = h.rng.uniform(0.0, 0.5) * case_steps
    if victim:
        wait_for_checkpoint(victim, target)
        if not is_zombie(victim[0]):
            os.kill(victim[0], signal.SIGKILL)
    rc = p.wait()
    rows = results(os.path.join(out, "results.csv"))
    failed = [r["error"] for r in rows.values() if r["status"] == "failed"]
    log(f"sweep kill 1: worker pid {victim[0] if victim else '-'} "
        f"({os.path.basename(victim[1]) if victim else 'none found'}) at its checkpoint at or past step {target:.0f}; "
        f"the sweep exited {rc}; failed: {failed or 'none'}")
    kills += rc != 0
    check(rc == 1 and any("killed by signal 9" in e for e in failed),
          "the killed worker is not recorded as killed (or the kill came too late)")
    # 2. The coordinator alone, while a case runs: its children get SIGTERM (PR_SET_PDEATHSIG) and
    # checkpoint. 3. The coordinator and every child at once (as a crash of the machine would).
    for kill, everything in ((2, False), (3, True)):
        p = h.start(args(out), cache)
        target = h.rng.uniform(0.0, 0.5) * case_steps
        kids = []
        victim = running_case(p)
        landed = bool(victim)
        if landed:
            wait_for_checkpoint(victim, target)
            kids = children_of(p.pid)
            for pid in (kids if everything else []) + [p.pid]:
                try:
                    os.kill(pid, signal.SIGKILL)
                except ProcessLookupError:
                    pass
            landed = p.wait() == -signal.SIGKILL
            check(wait_gone(kids), "children outlived the killed sweep")
        else:
            p.wait()
        log(f"sweep kill {kill} ({f'coordinator and {len(kids)} children at once' if everything else 'coordinator only'}) "
            f"at a case's checkpoint at or past step {target:.0f}: {'killed' if landed else 'had finished'}; "
            f"case states: {sorted(set(r['status'] for r in results(os.path.join(out, 'results.csv')).values()))}")
        kills += landed
    # To the end.
    p = h.start(args(out), cache)
    check(p.wait() == 0, "the final sweep rerun failed (see processes.log)")
    a, b = results(os.path.join(ref, "results.csv")), results(os.path.join(out, "results.csv"))
    same = check(a.keys() == b.keys(), "sweep: different cases")
    for name in a:
        same &= check(all(a[name][k] == b[name][k] for k in ("status", "vy", "vy_slope", "state_hash", "steps")),
                      f"sweep: case {name} differs: {a[name]['state_hash']} vs {b[name]['state_hash']}")
        same &= compare_run_dirs(os.path.join(ref, "cases", name), os.path.join(out, "cases", name), f"sweep {name}")
    left = [os.path.join(b, n) for b, _, names in os.walk(out) for n in names if ".tmp." in n]
    same &= check(not left, f"the sweep left temporary files: {left}")
    log(f"sweep: {kills} kills survived; results {'identical' if same else 'DIFFERENT'}")
    return kills


def main():
    ap = argparse.ArgumentParser(description=__doc__, formatter_class=argparse.RawDescriptionHelpFormatter)
    ap.add_argument("wiggle")
    ap.add_argument("--seed", type=int, default=None, help="seed of the kill moments (default: random, printed)")
    ap.add_argument("--run-kills", type=int, default=3, help="random kills during the run phase")
    ap.add_argument("--duration", type=float, default=1.0, help="simulated time of the run (and each sweep case)")
    ap.add_argument("--work", default=None, help="work directory (default: a new one under /tmp)")
    ap.add_argument("--keep", action="store_true", help="keep the work directory")
    a = ap.parse_args()
    seed = a.seed if a.seed is not None else random.SystemRandom().randrange(1 << 31)
    work = a.work or tempfile.mkdtemp(prefix="wiggle-kill-resume-")
    os.makedirs(work, exist_ok=True)
    log(f"seed {seed} (replay: {sys.argv[0]} {a.wiggle} --seed {seed} --run-kills {a.run_kills} "
        f"--duration {a.duration}); work dir {work}")
    h = Harness(os.path.abspath(a.wiggle), work, seed)
    t0 = time.monotonic()
    kills = run_trials(h, a.run_kills, a.duration)
    kills += sweep_trials(h, 2.0 * a.duration)
    log(f"{kills} kills in {time.monotonic() - t0:.1f} s; {len(failures)} failures")
    if failures:
        log(f"FAILED (seed {seed}; work dir kept: {work})")
        return 1
    if not a.keep and a.work is None:
        shutil.rmtree(work)
    log("PASS")
    return 0


if __name__ == "__main__":
    sys.exit(main())
