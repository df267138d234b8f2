#!/usr/bin/env bash
# The benchmark's LAMMPS anchor: the same LAMMPS version as Debian's `lmp` (the `lammps` package),
# built from Debian's own source package with -O3 -march=native and the OPENMP package, so that
# wiggle is compared with an optimised LAMMPS too and not only with the distribution's generic build.
#
#   bench/build_lammps.sh          builds (or finds) it and prints the binary's path on the last line
#
# Cache, outside the repository: ${WIGGLE_BENCH_CACHE:-$HOME/.cache/wiggle-bench}/lammps-opt
#   src/        Debian's source package (apt-get source)
#   build/lmp   the binary
#   build.log   the last build's output
#   build.stamp the source version and CMake flags the binary was built from: when they match the
#               present ones, the script does nothing
# Needs root (it adds a deb-src entry for bookworm main when apt has none, and apt-get installs the
# build tools and Debian's `lammps`). The build runs at nice 5 with 2 jobs (the machine is shared).
set -euo pipefail

die() { echo "build_lammps.sh: $*" >&2; exit 1; }

cache="${WIGGLE_BENCH_CACHE:-$HOME/.cache/wiggle-bench}/lammps-opt"
mkdir -p "$cache"
# Two benchmark runs starting at once must not build into the same directory.
exec 9> "$cache/.lock"
flock 9

# Every package the exported deck needs (wiggle export-lammps, docs/LAMMPS-EXPORT.md) is in LAMMPS's
# core except gran/hertz/history and fix freeze (GRANULAR); OPENMP gives the /omp styles that
# `-sf omp` picks; RIGID is there for decks that use fix rigid. Images, movies and compressed dumps
# are not needed, so their optional libraries stay out.
cmake_flags=(-D CMAKE_BUILD_TYPE=Release -D "CMAKE_CXX_FLAGS_RELEASE=-O3 -march=native"
             -D PKG_GRANULAR=on -D PKG_RIGID=on -D PKG_OPENMP=on -D BUILD_OMP=on -D BUILD_MPI=on
             -D WITH_JPEG=off -D WITH_PNG=off -D WITH_FFMPEG=off -D WITH_GZIP=off)

apt_install() {
  local missing=()
  for p in "$@"; do
    dpkg-query -W -f='${Status}' "$p" 2>/dev/null | grep -q "install ok installed" || missing+=("$p")
  done
  [ ${#missing[@]} -eq 0 ] && return 0
  [ "$(id -u)" -eq 0 ] || die "needs root to install ${missing[*]}"
  echo "build_lammps.sh: installing ${missing[*]}"
  DEBIAN_FRONTEND=noninteractive apt-get install -y -qq --no-install-recommends "${missing[@]}" \
    || die "apt-get install ${missing[*]} failed"
}

# Debian's `lmp` first: the benchmark runs it too, and its version is the one to build.
if ! dpkg-query -W -f='${Status}' lammps 2>/dev/null | grep -q "install ok installed"; then
  [ "$(id -u)" -eq 0 ] || die "needs root to install Debian's lammps"
  apt-get update -qq || die "apt-get update failed"
  apt_install lammps
fi
version="$(dpkg-query -W -f='${source:Version}' lammps)"   # e.g. 20220106.git7586adbb6a+ds1-2
stamp="source lammps $version; cmake ${cmake_flags[*]}"
binary="$cache/build/lmp"

if [ -x "$binary" ] && [ -f "$cache/build.stamp" ] && [ "$(cat "$cache/build.stamp")" = "$stamp" ]; then
  echo "build_lammps.sh: up to date (LAMMPS source $version)"
  echo "$binary"
  exit 0
fi

[ "$(id -u)" -eq 0 ] || die "needs root (apt-get source, build dependencies)"
apt_install dpkg-dev build-essential cmake libopenmpi-dev openmpi-bin libomp-dev

# apt-get source needs a deb-src entry. This image declares its sources in deb822 files
# (/etc/apt/sources.list.d/*.sources, "Types: deb"); older ones use one-line "deb-src" entries.
if ! grep -qsE '^[[:space:]]*(deb-src[[:space:]]|Types:.*deb-src)' /etc/apt/sources.list /etc/apt/sources.list.d/*.list \
       /etc/apt/sources.list.d/*.sources; then
  echo "build_lammps.sh: adding deb-src for bookworm main (/etc/apt/sources.list.d/wiggle-deb-src.sources)"
  cat > /etc/apt/sources.list.d/wiggle-deb-src.sources <<'EOF'
Types: deb-src
URIs: http://deb.debian.org/debian
Suites: bookworm bookworm-updates
Components: main
Signed-By: /usr/share/keyrings/debian-archive-keyring.gpg
EOF
fi
apt-get update -qq || die "apt-get update failed"

upstream="${version#*:}"
upstream="${upstream%-*}"                                   # the Debian revision off: the directory name
srcdir="$cache/src/lammps-$upstream"
if [ ! -f "$srcdir/cmake/CMakeLists.txt" ]; then
  rm -rf "$cache/src"
  mkdir -p "$cache/src"
  (cd "$cache/src" && apt-get source -qq "lammps=$version") || die "apt-get source lammps=$version failed"
  [ -f "$srcdir/cmake/CMakeLists.txt" ] || die "no $srcdir/cmake/CMakeLists.txt after apt-get source"
fi

# A build tree of another source goes; one of the same source is built on incrementally (CMake
# picks up changed flags), so an interrupted build does not start again from nothing.
rm -f "$cache/build.stamp"
[ "$(cat "$cache/build/wiggle-source" 2>/dev/null)" = "$srcdir" ] || rm -rf "$cache/build"
mkdir -p "$cache/build"
echo "$srcdir" > "$cache/build/wiggle-source"
echo "build_lammps.sh: building LAMMPS $version in $cache/build (nice 5, 2 jobs; log: $cache/build.log)"
{
  cmake -S "$srcdir/cmake" -B "$cache/build" "${cmake_flags[@]}" &&
  nice -n 5 make -C "$cache/build" -j2
} > "$cache/build.log" 2>&1 || { tail -n 30 "$cache/build.log" >&2; die "build failed; see $cache/build.log"; }
[ -x "$binary" ] || die "build finished without $binary"
# The build must have the styles the benchmark uses with -sf omp.
# (Captured first: grep -q would stop reading early, and pipefail would count lmp's broken pipe.)
styles="$("$binary" -h)" || die "$binary -h failed"
grep -q "gran/hertz/history/omp" <<< "$styles" || die "$binary lacks gran/hertz/history/omp"
echo "$stamp" > "$cache/build.stamp"
echo "build_lammps.sh: built (LAMMPS source $version)"
echo "$binary"
