#!/usr/bin/env bash
# Convergence sweeps with time: every scene family of families.py over its
# refinement levels with the Release dpana, the GetFEM harness on the same
# problems (getfem/), and the tables and plots of the run.
#   ./benchmarks/convergence/run.sh                 all families (about 70 min
#                                                   on a loaded 2-core machine)
#   ./benchmarks/convergence/run.sh --full          one more level each
#   ./benchmarks/convergence/run.sh --out DIR       results into DIR
#   ./benchmarks/convergence/run.sh --no-getfem     dpana only
#   ./benchmarks/convergence/run.sh FAMILY ...      these families only
# GetFEM (Debian python3-getfem) and gmsh are installed here with apt-get
# when missing; when they cannot be installed the benchmark says so and runs
# dpana alone.
# Output (benchmarks/convergence/results/ or DIR): <family>.json (dpana),
# getfem_<family>.json, convergence.md (the tables), summary.json, the PNGs.
set -euo pipefail
here="$(cd "$(dirname "$0")" && pwd)"
top="$(cd "$here/../.." && pwd)"
build="$(realpath -m "${DPANA_BUILD_DIR:-$top/build}")"
. "$here/../common.sh"
python="${PYTHON:-/usr/bin/python3}"

out="$here/results"
full=()
getfem=1
families=()
while [ $# -gt 0 ]; do
  case "$1" in
    --full) full=(--full); shift ;;
    --no-getfem) getfem=0; shift ;;
    --out) out="${2:?run.sh: error: --out needs a directory}"; shift 2 ;;
    -*) echo "run.sh: error: unknown option '$1'" >&2; exit 1 ;;
    *) families+=("$1"); shift ;;
  esac
done

# The peer: GetFEM's Python interface and gmsh (its meshes), from Debian.
install_peer() {
  local missing=()
  for p in python3-getfem gmsh python3-matplotlib python3-numpy; do
    if ! dpkg-query -W -f='${Status}' "$p" 2> /dev/null |
      grep -q "install ok installed"; then
      missing+=("$p")
    fi
  done
  [ ${#missing[@]} -eq 0 ] && return 0
  local sudo_cmd=()
  if [ "$(id -u)" -ne 0 ]; then
    command -v sudo > /dev/null 2>&1 || return 1
    sudo_cmd=(sudo)
  fi
  echo "run.sh: installing ${missing[*]}"
  "${sudo_cmd[@]}" apt-get update > /dev/null &&
    "${sudo_cmd[@]}" env DEBIAN_FRONTEND=noninteractive \
      apt-get install -y --no-install-recommends "${missing[@]}" > /dev/null
}
if [ "$getfem" = 1 ]; then
  if ! install_peer || ! "$python" -c "import getfem" 2> /dev/null; then
    echo "run.sh: GetFEM (python3-getfem) is not available: dpana alone"
    getfem=0
  fi
fi
require_matplotlib

if [ ! -f "$build/CMakeCache.txt" ]; then
  cmake -S "$top" -B "$build" -DCMAKE_BUILD_TYPE=Release > /dev/null
fi
cmake --build "$build" -j "${DPANA_JOBS:-2}" --target dpana

# The families GetFEM also solves: those the sweep is asked for (all by
# default). They are timed side by side, dpana then GetFEM per family, and
# every level runs twice (DPANA_REPEAT; a level under 0.1 s five times,
# one under 1 s three times, records.py), its fastest run kept (the machine
# may be shared).
repeat="${DPANA_REPEAT:-2}"
peer_all=(hertz_rigid_mu0 hertz_rigid_mu0_r10 hertz_rigid_mu0_graded
  hertz_rigid_mu1_graded hertz_ratio_1_mu0_graded hertz_ratio_1_mu0_graded_block
  hertz_rigid_mu0_d_shaped
  receding_2d_mu0
  receding_2d_mu1 two_body_ratio_1 two_body_ratio_1e-3 two_body_ratio_1e3
  hertz_ratio_1_mu0 hertz_ratio_1e-3_mu0 hertz_ratio_1e3_mu0
  hertz_ratio_1e3_mu0_graded_block hertz_ratio_1_mu1_graded_block
  hertz_ratio_1e3_mu1_graded_block hertz_ratio_1e-3_mu0_graded_block
  hertz_ratio_1e-3_mu1_graded_block hertz_cavity_mu1_graded receding_3d_L80
  hertz_sphere_rigid hertz_sphere_rigid_nested hertz_sphere_rigid_nested3
  hertz_rigid_mu1
  hertz_ratio_1_mu1 hertz_ratio_1e-3_mu1 hertz_ratio_1e3_mu1 hertz_cavity_mu0
  hertz_cavity_mu0_graded hertz_cavity_mu1
  hertz_two_spheres hertz_two_spheres_mu03 hertz_two_spheres_nested)
peer=()
rest=()
if [ ${#families[@]} -eq 0 ]; then
  mapfile -t families < <(cd "$here" && "$python" -c \
    "import families; print('\n'.join(f.name for f in families.FAMILIES))")
fi
for f in "${families[@]}"; do
  if [ "$getfem" = 1 ] && [[ " ${peer_all[*]} " == *" $f "* ]]; then
    peer+=("$f")
  else
    rest+=("$f")
  fi
done

mkdir -p "$out"
echo "run.sh: load average $(cut -d' ' -f1-3 /proc/loadavg)"
for f in "${peer[@]}"; do
  "$python" "$here/sweep.py" --dpana "$build/dpana" --prm-dir "$top/prm" \
    --out "$out" --repeat "$repeat" "${full[@]}" "$f"
  "$python" "$here/getfem/sweep.py" --dpana "$build/dpana" --out "$out" \
    --repeat "$repeat" "${full[@]}" "$f"
done
if [ ${#rest[@]} -gt 0 ]; then
  "$python" "$here/sweep.py" --dpana "$build/dpana" --prm-dir "$top/prm" \
    --out "$out" "${full[@]}" "${rest[@]}"
fi
"$python" "$here/analyse.py" "$out"
echo "results in $out"
