"""wiggleplot.cells: the cells' rule (mean, sd, se, verdict: rises / sinks at |mean| >= 2 se with
n >= 2, else not resolved), results.csv grouped by cell (a case without its seed) and cells.csv read
when present. That the C++ side's cells.csv and this grouping agree on a sweep run by wiggle is
checked by tests/cli/report_in_browser.py (ctest report_in_browser); that the rule's statistics are
the study's, and a committed study reads as its cells, by study/tests/test_cells_study.py."""
import math
import os
import shutil
import tempfile
import unittest

import numpy as np

from tests import synthetic
from wiggleplot import cells, htmlreport, prepare, sweepplots
from wiggleplot.report import Report


class RuleTest(unittest.TestCase):
    def test_the_verdict_is_two_standard_errors_of_the_cells_own_beds(self):
        self.assertEqual(cells.stats([])["n"], 0)
        one = cells.stats([0.5])
        self.assertEqual((one["n"], one["vy_mean"], one["verdict"]), (1, 0.5, "not resolved"))
        self.assertTrue(math.isnan(one["vy_se"]))
        three = cells.stats([0.09, 0.08, 0.10])
        self.assertAlmostEqual(three["vy_sd"], 0.01, places=15)
        self.assertAlmostEqual(three["vy_se"], 0.01 / math.sqrt(3), places=15)
        self.assertEqual(three["verdict"], "rises")
        self.assertEqual(cells.stats([-0.09, -0.08, -0.10])["verdict"], "sinks")
        self.assertEqual(cells.stats([0.1, 0.3])["verdict"], "rises")          # exactly 2 se
        self.assertEqual(cells.stats([0.1, 0.31])["verdict"], "not resolved")  # just under
        self.assertEqual(cells.stats([0.0, 0.0])["verdict"], "not resolved")

    def test_one_bed_is_said_as_one_bed(self):
        self.assertEqual(cells.in_words(1, 1, 0.0886, math.nan, "not resolved"),
                         "+0.0886 (one bed: its sign is not a verdict)")
        self.assertEqual(cells.in_words(1, 2, 0.0886, math.nan, "not resolved"),
                         "+0.0886 (one bed: its sign is not a verdict; part-run: 1 of its 2 beds)")
        self.assertEqual(cells.in_words(3, 3, 0.09, 0.01 / math.sqrt(3), "rises"), "+0.09 +- 0.0058 (3 beds): rises")

    def test_cell_names_drop_the_seed(self):
        self.assertEqual(cells.cell_name("period=5_seed=2"), "period=5")
        self.assertEqual(cells.cell_name("seed=4_period=1"), "period=1")
        self.assertEqual(cells.cell_name("seed=3"), "base")
        self.assertEqual(cells.cell_name("shape=disk_box.seed=1_fields.seed=2"), "shape=disk_fields.seed=2")


