"""wiggleplot.cells (the program's rule of a sweep's cells) against the study: its statistics are
study/tools/findings.py's, and a committed study in results/ reads as the study's own numbers."""
import os
import unittest

from tests.test_study_tools import load_tool
from wiggleplot import cells, readers

ROOT = os.path.dirname(os.path.dirname(os.path.dirname(os.path.abspath(__file__))))
findings = load_tool("findings")


class CellsAreTheStudysTest(unittest.TestCase):
    def test_the_statistics_are_the_studys(self):
        values = [0.088, 0.084, 0.094]
        mean, se = findings.stats(values)
        s = cells.stats(values)
        self.assertAlmostEqual(s["vy_mean"], mean, places=15)
        self.assertAlmostEqual(s["vy_se"], se, places=15)
        self.assertAlmostEqual(s["vy_sd"], findings.sd(values), places=15)

    def test_a_committed_study_reads_as_cells(self):
        """results/pour_protocol_small (no cells.csv: written before it existed), three beds a
        cell: the grouping gives the study's own numbers (study/VALIDATION.md: one bed's sd at the
        disk's T = 1, 0.018, the small preset's sigma in study/FINDINGS.md)."""
        study = os.path.join(ROOT, "results", "pour_protocol_small")
        table = cells.read_cells(study)
        results = readers.read_results(study)
        self.assertEqual(list(table["cell"]), ["pour=lattice_period=1", "pour=lattice_period=5",
                                               "pour=random_period=1", "pour=random_period=5"])
        self.assertTrue((table["beds"] == 3).all() and (table["n"] == 3).all())
        for i, cell in enumerate(table["cell"]):
            values = [results["vy"][k] for k in range(len(results["case"])) if cells.cell_name(results["case"][k]) == cell]
            self.assertAlmostEqual(table["vy_sd"][i], findings.sd(values), places=12)
        self.assertAlmostEqual(table["vy_sd"][0], 0.0183, places=4)
        self.assertEqual(list(table["verdict"]), ["sinks", "rises", "not resolved", "rises"])


if __name__ == "__main__":
    unittest.main()
