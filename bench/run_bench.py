#!/usr/bin/python3
"""wiggle vs LAMMPS on the same settled bed (docs/PERFORMANCE.md, bench/README.md).

One invocation: builds wiggle (Release) and its floor benchmark, gets LAMMPS (Debian's `lmp`, and
the optimised build of the same version from bench/build_lammps.sh), makes or reuses the cached
beds, exports each to LAMMPS with `wiggle export-lammps`, then runs every chosen code with the same
oscillating intruder for the same number of steps at 1 and 2 threads, interleaving the codes and
repeating the rounds. Then the floor (wiggle_floor: the contact law alone over the bed's listed
pairs) on each bed, and the step's ratio to it. Prints a table and appends the rows to
bench/results/<date>-<host>.csv.

Codes (--codes):
  wiggle      `wiggle run --threads N`
  wiggle-bound  the same with the threads bound one per CPU (OMP_PROC_BIND=true, OMP_PLACES=cores):
              the pinned placement, beside wiggle's unpinned one
  lammps      Debian's `lmp`, N MPI ranks (mpirun -np N)
  lammps-opt  the anchor: the same LAMMPS version built -O3 -march=native with OPENMP
              (bench/build_lammps.sh), one rank, `-sf omp -pk omp N`, OMP_NUM_THREADS=N

Timings are the run phase only: wiggle's summary.json `run_wall_s` (bed excluded) and LAMMPS's
"Loop time of X on P procs for N steps with M atoms". All are divided by the same particle count
(every atom of the LAMMPS data file: grains + base + intruder atoms) and the step count.

Then each case's `wiggle run --check` estimate (ns per particle-step, from this machine's speed log)
against wiggle's measured one-thread median.

The thread-scaling case (1, 2, 4, 8, 16 threads, with the step's profile) is bench/scaling.py, also
run as `bench/run_bench.sh --scaling [its options]`.

Usage: bench/run_bench.sh [--quick] [--cases small,preset,paper] [--codes wiggle,lammps,lammps-opt]
                          [--rounds N] [--threads 1,2] [--no-floor] [--lammps-opt PATH] ...
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
    # the paper-depth preset's box (configs/paper_depth.toml): ~12,500 grains
    "preset": (["box.width=60", "box.bed_height=195", "intruder.y0=90"], 10000),
    "paper": (["box.width=300", "box.bed_height=195", "intruder.y0=90"], 5000),
    # The 245-grain bed of tests/io/LammpsExportTest.cpp: a smoke test of this script (--cases tiny).
    "tiny": (["box.width=20", "box.bed_height=14", "box.seed=7", "intruder.y0=7", "bed.rest_energy=1e-6"], 20000),
}
COMMON = ["intruder.shape=disk", "drive.amplitude=3", "drive.period=5", "run.dt=0.0001",
          "run.dump_interval=0", "fields.enabled=false", "run.plot=false",
          "run.checkpoint_interval=1e9", "run.sample_interval=0.05"]
CODES = ["wiggle", "wiggle-bound", "lammps", "lammps-opt"]
WHAT_THREADS_ARE = {"wiggle": "OpenMP threads", "wiggle-bound": "OpenMP threads bound one per CPU",
                    "lammps": "MPI ranks", "lammps-opt": "OpenMP threads, 1 rank"}
BOUND = {"OMP_PROC_BIND": "true", "OMP_PLACES": "cores"}
ESTIMATE_TOL = 0.25   # `run --check`'s ns per particle-step within 25 % of the measured (the performance issue)
# The optimised LAMMPS is compiled with FMA contraction, Debian's is not (nor is wiggle): the same
# deck gives the same physics with other round-off, which the granular dynamics amplifies. So the
# intruder's height must agree closely at the first sample (t = 0.05, 500 steps: measured 1e-13 on
# the small bed) and loosely at the end (t = 2, 20,000 steps: measured 0.02 d, where Debian's own 1
# and 2 ranks differ by 0.013 d; the bound is 0.1 d). A wrong build, style or deck differs far more early on.
EARLY_TOL_Y = 1e-9
PHYSICS_TOL_Y = 0.1


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


def lammps_version(binary):
    out = subprocess.run([binary, "-h"], text=True, stdout=subprocess.PIPE).stdout
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


def optimised_lammps():
    """The anchor's binary: bench/build_lammps.sh builds it once (tens of minutes) and then finds it."""
    log("optimised LAMMPS: bench/build_lammps.sh (builds it the first time; that takes long) ...")
    r = run([os.path.join(REPO, "bench", "build_lammps.sh")], show_stderr=True)
    binary = r.stdout.strip().splitlines()[-1]
    if not os.access(binary, os.X_OK):
        sys.exit("bench/build_lammps.sh did not name a binary (got %r)" % binary)
    return binary


