#!/usr/bin/python3
"""The one measured cost table, bench/costs.csv, and the cost figures the documents take from it.

    tools/docs/costs.py            rewrite every cost block (README.md, docs/*.md, configs/*.toml) from the table
    tools/docs/costs.py --check    change nothing; exit 1 naming each block line that differs, and each
                                    figure of ns per particle-step outside a block that is more than 25 %
                                    from the table's figure for its bed and thread count
    tools/docs/costs.py --from-bench CSV --stamp TIMESTAMP --machine TEXT
                                    rewrite bench/costs.csv from one run of bench/run_bench.py (its rows
                                    of that timestamp in CSV), then the blocks (bench/run_bench.py
                                    --write-costs does this after its run)

The table holds, per bed (the three presets' beds) and thread count, the median ns per particle-step
of the run phase of each code the bench script runs (wiggle, Debian's LAMMPS, the optimised LAMMPS,
the floor), on one named machine, with the run it comes from. `wiggle run --check` and `sweep
--dry-run` estimate from its wiggle one-thread rows before this machine has recorded runs of its own
(src/scenario/cost/CostModel.h: the build embeds the table). A cost block sits between `<!-- costs: NAME
-->` and `<!-- /costs: NAME -->` (Markdown) or `# costs: NAME` and `# /costs: NAME` (TOML); BLOCKS
below says what each holds.
"""
import csv
import os
import re
import statistics
import sys
import textwrap

ROOT = os.path.dirname(os.path.dirname(os.path.dirname(os.path.abspath(__file__))))
sys.path.insert(0, os.path.dirname(os.path.abspath(__file__)))
import marked  # noqa: E402

TABLE = "bench/costs.csv"
COLUMNS = ["bed", "particles", "threads", "code", "ns_per_particle_step", "min", "max", "rounds", "machine", "source"]
# The bench script's cases are the presets' beds (bench/run_bench.py CASES)
BED_OF_CASE = {"small": "small", "preset": "paper_depth", "paper": "paper"}
BEDS = ["small", "paper_depth", "paper"]
BED_NAMES = {"small": "small preset (60 x 50 d)", "paper_depth": "paper-depth preset (60 x 195 d)",
             "paper": "paper bed (300 x 195 d)"}
CODES = ["wiggle", "lammps", "lammps-opt", "floor"]
TOLERANCE = 0.25
DT = 1e-4   # every preset's run.dt
# Documents whose cost figures are checked (a glob's worth, listed so that a new document is a decision)
SCANNED_DIRS = [("", ".md"), ("docs", ".md"), ("configs", ".toml"), ("configs/sweeps", ".toml")]


def load(root=ROOT):
    with open(os.path.join(root, TABLE), newline="") as f:
        rows = list(csv.DictReader(f))
    for r in rows:
        for k in ("particles", "threads", "rounds"):
            r[k] = int(r[k])
        for k in ("ns_per_particle_step", "min", "max"):
            r[k] = float(r[k])
    return rows


def row(rows, bed, threads=1, code="wiggle"):
    for r in rows:
        if (r["bed"], r["threads"], r["code"]) == (bed, threads, code):
            return r
    raise KeyError(f"{TABLE} has no row for {code} on the {bed} bed at {threads} thread(s)")


def ns(rows, bed, threads=1, code="wiggle"):
    return row(rows, bed, threads, code)["ns_per_particle_step"]


def run_seconds(rows, bed, duration, threads=1):
    """A run's wall time at the table's figure: particles x steps x ns."""
    r = row(rows, bed, threads)
    return 1e-9 * r["ns_per_particle_step"] * r["particles"] * round(duration / DT)


def duration_text(seconds):
    """'70 s', '4.7 min', '58 min', '6.6 h'."""
    if seconds < 100:
        return f"{seconds:.0f} s"
    if seconds < 600:
        return f"{seconds / 60:.1f} min"
    if seconds < 6000:
        return f"{seconds / 60:.0f} min"
    return f"{seconds / 3600:.1f} h"


