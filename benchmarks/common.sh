# The steps every benchmark's run.sh shares; sourced by them after they set
# top (the source tree), build (the build directory) and, before
# require_matplotlib, python (the interpreter of the plots).

# Configures the Release build in $build and builds the targets given, with
# DPANA_JOBS jobs (default 2).
build_targets() {
  cmake -S "$top" -B "$build" -DCMAKE_BUILD_TYPE=Release > /dev/null
  cmake --build "$build" -j "${DPANA_JOBS:-2}" --target "$@"
}

# Stops with one line, exit 1, unless $python can import matplotlib.
require_matplotlib() {
  if ! "$python" -c "import matplotlib" 2> /dev/null; then
    echo "run.sh: error: $python cannot import matplotlib (set PYTHON)" >&2
    exit 1
  fi
}
