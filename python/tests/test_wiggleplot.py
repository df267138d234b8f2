"""Tests of wiggleplot on synthetic inputs with known numbers (tests/synthetic.py): the data behind
each figure first, then that every figure file is written and non-empty."""
import contextlib
import io
import json
import math
import os
import shutil
import tempfile
import unittest
from unittest import mock

import numpy as np

from tests import synthetic
from wiggleplot import cli, geomplots, prepare, readers, report, runplots, style, sweepplots
from wiggleplot.report import Report


def quiet_report():
    return Report(quiet=True)


class DataDirs(unittest.TestCase):
    @classmethod
    def setUpClass(cls):
        cls.tmp = tempfile.mkdtemp(prefix="wiggleplot-test-")
        cls.run_dir = os.path.join(cls.tmp, "run")
        cls.summary = synthetic.write_run(cls.run_dir)
        cls.sweep_dir = os.path.join(cls.tmp, "sweep")
        synthetic.write_sweep(cls.sweep_dir)
        cls.sweep_mu_dir = os.path.join(cls.tmp, "sweep_mu")
        synthetic.write_sweep(cls.sweep_mu_dir, with_runs=False, mus=(0.0, 0.1, 0.3))
        cls.geometry = synthetic.write_geometries(os.path.join(cls.tmp, "geometry"))

    @classmethod
    def tearDownClass(cls):
        shutil.rmtree(cls.tmp, ignore_errors=True)


class ReaderTest(DataDirs):
    def test_table_parses_numbers_and_empty_cells(self):
        rates = readers.read_phase_rates(self.run_dir)
        self.assertEqual(len(rates["bin"]), 20)
        self.assertTrue(math.isnan(rates["vy_mean"][synthetic.EMPTY_BIN]))
        self.assertAlmostEqual(rates["vy_mean"][2], synthetic.phase_rate(2.5), places=9)

    def test_results_keep_strings(self):
        results = readers.read_results(self.sweep_dir)
        self.assertEqual(results["status"][-1], "failed")
        self.assertTrue(math.isnan(results["vy"][-1]))
        self.assertEqual(set(results[prepare.SHAPE].tolist()), {"disk", "triangle"})

    def test_dump_index_and_frames_sorted_by_id(self):
        dump = readers.Dump(os.path.join(self.run_dir, "dumps", "dump.lammpstrj"))
        self.assertEqual(dump.steps, [round(t / synthetic.DT) for t in synthetic.DUMP_TIMES])
        frame = dump.frame(1)
        ids, types, x, y, r = synthetic.dump_frame_atoms(synthetic.DUMP_TIMES[1])
        np.testing.assert_array_equal(frame["id"], ids)
        np.testing.assert_array_equal(frame["type"], types)
        np.testing.assert_allclose(frame["x"], x, atol=1e-6)
        np.testing.assert_allclose(frame["radius"], r, atol=1e-4)

    def test_truncated_dump_is_a_format_error(self):
        path = os.path.join(self.tmp, "bad.lammpstrj")
        with open(os.path.join(self.run_dir, "dumps", "dump.lammpstrj")) as f:
            lines = f.readlines()
        with open(path, "w") as f:
            f.writelines(lines[:40])
        with self.assertRaises(readers.FormatError):
            readers.Dump(path).frame(0)


