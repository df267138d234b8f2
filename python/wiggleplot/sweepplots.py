"""Figures of a sweep directory (results.csv): V_y against T per amplitude (paper fig. 5) and per
friction (fig. 6), the V_y colour map over A and T (fig. 14), Table 1 (observed T_rising beside
the cavity model's), and, from the cases' run directories, y(t) per T (fig. 2) and the
phase-resolved rate per T (fig. 8). The beds (seeds) of one point, a cell, are averaged; error
bars are +-2 standard errors of the mean over them, the cells' verdict rule (wiggleplot.cells): a bar
clear of zero rises or sinks. A point of one bed has no bar and is drawn open: its sign is one bed's,
not a verdict."""
import collections
import csv
import os
import textwrap

import numpy as np
from matplotlib.colors import TwoSlopeNorm

from wiggleplot import boundaryplots, cells, prepare, readers, style
from wiggleplot.prepare import AMPLITUDE, MU, PERIOD
from wiggleplot.style import plt


class Sweep:
    def __init__(self, sweep_dir, report):
        self.dir = sweep_dir
        self.report = report
        self.results = readers.read_results(sweep_dir)
        r = self.results
        self.rows = prepare.usable_rows(r)
        n = len(r["case"])
        bad = n - int(self.rows.sum())
        if bad:
            failed = [str(r["case"][i]) for i in range(n) if not self.rows[i]]
            shown = ", ".join(failed[:6]) + (" ..." if len(failed) > 6 else "")
            report.note(f"{bad} of {n} cases have no rate (failed or unfinished) and are left out: {shown}")
        for column in (PERIOD, AMPLITUDE):
            if column not in r:
                raise readers.FormatError(f"{sweep_dir}/results.csv: missing column '{column}'")
        self.panel = prepare.panel_labels(r)
        self.panels = [p for p in dict.fromkeys(self.panel[self.rows].tolist())]
        self._models = {}

    def main_mu_rows(self):
        """Rows at the friction most cases use (all rows when contact.mu is absent or fixed)."""
        mus = prepare.varying(self.results, MU, self.rows)
        if len(mus) < 2:
            return self.rows.copy(), None
        values = np.asarray(self.results[MU])
        counts = collections.Counter(values[self.rows].tolist())
        mu = max(mus, key=lambda m: (counts[m], -m))
        return self.rows & (values == mu), mu

    def run_dir(self, i):
        return os.path.join(self.dir, str(self.results["run_dir"][i]))

    def model(self, panel):
        """model.json of a case of this panel (the largest amplitude's first), or None."""
        if panel not in self._models:
            self._models[panel] = None
            # Largest amplitude first: the model's curve may depend on A (no rise below A_min).
            idx = np.flatnonzero(self.panel == panel)
            amps = np.nan_to_num(np.asarray(self.results[AMPLITUDE], dtype=float)[idx], nan=-1.0)
            for i in idx[np.argsort(-amps, kind="stable")]:
                try:
                    m = readers.read_model(self.run_dir(i))
                except (OSError, ValueError):
                    m = None
                if m is not None:
                    self._models[panel] = m
                    break
        return self._models[panel]


