#!/usr/bin/env python3
"""Runs the refinement levels of scene families with the dpana binary and
writes, per family, results/<family>.json: one record per level (mesh size,
sizes, time per phase, peak memory, the quantities of interest).

Each level is its scene file with the level's entries changed, written to a
temporary directory and run there, without the VTU files and the plot (the
output phase then writes only contact.csv and summary.json). A run that
fails or does not converge is recorded as such and ends the family's sweep.

  sweep.py --dpana BUILD/dpana --prm-dir prm --out results [--full]
           [--timeout S] [--repeat N] [FAMILY ...]
"""

import os
import subprocess
import sys
import tempfile
import time

import families
import prm_edit
import records as records_io
from quantities import read_contact_csv, run_quantities


def level_text(family, prm_dir, edits):
    """The scene file of one level: the level's entries (each must be set
    by the scene file, so that a misspelt path cannot pass unnoticed), and
    an output without VTU files and plot."""
    with open(os.path.join(prm_dir, family.prm)) as f:
        text = f.read()
    for path, value in edits.items():
        if prm_edit.get_entry(text, path) is None:
            raise SystemExit(f"sweep.py: error: {family.prm} sets no entry "
                             f"'{path}'")
        if isinstance(value, families.SphereMesh):
            value = value.path(prm_dir)
        text = prm_edit.set_entry(text, path, value)
    for path, value in (("Output/Directory", "output"),
                        ("Output/Write VTU", "false"),
                        ("Output/Plot", "false")):
        text = prm_edit.set_entry(text, path, value)
    return text


def run_level(dpana, family, prm_dir, level, h, edits, timeout,
              tractions=False):
    """The record of one level (quantities.run_quantities); with
    @p tractions also its rows of contact.csv, under "tractions"."""
    with tempfile.TemporaryDirectory(prefix=f"conv_{family.name}_") as tmp:
        prm = os.path.join(tmp, "scene.prm")
        with open(prm, "w") as f:
            f.write(level_text(family, prm_dir, edits))
        start = time.perf_counter()
        try:
            proc = subprocess.run([os.path.abspath(dpana), prm], cwd=tmp,
                                  capture_output=True,
                                  text=True, timeout=timeout)
        except subprocess.TimeoutExpired:
            return {"level": level, "h": h, "failed": f"timeout {timeout} s"}
        wall = time.perf_counter() - start
        if proc.returncode != 0:
            tail = (proc.stdout + proc.stderr).strip().splitlines()[-3:]
            return {"level": level, "h": h,
                    "failed": f"exit {proc.returncode}: " + " | ".join(tail)}
        record = run_quantities(os.path.join(tmp, "output"), family.dim,
                                family.uniform)
        if tractions:
            record["tractions"] = read_contact_csv(
                os.path.join(tmp, "output", "contact.csv"))
    record.update({"level": level, "h": h, "wall": wall,
                   "edits": {k: str(getattr(v, "level", v))
                             for k, v in edits.items()}})
    return record


def sweep(dpana, family, prm_dir, full, timeout, repeat=1):
    """The levels of family, each run repeat times (a short one more:
    records.fastest_of_runs), the fastest kept."""
    levels = family.levels + (family.full if full else [])
    records = []
    for i, (h, edits) in enumerate(levels):
        records.append(records_io.fastest_of_runs(
            lambda: run_level(dpana, family, prm_dir, i, h, edits, timeout),
            repeat))
        if not records_io.progress(records[-1]):
            break
    return records


def main():
    parser = records_io.parser(__doc__.splitlines()[0])
    parser.add_argument("--dpana", required=True)
    parser.add_argument("--prm-dir", required=True)
    args = parser.parse_args()
    names = args.family or [f.name for f in families.FAMILIES]
    unknown = [n for n in names if n not in families.BY_NAME]
    if unknown:
        sys.exit(f"sweep.py: error: unknown family {', '.join(unknown)} "
                 f"(known: {', '.join(families.BY_NAME)})")
    os.makedirs(args.out, exist_ok=True)
    load = records_io.load_average()
    for name in names:
        print(f"== {name}", flush=True)
        records = sweep(os.path.abspath(args.dpana), families.BY_NAME[name],
                        args.prm_dir, args.full, args.timeout, args.repeat)
        records_io.write(args.out, name, "dpana", records, load)


if __name__ == "__main__":
    main()
