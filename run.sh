#!/usr/bin/env bash
# Installs what is missing, builds dpana and runs one scene.
#   ./run.sh                 the default scene, prm/default.prm
#   ./run.sh prm/FILE.prm    any scene
set -euo pipefail
top="$(cd "$(dirname "$0")" && pwd)"
"$top/scripts/setup.sh"
scene="${1:-$top/prm/default.prm}"
exec "${DPANA_BUILD_DIR:-$top/build}/dpana" "$scene"
