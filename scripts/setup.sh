#!/usr/bin/env bash
# Shared set-up of ./run.sh and ./test.sh: installs the Debian packages dpana
# needs (only those missing, so a second call installs nothing), configures a
# Release build in build/ and builds it with two jobs.
#
# Environment: DPANA_BUILD_DIR (default build), DPANA_BUILD_TYPE (default
# Release), DPANA_JOBS (default 2); DPANA_PACKAGES_ONLY=1 installs the
# packages and stops (scripts/sanitize.sh, which builds elsewhere).
set -euo pipefail

top="$(cd "$(dirname "${BASH_SOURCE[0]}")/.." && pwd)"
build_dir="${DPANA_BUILD_DIR:-$top/build}"
build_type="${DPANA_BUILD_TYPE:-Release}"
jobs="${DPANA_JOBS:-2}"

# Debian packages used by the code, the tests and the plot scripts.
packages=(
  cmake g++ make
  libdeal.ii-dev        # finite elements (deal.II 9.4)
  libeigen3-dev         # dense algebra and the CHOLMOD interface
  libsuitesparse-dev    # CHOLMOD sparse Cholesky
  libmetis-dev          # nested dissection of a body's interior
  libmumps-dev          # MUMPS' C interface (a given ordering on one process)
  libopenblas-dev       # the BLAS of the dense products of the condensation
  nlohmann-json3-dev    # summary.json
  libgtest-dev          # unit tests
  numdiff               # regression runs compared with reference output
  python3 python3-matplotlib python3-numpy # plots of results and benchmarks
  libsiconos-numerics-dev # independent contact solvers for cross-checks
  gmsh                  # meshes made from .geo files (tutorials, 3D Hertz sphere)
  openmpi-bin           # mpirun: the MPI route and its tests (tests/mpi)
  clang-format
)

missing=()
for p in "${packages[@]}"; do
  if ! dpkg-query -W -f='${Status}' "$p" 2>/dev/null | grep -q "install ok installed"; then
    missing+=("$p")
  fi
done

if [ ${#missing[@]} -gt 0 ]; then
  echo "dpana setup: installing ${missing[*]}"
  sudo_cmd=()
  if [ "$(id -u)" -ne 0 ]; then
    if command -v sudo >/dev/null 2>&1; then
      sudo_cmd=(sudo)
    else
      echo "dpana setup: packages missing (${missing[*]}) and not root: install them or run as root" >&2
      exit 1
    fi
  fi
  "${sudo_cmd[@]}" apt-get update
  "${sudo_cmd[@]}" env DEBIAN_FRONTEND=noninteractive \
    apt-get install -y --no-install-recommends "${missing[@]}"
fi

if [ "${DPANA_PACKAGES_ONLY:-0}" = 1 ]; then
  exit 0
fi

if [ ! -f "$build_dir/CMakeCache.txt" ]; then
  echo "dpana setup: configuring $build_type build in $build_dir"
  cmake -S "$top" -B "$build_dir" -DCMAKE_BUILD_TYPE="$build_type"
fi
echo "dpana setup: building with $jobs jobs"
cmake --build "$build_dir" -j "$jobs"
