"""Runs and sweeps as pandas DataFrames, for analysis in Python or Jupyter, and a thin driver of the
`wiggle` command. Units follow docs/OUTPUT-FORMATS.md: lengths in d (mean grain diameter), times in
sqrt(d/g), velocities in sqrt(g d), forces in rho d^3 g; summary.json's keys, types and units are
listed in docs/summary-schema.json. Needs pandas (Debian: python3-pandas); the figure code does not."""
import dataclasses
import json
import os
import subprocess

from wiggleplot import readers


def _pandas():
    try:
        import pandas
    except ImportError as e:  # only this module needs it
        raise ImportError("wiggleplot.data needs pandas (Debian: apt-get install python3-pandas)") from e
    return pandas


# The unit of each column the files hold (docs/OUTPUT-FORMATS.md), put on every DataFrame as
# df.attrs["units"] (column -> unit; columns without a unit, like counts and names, are left out).
# results.csv's own columns carry the units of docs/results-schema.json (readers.results_columns).
LENGTH, TIME, SPEED, FORCE, STRESS = "d", "sqrt(d/g)", "sqrt(g d)", "rho d^3 g", "rho g d^2"
UNITS = {
    "t": TIME, "x": LENGTH, "y": LENGTH, "vx": SPEED, "vy": SPEED, "fy": FORCE, "angle": "rad", "omega": "sqrt(g/d)",
    "phase_center": "10 phi / pi", "vy_mean": SPEED,
    "phase": "10 phi / pi", "phi": "1 (area fraction)", "sxx": STRESS, "sxy": STRESS, "syy": STRESS,
    "pressure": STRESS,
    **{c["name"]: c["unit"] for c in readers.results_columns() if c["unit"]},
    "drive.amplitude": LENGTH, "drive.period": TIME, "contact.mu": "1", "intruder.y0": LENGTH,
    "box.width": LENGTH, "box.bed_height": LENGTH, "run.duration": TIME, "run.dt": TIME,
    "vy_sd": SPEED, "vy_se": SPEED,  # cells.csv (vy_mean as phase_rates.csv's)
}


def with_units(frame):
    """`frame` with frame.attrs["units"]: the unit of each of its columns that has one."""
    frame.attrs["units"] = {c: UNITS[c] for c in frame.columns if c in UNITS}
    return frame


def _frame(path):
    """A CSV file as a DataFrame (with its units in .attrs["units"]), or None when it does not exist."""
    if not os.path.exists(path):
        return None
    return with_units(_pandas().read_csv(path))


@dataclasses.dataclass
class RunData:
    """One run directory. `trajectory`: t, x, y, vx, vy, fy (the intruder centre [d, sqrt(g d)] and
    its vertical contact force); `phase_rates`: bin, phase_center (10 phi / pi), vy_mean, samples;
    `fields`: phase, x, y, phi, vx, vy, sxx, sxy, syy, pressure, frames (or None when fields were
    off); `summary`: summary.json as a dict (None for an unfinished run); `model`: model.json (or
    None); `config`: the run's configuration as a nested dict (config.toml). Each DataFrame carries
    its columns' units in .attrs["units"] (e.g. run.trajectory.attrs["units"]["vy"] == "sqrt(g d)")."""
    dir: str
    summary: dict
    trajectory: object
    phase_rates: object
    fields: object
    model: dict
    config: dict

    @property
    def vy(self):
        """The paper's rise rate [sqrt(g d)], or None for an unfinished run."""
        return None if self.summary is None else self.summary.get("vy")


def load_run(run_dir):
    """Reads a run directory (`wiggle run --out DIR`, or a sweep's DIR/cases/NAME). Files that are
    not there (a run still going, fields off) are None; a directory without a trajectory or a
    summary is refused with FileNotFoundError. A live case of the engine module (wiggle.Case) is
    read the same way: its record so far, `summary` its rise_rate() (`dir` None, no model)."""
    if is_live_case(run_dir):
        return _live_run(run_dir)
    summary_path = os.path.join(run_dir, "summary.json")
    trajectory_path = os.path.join(run_dir, "trajectory.csv")
    if not os.path.exists(summary_path) and not os.path.exists(trajectory_path):
        raise FileNotFoundError(f"{run_dir}: no summary.json or trajectory.csv: not a run directory")
    summary = readers.read_json(summary_path) if os.path.exists(summary_path) else None
    model_path = os.path.join(run_dir, "model.json")
    config = readers.read_config(run_dir)
    return RunData(dir=run_dir, summary=summary, trajectory=_frame(trajectory_path),
                   phase_rates=_frame(os.path.join(run_dir, "phase_rates.csv")),
                   fields=_frame(os.path.join(run_dir, "fields.csv")),
                   model=readers.read_json(model_path) if os.path.exists(model_path) else None,
                   config=config)


def is_live_case(source):
    """Whether `source` is a live case of the engine module (wiggle.Case) rather than a path."""
    return hasattr(source, "state_hash") and hasattr(source, "frame")


def _live_run(case):
    import tomllib
    pandas = _pandas()

    def frame(columns):
        return None if columns is None else with_units(pandas.DataFrame(dict(columns)))
    return RunData(dir=None, summary=dict(case.rise_rate()), trajectory=frame(case.trajectory),
                   phase_rates=frame(case.phase_rates), fields=frame(case.fields), model=None,
                   config=tomllib.loads(case.config))


