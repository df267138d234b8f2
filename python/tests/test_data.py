"""The pandas readers, the wiggle driver and the example notebook (examples/figures.ipynb)."""
import os
import shutil
import stat
import subprocess
import sys
import tempfile
import unittest

from tests import synthetic

try:
    import pandas  # noqa: F401
    HAVE_PANDAS = True
except ImportError:
    HAVE_PANDAS = False

REPO = os.path.dirname(os.path.dirname(os.path.dirname(os.path.abspath(__file__))))


@unittest.skipUnless(HAVE_PANDAS, "pandas is not installed (tools/bootstrap.sh installs python3-pandas)")
class DataTest(unittest.TestCase):
    def setUp(self):
        self.tmp = tempfile.mkdtemp()

    def tearDown(self):
        shutil.rmtree(self.tmp)

    def test_load_run_gives_frames_with_the_files_columns(self):
        import wiggleplot as wp
        d = os.path.join(self.tmp, "run")
        synthetic.write_run(d)
        run = wp.load_run(d)
        self.assertEqual(list(run.trajectory.columns[:6]), ["t", "x", "y", "vx", "vy", "fy"])
        self.assertEqual(len(run.phase_rates), 20)
        self.assertIsNotNone(run.fields)
        self.assertAlmostEqual(run.vy, run.summary["vy"])
        bare = os.path.join(self.tmp, "bare")
        synthetic.write_run(bare, with_fields=False, with_model=False)
        self.assertIsNone(wp.load_run(bare).fields)
        self.assertIsNone(wp.load_run(bare).model)
        with self.assertRaises(FileNotFoundError):
            wp.load_run(self.tmp)

    def test_load_sweep_keeps_every_case_in_order(self):
        import wiggleplot as wp
        d = os.path.join(self.tmp, "sweep")
        synthetic.write_sweep(d)
        table = wp.load_sweep(d)
        with open(os.path.join(d, "results.csv")) as f:
            self.assertEqual(len(table), sum(1 for _ in f) - 1)
        self.assertIn("drive.period", table.columns)
        self.assertEqual(table["vy"].dtype.kind, "f")
        first = wp.load_case(d, table.iloc[0])
        self.assertEqual(first.dir, os.path.join(d, table.iloc[0]["run_dir"]))
        self.assertEqual(wp.load_case(d, table.iloc[0]["case"]).dir, first.dir)
        with self.assertRaises(KeyError):
            wp.load_case(d, "no such case")

    def test_frames_carry_their_units(self):
        import wiggleplot as wp
        d = os.path.join(self.tmp, "run")
        synthetic.write_run(d)
        run = wp.load_run(d)
        units = run.trajectory.attrs["units"]
        self.assertEqual((units["t"], units["y"], units["vy"]), ("sqrt(d/g)", "d", "sqrt(g d)"))
        self.assertEqual(run.fields.attrs["units"]["pressure"], "rho g d^2")
        s = os.path.join(self.tmp, "sweep")
        synthetic.write_sweep(s)
        units = wp.load_sweep(s).attrs["units"]
        self.assertEqual((units["vy"], units["drive.period"], units["drive.amplitude"]), ("sqrt(g d)", "sqrt(d/g)", "d"))
        self.assertNotIn("case", units)

    def test_run_without_a_wiggle_anywhere_says_what_to_do(self):
        # The package in a clone with nothing built and no wiggle on PATH: the package's own error
        # naming the build command, not a raw FileNotFoundError.
        tree = os.path.join(self.tmp, "clone")
        shutil.copytree(os.path.join(REPO, "python", "wiggleplot"), os.path.join(tree, "python", "wiggleplot"))
        code = ("import wiggleplot as wp\n"
                "try:\n    wp.run('x.toml', 'out')\n"
                "except wp.WiggleError as e:\n    print('WiggleError', e.status, e)\n")
        done = subprocess.run(["/usr/bin/python3", "-c", code], capture_output=True, text=True, cwd=self.tmp,
                              env={"PATH": "/nonexistent", "PYTHONPATH": os.path.join(tree, "python")})
        self.assertEqual(done.returncode, 0, done.stderr)
        self.assertIn("WiggleError 127", done.stdout)
        self.assertIn("tools/bootstrap.sh build", done.stdout)
        # Built in that clone: its build tree's binary is the one run.
        os.makedirs(os.path.join(tree, "build", "release"))
        binary = self._fake_wiggle("exit 0\n")
        os.symlink(binary, os.path.join(tree, "build", "release", "wiggle"))
        done = subprocess.run(["/usr/bin/python3", "-c", "import wiggleplot as wp; print(wp.find_wiggle())"],
                              capture_output=True, text=True, cwd=self.tmp, env={"PATH": "/nonexistent",
                                                                   "PYTHONPATH": os.path.join(tree, "python")})
        self.assertEqual(done.stdout.strip(), os.path.join(tree, "build", "release", "wiggle"), done.stderr)

    def _fake_wiggle(self, body):
        path = os.path.join(self.tmp, "wiggle")
        with open(path, "w") as f:
            f.write("#!/bin/sh\n" + body)
        os.chmod(path, os.stat(path).st_mode | stat.S_IEXEC)
        return path

    def test_run_passes_overrides_and_reads_the_result(self):
        import wiggleplot as wp
        out = os.path.join(self.tmp, "out")
        log = os.path.join(self.tmp, "args")
        # A stand-in for wiggle: records its arguments and writes a run directory.
        script = (f'echo "$@" > {log}\n'
                  f'{sys.executable} -c "import sys; sys.path.insert(0, {REPO!r} + \'/python\'); '
                  f'from tests import synthetic; synthetic.write_run({out!r})"\n')
        run = wp.run("case.toml", out, {"drive.period": 5, "intruder.shape": "triangle", "fields.phases": [0, 5]},
                     wiggle=self._fake_wiggle(script), threads=1)
        with open(log) as f:
            args = f.read().split()
        self.assertEqual(args[:5], ["run", "case.toml", "--out", out, "--no-plot"])
        self.assertIn("drive.period=5", args)
        self.assertIn('intruder.shape="triangle"', args)
        self.assertIn("fields.phases=[0,", args)
        self.assertEqual(args[-2:], ["--threads", "1"])
        self.assertEqual(list(run.trajectory.columns[:3]), ["t", "x", "y"])

    def test_run_raises_wiggles_own_message(self):
        import wiggleplot as wp
        fake = self._fake_wiggle('echo "wiggle: warning: a note" >&2\n'
                                 'echo "wiggle: drive.period = 5.00005: must be a whole number of run.dt steps" >&2\n'
                                 "exit 2\n")
        with self.assertRaises(wp.WiggleError) as caught:
            wp.run(None, os.path.join(self.tmp, "x"), wiggle=fake)
        self.assertEqual(caught.exception.status, 2)
        self.assertEqual(str(caught.exception), "drive.period = 5.00005: must be a whole number of run.dt steps")

    @unittest.skipUnless(shutil.which("jupyter-nbconvert") or os.path.exists("/usr/bin/jupyter-nbconvert"),
                         "jupyter-nbconvert is not installed (tools/bootstrap.sh installs it)")
    def test_example_notebook_runs_on_a_sweep(self):
        d = os.path.join(self.tmp, "sweep")
        synthetic.write_sweep(d)
        figures = os.path.join(self.tmp, "figures")
        env = dict(os.environ, WIGGLE_SWEEP_DIR=d, WIGGLE_FIGURES_DIR=figures, MPLBACKEND="Agg",
                   PYTHONPATH=os.path.join(REPO, "python") + os.pathsep + os.environ.get("PYTHONPATH", ""))
        done = subprocess.run(["/usr/bin/python3", "-m", "nbconvert", "--to", "notebook", "--execute",
                               "--output-dir", self.tmp, "--ExecutePreprocessor.timeout=120",
                               os.path.join(REPO, "examples", "figures.ipynb")],
                              env=env, capture_output=True, text=True)
        self.assertEqual(done.returncode, 0, done.stderr[-2000:])
        for name in ("rate_vs_period.png", "rate_map.png"):
            self.assertTrue(os.path.exists(os.path.join(figures, name)), name)


