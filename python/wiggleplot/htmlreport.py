"""`wiggle report DIR`: one self-contained HTML page of a sweep directory (status, a table of the
cases, the figures as base64 PNG data URIs), so that it can be opened anywhere or mailed.

The status comes from `wiggle status`'s own computation (sweep/SweepStatus.h), handed over as JSON
by the C++ command (`--status FILE`); the table's numbers and parameters from results.csv
(load_sweep). Figures missing from DIR/figures are drawn first by the same code as `wiggle plot DIR`.
The page is written to a temporary file beside the target and renamed over it: a reader never sees
half a page, and a failure leaves the old page as it was."""
import base64
import datetime
import html
import json
import math
import os
import tempfile

from wiggleplot import cells as cell_rule
from wiggleplot import prepare

STATUS_ORDER = ("ok", "running", "failed", "pending")
STATUS_WORDS = {"ok": "done", "running": "running", "failed": "failed", "pending": "pending"}
# results.csv columns that are not parameters (docs/OUTPUT-FORMATS.md, "Sweep directory").
NOT_PARAMETERS = prepare.NON_PARAMETERS

STYLE = """
body { font-family: sans-serif; margin: 2em; color: #222; max-width: 1150px; }
h1 { margin-bottom: 0.2em; }
.counts span { display: inline-block; padding: 0.2em 0.6em; margin-right: 0.4em; border-radius: 4px; }
table { border-collapse: collapse; font-size: 0.9em; }
th, td { border: 1px solid #ccc; padding: 0.25em 0.6em; text-align: left; }
th { background: #eee; }
td.num { text-align: right; font-variant-numeric: tabular-nums; }
.ok { background: #d8f0d8; } .running { background: #fff2c0; }
.failed { background: #f8d0d0; } .pending { background: #e8e8e8; }
pre { background: #f6f6f6; padding: 0.6em; white-space: pre-wrap; }
figure { margin: 1.5em 0; } figure img { max-width: 100%; border: 1px solid #ddd; }
.note { color: #8a4b00; }
"""


def _number(value, digits=4):
    try:
        v = float(value)
    except (TypeError, ValueError):
        return ""
    return "" if math.isnan(v) else f"{v:.{digits}g}"


def _duration(seconds):
    s = float(seconds)
    if s < 10:
        return f"{s:.2g} s"
    if s < 120:
        return f"{s:.0f} s"
    if s < 7200:
        return f"{s / 60:.0f} min"
    return f"{s / 3600:.1f} h"


def _cell(value):
    if value is None or (isinstance(value, float) and math.isnan(value)):
        return ""
    return f"{value:g}" if isinstance(value, float) else str(value)


def varied_parameters(table):
    """The parameter columns (config keys) of results.csv, split into those that vary over the
    cases and those with one value: ([key, ...], {key: value})."""
    varied, fixed = [], {}
    for column in table.columns:
        if column in NOT_PARAMETERS or "." not in column:
            continue
        values = table[column].dropna().unique()
        if len(values) > 1:
            varied.append(column)
        elif len(values) == 1:
            fixed[column] = values[0]
    return varied, fixed


def sweep_figures(fig_dir):
    """(name, caption, path) of the sweep figures present in fig_dir as PNG, in plot_sweep's order."""
    from wiggleplot.sweepplots import SWEEP_FIGURES
    found = []
    for name, caption in SWEEP_FIGURES:
        path = os.path.join(fig_dir, name + ".png")
        if os.path.isfile(path):
            found.append((name, caption, path))
    return found


def draw_missing_figures(sweep_dir, report):
    """Draws the sweep's figures into DIR/figures as `wiggle plot DIR` does (PNG and PDF) when none
    is there yet; returns a note for the page when they could not be drawn, else None."""
    fig_dir = os.path.join(sweep_dir, "figures")
    if sweep_figures(fig_dir):
        return None
    from wiggleplot import sweepplots
    from wiggleplot.report import os_error_line
    try:
        os.makedirs(fig_dir, exist_ok=True)
        sweepplots.plot_sweep(sweep_dir, fig_dir, ["png", "pdf"], report)
    except OSError as e:
        return f"the figures could not be drawn ({os_error_line(e)})"
    return None


def _data_uri(path):
    with open(path, "rb") as f:
        return "data:image/png;base64," + base64.b64encode(f.read()).decode("ascii")


