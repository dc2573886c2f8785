#!/usr/bin/env python3
"""Writes the gmsh mesh of the quarter sphere of the 3D Hertz scenes.

    make_sphere.py OUT.msh [--side 1|-1] [--level L] [--refine K]
                   [--set NAME=VALUE ...]

Runs gmsh (Debian package `gmsh`) on scripts/meshes/sphere.geo, next to this
script, and prints the size of the mesh it wrote: nodes, tetrahedra, the
displacement unknowns (3 per node), the triangles of the contact cap and the
contact unknowns they give with 8 triangles per contact element (3 per
element; dpana merges the small groups its grouping of an unstructured
surface leaves into their neighbours, so that there are somewhat fewer).

`--level L` sets SizeFactor = 2^(-L/2), so that each level has about
2^(3/2) = 2.8 times the unknowns of the one before (level 0: the sizes of
sphere.geo); each level is a new unstructured mesh. `--refine K` instead
splits every tetrahedron of the level's mesh into 8, K times, with the new
boundary nodes on the sphere (gmsh's RefineMesh): meshes nested in the
level's mesh, h halved and about 7 times the unknowns per refinement, for
convergence studies that need one mesh family. `--set` passes any
parameter of sphere.geo (R, Side, CapRadius, PoleRadius, SizeContact,
SizeFar, Growth, SizeFactor, Algorithm3D). An existing OUT.msh made with
the same parameters is kept (the parameters are stored next to it in
OUT.msh.args).
"""
import argparse
import sys

from gmsh_mesh import count_type, element_counts, write_mesh

def round_coordinates(path, digits):
    """Rewrites the $Nodes section of a format 2.2 file with fewer digits."""
    lines = open(path).read().splitlines()
    start = lines.index("$Nodes") + 2
    end = lines.index("$EndNodes")
    for i in range(start, end):
        tag, *x = lines[i].split()
        lines[i] = " ".join([tag] + ["%.*g" % (digits, float(v)) for v in x])
    with open(path, "w") as f:
        f.write("\n".join(lines) + "\n")


def main():
    parser = argparse.ArgumentParser(description=__doc__.split("\n")[0])
    parser.add_argument("output")
    parser.add_argument("--side", type=int, default=1, choices=(1, -1))
    parser.add_argument("--level", type=float, default=0)
    parser.add_argument("--refine", type=int, default=0, metavar="K",
                        help="split every tetrahedron into 8, K times")
    parser.add_argument("--set", action="append", default=[],
                        metavar="NAME=VALUE")
    parser.add_argument("--digits", type=int, default=0,
                        help="round the node coordinates to this many "
                        "significant digits (a smaller file, for tests)")
    args = parser.parse_args()
    if args.refine < 0:
        sys.exit("make_sphere.py: error: --refine %d: must be 0 or more"
                 % args.refine)

    values = {"Side": args.side, "SizeFactor": 2 ** (-args.level / 2)}
    for item in args.set:
        name, _, value = item.partition("=")
        if not value:
            sys.exit("make_sphere.py: error: --set %s: expected NAME=VALUE"
                     % item)
        values[name] = float(value)
    round_nodes = None
    if args.digits > 0:
        def round_nodes(path):
            round_coordinates(path, args.digits)
    write_mesh("make_sphere.py", "sphere.geo", 3, values, args.output,
               key_suffix=" digits %d" % args.digits, after=round_nodes,
               refinements=args.refine)

    n_nodes, counts = element_counts(args.output)
    # Tetrahedra (gmsh type 4); the contact cap is the triangles (type 2)
    # of tag 3.
    n_tets, contact = count_type(counts, 4), counts.get((2, 3), 0)
    print("%s: %d nodes (%d displacement unknowns), %d tetrahedra, %d "
          "triangles on the contact cap (at most about %d contact unknowns: "
          "dpana merges small leftover groups into their neighbours)"
          % (args.output, n_nodes, 3 * n_nodes, n_tets, contact,
             3 * (contact // 8)))


if __name__ == "__main__":
    main()
