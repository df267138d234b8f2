#!/bin/sh
# wiggle vs LAMMPS benchmark: see bench/run_bench.py (and docs/PERFORMANCE.md). Usage:
#   bench/run_bench.sh [--quick] [--rounds N] [--threads 1,2] [--build-dir DIR] [--cache DIR]
exec /usr/bin/python3 "$(dirname "$0")/run_bench.py" "$@"
