#!/usr/bin/env python3
"""Writes the gmsh mesh of the quarter sphere of the 3D Hertz scenes.

    make_sphere.py OUT.msh [--side 1|-1] [--level L] [--set NAME=VALUE ...]

Runs gmsh (Debian package `gmsh`) on scripts/meshes/sphere.geo, next to this
script, and prints the size of the mesh it wrote: nodes, tetrahedra, the
displacement unknowns (3 per node), the triangles of the contact cap and the
contact unknowns they give with 8 triangles per contact element (3 per
element; dpana merges the small groups its grouping of an unstructured
surface leaves into their neighbours, so that there are somewhat fewer). `--level L` sets SizeFactor = 2^(-L/2), so that each level has
about 2^(3/2) = 2.8 times the unknowns of the one before (level 0: the
sizes of sphere.geo); `--set` passes any parameter of sphere.geo (R, Side,
CapRadius, PoleRadius, SizeContact, SizeFar, Growth, SizeFactor,
Algorithm3D). An
existing OUT.msh made with the same parameters is kept (the parameters are
stored next to it in OUT.msh.args).
"""
import argparse
import os
import subprocess
import sys

GEO = os.path.join(os.path.dirname(os.path.abspath(__file__)), "sphere.geo")


def mesh_size(path):
    """Nodes, tetrahedra and triangles per physical tag of a format 2.2 file."""
    n_nodes, n_tets, triangles = 0, 0, {}
    with open(path) as f:
        section = None
        for line in f:
            if line.startswith("$"):
                section = line.strip()
                continue
            if section == "$Nodes" and n_nodes == 0:
                n_nodes = int(line)
            elif section == "$Elements":
                fields = line.split()
                if len(fields) < 4:
                    continue
                if fields[1] == "4":
                    n_tets += 1
                elif fields[1] == "2":
                    tag = int(fields[3])
                    triangles[tag] = triangles.get(tag, 0) + 1
    return n_nodes, n_tets, triangles


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
    parser.add_argument("--set", action="append", default=[],
                        metavar="NAME=VALUE")
    parser.add_argument("--digits", type=int, default=0,
                        help="round the node coordinates to this many "
                        "significant digits (a smaller file, for tests)")
    args = parser.parse_args()

    values = {"Side": args.side, "SizeFactor": 2 ** (-args.level / 2)}
    for item in args.set:
        name, _, value = item.partition("=")
        if not value:
            sys.exit("make_sphere.py: error: --set %s: expected NAME=VALUE"
                     % item)
        values[name] = float(value)
    command = ["gmsh", "-3", "-v", "2", GEO, "-o", args.output]
    for name, value in sorted(values.items()):
        command[1:1] = ["-setnumber", name, repr(float(value))]
    stamp = args.output + ".args"
    key = " ".join(command[:-2]) + " digits %d" % args.digits
    if not (os.path.exists(args.output) and os.path.exists(stamp)
            and open(stamp).read() == key):
        if os.path.dirname(args.output):
            os.makedirs(os.path.dirname(args.output), exist_ok=True)
        try:
            subprocess.run(command, check=True, stdout=subprocess.DEVNULL)
        except (OSError, subprocess.CalledProcessError) as e:
            sys.exit("make_sphere.py: error: gmsh failed (%s)" % e)
        if args.digits > 0:
            round_coordinates(args.output, args.digits)
        with open(stamp, "w") as f:
            f.write(key)

    n_nodes, n_tets, triangles = mesh_size(args.output)
    contact = triangles.get(3, 0)
    print("%s: %d nodes (%d displacement unknowns), %d tetrahedra, %d "
          "triangles on the contact cap (at most about %d contact unknowns: "
          "dpana merges small leftover groups into their neighbours)"
          % (args.output, n_nodes, 3 * n_nodes, n_tets, contact,
             3 * (contact // 8)))


if __name__ == "__main__":
    main()