def machine(rows):
    names = sorted({r["machine"] for r in rows})
    if len(names) != 1:
        raise ValueError(f"{TABLE}: one machine expected, found {names}")
    return names[0]


def source(rows):
    return sorted({r["source"] for r in rows})[0]


# ---- the blocks

def readme_speed(rows):
    """The README's paragraph "How fast is it?"."""
    def both(bed, t):
        return f"{duration_text(run_seconds(rows, bed, t))} ({duration_text(run_seconds(rows, bed, t, 2))} on two)"
    text = (f"On one core of an {machine(rows).split(',')[0]} a run costs {ns(rows, 'small'):.0f}-{ns(rows, 'paper'):.0f} "
            f"ns per particle-step, more on bigger beds: the default case (t = 100) {both('small', 100)}, the paper-depth "
            f"preset {both('paper_depth', 100)}, by the paper's clock (t = 1000) {both('paper_depth', 1000)}, the paper's "
            f"own box at t = 1000 {both('paper', 1000)}: "
            f"{ns(rows, 'paper', code='lammps-opt') / ns(rows, 'paper'):.1f}-"
            f"{ns(rows, 'paper_depth', code='lammps-opt') / ns(rows, 'paper_depth'):.1f} x faster than LAMMPS built "
            "`-O3 -march=native` on the same beds. `wiggle run CONFIG --check` estimates a case before it runs; "
            "every figure: [docs/PERFORMANCE.md](docs/PERFORMANCE.md).")
    return textwrap.wrap(text, 104, break_on_hyphens=False, break_long_words=False)


def perf_table(rows):
    """docs/PERFORMANCE.md's table: every code on every bed at each thread count."""
    head = ["bed", "particles", "threads", "wiggle", "Debian `lmp` (MPI ranks)", "LAMMPS -O3 -march=native (OpenMP)",
            "floor (the law alone)", "wiggle / floor"]
    lines = ["| " + " | ".join(head) + " |", "|" + "---|" * len(head)]

    def cell(r, base=None):
        text = f"{r['ns_per_particle_step']:.1f} ({r['min']:.1f}-{r['max']:.1f})"
        return text + (f": {r['ns_per_particle_step'] / base:.2f} x" if base else "")
    for bed in BEDS:
        for t in (1, 2):
            w = row(rows, bed, t)
            others = [cell(row(rows, bed, t, c), w["ns_per_particle_step"]) for c in ("lammps", "lammps-opt")]
            if t == 1:
                f = row(rows, bed, 1, "floor")
                tail = [f"{f['ns_per_particle_step']:.1f}", f"{w['ns_per_particle_step'] / f['ns_per_particle_step']:.2f}"]
            else:
                tail = ["", ""]
            lines.append("| " + " | ".join([BED_NAMES[bed], f"{w['particles']:,}", str(t), "**" + cell(w) + "**"]
                                           + others + tail) + " |")
    lines += ["", f"(ns per particle-step of the run phase, median of {row(rows, 'small')['rounds']} rounds (min-max); "
              f"`x` = that code's time over wiggle's; machine: {machine(rows)}; {source(rows)}; made by "
              "`tools/docs/costs.py` from `bench/costs.csv`)"]
    return lines


def study_costs(rows):
    """docs/PERFORMANCE.md: what a case of each preset costs, one and two threads."""
    head = ["case", "particles", "steps", "one core", "two cores"]
    lines = ["| " + " | ".join(head) + " |", "|" + "---|" * len(head)]
    for bed, config, t in [("small", "configs/small.toml", 100), ("paper_depth", "configs/paper_depth.toml", 100),
                           ("paper_depth", "configs/paper_depth.toml", 1000), ("paper", "configs/paper.toml", 1000)]:
        r = row(rows, bed)
        lines.append(f"| `{config}`, t = {t:g} | {r['particles']:,} | {round(t / DT):.0e} | "
                     f"{duration_text(run_seconds(rows, bed, t))} | {duration_text(run_seconds(rows, bed, t, 2))} |"
                     .replace("e+0", "e"))
    lines += ["", "(particles x steps x the table's ns per particle-step; the bed comes on top the first time, "
              "`wiggle run CONFIG --check` estimates it)"]
    return lines


