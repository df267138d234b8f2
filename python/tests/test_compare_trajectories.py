"""tools/validation/compare_trajectories.py's figure: y(t) of each run, and a panel of the angle under it
only where a run's intruder turns (its trajectory.csv has the angle column)."""
import importlib.util
import os
import unittest

import numpy as np

HERE = os.path.dirname(os.path.abspath(__file__))
SCRIPT = os.path.join(HERE, "..", "..", "tools", "validation", "compare_trajectories.py")


def load_script():
    spec = importlib.util.spec_from_file_location("compare_trajectories", SCRIPT)
    module = importlib.util.module_from_spec(spec)
    spec.loader.exec_module(module)
    return module


def trajectory(turning):
    t = np.linspace(0.0, 10.0, 11)
    traj = {"t": t, "x": np.zeros_like(t), "y": 20.0 + 0.1 * t}
    if turning:
        traj["angle"] = 0.05 * np.sin(t)
    return traj


class DrawTest(unittest.TestCase):
    @classmethod
    def setUpClass(cls):
        cls.script = load_script()

    def tearDown(self):
        import matplotlib.pyplot as plt
        plt.close("all")

    def test_locked_runs_have_one_panel(self):
        fig = self.script.draw([("locked", trajectory(False), 0.1)], "t")
        self.assertEqual(len(fig.axes), 1)
        np.testing.assert_allclose(fig.axes[0].lines[0].get_ydata(), 0.1 * np.linspace(0.0, 10.0, 11), atol=1e-12)

    def test_a_turning_run_adds_its_angle_in_degrees_in_its_curves_colour(self):
        fig = self.script.draw([("locked", trajectory(False), 0.1), ("free", trajectory(True), 0.1)], "t")
        self.assertEqual(len(fig.axes), 2)
        top, angle = fig.axes
        # the angle panel holds the zero line and the one turning run, not the locked one
        turned = [line for line in angle.lines if len(line.get_ydata()) == 11]
        self.assertEqual(len(turned), 1)
        np.testing.assert_allclose(turned[0].get_ydata(), np.degrees(0.05 * np.sin(np.linspace(0.0, 10.0, 11))))
        self.assertEqual(turned[0].get_color(), top.lines[1].get_color())


if __name__ == "__main__":
    unittest.main()
