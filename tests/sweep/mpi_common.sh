# Sourced by the MPI test scripts (mpi_test.sh, mpi_boundary_test.sh) with their own arguments
# [WIGGLE_BINARY] [WORK_DIR] and NAME set: W (the binary, an absolute path), WORK (made), MPIRUN
# (three ranks on this machine, passing WIGGLE_CACHE on; each script sets that cache) and fail.
set -u
W=$(readlink -f "${1:-$(dirname "$0")/../../build/release/wiggle}")
WORK=${2:-$(mktemp -d "/tmp/wiggle-$NAME.XXXXXX")}
mkdir -p "$WORK"
# As root, Open MPI refuses to start without these.
export OMPI_ALLOW_RUN_AS_ROOT=1 OMPI_ALLOW_RUN_AS_ROOT_CONFIRM=1
MPIRUN="mpirun --oversubscribe -np 3 -x WIGGLE_CACHE"
fail() { echo "$NAME: FAIL: $*" >&2; exit 1; }
