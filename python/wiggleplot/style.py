"""One look for every figure: sizes for a printed page (a full-width figure is 7 in wide), fonts
readable at that size, colours chosen once, and the saver that writes each requested format."""
import os

import matplotlib

matplotlib.use(os.environ.get("MPLBACKEND", "Agg"))
import matplotlib.pyplot as plt  # noqa: E402

FULL_WIDTH = 7.0    # inches: a page-wide figure
COLUMN_WIDTH = 3.4  # inches: a one-column figure

# Axis labels with units (d = 1, g = 1: lengths in d, times in sqrt(d/g), speeds in sqrt(g d)).
T_LABEL = r"$t$ [$\sqrt{d/g}$]"
PERIOD_LABEL = r"$T$ [$\sqrt{d/g}$]"
AMPLITUDE_LABEL = r"$A$ [$d$]"
DY_LABEL = r"$y(t) - y(0)$ [$d$]"
VY_LABEL = r"$V_y$ [$\sqrt{g d}$]"
# The drive's phase phi = 2 pi t / T in the paper's units, 20 to a period (phase_rates.csv's phase_center).
PHASE_LABEL = r"phase $10\varphi/\pi$, $\varphi = 2\pi t/T$ (20 = one period)"
X_LABEL = r"$x$ [$d$]"
Y_LABEL = r"$y$ [$d$]"

GRAIN_COLOURS = ("#d9c9a3", "#b8a57a")  # alternating bands of grains (by initial height)
BASE_COLOUR = "#2b4c9b"                 # the frozen base row (blue, as in the paper's fig. 1)
INTRUDER_COLOUR = "#c8102e"             # intruder atoms
MODEL_COLOUR = "black"

RC = {
    "font.size": 9,
    "axes.labelsize": 9,
    "axes.titlesize": 9,
    "legend.fontsize": 7.5,
    "xtick.labelsize": 8,
    "ytick.labelsize": 8,
    "lines.linewidth": 1.2,
    "lines.markersize": 4,
    "axes.grid": True,
    "grid.alpha": 0.3,
    "grid.linewidth": 0.5,
    "legend.frameon": False,
    "figure.dpi": 100,
    "savefig.dpi": 200,
    "savefig.bbox": "tight",
    "pdf.fonttype": 42,
    "image.cmap": "viridis",
}


def apply():
    plt.rcParams.update(RC)


# How far along a colour map a series may go: the maps' light ends (viridis's yellow-green, plasma's
# yellow) are hard to see on white; up to 0.72 every colour has a contrast ratio of at least 2.2
# against the white page (WCAG's formula; viridis at 0.9 has 1.5).
SERIES_MAP_END = 0.72
MIN_CONTRAST_ON_WHITE = 2.2


def contrast_on_white(colour):
    """WCAG contrast ratio of an RGB(A) colour against white (1: invisible, 21: black)."""
    def linear(c):
        return c / 12.92 if c <= 0.03928 else ((c + 0.055) / 1.055) ** 2.4
    r, g, b = (linear(c) for c in colour[:3])
    return 1.05 / (0.2126 * r + 0.7152 * g + 0.0722 * b + 0.05)


def series_colours(n, cmap="viridis"):
    """n colours along a perceptually uniform map, dark to light but never the pale end."""
    if n <= 1:
        return [plt.get_cmap(cmap)(0.25)]
    return [plt.get_cmap(cmap)(SERIES_MAP_END * i / (n - 1)) for i in range(n)]


def save(fig, out_dir, name, formats):
    """Write fig as out_dir/name.<fmt> for each format; returns the paths written."""
    os.makedirs(out_dir, exist_ok=True)
    paths = []
    for fmt in formats:
        path = os.path.join(out_dir, f"{name}.{fmt}")
        fig.savefig(path, format=fmt)
        paths.append(path)
    plt.close(fig)
    return paths


def fmt_value(v):
    """3 -> '3', 0.25 -> '0.25', 'disk' -> 'disk'."""
    if isinstance(v, float):
        return f"{v:g}"
    return str(v)


def phase_axis(ax):
    """A phase axis over one period (0-20 in 10 phi / pi), labelled with what phi is, and on top where
    the intruder is at each phase (x = x0 + A sin phi)."""
    ax.set_xlim(0, 20)
    ax.set_xticks(range(0, 21, 5))
    ax.set_xlabel(PHASE_LABEL)
    top = ax.secondary_xaxis("top")
    top.set_xticks([0, 5, 10, 15, 20])
    top.set_xticklabels(["centre →", "right end", "centre ←", "left end", "centre →"], fontsize=6.5)
    top.tick_params(length=2, colors="0.35")
    return top

