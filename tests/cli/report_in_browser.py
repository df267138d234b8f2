#!/usr/bin/python3
"""`wiggle report` end to end, in a real browser (ctest report_in_browser, label browser):

    tests/cli/report_in_browser.py WIGGLE_BINARY [--keep DIR] [--screenshot FILE] [--source DIR --build DIR]

1. a tiny sweep (a 20 x 12 bed, 3 periods x 2 amplitudes, t = 0.4 each; A = 7 fails the geometry
   check at once, so the page shows failed cases and their errors), its own bed cache;
2. `wiggle report DIR`: DIR/report.html holds every case name, the failures' errors and one
   base64 PNG per figure that `wiggle plot` draws (made by the report, as DIR/figures was empty);
3. headless Chromium opens the page and takes a 1200 x 1600 screenshot: it must be a PNG of that
   size and not blank (its pixels vary; more than 2 % are not white);
4. bad input: a directory that is not a sweep, an output in a missing directory and an output that
   is a directory each give one line and exit status 2 and write nothing; a report that fails
   while rendering leaves the old page as it was and no temporary file;
5. with --source and --build, beds as replicates by the docs' own commands (docs/SWEEPS.md, "Beds
   as replicates": the ```sh block that runs configs/sweeps/beds_tiny.toml), run as written at the
   root of a fresh copy of the tree (its tracked files, build/release linked to BUILD): cells.csv has
   one row per cell with its two beds, its mean, standard error and verdict, and agrees with the
   Python side's grouping of results.csv (wiggleplot.cells, the same rule); `wiggle status` lists the
   cells; the figure of V_y against T has its error bars (2 standard errors); the report shows each
   cell's mean +- se, beds and verdict, and Chromium draws it.
About 30 s of CPU. Exit status 0 when every check passes.
"""
import argparse
import base64
import csv
import math
import os
import re
import shutil
import subprocess
import sys
import tempfile

HERE = os.path.dirname(os.path.abspath(__file__))

SWEEP = """\
[sweep]
name = "report_check"
[base.box]
width = 20.0
bed_height = 12.0
seed = 1
[base.intruder]
shape = "polygon"
vertices = [[-1.5, -1.5], [1.5, -1.5], [1.5, 1.5], [-1.5, 1.5]]
y0 = 6.0
[base.bed]
rest_energy = 1e-4
max_time = 100.0
cache_dir = "{cache}"
[base.run]
dt = 0.0001
duration = 0.4
sample_interval = 0.01
dump_interval = 0.0
plot = false
[base.fields]
enabled = false
[grid.drive]
amplitude = [0.5, 7.0]
period = [0.25, 0.5, 1.0]
"""
SIZE = (1200, 1600)
PNG_SIGNATURE = b"\x89PNG\r\n\x1a\n"

failures = []


def check(condition, what):
    print(("ok:     " if condition else "FAILED: ") + what)
    if not condition:
        failures.append(what)
    return condition


def run(command, **kwargs):
    return subprocess.run(command, capture_output=True, text=True, timeout=600, **kwargs)


def screenshot(page, png, work):
    chromium = shutil.which("chromium") or shutil.which("chromium-browser")
    if chromium is None:
        check(False, "chromium is installed (tools/bootstrap.sh installs it)")
        return False
    profile = tempfile.mkdtemp(prefix="chromium-profile-", dir=work)
    r = run([chromium, "--headless", "--no-sandbox", "--disable-gpu", "--hide-scrollbars",
             f"--user-data-dir={profile}", f"--screenshot={png}", f"--window-size={SIZE[0]},{SIZE[1]}",
             "file://" + os.path.abspath(page)])
    taken = r.returncode == 0 and os.path.isfile(png)
    return check(taken, "chromium took a screenshot" + ("" if taken else f" (exit {r.returncode}: {r.stderr.strip()[-500:]})"))


def check_screenshot(png):
    from matplotlib import image
    with open(png, "rb") as f:
        check(f.read(8) == PNG_SIGNATURE, "the screenshot is a PNG")
    pixels = image.imread(png)  # rows x columns x channels, floats in [0, 1]
    check(pixels.shape[1] == SIZE[0] and pixels.shape[0] == SIZE[1],
          f"the screenshot is {SIZE[0]} x {SIZE[1]} (got {pixels.shape[1]} x {pixels.shape[0]})")
    grey = pixels[..., :3].mean(axis=2)
    inked = float((grey < 0.9).mean())
    check(float(grey.std()) > 0.05 and inked > 0.02,
          f"the screenshot is not blank (std {grey.std():.3f}, {100 * inked:.1f} % not white)")


