#!/bin/bash
# MPI kill-and-resume test of `wiggle sweep` (docs/SWEEPS.md), run by hand:
#
#   tests/sweep/mpi_test.sh [WIGGLE_BINARY] [WORK_DIR]
#
# On one machine, with `mpirun --oversubscribe -np 3` (rank 0 coordinates, ranks 1 and 2 run cases):
#   1. a reference run (with its own bed cache, so the MPI run makes its bed on a rank) of the same sweep without MPI (`--local`);
#   2. an MPI run in which a worker rank is killed with SIGKILL while it runs a case (after that
#      case's first checkpoint): Open MPI then aborts the whole job;
#   3. no case process may outlive its rank (they get SIGTERM from PR_SET_PDEATHSIG and checkpoint);
#   4. the same mpirun command again: it must resume (the killed case from its checkpoint) and end
#      with every good case ok, its state_hash equal to the reference, and the bad cases failed
#      with their error.
# The sweep has 6 tiny cases (20 d x 12 d bed): 3 run about 1-2 s each, 3 fail the geometry check
# (amplitude 7 does not fit the box). Total about 30 s on 2 cores. Exit status 0 when it passes.
# Needs a wiggle built with MPI (CMake found OpenMPI) and mpirun on PATH.
NAME=mpi_test
. "$(dirname "$0")/mpi_common.sh"
# Separate bed caches: the MPI run must make its bed on a worker rank too (bed task first).
export WIGGLE_CACHE="$WORK/cache-mpi"

cat > "$WORK/sweep.toml" <<EOF
[sweep]
name = "mpi-test"
[base.box]
width = 20.0
bed_height = 12.0
[base.intruder]
shape = "polygon"
vertices = [[-1.5, -1.5], [1.5, -1.5], [1.5, 1.5], [-1.5, 1.5]]
y0 = 6.0
[base.bed]
rest_energy = 1e-4
max_time = 100.0
[base.run]
dt = 0.0001
duration = 2.0
sample_interval = 0.01
dump_interval = 0.0
checkpoint_interval = 0.02
plot = false
[base.fields]
enabled = false
[grid.drive]
amplitude = [0.5, 7.0]
period = [1.0, 2.0, 4.0]
EOF

echo "mpi_test: work dir $WORK"
echo "mpi_test: 1. reference run without MPI"
WIGGLE_CACHE="$WORK/cache-local" "$W" sweep "$WORK/sweep.toml" --out "$WORK/local" --local --jobs 2 > "$WORK/local.out" 2>&1
[ $? -eq 1 ] || fail "the reference run should exit 1 (three cases fail); see $WORK/local.out"

echo "mpi_test: 2. MPI run, a worker rank killed mid-case"
OUT="$WORK/mpi"
$MPIRUN "$W" sweep "$WORK/sweep.toml" --out "$OUT" > "$WORK/mpi1.out" 2>&1 &
LAUNCHER=$!
# Either worker rank may make the bed and either may draw the three good cases (the failing ones end
# at once), so the victim is whichever rank first runs a good case past its first checkpoint. The
# wait is by the clock, not by a count of polls: the three ranks share two cores with whatever else
# runs, so how long the bed and the cases take depends on the machine's load.
victim="" ; case_name="" ; rank=""
deadline=$((SECONDS + 240))
while [ $SECONDS -lt $deadline ]; do
  kill -0 "$LAUNCHER" 2>/dev/null || break
  if [ -f "$OUT/sweep.log" ]; then
    while read -r name r; do
      if [ -f "$OUT/cases/$name/checkpoint.bin" ] && [ ! -f "$OUT/cases/$name/summary.json" ]; then
        case_name=$name rank=$r
        victim=$(sed -n "s/.*rank $r ready: pid \([0-9]*\) .*/\1/p" "$OUT/sweep.log" | head -1)
        break
      fi
    done < <(sed -n 's/.*start case \(.*\) on rank \([0-9]*\) .*/\1 \2/p' "$OUT/sweep.log")
    [ -n "$victim" ] && break
  fi
  sleep 0.05
done
if [ -z "$victim" ]; then
  kill -0 "$LAUNCHER" 2>/dev/null && why="within 240 s" || why="before mpirun exited"
  kill "$LAUNCHER" 2>/dev/null
  echo "--- $OUT/sweep.log:" >&2; cat "$OUT/sweep.log" >&2 2>/dev/null
  echo "--- mpirun's output ($WORK/mpi1.out):" >&2; tail -n 30 "$WORK/mpi1.out" >&2
  fail "no worker rank ran a case past its first checkpoint $why (sweep log and mpirun output above)"
fi
echo "mpi_test:    killing rank $rank (pid $victim) while it runs $case_name"
kill -9 "$victim"
wait "$LAUNCHER"
rc=$?
[ $rc -ne 0 ] || fail "mpirun should fail after a rank was killed"
echo "mpi_test:    mpirun exited with $rc"

echo "mpi_test: 3. no orphaned case process"
sleep 2
if pgrep -f -- "--out $OUT/cases" > /dev/null; then
  pgrep -af -- "--out $OUT/cases" >&2
  fail "case processes outlived their rank"
fi

echo "mpi_test: 4. rerun resumes"
$MPIRUN "$W" sweep "$WORK/sweep.toml" --out "$OUT" > "$WORK/mpi2.out" 2>&1
rc=$?
[ $rc -ne 0 ] || fail "the rerun should report the three failing cases (exit non-zero)"
grep -q "resumed from" "$OUT/cases/$case_name/log.txt" || fail "$case_name did not resume from its checkpoint"

/usr/bin/python3 - "$WORK/local/results.csv" "$OUT/results.csv" <<'EOF' || fail "results differ (above)"
import csv, sys
ref = {r["case"]: r for r in csv.DictReader(open(sys.argv[1]))}
got = {r["case"]: r for r in csv.DictReader(open(sys.argv[2]))}
bad = 0
assert ref.keys() == got.keys(), (ref.keys(), got.keys())
for name, r in ref.items():
    g = got[name]
    same = r["status"] == g["status"] and r["state_hash"] == g["state_hash"] and r["vy"] == g["vy"]
    print(f"  {name:28s} {r['status']:7s} {g['status']:7s} {r['state_hash']:17s} {g['state_hash']:17s} {'ok' if same else 'DIFFERENT'}")
    bad += not same
oks = sum(r["status"] == "ok" for r in got.values())
fails = sum(r["status"] == "failed" and "too narrow" in r["error"] for r in got.values())
print(f"  {oks} ok, {fails} failed with the geometry error")
sys.exit(1 if bad or oks != 3 or fails != 3 else 0)
EOF
echo "mpi_test: PASS"
