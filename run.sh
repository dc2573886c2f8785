#!/usr/bin/env bash
# Installs what is missing, builds dpana and runs one scene or tutorial.
#   ./run.sh                 the default scene, prm/default.prm
#   ./run.sh prm/FILE.prm    any scene
#   ./run.sh --tutorial N    tutorial step N (doc/tutorials/step-N), run in
#                            build/doc/tutorials/step-N; its figures are
#                            copied to doc/tutorials/step-N/figures/
set -euo pipefail
top="$(cd "$(dirname "$0")" && pwd)"
"$top/scripts/setup.sh"
if [ "${1:-}" = "--tutorial" ]; then
  exec "$top/doc/tutorials/run_step.sh" "${2:?usage: ./run.sh --tutorial N}"
fi
scene="${1:-$top/prm/default.prm}"
# Scenes on generated meshes name them in "# mesh:" lines (gmsh, if missing).
python3 "$top/scripts/meshes/make_meshes.py" "$scene"
exec "${DPANA_BUILD_DIR:-$top/build}/dpana" "$scene"
