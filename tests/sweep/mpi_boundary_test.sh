#!/bin/bash
# `wiggle boundary` under MPI (docs/SWEEPS.md), against the same search run locally:
#
#   tests/sweep/mpi_boundary_test.sh [WIGGLE_BINARY] [WORK_DIR]
#
# A period search over tiny cases (20 d x 12 d bed, t = 1) that takes two rounds (the coarse scan on
# two beds, then a third bed at each point): run with --jobs 2 on this machine, then under
# `mpirun --oversubscribe -np 3` (rank 0 searches, ranks 1 and 2 run each round's cases, waiting
# between rounds). The two must reach the same probes and verdicts from the same runs (every case's
# state hash equal), and the same mpirun command again must find every run finished and start none.
# About 15 s on 2 cores. Exit status 0 when it passes. Needs a wiggle built with MPI and mpirun.
NAME=mpi_boundary_test
. "$(dirname "$0")/mpi_common.sh"
export WIGGLE_CACHE="$WORK/cache"

cat > "$WORK/base.toml" <<EOF
[box]
width = 20.0
bed_height = 12.0
[intruder]
shape = "polygon"
vertices = [[-1.5, -1.5], [1.5, -1.5], [1.5, 1.5], [-1.5, 1.5]]
y0 = 6.0
[bed]
rest_energy = 1e-4
max_time = 100.0
[run]
dt = 0.0001
duration = 1.0
sample_interval = 0.01
dump_interval = 0.0
plot = false
[fields]
enabled = false
EOF
SEARCH=("$WORK/base.toml" --set drive.amplitude=1 --range 0.5:2 --resolution 0.25 --points 3 --beds 2:3)

echo "mpi_boundary_test: work dir $WORK"
echo "mpi_boundary_test: 1. the search on this machine"
"$W" boundary "${SEARCH[@]}" --out "$WORK/local" --jobs 2 > "$WORK/local.out" 2>&1 || fail "local search failed: see $WORK/local.out"

echo "mpi_boundary_test: 2. the search under mpirun -np 3"
timeout 300 $MPIRUN "$W" boundary "${SEARCH[@]}" --out "$WORK/mpi" > "$WORK/mpi1.out" 2>&1 || fail "MPI search failed: see $WORK/mpi1.out"
rounds=$(grep -c "MPI worker ranks" "$WORK/mpi/sweep.log")
[ "$rounds" -ge 2 ] || fail "the search took $rounds round(s) under MPI; the test needs at least 2"
grep -q "on rank 1" "$WORK/mpi/sweep.log" && grep -q "on rank 2" "$WORK/mpi/sweep.log" || fail "not both worker ranks ran cases"

echo "mpi_boundary_test: 3. the same mpirun command again"
timeout 300 $MPIRUN "$W" boundary "${SEARCH[@]}" --out "$WORK/mpi" > "$WORK/mpi2.out" 2>&1 || fail "MPI rerun failed: see $WORK/mpi2.out"
[ "$(grep -c "MPI worker ranks" "$WORK/mpi/sweep.log")" -eq "$rounds" ] || fail "the rerun started a sweep"

/usr/bin/python3 - "$WORK/local" "$WORK/mpi" <<'EOF' || fail "the two searches differ (above)"
import csv, json, sys
def searches(d):
    j = json.load(open(f"{d}/boundary.json"))["searches"]
    for s in j:  # its wall time differs from run to run
        s.pop("cost", None)
    return json.dumps(j, sort_keys=True)
def hashes(d):
    return {r["case"]: (r["status"], r["state_hash"], r["vy"]) for r in csv.DictReader(open(f"{d}/results.csv"))}
a, b = sys.argv[1:3]
same_runs = hashes(a) == hashes(b)
same_search = searches(a) == searches(b)
print(f"  {len(hashes(b))} runs; the same state hashes: {same_runs}; the same probes and verdicts: {same_search}")
sys.exit(0 if same_runs and same_search and all(s == "ok" for s, _, _ in hashes(b).values()) else 1)
EOF
echo "mpi_boundary_test: PASS"
