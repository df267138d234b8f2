#!/usr/bin/python3
"""Thread scaling of wiggle's step (docs/PERFORMANCE.md, "Thread scaling"; bench/README.md).

Runs one preset (default: the paper-depth preset, configs/paper_depth.toml) at 1, 2, 4, 8, 16
threads, capped by the CPUs this process may use, `--rounds` times each (the thread counts
interleaved), with `run.profile = true`, and prints per thread count: ns per particle-step of the
run phase (median of the rounds), the speed-up over one thread, the step's serial share and wait
share (summary.json's step_profile), and Amdahl's prediction from the one-thread serial and wait share:
speed-up(n) = 1 / (s + (1 - s) / n); then per stage of the step its share of the wall time and, for a
parallel region, its threads' wait share at each thread count (which region the waiting is in). It
checks that every run ends in the same state hash. Then the
prediction with the strips' imbalance (step_profile's strip_imbalance, b(n): the heaviest thread's
share of the force stage's pairs over the mean, fixed by the list's blocks, for n = 2-32 whatever the
machine has): speed-up(n) = 1 / (s + (1 - s) b(n) / n), the divided work as slow as its heaviest strip.

It builds nothing: give it a wiggle binary (--wiggle; default build/release/wiggle) and, on a machine
without the bed, a bed cache that holds it (--cache, or $WIGGLE_CACHE): so a prepared binary and
bed can be carried to a many-core node. The bed is made on the first run when the cache lacks it.

Usage: bench/scaling.py [--wiggle PATH] [--config configs/paper_depth.toml] [--set KEY=VALUE ...]
                        [--threads 1,2,4,8,16] [--steps 2000] [--rounds 3] [--cache DIR]
                        [--work-dir DIR] [--csv FILE]
       (or bench/run_bench.sh --scaling ...)
"""
import argparse
import csv
import datetime
import json
import os
import shutil
import socket
import subprocess
import sys

REPO = os.path.dirname(os.path.dirname(os.path.abspath(__file__)))
# The bench's settings (bench/run_bench.py COMMON): no dumps, fields or figures, no checkpoint.
COMMON = ["run.dump_interval=0", "fields.enabled=false", "run.plot=false", "run.checkpoint_interval=1e9",
          "run.profile=true"]


def log(msg):
    print(msg, flush=True)


