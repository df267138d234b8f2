#!/usr/bin/python3
"""`import wiggle` (apps/python/WiggleModule.cpp, docs/PYTHON.md) against the command:

    engine_test.py MODULE_DIR WIGGLE_BINARY

The same config stepped from Python, in any split of step() calls, ends in the same state hash as
`wiggle run` writes in summary.json; the arrays are read-only views of the engine's memory; bad
input raises wiggle.Error with the command's one-line message; field maps, frames and the plotting
package on the live case are wiggle run's files. A tiny bed (20 x 12 d) in a private
cache: about 10 s."""
import json
import math
import os
import subprocess
import sys
import tempfile
import unittest

MODULE_DIR, WIGGLE = sys.argv[1], sys.argv[2]
sys.path.insert(0, MODULE_DIR)
sys.path.insert(0, os.path.join(os.path.dirname(os.path.abspath(__file__)), "..", "..", "python"))
import numpy as np  # noqa: E402
import wiggle  # noqa: E402
import wiggleplot as wp  # noqa: E402

TINY = """[box]
width = 20.0
bed_height = 12.0
seed = 1
[intruder]
shape = "polygon"
vertices = [[-1.5, -1.5], [1.5, -1.5], [1.5, 1.5], [-1.5, 1.5]]
y0 = 6.0
[drive]
amplitude = 0.5
period = 1.0
[bed]
rest_energy = 1e-4
max_time = 100.0
cache_dir = "{cache}"
[run]
dt = 0.0001
duration = 0.5
sample_interval = 0.01
dump_interval = 0.0
checkpoint_interval = 0.5
plot = false
[fields]
enabled = false
"""


def tiny_run(folder):
    """TINY in folder/tiny.toml (its bed cached in folder/cache), run by `wiggle run` into folder/run:
    the config's path and the run's directory."""
    config = os.path.join(folder, "tiny.toml")
    with open(config, "w") as f:
        f.write(TINY.format(cache=os.path.join(folder, "cache")))
    out = os.path.join(folder, "run")
    subprocess.run([WIGGLE, "run", config, "--out", out, "--threads", "1"], check=True,
                   stdout=subprocess.DEVNULL, stderr=subprocess.DEVNULL)
    return config, out


