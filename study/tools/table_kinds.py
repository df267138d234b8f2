"""The kinds of table the documents' blocks are made as: a spec (a dict, declared in the module of
the block) names its kind, its result folders (`sources`), a filter of their cases (`where`), what
makes a row and a column, and the value of a case (`value`: a results.csv column such as "vy", or a
function of the case such as cases.chord(t0, t1) or cases.slope(t0, t1) over its trajectory.csv).
Each kind returns (the table's lines, the sources it names under the table).

    pivot               rows x columns of V_y cells (each the beds of that row and column)
    paired_steps        rows x steps of a key, each cell the change of V_y bed by bed
    amplitude_threshold rows x periods, the smallest amplitude at which V_y leaves the beds' scatter
    listing             one row per case
    windows             one row per cell, one column per window of the run
    shape_by_period     a pivot spec: Table 1 and figure 5, shapes x periods at one amplitude
"""
import json
import os
import sys

import findings
from cases import (ROOT, SHAPES, PhaseProfile, beds, cell_text, chord, head_lines, key_of, mean, paper_observed,
                   row_line, select, value_of)
from findings import RESOLVED

sys.path.insert(0, os.path.join(ROOT, "python"))
from wiggleplot import prepare  # noqa: E402  (t_rising: the paper's reading of a crossing)


def grid_of(spec, col):
    """The finished cases of spec's sources and filter, by spec["row"] and then by col (a key or a function)."""
    grid = {}
    for c in select(spec["sources"], spec.get("where", {})):
        grid.setdefault(key_of(c, spec["row"]), {}).setdefault(key_of(c, col), []).append(c)
    return grid


def pivot(spec):
    """Rows x columns of V_y cells (each the beds of that row and column), with optional columns
    made from a row's cells before and after them (spec["pre"], spec["extra"]:
    [(header, function(row_key, {col: [values]}, {col: [cases]}))])."""
    grid = grid_of(spec, spec["col"])
    rows = spec.get("rows") or sorted(grid, key=spec.get("row_sort", lambda r: r))
    cols = spec.get("cols") or sorted({k for r in grid.values() for k in r})
    row_label = spec.get("row_label", lambda r: f"{r:g}" if isinstance(r, float) else str(r))
    col_label = spec.get("col_label", lambda k: f"{k:g}" if isinstance(k, float) else str(k))
    pre, extra = spec.get("pre", []), spec.get("extra", [])
    head = (spec["row_head"] + [h for h, _ in pre] + [col_label(k) for k in cols] + (["all beds"] if spec.get("all") else [])
            + [h for h, _ in extra])
    lines = head_lines(head)
    for r in rows:
        cells = grid.get(r, {})
        values = {k: [value_of(c, spec.get("value", "vy")) for c in beds(cells[k], f"{spec['name']}: {r} {k}")]
                  for k in cols if k in cells}
        row = list(row_label(r)) if isinstance(row_label(r), tuple) else [row_label(r)]
        row += [fn(r, values, cells) for _, fn in pre]
        row += [cell_text(values.get(k, []), spec.get("digits", 3), spec.get("each", False)) for k in cols]
        if spec.get("all"):
            row.append(cell_text([v for k in cols for v in values.get(k, [])], spec.get("digits", 3), spec.get("each", False)))
        row += [fn(r, values, cells) for _, fn in extra]
        lines.append(row_line(row))
    return lines, spec["sources"]


