"""The arrays behind each figure, apart from the drawing so that tests can check them: averages over
seeds, the observed T_rising, field grids and their masks. Only bookkeeping and interpolation of
numbers the C++ program wrote; no physics is re-derived here."""
import math

import numpy as np
from matplotlib.path import Path

from wiggleplot import cells, readers

# Column names of results.csv (config keys) that the sweep figures know by meaning.
SHAPE, AMPLITUDE, PERIOD, MU, SEED = (
    "intruder.shape", "drive.amplitude", "drive.period", "contact.mu", "box.seed")
# Columns of results.csv that are outcomes or bookkeeping, never parameters: docs/results-schema.json's
# own columns, and case_label, a [[case]]'s name, which the figures label by already.
NON_PARAMETERS = {c["name"] for c in readers.results_columns()} | {"case_label"}


# --- one run ------------------------------------------------------------------------------------

def displacement(traj):
    """(t, y - y(0)) of the intruder centre, paper fig. 2."""
    t = np.asarray(traj["t"], dtype=float)
    y = np.asarray(traj["y"], dtype=float)
    return t, y - y[0]


def rate_lines(summary, traj):
    """The straight lines drawn over y(t) - y(0) on [t_i, t_f]:
    'vy': the paper's rate, the chord from (t_i, y_initial) to (t_f, y_final) of summary.json;
    'slope': the least-squares line with summary's vy_slope, through the mean of the samples in
    [t_i, t_f] (for a fixed slope that is where the least-squares line passes);
    'settled': the paper's t_f rule, the chord from (t_i, y_initial) to t_settled with vy_settled,
    present only when the intruder settled before t_f (summary's `settled`).
    Each is (t_pair, dy_pair, rate) in the y - y(0) frame, or absent when summary lacks its keys."""
    t, dy = displacement(traj)
    y0 = float(traj["y"][0])
    lines = {}
    ti, tf = summary.get("t_i"), summary.get("t_f")
    if ti is None or tf is None or not np.isfinite([ti, tf]).all() or tf <= ti:
        return lines
    vy = summary.get("vy")
    if vy is not None and np.isfinite(vy):
        yi = summary.get("y_initial")
        yi = float(np.interp(ti, t, traj["y"])) if yi is None else float(yi)
        lines["vy"] = (np.array([ti, tf]), np.array([yi - y0, yi - y0 + vy * (tf - ti)]), float(vy))
    settled = settled_point(summary, traj)
    if settled is not None and "vy" in lines:
        (t_start, _), (dy_start, _), _ = lines["vy"]
        lines["settled"] = (np.array([t_start, settled[0]]), np.array([dy_start, settled[1]]),
                            float(summary["vy_settled"]))
    slope = summary.get("vy_slope")
    inside = (t >= ti) & (t <= tf)
    if slope is not None and np.isfinite(slope) and inside.any():
        tm, ym = t[inside].mean(), dy[inside].mean()
        tt = np.array([ti, tf])
        lines["slope"] = (tt, ym + slope * (tt - tm), float(slope))
    return lines


def settled_point(summary, traj):
    """(t_settled, y(t_settled) - y(0)) when summary.json says the intruder settled (the paper's t_f
    rule, docs/OUTPUT-FORMATS.md), else None (not settled, or a summary written before the rule)."""
    if not summary.get("settled") or summary.get("t_settled") is None:
        return None
    t, dy = displacement(traj)
    ts = float(summary["t_settled"])
    return ts, float(np.interp(ts, t, dy))


def phase_bars(rates):
    """(phase_center, vy_mean, empty) for fig. 8; empty bins (samples = 0) get vy NaN."""
    order = np.argsort(rates["bin"])
    centers = np.asarray(rates["phase_center"], dtype=float)[order]
    vy = np.asarray(rates["vy_mean"], dtype=float)[order].copy()
    empty = np.asarray(rates["samples"], dtype=float)[order] <= 0
    vy[empty] = np.nan
    return centers, vy, empty


def convex_hull(points):
    """Counter-clockwise convex hull of (n, 2) points (Andrew's monotone chain)."""
    pts = sorted(set(map(tuple, np.asarray(points, dtype=float))))
    if len(pts) <= 2:
        return np.array(pts)

    def cross(o, a, b):
        return (a[0] - o[0]) * (b[1] - o[1]) - (a[1] - o[1]) * (b[0] - o[0])

    lower, upper = [], []
    for p in pts:
        while len(lower) >= 2 and cross(lower[-2], lower[-1], p) <= 0:
            lower.pop()
        lower.append(p)
    for p in reversed(pts):
        while len(upper) >= 2 and cross(upper[-2], upper[-1], p) <= 0:
            upper.pop()
        upper.append(p)
    return np.array(lower[:-1] + upper[:-1])


