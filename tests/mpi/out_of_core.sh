#!/bin/bash
# MUMPS' out-of-core factor against its in-core one (tests/mpi/README.md).
#
#   out_of_core.sh ROUTE_OUTPUTS DPANA SCENE.prm WORKDIR MPIEXEC [FLAGS...]
#
# SCENE.prm sets `Out-of-core directory = ooc_files`. In WORKDIR (emptied
# first) the scene is run by ROUTE_OUTPUTS as it is (out of core) and
# without that line (in core), on one process and on two ranks (MPIEXEC
# -np 2); on each, the two runs must give the same A, tractions r and
# displacements u to a relative 1e-10 (ROUTE_OUTPUTS --compare). Then DPANA
# runs the scene out of core on one process: its log must say that MUMPS
# factored out of core, and ooc_files/ must be empty after every run (MUMPS
# removes its factor files when the factorisation is destroyed).
set -u
if [ $# -lt 5 ]; then
  echo "usage: $0 ROUTE_OUTPUTS DPANA SCENE.prm WORKDIR MPIEXEC [FLAGS...]" >&2
  exit 2
fi
tool=$1 dpana=$2 prm=$(readlink -f "$3") workdir=$4
shift 4

rm -rf "$workdir"
mkdir -p "$workdir/ooc_files"
cd "$workdir" || exit 2
cp "$prm" ooc.prm
grep -v "Out-of-core directory" "$prm" > in_core.prm
if cmp -s ooc.prm in_core.prm; then
  echo "FAIL: $prm sets no Out-of-core directory"
  exit 1
fi

empty() {
  if [ -n "$(ls -A ooc_files)" ]; then
    echo "FAIL: factor files left in ooc_files after $1: $(ls ooc_files)"
    exit 1
  fi
}

for np in 1 2; do
  mkdir -p "ic$np" "ooc$np"
  launch=()
  [ "$np" = 2 ] && launch=("$@" -np 2)
  "${launch[@]}" "$tool" in_core.prm "ic$np" ||
    { echo "FAIL: the in-core run on $np rank(s)"; exit 1; }
  "${launch[@]}" "$tool" ooc.prm "ooc$np" ||
    { echo "FAIL: the out-of-core run on $np rank(s)"; exit 1; }
  empty "the out-of-core run on $np rank(s)"
  echo "$np rank(s), out of core against in core:"
  "$tool" --compare "ooc$np" "ic$np" 1e-10 || exit 1
done

"$dpana" ooc.prm > log.txt || { echo "FAIL: dpana ooc.prm"; exit 1; }
empty "dpana ooc.prm"
if ! grep -q "MUMPS on 1 rank(s): .* out of core" log.txt; then
  echo "FAIL: the log of dpana ooc.prm does not say that MUMPS factored out of core"
  exit 1
fi
echo "PASS"
