#!/bin/bash
# The replicated and the distributed assembly of the MPI route, and the
# distributed mesh, side by side (doc/parallel.md, `Contact / Parallel
# assembly`, `Parallel mesh`): the 3D receding block of
# prm/receding_3d_L80.prm with Subdivisions = M, H, M (default 32, 16, 32),
# run on one process (Factorisation back end = mumps: the same MUMPS
# factorisation, sequential) and on two ranks with each assembly, the
# distributed one with the whole mesh on every rank (np2_distributed) and
# with the mesh distributed (np2_distributed_mesh, the default). For every run: the time of every phase
# (summary.json, rank 0), the peak and the resident memory of every rank
# after the assembly (the log lines "Peak memory after the assembly ..."
# and "Resident memory ..."), the peak resident memory of every rank over
# the whole run
# (/usr/bin/time), and the load before and after. Prints one markdown table
# (also written to WORK/assembly.md).
#
#   benchmarks/parallel/assembly.sh [DPANA]        # about 3 minutes
#
# SIZE="MxH" chooses the subdivisions; WORK (default build/benchmarks/
# parallel_assembly) the folder of the runs. Run under flock /work/...lock
# or another lock when other measurements share the machine.
set -eu
here=$(cd "$(dirname "$0")" && pwd)
root=$(cd "$here/../.." && pwd)
size=${SIZE:-32x16}
m=${size%x*}
h=${size#*x}
dpana=$(readlink -f "${1:-$root/build/dpana}")
work=${WORK:-$root/build/benchmarks/parallel_assembly}
mpiexec="mpirun -q --oversubscribe"
if [ "$(id -u)" = 0 ]; then
  mpiexec="$mpiexec --allow-run-as-root"
fi
export OMP_NUM_THREADS=1 OPENBLAS_NUM_THREADS=1
mkdir -p "$work"

for variant in np1 np2_replicated np2_distributed np2_distributed_mesh; do
  run="$work/receding_${m}x${h}x${m}_$variant"
  rm -rf "$run"
  mkdir -p "$run"
  assembly=${variant#np2_}
  assembly=${assembly%_mesh}
  # The scene without its comparison file (an output of another run).
  sed -e "s/Subdivisions = .*/Subdivisions = $m, $h, $m/" \
      -e "s|Directory = .*|Directory = output|" \
      -e "/Comparison file/d" \
      -e "s/^  set Cone model .*/&\n  set Factorisation back end  = mumps\n  set Parallel assembly      = ${assembly#np1}/" \
      "$root/prm/receding_3d_L80.prm" > "$run/scene.prm"
  if [ "$variant" = np2_distributed ]; then
    sed -i 's/^  set Parallel assembly .*/&\n  set Parallel mesh          = whole/' "$run/scene.prm"
  fi
  if [ "$variant" = np1 ]; then
    sed -i '/Parallel assembly/d' "$run/scene.prm"
    launcher=""
  else
    launcher="$mpiexec -x OMP_NUM_THREADS -x OPENBLAS_NUM_THREADS -np 2"
  fi
  cat /proc/loadavg > "$run/load_before.txt"
  (cd "$run" && $launcher /usr/bin/time -f "rank peak kB %M wall %e" \
      "$dpana" scene.prm > stdout.txt 2> stderr.txt) ||
    echo "run $run failed (see $run/stderr.txt)"
  cat /proc/loadavg > "$run/load_after.txt"
done

python3 - "$work" "$m" "$h" <<'PYTHON' | tee "$work/assembly.md"
import glob, json, os, re, sys
work, m, h = sys.argv[1:4]
phases = ["mesh", "assembly", "contact surface", "factorization", "condensation",
          "contact solve", "recovery", "output"]
print("| run | dofs | " + " | ".join(phases) +
      " | total | peak after assembly, per rank (MB) "
      "| resident after assembly, per rank (MB) "
      "| peak of the run, per rank (MB) | load before-after |")
print("|---" * (len(phases) + 7) + "|")
for variant in ["np1", "np2_replicated", "np2_distributed",
                "np2_distributed_mesh"]:
    run = os.path.join(work, "receding_%sx%sx%s_%s" % (m, h, m, variant))
    try:
        summary = json.load(open(os.path.join(run, "output", "summary.json")))
    except OSError:
        print("| %s | failed |" % variant)
        continue
    t = summary["timings"]
    log = open(os.path.join(run, "stdout.txt")).read()
    def per_rank(what):
        found = re.search(what + r" memory after the assembly \([\w ]+\), "
                          r"per rank \(MB\):([\d. ]+)", log)
        return found and " / ".join("%.0f" % float(x)
                                    for x in found.group(1).split())
    after, resident = per_rank("Peak"), per_rank("Resident") or "-"
    if not after:  # one process: the peak of the assembly phase
        after = "%.0f" % summary["peak_memory_mb"]["assembly"]
    peaks = re.findall(r"rank peak kB (\d+)",
                       open(os.path.join(run, "stderr.txt")).read())
    peaks = " / ".join("%.0f" % (int(p) / 1024) for p in peaks)
    load = (open(os.path.join(run, "load_before.txt")).read().split()[0] +
            "-" + open(os.path.join(run, "load_after.txt")).read().split()[0])
    print("| %s | %d | %s | %.3g | %s | %s | %s | %s |" % (
        variant, summary["bodies"][0]["dofs"],
        " | ".join("%.3g" % t.get(p, 0.0) for p in phases),
        sum(t.values()), after, resident, peaks, load))
PYTHON