def config_comment(bed, duration):
    """A preset's cost comment."""
    def lines(rows):
        return [f"# Cost (bench/costs.csv, {machine(rows).split(',')[0]}): {ns(rows, bed):.1f} ns per particle-step on one core, "
                f"{ns(rows, bed, 2):.1f} on two:",
                f"# a run to t = {duration:g} is {duration_text(run_seconds(rows, bed, duration))} on one core, "
                f"{duration_text(run_seconds(rows, bed, duration, 2))} on two; `wiggle run CONFIG --check` says more."]
    return lines


BLOCKS = {
    "readme_speed": ("README.md", readme_speed),
    "perf_table": ("docs/PERFORMANCE.md", perf_table),
    "study_costs": ("docs/PERFORMANCE.md", study_costs),
    "paper_toml": ("configs/paper.toml", config_comment("paper", 1000)),
    "paper_depth_toml": ("configs/paper_depth.toml", config_comment("paper_depth", 100)),
    "small_toml": ("configs/small.toml", config_comment("small", 100)),
}


# ---- figures outside the blocks

FIGURE = re.compile(r"(\d+(?:\.\d+)?)(?:\s*(?:-|to)\s*(\d+(?:\.\d+)?))?\s*ns(?: per particle-step|/particle-step)")
BED_WORDS = [("paper", re.compile(r"paper bed|paper's (own )?box|300 x 195|62,[0-9]{3}|paper\.toml|paper_box")),
             ("paper_depth", re.compile(r"paper-depth|paper_depth|paper's depth|12,[0-9]{3}|preset's box")),
             ("small", re.compile(r"small|3,[0-9]{3} (grains|particles)|default case"))]
TWO = re.compile(r"\b(two|both|2) (threads|cores|quiet cores)\b|\bon (two|both)\b|\b2 threads\b")
ONE = re.compile(r"\b(one|1|a single) (quiet )?(thread|core)\b")


def scanned_files(root, dirs=None):
    """The documents under the folders of dirs (SCANNED_DIRS: the program's) whose figures are checked."""
    for folder, ext in dirs or SCANNED_DIRS:
        base = os.path.join(root, folder)
        for name in sorted(os.listdir(base)):
            if name.endswith(ext) and os.path.isfile(os.path.join(base, name)):
                yield os.path.join(folder, name) if folder else name


def bed_of_file(path):
    name = os.path.basename(path)
    for bed, pattern in [("paper_depth", "paper_depth"), ("paper", "paper"), ("small", "small")]:
        if pattern in name:
            return bed
    return None


def figure_problems(rows, where, lines):
    """Each figure of ns per particle-step in these (number, line) pairs that is more than TOLERANCE
    from every table figure its line allows: the bed the line names (else the file's, else any),
    at the thread count it names near the figure (else either)."""
    problems = []
    for number, line in lines:
        beds = [bed for bed, pattern in BED_WORDS if pattern.search(line)] or \
            ([bed_of_file(where)] if bed_of_file(where) else BEDS)
        for m in FIGURE.finditer(line):
            near = line[max(0, m.start() - 60):m.end() + 30]
            threads = ([2] if TWO.search(near) else []) + ([1] if ONE.search(near) else []) or [1, 2]
            allowed = [ns(rows, b, t) for b in beds for t in threads]
            for text in filter(None, m.groups()):
                value = float(text)
                if not any(abs(value / a - 1) <= TOLERANCE for a in allowed):
                    problems.append(f"{where}:{number}: {value:g} ns per particle-step is more than "
                                    f"{TOLERANCE:.0%} from {TABLE}'s " + ", ".join(f"{a:g}" for a in allowed)
                                    + f" ({', '.join(beds)}; {' or '.join(map(str, threads))} thread(s)): '{m.group(0)}'")
    return problems


