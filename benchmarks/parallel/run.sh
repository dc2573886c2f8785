#!/bin/bash
# Strong scaling of the MPI route on this machine: the 3D receding block of
# prm/scale/receding_3d_1M.prm at the sizes below, each on 1 process
# (Factorisation back end = mumps: the same MUMPS factorisation, sequential)
# and on 2 MPI ranks (mpirun -np 2: the MPI route). For every run: the time
# and the peak memory of every phase (summary.json, rank 0), the peak
# resident memory of every rank (/usr/bin/time), and what MUMPS reports of
# its factorisation (the log line "MUMPS on P rank(s): ..."). Then
# collect.py writes results/results.csv and results/results.md, model.py
# fits the cost model and writes results/model.md, plot.py the figure.
#
#   benchmarks/parallel/run.sh [--quick] [DPANA]
#
# ORDERING="by MUMPS" lets MUMPS order (AMD) instead of giving it dpana's
# nested dissection (Contact / Schur ordering, the default).
# SIZES="m1xh1 m2xh2 ..." and NPS="1 2" choose other sizes (m x h x m
# subdivisions) and rank counts; the runs already in the work folder stay
# in the table. --quick: the smallest size only. DPANA defaults to build/dpana; PYTHON
# (default python3) must have matplotlib for the plot.
set -eu
here=$(cd "$(dirname "$0")" && pwd)
root=$(cd "$here/../.." && pwd)
sizes=${SIZES:-"16x40 24x56"}
nps=${NPS:-"1 2"}
if [ "${1:-}" = "--quick" ]; then
  sizes="12x24"
  shift
fi
dpana=$(readlink -f "${1:-$root/build/dpana}")
mpiexec="mpirun -q --oversubscribe"
if [ "$(id -u)" = 0 ]; then
  mpiexec="$mpiexec --allow-run-as-root"
fi
work="$root/build/benchmarks/parallel"
# One thread per rank (MUMPS' BLAS and OpenMP): np ranks use np cores, so
# that np = 1 and np = 2 compare the same work on one and on two cores.
export OMP_NUM_THREADS=1 OPENBLAS_NUM_THREADS=1
py=${PYTHON:-python3}
mkdir -p "$work"

for size in $sizes; do
  m=${size%x*}
  h=${size#*x}
  for np in $nps; do
    run="$work/receding_${m}x${h}x${m}_np$np"
    rm -rf "$run"
    mkdir -p "$run"
    # In memory, MUMPS given dpana's ordering (the scene's defaults);
    # ORDERING="by MUMPS" for MUMPS' own (AMD).
    sed -e "s/Subdivisions = .*/Subdivisions = $m, $h, $m/" \
        -e "s|^  set Directory = .*|  set Directory = output|" \
        -e "/Out-of-core directory/d" \
        -e "/Factorisation back end/d" \
        -e "s/^  set Cone model .*/&\n  set Factorisation back end  = mumps\n  set Schur ordering = ${ORDERING:-interior nested dissection}/" \
        "$root/prm/scale/receding_3d_1M.prm" > "$run/scene.prm"
    cat /proc/loadavg > "$run/load_before.txt"
    if [ "$np" = 1 ]; then
      launcher=""
    else
      launcher="$mpiexec -x OMP_NUM_THREADS -x OPENBLAS_NUM_THREADS -np $np"
    fi
    (cd "$run" && $launcher /usr/bin/time -f "rank peak kB %M user %U system %S wall %e" \
        "$dpana" scene.prm > stdout.txt 2> stderr.txt) ||
      echo "run $run failed (see $run/stderr.txt)"
    cat /proc/loadavg > "$run/load_after.txt"
    echo "done: $run"
  done
done
"$py" "$here/collect.py" "$work" "$here/results"
"$py" "$here/model.py" "$here/results/results.csv" "$here/results" \
  "$here/results/assembly.md"
"$py" "$here/plot.py" "$here/results/results.csv" "$here/results"