class RunDataTest(DataDirs):
    def test_rate_lines_follow_summary(self):
        traj = readers.read_trajectory(self.run_dir)
        lines = prepare.rate_lines(self.summary, traj)
        tt, yy, v = lines["vy"]
        self.assertAlmostEqual(v, synthetic.SLOPE, places=9)
        self.assertAlmostEqual((yy[1] - yy[0]) / (tt[1] - tt[0]), synthetic.SLOPE, places=9)
        y0 = synthetic.traj_xy(0.0)[1]
        self.assertAlmostEqual(yy[0], self.summary["y_initial"] - y0, places=9)
        tt, yy, v = lines["slope"]
        self.assertAlmostEqual((yy[1] - yy[0]) / (tt[1] - tt[0]), synthetic.SLOPE * 1.01, places=9)
        # The least-squares line of the given slope passes through the mean of the fitted samples.
        t, dy = prepare.displacement(traj)
        inside = (t >= 10) & (t <= 100)
        at_mean = yy[0] + v * (t[inside].mean() - tt[0])
        self.assertAlmostEqual(at_mean, dy[inside].mean(), places=9)

    def test_settled_chord_ends_at_t_settled_on_the_trajectory(self):
        traj = readers.read_trajectory(self.run_dir)
        self.assertNotIn("settled", prepare.rate_lines(self.summary, traj))  # a summary before the rule
        unsettled = dict(self.summary, settled=False, t_settled=100.0, vy_settled=self.summary["vy"])
        self.assertNotIn("settled", prepare.rate_lines(unsettled, traj))
        settled = dict(self.summary, settled=True, t_settled=60.0, vy_settled=0.5)
        tt, yy, v = prepare.rate_lines(settled, traj)["settled"]
        self.assertEqual(v, 0.5)
        self.assertEqual(list(tt), [10.0, 60.0])
        t, dy = prepare.displacement(traj)
        self.assertAlmostEqual(yy[1], float(np.interp(60.0, t, dy)), places=12)
        self.assertEqual(yy[0], prepare.rate_lines(settled, traj)["vy"][1][0])

    def test_the_trajectory_names_the_models_t_rise_and_draws_no_model_rate(self):
        # Issue 80: the model's V_y drawn on the trajectory read as a prediction of the run; only
        # where rising starts is the model's to say.
        figures = self.trajectory_figures(self.run_dir)
        ax = figures["trajectory"].axes[0]
        labels = [line.get_label() for line in ax.get_lines()]
        self.assertTrue(any("cavity model: rising" in l and "T_{rise}" in l for l in labels), labels)
        model_lines = [line for line in ax.get_lines() if "cavity model" in line.get_label()]
        self.assertTrue(all(len(line.get_xdata()) == 0 for line in model_lines), "a model line was drawn")
        from matplotlib import pyplot
        pyplot.close(figures["trajectory"])

    def trajectory_figures(self, run_dir):
        """{name: figure} that plot_trajectory draws for run_dir, kept instead of saved (close them)."""
        figures = {}

        def keep(fig, out_dir, name, formats):
            figures[name] = fig
            return []

        with mock.patch.object(runplots.style, "save", keep):
            runplots.plot_trajectory(runplots.Run(run_dir, quiet_report()), self.tmp, ("png",))
        return figures

    def test_a_turning_intruders_trajectory_shows_how_far_it_turned(self):
        from matplotlib import pyplot
        locked = self.trajectory_figures(self.run_dir)["trajectory"]
        self.assertEqual(len(locked.axes), 1)  # locked: no turn to show
        pyplot.close(locked)
        turning = os.path.join(self.tmp, "turning")
        synthetic.write_run(turning, with_fields=False, with_dump=False)
        path = os.path.join(turning, "trajectory.csv")
        with open(path) as f:
            rows = f.read().splitlines()
        with open(path, "w") as f:  # the columns a turning run adds: angle [rad], omega
            turned = [f"{r},{0.01 * i:.10g},0.01" for i, r in enumerate(rows[1:])]
            f.write("\n".join([rows[0] + ",angle,omega"] + turned) + "\n")
        figures = self.trajectory_figures(turning)
        turn = figures["trajectory"].axes[1]
        self.assertEqual(turn.get_ylabel(), "turned [degrees]")
        self.assertAlmostEqual(turn.get_lines()[0].get_ydata()[-1], np.degrees(0.01 * 400), places=9)
        pyplot.close(figures["trajectory"])

    def test_phase_axes_say_what_the_phase_is_and_where_the_intruder_is(self):
        fig, ax = style.plt.subplots()
        top = style.phase_axis(ax)
        self.assertIn(r"\varphi = 2\pi t/T", ax.get_xlabel())
        self.assertIn("one period", ax.get_xlabel())
        self.assertEqual([t.get_text() for t in top.get_xticklabels()][:2], ["centre →", "right end"])
        self.assertEqual(ax.get_xlim(), (0.0, 20.0))
        style.plt.close(fig)

    def test_phase_bars_blank_empty_bins(self):
        centers, vy, empty = prepare.phase_bars(readers.read_phase_rates(self.run_dir))
        np.testing.assert_allclose(centers, np.arange(20) + 0.5)
        self.assertTrue(empty[synthetic.EMPTY_BIN] and empty.sum() == 1)
        self.assertTrue(np.isnan(vy[synthetic.EMPTY_BIN]))
        np.testing.assert_allclose(vy[~empty], synthetic.phase_rate(centers[~empty]), atol=1e-9)

    def test_field_grids_values_and_masks(self):
        fields = readers.read_fields(self.run_dir)
        outline = prepare.envelope_of_atoms(synthetic.disk_atoms(), synthetic.ATOM_R)
        grids = prepare.field_grids(fields, radius=15.0, outline=outline)
        np.testing.assert_array_equal(grids["phases"], synthetic.FIELD_PHASES)
        xs, ys = grids["x"], grids["y"]
        gx, gy = np.meshgrid(xs, ys)
        r = np.hypot(gx, gy)
        for k, p in enumerate(synthetic.FIELD_PHASES):
            phi, vx, vy, sxx, _, syy = synthetic.field_values(p, gx, gy)
            ok = ~grids["phi"].mask[k]
            np.testing.assert_allclose(grids["phi"][k][ok], phi[ok], atol=1e-6)
            np.testing.assert_allclose(grids["speed"][k][ok], np.hypot(vx, vy)[ok], atol=1e-6)
            np.testing.assert_allclose(grids["pressure"][k][ok], (-(sxx + syy) / 2)[ok], atol=1e-5)
            for name in ("phi", "speed", "pressure"):
                mask = grids[name].mask[k]
                self.assertTrue(mask[r > 15.0].all(), "points beyond r = 15 must be masked")
                self.assertTrue(mask[r < synthetic.DISK_RADIUS - 0.01].all(), "intruder must be masked")
                self.assertFalse(mask[(r > synthetic.DISK_RADIUS + 0.5) & (r <= 15.0)].any())
        self.assertTrue(np.all(grids["frames"] == 50))

    def test_envelope_of_atoms_matches_outer_radius(self):
        hull = prepare.envelope_of_atoms(synthetic.disk_atoms(), synthetic.ATOM_R)
        radii = np.hypot(hull[:, 0], hull[:, 1])
        self.assertLess(radii.max(), synthetic.DISK_RADIUS + 1e-9)
        self.assertGreater(radii.min(), synthetic.DISK_RADIUS - 0.1)

    def test_outline_from_dump_is_centred_on_the_trajectory(self):
        run = runplots.Run(self.run_dir, quiet_report())
        outline, source = run.intruder_outline()
        self.assertEqual(source, "dump atoms")
        np.testing.assert_allclose(outline.mean(axis=0), [0, 0], atol=0.15)
        self.assertAlmostEqual(np.hypot(outline[:, 0], outline[:, 1]).max(), synthetic.DISK_RADIUS, places=6)

    def test_frame_choice(self):
        self.assertEqual(prepare.spread_frames(3), [0, 1, 2])
        self.assertEqual(prepare.spread_frames(11, 6), [0, 2, 4, 6, 8, 10])
        self.assertEqual(prepare.frames_near([0, 50, 100], [40, 100, 90]), [1, 2])


