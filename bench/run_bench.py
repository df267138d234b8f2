#!/usr/bin/python3
"""wiggle vs LAMMPS on the same settled bed (docs/PERFORMANCE.md).

One invocation: builds wiggle (Release), installs LAMMPS from Debian if `lmp` is absent, makes or
reuses the cached beds, exports each to LAMMPS with `wiggle export-lammps`, then runs both codes
with the same oscillating intruder for the same number of steps at 1 and 2 threads / MPI ranks,
interleaving the codes and repeating the rounds. Prints a table and appends the rows to
bench/results/<date>-<host>.csv.

Timings are the run phase only: wiggle's summary.json `run_wall_s` (bed excluded) and LAMMPS's
"Loop time of X on P procs for N steps with M atoms". Both are divided by the same particle count
(every atom of the LAMMPS data file: grains + base + intruder atoms) and the step count.

Usage: bench/run_bench.sh [--quick] [--rounds N] [--threads 1,2] [--build-dir DIR] [--no-build] [--cache DIR]
  --quick   the ~3,000-grain bed only (the 63,000-grain paper bed takes hours to make the first time)
"""
import argparse
import csv
import datetime
import json
import os
import re
import shutil
import socket
import subprocess
import sys

REPO = os.path.dirname(os.path.dirname(os.path.abspath(__file__)))

CASES = {
    # name: (--set overrides, steps)
    "small": (["box.width=60", "box.bed_height=50", "intruder.y0=25"], 20000),
    "paper": (["box.width=300", "box.bed_height=195", "intruder.y0=90"], 5000),
    # The 245-grain bed of tests/io/LammpsExportTest.cpp: a smoke test of this script (--cases tiny).
    "tiny": (["box.width=20", "box.bed_height=14", "box.seed=7", "intruder.y0=7", "bed.rest_energy=1e-6"], 20000),
}
COMMON = ["intruder.shape=disk", "drive.amplitude=3", "drive.period=5", "run.dt=0.0001",
          "run.dump_interval=0", "fields.enabled=false", "run.plot=false",
          "run.checkpoint_interval=1e9", "run.sample_interval=0.05"]


def log(msg):
    print(msg, flush=True)


def run(cmd, cwd=None, env=None, capture=True, show_stderr=False):
    r = subprocess.run(cmd, cwd=cwd, env=env, text=True,
                       stdout=subprocess.PIPE if capture else None,
                       stderr=subprocess.PIPE if capture and not show_stderr else None)
    if r.returncode != 0:
        sys.exit("command failed (%d): %s\n%s%s" % (r.returncode, " ".join(cmd),
                                                    r.stdout or "", r.stderr or ""))
    return r


def peak_rss_mb(stderr_text):
    m = re.search(r"Maximum resident set size \(kbytes\): (\d+)", stderr_text)
    return int(m.group(1)) / 1024.0 if m else float("nan")


def machine():
    model, cpus = "?", os.cpu_count()
    try:
        out = subprocess.run(["lscpu"], text=True, stdout=subprocess.PIPE).stdout
        for line in out.splitlines():
            if line.startswith("Model name:"):
                model = line.split(":", 1)[1].strip()
    except OSError:
        pass
    return model, cpus


def lammps_version():
    out = subprocess.run(["lmp", "-h"], text=True, stdout=subprocess.PIPE).stdout
    for line in out.splitlines():
        if "Large-scale" in line:
            return line.split(" - ", 1)[-1].strip()
    return "?"


def ensure_lammps():
    if shutil.which("lmp"):
        return
    if os.geteuid() != 0:
        sys.exit("lmp (LAMMPS) not found and not root: apt-get install lammps")
    log("installing LAMMPS from Debian (apt-get install -y lammps) ...")
    run(["apt-get", "install", "-y", "lammps"], capture=False)


def build(build_dir):
    log("building wiggle (Release) in %s ..." % build_dir)
    run(["cmake", "-S", REPO, "-B", build_dir, "-DCMAKE_BUILD_TYPE=Release"])
    run(["cmake", "--build", build_dir, "--target", "wiggle", "-j2"])
    return os.path.join(build_dir, "wiggle")


