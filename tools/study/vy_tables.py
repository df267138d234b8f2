#!/usr/bin/python3
"""The documents' tables of measured V_y, made from the committed results (results/, and the one
small-preset results.csv under docs/figures/).

    tools/study/vy_tables.py            rewrite every table in place, between its markers
    tools/study/vy_tables.py --check    change nothing; exit 1 naming each table that differs

A table sits in its document between two marker lines,

    <!-- vy_tables: NAME -->
    ...
    <!-- /vy_tables: NAME -->

and is declared in TABLES below: which result folders, which cases (a filter), what makes a row and
a column, which value (default `vy`, the paper's rule). Cases of one cell that differ only in their
bed (box.seed) are beds of that cell: the cell gives the number of beds and, from two beds on, the
mean and the standard error of the mean (the standard deviation over sqrt(n)). The same case in two
folders (same seed and state hash) counts once; two different runs of one cell on the same bed are
an error. Adding a table is a few lines in TABLES and its two markers in the document; for example
Table 1 read over t = 100-1000 from a folder of t = 1000 runs would be

    shape_by_period("depth_table1_t100_1000", ["results/paper_depth/table1_t1000"], {}, True,
                    value=chord(100, 1000)),

(`value`: a results.csv column such as "vy", or a function of the case such as chord(t0, t1) or
slope(t0, t1) over its trajectory.csv).

A case's key is its results.csv column when the sweep varied it, else the value in the case's
config.toml (every key, as the run resolved it).
"""
import csv
import functools
import json
import math
import os
import sys
import textwrap
import tomllib

ROOT = os.path.dirname(os.path.dirname(os.path.dirname(os.path.abspath(__file__))))
sys.path.insert(0, os.path.join(ROOT, "python"))
from wiggleplot import prepare  # noqa: E402  (t_rising: the paper's reading of a crossing)
import marked  # noqa: E402  (the generated blocks in the documents)
from findings import RESOLVED, mean, stats  # noqa: E402  (the findings' statistics)
import findings  # noqa: E402

SHAPES = ["disk", "square", "rect_narrow", "rect_wide", "triangle"]
# The paper's Table 1: docs/paper-table1.json, which `wiggle model` prints from too. Its observed
# T_rising range (A = 5) per shape, (low, high), in the table's order.
with open(os.path.join(ROOT, "docs", "paper-table1.json")) as _f:
    PAPER_RANGE = {row["shape"]: tuple(row["T_rising_observed"]) for row in json.load(_f)["rows"]}


def paper_observed(shape, printed=False):
    """The paper's observed T_rising range of a shape as text: '2.5-3' (printed: as the paper prints
    it, '2.5-3.0'); '' for a shape not in the paper's table."""
    if shape not in PAPER_RANGE:
        return ""
    lo, hi = PAPER_RANGE[shape]
    return f"{lo:.1f}-{hi:.1f}" if printed else f"{lo:g}-{hi:g}"


# Keys added after some of the committed cases were run, with the value every earlier run had.
LATER_KEYS = {"intruder.surface": "smooth", "intruder.mass_rule": "disk_area", "bed.pour": "lattice",
              "bed.cavity": "poured", "bed.relax_damping": 0.0, "drive.form": "displacement",
              "intruder.contact_mass": "body", "intruder.rotation": "locked"}


class Case:
    """One finished case: its results.csv row, and its folder for config.toml, model.json and trajectory.csv."""

    def __init__(self, source, row, case_dir):
        self.source, self.row, self.dir = source, row, case_dir
        self._config = self._trajectory = None

    def get(self, key):
        if self.row.get(key, "") != "":
            value = self.row[key]
            try:
                return float(value)
            except ValueError:
                return value
        if self._config is None:
            path = os.path.join(self.dir, "config.toml") if self.dir else ""
            self._config = {}
            if os.path.exists(path):
                with open(path, "rb") as f:
                    self._config = tomllib.load(f)
        node = self._config
        for part in key.split("."):
            if not isinstance(node, dict) or part not in node:
                if key in LATER_KEYS:
                    return LATER_KEYS[key]
                raise KeyError(f"{self.source}: case {self.row['case']} has no {key}")
            node = node[part]
        return node

    def trajectory(self):
        """(t, y) of trajectory.csv."""
        if self._trajectory is None:
            with open(os.path.join(self.dir, "trajectory.csv"), newline="") as f:
                rows = [(float(r["t"]), float(r["y"])) for r in csv.DictReader(f)]
            self._trajectory = [r[0] for r in rows], [r[1] for r in rows]
        return self._trajectory

    def phase_rates(self):
        """(phase centres as 10 phi / pi, mean v_y) of phase_rates.csv, in bin order."""
        with open(os.path.join(self.dir, "phase_rates.csv"), newline="") as f:
            rows = sorted(csv.DictReader(f), key=lambda r: int(r["bin"]))
        return [float(r["phase_center"]) for r in rows], [float(r["vy_mean"]) for r in rows]


def cases_of(source, finished):
    """The finished cases of a results folder (or of a results.csv file) under ROOT, or the others."""
    path = os.path.join(ROOT, source)
    csv_path = path if path.endswith(".csv") else os.path.join(path, "results.csv")
    with open(csv_path, newline="") as f:
        rows = [r for r in csv.DictReader(f) if (r["status"] == "ok") == finished]
    folder = None if path.endswith(".csv") else path
    return tuple(Case(source, r, os.path.join(folder, r["run_dir"]) if folder else None) for r in rows)


@functools.lru_cache(maxsize=None)
def load(source):
    """The finished cases of a results folder (or of a results.csv file) under ROOT."""
    return cases_of(source, finished=True)


def committed(folders):
    """Those of the results folders whose results.csv is committed so far."""
    return [f for f in folders if os.path.exists(os.path.join(ROOT, f, "results.csv"))]


# ---- values of a case, besides the results.csv columns

def y_at(case, t):
    ts, ys = case.trajectory()
    i = min(range(len(ts)), key=lambda k: abs(ts[k] - t))
    if abs(ts[i] - t) > 1e-6:
        raise ValueError(f"{case.source}: {case.row['case']} has no sample at t = {t:g}")
    return ys[i]


def chord(t0, t1):
    """(y(t1) - y(t0)) / (t1 - t0): the paper's rule over a window (without its plateau clause)."""
    return lambda case: (y_at(case, t1) - y_at(case, t0)) / (t1 - t0)


def slope(t0, t1):
    """The least-squares slope of y(t) over t0 <= t <= t1."""
    def value(case):
        pairs = [(t, y) for t, y in zip(*case.trajectory()) if t0 - 1e-9 <= t <= t1 + 1e-9]
        n = len(pairs)
        mt, my = sum(p[0] for p in pairs) / n, sum(p[1] for p in pairs) / n
        return sum((t - mt) * (y - my) for t, y in pairs) / sum((t - mt) ** 2 for t, _ in pairs)
    return value


class PhaseProfile:
    """A case's mean v_y per phase bin (the paper's figure 8) as its harmonics in the phase phi:
    v(phi) = mean + sum_n |h_n| cos(n phi - arg h_n). The symmetric shapes in a level bed repeat
    their profile half a cycle later, mirrored (moving left is moving right seen in a mirror), so
    their profile's own harmonic is n = 2 (`half`, largest at `half_peak` and half_peak + 10, in
    10 phi / pi); n = 1 (`whole`) is what differs between the two half cycles: the bed's own
    left-right asymmetry and noise; `rest` is the rms per bin of everything above n = 2."""

    def __init__(self, case):
        centres, self.bins = case.phase_rates()
        n = len(self.bins)
        phis = [c * math.pi / 10 for c in centres]
        self.mean = sum(self.bins) / n

        def harmonic(k):
            return complex(sum(v * math.cos(k * p) for v, p in zip(self.bins, phis)),
                           sum(v * math.sin(k * p) for v, p in zip(self.bins, phis))) * 2 / n
        h1, h2 = harmonic(1), harmonic(2)
        self.whole, self.half = abs(h1), abs(h2)
        self.half_peak = (10 / math.pi * math.atan2(h2.imag, h2.real) / 2) % 10
        fit = [self.mean + abs(h1) * math.cos(p - math.atan2(h1.imag, h1.real))
               + abs(h2) * math.cos(2 * p - math.atan2(h2.imag, h2.real)) for p in phis]
        self.rest = math.sqrt(sum((v - f) ** 2 for v, f in zip(self.bins, fit)) / n)


def phase_column(text):
    """A listing's column from a case's PhaseProfile."""
    return lambda c: text(PhaseProfile(c))


def value_of(case, value):
    return value(case) if callable(value) else float(case.get(value))


# ---- cells

def beds(cases, where):
    """The cases of one cell, one per bed (box.seed); a run repeated in two folders counts once."""
    by_seed = {}
    for c in cases:
        seed = c.get("box.seed")
        if seed in by_seed:
            if not c.row.get("state_hash") or by_seed[seed].row.get("state_hash") != c.row.get("state_hash"):
                raise ValueError(f"{where}: two different runs on bed {seed:g} "
                                 f"({by_seed[seed].source} {by_seed[seed].row['case']}, {c.source} {c.row['case']})")
            continue
        by_seed[seed] = c
    return [by_seed[s] for s in sorted(by_seed)]


def cell_text(values, digits=3, each=False):
    """'+0.054 (1 bed)', '+0.041 +- 0.013 (2 beds)'; with each, the beds' values after the count."""
    if not values:
        return ""
    m, se = stats(values)
    if len(values) == 1:
        return f"{m:+.{digits}f} (1 bed)"
    listed = ": " + ", ".join(f"{v:+.{digits}f}" for v in values) if each else ""
    return f"{m:+.{digits}f} +- {se:.{digits}f} ({len(values)} beds{listed})"


# ---- tables

def key_of(case, key):
    return key(case) if callable(key) else case.get(key)