class Engine(unittest.TestCase):
    @classmethod
    def setUpClass(cls):
        cls.tmp = tempfile.TemporaryDirectory(prefix="wiggle-engine-test-")
        cls.config, out = tiny_run(cls.tmp.name)
        with open(os.path.join(out, "summary.json")) as f:
            cls.summary = json.load(f)
        cls.cli_hash = cls.summary["state_hash"]
        cls.cli_trajectory = np.genfromtxt(os.path.join(out, "trajectory.csv"), delimiter=",", names=True)
        cls.cli_phase_rates = np.genfromtxt(os.path.join(out, "phase_rates.csv"), delimiter=",", names=True)

    @classmethod
    def tearDownClass(cls):
        cls.tmp.cleanup()

    def test_same_bits_as_wiggle_run_for_any_split_of_the_steps(self):
        whole = wiggle.Case(self.config, threads=1)
        whole.step(5000)
        self.assertAlmostEqual(whole.t, 0.5)
        self.assertEqual(whole.state_hash(), self.cli_hash)
        split = wiggle.Case(self.config, threads=2)
        for n in (1, 999, 1500, 2500):
            split.step(n)
        self.assertEqual(split.steps, 5000)
        self.assertEqual(split.state_hash(), self.cli_hash)
        by_time = wiggle.Case(self.config, overrides={"run.duration": 0.5}, threads=1)
        by_time.advance(0.25)
        by_time.advance(0.5)
        self.assertEqual(by_time.state_hash(), self.cli_hash)

    def test_the_run_record_and_its_rates_are_wiggle_runs(self):
        # Stepped to the run's end, the case's own record gives summary.json's numbers and the files' columns.
        c = wiggle.Case(self.config, threads=1)
        c.step(2500)
        c.step(2500)
        rate = c.rise_rate()
        for key in ("vy", "vy_slope", "t_i", "t_f", "plateau", "vy_window_periods", "vy_settled", "t_settled", "settled"):
            self.assertEqual(rate[key], self.summary[key], key)  # the same doubles, by summary.json's names
        traj = c.trajectory
        self.assertEqual(len(traj["t"]), len(self.cli_trajectory))
        for name in ("t", "x", "y", "vx", "vy", "fy"):  # the CSV holds 10 significant digits
            np.testing.assert_allclose(traj[name], self.cli_trajectory[name], rtol=1e-9, atol=1e-12, err_msg=name)
        rates = c.phase_rates
        np.testing.assert_array_equal(rates["samples"], self.cli_phase_rates["samples"])
        np.testing.assert_allclose(rates["vy_mean"], self.cli_phase_rates["vy_mean"], rtol=1e-9, atol=1e-12)

    def test_a_turning_intruders_trajectory_has_its_turn(self):
        # trajectory.csv's angle and omega columns, only where the intruder may turn
        locked = wiggle.Case(self.config, threads=1)
        self.assertNotIn("angle", locked.trajectory)
        turning = wiggle.Case(self.config, overrides={"intruder.rotation": "free"}, threads=1)
        turning.step(1000)
        traj = turning.trajectory
        self.assertEqual(len(traj["angle"]), len(traj["t"]))
        self.assertEqual(len(traj["omega"]), len(traj["t"]))
        self.assertEqual(traj["angle"][0], 0.0)
        self.assertNotEqual(traj["angle"][-1], 0.0)

    def test_save_and_load_are_wiggle_runs_checkpoints(self):
        # Saved mid-run, the case is a run directory: `wiggle run --resume` finishes it and
        # Case.load continues it, both to wiggle run's bits.
        c = wiggle.Case(self.config, threads=1)
        c.step(2000)
        saved = os.path.join(self.tmp.name, "saved")
        c.save(saved)
        with self.assertRaisesRegex(wiggle.Error, "already holds a run"):
            c.save(saved)
        again = wiggle.Case.load(saved, threads=1)
        self.assertEqual(again.steps, 2000)
        self.assertEqual(again.state_hash(), c.state_hash())
        again.step(3000)
        self.assertEqual(again.state_hash(), self.cli_hash)
        self.assertEqual(again.rise_rate()["vy"], self.summary["vy"])  # its record came with it
        subprocess.run([WIGGLE, "run", "--out", saved, "--resume", "--threads", "1"], check=True,
                       stdout=subprocess.DEVNULL, stderr=subprocess.DEVNULL)
        with open(os.path.join(saved, "summary.json")) as f:
            finished = json.load(f)
        self.assertEqual(finished["state_hash"], self.cli_hash)
        self.assertEqual(finished["vy"], self.summary["vy"])
        with self.assertRaisesRegex(wiggle.Error, "run.dump_interval = 0"):
            wiggle.Case(self.config, overrides={"run.dump_interval": 0.1}, threads=1).save(
                os.path.join(self.tmp.name, "with-dumps"))
        with self.assertRaisesRegex(wiggle.Error, "holds no run"):
            wiggle.Case.load(os.path.join(self.tmp.name, "nowhere"))

    def test_field_maps_and_frames_are_wiggle_runs(self):
        # With fields on (a 4 d grid, phases 0, 5 and 10: phase 0 falls on no step after t_i here) and dumps every 0.1: the live case's field
        # maps are fields.csv's, its frame() the dump's last frame, and a case saved half way with
        # its field frames is finished by `wiggle run --resume` to the same fields.csv, byte for byte.
        sets = {"fields.enabled": True, "fields.radius": 4.0, "fields.spacing": 1.0, "fields.phases": [0.0, 5.0, 10.0],
                "run.dump_interval": 0.1}
        out = os.path.join(self.tmp.name, "fields-run")
        subprocess.run([WIGGLE, "run", self.config, "--out", out, "--threads", "1"]
                       + [a for k, v in sets.items() for a in ("--set", f"{k}={json.dumps(v)}")],
                       check=True, stdout=subprocess.DEVNULL, stderr=subprocess.DEVNULL)
        csv = np.genfromtxt(os.path.join(out, "fields.csv"), delimiter=",", names=True)
        c = wiggle.Case(self.config, overrides=sets, threads=1)
        self.assertTrue(np.all(c.fields["frames"] == 0))  # none before t_i
        for n in (1234, 2000, 1766):
            c.step(n)
        with open(os.path.join(out, "summary.json")) as f:
            self.assertEqual(c.state_hash(), json.load(f)["state_hash"])
        fields = c.fields
        self.assertEqual(len(fields["phase"]), len(csv))
        self.assertEqual(sorted(set(zip(fields["phase"], fields["frames"]))), [(0, 0), (5, 1), (10, 1)])
        for name in csv.dtype.names:  # the CSV holds 10 significant digits; NaN where it is empty
            np.testing.assert_allclose(fields[name], csv[name], rtol=1e-9, atol=1e-12, equal_nan=True, err_msg=name)
        frame, dump = c.frame(), self.last_dump_frame(os.path.join(out, "dumps", "dump.lammpstrj"))
        self.assertEqual(frame["step"], 5000)
        np.testing.assert_array_equal(frame["id"], dump[:, 0])
        np.testing.assert_array_equal(frame["type"], dump[:, 1])
        columns = {"x": 2, "y": 3, "radius": 5, "vx": 6, "vy": 7, "fx": 8, "fy": 9, "tqz": 10}  # 9 and 6 digits
        for name, k in columns.items():
            np.testing.assert_allclose(frame[name], dump[:, k], rtol=5e-6, atol=1e-12, err_msg=name)
        np.testing.assert_array_equal(np.sort(c.tag[:c.particle_count]) + 1, np.sort(frame["id"][frame["type"] < 3]))

        half = wiggle.Case(self.config, overrides={**sets, "run.dump_interval": 0.0}, threads=1)
        half.step(3000)
        saved = os.path.join(self.tmp.name, "fields-saved")
        half.save(saved)
        subprocess.run([WIGGLE, "run", "--out", saved, "--resume", "--threads", "1"], check=True,
                       stdout=subprocess.DEVNULL, stderr=subprocess.DEVNULL)
        with open(os.path.join(out, "fields.csv")) as a, open(os.path.join(saved, "fields.csv")) as b:
            self.assertEqual(a.read(), b.read())
        self.assertIsNone(wiggle.Case(self.config, threads=1).fields)  # fields off: none

    def test_wiggleplot_reads_and_draws_the_live_case_as_a_run_directory(self):
        # load_run(case) holds what load_run(DIR) holds for the same run; plot_run(case) draws the
        # figures a run directory gives (snapshots from the frames the caller took).
        sets = {"fields.enabled": True, "fields.radius": 4.0, "fields.spacing": 1.0, "fields.phases": [5.0]}
        out = os.path.join(self.tmp.name, "plot-run")
        subprocess.run([WIGGLE, "run", self.config, "--out", out, "--threads", "1", "--no-plot"]
                       + [a for k, v in sets.items() for a in ("--set", f"{k}={json.dumps(v)}")],
                       check=True, stdout=subprocess.DEVNULL, stderr=subprocess.DEVNULL)
        c = wiggle.Case(self.config, overrides=sets, threads=1)
        frames = [c.frame()]
        c.step(5000)
        frames.append(c.frame())
        live, disk = wp.load_run(c), wp.load_run(out)
        self.assertIsNone(live.dir)
        self.assertEqual(live.config, disk.config)
        for name in ("vy", "vy_slope", "t_i", "t_f"):
            self.assertEqual(live.summary[name], disk.summary[name], name)
        for table in ("trajectory", "phase_rates", "fields"):
            a, b = getattr(live, table), getattr(disk, table)
            self.assertEqual(list(a.columns), list(b.columns), table)
            np.testing.assert_allclose(a.to_numpy(dtype=float), b.to_numpy(dtype=float), rtol=1e-9, atol=1e-12,
                                       equal_nan=True, err_msg=table)
        figures = os.path.join(self.tmp.name, "live-figures")
        written = wp.plot_run(c, figures, frames=frames)
        self.assertEqual(sorted(os.path.basename(f) for f in written),
                         ["fields.png", "phase_rates.png", "snapshots.png", "trajectory.png"])

    @staticmethod
    def last_dump_frame(path):
        with open(path) as f:
            lines = f.read().splitlines()
        start = max(i for i, line in enumerate(lines) if line.startswith("ITEM: ATOMS")) + 1
        count = int(lines[start - 6])
        return np.loadtxt(lines[start:start + count], ndmin=2)

    def test_the_step_profile_is_wiggle_runs_when_asked(self):
        self.assertIsNone(wiggle.Case(self.config, threads=1).step_profile)  # run.profile is off by default
        c = wiggle.Case(self.config, {"run.profile": True}, threads=2)
        c.step(300)
        p = c.step_profile
        self.assertEqual(p["steps"], 300)
        self.assertEqual(p["threads"], 2)
        self.assertAlmostEqual(sum(s["s"] for s in p["stages"].values()), p["step_s"], delta=1e-6 * p["step_s"])
        self.assertEqual(sorted(p["strip_imbalance"]), ["16", "2", "32", "4", "8"])
        self.assertGreaterEqual(min(p["strip_imbalance"].values()), 1.0)

    def test_arrays_are_read_only_views_of_the_engine(self):
        c = wiggle.Case(self.config, threads=1)
        x = c.x
        self.assertEqual(x.dtype, np.float64)
        self.assertEqual(x.shape, (c.particle_count,))
        self.assertFalse(x.flags.writeable)
        self.assertEqual(x.ctypes.data, c.x.ctypes.data)  # the same memory each time: no copy
        with self.assertRaises(ValueError):
            x[0] = 1.0
        self.assertTrue(np.all(c.radius[:c.grain_count] > 0))
        y0 = c.y.copy()
        c.step(100)
        self.assertFalse(np.array_equal(y0, c.y))  # the grains moved
        self.assertAlmostEqual(c.intruder["x"], 10.0 + 0.5 * np.sin(2 * np.pi * c.t / 1.0), places=12)

    def test_a_python_drive_that_is_the_sine_gives_the_built_in_drives_bits(self):
        # x = x0 + A sin(w t), vx = A w cos(w t) with the engine's own operations (ClumpMotion::at):
        # the same doubles, so the same state as `wiggle run` with its built-in drive.
        amplitude, w = 0.5, 2.0 * math.pi / 1.0
        calls = []

        def sine(t):
            calls.append(t)
            return amplitude * math.sin(w * t), amplitude * w * math.cos(w * t)
        c = wiggle.Case(self.config, threads=1, drive=sine, peak_speed=amplitude * w)
        c.step(2000)
        c.step(3000)
        self.assertEqual(c.state_hash(), self.cli_hash)
        self.assertEqual(sorted({round(t / c.dt) for t in calls}), list(range(5001)))  # at every step's time
        self.assertLessEqual(len(calls), 5002)  # once per step, and at t = 0 when set and when the run set up
        # Set after the start, the drive makes the engine evaluate its forces afresh: the same motion,
        # not the same bits (docs/PYTHON.md), but the same intruder path.
        later = wiggle.Case(self.config, threads=1)
        later.set_drive(sine, peak_speed=amplitude * w)
        later.step(5000)
        self.assertEqual(later.intruder["x"], c.intruder["x"])
        # Another waveform moves the grains otherwise: a triangle wave of the same amplitude and period.
        tri = wiggle.Case(self.config, threads=1)
        tri.set_drive(lambda t: (amplitude * (2 / math.pi) * math.asin(math.sin(w * t)),
                                 amplitude * (2 / math.pi) * w * math.cos(w * t) / max(1e-12, abs(math.cos(w * t)))),
                      peak_speed=amplitude * (2 / math.pi) * w)
        tri.step(5000)
        self.assertNotEqual(tri.state_hash(), self.cli_hash)
        self.assertAlmostEqual(tri.intruder["x"], 10.0 + amplitude * (2 / math.pi) * math.asin(math.sin(w * tri.t)),
                               places=12)

    def test_a_python_drive_that_fails_stops_the_case_with_its_error(self):
        c = wiggle.Case(self.config, threads=1)
        with self.assertRaisesRegex(wiggle.Error, "peak speed"):
            c.set_drive(lambda t: (0.0, 0.0), peak_speed=0.0)

        def breaks(t):
            if t > 0.01:
                raise ValueError("my drive broke")
            return 0.0, 0.0
        c.set_drive(breaks, peak_speed=1.0)
        with self.assertRaisesRegex(ValueError, "my drive broke"):
            c.step(1000)
        with self.assertRaisesRegex(wiggle.Error, "stopped inside a step that failed"):
            c.step(1)
        fast = wiggle.Case(self.config, threads=1)
        fast.set_drive(lambda t: (0.0, 2.0 if t > 0.01 else 0.0), peak_speed=1.0)
        with self.assertRaisesRegex(wiggle.Error, r"\|vx\| at most its peak speed 1"):
            fast.step(1000)

    def test_bad_input_raises_wiggle_error_with_the_one_line_message(self):
        with self.assertRaisesRegex(wiggle.Error, r"drive\.period = -1: must be > 0"):
            wiggle.Case(self.config, overrides={"drive.period": -1.0})
        with self.assertRaisesRegex(wiggle.Error, r"unknown key 'drive\.perod'"):
            wiggle.Case(self.config, overrides={"drive.perod": 2.0})
        with self.assertRaisesRegex(wiggle.Error, "advance"):
            c = wiggle.Case(self.config, threads=1)
            c.step(10)
            c.advance(0.0)


if __name__ == "__main__":
    unittest.main(argv=sys.argv[:1], verbosity=2)