def paired_steps(spec):
    """Rows x steps of spec["key"] (from one value to the next, then from the first to the last):
    each cell the change of V_y on each bed run at both values (a paired difference: the same bed,
    so the bed's own scatter cancels), their mean +- standard error over the beds that have both.
    Under the table, one bed's standard deviation of a change, pooled over the steps' cells of two
    beds or more, and the changes it resolves (mean at least RESOLVED x that / sqrt(beds) from zero)."""
    grid = grid_of(spec, spec["key"])
    values = spec["values"]
    steps = list(zip(values, values[1:])) + [(values[0], values[-1])]
    head = spec["row_head"] + [f"{spec['label']} {a:g} -> {b:g}" for a, b in steps]
    lines = head_lines(head)
    changes = {}   # (row, step): the beds' changes
    for r in spec["rows"]:
        by_value = {v: {c.get("box.seed"): value_of(c, spec.get("value", "vy")) for c in beds(cs, f"{spec['name']}: {r} {v}")}
                    for v, cs in grid.get(r, {}).items()}
        row = list(spec["row_label"](r))
        for a, b in steps:
            both = sorted(set(by_value.get(a, {})) & set(by_value.get(b, {})))
            changes[r, (a, b)] = [by_value[b][s] - by_value[a][s] for s in both]
            row.append(cell_text(changes[r, (a, b)], each=True))
        lines.append(row_line(row))
    # the last step (first to last value) repeats the others' beds: left out of the pooled scatter
    spread, dof, groups = findings.pooled_sd([d for (r, step), d in changes.items() if step != steps[-1]])
    if spread > 0:   # none when no step has two beds, or (degenerate) every bed changed alike
        def named(r):   # "disk, T = 3": the row's labels after the first, each with its column head
            first, *rest = spec["row_label"](r)
            return first + "".join(f", {h} = {v}" for h, v in zip(spec["row_head"][1:], rest))
        resolved = [f"{named(r)}, {spec['label']} {a:g} -> {b:g} ({mean(d):+.3f}, "
                    f"{findings.change_z(d, spread):+.1f})"
                    for (r, (a, b)), d in changes.items() if findings.change_resolved(d, spread)]
        lines += ["", f"One bed's standard deviation of a change, pooled over the {groups} steps of two beds or "
                  f"more ({dof} degrees of freedom): {spread:.3f}. Changes at least {RESOLVED:g} standard errors from "
                  "zero by it (the mean change, then its standard errors): " + ("; ".join(resolved) or "none") + "."]
    return lines, spec["sources"]


def amplitude_threshold(spec):
    """Rows x periods: the smallest amplitude of spec["amplitudes"] at which V_y leaves the scatter of
    the beds, |mean| >= RESOLVED standard errors from zero (se = sigma / sqrt(beds), sigma one bed's
    standard deviation, spec["sigma"]()), as the bracket from the next smaller amplitude measured, and
    the sign it goes."""
    sig = spec["sigma"]()
    grid = grid_of(spec, lambda c: (c.get("drive.amplitude"), c.get("drive.period")))
    head = spec["row_head"] + [f"T = {t:g}" for t in spec["periods"]]
    lines = head_lines(head)
    for r in spec["rows"]:
        row = [spec["row_label"](r)]
        for t in spec["periods"]:
            measured = [(a, [value_of(c, "vy") for c in beds(grid[r][(a, t)], f"{spec['name']}: {r} {a} {t}")])
                        for a in spec["amplitudes"] if (a, t) in grid.get(r, {})]
            row.append(threshold_text(measured, sig))
        lines.append(row_line(row))
    lines += ["", f"(the amplitudes measured: {', '.join(f'{a:g}' for a in spec['amplitudes'])}; "
              f"resolved: |V_y| >= {RESOLVED:g} sigma / sqrt(beds), sigma = {sig:.3f})"]
    return lines, spec["sources"]


def threshold_text(measured, sig):
    """'0.5-1 (rises)', '<= 0.5 (sinks)', 'above 5', '': where V_y of cells [(A, values)] in ascending
    A first leaves zero by the findings' rule, whichever way it goes, and which way."""
    resolved = findings.first_resolved(measured, sig)
    if not measured:
        return ""
    if not resolved:
        return f"above {measured[-1][0]:g}"
    below, a, sign = resolved
    return (f"{below:g}-{a:g}" if below is not None else f"<= {a:g}") + (" (rises)" if sign > 0 else " (sinks)")


