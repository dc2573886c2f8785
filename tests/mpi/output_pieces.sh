#!/bin/bash
# The output of the MPI route in pieces: runs SCENE once by the serial route
# (one process) and once on two ranks, then checks that every body's .pvtu
# record names one piece per rank and that the pieces together hold as many
# cells as the serial body_N.vtu.
#
#   output_pieces.sh DPANA SCENE WORK_DIR MPIEXEC...
set -eu
dpana=$1 scene=$2 work=$3
shift 3
rm -rf "$work" && mkdir -p "$work/serial" "$work/mpi"
cp "$scene" "$work/serial/scene.prm"
cp "$scene" "$work/mpi/scene.prm"
(cd "$work/serial" && "$dpana" scene.prm > log.txt)
(cd "$work/mpi" && "$@" -np 2 "$dpana" scene.prm > log.txt)
python3 - "$work" <<'PYTHON'
import glob, os, re, sys
work = sys.argv[1]
def cells(path):
    text = open(path).read()
    return sum(int(n) for n in re.findall(r'NumberOfCells="(\d+)"', text))
serial = sorted(glob.glob(os.path.join(work, "serial/output/body_*.vtu")))
if not serial:
    sys.exit("FAIL: the serial run wrote no body_N.vtu")
for path in serial:
    body = os.path.basename(path)[:-4]
    record = os.path.join(work, "mpi/output", body + ".pvtu")
    if not os.path.exists(record):
        sys.exit("FAIL: the MPI run wrote no %s.pvtu" % body)
    pieces = re.findall(r'<Piece Source="([^"]+)"', open(record).read())
    expected = ["%s_%d.vtu" % (body, rank) for rank in range(2)]
    if sorted(pieces) != expected:
        sys.exit("FAIL: %s.pvtu names %s, not %s" % (body, pieces, expected))
    n_mpi = sum(cells(os.path.join(work, "mpi/output", p)) for p in pieces)
    n_serial = cells(path)
    if n_mpi != n_serial:
        sys.exit("FAIL: %s: %d cells in the pieces, %d in the serial file"
                 % (body, n_mpi, n_serial))
    print("%s: %d cells in %d pieces, as in the serial file"
          % (body, n_mpi, len(pieces)))
PYTHON
