#!/usr/bin/python3
"""study/tools/bed_compaction.py through `import wiggle`, on the tiny case of the engine's own test
(tests/python/engine_test.py: its config, run as there):

    bed_compaction.py MODULE_DIR WIGGLE_BINARY

A case measured at its checkpoint and the same case run again and measured on the way give the same
row at the checkpoint's time. About 5 s."""
import os
import subprocess
import sys
import tempfile
import unittest

HERE = os.path.dirname(os.path.abspath(__file__))
sys.path.insert(0, os.path.join(HERE, "..", "..", "tests", "python"))
# engine_test reads MODULE_DIR and WIGGLE_BINARY from the command line, as this script takes them.
from engine_test import MODULE_DIR, tiny_run  # noqa: E402


class BedCompaction(unittest.TestCase):
    @classmethod
    def setUpClass(cls):
        cls.tmp = tempfile.TemporaryDirectory(prefix="wiggle-study-compaction-")
        tiny_run(cls.tmp.name)   # the case in tmp/run, finished with its checkpoint at t = 0.5

    @classmethod
    def tearDownClass(cls):
        cls.tmp.cleanup()

    def test_bed_compaction_in_time_meets_the_runs_own_checkpoint(self):
        # study/tools/bed_compaction.py measures a case at its checkpoint (the run's end here, t =
        # 0.5) or, with --times, runs it again through this module and measures it on the way: both
        # routes must give the same row at t = 0.5 (the bulk band is empty in this tiny bed; the
        # surface, the annulus and the intruder's height are not).
        sweep = os.path.join(self.tmp.name, "compaction")
        os.makedirs(os.path.join(sweep, "cases"))
        os.symlink(os.path.join(self.tmp.name, "run"), os.path.join(sweep, "cases", "tiny"))
        root = os.path.join(HERE, "..", "..")
        script = os.path.join(HERE, "..", "tools", "bed_compaction.py")
        env = dict(os.environ, PYTHONPATH=MODULE_DIR + os.pathsep + os.path.join(root, "python"))

        def rows(*extra):
            out = os.path.join(self.tmp.name, "compaction.csv")
            subprocess.run([sys.executable, script, sweep, "--csv", out, *extra], check=True, env=env,
                           stdout=subprocess.DEVNULL)
            with open(out) as f:
                return [line.strip().split(",") for line in f][1:]

        at_checkpoint, in_time = rows(), rows("--times", "0.25,0.5")
        self.assertEqual([r[1] for r in in_time], ["0.25", "0.5"])
        self.assertEqual(at_checkpoint, in_time[1:])
        self.assertNotEqual(in_time[0][2:], in_time[1][2:])
        bad = subprocess.run([sys.executable, script, sweep, "--times", "0.5,0.25"], env=env,
                             capture_output=True, text=True)
        self.assertEqual(bad.returncode, 2)
        self.assertIn("the times must be positive and increasing", bad.stderr)


if __name__ == "__main__":
    unittest.main(argv=sys.argv[:1], verbosity=2)