class GroupingTest(unittest.TestCase):
    @classmethod
    def setUpClass(cls):
        cls.tmp = tempfile.mkdtemp(prefix="wiggleplot-cells-")
        cls.sweep_dir = os.path.join(cls.tmp, "sweep")
        synthetic.write_sweep(cls.sweep_dir, with_runs=False)

    @classmethod
    def tearDownClass(cls):
        shutil.rmtree(cls.tmp, ignore_errors=True)

    def test_results_grouped_by_every_parameter_but_the_seed(self):
        table = cells.read_cells(self.sweep_dir)  # no cells.csv: results.csv grouped
        self.assertNotIn(cells.SEED, table)
        self.assertEqual(len(table["cell"]), 2 * 2 * 4)  # shapes x A x T
        for i in range(len(table["cell"])):
            shape, a, T = table["intruder.shape"][i], table["drive.amplitude"][i], table["drive.period"][i]
            base = synthetic.BASE[shape][a][synthetic.SWEEP_PERIODS.index(T)]
            self.assertAlmostEqual(table["vy_mean"][i], base, places=9)
            if (shape, a, T) == ("disk", 5.0, 4.0):  # its third bed failed: part-run, two of three beds
                self.assertEqual((table["state"][i], table["beds"][i], table["n"][i]), ("part-run", 3, 2))
            else:
                self.assertEqual((table["state"][i], table["beds"][i], table["n"][i]), ("done", 2, 2))
            self.assertAlmostEqual(table["vy_sd"][i], synthetic.SEED_OFFSET * math.sqrt(2), places=9)
            expected = cells.stats([base + synthetic.SEED_OFFSET, base - synthetic.SEED_OFFSET])["verdict"]
            self.assertEqual(table["verdict"][i], expected)

    def test_the_figures_bars_are_two_standard_errors_of_the_cells(self):
        sweep = sweepplots.Sweep(self.sweep_dir, Report(quiet=True))
        rows, _ = sweep.main_mu_rows()
        T, vy, std, n, se = sweepplots.curves_by(sweep, rows, prepare.AMPLITUDE)["disk"][3.0]
        np.testing.assert_allclose(se, synthetic.SEED_OFFSET, atol=1e-12)  # sd sqrt(2) x offset over sqrt(2)
        table = cells.read_cells(self.sweep_dir)
        for t, v, s in zip(T, vy, se):
            i = [k for k in range(len(table["cell"])) if table["intruder.shape"][k] == "disk"
                 and table["drive.amplitude"][k] == 3.0 and table["drive.period"][k] == t][0]
            self.assertAlmostEqual(v, table["vy_mean"][i], places=12)
            self.assertAlmostEqual(s, table["vy_se"][i], places=12)

    def drawn(self, sweep_dir):
        """The V_y-against-T figure plot_rate_vs_period draws for sweep_dir (its Figure, unsaved)."""
        figures = []
        saved = sweepplots.style.save
        sweepplots.style.save = lambda fig, *args, **kwargs: figures.append(fig) or []
        try:
            sweepplots.plot_rate_vs_period(sweepplots.Sweep(sweep_dir, Report(quiet=True)), self.tmp, ["png"])
        finally:
            sweepplots.style.save = saved
        return figures[0]

    def test_the_figure_draws_bars_of_two_standard_errors(self):
        fig = self.drawn(self.sweep_dir)
        halves = [abs(seg[1][1] - seg[0][1]) / 2 for ax in fig.axes for c in ax.containers
                  for seg in c.lines[2][0].get_segments()]
        self.assertTrue(halves)
        np.testing.assert_allclose(halves, 2 * synthetic.SEED_OFFSET, atol=1e-12)  # 2 se, se = the offset
        labels = [t.get_text() for legend in fig.legends for t in legend.get_texts()]
        self.assertTrue(any("2 standard errors" in t for t in labels), labels)
        self.assertFalse(any("one bed" in t for t in labels), labels)

    def test_a_point_of_one_bed_is_open_and_has_no_bar(self):
        one_bed = os.path.join(self.tmp, "one_bed")
        os.makedirs(one_bed)
        with open(os.path.join(self.sweep_dir, "results.csv")) as f:
            lines = f.readlines()
        with open(os.path.join(one_bed, "results.csv"), "w") as f:  # seed 1 only: one bed a cell
            f.writelines([lines[0]] + [l for l in lines[1:] if l.rstrip().endswith(",1")])
        for name in os.listdir(os.path.join(self.sweep_dir, "runs")):
            os.makedirs(os.path.join(one_bed, "runs"), exist_ok=True)
            shutil.copytree(os.path.join(self.sweep_dir, "runs", name), os.path.join(one_bed, "runs", name))
        fig = self.drawn(one_bed)
        halves = [abs(seg[1][1] - seg[0][1]) for ax in fig.axes for c in ax.containers
                  for seg in c.lines[2][0].get_segments()]
        self.assertTrue(all(h == 0 for h in halves))
        labels = [t.get_text() for legend in fig.legends for t in legend.get_texts()]
        self.assertIn("open: one bed (its sign is not a verdict)", labels)
        table = cells.read_cells(one_bed)
        self.assertEqual(set(table["verdict"]), {"not resolved"})

    def test_the_report_shows_each_cells_mean_se_and_verdict(self):
        table = cells.read_cells(self.sweep_dir)
        page = "\n".join(htmlreport.cells_section(table, ["drive.period", "box.seed"]))
        self.assertIn("<h2>Cells</h2>", page)
        self.assertIn(cells.RULE.replace(">", "&gt;"), page)
        self.assertIn("2 of 3 (part-run)", page)
        self.assertNotIn("box.seed", page)

    def test_a_sweep_of_one_bed_a_case_says_so(self):
        one = {"cell": np.array(["a"], dtype=object), "beds": np.array([1.0]), "n": np.array([1.0])}
        page = "\n".join(htmlreport.cells_section(one, []))
        self.assertIn("Each case is one bed", page)
        self.assertNotIn("rises", page)


if __name__ == "__main__":
    unittest.main()
