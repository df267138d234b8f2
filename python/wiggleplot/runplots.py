"""Figures of one run directory: y(t) with the rates (paper fig. 2), snapshots (figs 3-4), the
phase-resolved rate (fig. 8), the coarse-grained fields (figs 9-11) and an optional movie."""
import os
import shutil
import tomllib

import numpy as np
from matplotlib.collections import EllipseCollection
from matplotlib.patches import Polygon

from wiggleplot import prepare, readers, style
from wiggleplot.data import is_live_case
from wiggleplot.style import plt


class Run:
    """A run directory's inputs, each read once and None when absent or unreadable."""

    def __init__(self, run_dir, report):
        self.dir = run_dir
        self.report = report
        self.config = self._try(readers.read_config, "config.toml") or {}
        self.summary = self._try(readers.read_summary, "summary.json") or {}
        self.trajectory = self._try(readers.read_trajectory, "trajectory.csv")
        self.model = self._try(readers.read_model, "model.json")
        self.dt = float(readers.config_value(self.config, "run.dt", 1e-4))
        self._dump = None
        self._dump_tried = False

    def _try(self, reader, name):
        try:
            return reader(self.dir)
        except FileNotFoundError:
            return None
        except (readers.FormatError, ValueError, KeyError) as e:
            self.report.note(f"{name} unreadable, skipped: {e}")
            return None

    def meta(self, key, config_key):
        """A case parameter from summary.json, else from config.toml."""
        if key in self.summary:
            return self.summary[key]
        return readers.config_value(self.config, config_key)

    @property
    def period(self):
        v = self.meta("period", "drive.period")
        return None if v is None else float(v)

    def label(self):
        """'disk, A = 3 d, T = 5, mu = 0.1' from whatever parameters are known."""
        parts = []
        shape = self.meta("shape", "intruder.shape")
        if shape is not None:
            parts.append(str(shape))
        for key, ckey, fmt in (("amplitude", "drive.amplitude", r"$A$ = {:g}"),
                               ("period", "drive.period", r"$T$ = {:g}"),
                               ("mu", "contact.mu", r"$\mu$ = {:g}")):
            v = self.meta(key, ckey)
            if v is not None:
                parts.append(fmt.format(float(v)))
        return ", ".join(parts)

    def phase_rates(self):
        """phase_rates.csv's columns; FileNotFoundError or readers.FormatError when it cannot."""
        return readers.read_phase_rates(self.dir)

    def fields(self):
        """fields.csv's columns, or None when the run has none; readers.FormatError when unreadable."""
        try:
            return readers.read_fields(self.dir)
        except FileNotFoundError:
            return None

    def dump(self):
        if not self._dump_tried:
            self._dump_tried = True
            path = os.path.join(self.dir, "dumps", "dump.lammpstrj")
            if os.path.exists(path):
                try:
                    self._dump = readers.Dump(path)
                except (readers.FormatError, ValueError) as e:
                    self.report.note(f"dump unreadable, skipped: {e}")
        return self._dump

    def frame_times(self):
        return np.array(self.dump().steps, dtype=float) * self.dt

    def intruder_outline(self):
        """The intruder's outline in its own frame (relative to the centre the trajectory and the
        fields use): geometry.json's outline when the run directory has one, else the envelope of
        the intruder atoms (type 3) of the first dump frame about the trajectory's centre then."""
        path = os.path.join(self.dir, "geometry.json")
        if os.path.exists(path):
            try:
                return readers.read_geometry(path)["outline"], "geometry.json"
            except (readers.FormatError, ValueError, KeyError) as e:
                self.report.note(f"geometry.json unreadable: {e}")
        dump = self.dump()
        if dump is None or self.trajectory is None:
            return None, None
        t0 = dump.steps[0] * self.dt
        traj = self.trajectory
        centre = (float(np.interp(t0, traj["t"], traj["x"])), float(np.interp(t0, traj["t"], traj["y"])))
        return _outline_of_atoms(dump.frame(0), centre), "dump atoms"


def _outline_of_atoms(frame, centre):
    """The envelope of a frame's intruder atoms (type 3) about the intruder's centre, or None."""
    mine = frame["type"] == 3
    if not mine.any():
        return None
    atoms = np.column_stack([frame["x"][mine] - centre[0], frame["y"][mine] - centre[1]])
    # Undo a periodic wrap in x (the box is periodic; the intruder may straddle the seam).
    width = frame.box[0][1] - frame.box[0][0]
    atoms[:, 0] -= width * np.round(atoms[:, 0] / width)
    radius = float(np.median(frame["radius"][mine]))
    return prepare.envelope_of_atoms(atoms, radius)