def _panel_grid(n, width=style.FULL_WIDTH, height=2.2):
    ncols = min(n, 3)
    nrows = -(-n // ncols)
    width = min(width, 2.6 * ncols + 0.4)
    fig, axes = plt.subplots(nrows, ncols, figsize=(width, height * nrows + 0.3), squeeze=False)
    for ax in axes.flat[n:]:
        ax.set_visible(False)
    return fig, axes.flat[:n]


def _colour_per_line(panels, cmap="viridis"):
    """One colour per line key (an amplitude, a period) over every panel, in ascending order."""
    keys = sorted({k for lines in panels.values() for k in lines})
    return dict(zip(keys, style.series_colours(len(keys), cmap)))


def _legend_above(fig, items, most_columns):
    """One legend above the panels from (handle, label) pairs: each label once, as first drawn."""
    handles, labels = [], []
    for h, lab in items:
        if lab not in labels:
            handles.append(h)
            labels.append(lab)
    fig.legend(handles, labels, loc="lower center", ncol=min(len(labels), most_columns), bbox_to_anchor=(0.5, 1.0))


def _axes_legend_items(axes):
    """The (handle, label) pairs the axes drew, panel by panel."""
    return [item for ax in axes for item in zip(*ax.get_legend_handles_labels())]


def _mark_t_rise(ax, model):
    """The cavity model's T_rise (where the paper's model lets rising start, its use in Table 1) as a
    dashed line on a V_y-vs-T panel, where it falls within the panel's periods; the model's own V_y(T)
    is not drawn: its magnitude is the model's, many times a simulated rate, and on these axes
    (or a second one scaled to fit) it would read as an agreement or a disagreement it is not
    (`wiggle model --periods` prints it). Call it once the panel's limits are set; returns the
    line (for the legend) or None."""
    if model is None:
        return None
    rises = sorted({model[k] for k in ("T_rise", "T_rise_left", "T_rise_right") if isinstance(model.get(k), (int, float))})
    x_lo, x_hi = ax.get_xlim()
    line = None
    for t_rise in rises:
        if x_lo <= t_rise <= x_hi:
            line = ax.axvline(t_rise, color=style.MODEL_COLOUR, ls="--", lw=0.9,
                              label="cavity model's $T_{rise}$ (paper section 3.5)")
    return line


def _limit_to_data(ax, xs, ys):
    """Keep the axes on the simulation data (a model curve may reach far beyond it)."""
    xs, ys = np.concatenate(xs), np.concatenate(ys)
    if xs.size:
        pad = 0.04 * (xs.max() - xs.min() or 1.0)
        ax.set_xlim(min(0.0, xs.min()) - pad, xs.max() + pad)
        lo, hi = ys.min(), ys.max()
        pad = 0.12 * (hi - lo or 1.0)
        ax.set_ylim(min(lo, 0.0) - pad, max(hi, 0.0) + pad)


def curves_by(sweep, rows, line_key):
    """{panel: {line value: (T, mean, std, n, se)}} over the given rows, seeds averaged."""
    out = {}
    for panel in sweep.panels:
        sel = rows & (sweep.panel == panel)
        records = prepare.aggregate(sweep.results, [line_key, PERIOD], sel)
        by_line = collections.defaultdict(list)
        for rec in records:
            by_line[rec[line_key]].append(rec)
        if by_line:
            out[panel] = {k: prepare.series(v, PERIOD) for k, v in sorted(by_line.items())}
    return out


def _plot_rate_curves(sweep, curves, line_key, line_label, name, title_extra, formats, out_dir):
    fig, axes = _panel_grid(len(curves))
    colours = _colour_per_line(curves)
    legend = []
    for ax, (panel, lines) in zip(axes, curves.items()):
        xs, ys = [], []
        for value, (T, vy, std, n, se) in lines.items():
            bar = np.where(n >= cells.MIN_BEDS, cells.RESOLVED_SE * se, 0.0)
            ax.errorbar(T, vy, yerr=bar, marker="o", ms=3.5, capsize=2, lw=1.1,
                        color=colours[value], label=f"{line_label} = {style.fmt_value(value)}")
            one = n < cells.MIN_BEDS
            if one.any():  # one bed: no standard error, so no verdict; an open marker says so
                ax.plot(T[one], vy[one], "o", ms=3.5, mfc="white", mec=colours[value], mew=1.0, zorder=3,
                        label="open: one bed (its sign is not a verdict)")
            if (~one).any():
                ax.plot([], [], " ", label=r"bars: $\pm$2 standard errors over the beds (clear of 0: rises / sinks)")
            xs.append(T)
            ys.extend([vy - bar, vy + bar])
        _limit_to_data(ax, xs, ys)
        ax.axhline(0.0, color="0.4", lw=0.6)
        ax.set_title(panel + title_extra)
        ax.set_xlabel(style.PERIOD_LABEL)
        ax.set_ylabel(style.VY_LABEL)
        legend += _axes_legend_items([ax])
        model = _mark_t_rise(ax, sweep.model(panel))
        if model is not None and model.get_label() not in [label for _, label in legend]:
            legend.append((model, model.get_label()))
    _legend_above(fig, legend, most_columns=6)
    fig.tight_layout()
    sweep.report.wrote(style.save(fig, out_dir, name, formats))


def plot_rate_vs_period(sweep, out_dir, formats):
    """Paper fig. 5: V_y against T, one line per amplitude, one panel per shape."""
    rows, mu = sweep.main_mu_rows()
    curves = curves_by(sweep, rows, AMPLITUDE)
    if not curves:
        sweep.report.note("no usable cases: V_y(T) figure skipped")
        return
    extra = "" if mu is None else rf" ($\mu$ = {mu:g})"
    _plot_rate_curves(sweep, curves, AMPLITUDE, r"$A$", "rate_vs_period", extra, formats, out_dir)


def mu_rows(sweep):
    """Rows for fig. 6: the amplitude at which most friction values were run (ties: larger A);
    None when contact.mu does not vary."""
    if len(prepare.varying(sweep.results, MU, sweep.rows)) < 2:
        return None, None
    r = sweep.results
    amps = prepare.varying(r, AMPLITUDE, sweep.rows)
    amp_values = np.asarray(r[AMPLITUDE])

    def n_mu(a):
        return len(prepare.varying(r, MU, sweep.rows & (amp_values == a)))

    a = max(amps, key=lambda a: (n_mu(a), a))
    return sweep.rows & (amp_values == a), a


def plot_rate_vs_period_mu(sweep, out_dir, formats):
    """Paper fig. 6: V_y against T, one line per friction coefficient."""
    rows, amplitude = mu_rows(sweep)
    if rows is None:
        sweep.report.note("contact.mu does not vary: V_y(T) per mu figure skipped")
        return
    curves = curves_by(sweep, rows, MU)
    _plot_rate_curves(sweep, curves, MU, r"$\mu$", "rate_vs_period_mu",
                      rf" ($A$ = {amplitude:g})", formats, out_dir)


def rate_map(sweep, panel, rows):
    """(amplitudes, periods, masked mean V_y (nA, nT), n) of one panel for fig. 14."""
    sel = rows & (sweep.panel == panel)
    records = prepare.aggregate(sweep.results, [AMPLITUDE, PERIOD], sel)
    amps = sorted({r[AMPLITUDE] for r in records})
    periods = sorted({r[PERIOD] for r in records})
    grid = np.full((len(amps), len(periods)), np.nan)
    counts = np.zeros_like(grid, dtype=int)
    for rec in records:
        i, j = amps.index(rec[AMPLITUDE]), periods.index(rec[PERIOD])
        grid[i, j] = rec["vy"]
        counts[i, j] = rec["n"]
    return np.array(amps), np.array(periods), np.ma.masked_invalid(grid), counts


def plot_rate_map(sweep, out_dir, formats):
    """Paper fig. 14: V_y over (T, A) per shape, diverging colours centred at zero, one shared scale.
    Cells are the sweep's points (T and A are not evenly spaced), labelled by their values."""
    rows, mu = sweep.main_mu_rows()
    maps = {p: rate_map(sweep, p, rows) for p in sweep.panels}
    maps = {p: m for p, m in maps.items() if m[2].count()}
    if not maps:
        sweep.report.note("no usable cases: V_y colour map skipped")
        return
    vmax = max(float(np.abs(m[2]).max()) for m in maps.values()) or 1.0
    norm = TwoSlopeNorm(vcenter=0.0, vmin=-vmax, vmax=vmax)
    cmap = plt.get_cmap("RdBu_r").copy()
    cmap.set_bad("0.85")
    fig, axes = _panel_grid(len(maps), height=2.3)
    beds = np.concatenate([m[3][~np.ma.getmaskarray(m[2])].ravel() for m in maps.values()])
    mixed = bool((beds < cells.MIN_BEDS).any() and (beds >= cells.MIN_BEDS).any())  # star the one-bed cells
    image = None
    for ax, (panel, (amps, periods, grid, counts)) in zip(axes, maps.items()):
        image = ax.pcolormesh(np.arange(len(periods) + 1), np.arange(len(amps) + 1), grid,
                              cmap=cmap, norm=norm, edgecolors="white", linewidth=0.5)
        if grid.size <= 120:
            for i in range(len(amps)):
                for j in range(len(periods)):
                    if not np.ma.is_masked(grid[i, j]):
                        v = float(grid[i, j])
                        star = "*" if mixed and counts[i, j] < cells.MIN_BEDS else ""
                        ax.text(j + 0.5, i + 0.5, f"{v:.2g}{star}", ha="center", va="center", fontsize=5.5,
                                color="white" if abs(v) > 0.6 * vmax else "black")
        ax.set_xticks(np.arange(len(periods)) + 0.5)
        ax.set_xticklabels([f"{p:g}" for p in periods], fontsize=7)
        ax.set_yticks(np.arange(len(amps)) + 0.5)
        ax.set_yticklabels([f"{a:g}" for a in amps], fontsize=7)
        ax.grid(False)
        ax.set_xlabel(style.PERIOD_LABEL)
        ax.set_ylabel(style.AMPLITUDE_LABEL)
        ax.set_title(panel + ("" if mu is None else rf" ($\mu$ = {mu:g})"))
    if beds.size and (beds < cells.MIN_BEDS).all():
        fig.suptitle("one bed a cell: each colour is one bed's V_y, its sign not a verdict", fontsize=7, y=0.01,
                     va="bottom")
    elif mixed:
        fig.suptitle("mean V_y over each cell's beds; a cell of one bed (*) is one bed's, its sign not a verdict",
                     fontsize=7, y=0.01, va="bottom")
    fig.tight_layout()
    bar = fig.colorbar(image, ax=list(axes), shrink=0.9, pad=0.02)
    bar.set_label(style.VY_LABEL)
    sweep.report.wrote(style.save(fig, out_dir, "rate_map", formats))


def table1(sweep):
    """Rows of Table 1: per shape, the observed T_rising at the largest amplitude (seed-averaged
    V_y against T, zero crossing interpolated) beside the cavity model's l and T_rise."""
    rows, mu = sweep.main_mu_rows()
    amp_values = np.asarray(sweep.results[AMPLITUDE])
    out = []
    for panel in sweep.panels:
        sel = rows & (sweep.panel == panel)
        if not sel.any():
            continue
        a_max = max(prepare.varying(sweep.results, AMPLITUDE, sel))
        records = prepare.aggregate(sweep.results, [PERIOD], sel & (amp_values == a_max))
        T, vy, _, n, _ = prepare.series(records, PERIOD)
        t_obs, t_lo, t_hi, note = prepare.t_rising(T, vy)
        single = [f"{t:g}" for t, k in zip(T, n) if k < cells.MIN_BEDS and t in (t_lo, t_hi)]
        if single:  # the bracket rests on single beds' signs
            note = "; ".join(filter(None, [note, f"one bed at T = {', '.join(single)}: a sign, not a verdict"]))
        model = sweep.model(panel) or {}
        out.append({
            "shape": panel, "A": a_max, "mu": "" if mu is None else mu,
            "l": _model_number(model, "l"),
            "T_rise_model": _model_number(model, "T_rise"),
            "T_rising_observed": t_obs, "T_below": t_lo, "T_above": t_hi, "note": note,
        })
    return out


def _model_number(model, key):
    if key in model:
        return float(model[key])
    sides = [model[k] for k in (f"{key}_left", f"{key}_right") if k in model]
    return "/".join(f"{float(v):.4g}" for v in sides) if sides else float("nan")


TABLE1_COLUMNS = ["shape", "A", "mu", "l", "T_rise_model", "T_rising_observed", "T_below",
                  "T_above", "note"]


def _cell(v):
    if isinstance(v, float):
        return "" if np.isnan(v) else f"{v:.4g}"
    return str(v)


def _bracket(lo, hi):
    """'2 - 4' between the periods that bracket the crossing, '> 8' / '< 1' when open."""
    if np.isfinite(lo) and np.isfinite(hi):
        return f"{lo:g} - {hi:g}"
    if np.isfinite(lo):
        return f"> {lo:g}"
    if np.isfinite(hi):
        return f"< {hi:g}"
    return "-"


def write_table1(sweep, out_dir, formats):
    rows = table1(sweep)
    if not rows:
        sweep.report.note("no usable cases: Table 1 skipped")
        return
    os.makedirs(out_dir, exist_ok=True)
    path = os.path.join(out_dir, "table1.csv")
    with open(path, "w", newline="") as f:
        w = csv.writer(f)
        w.writerow(TABLE1_COLUMNS)
        for r in rows:
            w.writerow([_cell(r[c]) for c in TABLE1_COLUMNS])
    sweep.report.wrote([path])
    sweep.report.wrote(style.save(table1_figure(rows), out_dir, "table1", formats))


def table1_figure(rows):
    """Table 1 drawn as a figure (rows as table1 gives them)."""
    header = ["shape", "l [d]", r"$T_{rise}$ model", r"$T_{rising}$ observed", "bracket", "note"]
    same_a = len({r["A"] for r in rows}) == 1
    cells = [[r["shape"] if same_a else f"{r['shape']} ($A$ = {r['A']:g})", _cell(r["l"]) or "-", _cell(r["T_rise_model"]) or "-",
              _cell(r["T_rising_observed"]) or "-",
              _bracket(r["T_below"], r["T_above"]), r["note"]] for r in rows]
    # Every text on one line (fit_table sizes the columns to them and shrinks the font when the
    # table would be wider than the page); only a note too long for any page wraps.
    cells = [[textwrap.fill(c, 60) for c in row] for row in cells]
    lines = max(1, max(c.count("\n") + 1 for row in cells for c in row))
    fig, ax = plt.subplots(figsize=(style.FULL_WIDTH, 0.6 + 0.22 * (len(rows) * lines + 1)))
    ax.axis("off")
    table = ax.table(cellText=cells, colLabels=header, loc="center", cellLoc="center")
    table.auto_set_font_size(False)
    table.set_fontsize(8)
    fit_table(fig, table)
    where = rf" ($A$ = {rows[0]['A']:g} $d$)" if same_a else ""
    ax.set_title(rf"Table 1: $T_{{rising}}$ at the largest amplitude{where}; "
                 r"times in $\sqrt{d/g}$", fontsize=9)
    return fig


def fit_table(fig, table, pad_px=6):
    """Sizes a matplotlib table's columns and rows to their texts (widest text of each column, the
    lines of the tallest text of each row, plus padding), so that no text runs over a neighbour:
    matplotlib's own layout gives every column the same width whatever it holds."""
    renderer = fig.canvas.get_renderer()
    cells = table.get_celld()
    to_axes = table.axes.transAxes.inverted()

    def size(cell):  # the text's extent in axes fractions
        box = cell.get_text().get_window_extent(renderer)
        (x0, y0), (x1, y1) = to_axes.transform([(box.x0, box.y0), (box.x1 + pad_px, box.y1 + pad_px)])
        return x1 - x0, y1 - y0

    extents = {key: size(cell) for key, cell in cells.items()}
    columns = {c for _, c in cells}
    rows = {r for r, _ in cells}
    widths = {c: max(extents[(r, c)][0] for r in rows if (r, c) in cells) for c in columns}
    heights = {r: max(extents[(r, c)][1] for c in columns if (r, c) in cells) for r in rows}
    scale = min(1.0, 1.0 / sum(widths.values()))  # wider than the axes: shrink the font instead
    if scale < 1.0:
        table.set_fontsize(8 * scale)
    for (r, c), cell in cells.items():
        cell.set_width(widths[c] * scale)
        cell.set_height(heights[r] * scale)


def _reference_amplitude(sweep, rows):
    """The amplitude with the most periods run (ties: the larger), for the per-T figures."""
    amps = prepare.varying(sweep.results, AMPLITUDE, rows)
    values = np.asarray(sweep.results[AMPLITUDE])
    return max(amps, key=lambda a: (len(prepare.varying(sweep.results, PERIOD, rows & (values == a))), a))


def _per_period_cases(sweep, panel, rows, amplitude):
    """{T: [row indices]} of one panel at one amplitude."""
    r = sweep.results
    sel = rows & (sweep.panel == panel) & (np.asarray(r[AMPLITUDE]) == amplitude)
    out = collections.defaultdict(list)
    for i in np.flatnonzero(sel):
        out[float(r[PERIOD][i])].append(i)
    return dict(sorted(out.items()))


def _lines_per_panel(sweep, rows, amplitude, line_of_cases):
    """{panel: {T: line}} at one amplitude: line_of_cases(row indices of one panel's period) gives
    the period's line, or None to leave it out; a panel with no line is left out."""
    panels = {}
    for panel in sweep.panels:
        lines = {}
        for T, idx in _per_period_cases(sweep, panel, rows, amplitude).items():
            line = line_of_cases(idx)
            if line is not None:
                lines[T] = line
        if lines:
            panels[panel] = lines
    return panels


def plot_sweep_trajectories(sweep, out_dir, formats):
    """Paper fig. 2: y(t) - y(0) per period at one amplitude, one panel per shape (the first seed
    of each point is drawn: trajectories of different beds are not averaged), with a square at
    t_settled where the intruder settled (the paper's t_f rule)."""
    rows, _ = sweep.main_mu_rows()
    if not rows.any():
        return
    amplitude = _reference_amplitude(sweep, rows)

    def first_readable_trajectory(idx):
        for i in idx:
            try:
                trajectory = readers.read_trajectory(sweep.run_dir(i))
                summary = readers.read_summary(sweep.run_dir(i))
                return prepare.displacement(trajectory) + (prepare.settled_point(summary, trajectory),)
            except (OSError, readers.FormatError, ValueError):
                continue
        return None

    panels = _lines_per_panel(sweep, rows, amplitude, first_readable_trajectory)
    if not panels:
        sweep.report.note("no trajectory.csv in the run directories: y(t) per T skipped")
        return
    fig, axes = _panel_grid(len(panels))
    colours = _colour_per_line(panels, "plasma")
    for ax, (panel, lines) in zip(axes, panels.items()):
        for T, (t, dy, settled) in lines.items():
            ax.plot(t, dy, color=colours[T], lw=0.9, label=f"$T$ = {T:g}")
            if settled is not None:
                ax.plot(*settled, "s", color=colours[T], ms=4, mec="k", mew=0.5)
        ax.set_title(rf"{panel} ($A$ = {amplitude:g})")
        ax.set_xlabel(style.T_LABEL)
        ax.set_ylabel(style.DY_LABEL)
    _legend_above(fig, _axes_legend_items(axes), most_columns=8)
    fig.tight_layout()
    sweep.report.wrote(style.save(fig, out_dir, "trajectories", formats))


def pooled_phase_rates(dirs):
    """Mean v_y per phase bin over several runs, each bin weighted by its sample count.
    Returns (centers, vy) or None when no run has phase_rates.csv."""
    total, weight, centers = None, None, None
    for d in dirs:
        try:
            rates = readers.read_phase_rates(d)
        except (OSError, readers.FormatError):
            continue
        order = np.argsort(rates["bin"])
        n = np.nan_to_num(np.asarray(rates["samples"], dtype=float)[order])
        v = np.nan_to_num(np.asarray(rates["vy_mean"], dtype=float)[order])
        if total is None:
            centers, total, weight = np.asarray(rates["phase_center"])[order], v * n, n.copy()
        elif len(n) == len(total):
            total += v * n
            weight += n
    if total is None:
        return None
    with np.errstate(invalid="ignore", divide="ignore"):
        return centers, np.where(weight > 0, total / weight, np.nan)


def plot_sweep_phase_rates(sweep, out_dir, formats):
    """Paper fig. 8: mean v_y per phase bin per period at one amplitude, one panel per shape
    (seeds pooled, weighted by samples)."""
    rows, _ = sweep.main_mu_rows()
    if not rows.any():
        return
    amplitude = _reference_amplitude(sweep, rows)
    panels = _lines_per_panel(sweep, rows, amplitude,
                              lambda idx: pooled_phase_rates([sweep.run_dir(i) for i in idx]))
    if not panels:
        sweep.report.note("no phase_rates.csv in the run directories: phase-rate figure skipped")
        return
    fig, axes = _panel_grid(len(panels))
    colours = _colour_per_line(panels, "plasma")
    for ax, (panel, lines) in zip(axes, panels.items()):
        for T, (c, v) in lines.items():
            ax.plot(c, v, "-o", ms=2.5, color=colours[T], lw=0.9, label=f"$T$ = {T:g}")
        ax.axhline(0.0, color="0.4", lw=0.6)
        style.phase_axis(ax)
        ax.set_title(rf"{panel} ($A$ = {amplitude:g})", pad=14)
        ax.set_ylabel(r"mean $v_y$ [$\sqrt{g d}$]")
    _legend_above(fig, _axes_legend_items(axes), most_columns=8)
    fig.tight_layout()
    sweep.report.wrote(style.save(fig, out_dir, "phase_rates", formats))


# The figures plot_sweep may write (file name without extension, what it shows), in its order;
# which of them appear depends on what varies in the sweep (docs/OUTPUT-FORMATS.md).
SWEEP_FIGURES = (
    ("rate_vs_period", "V_y against T per amplitude (paper fig. 5)"),
    ("rate_vs_period_mu", "V_y against T per friction (paper fig. 6)"),
    ("rate_map", "V_y over (T, A) (paper fig. 14)"),
    ("table1", "T_rising observed and predicted (paper Table 1)"),
    ("trajectories", "y(t) - y(0) per T (paper fig. 2)"),
    ("phase_rates", "mean v_y per phase bin per T (paper fig. 8)"),
)


def plot_sweep(sweep_dir, out_dir, formats, report):
    style.apply()
    boundaryplots.plot_boundary(sweep_dir, out_dir, formats, report)  # a `wiggle boundary` directory
    sweep = Sweep(sweep_dir, report)
    if not sweep.panels:
        report.note("results.csv has no usable case: nothing to draw")
        return sweep
    plot_rate_vs_period(sweep, out_dir, formats)
    plot_rate_vs_period_mu(sweep, out_dir, formats)
    plot_rate_map(sweep, out_dir, formats)
    write_table1(sweep, out_dir, formats)
    plot_sweep_trajectories(sweep, out_dir, formats)
    plot_sweep_phase_rates(sweep, out_dir, formats)
    return sweep
