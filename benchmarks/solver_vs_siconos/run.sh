#!/usr/bin/env bash
# Builds the solver_vs_siconos benchmark (Release, in build/ of the
# repository, or $DPANA_BUILD_DIR), runs it and plots the result.
#   ./benchmarks/solver_vs_siconos/run.sh            default sizes (< 2 min)
#   ./benchmarks/solver_vs_siconos/run.sh --quick    a few seconds
#   ./benchmarks/solver_vs_siconos/run.sh --full     larger problems (minutes)
# First the FE scenes of scenes/*.prm are run with the built dpana (in the
# output directory, under fe_scenes/); each writes its condensed contact
# problem to fe_scenes/<scene>/problem.hdf5 (FCLIB), and these files are
# added to the benchmarked problems with --fclib.
# Output: results.csv, results.txt and solver_vs_siconos.png in
# $DPANA_BUILD_DIR/benchmarks/solver_vs_siconos_results/ (printed at the end).
set -euo pipefail
here="$(cd "$(dirname "$0")" && pwd)"
top="$(cd "$here/../.." && pwd)"
build="${DPANA_BUILD_DIR:-$top/build}"

# The project's set-up: installs what is missing, configures and builds.
DPANA_BUILD_DIR="$build" "$top/scripts/setup.sh"
targets="$(cmake --build "$build" --target help)"
if ! grep -q "solver_vs_siconos" <<< "$targets"; then
  echo "run.sh: error: Siconos numerics was not found by CMake" \
       "(install libsiconos-numerics-dev); the benchmark needs it" >&2
  exit 1
fi
cmake --build "$build" -j "${DPANA_JOBS:-2}" --target dpana solver_vs_siconos

out="$build/benchmarks/solver_vs_siconos_results"
mkdir -p "$out"

# The FE scenes: condensed problems of real contact runs.
fclib=()
for prm in "$here"/scenes/*.prm; do
  name="$(basename "$prm" .prm)"
  echo "run.sh: running the scene $name"
  (cd "$out" && "$build/dpana" "$prm" > "$out/scene_$name.log")
  file="$out/fe_scenes/$name/problem.hdf5"
  if [ ! -f "$file" ]; then
    echo "run.sh: error: the scene $name wrote no $file" >&2
    exit 1
  fi
  fclib+=("$file")
done

"$build/benchmarks/solver_vs_siconos" --csv "$out/results.csv" "$@" \
  --fclib "${fclib[@]}" | tee "$out/results.txt"

# matplotlib comes from Debian (python3-matplotlib): prefer the system
# interpreter, which sees it, over any other python3 on the PATH.
python="${PYTHON:-}"
if [ -z "$python" ]; then
  for candidate in /usr/bin/python3 python3; do
    if "$candidate" -c "import matplotlib" 2> /dev/null; then
      python="$candidate"
      break
    fi
  done
fi
if [ -z "$python" ]; then
  echo "run.sh: error: no python3 with matplotlib found (set PYTHON)" >&2
  exit 1
fi
"$python" "$here/plot.py" "$out/results.csv" "$out/solver_vs_siconos.png"
echo "results in $out"
