#!/usr/bin/env bash
# Whole dpana runs of the 3D scale scenes at growing sizes, then the table
# and the log-log plots with fitted exponents.
#   ./benchmarks/scale/run.sh                 1e4 .. 3e5 dofs (minutes)
#   ./benchmarks/scale/run.sh --quick         two small sizes (seconds)
#   ./benchmarks/scale/run.sh --full          up to 1e6 dofs, 1e4 contact
#                                             unknowns (~15 GB, several min)
#   ./benchmarks/scale/run.sh --out DIR ...   results into DIR
#   ./benchmarks/scale/run.sh --scenes receding   one scene family only
# Builds the Release dpana in build/ (or $DPANA_BUILD_DIR). Output in
# benchmarks/scale/results/ (or DIR): results.csv, results.md (the table),
# exponents.md, scale.png, and runs/NAME/ (the .prm, the log, the output).
set -euo pipefail
here="$(cd "$(dirname "$0")" && pwd)"
top="$(cd "$here/../.." && pwd)"
build="${DPANA_BUILD_DIR:-$top/build}"
. "$here/../common.sh"

out="$here/results"
sizes=default
scenes=receding,hertz_sphere
while [ $# -gt 0 ]; do
  case "$1" in
    --quick | --full) sizes="${1#--}"; shift ;;
    --out | --scenes)
      if [ $# -lt 2 ]; then
        echo "run.sh: error: $1 needs a value" >&2
        exit 1
      fi
      [ "$1" = --out ] && out="$2" || scenes="$2"
      shift 2
      ;;
    *)
      echo "run.sh: error: unknown argument '$1'" >&2
      exit 1
      ;;
  esac
done

build_targets dpana

python="${PYTHON:-/usr/bin/python3}"
require_matplotlib
mkdir -p "$out"
"$python" "$here/scale.py" --dpana "$build/dpana" --prm-dir "$top/prm" \
  --out "$out" --sizes "$sizes" --scenes "$scenes"
"$python" "$here/plot.py" "$out/results.csv"
echo "results in $out"