def listing(spec):
    """One row per case: spec["columns"] = [(header, function(case) -> text)]."""
    cases = select(spec["sources"], spec.get("where", {}))
    cases.sort(key=spec.get("sort", lambda c: 0))
    head = [h for h, _ in spec["columns"]]
    lines = head_lines(head)
    lines += [row_line(fn(c) for _, fn in spec["columns"]) for c in cases]
    return lines, spec["sources"]


def windows(spec):
    """One row per cell (spec["row"]), one column per window of the run (spec["windows"]: (t0, t1)):
    each cell the chord V_y over that window, on every bed of the row."""
    grid = {}
    for c in select(spec["sources"], spec.get("where", {})):
        r = key_of(c, spec["row"])
        if r is not None:   # None: a case of the sources that is none of the table's rows
            grid.setdefault(r, []).append(c)
    head = spec["row_head"] + [f"t = {t0:g}-{t1:g}" for t0, t1 in spec["windows"]]
    lines = head_lines(head)
    for r in sorted(grid, key=spec["row_sort"]):
        cases = beds(grid[r], f"{spec['name']}: {r}")
        lines.append(row_line(list(spec["row_label"](r))
                              + [cell_text([chord(t0, t1)(c) for c in cases]) for t0, t1 in spec["windows"]]))
    return lines, spec["sources"]


def means(values):
    return {k: mean(v) for k, v in values.items()}


def paper_crossing(cells):
    """The paper's reading of where V_y turns positive over cells [(T, values)] in ascending T:
    prepare.t_rising over the cells' mean V_y (its T_rising, the last period whose mean <= 0 and the
    next, and its note)."""
    return prepare.t_rising([t for t, _ in cells], [mean(v) for _, v in cells])


def table1_extra():
    """Table 1's columns after the periods: wiggle's T_rising (the paper's reading: the last period
    with mean V_y <= 0 and the next, interpolated), its bracket, the period of the largest mean V_y."""
    def crossing(values):
        return paper_crossing(sorted(values.items()))

    def t_text(shape, values, cases):
        t = crossing(values)[0]
        return f"{t:.2f}" if t == t else "-"

    def bracket(shape, values, cases):
        _, lo, hi, note = crossing(values)
        return f"{lo:g}-{hi:g}" if lo == lo and hi == hi else note

    def largest(shape, values, cases):
        m = means(values)
        return f"{max(m, key=m.get):g}"
    return [("wiggle T_rising", t_text), ("bracket", bracket), ("largest V_y at T", largest)]


def model_cell(key):
    """The cavity model's period `key` (T_rise, T_max) for a row's shape, from its cases' model.json."""
    def cell(shape, values, cases):
        for group in cases.values():
            for c in group:
                path = os.path.join(c.dir, "model.json")
                if os.path.exists(path):
                    with open(path) as f:
                        return f"{json.load(f)[key]:.2f}"
        return ""
    return cell


def shape_by_period(name, sources, where, with_paper, value="vy"):
    """Table 1 and figure 5: shapes x periods at one amplitude, with the cavity model's periods,
    the paper's observed T_rising (Table 1 only) and wiggle's; `value` as in this module's docstring."""
    return {"name": name, "kind": pivot, "sources": sources, "where": where, "value": value,
            "row": "intruder.shape", "col": "drive.period", "rows": None,
            "row_sort": lambda s: (SHAPES.index(s) if s in SHAPES else len(SHAPES), s),
            "row_head": ["shape"],
            "pre": [("model T_rise", model_cell("T_rise")), ("model T_max", model_cell("T_max"))]
            + ([("paper (observed)", lambda s, values, cases: paper_observed(s, printed=True))] if with_paper else []),
            "col_label": lambda t: f"T = {t:g}",
            "extra": table1_extra()}


def fmt(digits):
    return lambda x: f"{x:+.{digits}f}"


def column(key, text=lambda x: f"{x:g}"):
    """A listing's column: the case's key, as text."""
    return lambda c: text(key_of(c, key))


def phase_column(text):
    """A listing's column from a case's PhaseProfile."""
    return lambda c: text(PhaseProfile(c))
