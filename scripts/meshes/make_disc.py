#!/usr/bin/env python3
"""Writes the graded gmsh meshes of the bodies of the 2D Hertz scenes.

    make_disc.py OUT.msh [--body disc|block|cavity] [--level L]
                 [--set NAME=VALUE ...]

Runs gmsh (Debian package `gmsh`) on a .geo file next to this script.
`--body disc` (the default), disc.geo: the right half disc x >= 0 of radius
R = 40 and centre (0, R), its arc divided near the contact point as
dpana's `right half disc` with `Global refinements` = L and 5 `Contact
refinements` divides it (L = -2, -1: 0 global and 3, 4 contact
refinements), the element size growing with the distance from the contact
point elsewhere. `--body block`, block.geo: the elastic foundation
[0, 2R] x [-2R, 0] below it, its top face divided at the projections of
the vertices of that arc, the same size field elsewhere. `--body cavity`,
cavity.geo: the body with the cavity of radius 3R (the lower right quarter
of the ring 3R <= r <= 9R around (0, 3R)), its inner circle divided at
the projections of those vertices. Prints the size of the mesh it wrote:
nodes, the displacement unknowns (2 per node), triangles and the faces of
the arc (of the top face, of the inner circle). `--set` passes any other
parameter of the .geo file (R, Arc, Rho, Growth). An existing OUT.msh made
with the same parameters is kept (the parameters are stored next to it in
OUT.msh.args).
"""
import argparse
import sys

from gmsh_mesh import count_type, element_counts, write_mesh

NAMES = ("R", "Arc", "Rho", "Growth")
# --body: the .geo file, and the name of its physical curve of tag 1.
BODIES = {"disc": ("disc.geo", "arc"), "block": ("block.geo", "top face"),
          "cavity": ("cavity.geo", "inner circle")}


def fail(message):
    sys.exit("make_disc.py: error: " + message)


def main():
    parser = argparse.ArgumentParser(description=__doc__.split("\n")[0])
    parser.add_argument("output")
    parser.add_argument("--body", default="disc")
    parser.add_argument("--level", default="0")
    parser.add_argument("--set", action="append", default=[],
                        metavar="NAME=VALUE")
    args = parser.parse_args()

    if args.body not in BODIES:
        fail("--body %s: must be one of %s" % (args.body, ", ".join(BODIES)))
    geo, curve = BODIES[args.body]
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
    write_mesh("make_disc.py", geo, 2, values, args.output)

    n_nodes, counts = element_counts(args.output)
    # Triangles (gmsh type 2); the arc (the top face, the inner circle) is
    # the lines (type 1) of tag 1.
    n_triangles, n_curve = count_type(counts, 2), counts.get((1, 1), 0)
    print("%s: %d nodes (%d displacement unknowns), %d triangles, %d faces "
          "on the %s" % (args.output, n_nodes, 2 * n_nodes, n_triangles,
                         n_curve, curve))


if __name__ == "__main__":
    main()
