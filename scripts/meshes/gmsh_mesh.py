"""What make_sphere.py and make_disc.py share: running gmsh on a .geo file
of this directory, unless the mesh exists already with the same parameters,
and counting the nodes and elements of the format 2.2 file it wrote."""
import os
import subprocess
import sys

HERE = os.path.dirname(os.path.abspath(__file__))


def write_mesh(program, geo, dimension, values, output, key_suffix="",
               after=None, refinements=0):
    """Runs `gmsh -DIMENSION` on HERE/GEO with `-setnumber NAME VALUE` for
    each of `values`, writing `output`. With `refinements` > 0 the .geo file
    meshes, refines and saves the mesh itself (its numbers Refinements and
    string Output; `gmsh -parse_and_exit`): gmsh's command line would mesh
    the volume again after the script, on the refined surfaces. The command
    (with `key_suffix`) is stored in OUTPUT.args; an existing output with
    the same stored command is kept. `after(output)` runs on a new mesh
    before the command is stored. The mesh is written under a name of this
    process and renamed into place when complete, so that a program reading
    `output` while another writes it (tests run in parallel) never reads
    half a file. A failing gmsh stops with one line `PROGRAM: error: ...`."""
    command = ["gmsh", "-v", "2", os.path.join(HERE, geo)]
    if refinements > 0:
        values = dict(values, Refinements=refinements)
    else:
        command[1:1] = ["-%d" % dimension]
    for name, value in sorted(values.items()):
        command[1:1] = ["-setnumber", name, repr(float(value))]
    key = " ".join(command) + key_suffix
    stamp = output + ".args"
    if (os.path.exists(output) and os.path.exists(stamp)
            and open(stamp).read() == key):
        return
    base, extension = os.path.splitext(output)
    partial = "%s.part%d%s" % (base, os.getpid(), extension)
    if refinements > 0:
        command += ["-setstring", "Output", os.path.abspath(partial),
                    "-parse_and_exit"]
    else:
        command += ["-o", partial]
    if os.path.dirname(output):
        os.makedirs(os.path.dirname(output), exist_ok=True)
    try:
        subprocess.run(command, check=True, stdout=subprocess.DEVNULL)
    except (OSError, subprocess.CalledProcessError) as e:
        if os.path.exists(partial):
            os.remove(partial)
        sys.exit("%s: error: gmsh failed (%s)" % (program, e))
    if not os.path.exists(partial):
        sys.exit("%s: error: gmsh wrote no mesh to %s" % (program, output))
    if after is not None:
        after(partial)
    os.replace(partial, output)
    with open(partial + ".args", "w") as f:
        f.write(key)
    os.replace(partial + ".args", stamp)


def element_counts(path):
    """The number of nodes, and the number of elements per (gmsh element
    type, physical tag), of a format 2.2 file."""
    n_nodes, counts = 0, {}
    with open(path) as f:
        section = None
        for line in f:
            if line.startswith("$"):
                section = line.strip()
                continue
            fields = line.split()
            if section == "$Nodes" and n_nodes == 0:
                n_nodes = int(fields[0])
            elif section == "$Elements" and len(fields) >= 4:
                kind = (int(fields[1]), int(fields[3]))
                counts[kind] = counts.get(kind, 0) + 1
    return n_nodes, counts


def count_type(counts, element_type):
    """The elements of one gmsh type over all physical tags."""
    return sum(n for (kind, _), n in counts.items() if kind == element_type)