class FrameList:
    """Frames a live case handed out (wiggle.Case.frame()) in the Dump's interface: steps, frame(i)."""

    def __init__(self, frames):
        self.frames = list(frames)
        self.steps = [int(f["step"]) for f in self.frames]

    def __len__(self):
        return len(self.frames)

    def frame(self, index):
        f = self.frames[index]
        columns = {k: np.asarray(v) for k, v in f.items() if k not in ("step", "t", "box", "intruder")}
        return readers.DumpFrame(int(f["step"]), [list(b) for b in f["box"]], columns)


class LiveRun(Run):
    """A live case of the engine module (`import wiggle`: wiggle.Case) as a run: its config, its
    rise rate so far in place of summary.json, its trajectory, phase bins and field maps from the
    engine, and as the dump the frames the caller took with case.frame() (by default the current
    step alone). There is no cavity model (model.json is `wiggle run`'s)."""

    def __init__(self, case, report, frames=None):
        self.dir = None
        self.report = report
        self.case = case
        self.config = tomllib.loads(case.config)
        self.summary = dict(case.rise_rate())
        self.trajectory = case.trajectory
        self.model = None
        self.dt = case.dt
        self._frames = FrameList(frames if frames else [case.frame()])

    def phase_rates(self):
        return self.case.phase_rates

    def fields(self):
        return self.case.fields

    def dump(self):
        return self._frames

    def frame_times(self):
        return np.array([float(f["t"]) for f in self._frames.frames])

    def intruder_outline(self):
        first = self._frames.frames[0]
        return _outline_of_atoms(self._frames.frame(0), first["intruder"]), "frame atoms"


# --- fig. 2: y(t) - y(0) --------------------------------------------------------------------------

def plot_trajectory(run, out_dir, formats):
    if run.trajectory is None:
        run.report.note("no trajectory.csv: y(t) figure skipped")
        return
    t, dy = prepare.displacement(run.trajectory)
    fig, ax = plt.subplots(figsize=(style.COLUMN_WIDTH * 1.3, 2.7))
    ax.plot(t, dy, color="0.25", lw=0.9, label="intruder")
    lines = prepare.rate_lines(run.summary, run.trajectory)
    if "vy" in lines:
        tt, yy, v = lines["vy"]
        ax.plot(tt, yy, color="#d95f02", lw=1.8, label=rf"$V_y$ = {v:.3g}, one bed ($t_i$ to $t_f$ = {tt[1]:.4g})")
        ax.plot(tt, yy, "o", color="#d95f02", ms=3.5)
    if "settled" in lines:
        tt, yy, v = lines["settled"]
        ax.plot(tt, yy, color="#7570b3", lw=1.4, label=rf"$V_y$ = {v:.3g} to $t_{{settled}}$ = {tt[1]:.4g}")
        ax.plot(tt[1:], yy[1:], "s", color="#7570b3", ms=3.5)
    if "slope" in lines:
        tt, yy, v = lines["slope"]
        ax.plot(tt, yy, "--", color="#1b9e77", lw=1.2, label=rf"least squares: {v:.3g}")
    # The cavity model says where rising starts (T_rise), in words only: its own V_y is the model's
    # magnitude, many times a simulated rate, and drawn here it would read as a prediction of this run.
    t_rise = run.model.get("T_rise") if run.model is not None else None
    if isinstance(t_rise, (int, float)) and run.period is not None:
        side = r">" if run.period > t_rise else r"\leq"
        expect = "rising" if run.period > t_rise else "no rise"
        ax.plot([], [], " ", label=rf"cavity model: {expect} ($T$ = {run.period:g} {side} $T_{{rise}}$ = {t_rise:.3g})")
    ti = run.summary.get("t_i")
    if ti is not None:
        ax.axvline(ti, color="0.6", lw=0.6, ls="-")
        ax.annotate(r"$t_i$", xy=(ti, 0.0), xycoords=("data", "axes fraction"), xytext=(2, 2),
                    textcoords="offset points", fontsize=7, color="0.4")
    ax.set_xlabel(style.T_LABEL)
    ax.set_ylabel(style.DY_LABEL)
    if "angle" in run.trajectory:  # an intruder that may turn: how far it turned, on its own axis
        turn = ax.twinx()
        angle = np.degrees(np.asarray(run.trajectory["angle"], dtype=float))
        turn.plot(t, angle, color="#1f78b4", lw=0.7, alpha=0.8)
        turn.set_ylabel("turned [degrees]", color="#1f78b4")
        turn.tick_params(axis="y", colors="#1f78b4")
    status = run.summary.get("status")
    title = run.label() + ("" if status in (None, "ok") else f" [{status}]")
    ax.set_title(title)
    ax.legend(loc="best")
    run.report.wrote(style.save(fig, out_dir, "trajectory", formats))


