#!/bin/bash
# The output of the MPI route in pieces: runs SCENE once by the serial route
# (one process) and once on two ranks, then checks that every body's .pvtu
# record names one piece per rank and that the pieces together hold as many
# cells as the serial body_N.vtu, and that the results of every body in
# summary.json that are sums or maxima over its cells (cells, vertices,
# largest displacement and von Mises stress, reactions, load resultant)
# are those of the serial run to a relative 1e-8: with a distributed mesh
# each rank holds only its cells, and these are reduced over the ranks. So
# must the approach of a Hertz sphere be, if the scene measures it. The
# files of NAME.files/ beside SCENE are copied beside it.
#
#   output_pieces.sh DPANA SCENE WORK_DIR MPIEXEC...
set -eu
dpana=$1 scene=$2 work=$3
shift 3
rm -rf "$work" && mkdir -p "$work/serial" "$work/mpi"
cp "$scene" "$work/serial/scene.prm"
cp "$scene" "$work/mpi/scene.prm"
# The files a scene reads (its mesh) are in NAME.files/ beside it.
files="${scene%.prm}.files"
if [ -d "$files" ]; then
  cp -r "$files/." "$work/serial/"
  cp -r "$files/." "$work/mpi/"
fi
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

import json
def flat(x, path=""):
    if isinstance(x, dict):
        for k, v in x.items():
            yield from flat(v, path + "/" + k)
    elif isinstance(x, list):
        for i, v in enumerate(x):
            yield from flat(v, "%s[%d]" % (path, i))
    else:
        yield path, x
summaries = [json.load(open(os.path.join(work, run, "output/summary.json")))
             for run in ("serial", "mpi")]
keys = ["cells", "vertices", "max_displacement", "max_von_mises",
        "reactions", "applied_load_resultant"]
for serial_body, mpi_body in zip(*(s["bodies"] for s in summaries)):
    for key in keys:
        a, b = dict(flat(serial_body[key])), dict(flat(mpi_body[key]))
        scale = max([abs(v) for v in a.values()] + [1e-300])
        if a.keys() != b.keys() or any(
                abs(a[k] - b[k]) > 1e-8 * scale for k in a):
            sys.exit("FAIL: %s %s: %s on two ranks, %s on one"
                     % (serial_body["name"], key, b, a))
    print("%s: %s as in the serial run" % (serial_body["name"], ", ".join(keys)))
# The approach of a Hertz sphere: the displacement at two points, which
# with a distributed mesh only the ranks holding them can evaluate.
approaches = [s["contact"].get("estimates", {}).get("approach")
              for s in summaries]
if approaches[0] is not None or approaches[1] is not None:
    if None in approaches or abs(approaches[0] - approaches[1]) > \
            1e-8 * abs(approaches[0]):
        sys.exit("FAIL: approach %s on two ranks, %s on one"
                 % (approaches[1], approaches[0]))
    print("approach %.9g mm as in the serial run" % approaches[0])
PYTHON