def load_cells(sweep_dir):
    """The sweep's cells as a DataFrame, one row per cell (a case without its seed): cell, the
    parameters (less box.seed), state (done, part-run, not run), beds, n (beds with a V_y),
    vy_mean, vy_sd, vy_se, verdict (rises, sinks, not resolved) and verdict_rule. From DIR/cells.csv
    when the sweep wrote one, else grouped from results.csv by the same rule (wiggleplot.cells), so
    the committed studies in results/ read the same way. Units in table.attrs["units"]."""
    from wiggleplot import cells
    if not os.path.exists(os.path.join(sweep_dir, "results.csv")):
        raise FileNotFoundError(f"{sweep_dir}: no results.csv: not a sweep directory")
    table = cells.read_cells(sweep_dir)
    frame = _pandas().DataFrame({c: list(v) for c, v in table.items()})
    return with_units(frame.astype({"beds": int, "n": int}))


def load_sweep(sweep_dir):
    """results.csv of a sweep directory as a DataFrame, one row per case in case order, pending and
    failed cases included (their numbers NaN): case, run_dir, status, vy, vy_slope, vy_settled,
    t_settled (the paper's t_f rule; absent from tables written before it), wall_s, one
    column per parameter named by its config key (drive.period, intruder.shape, ...), n_grains,
    steps, ns_per_particle_step, state_hash, error, warnings. Units in table.attrs["units"].
    `load_case(sweep_dir, row)` reads a case's run."""
    path = os.path.join(sweep_dir, "results.csv")
    if not os.path.exists(path):
        raise FileNotFoundError(f"{sweep_dir}: no results.csv: not a sweep directory")
    return with_units(_pandas().read_csv(path, keep_default_na=True))


def load_case(sweep_dir, row):
    """The run of one case of a sweep: `row` is a row of load_sweep's DataFrame or a case name."""
    if isinstance(row, str):
        table = load_sweep(sweep_dir)
        match = table[table["case"] == row]
        if match.empty:
            raise KeyError(f"{sweep_dir}: no case named {row!r}")
        row = match.iloc[0]
    return load_run(os.path.join(sweep_dir, str(row["run_dir"])))


class WiggleError(RuntimeError):
    """`wiggle` exited with an error; the message is its one-line error."""

    def __init__(self, message, status):
        super().__init__(message)
        self.status = status


# Where this package sits: <clone>/python/wiggleplot or <prefix>/share/wiggle/python/wiggleplot.
_PACKAGE_TREE = os.path.dirname(os.path.dirname(os.path.dirname(os.path.abspath(__file__))))


def find_wiggle():
    """The `wiggle` program that goes with this package: the one installed beside it
    (<prefix>/bin/wiggle), else the one built in its clone (build/release, then any other preset's),
    else `wiggle` on PATH. Raises WiggleError saying what to do when there is none."""
    import glob
    import shutil
    share = os.path.dirname(_PACKAGE_TREE)
    if os.path.basename(_PACKAGE_TREE) == "wiggle" and os.path.basename(share) == "share":  # installed
        candidates = [os.path.join(os.path.dirname(share), "bin", "wiggle")]
    else:
        candidates = [os.path.join(_PACKAGE_TREE, "build", "release", "wiggle")]
        candidates += sorted(glob.glob(os.path.join(_PACKAGE_TREE, "build", "*", "wiggle")))
    for path in candidates:
        if os.path.isfile(path) and os.access(path, os.X_OK):
            return path
    on_path = shutil.which("wiggle")
    if on_path:
        return on_path
    raise WiggleError(f"the wiggle program was not found: not built in {_PACKAGE_TREE}/build (run "
                      "tools/bootstrap.sh build there), not installed beside this package, not on PATH; "
                      "or pass wiggle=PATH", 127)


def run(config=None, out="wiggle-out", overrides=None, wiggle=None, threads=None, resume=False):
    """Runs `wiggle run [CONFIG] --out OUT --set key=value ... --no-plot` and returns load_run(OUT).
    `overrides` maps config keys to values ({"drive.period": 5, "intruder.shape": "triangle"}); a
    value is passed as TOML (strings quoted, lists as [a, b]). `wiggle`: the program (default:
    find_wiggle()). Raises WiggleError with wiggle's own one-line message and exit status when the
    run fails or the input is refused."""
    command = [wiggle or find_wiggle(), "run"]
    if config is not None:
        command.append(os.fspath(config))
    command += ["--out", os.fspath(out), "--no-plot"]
    for key, value in (overrides or {}).items():
        command += ["--set", f"{key}={_toml(value)}"]
    if threads is not None:
        command += ["--threads", str(threads)]
    if resume:
        command.append("--resume")
    done = subprocess.run(command, capture_output=True, text=True)
    if done.returncode != 0:
        lines = [l for l in done.stderr.splitlines() if l.strip() and not l.startswith("wiggle: warning:")]
        message = lines[-1] if lines else f"wiggle exited with status {done.returncode}"
        raise WiggleError(message.removeprefix("wiggle: "), done.returncode)
    return load_run(os.fspath(out))


def _toml(value):
    if isinstance(value, bool):
        return "true" if value else "false"
    if isinstance(value, str):
        return json.dumps(value)  # a TOML basic string
    if isinstance(value, (list, tuple)):
        return "[" + ", ".join(_toml(v) for v in value) + "]"
    return repr(value)
