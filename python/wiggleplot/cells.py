"""A sweep's cells: a cell is a case without its seed (box.seed), the beds of one parameter point,
and its V_y is the mean over those beds with its standard error and a verdict by one rule
(docs/SWEEPS.md, "Beds as replicates"):

    over the n beds with a V_y: mean, sd (n - 1), se = sd / sqrt(n); the cell rises (mean > 0) or
    sinks (mean < 0) when n >= 2 and |mean| >= 2 se, else it is "not resolved".

One bed has no standard error: its sign is not a verdict ("one bed"). This module is the Python
side's one copy of the rule (the C++ side's is src/sweep/CellTable.cpp, which writes cells.csv;
a test checks the two agree on a sweep's data). read_cells reads DIR/cells.csv when the sweep
wrote one and otherwise groups DIR/results.csv by cell, so the committed studies in results/,
written before cells.csv existed, are read by the same code."""
import math
import os
import re

import numpy as np

from wiggleplot import readers

SEED = "box.seed"
RESOLVED_SE = 2.0   # standard errors
MIN_BEDS = 2        # beds before a cell has a standard error, so a verdict
RULE = "rises / sinks when |vy_mean| >= 2 vy_se with n >= 2, else not resolved"
VERDICTS = ("rises", "sinks", "not resolved")
STATES = ("done", "part-run", "not run")
# cells.csv's columns after `cell` and the parameters'.
COLUMNS_AFTER_PARAMETERS = ("state", "beds", "n", "vy_mean", "vy_sd", "vy_se", "verdict", "verdict_rule")
_SEED_PART = re.compile(r"(?:^|_)(?:box\.)?seed=[0-9+-]+(?=_|$)")


def stats(values):
    """{'n', 'vy_mean', 'vy_sd', 'vy_se', 'verdict'} of one cell's V_y values (one per bed); NaN
    where the rule has no number (no bed: no mean; one bed: no sd or se)."""
    v = [float(x) for x in values]
    n = len(v)
    out = {"n": n, "vy_mean": math.nan, "vy_sd": math.nan, "vy_se": math.nan, "verdict": "not resolved"}
    if n == 0:
        return out
    mean = sum(v) / n
    out["vy_mean"] = mean
    if n < MIN_BEDS:
        return out
    sd = math.sqrt(sum((x - mean) ** 2 for x in v) / (n - 1))
    se = sd / math.sqrt(n)
    out.update(vy_sd=sd, vy_se=se)
    if mean != 0.0 and abs(mean) >= RESOLVED_SE * se:
        out["verdict"] = "rises" if mean > 0 else "sinks"
    return out


def state(n, beds):
    """'done' (every bed has a V_y), 'part-run' (some have) or 'not run'."""
    return "not run" if n == 0 else "done" if n >= beds else "part-run"


def in_words(n, beds, mean, se, verdict):
    """A cell for a table: '+0.0886 +- 0.0025 (3 beds): rises', '+0.0886 (one bed: its sign is not
    a verdict)', with 'part-run: 1 of its 2 beds' when beds are missing."""
    n, beds = int(n), int(beds)
    run = f"part-run: {n} of its {beds} beds" if n < beds else ""
    if n == 0:
        return f"no bed run yet (of {beds})"
    if n == 1:
        return f"{mean:+.3g} (one bed: its sign is not a verdict" + (f"; {run})" if run else ")")
    return f"{mean:+.3g} +- {se:.2g} ({n} beds" + (f"; {run}" if run else "") + f"): {verdict}"


def cell_name(case):
    """The cell's name from a case's: the name without its seed part ('period=5_seed=2' ->
    'period=5'; 'base' when nothing else is left), as the sweep names its cells."""
    name = _SEED_PART.sub("", str(case), count=1).strip("_")
    return name or "base"


def _parameters(table):
    """results.csv's parameter columns: every column that is not one of its own (docs/results-schema.json)."""
    own = {c["name"] for c in readers.results_columns()}
    return [c for c in table if c not in own]


def _key(value):
    if isinstance(value, float) and math.isnan(value):
        return ""
    return repr(value)


def group_results(table):
    """results.csv's rows (readers.read_results) grouped by cell: every parameter but box.seed.
    Returns cells.csv's table, {column: array}: cell, the parameters (less box.seed), then
    COLUMNS_AFTER_PARAMETERS; cells in the order of their first case."""
    parameters = [p for p in _parameters(table) if p != SEED]
    status = np.asarray(table["status"], dtype=object)
    vy = np.asarray(table["vy"], dtype=float)
    order, members = [], {}
    for i in range(len(table["case"])):
        key = tuple(_key(table[p][i]) for p in parameters)
        if key not in members:
            order.append(key)
            members[key] = []
        members[key].append(i)
    rows = []
    for key in order:
        idx = members[key]
        values = [vy[i] for i in idx if status[i] == "ok" and np.isfinite(vy[i])]
        s = stats(values)
        row = {"cell": cell_name(table["case"][idx[0]])}
        row.update({p: table[p][idx[0]] for p in parameters})
        row.update(state=state(s["n"], len(idx)), beds=len(idx), n=s["n"], vy_mean=s["vy_mean"],
                   vy_sd=s["vy_sd"], vy_se=s["vy_se"], verdict=s["verdict"], verdict_rule=RULE)
        rows.append(row)
    columns = ["cell"] + parameters + list(COLUMNS_AFTER_PARAMETERS)
    out = {}
    for c in columns:
        values = [r[c] for r in rows]
        numeric = all(isinstance(v, (int, float, np.floating, np.integer)) for v in values)
        out[c] = np.array(values, dtype=float if numeric and values else object)
    return out


def read_cells(sweep_dir):
    """The sweep's cells as {column: array}: DIR/cells.csv when the sweep wrote one, else
    DIR/results.csv grouped by cell (group_results)."""
    path = os.path.join(sweep_dir, "cells.csv")
    if os.path.exists(path):
        return readers._require(readers.read_table(path), ["cell"] + list(COLUMNS_AFTER_PARAMETERS), path)
    return group_results(readers.read_results(sweep_dir))


def replicated(cells):
    """Whether some cell has more than one bed (a sweep with `beds = N` or a box.seed grid)."""
    beds = np.asarray(cells["beds"], dtype=float)
    return bool(beds.size) and float(beds.max()) > 1
