#!/usr/bin/env bash
# Runs the contact scenes of prm/ and tabulates, per scene, the size, the
# solver's iterations and residual, the contact half width a, the maximum
# normal traction, the zones, the errors against the scene's reference and
# the time of every phase; plots the Hertz tractions against the Hertz
# pressure profile.
#   ./benchmarks/scenes/run.sh              every contact scene (a few minutes)
#   ./benchmarks/scenes/run.sh --quick      without the 3D blocks L = 160, 320
#   ./benchmarks/scenes/run.sh --out DIR    results into DIR
# Output (benchmarks/scenes/results/ or DIR): scenes.md (the table),
# scenes.csv, hertz.png, and per scene its log and output directory under
# runs/.
set -euo pipefail
here="$(cd "$(dirname "$0")" && pwd)"
top="$(cd "$here/../.." && pwd)"
build="$(realpath -m "${DPANA_BUILD_DIR:-$top/build}")"
. "$here/../common.sh"

out="$here/results"
quick=0
while [ $# -gt 0 ]; do
  case "$1" in
    --quick)
      quick=1
      shift
      ;;
    --out)
      if [ $# -lt 2 ]; then
        echo "run.sh: error: --out needs a directory" >&2
        exit 1
      fi
      out="$2"
      shift 2
      ;;
    *)
      echo "run.sh: error: unknown argument '$1'" >&2
      exit 1
      ;;
  esac
done

build_targets dpana

scenes=(receding_2d_mu0 receding_2d_mu1 receding_2d_nu0_mu1 receding_3d_L80)
if [ "$quick" = 0 ]; then
  scenes+=(receding_3d_L160 receding_3d_L320)
fi
scenes+=(two_body_ratio_1 two_body_ratio_1e-3 two_body_ratio_1e3
  hertz_rigid_mu0 hertz_rigid_mu0_d_shaped hertz_rigid_mu1
  hertz_ratio_1_mu0 hertz_ratio_1_mu1 hertz_ratio_1e-3_mu0 hertz_ratio_1e-3_mu1
  hertz_ratio_1e3_mu0 hertz_ratio_1e3_mu1 hertz_cavity_mu0 hertz_cavity_mu1)

# Every scene runs in runs/ (the parameter files name their output
# directory relative to the working directory); the 3D scenes compare with
# the CSV of receding_2d_nu0_mu1, which runs first.
mkdir -p "$out/runs"
rm -rf "$out/runs/output" "$out/runs/"*.log
status=0
for s in "${scenes[@]}"; do
  echo "== $s"
  if (cd "$out/runs" && "$build/dpana" "$top/prm/$s.prm" > "$s.log" 2>&1); then
    grep -E "^(Results|Reference)" "$out/runs/$s.log" || true
  else
    echo "run.sh: $s failed (see $out/runs/$s.log)" >&2
    status=1
  fi
done

python="${PYTHON:-/usr/bin/python3}"
require_matplotlib
"$python" "$here/table.py" "$out" "${scenes[@]}"
echo "results in $out"
exit $status