if __name__ == "__main__":
    unittest.main()


class SchemaTest(unittest.TestCase):
    """The package reads summary.json by the names of docs/summary-schema.json, which a C++ test
    keeps equal to the table that writes the file."""

    def test_every_summary_key_the_package_reads_is_in_the_schema(self):
        import json
        import re
        with open(os.path.join(REPO, "docs", "summary-schema.json")) as f:
            names = {field["name"] for field in json.load(f)}
        used = set()
        package = os.path.join(REPO, "python", "wiggleplot")
        for name in os.listdir(package):
            if name.endswith(".py"):
                with open(os.path.join(package, name)) as f:
                    text = f.read()
                used |= set(re.findall(r'summary(?:\.get\(|\[)"([a-z_]+)"', text))
        self.assertTrue(used, "no summary key found: the pattern no longer matches the code")
        self.assertEqual(used - names, set())

    def test_results_columns_and_units_are_the_schemas(self):
        # docs/results-schema.json is results.csv's column table (a C++ test keeps it so): the columns
        # the figures must not take for parameters, and the units the DataFrames carry, are its own.
        import json
        from wiggleplot import data, prepare
        with open(os.path.join(REPO, "docs", "results-schema.json")) as f:
            schema = json.load(f)
        columns = schema["before_parameters"] + schema["after_parameters"]
        self.assertEqual(prepare.NON_PARAMETERS, {c["name"] for c in columns} | {"case_label"})
        for c in columns:
            if c["unit"]:
                self.assertEqual(data.UNITS.get(c["name"]), c["unit"], c["name"])