def cells_section(cells, varied):
    """The cells' table (mean +- se, n of beds, verdict: wiggleplot.cells) when some cell has more
    than one bed; else one sentence saying each case is one bed."""
    e = html.escape
    if cells is None or not len(cells["cell"]):
        return []
    if not cell_rule.replicated(cells):
        return ["<p>Each case is one bed: its V_y's sign is one bed's, not a verdict "
                "(<code>beds = N</code> in <code>[sweep]</code> runs every case on N beds; docs/SWEEPS.md).</p>"]
    shown = [k for k in varied if k in cells and k != cell_rule.SEED]
    out = ["<h2>Cells</h2><p>A cell is a case without its seed: V_y is the mean +- standard error over its beds; "
           f"{e(cell_rule.RULE)}.</p>",
           "<table><tr><th>cell</th>" + "".join(f"<th>{e(k)}</th>" for k in shown)
           + "<th>beds run</th><th>V_y (mean +- se)</th><th>verdict</th></tr>"]
    for i in range(len(cells["cell"])):
        n, beds = int(cells["n"][i]), int(cells["beds"][i])
        state = str(cells["state"][i])
        mean, se = float(cells["vy_mean"][i]), float(cells["vy_se"][i])
        value = "" if n == 0 else f"{mean:+.4g}" + ("" if n < cell_rule.MIN_BEDS else f" +- {se:.2g}")
        verdict = str(cells["verdict"][i]) if n >= cell_rule.MIN_BEDS else ("one bed" if n == 1 else "")
        css = {"done": "ok", "part-run": "running", "not run": "pending"}.get(state, "")
        out.append(f"<tr><td>{e(str(cells['cell'][i]))}</td>"
                   + "".join(f'<td class="num">{e(_cell(cells[k][i]))}</td>' for k in shown)
                   + f'<td class="num {css}">{n} of {beds}' + (f" ({e(state)})" if state != "done" else "") + "</td>"
                   + f'<td class="num">{e(value)}</td><td class="verdict">{e(verdict)}</td></tr>')
    out.append("</table><p>One bed has no standard error: its sign is marked <em>one bed</em>, never a verdict.</p>")
    return out


