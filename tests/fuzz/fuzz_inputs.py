#!/usr/bin/env python3
"""Deterministic fuzz test of the dpana executable.

    fuzz_inputs.py DPANA SOURCE_DIR WORK_DIR [--runs N] [--seed S] [--timeout T]

Takes the shipped parameter files (prm/*.prm, tests/prm/*.prm, the tutorial
scenes) and small gmsh meshes (tests/data/*.msh), shrinks the scenes so that
a run takes a fraction of a second (at most 4 subdivisions per direction, no
global refinement, no plot), and runs dpana on N mutants, drawn with a fixed
seed: bytes replaced by random ones, numbers replaced by extreme values (0,
-1, 1e308, nan, inf, a long string of digits...), names replaced or
misspelt, lines dropped or repeated, files truncated. A mutant of a gmsh
file is run through a fixed scene that reads it.

Every run must
  - end with exit status 0, 1 or 2 (no signal, no sanitizer report, which
    exits with another status) within the timeout;
  - on exit 1: write exactly one line to stderr, starting "dpana: error: ",
    and leave no output directory (the working directory holds exactly the
    input files afterwards).
Every run that breaks a rule is reported with its mutant, kept under
WORK_DIR/failures; the exit status is 1 if there was any. The shrunken,
unmutated scenes run first and must not break the rules either.
"""
import argparse
import collections
import glob
import os
import random
import re
import shutil
import subprocess
import sys

EXTREME_NUMBERS = ["0", "-1", "-0", "1e308", "-1e308", "1e-320", "nan", "inf",
                   "-inf", "1e6", "-1e6", "3", "0.5", "2", "12345678901234567890",
                   "1" * 400, "0x10", "1e", "+", "", "4294967296", "-2147483649"]
NAMES = ["bottom", "top", "left", "right", "curved", "axis", "Body 2",
         "Contact", "Contakt", "rectangle", "gmsh", "box", "x", "y", "z",
         "all", "nonexistent", "\x1b[31mred", "é", "a:b", "1, 2", ";", "="]

# The fixed scene that reads a mutated gmsh file "mesh.msh".
GMSH_SCENE = """set Dimension = {dim}
subsection Body 1
  subsection Geometry
    set Type = gmsh
    subsection Gmsh
      set Mesh file = mesh.msh
    end
  end
  subsection Boundary conditions
    set Fixed = {fixed}: all
  end
  subsection Loads
    set Body force = {force}
  end
end
"""
MESHES = {"rectangle_2x1_v22.msh": (2, "left"),
          "rectangle_2x1_v41.msh": (2, "left"),
          "plate_with_hole_v22.msh": (2, "outer"),
          "plate_with_hole_v41.msh": (2, "outer"),
          "cube_v22.msh": (3, "xmin"),
          "column_v41.msh": (3, "bottom")}


def shrink(text):
    """A quick version of a scene: small meshes, no plot, output to 'out'."""
    def fewer(match):
        numbers = [min(int(n), 4) for n in re.findall(r"\d+", match.group(2))]
        return match.group(1) + ", ".join(str(n) for n in numbers)
    text = re.sub(r"(set\s+Subdivisions\s*=\s*)([\d ,]+)", fewer, text)
    text = re.sub(r"(set\s+Global refinements\s*=\s*)\d+", r"\g<1>0", text)
    text = re.sub(r"(set\s+Radial subdivisions\s*=\s*)\d+", r"\g<1>2", text)
    text = "\n".join(line for line in text.split("\n")
                     if not re.match(r"\s*set\s+(Directory|Plot|Write VTU)\b",
                                     line))
    return text + ("\nsubsection Output\n  set Directory = out\n"
                   "  set Plot = false\n  set Write VTU = false\nend\n")


def load_corpus(source):
    """(name, dimension-free scene text or mesh bytes, kind, extra files)."""
    corpus = []
    files = sorted(glob.glob(os.path.join(source, "prm", "*.prm")) +
                   glob.glob(os.path.join(source, "tests", "prm", "*.prm")) +
                   glob.glob(os.path.join(source, "doc", "tutorials", "*",
                                          "*.prm")))
    for f in files:
        folder = os.path.splitext(f)[0] + ".files"
        extra = {}
        if os.path.isdir(folder):
            for g in os.listdir(folder):
                with open(os.path.join(folder, g), "rb") as h:
                    extra[g] = h.read()
        with open(f, "rb") as h:
            text = shrink(h.read().decode("utf-8", "replace"))
        corpus.append((os.path.relpath(f, source), text.encode(), "prm",
                       extra))
    for mesh, (dim, fixed) in sorted(MESHES.items()):
        with open(os.path.join(source, "tests", "data", mesh), "rb") as h:
            scene = GMSH_SCENE.format(dim=dim, fixed=fixed,
                                      force="0, -1" if dim == 2 else "0, 0, -1")
            corpus.append((mesh, h.read(), "msh", {"scene.prm": scene.encode()}))
    return corpus


