#!/usr/bin/env bash
# The hard-case matrix of the contact solvers (README.md beside this file).
#   ./benchmarks/hard_cases/run.sh           the whole matrix (~10 min)
#   ./benchmarks/hard_cases/run.sh --quick   the subset of the ctest
# Builds dpana and hard_cases (Release, in build/ of the repository, or
# $DPANA_BUILD_DIR), then:
#   1. whole runs: scenes made hard by editing shipped ones (mu = 100 and
#      1000, elements of aspect ratio 100, the 3D block with mu = 1), run by
#      the dpana executable; their exit status and the solver of their
#      answer are tabulated, and each writes its condensed problem as FCLIB;
#   2. the matrix of condensed problems (problems.h) plus those FCLIB files,
#      against every solver.
# Output in $DPANA_BUILD_DIR/benchmarks/hard_cases_results/: runs.md,
# matrix.md, matrix.csv and the runs' folders.
set -euo pipefail
here="$(cd "$(dirname "$0")" && pwd)"
top="$(cd "$here/../.." && pwd)"
build="${DPANA_BUILD_DIR:-$top/build}"

DPANA_BUILD_DIR="$build" "$top/scripts/setup.sh"
cmake --build "$build" -j "${DPANA_JOBS:-2}" --target dpana hard_cases

out="$build/benchmarks/hard_cases_results"
mkdir -p "$out"
cd "$out"

# A scene from a shipped one: $1 the new name, $2 the shipped file, then
# sed expressions for its entries.
variant() {
  local name="$1" source="$top/prm/$2"
  shift 2
  local edits=(-e "s|set Directory = .*|set Directory = $out/runs/$name|")
  for edit in "$@"; do edits+=(-e "$edit"); done
  sed "${edits[@]}" "$source" > "$out/$name.prm"
  # Every run writes its condensed problem, for the matrix.
  sed -i -e "/^subsection Output/a\\  set Write FCLIB = true" \
    -e "/^subsection Output/a\\  set Plot = false" "$out/$name.prm"
}

mu() { echo "s|set Friction coefficient = .*|set Friction coefficient = $1|"; }

variant receding_2d_mu100 receding_2d_mu1.prm "$(mu 100)"
variant receding_2d_mu1000 receding_2d_mu1.prm "$(mu 1000)"
# Elements 40 mm / 400 wide and 40 mm / 4 high: aspect ratio 100.
variant receding_2d_aspect100 receding_2d_mu1.prm \
  "s|set Subdivisions = 32, 32|set Subdivisions = 400, 4|"
variant hertz_rigid_mu100 hertz_rigid_mu1.prm "$(mu 100)"
runs=(receding_2d_mu100 receding_2d_mu1000 receding_2d_aspect100
      hertz_rigid_mu100)
if [ "${1:-}" != "--quick" ]; then
  variant receding_3d_L160_mu1 receding_3d_L160.prm
  variant receding_3d_L160_mu100 receding_3d_L160.prm "$(mu 100)"
  runs+=(receding_3d_L160_mu1 receding_3d_L160_mu100)
fi

{
  echo "| run | exit | converged | solver of the answer | iterations | residual | message |"
  echo "|---|---:|---|---|---:|---:|---|"
} > runs.md
fclib=()
for name in "${runs[@]}"; do
  echo "run.sh: running $name"
  status=0
  "$build/dpana" "$out/$name.prm" > "$out/$name.log" 2>&1 || status=$?
  summary="$out/runs/$name/summary.json"
  if [ -f "$summary" ]; then
    /usr/bin/python3 - "$summary" "$name" "$status" >> runs.md << 'EOF'
import json, sys
c = json.load(open(sys.argv[1]))["contact"]
print(f"| {sys.argv[2]} | {sys.argv[3]} | {c['converged']} | "
      f"{c.get('solved_by', c['solver'])} | {c['iterations']} | "
      f"{c['residual']:.2e} | {c['message']} |")
EOF
    fclib+=("$out/runs/$name/problem.hdf5")
  else
    echo "| $name | $status | - | - | - | - | $(tail -1 "$out/$name.log") |" >> runs.md
  fi
done

"$build/benchmarks/hard_cases" --csv "$out/matrix.csv" "$@" \
  --fclib "${fclib[@]}" | tee "$out/matrix.md"
echo "run.sh: results in $out (runs.md, matrix.md, matrix.csv)"
