"""study/tools: table1_markdown.py, the markdown table of V_y per shape and period that
study/VALIDATION.md's Table 1 and figure 5 sections print, and collect.py's sweep log."""
import csv
import importlib.util
import json
import os
import tempfile
import unittest

HERE = os.path.dirname(os.path.abspath(__file__))


def load_tool(name):
    spec = importlib.util.spec_from_file_location(name, os.path.join(HERE, "..", "tools", name + ".py"))
    module = importlib.util.module_from_spec(spec)
    spec.loader.exec_module(module)
    return module


table1_markdown = load_tool("table1_markdown")
collect = load_tool("collect")

COLUMNS = ["case", "run_dir", "status", "vy", "intruder.shape", "drive.period", "drive.amplitude", "box.seed"]


def write_folder(root, rows):
    """A results folder: results.csv plus a model.json for each finished case."""
    with open(os.path.join(root, "results.csv"), "w", newline="") as f:
        w = csv.writer(f)
        w.writerow(COLUMNS)
        for name, status, vy, shape, period, amplitude, *seed in rows:
            w.writerow([name, f"cases/{name}", status, vy, shape, period, amplitude, seed[0] if seed else 1])
            os.makedirs(os.path.join(root, "cases", name), exist_ok=True)
            with open(os.path.join(root, "cases", name, "model.json"), "w") as m:
                json.dump({"T_rise": 2.83, "T_max": 7.48}, m)


class TableTest(unittest.TestCase):
    def test_figure5_amplitude_has_no_paper_column_and_averages_beds(self):
        with tempfile.TemporaryDirectory() as root:
            write_folder(root, [("d1", "ok", -0.1, "disk", 1, 3), ("d3a", "ok", 0.02, "disk", 3, 3),
                                ("d3b", "ok", 0.04, "disk", 3, 3, 2), ("d5", "ok", 0.01, "disk", 5, 3),
                                ("d8", "pending", "", "disk", 8, 3)])
            lines = table1_markdown.table(root).splitlines()
        self.assertNotIn("paper", lines[0])
        self.assertNotIn("T = 8", lines[0])   # the pending case has no column
        cells = [c.strip() for c in lines[2].strip("|").split("|")]
        self.assertEqual(cells[:3], ["disk", "2.83", "7.48"])
        self.assertEqual(cells[3:6], ["-0.100 (1 bed)", "+0.030 +- 0.010 (2 beds)", "+0.010 (1 bed)"])
        self.assertEqual(cells[7], "1-3")    # sinks at 1, rises from 3: the bracket
        self.assertEqual(cells[-1], "3")     # the largest mean V_y

    def test_table1_amplitude_prints_the_papers_range(self):
        with tempfile.TemporaryDirectory() as root:
            write_folder(root, [("s2", "ok", -0.1, "square", 2, 5), ("s3", "ok", 0.07, "square", 3, 5)])
            lines = table1_markdown.table(root).splitlines()
        self.assertIn("paper (observed)", lines[0])
        self.assertIn("| 3.0-4.0 |", lines[2])

    def test_mixed_amplitudes_are_refused(self):
        with tempfile.TemporaryDirectory() as root:
            write_folder(root, [("a", "ok", 0.1, "disk", 3, 3), ("b", "ok", 0.1, "disk", 3, 5)])
            with self.assertRaises(ValueError):
                table1_markdown.table(root)


class CollectTest(unittest.TestCase):
    def test_log_keeps_earlier_sweep_directories_lines_once(self):
        earlier = ["s1 start\n", "s1 ok\n", "s2 start\n"]
        current = ["s2 start\n", "s2 ok\n"]   # the same directory, collected again later
        self.assertEqual(collect.merged_log(earlier, current), ["s1 start\n", "s1 ok\n", "s2 start\n", "s2 ok\n"])
        fresh = ["s3 start\n"]                  # a new sweep directory in a later session
        merged = collect.merged_log(["s1 start\n", "s1 ok"], fresh)
        self.assertEqual(merged, ["s1 start\n", "s1 ok\n", "s3 start\n"])
        self.assertEqual(collect.merged_log(merged, fresh), merged)   # collecting again changes nothing
        self.assertEqual(collect.merged_log([], fresh), fresh)


if __name__ == "__main__":
    unittest.main()