def envelope_of_atoms(atoms, radius, samples=24):
    """Outer envelope of a clump of discs (convex hull of their rims): the intruder region drawn and
    masked on the field maps when only the atoms are known (from a dump). Convex shapes only; a
    concave polygon's notch is filled in (geometry.json, when present, gives the true outline)."""
    atoms = np.asarray(atoms, dtype=float).reshape(-1, 2)
    angles = np.linspace(0.0, 2.0 * np.pi, samples, endpoint=False)
    rim = np.concatenate([atoms + radius * np.column_stack([np.cos(a) * np.ones(len(atoms)),
                                                            np.sin(a) * np.ones(len(atoms))])
                          for a in angles])
    return convex_hull(rim)


def field_grids(fields, radius=15.0, outline=None):
    """fields.csv -> {'x': (nx,), 'y': (ny,), 'phases': (np,), 'frames': (np,),
    'phi'|'speed'|'pressure'|'vx'|'vy': masked arrays (np, ny, nx)}. Masked: grid points with
    r > radius, points inside the intruder outline (polygon (k, 2), intruder frame), points absent
    from the file, and non-finite values."""
    phase = np.asarray(fields["phase"], dtype=float)
    x = np.asarray(fields["x"], dtype=float)
    y = np.asarray(fields["y"], dtype=float)
    xs = np.unique(np.round(x, 9))
    ys = np.unique(np.round(y, 9))
    phases = np.unique(phase)
    ix = np.searchsorted(xs, np.round(x, 9))
    iy = np.searchsorted(ys, np.round(y, 9))
    ip = np.searchsorted(phases, phase)
    shape = (len(phases), len(ys), len(xs))
    present = np.zeros(shape, dtype=bool)
    present[ip, iy, ix] = True
    gx, gy = np.meshgrid(xs, ys)
    geometric = np.hypot(gx, gy) > radius + 1e-9
    if outline is not None and len(outline) >= 3:
        inside = Path(np.asarray(outline)).contains_points(
            np.column_stack([gx.ravel(), gy.ravel()])).reshape(gx.shape)
        geometric |= inside
    grids = {"x": xs, "y": ys, "phases": phases}
    frames = np.full(len(phases), np.nan)
    if "frames" in fields:
        frames[ip] = np.asarray(fields["frames"], dtype=float)
    grids["frames"] = frames
    columns = {"phi": fields["phi"], "vx": fields["vx"], "vy": fields["vy"],
               "pressure": fields["pressure"]}
    vx = np.asarray(fields["vx"], dtype=float)
    vy = np.asarray(fields["vy"], dtype=float)
    columns["speed"] = np.hypot(vx, vy)
    for name, values in columns.items():
        data = np.full(shape, np.nan)
        data[ip, iy, ix] = np.asarray(values, dtype=float)
        mask = ~present | geometric[None, :, :] | ~np.isfinite(data)
        grids[name] = np.ma.array(data, mask=mask)
    return grids


def shared_limits(masked, low_pct=1.0, high_pct=99.0, symmetric=False):
    """Colour limits shared by one row of field maps: robust percentiles of the unmasked values."""
    values = np.ma.compressed(masked)
    if values.size == 0:
        return 0.0, 1.0
    lo, hi = np.percentile(values, [low_pct, high_pct])
    if symmetric:
        m = max(abs(lo), abs(hi)) or 1.0
        return -m, m
    if hi <= lo:
        hi = lo + 1.0
    return float(lo), float(hi)


def spread_frames(n_frames, count=6):
    """Indices of up to `count` frames spread evenly over a dump (first and last included)."""
    if n_frames <= 0:
        return []
    return sorted(set(int(round(i)) for i in np.linspace(0, n_frames - 1, min(count, n_frames))))


def frames_near(times, wanted):
    """For each wanted time, the index of the nearest frame time (duplicates removed, in order)."""
    times = np.asarray(times, dtype=float)
    out = []
    for w in wanted:
        i = int(np.argmin(np.abs(times - w)))
        if i not in out:
            out.append(i)
    return out


# --- a sweep ------------------------------------------------------------------------------------

def usable_rows(results):
    """Boolean mask of results.csv rows that carry a rate: status 'ok' and a finite vy."""
    status = np.asarray(results["status"], dtype=object)
    vy = np.asarray(results["vy"], dtype=float)
    return (status == "ok") & np.isfinite(vy)


def parameter_columns(results):
    return [c for c in results if c not in NON_PARAMETERS]