class SweepDataTest(DataDirs):
    def test_aggregate_averages_seeds_and_drops_failed(self):
        results = readers.read_results(self.sweep_dir)
        records = prepare.aggregate(results, [prepare.SHAPE, prepare.AMPLITUDE, prepare.PERIOD])
        self.assertEqual(len(records), 2 * 2 * 4)
        for rec in records:
            j = synthetic.SWEEP_PERIODS.index(rec[prepare.PERIOD])
            expected = synthetic.BASE[rec[prepare.SHAPE]][rec[prepare.AMPLITUDE]][j]
            self.assertAlmostEqual(rec["vy"], expected, places=12)
            self.assertAlmostEqual(rec["std"], synthetic.SEED_OFFSET * math.sqrt(2), places=12)
            self.assertEqual(rec["n"], 2)
            self.assertNotIn(synthetic.FAILED_CASE, rec["cases"])

    def test_t_rising_interpolates_the_zero_crossing(self):
        self.assertAlmostEqual(prepare.t_rising([1, 2, 4, 8], [-0.02, -0.01, 0.03, 0.05])[0], 2.5)
        t, lo, hi, note = prepare.t_rising([1, 2, 4, 8], [-0.04, -0.03, -0.02, -0.01])
        self.assertTrue(math.isnan(t) and lo == 8 and note == "V_y <= 0 at the largest T = 8")
        t, lo, hi, note = prepare.t_rising([1, 2], [0.01, 0.02])
        self.assertTrue(math.isnan(t) and hi == 1)
        # The last crossing counts: V_y > 0 at a small T followed by sinking is a transient, not rising.
        t, lo, hi, note = prepare.t_rising([1, 2, 3, 4], [-1, 1, -1, 3])
        self.assertAlmostEqual(t, 3.25)
        self.assertEqual((lo, hi, note), (3.0, 4.0, "V_y > 0 also at T = 2"))

    def test_table1(self):
        sweep = sweepplots.Sweep(self.sweep_dir, quiet_report())
        rows = {r["shape"]: r for r in sweepplots.table1(sweep)}
        self.assertAlmostEqual(rows["disk"]["T_rising_observed"], synthetic.DISK_T_RISING, places=12)
        self.assertEqual(rows["disk"]["A"], 5.0)
        self.assertEqual((rows["disk"]["T_below"], rows["disk"]["T_above"]), (2.0, 4.0))
        self.assertAlmostEqual(rows["disk"]["T_rise_model"], synthetic.T_RISE)
        self.assertTrue(math.isnan(rows["triangle"]["T_rising_observed"]))
        self.assertTrue(math.isnan(rows["triangle"]["T_rise_model"]))  # no model.json for it
        self.assertEqual(sweep.model("disk")["amplitude"], 5.0)  # the largest amplitude's model

    def test_table1_texts_fit_their_cells(self):
        # The notes are long ("rises already at the smallest T = 1") beside short cells ("< 1"):
        # each text must lie inside its own cell, not run over its neighbours.
        nan = float("nan")
        rows = [{"shape": "disk", "A": 3.0, "mu": "", "l": 3.5, "T_rise_model": 2.1, "T_rising_observed": nan,
                 "T_below": nan, "T_above": 1.0, "note": "rises already at the smallest T = 1"},
                {"shape": "rect_wide", "A": 3.0, "mu": "", "l": "3.1/3.3", "T_rise_model": 4.25,
                 "T_rising_observed": 4.6, "T_below": 4.0, "T_above": 5.0,
                 "note": "V_y > 0 also at T = 0.5, 1, 1.5, 2, 2.5"}]
        fig = sweepplots.table1_figure(rows)
        fig.canvas.draw()
        renderer = fig.canvas.get_renderer()
        table = fig.axes[0].tables[0]
        for key, cell in table.get_celld().items():
            text = cell.get_text().get_window_extent(renderer)
            box = cell.get_window_extent(renderer)
            self.assertTrue(text.x0 >= box.x0 - 0.5 and text.x1 <= box.x1 + 0.5 and text.y0 >= box.y0 - 0.5
                            and text.y1 <= box.y1 + 0.5, f"cell {key} {cell.get_text().get_text()!r}: text "
                            f"{text.x0:.0f}-{text.x1:.0f} x {text.y0:.0f}-{text.y1:.0f} outside its cell "
                            f"{box.x0:.0f}-{box.x1:.0f} x {box.y0:.0f}-{box.y1:.0f}")
        from matplotlib import pyplot
        pyplot.close(fig)

    def test_table1_texts_stay_on_one_line(self):
        # Issue 53: notes wrapped at 34 characters broke "rises already at the smallest T = 2" in two.
        nan = float("nan")
        rows = [{"shape": "disk", "A": 3.0, "mu": "", "l": 3.5, "T_rise_model": 2.8, "T_rising_observed": nan,
                 "T_below": nan, "T_above": 2.0, "note": "rises already at the smallest T = 2"},
                {"shape": "square", "A": 3.0, "mu": "", "l": 6.5, "T_rise_model": 3.7, "T_rising_observed": 2.6,
                 "T_below": 2.5, "T_above": 3.0, "note": "V_y > 0 also at T = 0.5, 1, 1.5, 2, 2.5"}]
        fig = sweepplots.table1_figure(rows)
        texts = [cell.get_text().get_text() for cell in fig.axes[0].tables[0].get_celld().values()]
        from matplotlib import pyplot
        pyplot.close(fig)
        self.assertEqual([t for t in texts if "\n" in t], [])

    def test_figure_5_keeps_every_curve_inside_its_axes(self):
        # Issue 53: the cavity model's V_y is ten times the measured one and drops to 0 at T_max: on
        # the data's scale it ran off the top and came down as vertical dashed lines. The committed
        # paper-depth sweep has both.
        sweep_dir = os.path.join(os.path.dirname(__file__), "..", "..", "results", "paper_depth", "fig5")
        figures = {}

        def keep(fig, out_dir, name, formats):
            figures[name] = fig
            return []

        with mock.patch.object(sweepplots.style, "save", keep):
            sweepplots.plot_rate_vs_period(sweepplots.Sweep(sweep_dir, quiet_report()), self.tmp, ("png",))
        fig = figures["rate_vs_period"]
        models = 0
        for ax in fig.axes:
            if not ax.get_visible():
                continue
            x_lo, x_hi = ax.get_xlim()
            y_lo, y_hi = ax.get_ylim()
            for line in ax.get_lines():
                if line.get_transform() != ax.transData:  # the zero line, in axes coordinates along x
                    continue
                x, y = np.asarray(line.get_xdata(), float), np.asarray(line.get_ydata(), float)
                drawn = np.isfinite(x) & np.isfinite(y)
                what = f"{line.get_label()!r} in {ax.get_title() or 'a model axis'}"
                self.assertTrue(np.all((x[drawn] >= x_lo) & (x[drawn] <= x_hi)), f"{what} leaves the axes in x")
                self.assertTrue(np.all((y[drawn] >= y_lo) & (y[drawn] <= y_hi)), f"{what} leaves the axes in y")
            # The cavity model as its T_rise only (issue 80): a dashed line across the panel at it,
            # no curve of its V_y on these axes or on a second one scaled to fit.
            for line in ax.get_lines():
                if "cavity model" in line.get_label() or (line.get_transform() != ax.transData
                                                          and line.get_linestyle() == "--"):
                    models += 1
                    self.assertEqual(len(set(np.asarray(line.get_xdata(), float))), 1, "not a T_rise marker")
        self.assertEqual(len([ax for ax in fig.axes if ax.get_visible() and ax.get_ylabel() == "cavity model"]), 0)
        self.assertEqual(models, 5)  # one per shape: every T_rise (2.8-4.5) lies within the periods run
        from matplotlib import pyplot
        pyplot.close(fig)

    def test_series_colours_are_readable_on_white(self):
        # Issue 53: the last period's line, the colour maps' yellow end, was hard to see on white.
        from wiggleplot import style
        for cmap in ("viridis", "plasma"):
            for n in range(1, 11):
                for colour in style.series_colours(n, cmap):
                    self.assertGreaterEqual(style.contrast_on_white(colour), style.MIN_CONTRAST_ON_WHITE,
                                            f"{cmap}, {n} series: {colour}")

    def test_a_case_with_a_torn_summary_is_not_done(self):
        # results.csv says ok, but the case's summary.json is garbage: the sweep would run it again
        # (caseFinished), so the figures must not count it either.
        d = os.path.join(self.tmp, "torn")
        rows = synthetic.write_sweep(d, with_runs=False)
        with open(os.path.join(d, rows[0][1], "summary.json"), "w") as f:
            f.write("{garbage")
        results = readers.read_results(d)
        self.assertEqual(results["status"][0], "pending")
        self.assertTrue(math.isnan(results["vy"][0]))
        self.assertEqual(results["status"][1], "ok")
        self.assertFalse(prepare.usable_rows(results)[0])

    def test_report_shows_each_cases_warnings(self):
        from wiggleplot import htmlreport
        from wiggleplot.data import load_sweep
        status = {"name": "s", "sweep_running": False, "eta_s": None, "text": "",
                  "cases": [{"name": "case_001", "status": "ok", "error": "", "vy": 0.1, "wall_s": 1.0,
                             "fraction": None, "warnings": ["V_y is measured over 0.9 drive periods"]}]}
        page = htmlreport.render(self.sweep_dir, status, load_sweep(self.sweep_dir), [], [])
        self.assertIn("warning: V_y is measured over 0.9 drive periods", page)

    def test_report_marks_only_the_cases_no_process_runs(self):
        from wiggleplot import htmlreport
        from wiggleplot.data import load_sweep
        running = {"status": "running", "error": "", "vy": None, "wall_s": None, "fraction": 0.25, "warnings": []}
        status = {"name": "s", "sweep_running": True, "eta_s": None, "text": "",
                  "cases": [dict(running, name="case_001", interrupted=False),
                            dict(running, name="case_002", interrupted=True)]}
        page = htmlreport.render(self.sweep_dir, status, load_sweep(self.sweep_dir), [], [])
        self.assertEqual(page.count("running (25 %)"), 1)
        self.assertEqual(page.count("running (25 %; interrupted)"), 1)

    def test_rate_map_grid(self):
        sweep = sweepplots.Sweep(self.sweep_dir, quiet_report())
        amps, periods, grid, counts = sweepplots.rate_map(sweep, "triangle", sweep.rows)
        np.testing.assert_array_equal(amps, synthetic.SWEEP_AMPS)
        np.testing.assert_array_equal(periods, synthetic.SWEEP_PERIODS)
        for i, a in enumerate(amps):
            np.testing.assert_allclose(grid[i], synthetic.BASE["triangle"][a], atol=1e-12)
        self.assertTrue((counts == 2).all())

    def test_curves_and_friction_selection(self):
        sweep = sweepplots.Sweep(self.sweep_mu_dir, quiet_report())
        rows, mu = sweep.main_mu_rows()
        self.assertIn(mu, (0.0, 0.1, 0.3))
        self.assertEqual(int(rows.sum()), 2 * 2 * 4 * 2)
        rows, amplitude = sweepplots.mu_rows(sweep)
        self.assertEqual(amplitude, 5.0)  # every A has all three mu: the larger wins
        curves = sweepplots.curves_by(sweep, rows, prepare.MU)
        T, vy, std, n, se = curves["disk"][0.3]
        np.testing.assert_allclose(vy, np.array(synthetic.BASE["disk"][5.0]) + 0.3, atol=1e-12)
        np.testing.assert_array_equal(n, 2)
        # The failed case (mu = 0.0, disk, A = 5, T = 4) is absent from the count.
        T, vy, std, n, se = curves["disk"][0.0]
        self.assertEqual(list(n), [2, 2, 2, 2])

    def test_pooled_phase_rates_weight_by_samples(self):
        d = os.path.join(self.tmp, "pool")
        for k, (v, n) in enumerate(((1.0, 10), (4.0, 30))):
            os.makedirs(os.path.join(d, str(k)), exist_ok=True)
            with open(os.path.join(d, str(k), "phase_rates.csv"), "w") as f:
                f.write("bin,phase_center,vy_mean,samples\n")
                for b in range(20):
                    f.write(f"{b},{b + 0.5},{v if b else ''},{n if b else 0}\n")
        centers, vy = sweepplots.pooled_phase_rates([os.path.join(d, "0"), os.path.join(d, "1")])
        self.assertTrue(np.isnan(vy[0]))
        np.testing.assert_allclose(vy[1:], (1.0 * 10 + 4.0 * 30) / 40)

    def test_geometry_marks(self):
        g = readers.read_geometry(self.geometry[1])
        marks = geomplots.geometry_marks(g)
        self.assertAlmostEqual(marks["y0"], g["y0"])
        self.assertEqual([m[2] for m in marks["nr"]], ["left", "right"])
        self.assertAlmostEqual(marks["nr"][0][0], -4.75)
        self.assertAlmostEqual(marks["l"][0], g["l_left"])


