#!/bin/sh
# wiggle vs LAMMPS (Debian's lmp and the optimised build of bench/build_lammps.sh) benchmark, with the
# contact law's floor: see bench/run_bench.py, bench/README.md and docs/PERFORMANCE.md. Usage:
#   bench/run_bench.sh [--quick] [--cases small,paper] [--codes wiggle,lammps,lammps-opt] [--rounds N]
#                      [--threads 1,2] [--no-floor] [--build-dir DIR] [--no-build] [--cache DIR]
exec /usr/bin/python3 "$(dirname "$0")/run_bench.py" "$@"
