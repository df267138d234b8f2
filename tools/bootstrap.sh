#!/usr/bin/env bash
# One entry point for a fresh Debian 12 machine (run as root, or with sudo available):
#   tools/bootstrap.sh run  [wiggle run args...]   install what is missing, build, run the default case
#   tools/bootstrap.sh test [ctest args...]        install what is missing, build, run the fast tests
# Environment: WIGGLE_PRESET (default "release"; CI sets WIGGLE_WERROR=ON for the first configure of
# build/release instead, so its one release tree has warnings as errors; and runs "asan-ubsan").
set -euo pipefail
cd "$(dirname "$0")/.."

packages=(build-essential cmake libgtest-dev libgmock-dev libbenchmark-dev libtomlplusplus-dev libcli11-dev
          nlohmann-json3-dev libomp-dev libopenmpi-dev openmpi-bin python3 python3-matplotlib python3-numpy
          python3-pandas jupyter-nbconvert python3-ipykernel python3-nbformat   # the analysis API and its notebook
          python3-dev python3-pybind11  # the engine as a Python module (import wiggle)
          clang-14 libclang-rt-14-dev   # clang: the fuzz and tsan presets (docs/RELIABILITY.md)
          ffmpeg                        # wiggle plot --movie
          chromium)                     # wiggle report's test opens the page in a headless browser
missing=()
for p in "${packages[@]}"; do
  dpkg-query -W -f='${Status}' "$p" 2>/dev/null | grep -q "install ok installed" || missing+=("$p")
done
if [ ${#missing[@]} -gt 0 ]; then
  echo "bootstrap: installing ${missing[*]}"
  sudo_cmd=""
  [ "$(id -u)" -ne 0 ] && sudo_cmd="sudo"
  $sudo_cmd apt-get update -qq
  DEBIAN_FRONTEND=noninteractive $sudo_cmd apt-get install -y -qq --no-install-recommends "${missing[@]}"
fi

preset="${WIGGLE_PRESET:-release}"
what="${1:-}"
shift || true
cmake --preset "$preset" > /dev/null
# A newcomer's first run needs only what a user runs (the command, `import wiggle`, the man page:
# CMake's user_programs target); the tests and benchmarks are built by `test`.
targets=()
[ "$what" = run ] && targets=(--target user_programs)
cmake --build --preset "$preset" -j "$(nproc)" "${targets[@]}"

case "$what" in
  # Typed again (the README's first command), the default run continues in wiggle-out: an
  # interrupted run from its checkpoint, a finished one only has its results and figures rewritten.
  run)
    if [ $# -eq 0 ] && [ -e wiggle-out/config.toml ]; then
      echo "bootstrap: wiggle-out already holds a run: continuing it (wiggle run --resume; --out DIR for a new one)"
      set -- --resume
    fi
    exec "build/$preset/wiggle" run "$@" ;;
  # Every test runs once and any failure fails the run: no test gets a second attempt. The tests
  # run in a random order, so two that wrote one file or directory would meet in some run. The
  # SIGKILL harnesses (label reliability) run last, beside each other only: their kills wait for
  # events (a checkpoint at a step, a file written), not for times, but they are the slowest to watch.
  test)
    cd "build/$preset"
    status=0
    ctest -LE "slow|mpi|reliability" --output-on-failure -j "$(nproc)" --schedule-random "$@" || status=1
    ctest -L reliability -LE "slow|mpi" --output-on-failure -j "$(nproc)" "$@" || status=1
    exit $status ;;
  build|"") ;;
  *) echo "usage: tools/bootstrap.sh run|test|build" >&2; exit 2 ;;
esac