def select(sources, where):
    """The finished cases of these sources whose keys have the values `where` gives."""
    return [c for source in sources for c in load(source) if all(key_of(c, k) == v for k, v in where.items())]


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
    lines = ["| " + " | ".join(head) + " |", "|" + "---|" * len(head)]
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
        lines.append("| " + " | ".join(row) + " |")
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
    lines = ["| " + " | ".join(head) + " |", "|" + "---|" * len(head)]
    changes = {}   # (row, step): the beds' changes
    for r in spec["rows"]:
        by_value = {v: {c.get("box.seed"): value_of(c, spec.get("value", "vy")) for c in beds(cs, f"{spec['name']}: {r} {v}")}
                    for v, cs in grid.get(r, {}).items()}
        row = list(spec["row_label"](r))
        for a, b in steps:
            both = sorted(set(by_value.get(a, {})) & set(by_value.get(b, {})))
            changes[r, (a, b)] = [by_value[b][s] - by_value[a][s] for s in both]
            row.append(cell_text(changes[r, (a, b)], each=True))
        lines.append("| " + " | ".join(row) + " |")
    # the last step (first to last value) repeats the others' beds: left out of the pooled scatter
    spread, dof, groups = findings.pooled_sd([d for (r, step), d in changes.items() if step != steps[-1]])
    if spread > 0:   # none when no step has two beds, or (degenerate) every bed changed alike
        def named(r):   # "disk, T = 3": the row's labels after the first, each with its column head
            first, *rest = spec["row_label"](r)
            return first + "".join(f", {h} = {v}" for h, v in zip(spec["row_head"][1:], rest))
        resolved = [f"{named(r)}, {spec['label']} {a:g} -> {b:g} ({mean(d):+.3f}, "
                    f"{mean(d) / (spread / math.sqrt(len(d))):+.1f})"
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
    lines = ["| " + " | ".join(head) + " |", "|" + "---|" * len(head)]
    for r in spec["rows"]:
        row = [spec["row_label"](r)]
        for t in spec["periods"]:
            measured = [(a, [value_of(c, "vy") for c in beds(grid[r][(a, t)], f"{spec['name']}: {r} {a} {t}")])
                        for a in spec["amplitudes"] if (a, t) in grid.get(r, {})]
            # the findings' rule against zero, whichever way V_y goes
            resolved = findings.first_resolved(measured, sig)
            if not measured:
                text = ""
            elif not resolved:
                text = f"above {measured[-1][0]:g}"
            else:
                below, a, sign = resolved
                text = (f"{below:g}-{a:g}" if below is not None else f"<= {a:g}") + (" (rises)" if sign > 0 else " (sinks)")
            row.append(text)
        lines.append("| " + " | ".join(row) + " |")
    lines += ["", f"(the amplitudes measured: {', '.join(f'{a:g}' for a in spec['amplitudes'])}; "
              f"resolved: |V_y| >= {RESOLVED:g} sigma / sqrt(beds), sigma = {sig:.3f})"]
    return lines, spec["sources"]


def listing(spec):
    """One row per case: spec["columns"] = [(header, function(case) -> text)]."""
    cases = select(spec["sources"], spec.get("where", {}))
    cases.sort(key=spec.get("sort", lambda c: 0))
    head = [h for h, _ in spec["columns"]]
    lines = ["| " + " | ".join(head) + " |", "|" + "---|" * len(head)]
    lines += ["| " + " | ".join(fn(c) for _, fn in spec["columns"]) + " |" for c in cases]
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
    lines = ["| " + " | ".join(head) + " |", "|" + "---|" * len(head)]
    for r in sorted(grid, key=spec["row_sort"]):
        cases = beds(grid[r], f"{spec['name']}: {r}")
        lines.append("| " + " | ".join(list(spec["row_label"](r))
                                       + [cell_text([chord(t0, t1)(c) for c in cases]) for t0, t1 in spec["windows"]]) + " |")
    return lines, spec["sources"]


def means(values):
    return {k: mean(v) for k, v in values.items()}


def table1_extra():
    """Table 1's columns after the periods: wiggle's T_rising (the paper's reading: the last period
    with mean V_y <= 0 and the next, interpolated), its bracket, the period of the largest mean V_y."""
    def crossing(values):
        m = means(values)
        ts = sorted(m)
        return prepare.t_rising(ts, [m[t] for t in ts])

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
    the paper's observed T_rising (Table 1 only) and wiggle's; `value` as in TABLES."""
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


BED_PROTOCOL = {("poured", 20.0, 0.0): "poured, preset's protocol", ("poured", 40.0, 2.0): "poured, fast protocol",
                ("carved", 40.0, 2.0): "carved, fast protocol"}


def protocol(c):
    return BED_PROTOCOL[(c.get("bed.cavity"), c.get("bed.batch_height"), c.get("bed.relax_damping"))]


# Table 1 by the paper's clock: bed 1 (paper_depth_t1000.toml) and the second beds (paper_depth_t1000_bed2.toml)
T1000_BEDS = ["results/paper_depth/table1_t1000", "results/paper_depth/table1_t1000_bed2"]
T1000_WINDOWS = [(100, 400), (400, 700), (700, 1000), (100, 1000)]   # the paper's window in thirds, and whole
# At the paper's depth, t = 100: Table 1 (A = 5) and figure 5 (A = 3), each on beds 1 and 2
DEPTH_A5 = ["results/paper_depth/table1", "results/paper_depth/table1_bed2"]
DEPTH_A3 = ["results/paper_depth/fig5", "results/paper_depth/fig5_bed2", "results/paper_depth/fast_corner"]
# Figure 6 at the paper's depth: the disk and the square (paper_depth_friction.toml), the other three shapes
# (paper_depth_friction_shapes.toml); its cells, shape and period by friction
DEPTH_FRICTION = ["results/paper_depth/friction", "results/paper_depth/friction_shapes"]
DEPTH_SMALL_A = ["results/paper_depth/small_amplitude"]
AMPLITUDES = [0.5, 1.0, 3.0, 5.0]          # A = 0.5 and 1 (paper_depth_small_amplitude.toml), figure 5's 3, Table 1's 5
AMPLITUDE_PERIODS = [1.0, 3.0, 5.0, 8.0]
FRICTION_MUS = [0.0, 0.1, 0.3, 0.5]
FRICTION_ROWS = [(shape, t) for shape in SHAPES for t in (3.0, 5.0)]

TABLES = [
    # ---- docs/VALIDATION.md, the small preset (60 d wide, intruder 25 d deep)
    {"name": "small_fig5", "kind": listing, "sources": ["docs/figures/small_fig5_results.csv"],
     "sort": lambda c: (SHAPES.index(c.get("intruder.shape")), c.get("drive.period")),
     "columns": [("shape", column("intruder.shape", str)), ("T", column("drive.period")),
                 ("V_y (paper rule)", column("vy", fmt(4))), ("least-squares slope", column("vy_slope", fmt(4))),
                 ("ns/particle-step", column("ns_per_particle_step", lambda x: f"{x:.0f}")),
                 ("wall [s]", column("wall_s", lambda x: f"{x:.0f}"))]},
    {"name": "small_pour_protocol", "kind": pivot, "sources": ["results/pour_protocol_small"],
     "row": "bed.pour", "col": "drive.period", "rows": ["lattice", "random"], "each": True,
     "row_head": ["protocol"], "col_label": lambda t: f"T = {t:g}"},
    {"name": "small_friction", "kind": pivot, "sources": ["results/small_friction_amplitude"],
     "where": {"drive.amplitude": 3.0, "drive.period": 5.0},
     "row": "contact.mu", "col": lambda c: (c.get("intruder.shape"), c.get("box.seed")),
     "cols": [("disk", 1.0), ("disk", 2.0), ("square", 1.0)], "row_head": ["A = 3, T = 5"],
     "row_label": lambda m: f"mu = {m:g}", "col_label": lambda k: f"{k[0]}, bed {k[1]:g}"},
    {"name": "small_friction_disk", "kind": pivot, "sources": ["results/small_friction_amplitude"],
     "where": {"intruder.shape": "disk", "drive.amplitude": 3.0, "drive.period": 5.0},
     "row": "contact.mu", "col": lambda c: "beds 1 and 2", "row_head": ["disk, A = 3, T = 5"], "each": True,
     "row_label": lambda m: f"mu = {m:g}"},
    {"name": "small_amplitude", "kind": pivot, "sources": ["results/small_friction_amplitude"],
     "where": {"intruder.shape": "disk", "contact.mu": 0.1}, "row": "drive.amplitude", "col": "drive.period",
     "row_head": ["disk, bed 1 (A = 3: beds 1 and 2)"], "row_label": lambda a: f"A = {a:g}", "each": True,
     "col_label": lambda t: f"T = {t:g}"},
    # ---- docs/VALIDATION.md, at the paper's depth (configs/paper_depth.toml: 60 d wide, 105 d deep)
    {"name": "depth_box", "kind": listing, "sources": ["results/paper_depth/box"],
     "sort": lambda c: (c.get("box.width"), c.get("box.seed"), c.get("drive.period")),
     "columns": [("width [d]", column("box.width")), ("grains", column("n_grains", lambda x: f"{x:,.0f}")),
                 ("seed", column("box.seed")), ("T", column("drive.period")),
                 ("V_y (paper's rule)", column("vy", fmt(4))), ("least-squares slope", column("vy_slope", fmt(4))),
                 ("wall [s]", column("wall_s", lambda x: f"{x:,.0f}")),
                 ("ns/particle-step", column("ns_per_particle_step", lambda x: f"{x:.1f}"))]},
    {"name": "depth_box_means", "kind": pivot, "sources": ["results/paper_depth/box", "results/paper_depth/seeds"],
     "where": {"intruder.shape": "disk"}, "row": "box.width", "col": "drive.period",
     "row_head": ["width [d]"], "col_label": lambda t: f"T = {t:g}"},
    {"name": "depth_below45", "kind": pivot, "sources": ["results/paper_depth/box", "results/paper_depth/below45"],
     "where": {"box.width": 60.0}, "row": "intruder.y0", "col": "drive.period", "rows": [90.0, 45.0], "each": True,
     "row_head": ["grains below the intruder"], "row_label": lambda y: f"{y:g} d" + (" (the preset)" if y == 90 else ""),
     "col_label": lambda t: f"T = {t:g}"},
    {"name": "depth_full_box", "kind": pivot,
     "sources": ["results/paper_depth/box", "results/paper_depth/seeds", "results/paper_depth/full_box"],
     "where": {"intruder.shape": "disk"}, "row": "box.width", "col": "drive.period", "rows": [60.0, 150.0, 300.0],
     "value": chord(5.0, 50.0), "each": True, "row_head": ["width [d]"],
     "col_label": lambda t: f"T = {t:g}, (y(50) - y(5)) / 45"},
    {"name": "depth_runlength", "kind": listing, "sources": ["results/paper_depth/runlength_t300"],
     "sort": lambda c: -c.get("drive.period"),
     "columns": [("disk, A = 5, bed 1", column("drive.period", lambda t: f"T = {t:g}")),
                 ("V_y to t = 100", lambda c: f"{chord(10, 100)(c):+.3f}"),
                 ("to t = 200", lambda c: f"{chord(20, 200)(c):+.3f}"),
                 ("to t = 300", lambda c: f"{c.get('vy'):+.3f}"),
                 ("slope over t = 10-50, 50-100, 100-150, 150-200, 200-250, 250-300",
                  lambda c: ", ".join(f"{slope(a, b)(c):+.3f}" for a, b in
                                      [(10, 50), (50, 100), (100, 150), (150, 200), (200, 250), (250, 300)])),
                 ("y at t = 0, 50, ..., 300", lambda c: ", ".join(f"{y_at(c, t):.1f}" for t in range(0, 301, 50)))]},
    {"name": "depth_one_bed", "kind": pivot,
     "sources": ["results/paper_depth/box", "results/paper_depth/seeds", "results/paper_depth/damped_relax"],
     "where": {"box.width": 60.0, "intruder.shape": "disk"},
     "row": lambda c: (c.get("bed.relax_damping"), c.get("box.seed")), "rows": [(0.0, 1.0), (2.0, 1.0), (0.0, 2.0), (0.0, 3.0)],
     "col": "drive.period", "row_head": ["bed (60 d)"], "col_label": lambda t: f"T = {t:g}",
     "row_label": lambda r: {(0.0, 1.0): "bed 1, relaxed by the contacts' own damping (the default)",
                             (2.0, 1.0): "bed 1 (same pour), relaxation damped (`bed.relax_damping = 2`)",
                             (0.0, 2.0): "another pour: bed 2", (0.0, 3.0): "another pour: bed 3"}[r]},
    {"name": "depth_triangle", "kind": pivot, "sources": ["results/paper_depth/triangle"],
     "row": lambda c: (c.get("intruder.surface"), c.get("bed.pour")), "col": "drive.period",
     "rows": [("smooth", "lattice"), ("glued", "lattice"), ("smooth", "random")], "cols": [6.0, 4.0],
     "row_head": ["triangle"], "col_label": lambda t: f"T = {t:g}",
     "row_label": lambda r: {("smooth", "lattice"): "smooth clump, disk-area mass 25.7 (the defaults)",
                             ("glued", "lattice"): "glued 0.5 d spheres, glued-disk mass 9.9 (the paper's construction)",
                             ("smooth", "random"): "random pour (`bed.pour = \"random\"`)"}[r]},
    shape_by_period("depth_table1", ["results/paper_depth/table1"], {}, True),
    {"name": "depth_table1_beds", "kind": pivot,
     "sources": ["results/paper_depth/table1", "results/paper_depth/table1_bed2"],
     "row": lambda c: (c.get("intruder.shape"), c.get("drive.period")), "col": "box.seed",
     "rows": [(s, t) for s in SHAPES[:4] for t in ((2.0, 2.5) if s == "disk" else (2.5, 3.0))],
     "all": True, "row_head": ["shape", "T"], "row_label": lambda r: (r[0], f"{r[1]:g}"),
     "col_label": lambda s: f"bed {s:g}"},
    {"name": "depth_glued", "kind": pivot,
     "sources": ["results/paper_depth/table1", "results/paper_depth/table1_bed2", "results/paper_depth/glued"],
     "where": {"intruder.shape": "disk"}, "row": "intruder.surface", "col": "drive.period", "rows": ["smooth", "glued"],
     "cols": [2.0, 2.5], "each": True, "row_head": ["disk, A = 5"], "col_label": lambda t: f"T = {t:g}",
     "row_label": lambda s: {"smooth": "smooth, disk-area mass 25.7 (the defaults)",
                             "glued": "glued 0.5 d spheres, glued-disk mass 9.9 (the paper's construction)"}[s]},
    shape_by_period("depth_fig5", ["results/paper_depth/fig5", "results/paper_depth/fast_corner"], {}, False),
    {"name": "depth_fig5_beds", "kind": pivot, "sources": ["results/paper_depth/fig5", "results/paper_depth/fig5_bed2"],
     "row": lambda c: (c.get("intruder.shape"), c.get("drive.period")), "col": "box.seed",
     "rows": [("square", 5.0), ("square", 8.0), ("rect_wide", 5.0), ("rect_wide", 8.0), ("disk", 3.0)],
     "all": True, "row_head": ["case, A = 3", "T"], "row_label": lambda r: (r[0], f"{r[1]:g}"),
     "col_label": lambda s: f"bed {s:g}"},
    # Figure 8: the phase-resolved rates of the figure 5 cases, as harmonics (PhaseProfile)
    {"name": "depth_fig8", "kind": listing, "sources": ["results/paper_depth/fig5", "results/paper_depth/fig5_bed2"],
     "sort": lambda c: (SHAPES.index(c.get("intruder.shape")), c.get("drive.period"), c.get("box.seed")),
     "columns": [("shape", column("intruder.shape", str)), ("T", column("drive.period")), ("bed", column("box.seed")),
                 ("V_y", column("vy", fmt(3))), ("mean of the bins", phase_column(lambda p: f"{p.mean:+.3f}")),
                 ("half-cycle swing", phase_column(lambda p: f"{p.half:.3f}")),
                 ("its peaks at 10 phi / pi", phase_column(lambda p: f"{p.half_peak:.1f}, {p.half_peak + 10:.1f}")),
                 ("whole-cycle swing", phase_column(lambda p: f"{p.whole:.3f}")),
                 ("rest (rms)", phase_column(lambda p: f"{p.rest:.3f}")),
                 ("bins below 0", phase_column(lambda p: f"{sum(v < 0 for v in p.bins)} of {len(p.bins)}")),
                 ("smallest, largest bin", phase_column(lambda p: f"{min(p.bins):+.2f}, {max(p.bins):+.2f}"))]},
    # Table 1 by three clocks, from the same t = 1000 runs: the preset's t = 100 window (t = 10-100),
    # the paper's window (t = 100-1000, `vy` of a t = 1000 run) and the paper's t_f rule (`vy_settled`)
    shape_by_period("depth_t1000_window100", T1000_BEDS, {}, True, value=chord(10, 100)),
    shape_by_period("depth_t1000_window1000", T1000_BEDS, {}, True),
    shape_by_period("depth_t1000_settled", T1000_BEDS, {}, True, value="vy_settled"),
    # The drive's two readings (issue 28): the committed displacement cases (figure 5 at A = 3,
    # Table 1 at A = 5; bed 1, t = 100) beside the same cases driven as a velocity
    {"name": "depth_drive_form_A3", "kind": pivot, "sources": ["results/paper_depth/fig5", "results/paper_depth/velocity"],
     "where": {"drive.amplitude": 3.0, "box.seed": 1.0}, "row": lambda c: (c.get("intruder.shape"), c.get("drive.form")),
     "rows": [(s, f) for s in SHAPES for f in ("displacement", "velocity")], "col": "drive.period",
     "cols": [0.5, 1.0, 2.0], "row_head": ["A = 3", "drive read as"], "row_label": lambda r: r,
     "col_label": lambda t: f"T = {t:g}"},
    {"name": "depth_drive_form_A5", "kind": pivot, "sources": ["results/paper_depth/table1", "results/paper_depth/velocity"],
     "where": {"drive.amplitude": 5.0, "box.seed": 1.0}, "row": lambda c: (c.get("intruder.shape"), c.get("drive.form")),
     "rows": [(s, f) for s in ("disk", "square") for f in ("displacement", "velocity")], "col": "drive.period",
     "cols": [2.5, 3.0, 4.0], "row_head": ["A = 5", "drive read as"], "row_label": lambda r: r,
     "col_label": lambda t: f"T = {t:g}"},
    # Table 1's crossings by the paper's window on two beds (bed 2: paper_depth_t1000_bed2.toml)
    {"name": "depth_t1000_beds", "kind": pivot,
     "sources": T1000_BEDS,
     "row": lambda c: (c.get("intruder.shape"), c.get("drive.period")), "col": "box.seed",
     "rows": [(s, t) for s in SHAPES[:4] for t in (2.5, 3.0)], "cols": [1.0, 2.0],
     "all": True, "row_head": ["shape", "T"], "row_label": lambda r: (r[0], f"{r[1]:g}"),
     "col_label": lambda s: f"bed {s:g}, t = 100-1000"},
    # The same runs' V_y over the paper's window in thirds, to show whether a rate holds through the window
    {"name": "depth_t1000_windows", "kind": windows, "sources": T1000_BEDS, "where": {"drive.amplitude": 5.0},
     "row": lambda c: (c.get("intruder.shape"), c.get("drive.period")),
     "row_sort": lambda r: (SHAPES.index(r[0]), r[1]), "row_head": ["shape", "T"],
     "row_label": lambda r: (r[0], f"{r[1]:g}"), "windows": T1000_WINDOWS},
    # Figure 6 at the paper's depth (paper_depth_friction.toml): the disk and the square at A = 3, each bed
    # poured at mu = 0.1 and run at four mu; the rates, then their changes bed by bed (paired)
    {"name": "depth_friction", "kind": pivot, "sources": DEPTH_FRICTION,
     "row": lambda c: (c.get("intruder.shape"), c.get("drive.period")), "col": "contact.mu",
     "rows": FRICTION_ROWS, "cols": FRICTION_MUS, "each": True, "row_head": ["A = 3", "T"],
     "row_label": lambda r: (r[0], f"{r[1]:g}"), "col_label": lambda m: f"mu = {m:g}"},
    {"name": "depth_friction_steps", "kind": paired_steps, "sources": DEPTH_FRICTION,
     "row": lambda c: (c.get("intruder.shape"), c.get("drive.period")), "key": "contact.mu", "label": "mu",
     "values": FRICTION_MUS, "rows": FRICTION_ROWS, "row_head": ["A = 3", "T"],
     "row_label": lambda r: (r[0], f"{r[1]:g}")},
    # The control (paper_depth_friction_own_beds.toml): bed 1 poured at the case's own mu, beside the pinned bed
    {"name": "depth_friction_own_beds", "kind": pivot, "sources": DEPTH_FRICTION + ["results/paper_depth/friction_own_beds"],
     "where": {"box.seed": 1.0, "drive.period": 3.0},
     "row": lambda c: (c.get("intruder.shape"), c.get("contact.mu")),
     "col": lambda c: "own" if c.get("bed.mu") < 0 else f"{c.get('bed.mu'):g}",
     "rows": [(s, m) for s in ("disk", "square") for m in (0.0, 0.5)], "cols": ["0.1", "own"],
     "row_head": ["A = 3, T = 3, bed 1", "mu"], "row_label": lambda r: (r[0], f"{r[1]:g}"),
     "col_label": lambda k: "bed poured at mu = 0.1" if k == "0.1" else "bed poured at the case's mu"},
    # Small amplitudes at the paper's depth (paper_depth_small_amplitude.toml, bed 1) beside figure 5's A = 3
    # and Table 1's A = 5 (their beds 1 and 2); then the amplitude at which V_y leaves the beds' scatter
    {"name": "depth_amplitude", "kind": pivot, "sources": DEPTH_SMALL_A + DEPTH_A3 + DEPTH_A5,
     "row": lambda c: (c.get("intruder.shape"), c.get("drive.amplitude")), "col": "drive.period",
     "rows": [(s, a) for s in SHAPES for a in AMPLITUDES], "cols": AMPLITUDE_PERIODS, "row_head": ["shape", "A"],
     "row_label": lambda r: (r[0], f"{r[1]:g}"), "col_label": lambda t: f"T = {t:g}"},
    {"name": "depth_amplitude_threshold", "kind": amplitude_threshold, "sources": DEPTH_SMALL_A + DEPTH_A3 + DEPTH_A5,
     "row": "intruder.shape", "rows": SHAPES, "amplitudes": AMPLITUDES, "periods": AMPLITUDE_PERIODS,
     "sigma": lambda: depth_sigma(), "row_head": ["shape: A_min between"], "row_label": str},
    # Figure 2 by the paper's clock (paper_depth_fig2_t1000.toml): each case's rate by the three clocks
    # and how far it moved
    {"name": "depth_fig2_t1000", "kind": listing, "sources": ["results/paper_depth/fig2_t1000"],
     "sort": lambda c: (SHAPES.index(c.get("intruder.shape")), c.get("drive.period")),
     "columns": [("shape", column("intruder.shape", str)), ("T", column("drive.period")),
                 ("V_y, t = 10-100", lambda c: fmt(3)(chord(10, 100)(c))),
                 ("V_y, t = 100-1000", column("vy", fmt(3))), ("V_y, t_f rule", column("vy_settled", fmt(3))),
                 ("settled at", lambda c: f"t = {c.get('t_settled'):g}" if c.get("t_settled") < c.get("run.duration")
                  else "not settled"),  # t_settled is the run's end when the intruder never settles
                 ("y(100) - y(0)", lambda c: f"{y_at(c, 100) - y_at(c, 0):+.1f}"),
                 ("y(1000) - y(0)", lambda c: f"{y_at(c, 1000) - y_at(c, 0):+.1f}")]},
    # ---- docs/PERFORMANCE.md
    {"name": "perf_bed_protocols", "kind": pivot,
     "sources": ["results/paper_depth/box", "results/paper_depth/seeds", "results/paper_depth/table1",
                 "results/paper_depth/table1_bed2", "results/paper_depth/bed_fast", "results/paper_depth/bed_carved"],
     "where": {"box.width": 60.0, "drive.amplitude": 5.0, "intruder.surface": "smooth", "bed.pour": "lattice"},
     "row": lambda c: (c.get("intruder.shape"), c.get("drive.period"), c.get("box.seed")),
     "rows": [("disk", 3.0, 1.0), ("disk", 3.0, 2.0), ("disk", 5.0, 1.0), ("disk", 5.0, 2.0),
              ("square", 3.0, 1.0), ("square", 3.0, 2.0)],
     "col": protocol, "cols": list(BED_PROTOCOL.values()), "row_head": ["case"],
     "row_label": lambda r: f"{r[0]}, T = {r[1]:g}, seed {r[2]:g}"},
]


# ---- the paper's findings (docs/PHYSICS.md §12), judged by a rule from comparisons of cells
#
# The rule (comparisons in standard errors of one bed's sigma at a scale, the verdicts) is
# tools/study/findings.py's; here the cells' values are gathered from the results and printed.


class Cell:
    """The beds of one case: `sources` (folders), `where` (key: value)."""

    def __init__(self, sources, **where):
        self.sources, self.where = sources, {k.replace("__", "."): v for k, v in where.items()}

    def values(self):
        cases = select(self.sources, self.where)
        return [float(c.get("vy")) for c in beds(cases, f"{self.sources} {self.where}")]


def sigma(cells):
    """One bed's standard deviation at a scale: the largest over the given cells, each of several beds."""
    return findings.largest_sd([c.values() for c in cells])


def cells_with_beds(sources):
    """Every (shape, A, T) cell of these sources that has two or more beds."""
    keys = {(c.get("intruder.shape"), c.get("drive.amplitude"), c.get("drive.period")) for s in sources for c in load(s)}
    cells = [Cell(sources, intruder__shape=s, drive__amplitude=a, drive__period=t) for s, a, t in sorted(keys)]
    return [c for c in cells if len(c.values()) >= 2]


def short(where):
    """'square, A = 5, T = 3' from a filter."""
    names = {"drive.amplitude": "A", "drive.period": "T", "contact.mu": "mu", "box.seed": "bed"}
    parts = [str(where["intruder.shape"])] if "intruder.shape" in where else []
    parts += [f"{names[k]} = {v:g}" for k, v in where.items() if k in names]
    return ", ".join(parts)


def mean_text(values):
    return cell_text(values) if values else "0"


def evidence_table(spec):
    """Every comparison of every finding: the cells, the difference and its standard errors."""
    head = ["finding", "scale", "comparison (the paper's way)", "a", "b", "a - b", "standard errors, the paper's way"]
    lines = ["| " + " | ".join(head) + " |", "|" + "---|" * len(head)]
    for number, finding, scales in spec["findings"]():
        for scale, (sig, comparisons, *_) in scales.items():
            for c in filter(None, comparisons):
                diff, z, _ = findings.judged(c, sig)
                lines.append("| " + " | ".join([str(number), scale, c[0], mean_text(c[1]), mean_text(c[2]),
                                                  f"{diff:+.3f}", f"{z:+.1f}"]) + " |")
    return lines, spec["sources"]


def findings_table(spec):
    """One row per finding: per scale, how its comparisons came out, and the verdict by the rule."""
    scales = spec["scales"]
    head = ["paper's finding"] + [f"{s}: comparisons" for s in scales] + [f"verdict, {s}" for s in scales]
    lines = ["| " + " | ".join(head) + " |", "|" + "---|" * len(head)]
    for number, finding, by_scale in spec["findings"]():
        counts, verdicts = [], []
        for s in scales:
            sig, comparisons, *note = by_scale.get(s, (0.0, []))
            comparisons = [c for c in comparisons if c]
            outcomes = [findings.judged(c, sig) for c in comparisons]
            kinds = [o[2] for o in outcomes]
            against = [f"{c[0]} ({o[1]:+.1f})" for c, o in zip(comparisons, outcomes) if o[2] == "against"]
            n = sorted({len(c[1]) for c in comparisons} | {len(c[2]) for c in comparisons if c[2]})
            text = (f"{len(kinds)} comparison{'s' if len(kinds) > 1 else ''} of cases of {n[0]}" + (f"-{n[-1]}" if n[-1] > n[0] else "")
                    + f" bed{'s' if n[-1] > 1 else ''}: "
                    f"{kinds.count('for')} the paper's way by >= {RESOLVED:g} standard errors, "
                    f"{kinds.count('within')} within {RESOLVED:g}, {kinds.count('against')} against"
                    + (": " + "; ".join(against) if against else "") + (f" ({note[0]})" if note else "")) \
                if kinds else (note[0] if note else "no committed results")
            counts.append(text)
            verdicts.append(findings.finding_verdict(sig, comparisons, *note))
        lines.append("| " + " | ".join([f"{number}. {finding}"] + counts + verdicts) + " |")
    sigmas = {s: v[0] for _, _, by_scale in spec["findings"]() for s, v in by_scale.items()}
    lines += ["", "One bed's standard deviation, sigma: " + ", ".join(f"{s} {sigmas[s]:.3f}" for s in scales) + "."]
    return lines, spec["sources"]


CLOCK_A5 = T1000_BEDS                              # the paper's clock: t = 1000 runs, V_y over t = 100-1000
CLOCK_A3 = ["results/paper_depth/fig2_t1000"]
SMALL_SESSION2 = ["docs/figures/small_fig5_results.csv"]   # disk and triangle, A = 3, bed 1, session 2's engine
SMALL_POUR = ["results/pour_protocol_small"]
SMALL_FRICTION = ["results/small_friction_amplitude"]
# The disk's and the triangle's rise/sink maps, A = 1-5, beds 1-3 (`wiggle boundary`)
SMALL_MAP = ["results/boundary/small_pd_disk", "results/boundary/small_pd_triangle"]
SMALL_MAP_SHAPES = ["disk", "triangle"]
SMALL_MAP_AMPLITUDES = [3.0, 4.0, 5.0]   # the findings for A >= 3
# Today's engine on the small preset's lattice beds at mu = 0.1 (a run in two folders counts once)
SMALL_TODAY = SMALL_MAP + SMALL_POUR + SMALL_FRICTION
SMALL_TODAY_WHERE = {"bed__pour": "lattice", "contact__mu": 0.1}
PAPER_ORDER = ["disk", "rect_narrow", "square", "rect_wide", "triangle"]   # the paper's order of rise rates


def periods(sources, **where):
    """The periods at which a cell of these sources and filter has results, in order."""
    return sorted({c.get("drive.period") for c in select(sources, Cell(sources, **where).where)})


def by_period(sources, **where):
    """{T: the beds' V_y} at each period at which a cell of these sources and filter has results."""
    return {t: Cell(sources, drive__period=t, **where).values() for t in periods(sources, **where)}


def sinks_then_rises(sources, label, shapes, **where):
    """Finding 1 for each shape (findings.sinks_then_rises)."""
    return [c for shape in shapes
            for c in findings.sinks_then_rises(label, shape, by_period(sources, intruder__shape=shape, **where))]


def has_maximum(sources, label, shapes, **where):
    """Finding 2 for each shape that rises somewhere (findings.has_maximum)."""
    return [c for shape in shapes
            for c in findings.has_maximum(label, shape, by_period(sources, intruder__shape=shape, **where))]


def in_order(sources, label, ts, **where):
    """Finding 4 at each period: every pair of neighbours in the paper's order that has results."""
    return [c for t in ts for c in findings.in_order(
        label, t, {s: Cell(sources, intruder__shape=s, drive__period=t, **where).values() for s in PAPER_ORDER})]


def sinks(sources, label, shape, **where):
    return findings.sinks(label, shape, by_period(sources, intruder__shape=shape, **where))


def friction(sources, label, shape, **where):
    """Finding 6: each step up in mu raises the rate, over every mu the shape was run at in these sources."""
    mus = sorted({c.get("contact.mu") for s in sources for c in load(s) if c.get("intruder.shape") == shape})
    return findings.friction_steps(label, {mu: Cell(sources, intruder__shape=shape, contact__mu=mu, **where).values()
                                           for mu in mus})


def table1_range(sources, **where):
    """Finding 7 for each of the paper's shapes (findings.table1_range)."""
    return [c for shape, paper_range in PAPER_RANGE.items()
            for c in findings.table1_range(shape, by_period(sources, intruder__shape=shape, **where), paper_range)]


def depth_sigma():
    """One bed's standard deviation at the paper's depth: the disk at A = 3, T = 3 on the box study's beds."""
    return sigma([Cell(["results/paper_depth/box", "results/paper_depth/seeds"], intruder__shape="disk",
                       box__width=60.0, drive__period=3.0)])


def small_amplitudes(sources, shape, t, direction, **where):
    """Finding 3 (findings.small_amplitudes) for a shape at period t."""
    return findings.small_amplitudes(shape, t, {a: Cell(sources, intruder__shape=shape, drive__amplitude=a, drive__period=t,
                                                        **where).values() for a in (3.0, 1.0, 0.5)}, direction)


_FINDINGS = []


def paper_findings():
    """[(number, the finding, {scale: (sigma, [comparisons])})], docs/PHYSICS.md §12."""
    if _FINDINGS:
        return _FINDINGS
    depth = depth_sigma()
    # The paper's clock: the largest standard deviation of its cells of two beds.
    clock = sigma(cells_with_beds(CLOCK_A5))
    small = sigma([Cell(SMALL_POUR, bed__pour="lattice", drive__period=t) for t in (1.0, 5.0)])
    today = SMALL_TODAY_WHERE
    _FINDINGS.extend([
        (1, "for A >= 3 the intruder sinks at short periods and rises at long ones", {
            "paper's depth": (depth, sinks_then_rises(DEPTH_A5, "A = 5", SHAPES) + sinks_then_rises(DEPTH_A3, "A = 3", SHAPES)),
            "paper's clock": (clock, sinks_then_rises(CLOCK_A5, "A = 5", SHAPES) + sinks_then_rises(CLOCK_A3, "A = 3", SHAPES)),
            "small preset": (small, [c for a in SMALL_MAP_AMPLITUDES
                                     for c in sinks_then_rises(SMALL_TODAY, f"A = {a:g}", SMALL_MAP_SHAPES,
                                                               drive__amplitude=a, **today)])}),
        (2, "the rise rate has a maximum in T", {
            "paper's depth": (depth, has_maximum(DEPTH_A5, "A = 5", SHAPES) + has_maximum(DEPTH_A3, "A = 3", SHAPES)),
            # Table 1's t = 1000 periods stop at T = 3-4, below the t = 100 grid's maxima, and figure 2's are 1 and 5
            "paper's clock": (clock, [], "not judged: its periods stop below the maxima"),
            "small preset": (small, [c for a in SMALL_MAP_AMPLITUDES
                                     for c in has_maximum(SMALL_TODAY, f"A = {a:g}", SMALL_MAP_SHAPES, drive__amplitude=a, **today)]
                             + has_maximum(SMALL_SESSION2, "A = 3 (session 2)", ["disk"]))}),
        (3, "at A = 0.5 and 1 the intruder hardly moves", {
            # the paper's way at A = 3: every shape sinks at T = 1 (finding 1); at T = 5 the disk rises and
            # the triangle sinks (findings 1 and 5)
            "paper's depth": (depth, [c for shape in SHAPES for c in small_amplitudes(DEPTH_SMALL_A + DEPTH_A3, shape, 1.0, -1)]
                              + small_amplitudes(DEPTH_SMALL_A + DEPTH_A3, "disk", 5.0, +1)
                              + small_amplitudes(DEPTH_SMALL_A + DEPTH_A3, "triangle", 5.0, -1)),
            # at A = 3 on this bed the disk sinks at T = 2 and rises at T = 5 (finding 1), the triangle sinks at both
            "small preset": (small, small_amplitudes(SMALL_TODAY, "disk", 2.0, -1, **today)
                             + small_amplitudes(SMALL_TODAY, "disk", 5.0, +1, **today)
                             + small_amplitudes(SMALL_TODAY, "triangle", 2.0, -1, **today)
                             + small_amplitudes(SMALL_TODAY, "triangle", 5.0, -1, **today))}),
        (4, "rise rates order the shapes disk > narrow rectangle > square > wide rectangle > triangle", {
            "paper's depth": (depth, in_order(DEPTH_A5, "A = 5", [3.0, 4.0, 5.0, 6.0])
                              + in_order(DEPTH_A3, "A = 3", [3.0, 4.0, 5.0, 6.0, 8.0])),
            "paper's clock": (clock, in_order(CLOCK_A5, "A = 5", [3.0, 4.0, 5.0, 6.0])
                              + in_order(CLOCK_A3, "A = 3", [3.0, 4.0, 5.0, 6.0, 8.0])),
            "small preset": (small, [c for a in SMALL_MAP_AMPLITUDES
                                     for c in in_order(SMALL_TODAY, f"A = {a:g}",
                                                       [t for t in periods(SMALL_TODAY, drive__amplitude=a, **today) if t >= 3],
                                                       drive__amplitude=a, **today)],
                             "the disk and the triangle, and at A = 3, T = 5 the square (one bed)")}),
        (5, "the triangle sinks in most of the grid", {
            "paper's depth": (depth, sinks(DEPTH_A5, "A = 5", "triangle") + sinks(DEPTH_A3, "A = 3", "triangle")),
            "paper's clock": (clock, sinks(CLOCK_A5, "A = 5", "triangle") + sinks(CLOCK_A3, "A = 3", "triangle")),
            "small preset": (small, [c for a in SMALL_MAP_AMPLITUDES
                                     for c in sinks(SMALL_TODAY, f"A = {a:g}", "triangle", drive__amplitude=a, **today)])}),
        (6, "more friction, faster rise", {
            "paper's depth": (depth, [step for shape, t in FRICTION_ROWS
                                      for step in friction(DEPTH_FRICTION, f"{shape}, A = 3, T = {t:g}", shape,
                                                           drive__period=t)]),
            "small preset": (small, friction(SMALL_FRICTION, "disk, A = 3, T = 5", "disk", drive__amplitude=3.0)
                             + friction(SMALL_FRICTION, "square, A = 3, T = 5", "square"))}),
        (7, "each shape starts rising where the paper's Table 1 says (A = 5)", {
            "paper's depth": (depth, table1_range(DEPTH_A5)),
            "paper's clock": (clock, table1_range(CLOCK_A5)),
            "small preset": (small, table1_range(SMALL_TODAY, drive__amplitude=5.0, **today))}),
    ])
    return _FINDINGS


FINDING_SOURCES = DEPTH_A5 + DEPTH_A3 + ["results/paper_depth/box", "results/paper_depth/seeds"] + CLOCK_A5 + CLOCK_A3 \
    + SMALL_POUR + SMALL_MAP \
    + DEPTH_FRICTION + DEPTH_SMALL_A + SMALL_FRICTION + SMALL_SESSION2
TABLES += [
    {"name": "findings", "kind": findings_table, "findings": paper_findings, "scales": ["paper's depth", "paper's clock", "small preset"],
     "sources": FINDING_SOURCES},
    {"name": "findings_evidence", "kind": evidence_table, "findings": paper_findings, "sources": FINDING_SOURCES},
]


# ---- the rise/sink boundaries found by `wiggle boundary` (boundary.json of each search)

BOUNDARIES = [("results/boundary/small_pd_disk", "disk", "small preset"),
              ("results/boundary/small_pd_triangle", "triangle", "small preset"),
              ("results/boundary/depth_disk_A5", "disk", "paper-depth preset")]


def boundary_table(spec):
    """One row per search (preset, shape, amplitude): where V_y turns from sinking to rising, the
    periods where it is indistinguishable from zero, and the runs it took."""
    head = ["preset", "shape", "A", "sinking -> rising", "V_y indistinguishable from zero at T", "runs"]
    lines = ["| " + " | ".join(head) + " |", "|" + "---|" * len(head)]
    for folder, shape, preset in BOUNDARIES:
        with open(os.path.join(ROOT, folder, "boundary.json")) as f:
            study = json.load(f)
        for search in study["searches"]:
            amplitude = search.get("over")
            if amplitude is None:   # a search without --over: the amplitude of its base config
                amplitude = load(folder)[0].get("drive.amplitude")
            crossing = "; ".join(f"between T = {c['below']:g} and {c['above']:g}" for c in search["crossings"]) or "none"
            bands = ", ".join(f"{b['first']:g}" + (f"-{b['last']:g}" if b["last"] != b["first"] else "")
                              for b in search["neutral_bands"]) or "none"
            if not search.get("finished"):
                crossing += " (search not finished)"
            lines.append("| " + " | ".join([preset, shape, f"{amplitude:g}", crossing, bands,
                                              str(search["cost"]["runs"])]) + " |")
    rules = []
    for folder, _, _ in BOUNDARIES:
        with open(os.path.join(ROOT, folder, "boundary.json")) as f:
            study = json.load(f)
        rule = study["rule"] + (f" (one bed's scatter taken as {study['known_scatter']:g})" if study["known_scatter"] else "")
        if rule not in rules:
            rules.append(rule)
    lines += ["", "(a period sinks or rises when, by each search's boundary.json: " + "; ".join(rules) + ")"]
    return lines, [b[0] for b in BOUNDARIES]


# ---- the answer first: docs/VALIDATION.md's opening page, "Does wiggle reproduce the paper?"
#
# Table 1 read by the findings' rule: a period's V_y is "rising" when it is at least RESOLVED
# standard errors above zero (findings.first_rise); wiggle's bracket is the first period that rises
# and the period run below it. By the paper's clock each shape is judged by its own scatter
# (clock_scatter below); the findings (docs/FINDINGS.md) keep their one sigma per scale.

SHAPE_NAMES = {"disk": "disk (OS1)", "square": "square (OS2)", "rect_narrow": "narrow rectangle (OS3)",
               "rect_wide": "wide rectangle (OS4)", "triangle": "triangle (OS5)"}
MODEL_T_RISE = {}   # from the cases' model.json: the cavity model's T_rise per shape
# The paper's own words on its triangle, beside its Table 1's 4-5: (quoted, where they stand in the paper)
PAPER_TRIANGLE_WORDS = [("is noticed to sink always irrespective of the time periods", "its section 3.1, of figure 2e at A = 3"),
                        ("is observed to have a negligible rise even when it is oscillated at a high time period",
                         "its conclusions, section 4.1")]


def paper_triangle_text():
    """The paper's words on its triangle, quoted, each with where it stands."""
    return " and ".join(f'"{words}" ({where})' for words, where in PAPER_TRIANGLE_WORDS)


def short_name(shape):
    return SHAPE_NAMES[shape].split(" (")[0]


# One bed's scatter by the paper's clock, shape by shape (issue 79): pooled over the shape's cells of
# two beds or more among the clock's runs in the 60 d box on beds poured for them: Table 1's
# (CLOCK_A5) and the factor screen's (each of its rows a new pour). Left out: the glued mass's runs
# (results/paper_depth/mass_t1000), on the baseline's own beds, whose deviations from their mean
# repeat the baseline's beds' (counted twice they would count as independent); the paper's 300 d box,
# one bed a cell. A shape without a cell of two beds takes the pool over every shape's cells
# (findings.shape_scatter), and the text says so.
CLOCK_SCATTER = CLOCK_A5 + ["results/paper_depth/factors_t1000"]
SCATTER_KEYS = ("intruder.shape", "drive.amplitude", "drive.period", "intruder.surface", "bed.pour",
                "intruder.mass_rule", "box.width")   # what makes a cell besides its bed


@functools.lru_cache(maxsize=None)
def clock_scatter():
    """{shape: findings.Scatter}: one bed's V_y standard deviation by the paper's clock per shape."""
    groups = {}
    for source in committed(CLOCK_SCATTER):
        for c in load(source):
            groups.setdefault(tuple(c.get(k) for k in SCATTER_KEYS), []).append(c)
    cells = {shape: [] for shape in SHAPES}
    for key in sorted(groups, key=str):
        cells.setdefault(key[0], []).append([float(c.get("vy")) for c in beds(groups[key], f"{CLOCK_SCATTER} {key}")])
    return findings.shape_scatter(cells)


def clock_sigma(shape):
    """One bed's sigma of a shape by the paper's clock (clock_scatter)."""
    return clock_scatter()[shape].sigma


def scatter_text(shape):
    """'0.0024 (5 dof)': a shape's sigma by the paper's clock and its degrees of freedom."""
    s = clock_scatter()[shape]
    return f"{s.sigma:.4f} ({s.dof} dof" + ("" if s.own else ": no cell of its own with two beds, every shape's pool") + ")"


def scatter_words(shapes):
    """How the clock's sigma of these shapes is made, each value with its degrees of freedom, and what
    2 standard errors are worth with so few: words for a caption."""
    scatter = clock_scatter()
    dofs = sorted({scatter[s].dof for s in shapes})
    student = ", ".join(f"{findings.t_critical(d):.2f} se for {d} dof" for d in dofs)
    return ("one bed's standard deviation of the shape by the paper's clock, pooled over the shape's cells "
            "of two beds or more (Table 1's runs and the factor screen's new pours in the 60 d box; the glued "
            "mass's runs, on the baseline's own beds, left out; dof: its degrees of freedom, the beds less one "
            "per cell): " + ", ".join(f"{short_name(s)} {scatter_text(s)}" for s in shapes)
            + f". The rule stays {RESOLVED:g} se whatever the dof; with so few it is a weaker test than it reads "
            f"(Student's t puts the two-sided 95 % at {student})")


def z_of(values, shape):
    """A cell's V_y in standard errors from zero by its shape's sigma (findings.z_from_zero)."""
    return findings.z_from_zero(values, clock_sigma(shape))


def student_note(z, shape):
    """'under Student's t 4.30 for its 2 dof' where |z| is resolved by the rule yet below Student's
    two-sided 95 % value for the shape's sigma's degrees of freedom, else ''."""
    s = clock_scatter()[shape]
    t = findings.t_critical(s.dof)
    return f"under Student's t {t:.2f} for its {s.dof} dof" if RESOLVED <= abs(z) < t else ""


def beds_z_text(values, shape):
    """'+0.019 (2 beds, +11.2 se)': a cell's mean, its beds and its standard errors from zero by its
    shape's sigma by the paper's clock."""
    z = z_of(values, shape)
    note = student_note(z, shape)
    return (f"{mean(values):+.3f} ({len(values)} bed{'s' if len(values) > 1 else ''}, {z:+.1f} se"
            + (f"; {note})" if note else ")"))


def model_t_rise(shape):
    """The cavity model's T_rise (paper section 3.5) for a shape, from a committed case's model.json."""
    if shape not in MODEL_T_RISE:
        case = next(c for c in load(T1000_BEDS[0]) if c.get("intruder.shape") == shape)
        with open(os.path.join(case.dir, "model.json")) as f:
            MODEL_T_RISE[shape] = json.load(f)["T_rise"]
    return MODEL_T_RISE[shape]


def first_rise(sources, shape, sig):
    """(T below, T above, [(T, values)]) of a shape's A = 5 cells: the first period whose V_y rises by
    the rule, and the period run below it (None when it is the shortest run, or when none rises)."""
    cells = list(by_period(sources, intruder__shape=shape, drive__amplitude=5.0).items())
    return (*findings.first_rise(cells, sig), cells)


def beds_text(values):
    return f"{mean(values):+.3f} ({len(values)} bed{'s' if len(values) > 1 else ''})"


def against_paper(lo, hi, shape):
    return findings.against_range(lo, hi, PAPER_RANGE[shape])


def bracket_text(lo, hi, cells):
    if hi is None:
        if not cells:
            return "not run"
        run = f"{cells[0][0]:g}" + (f"-{cells[-1][0]:g}" if len(cells) > 1 else "")
        return f"none: not rising at T = {run}"
    return f"{lo:g}-{hi:g}" if lo is not None else f"<= {hi:g}"


def beds_range(cells):
    """'1-2': the fewest and most beds of [(T, values)]."""
    n = sorted({len(v) for _, v in cells})
    return f"{n[0]}" + (f"-{n[-1]}" if n[-1] > n[0] else "")


# ---- where the mean V_y turns positive, the paper's own reading (no standard errors)

CROSSING_WORDS = {-1: "at or below the paper's lower end", 0: "overlaps the paper's range",
                  +1: "above the paper's range", None: "not placed by the periods run"}


def sign_crossing(cells):
    """(T below, T above) of [(T, values)]: the last period whose mean V_y <= 0 and the next, as the
    paper reads its T_rising (prepare.t_rising); T below None when the mean is positive already at the
    shortest period run, T above None when it never turns positive."""
    _, lo, hi, _ = prepare.t_rising([t for t, _ in cells], [mean(v) for _, v in cells])
    return (None if lo != lo else lo), (None if hi != hi else hi)


def crossing_text(lo, hi, cells):
    if hi is None:
        return f"none: mean <= 0 up to T = {cells[-1][0]:g}"
    return f"{lo:g}-{hi:g}" if lo is not None else f"> 0 already at T = {hi:g}, the shortest run"


def crossings():
    """[(shape, T below, T above, findings.crossing_against_range, [(T, values)])] by the paper's clock
    at A = 5, every shape run (sign_crossing)."""
    out = []
    for shape in SHAPES:
        cells = list(by_period(CLOCK_A5, intruder__shape=shape, drive__amplitude=5.0).items())
        if cells:
            lo, hi = sign_crossing(cells)
            out.append((shape, lo, hi, findings.crossing_against_range(lo, hi, PAPER_RANGE[shape]), cells))
    return out


def crossings_sentence(rest_too=True):
    """Where the sign crossings lie against the paper's ranges, in a sentence; its first words say
    whether every crossing the runs place lies at or below the paper's lower end; rest_too: also the
    shapes whose crossing the periods run do not place."""
    found = crossings()
    placed = [x for x in found if x[3] is not None and x[2] is not None]
    below = [x for x in placed if x[3] == -1]
    listed = ", ".join(f"{short_name(s)} {lo:g}-{hi:g} against {paper_observed(s)}" for s, lo, hi, _, _ in placed)
    rest = [f"the {short_name(s)}'s mean " + (f"is > 0 already at T = {hi:g}, its shortest period run (paper: "
                                              f"{paper_observed(s)})" if hi is not None else
                                              f"stays <= 0 up to T = {cells[-1][0]:g} (paper: {paper_observed(s)})")
            for s, lo, hi, side_, cells in found if not (side_ is not None and hi is not None)]
    if placed and len(below) == len(placed):
        head = (f"every crossing the runs place lies at or below the paper's lower end ({listed}): a shift to "
                "shorter periods")
    else:
        head = "the crossings the runs place: " + "; ".join(f"{short_name(s)} {lo:g}-{hi:g}, {CROSSING_WORDS[side_]}"
                                                            for s, lo, hi, side_, _ in placed)
    return head + ("; " + " and ".join(rest) if rest and rest_too else "")


def answer_table1(spec):
    """Table 1 (A = 5): the paper's observed range, the cavity model's T_rise, wiggle's bracket by the
    paper's clock with the V_y either side (each shape judged by its own scatter), where the mean turns
    positive (the paper's reading), and the bracket by the preset's t = 100 window."""
    depth = depth_sigma()
    head = ["shape", "paper, observed", "cavity model T_rise", "wiggle, paper's clock", "V_y there (below; first rising)",
            "the paper's range?", "the mean turns > 0 (paper's reading)", "wiggle, t = 100"]
    lines = ["| " + " | ".join(head) + " |", "|" + "---|" * len(head)]
    all_cells = []
    for shape in SHAPES:
        lo, hi, cells = first_rise(CLOCK_A5, shape, clock_sigma(shape))
        all_cells += cells
        values = dict(cells)
        there = "; ".join(beds_z_text(values[t], shape) for t in (lo, hi) if t is not None) if hi is not None else \
            ", ".join(f"{beds_z_text(vs, shape)} at T = {t:g}" for t, vs in cells)
        slo, shi = sign_crossing(cells)
        crossing = (f"{crossing_text(slo, shi, cells)}: "
                    f"{CROSSING_WORDS[findings.crossing_against_range(slo, shi, PAPER_RANGE[shape])]}")
        dlo, dhi, dcells = first_rise(DEPTH_A5, shape, depth)
        lines.append("| " + " | ".join([SHAPE_NAMES[shape], paper_observed(shape),
                                          f"{model_t_rise(shape):.2f}", bracket_text(lo, hi, cells), there,
                                          against_paper(lo, hi, shape), crossing, bracket_text(dlo, dhi, dcells)]) + " |")
    lines += ["", f"(T in sqrt(d/g); A = 5 d. The paper's clock: V_y over t = 100-1000 of runs to t = 1000 on the "
              f"paper-depth preset, {beds_range(all_cells)} beds a period. A period rises when its V_y is >= "
              f"{RESOLVED:g} sigma / sqrt(beds) above zero (se: its standard errors from zero), sigma "
              + scatter_words(SHAPES) + ". The bracket is the first period that rises and the period run below it. "
              "The mean turns > 0: the last period whose mean V_y <= 0 and the next, the paper's own reading of "
              f"T_rising, without standard errors. t = 100: V_y over t = 10-100, one sigma for every shape, {depth:.3f} "
              "(docs/FINDINGS.md's at the paper's depth))"]
    return lines, spec["sources"]


def verdict_cell(sig, comparisons, note):
    comparisons = [c for c in comparisons if c]
    verdict = findings.finding_verdict(sig, comparisons, *note)
    if not comparisons:
        return verdict
    kinds = [findings.judged(c, sig)[2] for c in comparisons]
    n = sorted({len(c[1]) for c in comparisons} | {len(c[2]) for c in comparisons if c[2]})
    beds_range = f"{n[0]}" + (f"-{n[-1]}" if n[-1] > n[0] else "")
    assert findings.verdict(kinds) == verdict, (verdict, kinds)
    said = findings.verdict_words(kinds)
    return f"**{verdict}**{said[len(verdict):]} ({beds_range} bed{'s' if n[-1] > 1 else ''})"


def findings_clock_sigma():
    """The findings' one sigma by the paper's clock (docs/FINDINGS.md's rule: the largest over its cells
    of two beds, for every shape)."""
    return sigma(cells_with_beds(CLOCK_A5))


def answer_findings(spec):
    """The paper's findings: the verdict at each scale with its count of comparisons."""
    scales = [("paper's clock", "paper's clock (t = 100-1000)"), ("paper's depth", "paper's depth (t = 10-100)"),
              ("small preset", "small preset (25 d deep)")]
    head = ["the paper's finding"] + [label for _, label in scales]
    lines = ["| " + " | ".join(head) + " |", "|" + "---|" * len(head)]
    for number, finding, by_scale in paper_findings():
        row = [f"{number}. {finding}"]
        for scale, _ in scales:
            sig, comparisons, *note = by_scale.get(scale, (0.0, []))
            row.append(verdict_cell(sig, comparisons, note))
        lines.append("| " + " | ".join(row) + " |")
    lines += ["", f"(a comparison counts for or against the paper at >= {RESOLVED:g} standard errors; by docs/FINDINGS.md's "
              f"rule one sigma per scale serves every shape, by the paper's clock {findings_clock_sigma():.3f}, the largest "
              "over its cells of two beds, where the tables above take each shape's own; the rule and every comparison: "
              "docs/FINDINGS.md)"]
    return lines, spec["sources"]


def against_findings(shape):
    """The numbers of the findings that a comparison of this shape goes against by the paper's clock
    (docs/FINDINGS.md's rule)."""
    numbers = []
    for number, _, by_scale in paper_findings():
        sig, comparisons, *_ = by_scale.get("paper's clock", (0.0, []))
        if any(c.label.startswith(shape) and findings.judged(c, sig)[2] == "against" for c in comparisons if c):
            numbers.append(number)
    return numbers


def answer_differences(spec):
    """Each difference from the paper, with what was measured about its cause."""
    def cell(sources, **where):
        return beds_text(Cell(sources, **where).values())
    glued = ["results/paper_depth/glued"]
    tri = ["results/paper_depth/triangle"]
    sq_lo, sq_hi, sq_cells = first_rise(CLOCK_A5, "square", clock_sigma("square"))
    sq_rise = dict(sq_cells)[sq_hi]
    _, _, tri_cells = first_rise(CLOCK_A5, "triangle", clock_sigma("triangle"))
    tri_a3 = list(by_period(CLOCK_A3, intruder__shape="triangle", drive__amplitude=3.0).items())
    tri_against = against_findings("triangle")
    small = SMALL_TODAY
    scatter = clock_scatter()
    quiet, loud = min(SHAPES, key=lambda s: scatter[s].sigma), max(SHAPES, key=lambda s: scatter[s].sigma)
    lines = [
        f"- **The square's bracket, {bracket_text(sq_lo, sq_hi, sq_cells)} against the paper's {paper_observed('square')}: "
        f"{against_paper(sq_lo, sq_hi, 'square').split(': ', 1)[-1]}**: by the paper's clock it rises at T = {sq_hi:g}, "
        f"{beds_z_text(sq_rise, 'square')}, on each bed (" + ", ".join(f"{v:+.3f}" for v in sq_rise)
        + "). Cause not known. Tried without a change of sign (t = 100, one bed): the paper's glued intruder (T = 3: "
        f"{cell(glued, intruder__shape='square', drive__period=3.0)}). " + protocol_so_far("square", 3.0),
        f"- **The triangle does not rise** (the paper's Table 1: from T = {paper_observed('triangle')}; its text: its "
        f"triangle {paper_triangle_text()}): by the paper's clock, at A = 5, "
        + ", ".join(f"{beds_z_text(vs, 'triangle')} at T = {t:g}" for t, vs in tri_cells)
        + (", not rising at any period run" if all(z_of(vs, "triangle") < RESOLVED for _, vs in tri_cells) else "")
        + ("; at A = 3 (figure 2's periods, its scatter there not measured) "
           + ", ".join(f"{beds_text(vs)} at T = {t:g}" for t, vs in tri_a3)
           + (", each below zero" if all(mean(vs) < 0 for _, vs in tri_a3) else "") if tri_a3 else "")
        + ": the paper's text, not its Table 1"
        + (f" (by docs/FINDINGS.md's rule, against finding{'s' if len(tri_against) > 1 else ''} "
           + " and ".join(str(n) for n in tri_against) + ")" if tri_against else "")
        + ". Cause not known. Tried without a change of sign (t = 100, one bed "
        "each, T = 4; 6): "
        f"the paper's glued intruder ({cell(tri, intruder__shape='triangle', intruder__surface='glued', drive__period=4.0)}; "
        f"{cell(tri, intruder__shape='triangle', intruder__surface='glued', drive__period=6.0)}) and a random pour "
        f"({cell(tri, intruder__shape='triangle', bed__pour='random', drive__period=4.0)}; "
        f"{cell(tri, intruder__shape='triangle', bed__pour='random', drive__period=6.0)}): all sink. "
        + protocol_so_far("triangle", 5.0),
        "- **Where the mean turns positive** (the paper's own reading of T_rising, by the sign of the mean, without "
        "standard errors): " + crossings_sentence() + ".",
        "- **The small preset crosses late** (findings 2 and 7 there): its bed is 25 d deep, the paper's 105 d. At A = 5 "
        f"its disk still sinks at T = 3.5, {cell(small, intruder__shape='disk', drive__amplitude=5.0, drive__period=3.5, **SMALL_TODAY_WHERE)}, "
        f"where at the paper's depth it rises at T = 3, {cell(DEPTH_A5, intruder__shape='disk', drive__period=3.0)}; "
        "the two presets differ only in depth, so depth is the measured cause. The small preset is for trying things, "
        "not for the paper's numbers.",
        f"- **Not resolved is mostly scatter**: at t = 100 one bed tells V_y to about +-{depth_sigma():.3f} (one figure "
        "for every shape) and most cells have one bed, so differences between shapes (finding 4), amplitudes (3) and "
        f"frictions (6) stay within {RESOLVED:g} standard errors; by the paper's clock one bed tells it to "
        f"+-{scatter[quiet].sigma:.4f} ({short_name(quiet)}, {scatter[quiet].dof} dof) to +-{scatter[loud].sigma:.4f} "
        f"({short_name(loud)}, {scatter[loud].dof} dof), each shape's own, but only Table 1's periods and "
        "figure 2's (A = 3, T = 1 and 5) have run that long.",
    ]
    return lines, spec["sources"]


def readme_answer(spec):
    """The README's paragraph "Does it reproduce the paper?": the page above in a few lines."""
    agree, differ, unplaced, never = [], [], [], []
    scatter = clock_scatter()
    cells_all = []
    for shape in SHAPES:
        lo, hi, cells = first_rise(CLOCK_A5, shape, clock_sigma(shape))
        cells_all += cells
        verdict_text = against_paper(lo, hi, shape)
        name = short_name(shape)
        if verdict_text.startswith("**yes"):
            agree.append(f"{name} {bracket_text(lo, hi, cells)}")
        elif hi is None:
            never.append(f"the {name} does not rise at any period run (T = {cells[0][0]:g}-{cells[-1][0]:g}), where the "
                         f"paper's Table 1 has it rising from {paper_observed(shape)}"
                         + (f" and its text says it {paper_triangle_text()}" if shape == "triangle" else ""))
        elif verdict_text.startswith("**no"):
            differ.append(f"the {name} rises from {bracket_text(lo, hi, cells)} (paper: {paper_observed(shape)})")
        else:
            z = z_of(dict(cells)[hi], shape)
            note = student_note(z, shape)
            unplaced.append(f"the {name} rises already at T = {hi:g}, its shortest period run ({z:.1f} se"
                            + (f", {note}" if note else "") + f"; paper: {paper_observed(shape)})")
    sigmas = sorted(scatter[s].sigma for s in SHAPES)
    dofs = sorted(scatter[s].dof for s in SHAPES)
    # the verdicts of docs/FINDINGS.md's table, by its rule
    verdicts = [findings.finding_verdict(*by_scale.get("paper's clock", (0.0, []))) for _, _, by_scale in paper_findings()]
    text = (f"Partly. By the paper's clock (runs to t = 1000, V_y over t = 100-1000; {beds_range(cells_all)} beds a "
            f"period) at its depth in a 60 d box, each shape judged at {RESOLVED:g} standard errors of its own scatter "
            f"(one bed's sigma {sigmas[0]:.4f}-{sigmas[-1]:.4f}, {dofs[0]}-{dofs[-1]} degrees of freedom), Table 1's "
            f"bracket is the paper's for {len(agree)} of 5 shapes (" + ", ".join(agree) + "); "
            + "; ".join(differ + unplaced + never) + ". By the sign of the mean, as the paper reads it, "
            + crossings_sentence(rest_too=False) + ". " + paper_box_summary() + protocol_summary()
            + f"Left unexplained: {unmeasured(short=True)}. Of the seven findings by that clock (docs/FINDINGS.md's rule, one "
            f"sigma for every shape, {findings_clock_sigma():.3f}): "
            + ", ".join(f"{verdicts.count(v)} {v}" for v in findings.VERDICTS) + ". In full: "
            "[docs/VALIDATION.md](docs/VALIDATION.md#does-wiggle-reproduce-the-paper).")
    return textwrap.wrap(text, 104, break_on_hyphens=False, break_long_words=False), spec["sources"]


# The drive read as a velocity (docs/VALIDATION.md, figure 5's section): what its one bed a cell at
# t = 100 can say of a crossing at A = 5.
def drive_form_words(spec):
    """A sentence on the velocity reading at A = 5: its V_y per shape and period, each in standard
    errors of the t = 100 window's one sigma, and whether one bed tells where, or whether, it crosses."""
    sig = depth_sigma()
    parts, resolved = [], False
    for shape in ("disk", "square"):
        cells = list(by_period(["results/paper_depth/velocity"], intruder__shape=shape, drive__amplitude=5.0,
                               drive__form="velocity").items())
        if not cells:
            continue
        zs = [findings.z_from_zero(vs, sig) for _, vs in cells]
        resolved = resolved or any(abs(z) >= RESOLVED for z in zs)
        parts.append(f"the {shape} gives " + ", ".join(f"{mean(vs):+.3f}" for _, vs in cells)
                     + " at T = " + ", ".join(f"{t:g}" for t, _ in cells)
                     + f" ({beds_range(cells)} bed{'s' if beds_range(cells) != '1' else ''} each: "
                     + ", ".join(f"{z:+.1f}" for z in zs) + " se)")
    if not parts:
        return [], spec["sources"]
    text = ("At A = 5, read as a velocity, " + " and ".join(parts) + f", in standard errors of one bed's sigma at t = 100, "
            f"{sig:.3f} (docs/FINDINGS.md's at the paper's depth): "
            + (f"some are {RESOLVED:g} se or more from zero, as the table above shows." if resolved else
               f"none is {RESOLVED:g} se from zero, so one bed each does not tell whether, or where, either crosses "
               "over the periods run."))
    return textwrap.wrap(text, 100, break_on_hyphens=False, break_long_words=False), spec["sources"]


# The paper's own protocol (issue 51): the preset's differences from the paper's stated protocol,
# one at a time at t = 1000, for the two cells that disagree most with the paper (the square at T = 3
# rises where the paper's Table 1 has it not rising yet; the triangle at T = 5 sinks where the paper's
# rises), then all of them together in the preset's 60 d box and in the paper's own 300 d box.
# The paper's protocol in its own 300 x 195 d box, by its clock (configs/sweeps/paper_box_t1000.toml).
PAPER_BOX = ["results/paper_box/t1000"]
PROTOCOL_FOLDERS = ["results/paper_depth/mass_t1000", "results/paper_depth/factors_t1000"] + PAPER_BOX
PRESET_PROTOCOL = {"intruder.surface": "smooth", "bed.pour": "lattice", "intruder.mass_rule": "disk_area"}
PAPER_PROTOCOL = {"intruder.surface": "glued", "bed.pour": "random", "intruder.mass_rule": "glued_disk"}
# (what changes from the preset, in the table and in a sentence; its cases: folders and the keys that
# differ; paired: run on the baseline's own beds, so compared with the baseline's runs of the same seeds only)
PROTOCOL_ROWS = [
    ("none: the preset (baseline)", "the preset", T1000_BEDS, {}, False),
    ("the glued disk's mass, 9.88 (on the baseline's own bed)", "the glued disk's mass (9.88 against 25.66, same bed)",
     ["results/paper_depth/mass_t1000"], {"intruder.mass_rule": "glued_disk"}, True),
    ("the glued 0.5 d surface (new pour)", "the glued 0.5 d surface", ["results/paper_depth/factors_t1000"],
     {"intruder.surface": "glued"}, False),
    ("the random pour (new pour)", "the random pour", ["results/paper_depth/factors_t1000"], {"bed.pour": "random"}, False),
    ("all three: the paper's protocol in the 60 d box", "the paper's protocol in the 60 d box",
     ["results/paper_depth/factors_t1000"], PAPER_PROTOCOL, False),
    ("the paper's protocol in its own 300 d box", "the paper's protocol in its own 300 d box", PAPER_BOX,
     PAPER_PROTOCOL, False),
]
# shape, T, the paper's sign of V_y there
PROTOCOL_CELLS = [(shape, t, findings.paper_side(t, PAPER_RANGE[shape])) for shape, t in [("square", 3.0), ("triangle", 5.0)]]
# The box's width alone: the last row (the paper's protocol in its 300 d box) against the row before
# it (the same protocol in the 60 d box), said beside the last row's change from the preset.
BOX_ROW, BOX_AGAINST = len(PROTOCOL_ROWS) - 1, len(PROTOCOL_ROWS) - 2
BOX_ALONE = "the 300 d box alone (against the paper's protocol in the 60 d box)"
PROTOCOL_CELL_KEYS = [(shape, period) for shape, period, _ in PROTOCOL_CELLS]


def protocol_beds(folders, where):
    """{seed: V_y} of a protocol row's cell (only the folders committed so far)."""
    present = committed(folders)
    return {c.get("box.seed"): float(c.get("vy")) for c in beds(select(present, where), f"{present} {where}")}


def protocol_cell(shape, period):
    """The keys of one of PROTOCOL_CELLS' cases (A = 5)."""
    return {"intruder.shape": shape, "drive.amplitude": 5.0, "drive.period": period}


def row_where(row, shape, period):
    """The keys of a case of PROTOCOL_ROWS[row] in the cell (shape, T)."""
    return dict(PRESET_PROTOCOL, **PROTOCOL_ROWS[row][3], **protocol_cell(shape, period))


def unfinished(source):
    """The cases of a results folder that have not finished but whose trajectory so far is committed
    (a long case carried from session to session with its checkpoint)."""
    return [c for c in cases_of(source, finished=False) if os.path.exists(os.path.join(c.dir, "trajectory.csv"))]


OWN_SCATTER_WORDS = " of its own beds' scatter"  # after "by 2 standard errors", where a change is judged by it
SO_FAR_FROM = 200.0   # an unfinished case is shown once its window t = 100-t_now spans this much


def so_far(case):
    """(t of an unfinished case's last committed sample, its rate so far by the paper's rule over
    t = 100 to then, or None while that window spans less than SO_FAR_FROM)."""
    t_now = case.trajectory()[0][-1]
    return t_now, (chord(100.0, t_now)(case) if t_now - 100.0 >= SO_FAR_FROM else None)


def protocol_so_far_cell(row, shape, period):
    """A cell of PROTOCOL_ROWS[row] not finished yet whose case is on its way: its rate so far, by the
    paper's rule over t = 100 to its last committed sample, beside the baseline's over the same window
    (and, in the 300 d box's row, the 60 d box's: BOX_ALONE); "" when none."""
    compared = [(0, "the baseline")] + ([(BOX_AGAINST, "the 60 d box's")] if row == BOX_ROW else [])
    on_way = [c for f in committed(PROTOCOL_ROWS[row][2]) for c in unfinished(f)
              if all(c.get(k) == v for k, v in row_where(row, shape, period).items())]
    parts = []
    for c in on_way:
        t_now, rate = so_far(c)
        if rate is None:
            continue
        window = chord(100.0, t_now)
        beside = []
        for i, name in compared:
            keys = row_where(i, shape, period)
            done = beds(select(committed(PROTOCOL_ROWS[i][2]), keys), f"{name} {keys}")
            if done:
                beside.append(f"{name} {cell_text([window(b) for b in done])}")
        parts.append(f"not finished, t = {t_now:g} of 1000 so far: over t = 100-{t_now:g} {cell_text([rate])}, "
                     + ", ".join(beside))
    return "; ".join(parts)


def protocol_change(row, shape, period, paper_sign, sig, against=0):
    """One cell of PROTOCOL_ROWS[row]: (its V_y values, or [] when none is committed; the change from
    row `against` (the baseline unless said), its size in standard errors and which way it moves the
    cell), the change None for the compared row itself or while that row has no values."""
    def row_beds(i):
        return protocol_beds(PROTOCOL_ROWS[i][2], row_where(i, shape, period))
    beds_of_row = row_beds(row)
    values = list(beds_of_row.values())
    if not values or row == against:
        return values, None
    compared = row_beds(against)
    paired = PROTOCOL_ROWS[row][4]
    base = [v for seed, v in compared.items() if seed in beds_of_row] if paired else list(compared.values())
    if not base:
        return values, None
    comparison = findings.Comparison(shape, values, base, paper_sign)
    diff, z, _ = findings.judged(comparison, sig)
    caveat = own_scatter_caveat(comparison, z, sig)
    toward = {+1: "toward the paper", -1: "away from the paper", 0: "within the scatter"}[
        0 if caveat else findings.resolved_side(z)]
    return values, (diff, abs(z), toward, caveat)


def own_scatter_caveat(comparison, z, sig):
    """A change resolved on the scale's sigma whose sides' own beds (2 to OWN_SCATTER_BEDS - 1 of them,
    too few for judged() to count their scatter) scatter enough that by their largest standard
    deviation it would not be: the words that say so, else "". Such a change is shown within the
    scatter: a cell is never shown as better known than its own beds show, even before judged()
    counts them."""
    few = [(findings.sd(v), whose, len(v)) for v, whose in ((comparison.a, "its"), (comparison.b, "the compared row's"))
           if 2 <= len(v) < findings.OWN_SCATTER_BEDS]
    own, whose, n = max(few, default=(0.0, "", 0))
    if findings.resolved_side(z) == 0 or own <= sig:
        return ""
    z_own = findings.judged(comparison, own)[1]
    if findings.resolved_side(z_own) != 0:
        return ""
    return (f"{abs(z_own):.1f} se by {whose} {n} beds' own scatter, one bed's standard deviation {own:.4f} "
            f"against sigma {sig:.4f}")


def protocol_row(case):
    """(shape, T, the index of its PROTOCOL_ROWS row) of a case of one of the protocol block's cells,
    None for any other case of its folders."""
    cell = (case.get("intruder.shape"), case.get("drive.period"))
    if cell not in PROTOCOL_CELL_KEYS:
        return None
    for i, (_, _, folders, keys, _) in enumerate(PROTOCOL_ROWS):
        if case.source in folders and all(case.get(k) == v for k, v in dict(PRESET_PROTOCOL, **keys).items()):
            return cell + (i,)
    return None


def box_alone_change(shape, period, paper_sign, sig):
    """BOX_ALONE's change in one cell, as protocol_change gives it; None while either row has no value."""
    return protocol_change(BOX_ROW, shape, period, paper_sign, sig, against=BOX_AGAINST)[1]


def change_text(change):
    diff, z, toward, caveat = change
    return f"{diff:+.4f} ({z:.1f} se, {toward}" + (f": {caveat}" if caveat else "") + ")"


SIDE = {+1: "rising", -1: "sinking", 0: "level within the scatter"}   # a cell's side of zero
# The paper's Table 1 at a period (findings.paper_side): rising at or above its observed range, not
# rising at or below it (its bracket says where rising starts, not that the intruder sinks below it)
PAPER_SIDE = {+1: "rising", -1: "not rising"}


def side(values, sig):
    """A cell's side of zero by the findings' rule: +1 rising, -1 sinking, 0 within the scatter."""
    return findings.resolved_side(findings.z_from_zero(values, sig))


def on_paper_side(values, sig, paper_sign):
    """Whether a cell says what the paper's Table 1 says at its period: rising where the paper has it
    rising (+1), not rising (sinking or level within the scatter) where the paper has it not rising (-1)."""
    return (side(values, sig) > 0) == (paper_sign > 0)


def paper_reading(values, shape, period):
    """'rising, where the paper has it not rising', 'not rising, as the paper': a cell of the paper's clock
    read against the paper's Table 1 at its period, by its shape's sigma; inside the paper's range,
    where the paper does not say, the cell's side of zero."""
    paper = findings.paper_side(period, PAPER_RANGE[shape])
    sig = clock_sigma(shape)
    if paper == 0:
        return f"{SIDE[side(values, sig)]}, inside the paper's range"
    mine = "rising" if side(values, sig) > 0 else "not rising"
    return f"{mine}, " + ("as the paper" if on_paper_side(values, sig, paper) else f"where the paper has it {PAPER_SIDE[paper]}")


def paper_box_cases(shape):
    """{T: the finished cases (beds)} of a shape at A = 5 in the paper's box."""
    cases = {}
    for c in select(committed(PAPER_BOX), {"intruder.shape": shape, "drive.amplitude": 5.0}):
        cases.setdefault(c.get("drive.period"), []).append(c)
    return {t: beds(cases[t], f"{PAPER_BOX} {shape} {t:g}") for t in sorted(cases)}


def paper_box_cells(shape):
    """({T: the beds' V_y} of a shape's finished cases in the paper's box, [its unfinished cases whose
    trajectory so far is committed])."""
    box = committed(PAPER_BOX)
    return (by_period(box, intruder__shape=shape, drive__amplitude=5.0),
            [c for f in box for c in unfinished(f) if c.get("intruder.shape") == shape and c.get("drive.amplitude") == 5.0])


# How a run's rate holds through the paper's window: V_y by the paper's rule over its halves
HALVES = ((100.0, 500.0), (500.0, 1000.0))
STALL = 4.0   # the second half's rate under 1/STALL of the first's: "then stalls"
PAPER_BOX_FIGURE = "`wiggle plot results/paper_box/t1000 --out DIR` draws the trajectories, DIR/trajectories.png"


def halves_text():
    return " and ".join(f"t = {t0:g}-{t1:g}" for t0, t1 in HALVES)


def course(cases):
    """(mean V_y over the first half of the window, over the second) of a cell's beds."""
    return tuple(mean([chord(t0, t1)(c) for c in cases]) for t0, t1 in HALVES)


def course_words(first, second):
    """How the second half's rate follows the first's: 'then stalls' (under 1/STALL of it), 'then turns
    back' (the other sign), 'then faster', 'then slower'."""
    if abs(second) < abs(first) / STALL:
        return "then stalls"
    if (second > 0) != (first > 0):
        return "then turns back"
    return "then faster" if abs(second) > abs(first) else "then slower"


def courses_text(shape, by_t, only=None):
    """'the square climbs over t = 100-500 (+0.070 at T = 3, +0.114 at T = 4), then stalls over
    t = 500-1000 (+0.008, +0.004)': a shape's cells ({T: cases}) by the halves of the window, periods
    that go alike in one clause; only: the words to keep (None: all)."""
    groups = {}
    for t, cases in by_t.items():
        first, second = course(cases)
        words = ("climbs" if first > 0 else "sinks", course_words(first, second))
        if only is None or words[1] in only:
            groups.setdefault(words, []).append((t, first, second, len(cases)))
    (t0, t1), (t2, t3) = HALVES
    return [f"the {shape} {verb} over t = {t0:g}-{t1:g} (" + ", ".join(f"{a:+.3f} at T = {t:g}" for t, a, _, _ in runs)
            + f"), {words} over t = {t2:g}-{t3:g} (" + ", ".join(f"{b:+.3f}" for _, _, b, _ in runs) + ")"
            for (verb, words), runs in groups.items()]


def answer_paper_box(spec):
    """Table 1 in the paper's own box: each period run per shape read against the paper's Table 1, its
    rate over the halves of the window, the bracket by the answer's rule and how it stands against the
    paper's range, beside the 60 d preset's bracket by the same clock."""
    head = ["shape", "paper, observed", "60 d preset, paper's clock", "the paper's box: V_y at each period run",
            f"the paper's box: V_y over {halves_text()}", "the paper's box: bracket", "the paper's range?"]
    lines = ["| " + " | ".join(head) + " |", "|" + "---|" * len(head)]
    shown = []
    for shape in SHAPES:
        done, on_way = paper_box_cells(shape)
        if not done and not on_way:
            continue
        shown.append(shape)
        sig = clock_sigma(shape)
        periods_run = [(t, f"{beds_z_text(vs, shape)}, {paper_reading(vs, shape, t)}") for t, vs in done.items()]
        for c in on_way:
            t_now, rate = so_far(c)
            periods_run.append((c.get("drive.period"), f"not finished, t = {t_now:g} of {c.get('run.duration'):g}"
                                + (f" (over t = 100-{t_now:g} {rate:+.3f} so far)" if rate is not None else "")))
        halves = "; ".join(f"T = {t:g}: " + ", ".join(f"{v:+.3f}" for v in course(cases))
                           for t, cases in paper_box_cases(shape).items())
        cells = list(done.items())
        lo, hi = findings.first_rise(cells, sig)
        plo, phi, pcells = first_rise(CLOCK_A5, shape, sig)
        lines.append("| " + " | ".join([SHAPE_NAMES[shape], paper_observed(shape), bracket_text(plo, phi, pcells),
                                          "; ".join(f"T = {t:g}: {text}" for t, text in sorted(periods_run)), halves,
                                          bracket_text(lo, hi, cells) if cells else "none finished yet",
                                          against_paper(lo, hi, shape) if cells else "not judged yet"]) + " |")
    lines += ["", f"(T in sqrt(d/g); A = 5 d; one bed per shape, poured around it. V_y over t = 100-1000 of runs to "
              "t = 1000 in the paper's 300 x 195 d box by its protocol (configs/paper.toml), judged as the answer's "
              f"Table 1 above: a period rises when its V_y is >= {RESOLVED:g} sigma above zero (se: its standard errors "
              "from zero), sigma " + scatter_words(shown) + "; the 300 d box's own is "
              "not measured (one bed per cell). The paper's side at a period: not rising at or below its observed range, "
              f"rising at or above it. The halves: V_y by the paper's rule over {halves_text()} ({PAPER_BOX_FIGURE}). "
              "A case not finished is shown by its rate so far over t = 100 to its last committed sample once that "
              f"spans {SO_FAR_FROM:g}, and not judged)"]
    return lines, committed(PAPER_BOX) + committed(CLOCK_SCATTER)


def paper_box_summary():
    """What the paper's protocol in its own box gives so far, cell by cell, against the paper's Table 1,
    and where a rate stalls or turns within the window, in sentences for the README ("" before any of
    its cases has finished)."""
    parts = [f"the {shape} at T = {t:g} {beds_z_text(vs, shape)}: {paper_reading(vs, shape, t)}"
             for shape in SHAPES for t, vs in paper_box_cells(shape)[0].items()]
    if not parts:
        return ""
    turns = [text for shape in SHAPES for text in courses_text(shape, paper_box_cases(shape), ("then stalls", "then turns back"))]
    short = PROTOCOL_ROWS[BOX_ROW][1]
    return (short[0].upper() + short[1:] + " (one bed a cell, judged by the 60 d box's scatter) leaves " + "; ".join(parts)
            + ". " + (f"There {'; '.join(turns)}: its V_y over t = 100-1000 averages the two ({PAPER_BOX_FIGURE}). "
                      if turns else ""))


def protocol_summary():
    """The protocol table so far in a sentence for the README ("" before any of its cells has a case)."""
    measured, toward, own_scatter = [], [], []
    for row in range(1, len(PROTOCOL_ROWS)):
        name = PROTOCOL_ROWS[row][1].split(" (")[0]
        for shape, period, paper_sign in PROTOCOL_CELLS:
            sig = clock_sigma(shape)
            values, change = protocol_change(row, shape, period, paper_sign, sig)
            if values:
                measured.append((name, len(values)))
                said = [(name, change)]
                if row == BOX_ROW:
                    said.append((BOX_ALONE.split(" (")[0], box_alone_change(shape, period, paper_sign, sig)))
                # The 300 d box has one bed a cell: its changes are counted in the 60 d box's scatter.
                scale = " of the 60 d box's scatter, the 300 d box's own not measured" if row == BOX_ROW else ""
                toward += [f"{who} moves the {shape} at T = {period:g} {c[2]} ({c[1]:.1f} se{scale})"
                           for who, c in said if c and c[2] != "within the scatter"]
                own_scatter += [f"{who} moves the {shape} at T = {period:g} by {c[1]:.1f} se of sigma, {c[3]}"
                                for who, c in said if c and c[3]]
    if not measured:
        return ""
    names = list(dict.fromkeys(name for name, _ in measured))
    counts = sorted({n for _, n in measured})
    beds_each = f"{counts[0]}" if len(counts) == 1 else f"{counts[0]}-{counts[-1]}"
    cells = len(PROTOCOL_CELLS) * (len(PROTOCOL_ROWS) - 1)
    on = " and ".join(f"the {shape} at T = {period:g}" for shape, period, _ in PROTOCOL_CELLS)
    moved = "; ".join(toward) if toward else (f"none moves a cell by {RESOLVED:g} standard errors"
                                              + (OWN_SCATTER_WORDS if own_scatter else ""))
    if own_scatter:
        moved += f" ({'; '.join(own_scatter)})"
    return (f"Of the preset's differences from the paper's stated protocol, measured so far by that clock on {on} "
            f"({', '.join(names)}: {len(measured)} of {cells} cells, {beds_each} bed{'s' if counts[-1] > 1 else ''} "
            f"each), {moved}. ")


def protocol_cells_text():
    """'the square not rising at T = 3 (the lower end of its 3-4) and ...': what the paper's Table 1 says
    at the protocol block's cells."""
    def end(shape, period):
        lo, hi = PAPER_RANGE[shape]
        return "the lower end of" if period == lo else "the upper end of" if period == hi else "beside"
    return " and ".join(f"the {shape} {PAPER_SIDE[sign]} at T = {period:g} ({end(shape, period)} its "
                        f"{paper_observed(shape)})" for shape, period, sign in PROTOCOL_CELLS)


def answer_protocol(spec):
    """The factor table: each row's V_y per cell, its change from the baseline in standard errors of
    the paper's clock (one bed's sigma of that shape there), and whether it moves the cell toward the
    paper's side."""
    head = "| what changes | " + " | ".join(f"{s}, A = 5, T = {t:g}: V_y; change (se)" for s, t, _ in PROTOCOL_CELLS) + " |"
    lines = [head, "|---|" + "---|" * len(PROTOCOL_CELLS)]
    for row, (label, *_) in enumerate(PROTOCOL_ROWS):
        cells = []
        for shape, period, paper_sign in PROTOCOL_CELLS:
            sig = clock_sigma(shape)
            values, change = protocol_change(row, shape, period, paper_sign, sig)
            box = box_alone_change(shape, period, paper_sign, sig) if row == BOX_ROW else None
            if not values:
                cells.append(protocol_so_far_cell(row, shape, period) or "not run yet")
            elif change is None:
                cells.append(cell_text(values))
            else:
                cells.append(f"{cell_text(values)}; {change_text(change)}"
                             + (f"; the box alone: {change_text(box)}" if box else ""))
        lines.append(f"| {label} | " + " | ".join(cells) + " |")
    few = findings.OWN_SCATTER_BEDS - 1
    few_beds = f"2 to {few} beds" if few > 2 else "2 beds"
    shapes = list(dict.fromkeys(s for s, _, _ in PROTOCOL_CELLS))
    lines += ["", f"(V_y over t = 100-1000 of runs to t = 1000, A = 5 d. The paper's Table 1 has {protocol_cells_text()}. "
              f"A change is the row's mean minus the baseline's, in standard errors se = sigma sqrt(1/n_row + 1/n_baseline), "
              "sigma " + scatter_words(shapes) + ". The mass's change is against the baseline's run on the same bed, "
              "with the same sigma, which its pairing is expected to make smaller (not measured); the 300 d box's "
              "sigma is taken as the 60 d box's (one bed per cell there, so not measured); the box alone is the "
              "300 d box's row against the 60 d box's row of the same protocol; a change moves the "
              f"cell toward the paper's side when >= {RESOLVED:g} se that way, also by the own standard deviation of "
              f"a side of {few_beds} where that is larger than sigma (from "
              f"{findings.OWN_SCATTER_BEDS} beds on, a side's own scatter counts in its se as everywhere on this page). "
              f"A case not finished yet is shown by the paper's rule over t = 100 to its last committed sample, beside "
              f"the baseline's over the same window (and the 60 d box's, in the 300 d box's row), once that window spans "
              f"{SO_FAR_FROM:g}: a rate so far, not judged)"]
    return lines, committed(PROTOCOL_FOLDERS + T1000_BEDS)


def protocol_so_far(shape, period):
    """What the one-factor screen of the protocol block has measured of one cell so far, in a sentence."""
    sig = clock_sigma(shape)
    paper_sign = next(sign for s, t, sign in PROTOCOL_CELLS if (s, t) == (shape, period))
    done, left = [], []
    for row in range(1, len(PROTOCOL_ROWS)):
        short = PROTOCOL_ROWS[row][1]
        values, change = protocol_change(row, shape, period, paper_sign, sig)
        if values:
            box = box_alone_change(shape, period, paper_sign, sig) if row == BOX_ROW else None
            compared = f"a change of {change_text(change)}" if change else "no baseline on its beds yet"
            done.append(f"{short}: {cell_text(values)}, {compared}"
                        + (f", of which {BOX_ALONE} {change_text(box)}" if box else ""))
        else:
            left.append(short)
    sentences = []
    if done:
        sentences.append(f"By the paper's clock, one factor at a time (the protocol block below; se of the {shape}'s "
                         f"sigma, {scatter_text(shape)}): " + "; ".join(done) + ".")
    if left:
        sentences.append("Not yet measured at t = 1000: " + ", ".join(left) + " (issue 51).")
    return " ".join(sentences)


# What is left when no measured factor accounts for a difference: the intruder's coupling to its grains
# as the paper's LAMMPS body had it (issue 79, configs/sweeps/paper_depth_coupling_t1000.toml, its
# results to come in COUPLING), what the paper leaves open and the protocol block did not vary
# (docs/PHYSICS.md, "The paper's stated protocol"), and the paper's own scatter.
COUPLING = ["results/paper_depth/coupling_t1000"]
UNMEASURED = ("what the paper leaves open and the screen did not vary (the grains' diameter distribution, the "
              "pour's batch height and fill fraction), and the paper's own scatter, which it does not report (no "
              "repeated beds, no error bars)")


UNMEASURED_SHORT = ("what the paper leaves open (the grains' diameter distribution, the pour's batch height and fill "
                    "fraction) and its own scatter (no repeated beds, no error bars)")


# The coupling screen (issue 79): each factor on the factor screen's beds of the paper's protocol in the
# 60 d box, paired bed by bed with that protocol's own run there (its `*_paper` cases; the square at
# T = 4, the control, has its baseline in COUPLING).
COUPLING_CELLS = [("square", 3.0), ("triangle", 5.0), ("square", 4.0)]
COUPLING_BASE = dict(PAPER_PROTOCOL, **{"intruder.contact_mass": "body", "intruder.rotation": "locked",
                                        "drive.form": "displacement"})
COUPLING_ROWS = [('the atoms\' mass in the contacts (intruder.contact_mass = "atom")', {"intruder.contact_mass": "atom"}),
                 ('the lattice body (intruder.surface = "lattice", on the same bed)', {"intruder.surface": "lattice"}),
                 ('turning (intruder.rotation = "free")', {"intruder.rotation": "free"}),
                 ('the drive read as a velocity (drive.form = "velocity")', {"drive.form": "velocity"})]


def coupling_beds(shape, period, changes):
    """{seed: V_y} of the coupling screen's cell with `changes` from the paper's protocol (none: its baseline)."""
    where = dict(COUPLING_BASE, **changes, **{"intruder.shape": shape, "drive.period": period, "drive.amplitude": 5.0,
                                              "box.width": 60.0})
    return protocol_beds(COUPLING + ["results/paper_depth/factors_t1000"], where)


def coupling_change(shape, period, changes):
    """(change, z, which way, the factor's short name, the cell) of a coupling row in one cell, over the beds it
    shares with the baseline; None while there are none."""
    values, base = coupling_beds(shape, period, changes), coupling_beds(shape, period, {})
    paired = sorted(set(values) & set(base))
    if not paired:
        return None
    paper_sign = findings.paper_side(period, PAPER_RANGE[shape])
    comparison = findings.Comparison(shape, [values[b] for b in paired], [base[b] for b in paired], paper_sign)
    diff, z, _ = findings.judged(comparison, clock_sigma(shape))
    toward = {+1: "toward the paper", -1: "away from the paper", 0: "within the scatter"}[findings.resolved_side(z)]
    name = next(label.split(" (")[0] for label, c in COUPLING_ROWS if c == changes)
    return diff, z, toward, name, f"the {shape} at T = {period:g}", len(paired)


def answer_coupling(spec):
    """The coupling screen: each factor's V_y per bed and its change from the paper's protocol on the
    same beds, in standard errors of the shape's sigma by the paper's clock, and which way it moves the
    cell against the paper's side there."""
    head = "| what changes | " + " | ".join(f"{s}, A = 5, T = {t:g}: V_y; change (se)" for s, t in COUPLING_CELLS) + " |"
    lines = [head, "|---|" + "---|" * len(COUPLING_CELLS)]
    rows = [("none: the paper's protocol in the 60 d box (baseline)", {})] + COUPLING_ROWS
    for label, changes in rows:
        cells = []
        for shape, period in COUPLING_CELLS:
            values = coupling_beds(shape, period, changes)
            if not values:
                cells.append("not run yet")
                continue
            each = ", ".join(f"{v:+.4f} (bed {seed:g})" for seed, v in sorted(values.items()))
            change = coupling_change(shape, period, changes) if changes else None
            if not change:
                cells.append(each)
                continue
            diff, z, toward, _, _, paired = change
            cells.append(f"{each}; {diff:+.4f} ({abs(z):.1f} se, {toward}; {paired} bed{'s' if paired > 1 else ''} paired)")
        lines.append(f"| {label} | " + " | ".join(cells) + " |")
    shapes = list(dict.fromkeys(s for s, _ in COUPLING_CELLS))
    lines += ["", "(V_y over t = 100-1000 of runs to t = 1000, A = 5 d, on the factor screen's beds of the paper's "
              "protocol in the 60 d box (random pour, glued 0.5 d shell, the glued disk's mass 9.88; bed = box.seed); "
              "configs/sweeps/paper_depth_coupling_t1000.toml. The paper's side: not rising at T = 3 for the square "
              "(the lower end of its 3-4), rising at T = 4; rising at T = 5 for the triangle (the upper end of its 4-5). "
              "A change is the row's mean minus the baseline's over the beds both have, in standard errors se = sigma "
              "sqrt(1/n + 1/n), sigma " + scatter_words(shapes) + ". The pairing on one bed is expected to make a "
              f"change's own scatter smaller than that (not measured). A change moves the cell toward the paper's side "
              f"when >= {RESOLVED:g} se that way)"]
    return lines, committed(COUPLING + ["results/paper_depth/factors_t1000"])


def unmeasured(short=False):
    """What is left unexplained, in words: the coupling (as far as its screen has gone), then UNMEASURED
    (short: UNMEASURED_SHORT)."""
    done = [c for f in committed(COUPLING) for c in load(f)]
    if not done:
        status = "its screen, configs/sweeps/paper_depth_coupling_t1000.toml, being run, no results committed yet"
    else:
        changes = [coupling_change(shape, period, changes) for _, changes in COUPLING_ROWS
                   for shape, period in COUPLING_CELLS]
        changes = [c for c in changes if c]
        moved = [c for c in changes if c[2] != "within the scatter"]
        beds_each = sorted({c[5] for c in changes}) or [0]
        on = f"{beds_each[0]}" + (f"-{beds_each[-1]}" if beds_each[-1] > beds_each[0] else "")
        status = (f"its screen being run, {len(changes)} change{'s' if len(changes) > 1 else ''} measured so far, on "
                  f"{on} bed{'s' if beds_each[-1] > 1 else ''} each: " + ("none moves a cell by 2 standard errors so far" if not moved else
                                                "; ".join(f"the {c[3]} moves {c[4]} {c[2]}" for c in moved))
                  + "; docs/VALIDATION.md, \"The intruder's coupling\"")
    if short:
        return f"how the paper's glued LAMMPS body met its grains ({status}), " + UNMEASURED_SHORT
    return ("how the paper's glued LAMMPS body met its grains (its atoms' masses in the contacts' damping, a body "
            f"built on a lattice, its rotation; {status}), " + UNMEASURED)


def factor_changes(shape, period, paper_sign, sig):
    """([(what changed, its change as protocol_change gives it)] of every protocol row measured in one
    cell, the box alone beside the 300 d box's row; [the rows not measured there yet])."""
    changes, left = [], []
    for row in range(1, len(PROTOCOL_ROWS)):
        name = PROTOCOL_ROWS[row][1]
        change = protocol_change(row, shape, period, paper_sign, sig)[1]
        if not change:
            left.append(name)
            continue
        changes.append((name, change))
        box = box_alone_change(shape, period, paper_sign, sig) if row == BOX_ROW else None
        if box:
            changes.append((BOX_ALONE, box))
    return changes, left


def factors_text(shape, period, paper_sign, sig, box_values):
    """What the protocol block measured in one of its cells, and what is left of the difference from the
    paper there, in sentences; box_values: the paper's box's V_y in the cell ([] while not finished)."""
    changes, left = factor_changes(shape, period, paper_sign, sig)
    base = list(protocol_beds(PROTOCOL_ROWS[0][2], row_where(0, shape, period)).values())
    text = (f"At T = {period:g}, where the paper has it {PAPER_SIDE[paper_sign]}, the preset gives {beds_z_text(base, shape)}; "
            "changed one at a time and together, " + "; ".join(f"{name} {change_text(c)}" for name, c in changes) + ". ")
    if left:
        text += "Not measured there yet: " + ", ".join(left) + ". "
    moved = [f"{name}, {c[2]}" for name, c in changes if c[2] != "within the scatter"]
    toward = [name for name, c in changes if c[2] == "toward the paper"]
    if moved:
        text += f"Resolved by {RESOLVED:g} standard errors: " + "; ".join(moved) + ". "
    elif changes:
        # as the README's sentence: a change shown within its own beds' scatter was >= 2 se of sigma
        own_scatter = any(c[3] for _, c in changes)
        text += (f"No measured factor moves it by {RESOLVED:g} standard errors"
                 + (OWN_SCATTER_WORDS if own_scatter else "") + ". ")
    if box_values and not on_paper_side(box_values, sig, paper_sign):
        text += ("So " + ("none" if not toward else "not all") + " of the difference is accounted for: what is left "
                 f"is {'all of it' if not toward else 'the rest'}: {unmeasured()}.")
    elif box_values:
        text += "In the paper's box by its protocol the cell is on the paper's side."
    return text


def answer_per_shape(spec):
    """Item 4 of issue 51 per shape run in the paper's box: does the paper's own protocol give the
    paper's Table 1 bracket; if not, what each measured factor moved at the cell that disagrees, and
    what is left; and how its rates hold through the window."""
    lines, shown = [], []
    for shape in SHAPES:
        done, on_way = paper_box_cells(shape)
        if not done and not on_way:
            continue
        shown.append(shape)
        sig = clock_sigma(shape)
        runs = [(t, f"T = {t:g} {beds_z_text(vs, shape)}, {paper_reading(vs, shape, t)}") for t, vs in done.items()]
        runs += [(c.get("drive.period"), f"T = {c.get('drive.period'):g} not finished "
                  f"(t = {so_far(c)[0]:g} of {c.get('run.duration'):g})") for c in on_way]
        text = (f"- **{SHAPE_NAMES[shape]}**, the paper's T_rising {paper_observed(shape)}: in the paper's own protocol "
                "and box, by its clock, " + "; ".join(said for _, said in sorted(runs)) + ". ")
        cells = list(done.items())
        if on_way:
            text += "Not answered yet: a period is still running. "
        elif cells:
            lo, hi = findings.first_rise(cells, sig)
            plo, phi, pcells = first_rise(CLOCK_A5, shape, sig)
            verdict = against_paper(lo, hi, shape)
            text += (f"Its bracket by the rule of the Table 1 below, {bracket_text(lo, hi, cells)}; {verdict} (the 60 d "
                     f"preset's by the same clock, {bracket_text(plo, phi, pcells)}). ")
            text += ("The paper's protocol, as far as the paper states it, gives the paper's bracket. "
                     if verdict.startswith("**yes") else
                     "**The paper's protocol, as far as the paper states it, does not give the paper's bracket.** ")
        box_cases = paper_box_cases(shape)
        if box_cases:
            preset = {t: beds(select(T1000_BEDS, {"intruder.shape": shape, "drive.amplitude": 5.0, "drive.period": t}),
                              f"{T1000_BEDS} {shape} {t:g}") for t in box_cases}
            preset = {t: cs for t, cs in preset.items() if cs}
            text += ("Through the window: " + "; ".join(courses_text(shape, box_cases))
                     + (" (the 60 d preset by the same halves: " + "; ".join(
                         f"T = {t:g} " + ", then ".join(f"{v:+.3f}" for v in course(cs)) + f" ({len(cs)} bed"
                         + ("s" if len(cs) > 1 else "") + ")" for t, cs in preset.items()) + ")" if preset else "")
                     + f"; {PAPER_BOX_FIGURE}. ")
        text += "".join(factors_text(shape, period, paper_sign, sig, done.get(period, []))
                        for s, period, paper_sign in PROTOCOL_CELLS if s == shape)
        lines.append(text.rstrip())
    lines += ["", "(A = 5 d; one bed per cell in the paper's box, judged as the Table 1 below (se: standard errors from "
              "zero, or of a change) with sigma " + scatter_words(shown)
              + f"; the halves: V_y by the paper's rule over {halves_text()}; the changes are the protocol block's "
              "below, where each case and its beds are listed)"]
    return lines, committed(PROTOCOL_FOLDERS + T1000_BEDS)


ANSWER_SOURCES = FINDING_SOURCES + ["results/paper_depth/glued", "results/paper_depth/triangle"] + PROTOCOL_FOLDERS
TABLES += [
    {"name": "answer_table1", "kind": answer_table1, "sources": CLOCK_SCATTER + DEPTH_A5},
    {"name": "answer_findings", "kind": answer_findings, "sources": FINDING_SOURCES},
    {"name": "answer_differences", "kind": answer_differences, "sources": ANSWER_SOURCES},
    {"name": "answer_protocol", "kind": answer_protocol, "sources": PROTOCOL_FOLDERS + T1000_BEDS},
    {"name": "answer_coupling", "kind": answer_coupling, "sources": COUPLING + ["results/paper_depth/factors_t1000"]},
    {"name": "answer_paper_box", "kind": answer_paper_box, "sources": PAPER_BOX + CLOCK_SCATTER},
    {"name": "answer_per_shape", "kind": answer_per_shape, "sources": PROTOCOL_FOLDERS + T1000_BEDS},
    {"name": "readme_answer", "kind": readme_answer, "sources": CLOCK_A5 + PROTOCOL_FOLDERS, "bare": True},
    {"name": "depth_drive_form_words", "kind": drive_form_words, "sources": ["results/paper_depth/velocity"], "bare": True},
    {"name": "boundaries", "kind": boundary_table, "sources": [b[0] for b in BOUNDARIES]},
    # The protocol block's cases in the thirds of the paper's window, as depth_t1000_windows the preset's
    {"name": "protocol_windows", "kind": windows, "sources": T1000_BEDS + PROTOCOL_FOLDERS,
     "where": {"drive.amplitude": 5.0}, "row": protocol_row,
     "row_sort": lambda r: (PROTOCOL_CELL_KEYS.index(r[:2]), r[2]),
     "row_head": ["shape", "T", "what changes"],
     "row_label": lambda r: (r[0], f"{r[1]:g}", PROTOCOL_ROWS[r[2]][1]), "windows": T1000_WINDOWS},
]

DOCUMENTS = ["docs/VALIDATION.md", "docs/FINDINGS.md", "docs/PERFORMANCE.md", "README.md",
             "results/paper_depth/box/README.md", "results/paper_depth/fig5/README.md",
             "results/paper_depth/table1_t1000/README.md", "results/paper_depth/runlength_t300/README.md"]


def render(spec):
    """The table's lines, then the line that names its sources."""
    lines, sources = spec["kind"](spec)
    if spec.get("bare"):   # prose in a document that names its source itself
        return lines
    return lines + ["", "(made by `tools/study/vy_tables.py` from " + ", ".join(sources)
                    + "; a cell is one bed's V_y, or the mean +- standard error of the mean over the beds it counts)"]


def run(check):
    """Regenerate (or, with check, compare) every document; the problems, one line each."""
    tables = {spec["name"]: render(spec) for spec in TABLES}
    return marked.rewrite(ROOT, DOCUMENTS, tables, "vy_tables", check)


def main():
    args = sys.argv[1:]
    if args not in ([], ["--check"]):
        sys.exit("usage: tools/study/vy_tables.py [--check]")
    try:
        problems = run(check=args == ["--check"])
    except (OSError, KeyError, ValueError) as e:
        problems = [f"{type(e).__name__}: {e}"]
    for p in problems:
        print(p)
    if args:
        print(f"vy_tables: {len(problems)} differences between the documents' tables and results/")
    sys.exit(1 if problems else 0)


if __name__ == "__main__":
    main()
