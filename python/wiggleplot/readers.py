"""Readers for the files wiggle writes (docs/OUTPUT-FORMATS.md). Each returns plain numpy arrays or
dicts; nothing here computes physics. Missing optional files are the caller's business: readers
raise FileNotFoundError, and the figure code turns that into a note."""
import csv
import functools
import itertools
import json
import os
import tomllib

import numpy as np


class FormatError(Exception):
    """A file exists but does not follow the documented format; the message names file and problem."""


def read_table(path):
    """A CSV file with a header row -> {column: array}. Columns whose every non-empty cell parses as a
    number become float arrays (empty cells and 'nan' -> NaN); the others stay arrays of str."""
    with open(path, newline="") as f:
        rows = list(csv.reader(f))
    if not rows:
        raise FormatError(f"{path}: empty file, expected a header row")
    header = [h.strip() for h in rows[0]]
    body = [r for r in rows[1:] if r and any(c.strip() for c in r)]
    table = {}
    for j, name in enumerate(header):
        cells = [r[j].strip() if j < len(r) else "" for r in body]
        table[name] = _column(cells)
    return table


def _column(cells):
    values = np.empty(len(cells), dtype=float)
    for i, c in enumerate(cells):
        if c == "":
            values[i] = np.nan
            continue
        try:
            values[i] = float(c)
        except ValueError:
            return np.array(cells, dtype=object)
    return values


def _require(table, columns, path):
    missing = [c for c in columns if c not in table]
    if missing:
        raise FormatError(f"{path}: missing column(s) {', '.join(missing)}")
    return table


def read_json(path):
    with open(path) as f:
        return json.load(f)


@functools.lru_cache(maxsize=None)
def results_columns():
    """results.csv's own columns, those before the parameters then those after, as dicts of name,
    unit and meaning: docs/results-schema.json, which a C++ test keeps equal to the table that
    writes the file (src/sweep/ResultsTable.cpp). The package holds it as results-schema.json: in
    the source tree a link to docs/, installed a copy (cmake --install, pip: the package's data)."""
    here = os.path.dirname(os.path.abspath(__file__))
    schema = read_json(os.path.join(here, "results-schema.json"))
    return tuple(schema["before_parameters"] + schema["after_parameters"])


def read_config(run_dir):
    """config.toml as nested dicts; {} when absent (figures then fall back to summary.json)."""
    path = os.path.join(run_dir, "config.toml")
    if not os.path.exists(path):
        return {}
    with open(path, "rb") as f:
        return tomllib.load(f)


def config_value(config, key, default=None):
    """config_value(cfg, "drive.period") -> value or default."""
    node = config
    for part in key.split("."):
        if not isinstance(node, dict) or part not in node:
            return default
        node = node[part]
    return node


def read_summary(run_dir):
    return read_json(os.path.join(run_dir, "summary.json"))


def read_trajectory(run_dir):
    path = os.path.join(run_dir, "trajectory.csv")
    return _require(read_table(path), ["t", "x", "y"], path)


def read_phase_rates(run_dir):
    path = os.path.join(run_dir, "phase_rates.csv")
    return _require(read_table(path), ["bin", "phase_center", "vy_mean", "samples"], path)


def read_fields(run_dir):
    path = os.path.join(run_dir, "fields.csv")
    return _require(read_table(path), ["phase", "x", "y", "phi", "vx", "vy", "pressure"], path)


def read_model(run_dir):
    """model.json of a run directory, or None when absent."""
    path = os.path.join(run_dir, "model.json")
    if not os.path.exists(path):
        return None
    model = read_json(path)
    curve = np.asarray(model.get("curve", []), dtype=float).reshape(-1, 2)
    model["curve"] = curve
    return model


def case_finished(run_dir):
    """Whether a sweep's case is finished: its summary.json reads whole and says "ok". The one rule
    the sweep itself, `wiggle status` and `wiggle report` apply (caseFinished, src/sweep/ResultsTable.h):
    a case results.csv calls ok but whose summary.json is torn or says otherwise runs again."""
    try:
        return read_summary(run_dir).get("status") == "ok"
    except (OSError, ValueError, FormatError, AttributeError):
        return False