def build(build_dir, targets):
    log("building %s (Release) in %s ..." % (", ".join(targets), build_dir))
    run(["cmake", "-S", REPO, "-B", build_dir, "-DCMAKE_BUILD_TYPE=Release", "-DWIGGLE_BENCH=ON"])
    for target in targets:
        run(["nice", "-n", "5", "cmake", "--build", build_dir, "--target", target, "-j2"])


def sets(items):
    out = []
    for s in items:
        out += ["--set", s]
    return out


def data_file_atoms(deck_dir):
    """The particle count every code is divided by: the data file's header line 'N atoms'."""
    with open(os.path.join(deck_dir, "data.lammps")) as f:
        for line in f:
            m = re.match(r"\s*(\d+)\s+atoms\s*$", line)
            if m:
                return int(m.group(1))
    sys.exit("no 'N atoms' line in %s/data.lammps" % deck_dir)


def run_wiggle(wiggle, case_sets, out_dir, threads, env, bound):
    shutil.rmtree(out_dir, ignore_errors=True)
    env = dict(env, **BOUND) if bound else env
    cmd = ["/usr/bin/time", "-v", wiggle, "run"] + sets(case_sets) + \
          ["--out", out_dir, "--threads", str(threads), "--no-plot"]
    r = run(cmd, env=env)
    with open(os.path.join(out_dir, "summary.json")) as f:
        summary = json.load(f)
    return dict(wall=summary["run_wall_s"], steps=summary["steps"], atoms=None, rss=peak_rss_mb(r.stderr))


def samples(work_dir):
    """The intruder's (t, y) rows of the deck's trajectory.csv (17 significant digits), from t = 0."""
    with open(os.path.join(work_dir, "trajectory.csv")) as f:
        rows = [line.split(",") for line in f.read().split("\n")[1:] if line.strip()]
    if len(rows) < 2:
        sys.exit("fewer than two samples in %s/trajectory.csv" % work_dir)
    return [(float(r[0]), float(r[2])) for r in rows]


def run_lammps(binary, deck_dir, work_dir, n, openmp):
    """Debian's style (openmp False): n MPI ranks. The anchor's (openmp True): one rank, n threads."""
    shutil.rmtree(work_dir, ignore_errors=True)
    os.makedirs(work_dir)
    for name in ("data.lammps", "in.wiggle"):
        shutil.copy(os.path.join(deck_dir, name), work_dir)
    lmp = [binary, "-in", "in.wiggle", "-log", "log.lammps", "-screen", "none"]
    env = dict(os.environ)
    if openmp:
        lmp += ["-sf", "omp", "-pk", "omp", str(n)]
        env["OMP_NUM_THREADS"] = str(n)
    elif n > 1:
        lmp = ["mpirun", "--allow-run-as-root", "--oversubscribe", "-np", str(n)] + lmp
    r = run(["/usr/bin/time", "-v"] + lmp, cwd=work_dir, env=env)
    with open(os.path.join(work_dir, "log.lammps")) as f:
        text = f.read()
    m = re.search(r"Loop time of ([0-9.eE+-]+) on (\d+) procs for (\d+) steps with (\d+) atoms", text)
    if not m:
        sys.exit("no loop time in %s/log.lammps" % work_dir)
    return dict(wall=float(m.group(1)), steps=int(m.group(3)), atoms=int(m.group(4)), rss=peak_rss_mb(r.stderr),
                samples=samples(work_dir))