def sets(items):
    out = []
    for s in items:
        out += ["--set", s]
    return out


def run_wiggle(wiggle, case_sets, out_dir, threads, env):
    shutil.rmtree(out_dir, ignore_errors=True)
    cmd = ["/usr/bin/time", "-v", wiggle, "run"] + sets(case_sets) + \
          ["--out", out_dir, "--threads", str(threads), "--no-plot"]
    r = run(cmd, env=env)
    with open(os.path.join(out_dir, "summary.json")) as f:
        summary = json.load(f)
    return summary["run_wall_s"], summary["steps"], peak_rss_mb(r.stderr)


def run_lammps(deck_dir, work_dir, ranks):
    shutil.rmtree(work_dir, ignore_errors=True)
    os.makedirs(work_dir)
    for name in ("data.lammps", "in.wiggle"):
        shutil.copy(os.path.join(deck_dir, name), work_dir)
    lmp = ["lmp", "-in", "in.wiggle", "-log", "log.lammps", "-screen", "none"]
    if ranks > 1:
        lmp = ["mpirun", "--allow-run-as-root", "--oversubscribe", "-np", str(ranks)] + lmp
    r = run(["/usr/bin/time", "-v"] + lmp, cwd=work_dir)
    with open(os.path.join(work_dir, "log.lammps")) as f:
        text = f.read()
    m = re.search(r"Loop time of ([0-9.eE+-]+) on (\d+) procs for (\d+) steps with (\d+) atoms", text)
    if not m:
        sys.exit("no loop time in %s/log.lammps" % work_dir)
    return float(m.group(1)), int(m.group(3)), int(m.group(4)), peak_rss_mb(r.stderr)


