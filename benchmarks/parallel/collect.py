#!/usr/bin/env python3
"""The runs of run.sh as one table: results.csv (every phase's time and
peak memory of rank 0 from summary.json, the peak resident memory of every
rank from /usr/bin/time, MUMPS' flops and memory from the log) and
results.md.

    collect.py WORKDIR RESULTS_DIR
"""
import csv
import glob
import json
import os
import re
import sys

PHASES = ["mesh", "assembly", "contact surface", "factorization", "condensation",
          "contact solve", "recovery", "output"]
MUMPS = re.compile(
    r"MUMPS on (\d+) rank\(s\): ([\d.]+) Gflop, memory estimated (\d+) MB "
    r"\(at most (\d+) MB on one rank\), used (\d+) MB \(at most (\d+) MB on "
    r"one rank\), (-?\d+) factor entries, Schur complement of (\d+) unknowns")


def row_of(run):
    name = os.path.basename(run)
    scene, np = name.rsplit("_np", 1)
    summary = json.load(open(os.path.join(run, "output", "summary.json")))
    body = summary["bodies"][0]
    contact = summary["contact"]
    row = {"scene": scene, "np": int(np), "dofs": body["dofs"],
           "n_c": 3 * contact["contact_elements"],
           "converged": contact["converged"]}
    for p in PHASES:
        row["t " + p] = summary["timings"].get(p, 0.0)
        row["mb " + p] = summary["peak_memory_mb"].get(p, 0.0)
    row["total"] = sum(summary["timings"].values())
    ranks = re.findall(
        r"rank peak kB (\d+) user ([\d.]+) system ([\d.]+) wall ([\d.]+)",
        open(os.path.join(run, "stderr.txt")).read())
    # /usr/bin/time reports the ranks in the order they end; rank 0 is the
    # one whose peak summary.json (written by rank 0) records.
    rank0 = max(summary["peak_memory_mb"].values())
    peaks = sorted((int(r[0]) / 1024 for r in ranks),
                   key=lambda p: abs(p - rank0))
    peaks = peaks[:1] + sorted(peaks[1:])
    # The CPU time of every rank against its wall time: the cores the run
    # had (a loaded machine gives a second rank less than a second core).
    row["cpu_s"] = sum(float(r[1]) + float(r[2]) for r in ranks)
    row["wall_s"] = max([float(r[3]) for r in ranks] or [0])
    row["cores_used"] = row["cpu_s"] / row["wall_s"] if row["wall_s"] else 0
    row["rank_peaks_mb"] = " ".join("%.0f" % p for p in peaks)
    row["max_rank_peak_mb"] = max(peaks) if peaks else 0
    row["sum_rank_peak_mb"] = sum(peaks)
    m = MUMPS.search(open(os.path.join(run, "stdout.txt")).read())
    keys = ["gflop", "mumps_est_total_mb", "mumps_est_max_mb",
            "mumps_used_total_mb", "mumps_used_max_mb", "factor_entries",
            "n_gamma"]
    for k, v in zip(keys, m.groups()[1:] if m else [0] * len(keys)):
        row[k] = float(v)
    row["load"] = (open(os.path.join(run, "load_before.txt")).read().split()[0]
                   + "-" +
                   open(os.path.join(run, "load_after.txt")).read().split()[0])
    return row


def main():
    work, out = sys.argv[1], sys.argv[2]
    os.makedirs(out, exist_ok=True)
    rows = [row_of(r) for r in sorted(glob.glob(os.path.join(work, "*_np*")))
            if os.path.exists(os.path.join(r, "output", "summary.json"))]
    rows.sort(key=lambda r: (r["dofs"], r["np"]))
    with open(os.path.join(out, "results.csv"), "w", newline="") as f:
        w = csv.DictWriter(f, fieldnames=list(rows[0].keys()))
        w.writeheader()
        w.writerows(rows)
    with open(os.path.join(out, "results.md"), "w") as f:
        f.write("| scene | np | dofs | n_c | n_Γ | " +
                " | ".join(p + " [s]" for p in PHASES) +
                " | total [s] | CPU [s] / wall [s] | peak per rank [MB] | MUMPS Gflop | MUMPS "
                "memory est./used, total [MB] | load |\n")
        f.write("|---" * (len(PHASES) + 11) + "|\n")
        for r in rows:
            f.write("| %s | %d | %d | %d | %d | " % (
                r["scene"], r["np"], r["dofs"], r["n_c"], r["n_gamma"]) +
                " | ".join("%.3g" % r["t " + p] for p in PHASES) +
                " | %.3g | %.3g / %.3g | %s | %.3g | %d / %d | %s |\n" % (
                    r["total"], r["cpu_s"], r["wall_s"], r["rank_peaks_mb"], r["gflop"],
                    r["mumps_est_total_mb"], r["mumps_used_total_mb"],
                    r["load"]))


if __name__ == "__main__":
    main()
