#!/bin/bash
# Builds dpana with AddressSanitizer and UndefinedBehaviorSanitizer in its own
# build directory and runs the unit tests, the .prm regression runs and the
# fuzz test there, all with leak detection on. Any sanitizer report stops
# the offending run with a non-zero status, so the ctest that ran it fails.
#
#   scripts/sanitize.sh [BUILD_DIR]      (default: build-sanitize)
#
# Prints the ctest summary and the wall time; exits non-zero if a test failed.
set -eu
cd "$(dirname "$0")/.."
build=${1:-build-sanitize}
start=$(date +%s)
# The packages of ./run.sh and ./test.sh (only those missing).
DPANA_PACKAGES_ONLY=1 scripts/setup.sh
flags="-O1 -g -fno-omit-frame-pointer -fsanitize=address,undefined"
flags="$flags -fno-sanitize-recover=undefined"
# ccache, where it is installed, keeps the objects of an earlier build.
launcher=()
if command -v ccache > /dev/null 2>&1; then
  launcher=(-DCMAKE_CXX_COMPILER_LAUNCHER=ccache)
fi
cmake -S . -B "$build" -DCMAKE_BUILD_TYPE=Release "${launcher[@]}" \
  -DCMAKE_CXX_FLAGS="$flags" \
  -DCMAKE_EXE_LINKER_FLAGS="-fsanitize=address,undefined" \
  -DDPANA_FUZZ_TIMEOUT=5400 > /dev/null
cmake --build "$build" -j2 \
  --target dpana dpana_contact_tests dpana_fe_tests

# Siconos numerics (used by the cross-checks) and the MPI library that
# deal.II initialises keep memory until exit, which is not dpana's: those
# leaks are suppressed by library name.
suppressions=$(readlink -f "$build")/lsan.supp
printf 'leak:libsiconos_numerics\nleak:libopen-pal\nleak:libmpi\nleak:libhwloc\nleak:libpmix\nleak:libevent\nleak:libopen-rte\n' \
  > "$suppressions"
# The slow unwinder (fast_unwind_on_malloc=0) walks the stacks of
# allocations inside the MPI plugins that are unloaded before exit, so that
# their leaks are attributed to the libraries above and suppressed by name;
# the fast one leaves them in "<unknown module>". print_suppressions=0 keeps
# the statistics of the suppressions out of stderr, which the .prm tests
# compare line by line.
export ASAN_OPTIONS=detect_leaks=1:fast_unwind_on_malloc=0:abort_on_error=0:exitcode=86
export LSAN_OPTIONS=suppressions=$suppressions:print_suppressions=0
export UBSAN_OPTIONS=print_stacktrace=1:halt_on_error=1:exitcode=87
status=0
(cd "$build" && ctest -j2 --output-on-failure -R '^(contact/|fe/|prm/|fuzz/)') ||
  status=$?
echo "sanitize.sh: wall time $(($(date +%s) - start)) s, ctest status $status"
exit $status
