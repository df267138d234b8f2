"""The measured tables of study/VALIDATION.md, docs/PERFORMANCE.md and the results folders' READMEs:
which folders, which cases, what makes a row and a column (the kinds: table_kinds.py), and the
rise/sink boundaries that `wiggle boundary` found. Adding a table is a few lines in TABLES and its
two markers in the document; for example Table 1 read over t = 100-1000 from a folder of t = 1000
runs would be

    shape_by_period("depth_table1_t100_1000", ["results/paper_depth/table1_t1000"], {}, True,
                    value=chord(100, 1000)),
"""
import json
import os

from cases import (DEPTH_A3, DEPTH_A5, DEPTH_FRICTION, DEPTH_SMALL_A, ROOT, SHAPES, T1000_BEDS, T1000_WINDOWS, chord,
                   head_lines, load, row_line, slope, y_at)
from scatter import depth_sigma
from table_kinds import (amplitude_threshold, column, fmt, listing, paired_steps, phase_column, pivot,
                         shape_by_period, windows)


BED_PROTOCOL = {("poured", 20.0, 0.0): "poured, preset's protocol", ("poured", 40.0, 2.0): "poured, fast protocol",
                ("carved", 40.0, 2.0): "carved, fast protocol"}


def protocol(c):
    return BED_PROTOCOL[(c.get("bed.cavity"), c.get("bed.batch_height"), c.get("bed.relax_damping"))]


AMPLITUDES = [0.5, 1.0, 3.0, 5.0]          # A = 0.5 and 1 (paper_depth_small_amplitude.toml), figure 5's 3, Table 1's 5
AMPLITUDE_PERIODS = [1.0, 3.0, 5.0, 8.0]
FRICTION_MUS = [0.0, 0.1, 0.3, 0.5]
FRICTION_ROWS = [(shape, t) for shape in SHAPES for t in (3.0, 5.0)]

TABLES = [
    # ---- study/VALIDATION.md, the small preset (60 d wide, intruder 25 d deep)
    {"name": "small_fig5", "kind": listing, "sources": ["study/figures/small_fig5_results.csv"],
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
    # ---- study/VALIDATION.md, at the paper's depth (configs/paper_depth.toml: 60 d wide, 105 d deep)
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


# ---- the rise/sink boundaries found by `wiggle boundary` (boundary.json of each search)

BOUNDARIES = [("results/boundary/small_pd_disk", "disk", "small preset"),
              ("results/boundary/small_pd_triangle", "triangle", "small preset"),
              ("results/boundary/depth_disk_A5", "disk", "paper-depth preset")]


def boundary_table(spec):
    """One row per search (preset, shape, amplitude): where V_y turns from sinking to rising, the
    periods where it is indistinguishable from zero, and the runs it took."""
    head = ["preset", "shape", "A", "sinking -> rising", "V_y indistinguishable from zero at T", "runs"]
    lines = head_lines(head)
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
            lines.append(row_line([preset, shape, f"{amplitude:g}", crossing, bands,
                                     str(search["cost"]["runs"])]))
    rules = []
    for folder, _, _ in BOUNDARIES:
        with open(os.path.join(ROOT, folder, "boundary.json")) as f:
            study = json.load(f)
        rule = study["rule"] + (f" (one bed's scatter taken as {study['known_scatter']:g})" if study["known_scatter"] else "")
        if rule not in rules:
            rules.append(rule)
    lines += ["", "(a period sinks or rises when, by each search's boundary.json: " + "; ".join(rules) + ")"]
    return lines, [b[0] for b in BOUNDARIES]


TABLES.append({"name": "boundaries", "kind": boundary_table, "sources": [b[0] for b in BOUNDARIES]})
