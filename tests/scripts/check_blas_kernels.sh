#!/usr/bin/env bash
# check_blas_kernels.sh DPANA PRM: the dpana command never leaves OpenBLAS on
# its generic SSE3 kernels ("Prescott") on a processor with AVX2 and FMA
# (source/launcher/launcher.cc), and keeps an OPENBLAS_CORETYPE it is given.
# OPENBLAS_VERBOSE=2 makes OpenBLAS print "Core: NAME" when it is loaded:
# once in the launcher (its own choice), then in dpana-solver (the kernels
# the run computes with). Exit 77 (skipped) without AVX2 and FMA or without
# OpenBLAS.
set -euo pipefail
dpana="$(realpath "$1")"
prm="$(realpath "$2")"
flags="$(grep -m1 '^flags' /proc/cpuinfo)"
if [[ " $flags " != *" avx2 "* || " $flags " != *" fma "* ]]; then
  echo "skipped: the processor has no AVX2 and FMA"
  exit 77
fi
work="$(mktemp -d)"
trap 'rm -rf "$work"' EXIT
cp "$prm" "$work/scene.prm"
cd "$work"

solver_core() {
  env "$@" OPENBLAS_VERBOSE=2 "$dpana" scene.prm 2>&1 |
    sed -n 's/^Core: //p' | tail -n 1
}

core="$(solver_core)"
if [ -z "$core" ]; then
  echo "skipped: no OpenBLAS in this run"
  exit 77
fi
echo "kernels of the run: $core"
if [ "$core" = "Prescott" ]; then
  echo "FAIL: dpana-solver ran OpenBLAS' generic kernels on a processor" \
    "with AVX2 and FMA"
  exit 1
fi
given="$(solver_core OPENBLAS_CORETYPE=Prescott)"
echo "kernels with OPENBLAS_CORETYPE=Prescott given: $given"
if [ "$given" != "Prescott" ]; then
  echo "FAIL: the given OPENBLAS_CORETYPE was not kept"
  exit 1
fi
