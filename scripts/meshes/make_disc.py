#!/usr/bin/env python3
"""Writes the graded gmsh mesh of the circular body of the 2D Hertz scenes.

    make_disc.py OUT.msh [--level L] [--set NAME=VALUE ...]

Runs gmsh (Debian package `gmsh`) on scripts/meshes/disc.geo, next to this
script: the right half disc x >= 0 of radius R = 40 and centre (0, R), its
arc divided near the contact point as dpana's `right half disc` with
`Global refinements` = L and 5 `Contact refinements` divides it (L = -2,
-1: 0 global and 3, 4 contact refinements), the element size growing with
the distance from the contact point elsewhere. Prints the size of the mesh
it wrote: nodes, the displacement unknowns (2 per node), triangles and the
faces of the arc. `--set` passes any other parameter of disc.geo (R, Arc,
Rho, Growth). An existing OUT.msh made with the same parameters is kept
(the parameters are stored next to it in OUT.msh.args).
"""
import argparse
import os
import subprocess
import sys

GEO = os.path.join(os.path.dirname(os.path.abspath(__file__)), "disc.geo")
NAMES = ("R", "Arc", "Rho", "Growth")


def fail(message):
    sys.exit("make_disc.py: error: " + message)


def mesh_size(path):
    """Nodes, triangles and arc faces (physical tag 1) of a format 2.2 file."""
    n_nodes, n_triangles, n_arc = 0, 0, 0
    with open(path) as f:
        section = None
        for line in f:
            if line.startswith("$"):
                section = line.strip()
                continue
            fields = line.split()
            if section == "$Nodes" and n_nodes == 0:
                n_nodes = int(fields[0])
            elif section == "$Elements" and len(fields) > 4:
                if fields[1] == "2":
                    n_triangles += 1
                elif fields[1] == "1" and fields[3] == "1":
                    n_arc += 1
    return n_nodes, n_triangles, n_arc


def main():
    parser = argparse.ArgumentParser(description=__doc__.split("\n")[0])
    parser.add_argument("output")
    parser.add_argument("--level", default="0")
    parser.add_argument("--set", action="append", default=[],
                        metavar="NAME=VALUE")
    args = parser.parse_args()

    try:
        level = int(args.level)
    except ValueError:
        level = None
    if level is None or not -4 <= level <= 8:
        fail("--level %s: must be an integer from -4 to 8" % args.level)
    values = {"Level": level}
    for item in args.set:
        name, _, value = item.partition("=")
        if name not in NAMES:
            fail("--set %s: unknown parameter '%s' (one of %s)"
                 % (item, name, ", ".join(NAMES)))
        try:
            values[name] = float(value)
        except ValueError:
            fail("--set %s: expected NAME=NUMBER" % item)
        if not values[name] > 0:
            fail("--set %s: %s must be positive" % (item, name))
    command = ["gmsh", "-2", "-v", "2", GEO, "-o", args.output]
    for name, value in sorted(values.items()):
        command[1:1] = ["-setnumber", name, repr(float(value))]
    stamp = args.output + ".args"
    key = " ".join(command[:-2])
    if not (os.path.exists(args.output) and os.path.exists(stamp)
            and open(stamp).read() == key):
        if os.path.dirname(args.output):
            os.makedirs(os.path.dirname(args.output), exist_ok=True)
        try:
            subprocess.run(command, check=True, stdout=subprocess.DEVNULL)
        except (OSError, subprocess.CalledProcessError) as e:
            fail("gmsh failed (%s)" % e)
        with open(stamp, "w") as f:
            f.write(key)

    n_nodes, n_triangles, n_arc = mesh_size(args.output)
    print("%s: %d nodes (%d displacement unknowns), %d triangles, %d faces "
          "on the arc" % (args.output, n_nodes, 2 * n_nodes, n_triangles,
                          n_arc))


if __name__ == "__main__":
    main()
