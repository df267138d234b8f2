"""The committed results as the study's blocks read them (results/, and the one small-preset
results.csv under study/figures/): a finished case and its files, the beds of a cell, the study's
folders, and a cell as text. Shared by every module that makes the documents' blocks
(study/tools/vy_tables.py lists them); no statistics here, those are findings.py's.

Cases of one cell that differ only in their bed (box.seed) are beds of that cell (beds()); the same
case in two folders (same seed and state hash) counts once; two different runs of one cell on the
same bed are an error. A case's key is its results.csv column when the sweep varied it, else the
value in the case's config.toml (every key, as the run resolved it).
"""
import csv
import functools
import json
import os
import tomllib

import findings
from findings import mean, stats

ROOT = os.path.dirname(os.path.dirname(os.path.dirname(os.path.abspath(__file__))))

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

    def bed_key(self):
        """The key of the bed the case ran on (summary.json's bed_key): two cases ran on the same bed when
        their keys are equal, whatever their seeds."""
        with open(os.path.join(self.dir, "summary.json")) as f:
            return json.load(f)["bed_key"]

    def pours_own_bed(self):
        """Whether the case poured its own bed, rather than ran on a committed one (bed.file)."""
        try:
            return not self.get("bed.file")
        except KeyError:
            return True

    def trajectory(self):
        """(t, y) of trajectory.csv."""
        if self._trajectory is None:
            with open(os.path.join(self.dir, "trajectory.csv"), newline="") as f:
                rows = [(float(r["t"]), float(r["y"])) for r in csv.DictReader(f)]
            self._trajectory = [r[0] for r in rows], [r[1] for r in rows]
        return self._trajectory

    def turn(self):
        """(t, angle in radians, counter-clockwise) of trajectory.csv: the columns a turning intruder
        (intruder.rotation = "free") records; ValueError for a case without them."""
        with open(os.path.join(self.dir, "trajectory.csv"), newline="") as f:
            rows = csv.DictReader(f)
            if "angle" not in (rows.fieldnames or []):
                raise ValueError(f"{self.source}: case {self.row['case']} records no angle (its intruder does not turn)")
            pairs = [(float(r["t"]), float(r["angle"])) for r in rows]
        return [t for t, _ in pairs], [a for _, a in pairs]

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


def unfinished(source):
    """The cases of a results folder that have not finished but whose trajectory so far is committed
    (a long case carried from session to session with its checkpoint)."""
    return [c for c in cases_of(source, finished=False) if os.path.exists(os.path.join(c.dir, "trajectory.csv"))]


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
        return findings.least_squares_slope([t for t, _ in pairs], [y for _, y in pairs])
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
        self.mean, self.whole, self.half, self.half_peak, self.rest = findings.phase_harmonics(centres, self.bins)


def value_of(case, value):
    return value(case) if callable(value) else float(case.get(value))


WINDOW_FROM = 100.0   # the paper's V_y window: from t = 100 to the run's end
SO_FAR_FROM = 200.0   # an unfinished case is shown once its window t = 100-t_now spans this much


def so_far(case):
    """(t of an unfinished case's last committed sample, its rate so far by the paper's rule over
    t = 100 to then, or None while that window spans less than SO_FAR_FROM)."""
    t_now = case.trajectory()[0][-1]
    return t_now, (chord(WINDOW_FROM, t_now)(case) if t_now - WINDOW_FROM >= SO_FAR_FROM else None)


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


def key_of(case, key):
    return key(case) if callable(key) else case.get(key)


def select(sources, where):
    """The finished cases of these sources whose keys have the values `where` gives."""
    return [c for source in sources for c in load(source) if all(key_of(c, k) == v for k, v in where.items())]


class Cell:
    """The beds of one case: `sources` (folders), `where` (key: value)."""

    def __init__(self, sources, **where):
        self.sources, self.where = sources, {k.replace("__", "."): v for k, v in where.items()}

    def values(self):
        cases = select(self.sources, self.where)
        return [float(c.get("vy")) for c in beds(cases, f"{self.sources} {self.where}")]


def periods(sources, **where):
    """The periods at which a cell of these sources and filter has results, in order."""
    return sorted({c.get("drive.period") for c in select(sources, Cell(sources, **where).where)})


def by_period(sources, **where):
    """{T: the beds' V_y} at each period at which a cell of these sources and filter has results."""
    return {t: Cell(sources, drive__period=t, **where).values() for t in periods(sources, **where)}


# ---- a cell and a table as text

def row_line(cells):
    """A Markdown table row of these cells (text)."""
    return "| " + " | ".join(cells) + " |"


def head_lines(head):
    """A Markdown table's head: its column names, then the line under them."""
    return [row_line(head), "|" + "---|" * len(head)]


def cell_text(values, digits=3, each=False):
    """'+0.054 (1 bed)', '+0.041 +- 0.013 (2 beds)'; with each, the beds' values after the count."""
    if not values:
        return ""
    m, se = stats(values)
    if len(values) == 1:
        return f"{m:+.{digits}f} (1 bed)"
    listed = ": " + ", ".join(f"{v:+.{digits}f}" for v in values) if each else ""
    return f"{m:+.{digits}f} +- {se:.{digits}f} ({len(values)} beds{listed})"


def count_range(counts):
    """'1', '1-2': the fewest and most of some counts ('0' for none)."""
    n = sorted(set(counts)) or [0]
    return f"{n[0]}" + (f"-{n[-1]}" if n[-1] > n[0] else "")


def beds_count(counts):
    """'1 bed', '2 beds', '1-2 beds': count_range of some cells' beds, with its noun."""
    counts = list(counts)
    return count_range(counts) + f" bed{'s' if max(counts, default=0) > 1 else ''}"


def beds_text(values):
    """'+0.019 (2 beds)': a cell's mean and its beds."""
    return f"{mean(values):+.3f} ({beds_count([len(values)])})"


# ---- the study's folders, named where more than one block reads them

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
CLOCK_A5 = T1000_BEDS                              # the paper's clock: t = 1000 runs, V_y over t = 100-1000
CLOCK_A3 = ["results/paper_depth/fig2_t1000"]
SMALL_SESSION2 = ["study/figures/small_fig5_results.csv"]   # disk and triangle, A = 3, bed 1, session 2's engine
SMALL_POUR = ["results/pour_protocol_small"]
SMALL_FRICTION = ["results/small_friction_amplitude"]
# The disk's and the triangle's rise/sink maps, A = 1-5, beds 1-3 (`wiggle boundary`)
SMALL_MAP = ["results/boundary/small_pd_disk", "results/boundary/small_pd_triangle"]
# Today's engine on the small preset's lattice beds at mu = 0.1 (a run in two folders counts once)
SMALL_TODAY = SMALL_MAP + SMALL_POUR + SMALL_FRICTION
SMALL_TODAY_WHERE = {"bed__pour": "lattice", "contact__mu": 0.1}
# The paper's protocol in its own 300 x 195 d box, by its clock (study/sweeps/paper_box_t1000.toml).
PAPER_BOX = ["results/paper_box/t1000"]
# The coupling screen (issue 79, study/sweeps/paper_depth_coupling_t1000.toml)
COUPLING = ["results/paper_depth/coupling_t1000"]
