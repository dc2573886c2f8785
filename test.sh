#!/usr/bin/env bash
# Installs what is missing, builds dpana and runs every test with ctest.
# Extra arguments go to ctest (e.g. ./test.sh -R contact).
set -euo pipefail
top="$(cd "$(dirname "$0")" && pwd)"
"$top/scripts/setup.sh"
cd "${DPANA_BUILD_DIR:-$top/build}"
exec ctest --output-on-failure -j "${DPANA_JOBS:-2}" "$@"
