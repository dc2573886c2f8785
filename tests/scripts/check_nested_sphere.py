#!/usr/bin/env python3
"""Checks the nested meshes of scripts/meshes/make_sphere.py --refine.

    check_nested_sphere.py MAKE_SPHERE WORKDIR

Makes the quarter sphere at --level -2 and the same mesh split once
(--refine 1), then checks what the nested convergence family relies on:
every node of the coarse mesh is a node of the refined one, every
tetrahedron became 8, and every node of the spherical boundaries (`contact`,
`sphere`, `pole`) of the refined mesh lies on the sphere of radius 40 about
(0, 40, 0). A refinement that left the new nodes on the flat faces (gmsh
-refine on the mesh file alone) misses the sphere by about h^2/(8R): by
3.6e-3 mm on the cap and 0.72 mm far from it at this level; the check
allows 1e-9 mm. Prints one line per check and
exits 1 on the first failure.
"""
import math
import os
import subprocess
import sys

R, CENTRE = 40.0, (0.0, 40.0, 0.0)
SPHERICAL = {3: "contact", 4: "pole", 5: "sphere"}   # physical tags


def read(path):
    """Nodes {tag: (x, y, z)}, tetrahedra count, and the nodes of the
    triangles of each physical tag, of a gmsh format 2.2 file."""
    lines = open(path).read().splitlines()
    i = lines.index("$Nodes")
    nodes = {}
    for line in lines[i + 2:i + 2 + int(lines[i + 1])]:
        tag, *x = line.split()
        nodes[int(tag)] = tuple(float(v) for v in x)
    j = lines.index("$Elements")
    n_tets, surfaces = 0, {}
    for line in lines[j + 2:j + 2 + int(lines[j + 1])]:
        f = [int(v) for v in line.split()]
        if f[1] == 4:
            n_tets += 1
        elif f[1] == 2:
            surfaces.setdefault(f[3], set()).update(f[3 + f[2]:])
    return nodes, n_tets, surfaces


def fail(message):
    print("FAIL: " + message)
    sys.exit(1)


def main():
    make_sphere, workdir = sys.argv[1:3]
    os.makedirs(workdir, exist_ok=True)
    paths = []
    for k in (0, 1):
        path = os.path.join(workdir, "nested_sphere_r%d.msh" % k)
        subprocess.run([sys.executable, make_sphere, path, "--level", "-2",
                        "--refine", str(k)], check=True,
                       stdout=subprocess.DEVNULL)
        paths.append(path)
    (coarse, tets0, _), (fine, tets1, surfaces) = map(read, paths)

    points = {tuple(round(v, 9) for v in x) for x in fine.values()}
    missing = [x for x in coarse.values()
               if tuple(round(v, 9) for v in x) not in points]
    if missing:
        fail("%d of the %d coarse nodes are not nodes of the refined mesh"
             % (len(missing), len(coarse)))
    print("nested: the %d coarse nodes are among the %d refined ones"
          % (len(coarse), len(fine)))
    if tets1 != 8 * tets0:
        fail("%d tetrahedra refined into %d, not 8 times as many"
             % (tets0, tets1))
    print("tetrahedra: %d -> %d (8 times)" % (tets0, tets1))
    for tag, name in SPHERICAL.items():
        off = max(abs(math.dist(fine[n], CENTRE) - R) for n in surfaces[tag])
        if off > 1e-9:
            fail("a node of '%s' lies %.3g mm off the sphere" % (name, off))
        print("'%s': %d nodes, at most %.1e mm off the sphere"
              % (name, len(surfaces[tag]), off))


if __name__ == "__main__":
    main()
