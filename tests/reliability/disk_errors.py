#!/usr/bin/python3
"""Full disk, file-size limit and read-only output directory (docs/RELIABILITY.md):

    tests/reliability/disk_errors.py WIGGLE_BINARY [--work DIR] [--keep]

Each case must end with a non-zero exit, exactly one error line on stderr naming the file and the
system's reason, no temporary file left behind, and every file written earlier byte for byte as
it was; a run stopped that way must then resume to the uninterrupted run's results.
  1. ulimit -f (RLIMIT_FSIZE, SIGXFSZ ignored by wiggle): a resumed run cannot write its checkpoint.
  2. A full file system (a small tmpfs): a second run and a sweep on a disk the first run filled.
  3. A read-only file system (tmpfs remounted read-only; without mount rights as a non-root user,
     a chmod 0555 directory): a new run, a resume of a finished run, a sweep, and a bed cache
     there (the last only warns: the run goes on without caching its bed).
Cases 2 and 3 need `mount` (root with CAP_SYS_ADMIN); where it is refused they print SKIP and why.
"""
import argparse
import os
import resource
import shutil
import subprocess
import sys
import tempfile
import time

sys.path.insert(0, os.path.dirname(os.path.abspath(__file__)))
from kill_resume import RUN_CONFIG, Reporter, compare_run_dirs, read  # noqa: E402  (one tiny case for both)

_report = Reporter("disk_errors")
log, check, failures = _report.log, _report.check, _report.failures


def snapshot(directory):
    """Every file under `directory` with its bytes."""
    files = {}
    for base, _, names in os.walk(directory):
        for n in names:
            p = os.path.join(base, n)
            files[os.path.relpath(p, directory)] = read(p)
    return files


def temporaries(directory):
    return [os.path.join(b, n) for b, _, names in os.walk(directory) for n in names if ".tmp" in n]


def tiny_sweep(work):
    """A sweep of two tiny cases: the run config under [base], two periods in [grid]."""
    path = os.path.join(work, "tiny.sweep.toml")
    with open(path, "w") as f:
        f.write(RUN_CONFIG.format(duration=0.3).replace("\n[", "\n[base.").replace("[box]", "[base.box]") +
                "[grid.drive]\nperiod = [0.5, 1.0]\n")
    return path


class Wiggle:
    def __init__(self, binary, cache):
        self.binary, self.cache = binary, cache

    def run(self, args, limit=None, cache=None):
        env = dict(os.environ, OMP_NUM_THREADS="1", OMP_WAIT_POLICY="PASSIVE", WIGGLE_CACHE=cache or self.cache)
        pre = (lambda: resource.setrlimit(resource.RLIMIT_FSIZE, (limit, limit))) if limit else None
        p = subprocess.run([self.binary] + args, env=env, capture_output=True, text=True, preexec_fn=pre,
                           timeout=600)
        return p.returncode, p.stderr

    def start(self, args):
        env = dict(os.environ, OMP_NUM_THREADS="1", OMP_WAIT_POLICY="PASSIVE", WIGGLE_CACHE=self.cache)
        return subprocess.Popen([self.binary] + args, env=env, stdout=subprocess.DEVNULL, stderr=subprocess.DEVNULL)


def expect_one_line_error(label, rc, stderr, reason):
    errors = [l for l in stderr.splitlines() if l.startswith("wiggle: ") and not l.startswith("wiggle: warning")]
    log(f"{label}: exit {rc}; {errors[-1] if errors else repr(stderr.strip()[-200:])}")
    check(rc not in (0, None) and rc > 0, f"{label}: exit status {rc}, expected a non-zero exit (not a signal)")
    check(len(errors) == 1, f"{label}: expected one error line, got {errors or stderr!r}")
    check(bool(errors) and reason in errors[-1], f"{label}: the error does not say '{reason}'")


class Mount:
    """A small tmpfs at `path`; `ok` False (with `why`) when mounting is not permitted here."""

    def __init__(self, path, size):
        self.path = path
        os.makedirs(path, exist_ok=True)
        p = subprocess.run(["mount", "-t", "tmpfs", "-o", f"size={size}", "tmpfs", path], capture_output=True, text=True)
        self.ok, self.why = p.returncode == 0, p.stderr.strip()

    def read_only(self):
        p = subprocess.run(["mount", "-o", "remount,ro", self.path], capture_output=True, text=True)
        return p.returncode == 0

    def __enter__(self):
        return self

    def __exit__(self, *exc):
        if self.ok:
            subprocess.run(["umount", self.path])


def file_size_limit(w, cfg, work, ref):
    out = os.path.join(work, "fsize")
    p = w.start(["run", cfg, "--out", out, "--threads", "1"])
    end = time.monotonic() + 120
    while not os.path.exists(os.path.join(out, "checkpoint.bin")) and p.poll() is None and time.monotonic() < end:
        time.sleep(0.005)
    p.kill()
    p.wait()
    before = snapshot(out)
    # The last good checkpoint: checkpoint.bin, or checkpoint.prev.bin when the kill came between the
    # two steps of a checkpoint's write (the old one moved aside, the new one not yet in place).
    last_good = before.get("checkpoint.bin", before.get("checkpoint.prev.bin"))
    check(last_good is not None and "summary.json" not in before, "ulimit: no checkpoint to resume from")
    limit = len(before["config.toml"]) + 2048  # config.toml fits, a checkpoint does not
    rc, err = w.run(["run", "--out", out, "--resume", "--threads", "1"], limit=limit)
    expect_one_line_error(f"ulimit -f {limit} B, resume", rc, err, "File too large")
    after = snapshot(out)
    check(last_good is not None and last_good in (after.get("checkpoint.bin"), after.get("checkpoint.prev.bin")),
          "ulimit: the last good checkpoint was not kept")
    check(after.get("config.toml") == before["config.toml"], "ulimit: config.toml changed")
    check(not temporaries(out), f"ulimit: temporary files left: {temporaries(out)}")
    rc, err = w.run(["run", "--out", out, "--resume", "--threads", "1"])
    check(rc == 0, f"ulimit: the resume without a limit failed: {err.strip()[-300:]}")
    if rc == 0 and compare_run_dirs(ref, out, "ulimit"):
        log("ulimit: resumed without the limit: outputs identical to the uninterrupted run")