def one_line_exit_2(result, what, naming):
    lines = result.stderr.strip().splitlines()
    check(result.returncode == 2 and len(lines) == 1 and naming in lines[0],
          f"{what}: exit 2 with one line naming {naming!r} (exit {result.returncode}: {result.stderr.strip()!r})")


BEDS_SWEEP = "configs/sweeps/beds_tiny.toml"


def documented_beds_block(tree):
    """The ```sh block of docs/SWEEPS.md that runs the beds example."""
    with open(os.path.join(tree, "docs", "SWEEPS.md"), encoding="utf-8") as f:
        text = f.read()
    blocks = re.findall(r"```sh\n(.*?)```", text, re.S)
    return next((b for b in blocks if BEDS_SWEEP in b), None)


def beds_route(source, build, work):
    """Step 5: the documented beds example in a fresh copy of the tree."""
    sys.path.insert(0, os.path.join(HERE, "..", "docs"))
    sys.path.insert(0, os.path.join(HERE, "..", "..", "python"))
    from python_routes import fresh_copy
    from wiggleplot import cells, readers, sweepplots
    from wiggleplot.report import Report

    tree, home = os.path.join(work, "clone"), os.path.join(work, "home")
    os.makedirs(home)
    fresh_copy(source, tree)
    os.makedirs(os.path.join(tree, "build"), exist_ok=True)
    os.symlink(build, os.path.join(tree, "build", "release"))
    block = documented_beds_block(tree)
    if not check(block is not None, f"docs/SWEEPS.md has a ```sh block running {BEDS_SWEEP}"):
        return
    done = subprocess.run(["/bin/sh", "-ec", block], cwd=tree, capture_output=True, text=True, timeout=900,
                          env={"PATH": "/usr/bin:/bin", "HOME": home, "OMP_NUM_THREADS": "1", "MPLBACKEND": "Agg"})
    check(done.returncode == 0, f"the documented block ran (exit {done.returncode}: {done.stderr.strip()[-800:]})")
    out = re.search(r"--out (\S+)", block.split(BEDS_SWEEP, 1)[1]).group(1)
    sweep_dir = os.path.join(tree, out)
    check("2 cells x 2 beds" in done.stdout, "the dry run counts the cells and their beds")
    path = os.path.join(sweep_dir, "cells.csv")
    if not check(os.path.isfile(path), f"the sweep wrote {path}"):
        return
    written = readers.read_table(path)
    grouped = cells.group_results(readers.read_results(sweep_dir))
    check(list(written["cell"]) == ["period=0.25", "period=0.5"], f"one row per cell ({list(written['cell'])})")
    check(list(written["beds"]) == [2, 2] and list(written["n"]) == [2, 2], "each cell has its two beds run")
    check(all(v in cells.VERDICTS for v in written["verdict"]), f"each cell has a verdict ({list(written['verdict'])})")
    check(set(written["verdict_rule"]) == {cells.RULE}, "the file states the rule")
    agree = list(written) == list(grouped) and all(
        (written[c] == grouped[c]).all() if written[c].dtype == object else
        all(math.isclose(a, b, rel_tol=1e-8, abs_tol=1e-9) or (math.isnan(a) and math.isnan(b))
            for a, b in zip(written[c], grouped[c]))
        for c in written)
    check(agree, "cells.csv (C++) and wiggleplot.cells' grouping of results.csv (Python) agree")
    check("cell     period=0.25: " in done.stdout and "cell     period=0.5: " in done.stdout,
          "wiggle status lists the cells")
    check(os.path.isfile(os.path.join(sweep_dir, "figures", "rate_vs_period.png")), "wiggle plot drew V_y against T")
    sweep = sweepplots.Sweep(sweep_dir, Report(quiet=True))
    curve = next(iter(next(iter(sweepplots.curves_by(sweep, sweep.rows, "drive.amplitude").values())).values()))
    check(list(curve[3]) == [2, 2] and (curve[4] > 0).all(), "the figure's points have their error bars (n = 2, se > 0)")
    page = os.path.join(sweep_dir, "report.html")
    with open(page, encoding="utf-8") as f:
        text = f.read()
    check("<h2>Cells</h2>" in text, "the report has the cells")
    for i in range(2):
        shown = f"{written['vy_mean'][i]:+.4g} +- {written['vy_se'][i]:.2g}"
        check(shown in text, f"the report shows cell {written['cell'][i]}'s mean +- se ({shown})")
    check(text.count('<td class="verdict">') == 2 and all(
        f'<td class="verdict">{v}</td>' in text for v in written["verdict"]), "the report shows each cell's verdict")
    png = os.path.join(work, "beds-report.png")
    if screenshot(page, png, work):
        check_screenshot(png)