def varying(results, column, rows=None):
    """Distinct values of a column (over `rows`), sorted; [] when the column is absent."""
    if column not in results:
        return []
    values = np.asarray(results[column])
    if rows is not None:
        values = values[rows]
    if values.dtype == object:
        return sorted(set(values.tolist()))
    return sorted(set(v for v in values.tolist() if np.isfinite(v)))


def panel_labels(results):
    """One label per row naming its panel: the shape, plus any other parameter that varies and is
    not one the figures put on an axis or average over (A, T, mu, seed), e.g. 'triangle, intruder.angle=180'."""
    n = len(results["case"])
    shape = results.get(SHAPE)
    labels = [str(shape[i]) if shape is not None else "all" for i in range(n)]
    for column in parameter_columns(results):
        if column in (SHAPE, AMPLITUDE, PERIOD, MU, SEED) or len(varying(results, column)) < 2:
            continue
        values = results[column]
        labels = [f"{labels[i]}, {column}={_fmt(values[i])}" for i in range(n)]
    return np.array(labels, dtype=object)


def _fmt(v):
    if isinstance(v, float) and v.is_integer():
        return str(int(v))
    return str(v)


def aggregate(results, keys, rows=None):
    """Average vy over all rows sharing the same values of `keys` (seeds and any other unlisted
    parameter are pooled: with every parameter but the seed among the keys, a group is a cell).
    Returns a list of dicts {key: value, 'vy': mean, 'std': sample standard deviation (0 for one
    value), 'se': its standard error (0 for one value), 'verdict' (the cells' rule, wiggleplot.cells),
    'min', 'max', 'n', 'cases'}, sorted by the keys."""
    mask = usable_rows(results) if rows is None else (rows & usable_rows(results))
    vy = np.asarray(results["vy"], dtype=float)
    groups = {}
    for i in np.flatnonzero(mask):
        key = tuple(results[k][i] if k in results else None for k in keys)
        groups.setdefault(key, []).append(i)
    out = []
    for key in sorted(groups, key=lambda k: tuple((str(type(v)), v) for v in k)):
        idx = groups[key]
        v = vy[idx]
        rec = dict(zip(keys, key))
        s = cells.stats(v)
        one = s["n"] < cells.MIN_BEDS
        rec.update(vy=s["vy_mean"], std=0.0 if one else s["vy_sd"], se=0.0 if one else s["vy_se"],
                   verdict=s["verdict"], min=float(v.min()), max=float(v.max()), n=s["n"],
                   cases=[results["case"][i] for i in idx])
        out.append(rec)
    return out


def series(records, x_key):
    """Records of one curve -> arrays (x, mean, std, n, se) sorted by x."""
    records = sorted(records, key=lambda r: r[x_key])
    return (np.array([r[x_key] for r in records], dtype=float),
            np.array([r["vy"] for r in records]), np.array([r["std"] for r in records]),
            np.array([r["n"] for r in records]), np.array([r["se"] for r in records]))


def t_rising(periods, vy):
    """The observed T_rising of Table 1: the period above which the (seed-averaged) V_y stays > 0,
    interpolated linearly between the last period with V_y <= 0 and the next one. The last crossing,
    not the first: at small T the intruder can gain height in a transient (V_y slightly > 0) and
    still sink at the periods above, and the paper's T_rising is where rising sets in for good.
    Returns (T_rising, T_below, T_above, note); T_rising is NaN with a note when V_y is positive at
    every period or never turns positive; the note also names positive periods below the crossing."""
    periods = np.asarray(periods, dtype=float)
    vy = np.asarray(vy, dtype=float)
    ok = np.isfinite(periods) & np.isfinite(vy)
    order = np.argsort(periods[ok])
    T, v = periods[ok][order], vy[ok][order]
    if len(T) == 0:
        return math.nan, math.nan, math.nan, "no data"
    not_rising = np.nonzero(v <= 0)[0]
    if len(not_rising) == 0:
        return math.nan, math.nan, float(T[0]), f"rises already at the smallest T = {T[0]:g}"
    i = int(not_rising[-1])
    if i == len(T) - 1:
        return math.nan, float(T[-1]), math.nan, f"V_y <= 0 at the largest T = {T[-1]:g}"
    t_star = T[i] + (0.0 - v[i]) * (T[i + 1] - T[i]) / (v[i + 1] - v[i])
    early = [f"{t:g}" for t in T[:i][v[:i] > 0]]
    note = f"V_y > 0 also at T = {', '.join(early)}" if early else ""
    return float(t_star), float(T[i]), float(T[i + 1]), note