class FigureFilesTest(DataDirs):
    def run_cli(self, *args):
        out, err = io.StringIO(), io.StringIO()
        with contextlib.redirect_stdout(out), contextlib.redirect_stderr(err):
            code = cli.main(list(args))
        return code, out.getvalue(), err.getvalue()

    def assert_files(self, directory, names):
        for name in names:
            path = os.path.join(directory, name)
            self.assertTrue(os.path.isfile(path), f"{path} missing")
            self.assertGreater(os.path.getsize(path), 1000, f"{path} is (nearly) empty")

    def test_run_directory(self):
        code, out, err = self.run_cli(self.run_dir)
        self.assertEqual(code, 0, err)
        figures = os.path.join(self.run_dir, "figures")
        self.assert_files(figures, [f"{n}.{e}" for n in ("trajectory", "snapshots", "phase_rates", "fields")
                                    for e in ("png", "pdf")])

    def test_boundary_map_of_two_searches(self):
        """A boundary.json as `wiggle boundary` writes it (tests/sweep/BoundaryStudyTest checks the
        writer): the map is drawn, one row per --over value."""
        from wiggleplot import boundaryplots
        probe = lambda v, verdict, m, n: {"value": v, "verdict": verdict, "vy": [m] * n, "beds": n, "mean": m,
                                          "standard_error": 0.001}
        search = lambda over, lo, hi: {"over": over, "finished": True,
                                       "probes": [probe(1.0, "sinking", -0.1, 2), probe(lo, "sinking", -0.01, 3),
                                                  probe(hi, "rising", 0.01, 4), probe(5.0, "rising", 0.1, 2),
                                                  {"value": 4.0, "verdict": "failed", "vy": [], "beds": 0,
                                                   "errors": ["the simulation blew up"]}],
                                       "crossings": [{"below": lo, "above": hi, "from": "sinking", "to": "rising",
                                                      "neutral": None}],
                                       "neutral_bands": [], "cost": {"runs": 11, "wall_s": 1.0},
                                       "grid": {"spacing": 0.25, "points": 17, "beds": 4, "cases": 68}}
        b = {"key": "drive.period", "over_key": "drive.amplitude", "rate": "paper",
             "searches": [search(3.0, 3.25, 3.5), search(5.0, 2.25, 2.5)]}
        d = os.path.join(self.tmp, "boundary")
        os.makedirs(d, exist_ok=True)
        with open(os.path.join(d, "boundary.json"), "w") as f:
            json.dump(b, f)
        report = quiet_report()
        boundaryplots.plot_boundary(d, os.path.join(d, "figures"), ["png"], report)
        self.assert_files(os.path.join(d, "figures"), ["boundary.png"])
        b["over_key"], b["searches"] = "", b["searches"][:1]   # one search: the map and V_y(T)
        with open(os.path.join(d, "boundary.json"), "w") as f:
            json.dump(b, f)
        boundaryplots.plot_boundary(d, os.path.join(d, "one"), ["png"], report)
        self.assert_files(os.path.join(d, "one"), ["boundary.png"])

    def test_boundary_map_marks_the_models_t_rise_per_row(self):
        """T_rise per --over value from the runs' model.json and config.toml; a row whose runs give two
        values (the model depends on the varied key) gets none; runs without a model are skipped."""
        from wiggleplot import boundaryplots
        d = os.path.join(self.tmp, "boundary_model")
        runs = [("a3_T2_s1", 3.0, 2.83), ("a3_T5_s1", 3.0, 2.83), ("a5_T2_s1", 5.0, 3.1), ("a5_T5_s1", 5.0, 3.2),
                ("a4_T2_s1", 4.0, None)]
        for name, amplitude, t_rise in runs:
            case = os.path.join(d, "cases", name)
            os.makedirs(case, exist_ok=True)
            with open(os.path.join(case, "config.toml"), "w") as f:
                f.write(f"[drive]\namplitude = {amplitude}\n")
            if t_rise is not None:
                with open(os.path.join(case, "model.json"), "w") as f:
                    json.dump({"T_rise": t_rise, "curve": []}, f)
        self.assertEqual(boundaryplots.model_t_rise(d, "drive.amplitude"), {3.0: 2.83})
        self.assertEqual(boundaryplots.model_t_rise(os.path.join(self.tmp, "nowhere"), ""), {})

    def test_movie_trail_is_the_path_so_far(self):
        traj = {"t": np.array([0.0, 0.5, 1.0, 1.5]), "x": np.array([30.0, 31.0, 30.0, 29.0]),
                "y": np.array([25.0, 25.5, 26.0, 26.5])}
        x, y = runplots.path_until(traj, 1.0)
        self.assertEqual(list(x), [30.0, 31.0, 30.0])
        self.assertEqual(list(y), [25.0, 25.5, 26.0])
        self.assertEqual(len(runplots.path_until(traj, -1.0)[0]), 0)

    def decoded_movie(self, run_dir, name):
        """(frame count, (width, height), decode(k) -> RGB array of frame k) of the movie of run_dir."""
        import subprocess
        from matplotlib import image
        out_dir = os.path.join(self.tmp, name)
        run = runplots.Run(run_dir, quiet_report())
        runplots.write_movie(run, out_dir)
        movie = os.path.join(out_dir, "movie.mp4")
        self.assertEqual(sorted(os.listdir(out_dir)), ["movie.mp4"])  # no temporary left
        probe = subprocess.run(["ffprobe", "-v", "error", "-count_frames", "-select_streams", "v:0",
                                "-show_entries", "stream=nb_read_frames,width,height", "-of", "csv=p=0", movie],
                               capture_output=True, text=True, check=True).stdout.strip().split(",")
        width, height, count = (int(v) for v in probe)

        def decode(k):
            png = os.path.join(out_dir, f"decoded{k}.png")
            subprocess.run(["ffmpeg", "-v", "error", "-y", "-i", movie, "-vf", f"select=eq(n\\,{k})",
                            "-vframes", "1", png], check=True)
            return image.imread(png)[:, :, :3]
        return count, (width, height), decode

    def drawn_frame(self, run_dir, k):
        from matplotlib import image
        frames = runplots.MovieFrames(runplots.Run(run_dir, quiet_report()))
        frames.draw(k)
        png = os.path.join(self.tmp, f"drawn{k}.png")
        frames.save_png(png)
        size = frames.size
        frames.close()
        return size, image.imread(png)[:, :, :3]

    def test_movie_holds_every_dump_frame_as_drawn(self):
        # The movie is decoded: as many frames as the dump, of the size declared, each the picture
        # of that frame (up to the codec's loss), not sheared stripes of mis-sized frames.
        if runplots.find_ffmpeg() is None or not shutil.which("ffprobe"):
            self.skipTest("no ffmpeg/ffprobe")
        count, size, decode = self.decoded_movie(self.run_dir, "movie")
        self.assertEqual(count, len(synthetic.DUMP_TIMES))
        for k in (0, count - 1):
            drawn_size, drawn = self.drawn_frame(self.run_dir, k)
            self.assertEqual(size, drawn_size)
            decoded = decode(k)
            self.assertEqual(decoded.shape, drawn.shape)
            self.assertLess(float(np.mean(np.abs(decoded - drawn))), 0.02, f"frame {k}")
        # One dump frame makes a one-frame movie, not an ffmpeg error.
        one = os.path.join(self.tmp, "one_frame_run")
        synthetic.write_run(one, with_fields=False, with_dump=False)
        synthetic.write_dump(os.path.join(one, "dumps", "dump.lammpstrj"), times=synthetic.DUMP_TIMES[:1])
        count, size, decode = self.decoded_movie(one, "movie_one")
        self.assertEqual(count, 1)
        self.assertLess(float(np.mean(np.abs(decode(0) - self.drawn_frame(one, 0)[1]))), 0.02)

    def test_snapshot_times(self):
        out_dir = os.path.join(self.tmp, "snap")
        code, _, err = self.run_cli(self.run_dir, "--times", "0,100", "--format", "png", "--out", out_dir)
        self.assertEqual(code, 0, err)
        self.assert_files(out_dir, ["snapshots.png"])

    def test_sweep_directory(self):
        code, out, err = self.run_cli(self.sweep_mu_dir, "--format", "png")
        self.assertEqual(code, 0, err)
        figures = os.path.join(self.sweep_mu_dir, "figures")
        self.assert_files(figures, ["rate_vs_period.png", "rate_vs_period_mu.png", "rate_map.png",
                                    "table1.png"])
        code, out, err = self.run_cli(self.sweep_dir)
        self.assertEqual(code, 0, err)
        figures = os.path.join(self.sweep_dir, "figures")
        self.assert_files(figures, [f"{n}.{e}" for n in ("rate_vs_period", "rate_map", "table1",
                                                         "trajectories", "phase_rates")
                                    for e in ("png", "pdf")])
        self.assertIn("contact.mu does not vary", out)
        table = readers.read_table(os.path.join(figures, "table1.csv"))
        disk = list(table["shape"]).index("disk")
        self.assertAlmostEqual(table["T_rising_observed"][disk], synthetic.DISK_T_RISING)

    def test_geometry(self):
        out_dir = os.path.join(self.tmp, "geom")
        code, _, err = self.run_cli("--geometry", *self.geometry, "--out", out_dir)
        self.assertEqual(code, 0, err)
        self.assert_files(out_dir, ["geometry.png", "geometry.pdf"])

    def test_missing_optional_inputs_are_notes(self):
        d = os.path.join(self.tmp, "bare")
        synthetic.write_run(d, with_fields=False, with_dump=False, with_model=False)
        os.remove(os.path.join(d, "phase_rates.csv"))
        code, out, err = self.run_cli(d, "--format", "png", "--movie")
        if runplots.find_ffmpeg() is None:  # --movie without ffmpeg: one line, status 3, nothing drawn
            self.assertEqual(code, 3, err)
            self.assertEqual(len(err.strip().splitlines()), 1)
            self.assertIn("ffmpeg", err)
            self.assertFalse(os.path.exists(os.path.join(d, "figures")))
            code, out, err = self.run_cli(d, "--format", "png")
        self.assertEqual(code, 0, err)
        self.assert_files(os.path.join(d, "figures"), ["trajectory.png"])
        for skipped in ("snapshots skipped", "phase-rate figure skipped", "field maps skipped"):
            self.assertIn(skipped, out)
        if runplots.find_ffmpeg() is not None:
            self.assertIn("movie skipped", out)  # no dump to make it from

    def test_bad_input_is_one_line_and_status_2(self):
        code, _, err = self.run_cli(os.path.join(self.tmp, "nowhere"))
        self.assertEqual(code, 2)
        self.assertEqual(len(err.strip().splitlines()), 1)
        code, _, err = self.run_cli(self.tmp)  # a directory that is neither kind
        self.assertEqual(code, 2)
        self.assertIn("neither a run directory", err)
        code, _, err = self.run_cli(self.run_dir, "--format", "gif")
        self.assertEqual(code, 2)

    def test_out_creates_only_its_last_component(self):
        # A missing parent is refused, nothing is created: --out is one new directory at most.
        deep = os.path.join(self.tmp, "no_such_parent", "deep", "figs")
        code, out, err = self.run_cli(self.run_dir, "--format", "png", "--out", deep)
        self.assertEqual(code, 2)
        self.assertEqual(err.strip(), f"wiggleplot: --out {deep}: parent directory "
                                      f"{os.path.dirname(deep)} does not exist")
        self.assertFalse(os.path.exists(os.path.join(self.tmp, "no_such_parent")))
        self.assertEqual(out, "")
        # A file where the directory should be, or a place where no directory can be made (/proc):
        # one line naming --out, status 2, no Python error text.
        a_file = os.path.join(self.tmp, "a_file")
        with open(a_file, "w") as f:
            f.write("x\n")
        for bad, words in ((a_file, "exists and is not a directory"),
                           (os.path.join(a_file, "figs"), "is not a directory"),
                           ("/proc/nope", "cannot create the directory")):
            code, _, err = self.run_cli(self.run_dir, "--format", "png", "--out", bad)
            self.assertEqual(code, 2, bad)
            self.assertEqual(len(err.strip().splitlines()), 1, err)
            self.assertTrue(err.startswith(f"wiggleplot: --out {bad}: "), err)
            self.assertIn(words, err)
            self.assertNotIn("Errno", err)
        # The geometry figure's --out is checked the same way.
        code, _, err = self.run_cli("--geometry", *self.geometry, "--out", deep)
        self.assertEqual(code, 2)
        self.assertIn("does not exist", err)
        # A new last component is created.
        fresh = os.path.join(self.tmp, "fresh_out")
        code, _, err = self.run_cli(self.run_dir, "--format", "png", "--out", fresh + "/")
        self.assertEqual(code, 0, err)
        self.assert_files(fresh, ["trajectory.png"])

    def test_os_errors_are_one_line_without_errno(self):
        e = PermissionError(13, "Permission denied", "/ro/figures/trajectory.png")
        self.assertEqual(report.os_error_line(e), "/ro/figures/trajectory.png: Permission denied")


if __name__ == "__main__":
    unittest.main()
