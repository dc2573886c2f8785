#!/usr/bin/env bash
# Builds and runs tutorial step N in build/doc/tutorials/step-N, then copies
# the figures its run made (output/*.png) into doc/tutorials/step-N/figures/,
# where its results.md shows them.
#
#   doc/tutorials/run_step.sh N
set -euo pipefail
top="$(cd "$(dirname "$0")/../.." && pwd)"
n=${1:?usage: run_step.sh N}
build="${DPANA_BUILD_DIR:-$top/build}"
cmake --build "$build" -j "${DPANA_JOBS:-2}" --target "step-$n"
run="$build/doc/tutorials/step-$n"
mkdir -p "$run"
cd "$run"
"$build/doc/tutorials/bin/step-$n"
if compgen -G "output/*.png" > /dev/null; then
  mkdir -p "$top/doc/tutorials/step-$n/figures"
  cp output/*.png "$top/doc/tutorials/step-$n/figures/"
  echo "figures copied to doc/tutorials/step-$n/figures/"
fi