def main():
    ap = argparse.ArgumentParser(description=__doc__, formatter_class=argparse.RawDescriptionHelpFormatter)
    ap.add_argument("--quick", action="store_true", help="small bed only")
    ap.add_argument("--rounds", type=int, default=3)
    ap.add_argument("--threads", default="1,2", help="thread / rank counts, comma separated")
    ap.add_argument("--build-dir", default=os.path.join(REPO, "build", "bench"))
    ap.add_argument("--work-dir", default=os.path.join(REPO, "build", "bench-work"))
    ap.add_argument("--no-build", action="store_true", help="use the wiggle already in --build-dir")
    ap.add_argument("--cache", default="", help="bed cache (default: $WIGGLE_CACHE or ~/.cache/wiggle)")
    ap.add_argument("--cases", default="", help="comma-separated case names (small, paper, tiny); overrides --quick")
    ap.add_argument("--steps-small", type=int, default=CASES["small"][1])
    ap.add_argument("--steps-paper", type=int, default=CASES["paper"][1])
    args = ap.parse_args()

    wiggle = os.path.join(args.build_dir, "wiggle") if args.no_build else build(args.build_dir)
    ensure_lammps()
    model, cpus = machine()
    host = socket.gethostname()
    env = dict(os.environ)
    if args.cache:
        env["WIGGLE_CACHE"] = args.cache
    threads = [int(t) for t in args.threads.split(",")]
    cases = ["small"] if args.quick else ["small", "paper"]
    if args.cases:
        cases = args.cases.split(",")
    steps_of = {"small": args.steps_small, "paper": args.steps_paper, "tiny": CASES["tiny"][1]}
    log("machine: %s, %d logical CPUs; LAMMPS %s" % (model, cpus, lammps_version()))

    rows = []
    for case in cases:
        steps = steps_of[case]
        case_sets = COMMON + CASES[case][0] + ["run.duration=%r" % (steps * 1e-4)]
        deck_dir = os.path.join(args.work_dir, case, "deck")
        log("[%s] bed + export-lammps (the bed is made once and cached; that can take long) ..." % case)
        t0 = datetime.datetime.now()
        # stderr passes through: making the paper bed takes long, and its progress lines say how far it is.
        r = run([wiggle, "export-lammps"] + sets(case_sets) + ["--out", deck_dir], env=env, show_stderr=True)
        log("  " + r.stdout.strip().replace("\n", "\n  ") +
            "  (%.0f s)" % (datetime.datetime.now() - t0).total_seconds())
        for rnd in range(1, args.rounds + 1):
            for t in threads:
                # Interleave: wiggle then LAMMPS at the same thread count, alternating the order per round.
                order = ["wiggle", "lammps"] if rnd % 2 else ["lammps", "wiggle"]
                for code in order:
                    load = os.getloadavg()[0]
                    if code == "wiggle":
                        wall, nsteps, rss = run_wiggle(wiggle, case_sets,
                                                       os.path.join(args.work_dir, case, "wiggle-%d" % t), t, env)
                        atoms = None
                    else:
                        wall, nsteps, atoms, rss = run_lammps(deck_dir, os.path.join(args.work_dir, case, "lammps-%d" % t), t)
                    rows.append(dict(case=case, code=code, threads=t, round=rnd, steps=nsteps, wall=wall,
                                     atoms=atoms, rss=rss, load=load))
                    log("  round %d %-6s %d thr: %.3f s for %d steps, peak RSS %.0f MB (load before %.2f)" %
                        (rnd, code, t, wall, nsteps, rss, load))
        n_atoms = next(r["atoms"] for r in rows if r["case"] == case and r["code"] == "lammps")
        for r in rows:
            if r["case"] == case:
                r["atoms"] = n_atoms
                r["ns"] = 1e9 * r["wall"] / (n_atoms * r["steps"])

    # Table: median over rounds.
    def median(v):
        v = sorted(v)
        return v[len(v) // 2] if len(v) % 2 else 0.5 * (v[len(v) // 2 - 1] + v[len(v) // 2])

    log("\nns per particle-step (median of %d rounds; min-max), particles = all LAMMPS atoms" % args.rounds)
    log("%-6s %7s %4s | %-20s | %-20s | %-6s | %-9s %-9s" %
        ("case", "atoms", "thr", "wiggle", "LAMMPS", "ratio", "RSS wig", "RSS lmp"))
    for case in cases:
        for t in threads:
            w = [r for r in rows if r["case"] == case and r["threads"] == t and r["code"] == "wiggle"]
            l = [r for r in rows if r["case"] == case and r["threads"] == t and r["code"] == "lammps"]
            wm, lm = median([r["ns"] for r in w]), median([r["ns"] for r in l])
            log("%-6s %7d %4d | %6.1f (%5.1f-%5.1f) | %6.1f (%5.1f-%5.1f) | %6.2f | %6.0f MB %6.0f MB" %
                (case, w[0]["atoms"], t, wm, min(r["ns"] for r in w), max(r["ns"] for r in w),
                 lm, min(r["ns"] for r in l), max(r["ns"] for r in l), lm / wm,
                 max(r["rss"] for r in w), max(r["rss"] for r in l)))

    os.makedirs(os.path.join(REPO, "bench", "results"), exist_ok=True)
    path = os.path.join(REPO, "bench", "results", "%s-%s.csv" % (datetime.date.today().isoformat(), host))
    new = not os.path.exists(path)
    stamp = datetime.datetime.now().isoformat(timespec="seconds")
    with open(path, "a", newline="") as f:
        w = csv.writer(f)
        if new:
            w.writerow(["timestamp", "host", "cpu_model", "logical_cpus", "case", "code", "threads", "round",
                        "atoms", "steps", "loop_s", "ns_per_particle_step", "peak_rss_mb", "load_avg_1min"])
        for r in rows:
            w.writerow([stamp, host, model, cpus, r["case"], r["code"], r["threads"], r["round"], r["atoms"],
                        r["steps"], "%.4f" % r["wall"], "%.2f" % r["ns"], "%.1f" % r["rss"], "%.2f" % r["load"]])
    log("appended %d rows to %s" % (len(rows), path))


if __name__ == "__main__":
    main()
