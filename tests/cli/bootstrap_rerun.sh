#!/usr/bin/env bash
# The README's first command, `tools/bootstrap.sh run`, typed twice must succeed twice (issue 27):
# the second continues the run in wiggle-out instead of refusing it. And it must build what every
# documented route needs (issue 53). The script is run from a copy of the tree's tools/ with the
# build step stubbed (cmake on PATH records its arguments and does nothing) and the built
# binary behind build/release/wiggle, its default case shrunk to a tiny one (--set) so that the
# test takes seconds; the decision to refuse or continue is the real binary's.
# Usage: bootstrap_rerun.sh SOURCE_DIR WIGGLE_BINARY
set -euo pipefail
src=$1
binary=$2
work=$(mktemp -d /tmp/wiggle-bootstrap-test-XXXXXX)
trap 'rm -rf "$work"' EXIT
mkdir -p "$work/tree/tools" "$work/tree/build/release" "$work/bin"
cp "$src/tools/bootstrap.sh" "$work/tree/tools/"
printf '#!/bin/sh\necho "$*" >> "%s/cmake-calls"\nexit 0\n' "$work" > "$work/bin/cmake"
cat > "$work/tree/build/release/wiggle" <<WRAP
#!/bin/sh
exec "$binary" "\$@" --threads 1 --set box.width=20 --set box.bed_height=12 --set intruder.shape=square \
  --set intruder.y0=6 --set drive.amplitude=0.5 --set drive.period=1 --set bed.rest_energy=1e-4 \
  --set run.duration=0.05 --set run.sample_interval=0.005 --set run.dump_interval=0 --set fields.enabled=false --set run.plot=false
WRAP
chmod +x "$work/bin/cmake" "$work/tree/build/release/wiggle"
export PATH="$work/bin:$PATH" WIGGLE_CACHE="$work/cache"
# The README's command as a newcomer types it: the default preset, whatever preset runs this test
# (a developer may run the suite with WIGGLE_PRESET set).
unset WIGGLE_PRESET
for attempt in 1 2; do
  if ! "$work/tree/tools/bootstrap.sh" run > "$work/out$attempt" 2>&1; then
    echo "bootstrap_rerun: FAIL: 'tools/bootstrap.sh run' #$attempt exited non-zero:" >&2
    cat "$work/out$attempt" >&2
    exit 1
  fi
done
grep -q "V_y = " "$work/out2" || { echo "bootstrap_rerun: FAIL: no result the second time" >&2; cat "$work/out2" >&2; exit 1; }
# What `run` builds is every program a documented route needs (issue 53: it built only `wiggle`,
# and `import wiggle` failed after it): CMake's user_programs target, which this build tree has.
grep -q -- "--build .*--target user_programs" "$work/cmake-calls" ||
  { echo "bootstrap_rerun: FAIL: 'tools/bootstrap.sh run' does not build user_programs:" >&2; cat "$work/cmake-calls" >&2; exit 1; }
targets=$(/usr/bin/cmake --build "$(dirname "$binary")" --target help)
grep -q "user_programs" <<< "$targets" ||
  { echo "bootstrap_rerun: FAIL: the build tree has no user_programs target" >&2; exit 1; }
echo "bootstrap_rerun: ok: run twice, both exit 0; it builds user_programs"