def render(sweep_dir, status, table, figures, notes, cells=None):
    """The page as a string. status: the JSON of sweep/SweepStatus.h; table: load_sweep(sweep_dir);
    figures: sweep_figures(...); notes: sentences for the reader (figures missing, stale, ...);
    cells: wiggleplot.cells.read_cells(sweep_dir), or None."""
    e = html.escape
    name = status.get("name") or os.path.basename(os.path.normpath(sweep_dir))
    cases = status["cases"]
    counts = {s: sum(c["status"] == s for c in cases) for s in STATUS_ORDER}
    varied, fixed = varied_parameters(table)
    rows_by_case = {str(r["case"]): r for _, r in table.iterrows()}
    has_labels = "case_label" in table.columns and any(  # a [[case]] name other than the case's own
        isinstance(label, str) and label != case for case, label in zip(table["case"], table["case_label"]))

    out = ["<!DOCTYPE html>", '<html lang="en"><head><meta charset="utf-8">',
           f"<title>wiggle sweep {e(name)}</title>", f"<style>{STYLE}</style></head><body>",
           f"<h1>Sweep {e(name)}</h1>",
           f"<p>Directory <code>{e(os.path.abspath(sweep_dir))}</code>; report written "
           f"{e(datetime.datetime.now().strftime('%Y-%m-%d %H:%M'))}.</p>",
           '<p class="counts">' + "".join(
               f'<span class="{s}">{counts[s]} {STATUS_WORDS[s]}</span>' for s in STATUS_ORDER)
           + f" of {len(cases)} cases. "
           + ("A <code>wiggle sweep</code> is running in it." if status["sweep_running"] else
              "No <code>wiggle sweep</code> is running in it.")
           + (f" Time to go: about {e(_duration(status['eta_s']))}." if status.get("eta_s") is not None
              and counts["running"] + counts["pending"] > 0 else "") + "</p>",
           "<details><summary><code>wiggle status</code></summary>"
           f"<pre>{e(status['text'])}</pre></details>"]
    for note in notes:
        out.append(f'<p class="note">{e(note)}</p>')

    out.append("<h2>Cases</h2><table><tr><th>case</th>" + ("<th>label</th>" if has_labels else "")
               + "<th>status</th><th>V_y</th><th>slope</th>"
               + "".join(f"<th>{e(k)}</th>" for k in varied) + "<th>wall time</th><th>error, warnings</th></tr>")
    for c in cases:
        row = rows_by_case.get(c["name"])
        get = (lambda key: row[key] if row is not None and key in row.index else None)
        state = c["status"]
        shown = STATUS_WORDS.get(state, state)
        if state == "running":  # how far it got, and whether no process runs it now
            details = [f"{100 * c['fraction']:.0f} %"] if c.get("fraction") is not None else []
            details += ["interrupted"] if c.get("interrupted") else []
            shown += f" ({'; '.join(details)})" if details else ""
        cell_notes = ([c["error"]] if c.get("error") else []) + [f"warning: {w}" for w in c.get("warnings") or []]
        out.append(
            f"<tr><td>{e(c['name'])}</td>"
            + (f"<td>{e(_cell(get('case_label')))}</td>" if has_labels else "")
            + f'<td class="{e(state)}">{e(shown)}</td>'
            + (f'<td class="num">{_number(get("vy"))}</td><td class="num">{_number(get("vy_slope"))}</td>'
               if state == "ok" else '<td class="num"></td><td class="num"></td>')
            + "".join(f'<td class="num">{e(_cell(get(k)))}</td>' for k in varied)
            + f'<td class="num">{e(_duration(c["wall_s"])) if c.get("wall_s") is not None else ""}</td>'
            + "<td>" + "<br>".join(e(t) for t in cell_notes) + "</td></tr>")
    out.append("</table>")
    if fixed:
        out.append("<p>The same for every case: " + ", ".join(
            f"<code>{e(k)}</code> = {e(_cell(v))}" for k, v in fixed.items()) + ".</p>")
    out.append("<p>V_y and slope in sqrt(g d): the paper's rate (chord) and the least-squares "
               "slope of y(t) over [t_i, t_f] (docs/OUTPUT-FORMATS.md).</p>")
    out.extend(cells_section(cells, varied))

    out.append("<h2>Figures</h2>")
    if not figures:
        out.append(f'<p class="note">No figures in {e(os.path.join(sweep_dir, "figures"))}: '
                   f"<code>wiggle plot {e(sweep_dir)}</code> draws them (it needs finished cases), "
                   f"then <code>wiggle report {e(sweep_dir)}</code> again.</p>")
    for name_, caption, path in figures:
        out.append(f'<figure><img alt="{e(name_)}" src="{_data_uri(path)}">'
                   f"<figcaption>{e(name_)}: {e(caption)}</figcaption></figure>")
    out.append("</body></html>")
    return "\n".join(out) + "\n"


def write_atomically(path, text):
    """Writes text to path through a temporary file in the same directory, flushed and renamed."""
    directory = os.path.dirname(os.path.abspath(path))
    fd, tmp = tempfile.mkstemp(dir=directory, prefix=os.path.basename(path) + ".tmp.")
    try:
        with os.fdopen(fd, "w", encoding="utf-8") as f:
            f.write(text)
            f.flush()
            os.fsync(f.fileno())
        os.chmod(tmp, 0o644)
        os.replace(tmp, path)
    except BaseException:
        try:
            os.unlink(tmp)
        except OSError:
            pass
        raise


def write_report(sweep_dir, out_path, status_path, report):
    """The page of sweep_dir to out_path, drawing missing figures first; returns out_path."""
    from wiggleplot.data import load_sweep
    with open(status_path, encoding="utf-8") as f:
        status = json.load(f)
    notes = []
    problem = draw_missing_figures(sweep_dir, report)
    if problem:
        notes.append(problem + f"; `wiggle plot {sweep_dir}` draws them.")
    fig_dir = os.path.join(sweep_dir, "figures")
    figures = sweep_figures(fig_dir)
    results = os.path.join(sweep_dir, "results.csv")
    if figures and min(os.path.getmtime(p) for _, _, p in figures) < os.path.getmtime(results):
        notes.append(f"The figures are older than results.csv: `wiggle plot {sweep_dir}` redraws them "
                     "with the cases finished since.")
    write_atomically(out_path, render(sweep_dir, status, load_sweep(sweep_dir), figures, notes,
                                      cell_rule.read_cells(sweep_dir)))
    report.wrote([out_path])
    return out_path