def main():
    p = argparse.ArgumentParser()
    p.add_argument("wiggle")
    p.add_argument("--keep", help="work in this directory and keep it")
    p.add_argument("--screenshot", help="also copy the screenshot here")
    p.add_argument("--source", help="the source tree: run the documented beds example in a fresh copy of it")
    p.add_argument("--build", help="the build directory the copy's build/release links to (with --source)")
    args = p.parse_args()
    work = args.keep or tempfile.mkdtemp(prefix="wiggle-report-test-")
    os.makedirs(work, exist_ok=True)
    env = dict(os.environ, OMP_NUM_THREADS="1", MPLBACKEND="Agg")
    try:
        sweep_file = os.path.join(work, "report_check.toml")
        with open(sweep_file, "w") as f:
            f.write(SWEEP.format(cache=os.path.join(work, "cache")))
        sweep_dir = os.path.join(work, "sweep")
        r = run([args.wiggle, "sweep", sweep_file, "--out", sweep_dir, "--jobs", "2", "--threads", "1"], env=env)
        check(r.returncode in (0, 1) and os.path.isfile(os.path.join(sweep_dir, "results.csv")),
              f"the sweep ran (exit {r.returncode}: 1 means some cases failed, as planned)")
        with open(os.path.join(sweep_dir, "results.csv")) as f:
            rows = list(csv.DictReader(f))
        statuses = sorted(row["status"] for row in rows)
        check(statuses == ["failed"] * 3 + ["ok"] * 3, f"3 cases ok, 3 failed ({statuses})")

        r = run([args.wiggle, "report", sweep_dir], env=env)
        page = os.path.join(sweep_dir, "report.html")
        check(r.returncode == 0 and os.path.isfile(page), f"wiggle report wrote {page} ({r.stderr.strip()})")
        with open(page, encoding="utf-8") as f:
            text = f.read()
        for row in rows:
            check(row["case"] in text, f"the page names case {row['case']}")
        errors = {row["error"] for row in rows if row["status"] == "failed"}
        check(all(e and e.replace("'", "&#x27;").replace('"', "&quot;") in text for e in errors),
              "the page shows the failed cases' errors")
        check("report_check" in text and "3 done" in text and "3 failed" in text,
              "the page names the sweep and counts its cases")
        drawn = sorted(n for n in os.listdir(os.path.join(sweep_dir, "figures")) if n.endswith(".png"))
        uris = text.split('src="data:image/png;base64,')[1:]
        check(len(drawn) >= 3 and len(uris) == len(drawn),
              f"one embedded PNG per figure drawn ({len(uris)} embedded, drawn: {drawn})")
        check(all(base64.b64decode(u[:u.index('"')]).startswith(PNG_SIGNATURE) for u in uris),
              "every embedded figure decodes to a PNG")
        check(not any(".tmp." in n for n in os.listdir(sweep_dir)), "no temporary file left beside the page")

        png = os.path.join(work, "report.png")
        if screenshot(page, png, work):
            check_screenshot(png)
            if args.screenshot:
                shutil.copyfile(png, args.screenshot)

        # Bad input: one line, exit 2, nothing written.
        one_line_exit_2(run([args.wiggle, "report", os.path.join(work, "cache")], env=env),
                        "a directory that is not a sweep", "not a sweep directory")
        missing = os.path.join(work, "nowhere", "r.html")
        one_line_exit_2(run([args.wiggle, "report", sweep_dir, "--out", missing], env=env),
                        "an output in a missing directory", os.path.join(work, "nowhere"))
        check(not os.path.exists(os.path.dirname(missing)), "the missing directory was not made")
        one_line_exit_2(run([args.wiggle, "report", sweep_dir, "--out", work], env=env),
                        "an output that is a directory", "is a directory")
        # A report that fails while rendering (a status it cannot read) keeps the old page.
        before = text
        status = os.path.join(work, "bad-status.json")
        with open(status, "w") as f:
            f.write("{ not json")
        package = os.path.join(os.path.dirname(os.path.abspath(__file__)), "..", "..", "python")
        r = run(["/usr/bin/python3", "-m", "wiggleplot", sweep_dir, "--html", page, "--status", status],
                env=dict(env, PYTHONPATH=package))
        one_line_exit_2(r, "an unreadable status", "wiggleplot:")
        with open(page, encoding="utf-8") as f:
            check(f.read() == before, "the old page is kept whole when a report fails")
        check(not any(".tmp." in n for n in os.listdir(sweep_dir)), "no temporary file left after the failure")

        if args.source and args.build:
            beds_route(os.path.abspath(args.source), os.path.abspath(args.build), os.path.join(work, "beds"))
    finally:
        if not args.keep:
            shutil.rmtree(work, ignore_errors=True)
    print(f"{len(failures)} check(s) failed" if failures else "all checks passed")
    return 1 if failures else 0


if __name__ == "__main__":
    sys.exit(main())
