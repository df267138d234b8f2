#!/usr/bin/env bash
# Fuzzing with libFuzzer (docs/RELIABILITY.md):
#   tools/fuzz.sh TARGET SECONDS [libFuzzer options...]
# TARGET: run_config | sweep_file | checkpoint | bed_cache | all (each for SECONDS).
# Builds the targets in the "asan-ubsan" preset's tree (clang-14, ASan + UBSan, asserts on; the same
# tree CI's sanitized unit tests run in) at build/asan-ubsan, seeds each target from the
# shipped configs, the bad-input corpora and small state files made by a tiny run, and fuzzes with
# a 2 GB memory limit and 60 s per input (wall clock: generous, as a loaded
# machine can slow a nice-d fuzzer 30-fold). The growing corpus stays in build/asan-ubsan/corpus/TARGET;
# findings are written to build/asan-ubsan/findings/. Prints executions and findings per target; exits
# non-zero when a target found a crash, a hang or an allocation past the limit.
# Environment: WIGGLE_JOBS (build parallelism, default: nproc); WIGGLE_SEED_BINARY (a wiggle binary
# that makes the seed state files, e.g. build/release/wiggle; default: build/asan-ubsan/wiggle, built here).
set -euo pipefail
cd "$(dirname "$0")/.."
root=$(pwd)
[ $# -ge 2 ] || { echo "usage: tools/fuzz.sh run_config|sweep_file|checkpoint|bed_cache|all SECONDS [libFuzzer options]" >&2; exit 2; }
what=$1 seconds=$2
shift 2
case "$what" in
  all) targets=(run_config sweep_file checkpoint bed_cache) ;;
  run_config|sweep_file|checkpoint|bed_cache) targets=("$what") ;;
  *) echo "tools/fuzz.sh: unknown target '$what'" >&2; exit 2 ;;
esac
binary_of() {
  case "$1" in run_config) echo fuzz_RunConfig ;; sweep_file) echo fuzz_SweepFile ;;
    checkpoint) echo fuzz_Checkpoint ;; bed_cache) echo fuzz_BedCache ;; esac
}

B=build/asan-ubsan
cmake --preset asan-ubsan > /dev/null
seeder=${WIGGLE_SEED_BINARY:-}
names=()
[ -n "$seeder" ] || { names+=(wiggle); seeder=$B/wiggle; }
for t in "${targets[@]}"; do names+=("$(binary_of "$t")"); done
mkdir -p "$B"
for n in "${names[@]}"; do
  cmake --build --preset asan-ubsan -j "${WIGGLE_JOBS:-$(nproc)}" --target "$n" > "$B/build.log" 2>&1 || { cat "$B/build.log" >&2; exit 1; }
done

# Seed state files: a checkpoint and a cached bed of a tiny run (made once).
seeds=$B/seeds
if [ ! -f "$seeds/state/checkpoint.bin" ]; then
  rm -rf "$seeds/state" && mkdir -p "$seeds/state"
  OMP_NUM_THREADS=1 WIGGLE_CACHE="$seeds/state/cache" "$seeder" run --out "$seeds/state/run" --threads 1 --no-plot \
    --set box.width=16 --set box.bed_height=10 --set intruder.shape=polygon \
    --set 'intruder.vertices=[[-1,-1],[1,-1],[1,1],[-1,1]]' --set intruder.y0=5 --set drive.amplitude=0.5 \
    --set drive.period=0.1 --set bed.rest_energy=1e-3 --set run.duration=0.05 --set run.sample_interval=0.01 \
    --set run.dump_interval=0 --set fields.radius=2 --set fields.phases=[0,10] > "$seeds/state/run.log" 2>&1
  cp "$seeds/state/run/checkpoint.bin" "$seeds/state/checkpoint.bin"
fi

status=0
for t in "${targets[@]}"; do
  seed=$seeds/$t corpus=$B/corpus/$t
  rm -rf "$seed" && mkdir -p "$seed" "$corpus" "$B/findings"
  case "$t" in
    run_config) cp configs/*.toml tests/data/bad_inputs/* "$seed/" ;;
    sweep_file) cp configs/sweeps/*.toml tests/data/bad_sweeps/* "$seed/" ;;
    checkpoint) cp "$seeds/state/checkpoint.bin" "$seed/" ;;
    bed_cache) cp "$seeds"/state/cache/bed-*.bin "$seed/" ;;
  esac
  log=$B/findings/$t.log
  set +e
  "$B/$(binary_of "$t")" -max_total_time="$seconds" -rss_limit_mb=2048 -malloc_limit_mb=2048 -timeout=60 \
    -print_final_stats=1 -artifact_prefix="$root/$B/findings/$t-" "$@" "$corpus" "$seed" > "$log" 2>&1
  rc=$?
  set -e
  runs=$(sed -n 's/^stat::number_of_executed_units: *//p' "$log" | tail -1)
  cov=$(grep -o 'cov: [0-9]*' "$log" | tail -1)
  artifacts=$(sed -n 's/.*Test unit written to //p' "$log")
  echo "fuzz $t: ${runs:-?} executions in ${seconds} s, ${cov:-cov ?}, corpus $(ls "$corpus" | wc -l) files," \
       "exit $rc${artifacts:+, finding: $artifacts}"
  if [ $rc -ne 0 ]; then
    grep -m 3 -E "ERROR|SUMMARY|==[0-9]+==" "$log" >&2 || true
    echo "fuzz $t: see $log" >&2
    status=1
  fi
done
exit $status