def full_disk(w, cfg, work, ref):
    small = os.path.join(work, "small-disk")
    # Room for the finished run's files plus about half a checkpoint: the next run fills the disk.
    pages = sum((len(b) + 4095) // 4096 for b in snapshot(ref).values()) + 3
    checkpoint = len(read(os.path.join(ref, "checkpoint.bin")))
    size = pages * 4096 + checkpoint // 2
    with Mount(small, size) as m:
        if not m.ok:
            log(f"SKIP full disk: cannot mount a tmpfs ({m.why})")
            return
        shutil.copytree(ref, os.path.join(small, "first"))
        first = snapshot(os.path.join(small, "first"))
        rc, err = w.run(["run", cfg, "--out", os.path.join(small, "second"), "--threads", "1"])
        expect_one_line_error(f"full disk ({size} B tmpfs), second run", rc, err, "No space left on device")
        check(snapshot(os.path.join(small, "first")) == first, "full disk: the first run's files changed")
        check(not temporaries(small), f"full disk: temporary files left: {temporaries(small)}")
        try:  # now fill it up to the last byte
            with open(os.path.join(small, "filler"), "wb") as f:
                while True:
                    f.write(b"\0" * 4096)
                    f.flush()
        except OSError:
            pass
        sweep = tiny_sweep(work)
        rc, err = w.run(["sweep", sweep, "--out", os.path.join(small, "sweep"), "--local"])
        expect_one_line_error("full disk, sweep", rc, err, "No space left on device")
        check(snapshot(os.path.join(small, "first")) == first, "full disk: the first run's files changed")


def read_only(w, cfg, work, ref):
    ro = os.path.join(work, "read-only")
    with Mount(ro, "16m") as m:
        if m.ok:
            shutil.copytree(ref, os.path.join(ro, "done"))
            if not m.read_only():
                log("SKIP read-only: cannot remount the tmpfs read-only")
                return
            reason = "Read-only file system"
        elif os.geteuid() != 0:
            log(f"read-only: no mount rights ({m.why}); using a chmod 0555 directory instead")
            shutil.copytree(ref, os.path.join(ro, "done"))
            for base, dirs, _ in os.walk(ro):
                for d in dirs:
                    os.chmod(os.path.join(base, d), 0o555)
            os.chmod(ro, 0o555)
            reason = "Permission denied"
        else:
            log(f"SKIP read-only: running as root (which ignores chmod) and mount is refused ({m.why})")
            return
        done = snapshot(os.path.join(ro, "done"))
        rc, err = w.run(["run", cfg, "--out", os.path.join(ro, "new"), "--threads", "1"])
        expect_one_line_error("read-only, new run", rc, err, reason)
        rc, err = w.run(["run", "--out", os.path.join(ro, "done"), "--resume", "--threads", "1"])
        expect_one_line_error("read-only, resume of a finished run", rc, err, reason)
        sweep = tiny_sweep(work)
        rc, err = w.run(["sweep", sweep, "--out", os.path.join(ro, "sweep"), "--local"])
        expect_one_line_error("read-only, sweep", rc, err, reason)
        check(snapshot(os.path.join(ro, "done")) == done, "read-only: the finished run's files changed")
        # A bed cache that cannot be written: a warning, and the run goes on.
        out = os.path.join(work, "ro-cache")
        rc, err = w.run(["run", cfg, "--out", out, "--threads", "1"], cache=os.path.join(ro, "cache"))
        warned = [l for l in err.splitlines() if "bed not cached" in l]
        log(f"read-only bed cache: exit {rc}; {warned[0] if warned else err.strip()[-200:]}")
        check(rc == 0 and len(warned) == 1, "read-only bed cache: expected one warning and a finished run")
        if rc == 0:
            compare_run_dirs(ref, out, "read-only bed cache")
        if not m.ok:
            for base, dirs, _ in os.walk(ro):
                os.chmod(base, 0o755)


def main():
    ap = argparse.ArgumentParser(description=__doc__, formatter_class=argparse.RawDescriptionHelpFormatter)
    ap.add_argument("wiggle")
    ap.add_argument("--work", default=None)
    ap.add_argument("--keep", action="store_true")
    a = ap.parse_args()
    work = a.work or tempfile.mkdtemp(prefix="wiggle-disk-errors-")
    os.makedirs(work, exist_ok=True)
    log(f"work dir {work}")
    w = Wiggle(os.path.abspath(a.wiggle), os.path.join(work, "cache"))
    cfg = os.path.join(work, "run.toml")
    with open(cfg, "w") as f:
        f.write(RUN_CONFIG.format(duration=0.3))
    ref = os.path.join(work, "ref")
    rc, err = w.run(["run", cfg, "--out", ref, "--threads", "1"])
    if not check(rc == 0, f"the reference run failed: {err.strip()[-300:]}"):
        return 1
    file_size_limit(w, cfg, work, ref)
    full_disk(w, cfg, work, ref)
    read_only(w, cfg, work, ref)
    log(f"{len(failures)} failures")
    if failures:
        log(f"FAILED (work dir kept: {work})")
        return 1
    if not a.keep and a.work is None:
        shutil.rmtree(work)
    log("PASS")
    return 0


if __name__ == "__main__":
    sys.exit(main())
