#!/usr/bin/python3
"""Threads on a busy machine (docs/PERFORMANCE.md, "Threads on a busy machine"; bench/README.md).

A run given two threads on a machine where another process holds one core waits at every barrier
for its descheduled thread, unless it sheds that thread (physics/ThreadGovernor.h). This bench
measures it on a 2-CPU machine (or the first two CPUs of a bigger one):

  busy:  a CPU-bound process pinned to one of the two CPUs, and beside it, interleaved, `--rounds`
         times each: `--threads 1`; `--threads 2` (the default, adaptive: it sheds the waiting thread);
         `--threads 2 --fixed-threads` (the behaviour before the governor). Prints ns per
         particle-step of the run phase (medians) and the ratios to one thread (goal: adaptive two
         threads within 1.2 x of one thread).
  quiet: the hog stopped, `--threads 1` and `--threads 2` (adaptive) on the quiet config (default the
         paper-depth preset): the speed-up of two threads (goal: at least 1.85 x) and whether the
         governor shed a thread on a quiet machine (it should not).

Every run of a config must end in the same state hash (the thread count never changes a result).
It builds nothing (--wiggle, default build/release/wiggle); beds are made on the first run, untimed.
Stop other work first: a process already busy on the machine counts as a second hog.

Usage: bench/busy_threads.py [--wiggle PATH] [--config configs/small.toml] [--steps 20000]
                             [--quiet-config configs/paper_depth.toml] [--quiet-steps 4000]
                             [--rounds 3] [--cache DIR] [--work-dir DIR] [--skip-quiet]
"""
import argparse
import os
import signal
import subprocess
import sys

sys.path.insert(0, os.path.dirname(os.path.abspath(__file__)))
from scaling import REPO, log, median, run_case  # noqa: E402  (the same runs as the scaling bench)


def measure(name, wiggle, config, steps, variants, rounds, work_dir, env):
    """Runs each (label, threads, flags) `rounds` times, interleaved; returns {label: [summaries]}."""
    runs = {label: [] for label, _, _ in variants}
    for r in range(rounds):
        order = variants[r % len(variants):] + variants[:r % len(variants)]
        for label, threads, flags in order:
            s = run_case(wiggle, config, [], steps, 1e-4, threads, os.path.join(work_dir, name, label), env, flags)
            runs[label].append(s)
            used = s.get("threads_used") or {}
            log("  %s, round %d, %-14s %8.2f ns/particle-step  threads_used %s" %
                (name, r + 1, label + ":", s["ns_per_particle_step"],
                 ", ".join("%s: %.1f s" % kv for kv in sorted(used.items())) or "-"))
    hashes = {s["state_hash"] for v in runs.values() for s in v}
    if len(hashes) != 1:
        sys.exit("%s: the runs ended in different states: %s" % (name, ", ".join(sorted(hashes))))
    return runs


def ns(runs, label):
    return median([s["ns_per_particle_step"] for s in runs[label]])