def read_results(sweep_dir):
    """results.csv as {column: array}; a row that says ok but whose case is not finished
    (case_finished) is pending, its numbers NaN, as the sweep and `wiggle status` count it."""
    path = os.path.join(sweep_dir, "results.csv")
    table = _require(read_table(path), ["case", "run_dir", "status", "vy"], path)
    status = np.asarray(table["status"], dtype=object).copy()
    for i in range(len(status)):
        if status[i] == "ok" and not case_finished(os.path.join(sweep_dir, str(table["run_dir"][i]))):
            status[i] = "pending"
            for column in ("vy", "vy_slope"):
                if column in table and table[column].dtype == float:
                    table[column][i] = np.nan
    table["status"] = status
    return table


def read_geometry(path):
    """`wiggle model --geometry FILE.json` output with outline and atoms as (n, 2) arrays."""
    geom = read_json(path)
    for key in ("outline", "atoms"):
        if key not in geom:
            raise FormatError(f"{path}: missing key '{key}'")
        geom[key] = np.asarray(geom[key], dtype=float).reshape(-1, 2)
    return geom


# --- LAMMPS text dump --------------------------------------------------------------------------


class DumpFrame:
    """One frame: step, box bounds [[xlo, xhi], [ylo, yhi], [zlo, zhi]], and per-atom columns
    (arrays named as in the ITEM: ATOMS line, sorted by id)."""

    def __init__(self, step, box, columns):
        self.step = step
        self.box = box
        self.columns = columns

    def __getitem__(self, name):
        return self.columns[name]


class Dump:
    """Index of a multi-frame LAMMPS text dump: one pass records each frame's step and byte offset,
    so that a few chosen frames of a large file can be read without parsing the rest."""

    def __init__(self, path):
        self.path = path
        self.steps = []
        self._offsets = []  # (byte offset of the first atom line, atom count, box, column names)
        with open(path, "rb") as f:
            while True:
                line = f.readline()
                if not line:
                    break
                if not line.startswith(b"ITEM: TIMESTEP"):
                    continue
                try:
                    step = int(f.readline())
                    if not f.readline().startswith(b"ITEM: NUMBER OF ATOMS"):
                        raise ValueError("no NUMBER OF ATOMS item")
                    count = int(f.readline())
                    if not f.readline().startswith(b"ITEM: BOX BOUNDS"):
                        raise ValueError("no BOX BOUNDS item")
                    box = [[float(v) for v in f.readline().split()[:2]] for _ in range(3)]
                    atoms = f.readline().decode()
                    if not atoms.startswith("ITEM: ATOMS"):
                        raise ValueError("no ATOMS item")
                except ValueError as e:
                    raise FormatError(f"{path}: frame {len(self.steps)}: {e}") from None
                names = atoms.split()[2:]
                self.steps.append(step)
                self._offsets.append((f.tell(), count, box, names))
                for _ in range(count):
                    f.readline()
        if not self.steps:
            raise FormatError(f"{path}: no 'ITEM: TIMESTEP' frame")

    def __len__(self):
        return len(self.steps)

    def frame(self, index):
        offset, count, box, names = self._offsets[index]
        with open(self.path, "rb") as f:
            f.seek(offset)
            lines = list(itertools.islice(f, count))
        data = np.loadtxt(lines, ndmin=2) if count else np.zeros((0, len(names)))
        if data.shape[0] != count or data.shape[1] != len(names):
            raise FormatError(f"{self.path}: frame {index} (step {self.steps[index]}) is truncated")
        columns = {name: data[:, j] for j, name in enumerate(names)}
        if "id" in columns:
            order = np.argsort(columns["id"], kind="stable")
            columns = {k: v[order] for k, v in columns.items()}
        for needed in ("type", "x", "y", "radius"):
            if needed not in columns:
                raise FormatError(f"{self.path}: ATOMS line lacks column '{needed}'")
        return DumpFrame(self.steps[index], box, columns)
