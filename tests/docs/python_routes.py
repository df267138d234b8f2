#!/usr/bin/python3
"""The documented Python routes, run exactly as the documents write them, in a fresh copy of the
source tree (its tracked files, no build, nothing set in the environment but PATH and HOME).

    python_routes.py SOURCE_DIR BUILD_DIR [--after-set-up]

1. The notebook's own command, `jupyter nbconvert --to notebook --execute examples/figures.ipynb`,
   typed at the root of the copy with nothing built: it must redraw figures 5 and 14 from the
   committed results (results/paper_depth/fig5).
2. python/README.md's `wp.run(...)` line, run from the root with `PYTHONPATH=python` as documented:
   first with nothing built (it must raise the package's own WiggleError saying what to do, not a
   raw FileNotFoundError), then with the copy built (build/release linked to BUILD_DIR): it must
   find the build tree's wiggle and return the run.
3. docs/PYTHON.md's `import wiggle` line, its ```python examples and the engine's notebook
   (examples/engine.ipynb) by its documented command, at the root of the built copy (when the
   module is built).
4. The notebook as `cmake --install` puts it (share/wiggle/examples), run where it was installed,
   and `import wiggle` from where the install puts the module (PYTHONPATH=PREFIX/share/wiggle/python).
Every command is taken from the documents' text (a test of the text, not of a variant of it).
The notebooks run with TMPDIR set to a directory of the test's own, which must be left empty (a
notebook cleans up what it writes there). Exits 1 with a line per failure. The bed of route 2 goes
to $WIGGLE_CACHE when set.

--after-set-up: BUILD_DIR is what the README's set-up commands left (CI runs this right after
`tools/bootstrap.sh run`), so every route must work there: the Python module missing from it is a
failure, not a route skipped.
"""
import glob
import json
import os
import re
import shlex
import shutil
import subprocess
import sys
import tempfile

NOTEBOOK_COMMAND = "jupyter nbconvert --to notebook --execute examples/figures.ipynb"
ENGINE_NOTEBOOK_COMMAND = "PYTHONPATH=$PWD/build/release/python jupyter nbconvert --to notebook --execute examples/engine.ipynb"
failures = []


def check(ok, message):
    if not ok:
        failures.append(message)
        print(f"python_routes: FAIL: {message}", file=sys.stderr)
    return ok


def documented(path, needle):
    with open(path, encoding="utf-8") as f:
        return needle in f.read()


def fresh_copy(source, dest):
    """The files a clone has: git's tracked files when SOURCE is a checkout, else the tree without build/."""
    listed = subprocess.run(["git", "-C", source, "ls-files", "-z"], capture_output=True)
    if listed.returncode == 0 and listed.stdout:
        for name in listed.stdout.decode().split("\0"):
            if name and os.path.lexists(os.path.join(source, name)):
                os.makedirs(os.path.join(dest, os.path.dirname(name)), exist_ok=True)
                shutil.copy2(os.path.join(source, name), os.path.join(dest, name), follow_symlinks=False)
    else:
        shutil.copytree(source, dest, dirs_exist_ok=True, ignore=shutil.ignore_patterns("build", "wiggle-out"))


def shell(command, cwd, home, extra=None):
    env = {"PATH": "/usr/bin:/bin", "HOME": home}
    env.update(extra or {})
    return subprocess.run(["/bin/sh", "-c", command], cwd=cwd, env=env, capture_output=True, text=True,
                          timeout=1200)


def notebook_left_nothing(tmp, what):
    """The notebook left nothing in its TMPDIR (issue 53: figures.ipynb left /tmp/wiggle-figures-*)."""
    left = sorted(os.listdir(tmp))
    check(not left, f"{what}: the notebook left {left} in its temporary directory")
    for name in left:
        shutil.rmtree(os.path.join(tmp, name), ignore_errors=True)