def main():
    ap = argparse.ArgumentParser(description=__doc__, formatter_class=argparse.RawDescriptionHelpFormatter)
    ap.add_argument("--wiggle", default=os.path.join(REPO, "build", "release", "wiggle"))
    ap.add_argument("--config", default=os.path.join(REPO, "configs", "small.toml"), help="the busy machine's case")
    ap.add_argument("--steps", type=int, default=20000, help="steps of each busy run (dt = 1e-4)")
    ap.add_argument("--quiet-config", default=os.path.join(REPO, "configs", "paper_depth.toml"))
    ap.add_argument("--quiet-steps", type=int, default=4000)
    ap.add_argument("--rounds", type=int, default=3)
    ap.add_argument("--cache", default="", help="bed cache (default: $WIGGLE_CACHE or ~/.cache/wiggle)")
    ap.add_argument("--work-dir", default=os.path.join(REPO, "build", "bench-work", "busy"))
    ap.add_argument("--skip-quiet", action="store_true", help="the busy part only")
    args = ap.parse_args()
    if not os.access(args.wiggle, os.X_OK):
        sys.exit("--wiggle: %s is not an executable (this script builds nothing)" % args.wiggle)
    cpus = sorted(os.sched_getaffinity(0))
    if len(cpus) < 2:
        sys.exit("busy_threads: needs two CPUs, this process may use %d" % len(cpus))
    env = dict(os.environ)
    if args.cache:
        env["WIGGLE_CACHE"] = args.cache
    env.pop("OMP_NUM_THREADS", None)
    # Two CPUs: the runs and the hog on the first two, whatever the machine has.
    pair = "%d,%d" % (cpus[0], cpus[1])
    env_runs = ["taskset", "-c", pair]
    wiggle = args.wiggle
    log("busy_threads: %s, %d steps a run, CPUs %s; load average %.2f %.2f %.2f" %
        (os.path.relpath(args.config, REPO), args.steps, pair, *os.getloadavg()))
    for name in ("busy", "quiet"):
        os.makedirs(os.path.join(args.work_dir, name), exist_ok=True)
    log("bed: made once and cached ...")
    run_case(wiggle, args.config, [], 400, 1e-4, 1, os.path.join(args.work_dir, "bed"), env)
    # The runs see only the two CPUs; the hog holds the first of them.
    wrapper = os.path.join(args.work_dir, "on-two-cpus")
    with open(wrapper, "w") as f:
        f.write("#!/bin/sh\nexec %s %s \"$@\"\n" % (" ".join(env_runs), os.path.abspath(wiggle)))
    os.chmod(wrapper, 0o755)
    # A SIGTERM (a timeout) must not leave the hog running: it becomes an exception, and `finally` stops it.
    signal.signal(signal.SIGTERM, lambda *_: sys.exit("busy_threads: terminated"))
    hog = subprocess.Popen(["taskset", "-c", str(cpus[0]), "/usr/bin/python3", "-c", "while True: pass"])
    try:
        busy = measure("busy", wrapper, args.config, args.steps,
                       [("1 thread", 1, ()), ("2 adaptive", 2, ()), ("2 fixed", 2, ("--fixed-threads",))],
                       args.rounds, args.work_dir, env)
    finally:
        hog.kill()
        hog.wait()
    one = ns(busy, "1 thread")
    log("")
    log("busy (one CPU of two held by a pinned hog), medians of %d rounds:" % args.rounds)
    log("| run | ns/particle-step | x one thread |")
    log("|---|---|---|")
    for label in ("1 thread", "2 adaptive", "2 fixed"):
        log("| %s | %.2f | %.2f |" % (label, ns(busy, label), ns(busy, label) / one))
    ratio = ns(busy, "2 adaptive") / one
    log("adaptive two threads / one thread: %.2f (goal <= 1.2): %s" % (ratio, "met" if ratio <= 1.2 else "NOT met"))
    if args.skip_quiet:
        return
    quiet = measure("quiet", wrapper, args.quiet_config, args.quiet_steps,
                    [("1 thread", 1, ()), ("2 adaptive", 2, ())], args.rounds, args.work_dir, env)
    speedup = ns(quiet, "1 thread") / ns(quiet, "2 adaptive")
    shed = sum(1 for s in quiet["2 adaptive"] if any(k != "2" for k in (s.get("threads_used") or {})))
    log("")
    log("quiet (%s): one thread %.2f, two %.2f ns/particle-step: two threads %.2f x (goal >= 1.85): %s; "
        "runs that shed a thread: %d of %d" %
        (os.path.relpath(args.quiet_config, REPO), ns(quiet, "1 thread"), ns(quiet, "2 adaptive"), speedup,
         "met" if speedup >= 1.85 else "NOT met", shed, len(quiet["2 adaptive"])))


if __name__ == "__main__":
    main()