def median(v):
    v = sorted(v)
    n = len(v)
    return v[n // 2] if n % 2 else 0.5 * (v[n // 2 - 1] + v[n // 2])


def run_case(wiggle, config, extra, steps, dt, threads, out_dir, env, flags=()):
    """One run of `steps` steps at `threads` threads (`flags`: more `wiggle run` options); its summary."""
    shutil.rmtree(out_dir, ignore_errors=True)
    sets = COMMON + extra + ["run.duration=%r" % (steps * dt), "run.sample_interval=%r" % (max(1, steps // 4) * dt)]
    cmd = [wiggle, "run", config, "--out", out_dir, "--threads", str(threads)] + list(flags)
    for s in sets:
        cmd += ["--set", s]
    r = subprocess.run(cmd, env=env, stdout=subprocess.PIPE, stderr=subprocess.PIPE, text=True)
    if r.returncode != 0:
        sys.exit("failed (%d): %s\n%s" % (r.returncode, " ".join(cmd), r.stderr[-3000:]))
    with open(os.path.join(out_dir, "summary.json")) as f:
        return json.load(f)


def log_stages(runs, threads):
    """Per stage of the step (summary.json's step_profile): its share of the wall time at each thread
    count and, for a parallel stage, its threads' wait share (medians of the rounds), so that a
    many-core run says which region the waiting is in. Stages under 0.5 % at every count are left out."""
    def stage_median(t, name, key):
        values = [s["step_profile"]["stages"].get(name, {}).get(key) for s in runs[t]]
        values = [v for v in values if v is not None]
        return median(values) if values else None

    names = sorted({name for t in threads for s in runs[t] for name in s["step_profile"]["stages"]})
    shown = [n for n in names if any((stage_median(t, n, "share") or 0.0) >= 0.005 for t in threads)]
    counts = " | ".join("%d" % t for t in threads)
    log("")
    log("Per stage: share of the step's wall time / wait share of its threads (parallel stages), at %s threads:" %
        ",".join(map(str, threads)))
    log("| stage | kind | %s |" % counts)
    log("|---|---|%s" % ("---|" * len(threads)))
    for name in shown:
        kind = next(s["step_profile"]["stages"][name]["kind"] for t in threads for s in runs[t]
                    if name in s["step_profile"]["stages"])
        cells = []
        for t in threads:
            share, wait = stage_median(t, name, "share"), stage_median(t, name, "wait_share")
            cells.append("" if share is None else "%.3f" % share + ("" if wait is None else " / %.3f" % wait))
        log("| %s | %s | %s |" % (name, kind, " | ".join(cells)))


def main():
    ap = argparse.ArgumentParser(description=__doc__, formatter_class=argparse.RawDescriptionHelpFormatter)
    ap.add_argument("--wiggle", default=os.path.join(REPO, "build", "release", "wiggle"), help="the binary to run")
    ap.add_argument("--config", default=os.path.join(REPO, "configs", "paper_depth.toml"),
                    help="the case (its bed and engine keys); configs/paper.toml for the paper bed")
    ap.add_argument("--set", action="append", default=[], metavar="KEY=VALUE",
                    help="a config key for every run, as wiggle run --set (e.g. intruder.shape=square)")
    ap.add_argument("--threads", default="1,2,4,8,16", help="thread counts; those above the usable CPUs are dropped")
    ap.add_argument("--steps", type=int, default=4000, help="steps of each run, a multiple of 4 (at least ~2,000)")
    ap.add_argument("--dt", type=float, default=1e-4, help="the config's run.dt (the steps' duration)")
    ap.add_argument("--rounds", type=int, default=3)
    ap.add_argument("--cache", default="", help="bed cache (default: $WIGGLE_CACHE or ~/.cache/wiggle)")
    ap.add_argument("--work-dir", default=os.path.join(REPO, "build", "bench-work", "scaling"))
    ap.add_argument("--csv", default="", help="append the rows to this CSV file")
    args = ap.parse_args()

    if not os.access(args.wiggle, os.X_OK):
        sys.exit("--wiggle: %s is not an executable (this script builds nothing)" % args.wiggle)
    cpus = len(os.sched_getaffinity(0))
    wanted = [int(t) for t in args.threads.split(",")]
    threads = [t for t in wanted if 1 <= t <= cpus]
    if 1 not in threads:
        threads = [1] + threads
    dropped = [t for t in wanted if t > cpus]
    env = dict(os.environ)
    if args.cache:
        env["WIGGLE_CACHE"] = args.cache
    env.pop("OMP_NUM_THREADS", None)  # --threads decides
    load = os.getloadavg()
    log("scaling: %s, %d steps, threads %s on %d usable CPUs%s; load average %.2f %.2f %.2f" %
        (os.path.relpath(args.config), args.steps, ",".join(map(str, threads)), cpus,
         " (left out: %s)" % ",".join(map(str, dropped)) if dropped else "", *load))
    os.makedirs(args.work_dir, exist_ok=True)
    # The bed first (made and cached when missing): no run below times it.
    log("bed: made once and cached (that can take long) ...")
    run_case(args.wiggle, args.config, args.set, 400, args.dt, 1, os.path.join(args.work_dir, "bed"), env)

    runs = {t: [] for t in threads}
    for r in range(args.rounds):
        order = threads[r % len(threads):] + threads[:r % len(threads)]  # which count goes first rotates
        for t in order:
            s = run_case(args.wiggle, args.config, args.set, args.steps, args.dt, t, os.path.join(args.work_dir, "t%d" % t), env)
            runs[t].append(s)
            p = s["step_profile"]
            log("  round %d, %2d threads: %.2f ns/particle-step, serial %.3f, wait %.3f" %
                (r + 1, t, s["ns_per_particle_step"], p["serial_share"], p["wait_share"]))

    hashes = {s["state_hash"] for t in threads for s in runs[t]}
    if len(hashes) != 1:
        sys.exit("the thread counts ended in different states: %s" % ", ".join(sorted(hashes)))
    particles = runs[1][0]["n_particles"]
    ns = {t: median([s["ns_per_particle_step"] for s in runs[t]]) for t in threads}
    serial = {t: median([s["step_profile"]["serial_share"] for s in runs[t]]) for t in threads}
    wait = {t: median([s["step_profile"]["wait_share"] for s in runs[t]]) for t in threads}
    # One thread: the share of the step not divided among threads (the serial stages, and the parallel
    # regions' own fork and join, which the profile counts as waiting).
    s1 = median([s["step_profile"]["serial_and_wait_share"] for s in runs[1]])
    log("")
    log("%s: %d particles, %d steps, median of %d rounds, state %s" %
        (os.path.relpath(args.config), particles, args.steps, args.rounds, hashes.pop()))
    log("| threads | ns/particle-step | speed-up | Amdahl 1/(s+(1-s)/n), s = %.3f | serial share | wait share |" % s1)
    log("|---|---|---|---|---|---|")
    rows = []
    for t in threads:
        amdahl = 1.0 / (s1 + (1.0 - s1) / t)
        rows.append(dict(date=datetime.datetime.now().isoformat(timespec="seconds"), host=socket.gethostname(),
                         config=os.path.relpath(args.config), particles=particles, steps=args.steps, threads=t,
                         cpus=cpus, ns_per_particle_step=ns[t], speedup=ns[1] / ns[t], amdahl=amdahl,
                         serial_share=serial[t], wait_share=wait[t], load=load[0]))
        log("| %d | %.2f | %.2f | %.2f | %.3f | %.3f |" % (t, ns[t], ns[1] / ns[t], amdahl, serial[t], wait[t]))
    log("(speed-up below Amdahl's prediction is the wait share's: threads idle at a region's end)")
    log_stages(runs, threads)
    imbalance = runs[1][0]["step_profile"].get("strip_imbalance", {})
    if imbalance:
        log("")
        log("Prediction with the strips' imbalance b(n) (the list's blocks), s = %.3f:" % s1)
        log("| threads | b(n) | Amdahl | with b(n): 1/(s+(1-s)b/n) |")
        log("|---|---|---|---|")
        for n in sorted(imbalance, key=int):
            b, t = imbalance[n], int(n)
            log("| %d | %.3f | %.2f | %.2f |" % (t, b, 1.0 / (s1 + (1.0 - s1) / t), 1.0 / (s1 + (1.0 - s1) * b / t)))
    if args.csv:
        new = not os.path.exists(args.csv)
        with open(args.csv, "a", newline="") as f:
            w = csv.DictWriter(f, fieldnames=list(rows[0]))
            if new:
                w.writeheader()
            w.writerows(rows)


if __name__ == "__main__":
    main()