def estimated_ns(wiggle, case_sets, out_dir, env):
    """The ns per particle-step `wiggle run --check` would plan this case with (this machine's speed log)."""
    r = run([wiggle, "run"] + sets(case_sets) + ["--check", "--out", out_dir], env=env)
    m = re.search(r"at ([0-9.]+) ns per particle-step", r.stdout + (r.stderr or ""))
    if not m:
        sys.exit("no 'at X ns per particle-step' in `wiggle run --check`'s output:\n" + r.stdout)
    return float(m.group(1))


def run_floor(floor, case_sets, json_path, env):
    """wiggle_floor on the case's bed at one thread: the law's sweep time and the engine's step time."""
    env = dict(env, OMP_NUM_THREADS="1")
    run([floor] + sets(case_sets) + ["--threads", "1", "--json", json_path], env=env)
    with open(json_path) as f:
        return json.load(f)


def median(v):
    v = sorted(v)
    return v[len(v) // 2] if len(v) % 2 else 0.5 * (v[len(v) // 2 - 1] + v[len(v) // 2])


def check_same_physics(rows, case, atoms, steps, tol):
    """The anchor against Debian's lmp on this case: the same atoms, steps and samples in every run
    (else exit); the intruder's height at the first sample after t = 0, before chaos has grown the
    round-off, to EARLY_TOL_Y; and at the end to tol. Returns a line to print and whether it passed."""
    lmp = [r for r in rows if r["case"] == case and r["code"] in ("lammps", "lammps-opt")]
    for r in lmp:
        if r["atoms"] != atoms or r["steps"] != steps:
            sys.exit("%s %s round %d ran %d atoms for %d steps; the deck has %d atoms and %d steps" %
                     (case, r["code"], r["round"], r["atoms"], r["steps"], atoms, steps))
    if len({tuple(t for t, _ in r["samples"]) for r in lmp}) > 1:
        sys.exit("%s: the LAMMPS runs' trajectory.csv have different sample times" % case)
    ref = [r["samples"] for r in lmp if r["code"] == "lammps"]
    opt = [r["samples"] for r in lmp if r["code"] == "lammps-opt"]
    if not ref or not opt:
        return None, True

    def gap(index):
        return max(abs(a[index][1] - b[index][1]) for a in opt for b in ref)

    def spread(runs, index):
        return max(r[index][1] for r in runs) - min(r[index][1] for r in runs)

    early, final = gap(1), gap(-1)
    ok = early <= EARLY_TOL_Y and final <= tol
    return ("%s: lammps-opt vs lammps: %d atoms, %d steps, the same samples in every run; intruder's y "
            "(trajectory.csv) at t = %g differs by %.1e d at most (tolerance %.0e), at the end (t = %g) by %.1e d "
            "(tolerance %.2g; Debian's own runs spread by %.1e d): %s" %
            (case, atoms, steps, opt[0][1][0], early, EARLY_TOL_Y, opt[0][-1][0], final, tol, spread(ref, -1),
             "same physics" if ok else "DIFFERENT")), ok


def main():
    if "--scaling" in sys.argv[1:]:  # the thread-scaling case: bench/scaling.py, which builds nothing
        args = [a for a in sys.argv[1:] if a != "--scaling"]
        os.execv(sys.executable, [sys.executable, os.path.join(REPO, "bench", "scaling.py")] + args)
    ap = argparse.ArgumentParser(description=__doc__, formatter_class=argparse.RawDescriptionHelpFormatter)
    ap.add_argument("--quick", action="store_true", help="small bed only")
    ap.add_argument("--rounds", type=int, default=3)
    ap.add_argument("--threads", default="1,2", help="thread / rank counts, comma separated")
    ap.add_argument("--codes", default=",".join(CODES), help="comma-separated, of: " + ", ".join(CODES))
    ap.add_argument("--no-floor", action="store_true", help="skip wiggle_floor (the law's floor and the ratio)")
    ap.add_argument("--lammps-opt", default="", help="the optimised LAMMPS binary (default: bench/build_lammps.sh's)")
    ap.add_argument("--physics-tol", type=float, default=PHYSICS_TOL_Y,
                    help="largest |final y| difference [d] between lammps-opt and lammps (%(default)s)")
    ap.add_argument("--build-dir", default=os.path.join(REPO, "build", "bench"))
    ap.add_argument("--work-dir", default=os.path.join(REPO, "build", "bench-work"))
    ap.add_argument("--no-build", action="store_true", help="use the wiggle already in --build-dir")
    ap.add_argument("--cache", default="", help="bed cache (default: $WIGGLE_CACHE or ~/.cache/wiggle)")
    ap.add_argument("--cases", default="", help="comma-separated case names (small, preset, paper, tiny); overrides --quick")
    ap.add_argument("--steps-small", type=int, default=CASES["small"][1])
    ap.add_argument("--steps-preset", type=int, default=CASES["preset"][1])
    ap.add_argument("--steps-paper", type=int, default=CASES["paper"][1])
    ap.add_argument("--write-costs", action="store_true",
                    help="then rewrite bench/costs.csv (the one cost table) from this run's medians, and the documents' "
                         "cost blocks (tools/docs/costs.py); needs the three default beds at 1 and 2 threads")
    ap.add_argument("--machine", default="",
                    help="with --write-costs: the machine as the table names it (default: lscpu's model name, "
                         "the logical CPUs and the widest instruction set)")
    args = ap.parse_args()

    codes = args.codes.split(",")
    unknown = [c for c in codes if c not in CODES]
    if unknown or not codes:
        sys.exit("--codes: unknown %s (choose from %s)" % (",".join(unknown), ", ".join(CODES)))
    codes = [c for c in CODES if c in codes]  # the table's order
    with_floor = "wiggle" in codes and not args.no_floor
    cases = ["small"] if args.quick else ["small", "preset", "paper"]
    if args.cases:
        cases = args.cases.split(",")
    unknown = [c for c in cases if c not in CASES]
    if unknown:
        sys.exit("--cases: unknown %s (choose from %s)" % (",".join(unknown), ", ".join(CASES)))

    threads = [int(t) for t in args.threads.split(",")]
    # With more than one thread, how far apart the CPUs are says what the threads' numbers mean.
    with_latency = max(threads) > 1 and len(os.sched_getaffinity(0)) > 1
    targets = ["wiggle"] + (["wiggle_floor"] if with_floor else []) + (["wiggle_core_latency"] if with_latency else [])
    if not args.no_build:
        build(args.build_dir, targets)
    wiggle, floor = (os.path.join(args.build_dir, t) for t in ("wiggle", "wiggle_floor"))
    for t in targets:
        if not os.access(os.path.join(args.build_dir, t), os.X_OK):
            sys.exit("no %s in %s" % (t, args.build_dir))
    binaries = {}
    if "lammps" in codes:
        ensure_lammps()
        binaries["lammps"] = shutil.which("lmp")
    if "lammps-opt" in codes:
        binaries["lammps-opt"] = args.lammps_opt or optimised_lammps()
        if not os.access(binaries["lammps-opt"], os.X_OK):
            sys.exit("--lammps-opt: %s is not an executable" % binaries["lammps-opt"])
    model, cpus = machine()
    host = socket.gethostname()
    env = dict(os.environ)
    if args.cache:
        env["WIGGLE_CACHE"] = args.cache
    steps_of = {"small": args.steps_small, "preset": args.steps_preset, "paper": args.steps_paper, "tiny": CASES["tiny"][1]}
    log("machine: %s, %d logical CPUs" % (model, cpus))
    if with_latency:  # one line per pair of CPUs: the placement every multi-thread number below had
        r = run([os.path.join(args.build_dir, "wiggle_core_latency"), "--rounds", "100000"])
        log("  " + r.stdout.strip().replace("\n", "\n  "))
    for code, binary in binaries.items():
        log("%s: %s, LAMMPS %s" % (code, binary, lammps_version(binary)))
    versions = {lammps_version(b) for b in binaries.values()}
    if len(versions) > 1:
        sys.exit("the two LAMMPS builds are of different versions: %s" % ", ".join(sorted(versions)))

    rows, floors, checks, all_same, estimates = [], {}, [], True, {}
    for case in cases:
        steps = steps_of[case]
        case_sets = COMMON + CASES[case][0] + ["run.duration=%r" % (steps * 1e-4)]
        case_dir = os.path.join(args.work_dir, case)
        deck_dir = os.path.join(case_dir, "deck")
        os.makedirs(case_dir, exist_ok=True)  # export-lammps makes only the last component of --out
        log("[%s] bed + export-lammps (the bed is made once and cached; that can take long) ..." % case)
        t0 = datetime.datetime.now()
        # stderr passes through: making the paper bed takes long, and its progress lines say how far it is.
        r = run([wiggle, "export-lammps"] + sets(case_sets) + ["--out", deck_dir], env=env, show_stderr=True)
        log("  " + r.stdout.strip().replace("\n", "\n  ") +
            "  (%.0f s)" % (datetime.datetime.now() - t0).total_seconds())
        atoms = data_file_atoms(deck_dir)
        if "wiggle" in codes:   # before this case's own runs enter the speed log
            estimates[case] = estimated_ns(wiggle, case_sets, os.path.join(case_dir, "check"), env)
        for rnd in range(1, args.rounds + 1):
            for t in threads:
                # Interleave the codes at the same thread count, rotating which goes first each round.
                shift = (rnd - 1) % len(codes)
                for code in codes[shift:] + codes[:shift]:
                    load = os.getloadavg()[0]
                    work = os.path.join(case_dir, "%s-%d" % (code, t))
                    if code in ("wiggle", "wiggle-bound"):
                        res = run_wiggle(wiggle, case_sets, work, t, env, bound=code == "wiggle-bound")
                    else:
                        res = run_lammps(binaries[code], deck_dir, work, t, openmp=(code == "lammps-opt"))
                    row = dict(case=case, code=code, threads=t, round=rnd, load=load, **res)
                    row["ns"] = 1e9 * row["wall"] / (atoms * row["steps"])
                    rows.append(row)
                    log("  round %d %-12s %d thr: %.3f s for %d steps, %.1f ns/particle-step, peak RSS %.0f MB "
                        "(load before %.2f)" % (rnd, code, t, row["wall"], row["steps"], row["ns"], row["rss"], load))
        for r in rows:
            if r["case"] == case:
                r["atoms"] = r["atoms"] or atoms
        line, ok = check_same_physics(rows, case, atoms, steps, args.physics_tol)
        if line:
            checks.append(line)
            all_same = all_same and ok
        if with_floor:
            load = os.getloadavg()[0]
            fl = run_floor(floor, case_sets, os.path.join(case_dir, "floor.json"), env)
            if fl["particles"] != atoms:
                sys.exit("wiggle_floor counted %d particles, the data file has %d" % (fl["particles"], atoms))
            floors[case] = fl
            # One row per sweep over all pairs: loop_s is one sweep, steps 1, so ns_per_particle_step reads as for the others.
            rows.append(dict(case=case, code="floor", threads=1, round=1, steps=1, wall=fl["floor_sweep_s"],
                             atoms=atoms, rss=float("nan"), load=load, ns=1e9 * fl["floor_sweep_s"] / atoms))
            log("  floor: %.2f ns per particle-step (%.2f ns per pair, %d pairs, %d touching; %d lanes, the engine's %d)" %
                (rows[-1]["ns"], fl["floor_ns_per_pair"], fl["pairs"], fl["touching"], fl["floor_lanes"],
                 fl["step_lanes"]))

    log("\nns per particle-step (median of %d rounds; min-max), particles = all LAMMPS atoms; "
        "'x wiggle' = this code's time / wiggle's at the same thread count" % args.rounds)
    log("threads: " + "; ".join("%s = %s" % (c, WHAT_THREADS_ARE[c]) for c in codes))
    log("%-6s %7s %4s %-12s | %-20s | %-8s | %-8s" % ("case", "atoms", "thr", "code", "ns/particle-step",
                                                       "x wiggle", "peak RSS"))
    for case in cases:
        for t in threads:
            runs = {c: [r for r in rows if r["case"] == case and r["threads"] == t and r["code"] == c] for c in codes}
            wm = median([r["ns"] for r in runs["wiggle"]]) if "wiggle" in codes else None
            for code in codes:
                ns = [r["ns"] for r in runs[code]]
                m = median(ns)
                log("%-6s %7d %4d %-12s | %6.1f (%5.1f-%5.1f) | %8s | %5.0f MB" %
                    (case, runs[code][0]["atoms"], t, code, m, min(ns), max(ns),
                     "%.2f" % (m / wm) if wm else "-", max(r["rss"] for r in runs[code])))
        if case in floors:
            fl = floors[case]
            floor_ns = 1e9 * fl["floor_sweep_s"] / fl["particles"]
            one = [r["ns"] for r in rows if r["case"] == case and r["code"] == "wiggle" and r["threads"] == 1]
            ratio = "wiggle 1-thread step / floor: %.2f" % (median(one) / floor_ns) if one else "(no 1-thread wiggle run)"
            log("%-6s %7d %4d %-12s | %6.1f ns (%.2f ns per pair) | %s (wiggle_floor's own step: %.1f ns, %.2f)" %
                (case, fl["particles"], 1, "floor", floor_ns, fl["floor_ns_per_pair"], ratio,
                 fl["step_ns_per_particle_step"], fl["step_over_floor"]))
    for case, est in estimates.items():
        one = median([r["ns"] for r in rows if r["case"] == case and r["code"] == "wiggle" and r["threads"] == 1] or [float("nan")])
        log("%-6s `run --check` plans %.1f ns per particle-step, measured %.1f (1 thread): %.2f x, %s (tolerance %d %%)" %
            (case, est, one, est / one, "within" if abs(est / one - 1) <= ESTIMATE_TOL else "OUTSIDE", ESTIMATE_TOL * 100))
    for line in checks:
        log(line)

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
                        r["steps"], "%.6g" % r["wall"], "%.2f" % r["ns"], "%.1f" % r["rss"], "%.2f" % r["load"]])
    log("appended %d rows to %s" % (len(rows), path))
    if args.write_costs:
        sys.path.insert(0, os.path.join(REPO, "tools", "docs"))
        import costs  # noqa: E402  (the one cost table and the documents' cost blocks)
        flags = open("/proc/cpuinfo").read() if os.path.exists("/proc/cpuinfo") else ""
        simd = "AVX-512" if " avx512f" in flags else "AVX2" if " avx2" in flags else "no AVX2"
        costs.from_bench(path, stamp, args.machine or "%s, %d logical CPUs, %s" % (model, cpus, simd))
        for line in costs.run(check=False):
            log(line)
    if not all_same:
        sys.exit("the optimised LAMMPS does not reproduce Debian's on the deck (see above)")


if __name__ == "__main__":
    main()
