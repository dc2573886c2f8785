#!/bin/bash
# The serial and the MPI route on one contact scene (tests/mpi/README.md).
#
#   run_mpi_test.sh ROUTE_OUTPUTS NAME.prm WORKDIR MPIEXEC [MPIEXEC FLAGS...]
#
# Runs ROUTE_OUTPUTS NAME.prm on one process (the serial route) and through
# MPIEXEC -np 2 (the MPI route) in WORKDIR (emptied first; the files of
# NAME.files/ are copied into it), then compares A (1e-10), the tractions r
# and the displacements of the bodies (1e-8) with ROUTE_OUTPUTS --compare.
set -u
if [ $# -lt 4 ]; then
  echo "usage: $0 ROUTE_OUTPUTS NAME.prm WORKDIR MPIEXEC [FLAGS...]" >&2
  exit 2
fi
tool=$1
prm=$(readlink -f "$2")
workdir=$3
shift 3
name=$(basename "$prm" .prm)
srcdir=$(dirname "$prm")

rm -rf "$workdir"
mkdir -p "$workdir/np1" "$workdir/np2"
cp "$prm" "$workdir/"
if [ -d "$srcdir/$name.files" ]; then
  cp -r "$srcdir/$name.files/." "$workdir/"
fi
cd "$workdir" || exit 2
"$tool" "$name.prm" np1 || { echo "FAIL: the serial run"; exit 1; }
"$@" -np 2 "$tool" "$name.prm" np2 || { echo "FAIL: the run on 2 ranks"; exit 1; }
"$tool" --compare np2 np1