def executed_notebook_ok(path, what, figures=3, what_figures="figures 5, 14 and a trajectory"):
    """Whether the executed notebook at `path` holds its figures and no error."""
    if not check(os.path.exists(path), f"{what}: no executed notebook {path}"):
        return
    with open(path, encoding="utf-8") as f:
        nb = json.load(f)
    outputs = [o for c in nb["cells"] if c["cell_type"] == "code" for o in c.get("outputs", [])]
    images = sum("image/png" in o.get("data", {}) for o in outputs)
    errors = [o for o in outputs if o.get("output_type") == "error"]
    check(not errors, f"{what}: the notebook raised {errors[:1]}")
    check(images >= figures, f"{what}: {images} figures shown, expected {what_figures}")


def main():
    source, build = os.path.abspath(sys.argv[1]), os.path.abspath(sys.argv[2])
    after_set_up = "--after-set-up" in sys.argv[3:]
    work = tempfile.mkdtemp(prefix="wiggle-python-routes-")
    try:
        home = os.path.join(work, "home")
        os.makedirs(home)
        tmp = {"TMPDIR": os.path.join(work, "tmp")}  # the notebooks' temporary files
        os.makedirs(tmp["TMPDIR"])
        tree = os.path.join(work, "clone")
        fresh_copy(source, tree)

        # 1. The notebook's own command at the root of the copy.
        check(documented(os.path.join(tree, "python", "README.md"), NOTEBOOK_COMMAND),
              "python/README.md no longer gives the notebook's command")
        check(documented(os.path.join(tree, "examples", "figures.ipynb"), NOTEBOOK_COMMAND),
              "the notebook no longer gives its command")
        done = shell(NOTEBOOK_COMMAND, tree, home, tmp)
        if check(done.returncode == 0, f"`{NOTEBOOK_COMMAND}` at the root: exit {done.returncode}: {done.stderr[-1500:]}"):
            executed_notebook_ok(os.path.join(tree, "examples", "figures.nbconvert.ipynb"), "notebook at the root")
        notebook_left_nothing(tmp["TMPDIR"], "notebook at the root")

        # 2. python/README.md's wp.run line, from the root with PYTHONPATH=python.
        with open(os.path.join(tree, "python", "README.md"), encoding="utf-8") as f:
            line = next((l for l in f if "wp.run(" in l and l.lstrip().startswith("run = ")), None)
        if check(line is not None, "python/README.md has no `run = wp.run(...)` line"):
            code = "import wiggleplot as wp; " + line.split("#")[0].strip() + "; print('vy', run.vy)"
            command = f"PYTHONPATH=python /usr/bin/python3 -c {shlex.quote(code)}"
            cache = {"WIGGLE_CACHE": os.environ["WIGGLE_CACHE"]} if os.environ.get("WIGGLE_CACHE") else {}
            unbuilt = shell(command, tree, home, cache)
            check(unbuilt.returncode != 0 and "WiggleError" in unbuilt.stderr and "tools/bootstrap.sh build" in unbuilt.stderr,
                  f"wp.run with nothing built: expected the package's WiggleError naming tools/bootstrap.sh build, got "
                  f"exit {unbuilt.returncode}: {unbuilt.stderr.strip().splitlines()[-1:]}")
            os.makedirs(os.path.join(tree, "build"))
            os.symlink(build, os.path.join(tree, "build", "release"))
            built = shell(command, tree, home, cache)
            if check(built.returncode == 0, f"wp.run built: exit {built.returncode}: {built.stderr[-1500:]}"):
                check(re.search(r"^vy [-+0-9.e]+$", built.stdout, re.M) is not None, f"wp.run printed {built.stdout!r}")
                check(os.path.exists(os.path.join(tree, "t5", "summary.json")), "wp.run wrote no t5/summary.json")

        # 3. docs/PYTHON.md's `import wiggle` line in the built copy (when the module was built; after
        # the README's set-up it must have been).
        module_built = bool(glob.glob(os.path.join(build, "python", "wiggle.*.so")))
        check(module_built or not after_set_up,
              f"the README's set-up left no Python module in {build}/python (docs/PYTHON.md: import wiggle)")
        if module_built or after_set_up:
            with open(os.path.join(tree, "docs", "PYTHON.md"), encoding="utf-8") as f:
                engine_line = next((l.strip() for l in f if l.startswith("PYTHONPATH=build/release/python ")), None)
            if check(engine_line is not None, "docs/PYTHON.md has no `PYTHONPATH=build/release/python ...` line"):
                cache = {"WIGGLE_CACHE": os.environ["WIGGLE_CACHE"]} if os.environ.get("WIGGLE_CACHE") else {}
                done = shell(engine_line, tree, home, cache)
                if check(done.returncode == 0, f"docs/PYTHON.md's line: exit {done.returncode}: {done.stderr[-1500:]}"):
                    check(re.search(r"^1\.0 [-+0-9.e]+ [0-9a-f]{16}$", done.stdout, re.M) is not None,
                          f"docs/PYTHON.md's line printed {done.stdout!r}")
                # the engine's notebook, by the command docs/PYTHON.md and the notebook give;
                for where in (os.path.join("docs", "PYTHON.md"), os.path.join("examples", "engine.ipynb")):
                    check(documented(os.path.join(tree, where), ENGINE_NOTEBOOK_COMMAND),
                          f"{where} no longer gives the engine notebook's command")
                done = shell(ENGINE_NOTEBOOK_COMMAND, tree, home, {**cache, **tmp})
                if check(done.returncode == 0, f"`{ENGINE_NOTEBOOK_COMMAND}`: exit {done.returncode}: {done.stderr[-1500:]}"):
                    executed_notebook_ok(os.path.join(tree, "examples", "engine.nbconvert.ipynb"), "engine notebook",
                                         figures=2, what_figures="the grains with the path, and y(t) with the counts")
                notebook_left_nothing(tmp["TMPDIR"], "engine notebook")
                # and its ```python examples, each as written (the module and the plotting package on
                # PYTHONPATH, as the page says).
                with open(os.path.join(tree, "docs", "PYTHON.md"), encoding="utf-8") as f:
                    blocks = re.findall(r"^```python\n(.*?)^```$", f.read(), re.M | re.S)
                check(len(blocks) > 0, "docs/PYTHON.md has no ```python example")
                check(documented(os.path.join(tree, "docs", "PYTHON.md"), "PYTHONPATH=build/release/python:python"),
                      "docs/PYTHON.md no longer says the path its ```python examples run with")
                for k, code in enumerate(blocks):
                    done = shell(f"PYTHONPATH=build/release/python:python /usr/bin/python3 -c {shlex.quote(code)}",
                                 tree, home, cache)
                    check(done.returncode == 0, f"docs/PYTHON.md's python example {k + 1}: exit {done.returncode}: "
                                                f"{done.stderr[-1500:]}")

        # 4. The installed notebook, run where it was installed; `import wiggle` from the installed tree.
        prefix = os.path.join(work, "prefix")
        installed = subprocess.run(["cmake", "--install", build, "--prefix", prefix], capture_output=True, text=True)
        if check(installed.returncode == 0, f"cmake --install: {installed.stderr[-500:]}"):
            examples = os.path.join(prefix, "share", "wiggle", "examples")
            done = shell("jupyter nbconvert --to notebook --execute figures.ipynb", examples, home, tmp)
            if check(done.returncode == 0, f"installed notebook: exit {done.returncode}: {done.stderr[-1500:]}"):
                executed_notebook_ok(os.path.join(examples, "figures.nbconvert.ipynb"), "installed notebook")
            notebook_left_nothing(tmp["TMPDIR"], "installed notebook")
            if module_built:
                package = os.path.join(prefix, "share", "wiggle", "python")
                done = shell("/usr/bin/python3 -c 'import wiggle; print(wiggle.__version__)'", work, home,
                             {"PYTHONPATH": package})
                check(done.returncode == 0, f"import wiggle from {package}: exit {done.returncode}: {done.stderr[-500:]}")
    finally:
        shutil.rmtree(work, ignore_errors=True)
    if not failures:
        print("python_routes: ok: the notebook at the root of a fresh copy and installed, wp.run unbuilt and built, "
              "import wiggle built and installed")
    return 1 if failures else 0


if __name__ == "__main__":
    sys.exit(main())