def mutate(data, rng):
    """One mutation of the bytes of a file, and its description."""
    text = data.decode("utf-8", "replace")
    kind = rng.choice(["byte", "number", "number", "name", "truncate",
                       "drop line", "repeat line", "swap lines"])
    if kind == "byte" and data:
        data = bytearray(data)
        for _ in range(rng.randint(1, 4)):
            data[rng.randrange(len(data))] = rng.randrange(256)
        return bytes(data), kind
    if kind == "number":
        numbers = list(re.finditer(r"-?\d+(\.\d*)?([eE][-+]?\d+)?", text))
        if numbers:
            m = rng.choice(numbers)
            new = rng.choice(EXTREME_NUMBERS)
            return (text[:m.start()] + new + text[m.end():]).encode(), \
                "number %r -> %r" % (m.group(0), new[:20])
    if kind == "name":
        words = list(re.finditer(r"[A-Za-z_][A-Za-z_']+", text))
        if words:
            m = rng.choice(words)
            if rng.random() < 0.5:
                new = rng.choice(NAMES)
            else:
                w = m.group(0)
                i = rng.randrange(len(w))
                new = w[:i] + w[i + 1:]
            return (text[:m.start()] + new + text[m.end():]).encode(), \
                "name %r -> %r" % (m.group(0), new)
    lines = text.split("\n")
    if kind == "drop line" and len(lines) > 1:
        del lines[rng.randrange(len(lines))]
        return "\n".join(lines).encode(), kind
    if kind == "repeat line" and lines:
        i = rng.randrange(len(lines))
        lines.insert(i, lines[i])
        return "\n".join(lines).encode(), kind
    if kind == "swap lines" and len(lines) > 1:
        i, j = rng.randrange(len(lines)), rng.randrange(len(lines))
        lines[i], lines[j] = lines[j], lines[i]
        return "\n".join(lines).encode(), kind
    return data[:rng.randrange(len(data) + 1)], "truncate"


def run_case(dpana, workdir, files, scene, timeout):
    """Runs dpana on scene in a fresh workdir; returns (status, stderr,
    problems)."""
    shutil.rmtree(workdir, ignore_errors=True)
    os.makedirs(workdir)
    for name, content in files.items():
        with open(os.path.join(workdir, name), "wb") as h:
            h.write(content)
    before = sorted(os.listdir(workdir))
    try:
        p = subprocess.run([dpana, scene], cwd=workdir, capture_output=True,
                           timeout=timeout)
    except subprocess.TimeoutExpired:
        return None, b"", ["no answer within %g s" % timeout]
    problems = []
    err = p.stderr.decode("utf-8", "replace")
    if p.returncode not in (0, 1, 2):
        problems.append("exit status %d" % p.returncode)
    if p.returncode == 1:
        lines = err.splitlines()
        if len(lines) != 1 or not lines[0].startswith("dpana: error: "):
            problems.append("stderr is not one 'dpana: error:' line")
        if sorted(os.listdir(workdir)) != before:
            problems.append("files left behind: %s" % sorted(
                set(os.listdir(workdir)) - set(before)))
    return p.returncode, err, problems


def main():
    parser = argparse.ArgumentParser()
    parser.add_argument("dpana")
    parser.add_argument("source")
    parser.add_argument("work")
    parser.add_argument("--runs", type=int, default=300)
    parser.add_argument("--seed", type=int, default=20261123)
    parser.add_argument("--timeout", type=float, default=60)
    args = parser.parse_args()
    dpana = os.path.abspath(args.dpana)
    work = os.path.abspath(args.work)
    shutil.rmtree(work, ignore_errors=True)
    os.makedirs(os.path.join(work, "failures"))

    corpus = load_corpus(args.source)
    rng = random.Random(args.seed)
    cases = []
    for name, data, kind, extra in corpus:
        cases.append((name, data, kind, extra, "unmutated"))
    for _ in range(args.runs):
        name, data, kind, extra = rng.choice(corpus)
        mutant, how = mutate(data, rng)
        cases.append((name, mutant, kind, extra, how))

    counts = collections.Counter()
    failures = 0
    for k, (name, data, kind, extra, how) in enumerate(cases):
        files = dict(extra)
        if kind == "prm":
            files["scene.prm"] = data
        else:
            files["mesh.msh"] = data
        status, err, problems = run_case(dpana, os.path.join(work, "run"),
                                         files, "scene.prm", args.timeout)
        counts[status] += 1
        if problems:
            failures += 1
            keep = os.path.join(work, "failures", "%03d" % k)
            os.makedirs(keep)
            for f, content in files.items():
                with open(os.path.join(keep, f), "wb") as h:
                    h.write(content)
            print("FAIL %03d %s (%s): %s; stderr: %s" %
                  (k, name, how, "; ".join(problems), err[:300].strip()),
                  flush=True)
    shutil.rmtree(os.path.join(work, "run"), ignore_errors=True)
    print("fuzz: %d runs (%d unmutated), seed %d: exit 0: %d, exit 1: %d, "
          "exit 2: %d, broken rules: %d" %
          (len(cases), len(corpus), args.seed, counts[0], counts[1],
           counts[2], failures))
    return 1 if failures else 0


if __name__ == "__main__":
    sys.exit(main())
