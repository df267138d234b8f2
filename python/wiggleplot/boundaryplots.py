"""The figure of a `wiggle boundary` directory (its boundary.json): a rise/sink map.

One row per search (per --over value; one row without --over), the varied key along x. Each probe
is a marker coloured by its verdict (rising, sinking, neutral: V_y indistinguishable from zero,
failed), labelled with its mean V_y and beds; each crossing is the span between the two probes that
bracket it. When the varied key is drive.period, each row also marks the cavity model's T_rise
(model.json of its runs: the paper's prediction of the crossing, docs/MODEL.md). With a single
search a second panel shows the probes' V_y with their standard errors."""
import json
import os

from wiggleplot import readers, style
from wiggleplot.style import plt

MODEL_COLOUR = "#2166ac"

VERDICT_STYLE = {  # colour, marker
    "rising": ("#1b7837", "^"),
    "sinking": ("#b2182b", "v"),
    "neutral": ("#878787", "o"),
    "failed": ("black", "x"),
    "undecided": ("#cccccc", "."),
}


def read_boundary(path):
    with open(path) as f:
        return json.load(f)


def _label(key):
    return {"drive.period": style.PERIOD_LABEL, "drive.amplitude": style.AMPLITUDE_LABEL}.get(key, key)


def model_t_rise(run_dir, over_key):
    """{--over value (None without --over): the cavity model's T_rise} from the runs in DIR/cases
    (each run's model.json, its config.toml for the --over value). A row whose runs disagree (the
    model depends on a key the search varies) gets no mark."""
    found = {}
    cases = os.path.join(run_dir, "cases")
    for name in sorted(os.listdir(cases)) if os.path.isdir(cases) else []:
        model = readers.read_model(os.path.join(cases, name))
        if not model or "T_rise" not in model:
            continue
        over = readers.config_value(readers.read_config(os.path.join(cases, name)), over_key) if over_key else None
        found.setdefault(over, set()).add(model["T_rise"])
    return {over: values.pop() for over, values in found.items() if len(values) == 1}


def _draw_map(ax, b, t_rise):
    searches = b["searches"]
    over = b["over_key"]
    ys = [s["over"] if over else 0.0 for s in searches]
    marked = [(t_rise[s["over"] if over else None], y) for s, y in zip(searches, ys)
              if (s["over"] if over else None) in t_rise]
    for t, y in marked:
        ax.plot([t], [y], marker="|", color=MODEL_COLOUR, ms=14, mew=1.5, zorder=3)
    for s, y in zip(searches, ys):
        for c in s["crossings"]:
            ax.plot([c["below"], c["above"]], [y, y], color="black", lw=3, solid_capstyle="butt", zorder=1)
        for p in s["probes"]:
            colour, marker = VERDICT_STYLE.get(p["verdict"], VERDICT_STYLE["undecided"])
            ax.scatter([p["value"]], [y], color=colour, marker=marker, s=36, zorder=2)
            if p.get("beds"):
                ax.annotate(f"{p['mean']:+.3f}\n{p['beds']}", (p["value"], y), textcoords="offset points",
                            xytext=(0, 7), ha="center", fontsize=5)
    pending = any(p["verdict"] == "undecided" for s in searches for p in s["probes"])
    for verdict in ("rising", "sinking", "neutral", "failed") + (("undecided",) if pending else ()):
        colour, marker = VERDICT_STYLE[verdict]
        label = "undecided (more beds to run)" if verdict == "undecided" else verdict
        ax.scatter([], [], color=colour, marker=marker, label=label)
    ax.plot([], [], color="black", lw=3, label="crossing (bracket)")
    if marked:
        ax.plot([], [], marker="|", color=MODEL_COLOUR, ms=10, mew=1.5, ls="none", label="cavity model's T_rise")
    ax.set_xlabel(_label(b["key"]))
    if over:
        ax.set_ylabel(_label(over))
        ax.set_yticks(ys)
        ax.margins(y=0.15)   # room above the top row for its probes' labels
    else:
        ax.set_yticks([])
    ax.legend(fontsize=6, loc="upper left", bbox_to_anchor=(1.01, 1.0))
    ax.set_title(f"where V_y changes sign ({b['rate']} rule; labels: mean V_y, beds)", fontsize=8)


def _draw_rates(ax, b, t_rise):
    s = b["searches"][0]
    if None in t_rise:
        ax.axvline(t_rise[None], color=MODEL_COLOUR, ls="--", lw=0.8, label="cavity model's T_rise")
        ax.legend(fontsize=6)
    probes = [p for p in s["probes"] if p.get("beds")]
    for p in probes:
        colour, marker = VERDICT_STYLE.get(p["verdict"], VERDICT_STYLE["undecided"])
        ax.errorbar([p["value"]], [p["mean"]], yerr=[1.96 * p["standard_error"]], color=colour, marker=marker,
                    ms=4, capsize=2)
        ax.scatter([p["value"]] * len(p["vy"]), p["vy"], color=colour, s=6, alpha=0.5)
    ax.axhline(0.0, color="black", lw=0.5)
    for c in s["crossings"]:
        ax.axvspan(c["below"], c["above"], color="#dddddd", zorder=0)
    ax.set_xlabel(_label(b["key"]))
    ax.set_ylabel(style.VY_LABEL)


def plot_boundary(run_dir, out_dir, formats, report):
    """Draws DIR/boundary.json into out_dir/boundary.<fmt>; returns nothing when there is none."""
    path = os.path.join(run_dir, "boundary.json")
    if not os.path.isfile(path):
        return
    b = read_boundary(path)
    single = not b["over_key"]
    rows = 1 if single else max(1, len(b["searches"]))
    fig, axes = plt.subplots(2 if single else 1, 1, figsize=(style.FULL_WIDTH, 3.6 if single else 1.2 + 0.5 * rows),
                             squeeze=False)
    t_rise = model_t_rise(run_dir, b["over_key"]) if b["key"] == "drive.period" else {}
    _draw_map(axes[0][0], b, t_rise)
    if single:
        _draw_rates(axes[1][0], b, t_rise)
    fig.tight_layout()
    report.wrote(style.save(fig, out_dir, "boundary", formats))
