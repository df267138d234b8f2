"""Command line: `python3 -m wiggleplot DIR [--format png,pdf] [--movie] [--times t1,t2,...]
[--out OUT]` draws a run or sweep directory (detected from its files) into DIR/figures (or OUT);
`python3 -m wiggleplot --geometry a.json b.json ... --out OUT` draws intruder geometries;
`python3 -m wiggleplot DIR --html FILE --status STATUS.json` writes a sweep's HTML page (what
`wiggle report` runs, with the status it computed: wiggleplot.htmlreport).
Exit status: 0 done, 2 bad input (one line on stderr), 3 matplotlib or numpy missing."""
import argparse
import os
import sys

KNOWN_FORMATS = ("png", "pdf", "svg", "eps")


def directory_kind(path):
    """'sweep' when DIR holds results.csv, 'run' when it holds summary.json or trajectory.csv."""
    if os.path.isfile(os.path.join(path, "results.csv")):
        return "sweep"
    if any(os.path.isfile(os.path.join(path, f)) for f in ("summary.json", "trajectory.csv")):
        return "run"
    return None


def parse_args(argv):
    p = argparse.ArgumentParser(
        prog="wiggleplot",
        description="Figures of a wiggle run or sweep directory, or of intruder geometry files.")
    p.add_argument("dir", nargs="?", help="run directory (summary.json, trajectory.csv, ...) or "
                   "sweep directory (results.csv)")
    p.add_argument("--format", default="png,pdf", help="comma-separated figure formats (default png,pdf)")
    p.add_argument("--out", help="output directory (default DIR/figures)")
    p.add_argument("--movie", action="store_true", help="also write movie.mp4 from the dump frames (ffmpeg)")
    p.add_argument("--times", help="snapshot times, comma-separated, in sqrt(d/g) (default: up to 6 "
                   "frames spread over the run)")
    p.add_argument("--geometry", nargs="+", metavar="FILE.json",
                   help="draw intruder geometries written by `wiggle model --geometry`")
    p.add_argument("--html", metavar="FILE", help="write the sweep's HTML report to FILE (with --status)")
    p.add_argument("--status", metavar="STATUS.json", help="the sweep's status as `wiggle report` hands it over")
    p.add_argument("--quiet", action="store_true", help="do not list the files written")
    return p.parse_args(argv)


def make_out_dir(out, given):
    """Creates the output directory OUT, its last component only (like `wiggle --out`): returns None
    when OUT is a directory now, else the one-line reason. given: OUT came from --out."""
    name = f"--out {out}" if given else out
    path = out.rstrip("/") or out
    if os.path.isdir(path):
        return None
    if os.path.lexists(path):
        return f"{name}: exists and is not a directory"
    parent = os.path.dirname(path) or "."
    if not os.path.isdir(parent):
        if os.path.exists(parent):
            return f"{name}: parent {parent} is not a directory"
        return f"{name}: parent directory {parent} does not exist"
    try:
        os.mkdir(path)
    except OSError as e:
        return f"{name}: cannot create the directory: {e.strerror or e}"
    return None


def fail(message, code=2):
    print(f"wiggleplot: {message}", file=sys.stderr)
    return code


def main(argv=None):
    args = parse_args(sys.argv[1:] if argv is None else argv)
    try:
        import matplotlib  # noqa: F401
        import numpy  # noqa: F401
    except ImportError as e:
        return fail(f"{e.name} is not installed (Debian: apt-get install python3-matplotlib python3-numpy)", 3)
    from wiggleplot import geomplots, readers, runplots, sweepplots
    from wiggleplot.report import Report, os_error_line

    if args.movie and runplots.find_ffmpeg() is None:  # asked for, so its absence is an error
        return fail("--movie needs ffmpeg, which is not installed (Debian: apt-get install ffmpeg)", 3)

    formats = [f.strip().lower() for f in args.format.split(",") if f.strip()]
    bad = [f for f in formats if f not in KNOWN_FORMATS]
    if not formats or bad:
        return fail(f"--format: unknown format '{','.join(bad)}' (use {', '.join(KNOWN_FORMATS)})")
    times = None
    if args.times:
        try:
            times = [float(v) for v in args.times.split(",") if v.strip()]
        except ValueError:
            return fail(f"--times: '{args.times}' is not a comma-separated list of numbers")
    report = Report(quiet=args.quiet)
    try:
        if args.geometry:
            out = args.out or (os.path.join(args.dir, "figures") if args.dir else ".")
            missing = [g for g in args.geometry if not os.path.isfile(g)]
            if missing:
                return fail(f"geometry file not found: {missing[0]}")
            if args.dir and not os.path.isdir(args.dir):
                return fail(f"not a directory: {args.dir}")
            problem = make_out_dir(out, bool(args.out))
            if problem:
                return fail(problem)
            geomplots.plot_geometries(args.geometry, out, formats, report)
            if not args.dir:
                return 0
        if not args.dir:
            return fail("give a run or sweep directory, or --geometry FILE.json ...")
        if not os.path.isdir(args.dir):
            return fail(f"not a directory: {args.dir}")
        kind = directory_kind(args.dir)
        if args.html:
            if kind != "sweep":
                return fail(f"{args.dir}: no results.csv: not a sweep directory")
            if not args.status:
                return fail("--html needs --status STATUS.json (run `wiggle report DIR`)")
            from wiggleplot import htmlreport
            htmlreport.write_report(args.dir, args.html, args.status, report)
            return 0
        out = args.out or os.path.join(args.dir, "figures")
        if kind is not None:
            problem = make_out_dir(out, bool(args.out))
            if problem:
                return fail(problem)
        if kind == "sweep":
            sweepplots.plot_sweep(args.dir, out, formats, report)
            if args.movie:
                report.note("--movie applies to run directories; ignored for a sweep")
        elif kind == "run":
            runplots.plot_run(args.dir, out, formats, report, times=times, movie=args.movie)
        else:
            return fail(f"{args.dir} is neither a run directory (summary.json or trajectory.csv) "
                        "nor a sweep directory (results.csv)")
    except OSError as e:
        return fail(os_error_line(e))
    except (readers.FormatError, ValueError) as e:
        return fail(str(e).splitlines()[0] if str(e) else type(e).__name__)
    if not report.written:
        return fail(f"nothing drawn from {args.dir or 'the geometry files'}", 2)
    return 0
