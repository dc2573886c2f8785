#!/usr/bin/env python3
"""Makes the gmsh meshes a scene asks for.

    make_meshes.py SCENE.prm

A scene whose mesh is generated says so in its header, one comment line per
mesh:

    # mesh: meshes/NAME.msh [options of make_sphere.py]

e.g. `# mesh: meshes/hertz_sphere_L4.msh --level 4`. Each such mesh is
written by make_sphere.py (path relative to the working directory, as the
scene's `Mesh file`), unless it exists already with the same options. A
line `# disc mesh: OUT.msh [options of make_disc.py]` writes the graded
mesh of the 2D circular body by make_disc.py in the same way, and a line
`# block mesh: OUT.msh [options]` (`# cavity mesh: ...`) the graded mesh
of its elastic foundation (of the body with the cavity): make_disc.py
--body block (--body cavity).
./run.sh calls this before every run; a scene without such lines is left
alone.
"""
import os
import re
import shlex
import subprocess
import sys

HERE = os.path.dirname(os.path.abspath(__file__))


def main():
    if len(sys.argv) != 2:
        sys.exit("usage: make_meshes.py SCENE.prm")
    try:
        lines = open(sys.argv[1]).read().splitlines()
    except OSError:
        return  # dpana itself reports a scene it cannot read
    for line in lines:
        match = re.match(
            r"#\s*(?:(disc|block|cavity)\s+)?mesh:\s*(\S+)(.*)$", line)
        if not match:
            continue
        script = "make_disc.py" if match.group(1) else "make_sphere.py"
        output, options = match.group(2), shlex.split(match.group(3))
        if match.group(1) in ("block", "cavity"):
            options = ["--body", match.group(1)] + options
        subprocess.run([sys.executable, os.path.join(HERE, script),
                        output] + options, check=True)


if __name__ == "__main__":
    main()
