"""wiggleplot: figures for wiggle's run and sweep directories.

Python draws, C++ computes: this package only reads the files that `wiggle run`, `wiggle sweep`
and `wiggle model` write (docs/OUTPUT-FORMATS.md) and never re-derives physics. Modules:

- readers:   file readers (one function per file format), numpy arrays out
- cells:     a sweep's cells (a case without its seed): mean, se and verdict over the beds (cells.csv)
- prepare:   the arrays behind each figure (aggregation over seeds, T_rising, field grids, masks)
- style:     one matplotlib style for every figure and the saver (PNG + PDF)
- runplots:  figures of one run directory (paper figs 2, 3-4, 8, 9-11, movie)
- sweepplots: figures of a sweep directory (paper figs 2, 5, 6, 8, 14, Table 1)
- geomplots: the intruder geometry figure (paper fig 13)
- htmlreport: a sweep's self-contained HTML page (`wiggle report DIR`)
- cli:       `python3 -m wiggleplot DIR` / `--geometry a.json ... --out DIR` / `DIR --html FILE --status S.json`
- data:      runs and sweeps as pandas DataFrames, and `run()`, a thin driver of `wiggle run`

For analysis (pandas from Debian: python3-pandas):

    import wiggleplot as wp
    sweep = wp.load_sweep("fig5")             # results.csv as a DataFrame
    cells = wp.load_cells("fig5")             # cells.csv (or results.csv grouped by cell)
    run = wp.load_case("fig5", "shape=disk_period=5")   # or wp.load_run(DIR), wp.load_run(case)
    run.trajectory.plot(x="t", y="y")
    wp.plot_sweep("fig5", "fig5/figures")     # the paper's figures of a sweep
"""

import os

from wiggleplot.data import RunData, WiggleError, find_wiggle, load_case, load_cells, load_run, load_sweep, run  # noqa: F401

__version__ = "0.1.0"


def plot_sweep(sweep_dir, out_dir, formats=("png",)):
    """Draws a sweep's figures (figs 5, 6, 14, Table 1, ...) into out_dir; returns the files written."""
    from wiggleplot import sweepplots
    from wiggleplot.report import Report
    report = Report(quiet=True)
    os.makedirs(out_dir, exist_ok=True)
    sweepplots.plot_sweep(sweep_dir, out_dir, list(formats), report)
    return list(report.written)


def plot_run(run, out_dir, formats=("png",), frames=None):
    """Draws a run's figures (figs 2, 3-4, 8, 9-11) into out_dir; returns the files written. `run`:
    a run directory, or a live case of the engine module (wiggle.Case, docs/PYTHON.md), whose
    snapshots are the case.frame() dicts in `frames` (default: its current step)."""
    from wiggleplot import runplots
    from wiggleplot.report import Report
    report = Report(quiet=True)
    os.makedirs(out_dir, exist_ok=True)
    runplots.plot_run(run, out_dir, list(formats), report, frames=frames)
    return list(report.written)
