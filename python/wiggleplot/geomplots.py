"""Paper fig. 13: each intruder shape's outline and atoms, with y0 (top of the outline) and the
point(s) of no return y_nr marked, from `wiggle model --shape S --geometry FILE.json` files."""
import numpy as np
from matplotlib.collections import EllipseCollection

from wiggleplot import readers, style
from wiggleplot.style import plt


def geometry_marks(geom):
    """The marks drawn on one shape: {'y0', 'nr': [(x, y_nr, side), ...], 'l': [...]} with the point
    of no return placed at the outline's extreme x on its side (where the tangent is vertical)."""
    outline = geom["outline"]
    y0 = float(geom.get("y0", outline[:, 1].max()))
    marks = {"y0": y0, "nr": [], "l": []}
    for side, x in (("left", float(outline[:, 0].min())), ("right", float(outline[:, 0].max()))):
        key = f"y_nr_{side}"
        if key in geom:
            y_nr = float(geom[key])
            marks["nr"].append((x, y_nr, side))
            marks["l"].append(y0 - y_nr)
    return marks


def plot_geometries(paths, out_dir, formats, report, name="geometry"):
    style.apply()
    geoms = []
    for p in paths:
        try:
            geoms.append(readers.read_geometry(p))
        except (OSError, ValueError, readers.FormatError) as e:
            report.note(f"{p} unreadable, skipped: {e}")
    if not geoms:
        report.note("no readable geometry file: geometry figure skipped")
        return
    n = len(geoms)
    ncols = min(n, 5)
    nrows = -(-n // ncols)
    half = max(float(np.abs(g["outline"]).max()) for g in geoms) + 1.0
    fig, axes = plt.subplots(nrows, ncols, figsize=(min(style.FULL_WIDTH, 1.7 * ncols), 1.95 * nrows + 0.2),
                             squeeze=False, sharex=True, sharey=True)
    for ax in axes.flat[n:]:
        ax.set_visible(False)
    for ax, g in zip(axes.flat, geoms):
        outline = np.vstack([g["outline"], g["outline"][:1]])
        atoms = g["atoms"]
        r = float(g.get("atom_radius", 0.25))
        coll = EllipseCollection(np.full(len(atoms), 2 * r), np.full(len(atoms), 2 * r),
                                 np.zeros(len(atoms)), units="xy", offsets=atoms,
                                 offset_transform=ax.transData, facecolors=style.INTRUDER_COLOUR,
                                 edgecolors="none", alpha=0.55)
        ax.add_collection(coll)
        ax.plot(outline[:, 0], outline[:, 1], "-", color="black", lw=0.9)
        marks = geometry_marks(g)
        ax.axhline(marks["y0"], color="#1b9e77", lw=0.8, ls="--")
        ax.text(-half + 0.2, marks["y0"] + 0.25, r"$y_0$", color="#1b9e77", fontsize=8)
        for x, y_nr, side in marks["nr"]:
            ax.plot([x], [y_nr], "o", color="#7570b3", ms=5, zorder=5)
            ax.axhline(y_nr, color="#7570b3", lw=0.6, ls=":")
            ax.annotate("", xy=(x, y_nr), xytext=(x, marks["y0"]),
                        arrowprops=dict(arrowstyle="<->", color="#7570b3", lw=0.8))
        if marks["nr"]:
            x, y_nr, _ = marks["nr"][-1]
            ax.text(half - 0.2, y_nr - 0.35, r"$y_{nr}$", color="#7570b3", fontsize=8, ha="right", va="top")
        ls = sorted(set(round(v, 3) for v in marks["l"]))
        l_text = "/".join(f"{v:.2f}" for v in ls)
        t_rise = g.get("T_rise_left"), g.get("T_rise_right")
        t_text = "/".join(sorted({f"{v:.2f}" for v in t_rise if v is not None}))
        ax.set_title(f"{g.get('shape', '?')}\n$l$ = {l_text}, $T_{{rise}}$ = {t_text}", fontsize=8)
        ax.set_xlim(-half, half)
        ax.set_ylim(-half, half)
        ax.set_aspect("equal")
        ax.tick_params(labelsize=7)
    for ax in axes[-1, :]:
        ax.set_xlabel(r"$x$ [$d$]")
    for ax in axes[:, 0]:
        ax.set_ylabel(r"$y$ [$d$]")
    fig.tight_layout()
    report.wrote(style.save(fig, out_dir, name, formats))