# --- figs 3-4: snapshots ---------------------------------------------------------------------------

def _discs(ax, x, y, r, colours, rasterize=True):
    coll = EllipseCollection(2 * r, 2 * r, np.zeros_like(r), units="xy",
                             offsets=np.column_stack([x, y]), offset_transform=ax.transData,
                             facecolors=colours, edgecolors="none")
    coll.set_rasterized(rasterize)
    ax.add_collection(coll)
    return coll


def _colours(frame, band_of_id, band_height=10.0):
    """Per-atom colours: grains in alternating bands of their initial height (so mixing shows),
    base and intruder in their own colours."""
    types = frame["type"]
    if band_of_id is not None and "id" in frame.columns:
        ids = frame["id"].astype(np.int64)
        band = band_of_id.get_many(ids)
    else:
        band = np.floor(frame["y"] / band_height).astype(int) % 2
    colours = np.where(band[:, None] == 0, _rgba(style.GRAIN_COLOURS[0]), _rgba(style.GRAIN_COLOURS[1]))
    colours[types == 2] = _rgba(style.BASE_COLOUR)
    colours[types == 3] = _rgba(style.INTRUDER_COLOUR)
    return colours


def _rgba(c):
    import matplotlib.colors as mc
    return np.array(mc.to_rgba(c))


class _Bands:
    """Initial height band (0/1) of each grain id, taken from the dump's first frame."""

    def __init__(self, frame, band_height=10.0):
        ids = frame["id"].astype(np.int64)
        self.lookup = dict(zip(ids.tolist(), (np.floor(frame["y"] / band_height).astype(int) % 2).tolist()))

    def get_many(self, ids):
        return np.array([self.lookup.get(i, 0) for i in ids.tolist()], dtype=int)


def _system_limits(frame, top):
    (xlo, xhi), (ylo, _yhi) = frame.box[0], frame.box[1]
    return (xlo, xhi), (min(ylo, -0.6), top)