def check_figures(root=ROOT, rows=None, dirs=None):
    """The figure problems of the documents under dirs (default SCANNED_DIRS); study/tests/costs.py
    checks the study's folders with it."""
    rows = rows or load(root)
    problems = []
    for doc in scanned_files(root, dirs):
        with open(os.path.join(root, doc), encoding="utf-8") as f:
            text = f.read()
        problems += figure_problems(rows, doc, marked.outside_blocks(text, "costs", doc))
    return problems


def run(check, root=ROOT):
    rows = load(root)
    blocks, documents = {}, []
    for name, (doc, make) in BLOCKS.items():
        blocks[name] = make(rows)
        if doc not in documents:
            documents.append(doc)
    return marked.rewrite(root, documents, blocks, "costs", check) + (check_figures(root, rows) if check else [])


# ---- the table from a bench run

def from_bench(csv_path, stamp, machine_text, root=ROOT):
    """bench/costs.csv from the rows of one bench run (its timestamp) in a bench results CSV: per
    bed, code and thread count, the median over the rounds, with the min and max."""
    with open(csv_path, newline="") as f:
        runs = [r for r in csv.DictReader(f) if r["timestamp"] == stamp and r["case"] in BED_OF_CASE
                and r["code"] in CODES]
    if not runs:
        raise ValueError(f"{csv_path}: no rows of the bench run {stamp}")
    out = []
    for case, bed in BED_OF_CASE.items():
        for code in CODES:
            for t in (1, 2):
                values = [float(r["ns_per_particle_step"]) for r in runs
                          if (r["case"], r["code"], int(r["threads"])) == (case, code, t)]
                if not values:
                    continue
                atoms = {int(r["atoms"]) for r in runs if r["case"] == case}
                out.append({"bed": bed, "particles": max(atoms), "threads": t, "code": code,
                            "ns_per_particle_step": f"{statistics.median(values):.1f}",
                            "min": f"{min(values):.1f}", "max": f"{max(values):.1f}", "rounds": len(values),
                            "machine": machine_text,
                            "source": f"{os.path.relpath(csv_path, root)}, the run of {stamp}"})
    missing = [(bed, t) for bed in BEDS for t in (1, 2) if not any(
        (r["bed"], r["threads"], r["code"]) == (bed, t, "wiggle") for r in out)]
    if missing:
        raise ValueError(f"{csv_path}: the run of {stamp} has no wiggle rows for {missing}: the table needs every "
                         "bed at 1 and 2 threads (bench/run_bench.sh with its default cases and threads)")
    path = os.path.join(root, TABLE)
    with open(path + ".tmp", "w", newline="") as f:
        w = csv.DictWriter(f, COLUMNS, lineterminator="\n")
        w.writeheader()
        w.writerows(out)
    os.replace(path + ".tmp", path)
    print(f"costs: {TABLE} rewritten from {csv_path} ({len(out)} rows)")


def main():
    args = sys.argv[1:]
    try:
        if args[:1] == ["--from-bench"] and len(args) == 6 and args[2] == "--stamp" and args[4] == "--machine":
            from_bench(args[1], args[3], args[5])
            problems = run(check=False)
        elif args in ([], ["--check"]):
            problems = run(check=args == ["--check"])
        else:
            print("usage: tools/docs/costs.py [--check | --from-bench CSV --stamp TIMESTAMP --machine TEXT]",
                  file=sys.stderr)
            sys.exit(2)
    except (OSError, KeyError, ValueError) as e:
        print(f"costs: {e}", file=sys.stderr)
        sys.exit(2)
    for p in problems:
        print(p)
    if args == ["--check"]:
        print(f"costs: {len(problems)} problems")
    sys.exit(1 if problems else 0)


if __name__ == "__main__":
    main()
