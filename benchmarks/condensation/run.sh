#!/usr/bin/env bash
# Builds the condensation benchmark (Release, target condensation_benchmark,
# in build/ of the repository or $DPANA_BUILD_DIR), runs it and plots the
# result.
#   ./benchmarks/condensation/run.sh                 default sizes (minutes)
#   ./benchmarks/condensation/run.sh --quick         small scenes (seconds)
#   ./benchmarks/condensation/run.sh --full          up to 1.1 M dofs
#   ./benchmarks/condensation/run.sh --out DIR ...   results into DIR
# Other arguments are passed to the executable (e.g. --repeats N;
# --only TEXT, repeatable: the cases whose label contains TEXT;
# --schur-only: the Schur route with CHOLMOD alone;
# --orderings or --analysis-only [--box "M, H, M"]: the table of the
# orderings of the Schur route into orderings.txt, no plot).
# Output: results.csv, results.txt and condensation.png in
# benchmarks/condensation/results/ (or DIR), printed at the end.
set -euo pipefail
here="$(cd "$(dirname "$0")" && pwd)"
top="$(cd "$here/../.." && pwd)"
build="${DPANA_BUILD_DIR:-$top/build}"
. "$here/../common.sh"

out="$here/results"
args=()
while [ $# -gt 0 ]; do
  case "$1" in
    --out)
      if [ $# -lt 2 ]; then
        echo "run.sh: error: --out needs a directory" >&2
        exit 1
      fi
      out="$2"
      shift 2
      ;;
    *)
      args+=("$1")
      shift
      ;;
  esac
done

build_targets condensation_benchmark

mkdir -p "$out"
case " ${args[*]-} " in
  *" --orderings "* | *" --analysis-only "*)
    # The table of the orderings only: no csv, no plot.
    "$build/benchmarks/condensation_benchmark" --prm-dir "$top/prm" \
      "${args[@]}" | tee "$out/orderings.txt"
    exit 0
    ;;
esac
"$build/benchmarks/condensation_benchmark" --prm-dir "$top/prm" \
  --csv "$out/results.csv" \
  ${args[@]+"${args[@]}"} | tee "$out/results.txt"

# matplotlib comes from Debian (python3-matplotlib): use the system
# interpreter explicitly (another python3 first on the PATH may lack it),
# unless PYTHON is set.
python="${PYTHON:-/usr/bin/python3}"
require_matplotlib
"$python" "$here/plot.py" "$out/results.csv" "$out/condensation.png"
echo "results in $out"