def plot_snapshots(run, out_dir, formats, times=None, count=6):
    dump = run.dump()
    if dump is None:
        run.report.note("no dumps/dump.lammpstrj: snapshots skipped")
        return
    ftimes = run.frame_times()
    indices = prepare.frames_near(ftimes, times) if times else prepare.spread_frames(len(dump), count)
    first = dump.frame(0)
    bands = _Bands(first) if "id" in first.columns else None
    frames = [dump.frame(i) for i in indices]
    top = max(float(np.max(f["y"] + f["radius"])) for f in frames) + 1.0
    (xlo, xhi), (ylo, yhi) = _system_limits(first, top)
    aspect = (xhi - xlo) / (yhi - ylo)
    ncols = 2 if aspect > 1.15 else 3
    ncols = min(ncols, len(frames))
    nrows = -(-len(frames) // ncols)
    panel_w = style.FULL_WIDTH / ncols
    fig, axes = plt.subplots(nrows, ncols, figsize=(style.FULL_WIDTH, nrows * panel_w / aspect + 0.45 * nrows),
                             squeeze=False, sharex=True, sharey=True)
    for k, (ax, frame, i) in enumerate(zip(axes.flat, frames, indices)):
        _discs(ax, frame["x"], frame["y"], frame["radius"], _colours(frame, bands))
        ax.set_xlim(xlo, xhi)
        ax.set_ylim(ylo, yhi)
        ax.set_aspect("equal")
        ax.grid(False)
        ax.set_title(f"({chr(97 + k)}) $t$ = {ftimes[i]:g}")
    for ax in axes.flat[len(frames):]:
        ax.set_visible(False)
    for ax in axes[-1, :]:
        ax.set_xlabel(style.X_LABEL)
    for ax in axes[:, 0]:
        ax.set_ylabel(style.Y_LABEL)
    fig.suptitle(run.label() + r"   (time in $\sqrt{d/g}$; intruder red, base blue)", y=1.0)
    fig.tight_layout()
    run.report.wrote(style.save(fig, out_dir, "snapshots", formats))


# --- fig. 8: phase-resolved rate --------------------------------------------------------------------

def plot_phase_rates(run, out_dir, formats):
    try:
        rates = run.phase_rates()
    except FileNotFoundError:
        run.report.note("no phase_rates.csv: phase-rate figure skipped")
        return
    except readers.FormatError as e:
        run.report.note(f"phase_rates.csv unreadable, skipped: {e}")
        return
    centers, vy, empty = prepare.phase_bars(rates)
    fig, ax = plt.subplots(figsize=(style.COLUMN_WIDTH * 1.3, 2.6))
    colours = np.where(np.nan_to_num(vy) >= 0, "#1b7837", "#b2182b")
    ax.bar(centers, np.nan_to_num(vy), width=0.85, color=colours, alpha=0.85)
    ax.plot(centers, vy, "-", color="0.2", lw=0.8)
    if empty.any():
        ax.plot(centers[empty], np.zeros(empty.sum()), "x", color="0.4", label="no samples")
        ax.legend(loc="lower left")
    ax.axhline(0.0, color="0.3", lw=0.6)
    for c in (5, 10, 15):
        ax.axvline(c, color="0.6", lw=0.5, ls=":")
    style.phase_axis(ax)
    ax.set_ylabel(r"mean $v_y$ [$\sqrt{g d}$]")
    ax.set_title(run.label())
    run.report.wrote(style.save(fig, out_dir, "phase_rates", formats))


# --- figs 9-11: fields --------------------------------------------------------------------------------

FIELD_ROWS = (
    ("phi", r"$\Phi$", "viridis", False),
    ("speed", r"$|\mathbf{v}|$ [$\sqrt{g d}$]", "magma", False),
    ("pressure", r"$P$ [$\rho g d^2$]", "cividis", False),
)


ARROW_SPACING = 2.5  # [d] between the velocity arrows drawn on the |v| maps, as the paper's figures 9-11


def velocity_arrows(ax, grids, j, vmax):
    """The mean velocity's direction and size on a |v| map: arrows every ARROW_SPACING, scaled so
    that a speed of vmax (the row's colour limit) spans 0.9 of the spacing; none where masked."""
    xs, ys = grids["x"], grids["y"]
    step = max(1, int(round(ARROW_SPACING / (xs[1] - xs[0])))) if len(xs) > 1 else 1
    gx, gy = np.meshgrid(xs[::step], ys[::step])
    u = grids["vx"][j][::step, ::step]
    v = grids["vy"][j][::step, ::step]
    length = 0.9 * step * (xs[1] - xs[0] if len(xs) > 1 else 1.0)
    ax.quiver(gx, gy, u, v, color="white", edgecolor="black", linewidth=0.3, angles="xy", scale_units="xy",
              scale=max(vmax, 1e-12) / length, width=0.006, headwidth=3.5, pivot="mid")


def field_data(run):
    """(grids, outline, outline source) for the field maps, or None when there is no fields.csv."""
    fields = run.fields()
    if fields is None:
        return None
    radius = float(readers.config_value(run.config, "fields.radius", 15.0))
    outline, source = run.intruder_outline()
    return prepare.field_grids(fields, radius=radius, outline=outline), outline, source


def plot_fields(run, out_dir, formats):
    try:
        data = field_data(run)
    except readers.FormatError as e:
        run.report.note(f"fields.csv unreadable, skipped: {e}")
        return
    if data is None:
        run.report.note("no fields.csv: field maps skipped")
        return
    grids, outline, source = data
    if outline is None:
        run.report.note("field maps: intruder outline unknown (no geometry.json, no dump); "
                        "only r > radius is masked")
    phases = grids["phases"]
    xs, ys = grids["x"], grids["y"]
    n = len(phases)
    dx = xs[1] - xs[0] if len(xs) > 1 else 1.0
    dy = ys[1] - ys[0] if len(ys) > 1 else 1.0
    extent = (xs[0] - dx / 2, xs[-1] + dx / 2, ys[0] - dy / 2, ys[-1] + dy / 2)
    panel = min(1.35, (style.FULL_WIDTH - 0.9) / n)
    fig, axes = plt.subplots(3, n, figsize=(panel * n + 0.9, 3 * panel + 0.6), squeeze=False,
                             sharex=True, sharey=True, constrained_layout=True)
    for row, (name, label, cmap, symmetric) in enumerate(FIELD_ROWS):
        vmin, vmax = prepare.shared_limits(grids[name], symmetric=symmetric)
        image = None
        for j in range(n):
            ax = axes[row, j]
            cm = plt.get_cmap(cmap).copy()
            cm.set_bad("white")
            image = ax.imshow(grids[name][j], origin="lower", extent=extent, cmap=cm, vmin=vmin,
                              vmax=vmax, interpolation="nearest")
            if name == "speed":
                velocity_arrows(ax, grids, j, vmax)
            if outline is not None:
                ax.add_patch(Polygon(outline, closed=True, facecolor="0.55", edgecolor="black", lw=0.6))
            ax.set_aspect("equal")
            ax.grid(False)
            ax.tick_params(labelsize=7)
            if row == 0:
                frames = grids["frames"][j]
                extra = f"\n{int(frames)} frames" if np.isfinite(frames) else ""
                ax.set_title(rf"$10\varphi/\pi$ = {phases[j]:g}" + extra, fontsize=8)
            if row == 2:
                ax.set_xlabel(r"$x - x_c$ [$d$]", fontsize=8)
            if j == 0:
                ax.set_ylabel(r"$y - y_c$ [$d$]", fontsize=8)
        bar = fig.colorbar(image, ax=axes[row, :].tolist(), shrink=0.9, pad=0.02)
        bar.set_label(label)
        bar.ax.tick_params(labelsize=7)
    fig.suptitle(run.label(), fontsize=9)
    run.report.wrote(style.save(fig, out_dir, "fields", formats))


# --- movie ------------------------------------------------------------------------------------------

def find_ffmpeg():
    """The ffmpeg executable the movie needs, or None."""
    return shutil.which("ffmpeg") or ("/usr/bin/ffmpeg" if os.path.exists("/usr/bin/ffmpeg") else None)


def path_until(trajectory, t):
    """The intruder's centre (x, y) from the start of the run to time t: the trail a movie frame
    at t draws."""
    shown = np.asarray(trajectory["t"]) <= t + 1e-9
    return np.asarray(trajectory["x"])[shown], np.asarray(trajectory["y"])[shown]


MOVIE_DPI = 120


class MovieFrames:
    """The movie's one figure, redrawn for each dump frame: the grains, the intruder's path so far
    and the time. Its size in pixels is fixed (no tight bounding box: the style's savefig.bbox
    would crop each frame to its contents, and ffmpeg reads raw frames of the size declared to it);
    `draw(i)` then `save_png` gives exactly the picture the movie holds as frame i."""

    def __init__(self, run):
        self.run = run
        self.dump = run.dump()
        self.times = run.frame_times()
        self.first = self.dump.frame(0)
        self.bands = _Bands(self.first) if "id" in self.first.columns else None
        top = float(np.max(self.first["y"] + self.first["radius"])) + 2.0
        (xlo, xhi), (ylo, yhi) = _system_limits(self.first, top)
        aspect = (xhi - xlo) / (yhi - ylo)
        width = 6.4
        # Whole pixels, even in both directions (H.264 with yuv420p needs even sizes).
        w_px = 2 * round(width * MOVIE_DPI / 2)
        h_px = 2 * round((width / aspect + 0.5) * MOVIE_DPI / 2)
        self.fig, ax = plt.subplots(figsize=(w_px / MOVIE_DPI, h_px / MOVIE_DPI), dpi=MOVIE_DPI)
        ax.set_xlim(xlo, xhi)
        ax.set_ylim(ylo, yhi)
        ax.set_aspect("equal")
        ax.grid(False)
        ax.set_xlabel(style.X_LABEL)
        ax.set_ylabel(style.Y_LABEL)
        self.ax = ax
        self.coll = _discs(ax, self.first["x"], self.first["y"], self.first["radius"],
                           _colours(self.first, self.bands), rasterize=False)
        # The intruder's path so far, over the grains: where the drive has taken it, up or down.
        self.trail, = ax.plot([], [], color="black", lw=0.8, zorder=5)
        self.title = ax.set_title("")
        self.fig.tight_layout()  # once, for the axes' place; every frame keeps the same canvas

    def __len__(self):
        return len(self.dump)

    @property
    def size(self):
        """(width, height) in pixels of every frame."""
        w, h = self.fig.get_size_inches() * MOVIE_DPI
        return int(round(w)), int(round(h))

    def draw(self, i):
        frame = self.first if i == 0 else self.dump.frame(i)
        if len(frame["x"]) != len(self.first["x"]):
            self.coll.remove()
            self.coll = _discs(self.ax, frame["x"], frame["y"], frame["radius"], _colours(frame, self.bands),
                               rasterize=False)
        else:
            self.coll.set_offsets(np.column_stack([frame["x"], frame["y"]]))
        if self.run.trajectory is not None:
            self.trail.set_data(*path_until(self.run.trajectory, self.times[i]))
        self.title.set_text(f"{self.run.label()}   $t$ = {self.times[i]:g}")

    def rgb(self):
        """The drawn frame's pixels, (height, width, 3) uint8: what is handed to ffmpeg."""
        self.fig.canvas.draw()
        return np.asarray(self.fig.canvas.buffer_rgba())[:, :, :3].copy()

    def save_png(self, path):
        with plt.rc_context({"savefig.bbox": "standard"}):
            self.fig.savefig(path, dpi=MOVIE_DPI)

    def close(self):
        plt.close(self.fig)


def write_movie(run, out_dir, fps=10):
    """movie.mp4: every dump frame, in order, at `fps`; written to a temporary name and renamed.
    Raises OSError when ffmpeg fails (its last message line says why)."""
    import subprocess
    ffmpeg = find_ffmpeg()
    if ffmpeg is None:
        run.report.note("ffmpeg not found: movie skipped (apt-get install ffmpeg)")
        return
    if run.dump() is None:
        run.report.note("no dumps/dump.lammpstrj: movie skipped")
        return
    frames = MovieFrames(run)
    os.makedirs(out_dir, exist_ok=True)
    path = os.path.join(out_dir, "movie.mp4")
    tmp = os.path.join(out_dir, f"movie.tmp.{os.getpid()}.mp4")
    w, h = frames.size
    # Raw RGB frames of exactly w x h on stdin; H.264, yuv420p so that every player shows it.
    command = [ffmpeg, "-loglevel", "error", "-y", "-f", "rawvideo", "-pix_fmt", "rgb24", "-s", f"{w}x{h}",
               "-r", str(fps), "-i", "pipe:0", "-c:v", "libx264", "-pix_fmt", "yuv420p", "-crf", "18",
               "-metadata", f"title={run.label()}", tmp]
    proc = subprocess.Popen(command, stdin=subprocess.PIPE, stderr=subprocess.PIPE)
    try:
        for i in range(len(frames)):
            frames.draw(i)
            pixels = frames.rgb()
            if pixels.shape != (h, w, 3):  # never: the canvas is fixed; a guard against garbling
                raise ValueError(f"movie frame {i} is {pixels.shape[1]}x{pixels.shape[0]}, not {w}x{h}")
            proc.stdin.write(pixels.tobytes())
        proc.stdin.close()
        err = proc.stderr.read().decode(errors="replace")
        if proc.wait() != 0:
            lines = err.strip().splitlines()
            raise OSError(f"ffmpeg failed writing {path}: {lines[-1] if lines else 'exit status ' + str(proc.returncode)}")
        os.replace(tmp, path)
    except BaseException:
        proc.kill()
        proc.wait()
        if os.path.exists(tmp):
            os.remove(tmp)
        raise
    finally:
        frames.close()
    run.report.wrote([path])


def plot_run(source, out_dir, formats, report, times=None, movie=False, frames=None):
    """A run's figures from its directory or from a live wiggle.Case (LiveRun; `frames`: the
    case.frame() dicts its snapshots and movie show)."""
    style.apply()
    run = LiveRun(source, report, frames) if is_live_case(source) else Run(source, report)
    plot_trajectory(run, out_dir, formats)
    plot_snapshots(run, out_dir, formats, times=times)
    plot_phase_rates(run, out_dir, formats)
    plot_fields(run, out_dir, formats)
    if movie:
        write_movie(run, out_dir)
    return run
