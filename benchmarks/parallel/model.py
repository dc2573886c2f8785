#!/usr/bin/env python3
"""A cost model of the MPI route per phase, fitted to the runs of run.sh
(results.csv) and to what MUMPS reports, and its prediction for a 3D body
of 1e7 dofs with 1e4 contact unknowns on 16, 64 and 256 ranks
(model.md). The model and its assumptions are in doc/parallel.md; here:

- factorisation: MUMPS' flops F(N) = F_0 (N / N_0)^p, p fitted to the flops
  MUMPS reports for the two largest sizes run (with a Schur complement
  Debian's MUMPS 5.5 orders by AMD whatever ICNTL(7) asks, and p is well above the
  2 of nested dissection in 3D, George 1973), at the measured rate r_1 of
  one rank, divided over P
  ranks with a parallel efficiency e: t(P) = F / (r_1 P e), once with the
  efficiency measured between np = 1 and np = 2, e = t(1) / (2 t(2)), and
  once with e = 1 (the bound);
- factor memory: MUMPS' estimate (INFOG(17)) ~ N^q, q fitted as p (4/3
  for nested dissection in 3D), divided over P ranks with the imbalance of the
  run on 2 ranks (INFOG(16) x P / INFOG(17));
- the dense Schur block: S and L_S (n_G^3 / 3 flops, 2 x 8 n_G^2 bytes, on
  rank 0), W = L_S^-1 V_G and A = W^T W (n_G^2 n_c + n_G n_c^2 flops,
  8 (n_G n_c + n_c^2) bytes) at the measured dense rate, serial, on rank 0;
- the contact solve: t = t_0 (n_c / n_c0)^q, q fitted to the measured runs,
  serial on rank 0;
- assembly at the measured rate per dof, not divided by P (rank 0 builds
  the whole mesh); the per-rank memory of the mesh and K at the measured
  bytes per dof, of which, with the distributed mesh and assembly (the
  default), the fraction measured by assembly.sh on two ranks
  (results/assembly.md: one process against rank 1 of the distributed
  mesh) is divided over P and the rest (the vectors of all dofs, the
  points and dofs of every vertex) stays on every rank;
- recovery: two interior solves, 4 flops per factor entry, divided over P
  ranks as the factorisation.

    model.py results.csv OUT_DIR [assembly.md]
"""
import csv
import math
import os
import re
import sys

TARGET_N, TARGET_NC = 1e7, 1e4
RANKS = [16, 64, 256]


def load(path):
    rows = list(csv.DictReader(open(path)))
    for r in rows:
        for k, v in r.items():
            try:
                r[k] = float(v)
            except ValueError:
                pass
    return rows


def exponent(x0, y0, x1, y1):
    if x0 <= 0 or x1 <= 0 or y0 <= 0 or y1 <= 0 or x0 == x1:
        return float("nan")
    return math.log(y1 / y0) / math.log(x1 / x0)


def fit(rows):
    one = sorted([r for r in rows if r["np"] == 1], key=lambda r: r["dofs"])
    two = {r["dofs"]: r for r in rows if r["np"] == 2}
    big = one[-1]
    small = one[0]
    N0, nc0, nG0 = big["dofs"], big["n_c"], big["n_gamma"]
    m = {"N0": N0, "nc0": nc0, "nG0": nG0}
    m["flops0"] = big["gflop"] * 1e9
    # MUMPS' counts do not depend on the ranks (the same sequential
    # ordering): the exponents from the two largest sizes run, on any
    # number of ranks (the memory from the runs on 2 ranks).
    by_size = sorted({r["dofs"]: r for r in rows}.values(),
                     key=lambda r: r["dofs"])
    a, b = by_size[-2], by_size[-1]
    m["flop_exponent"] = exponent(a["dofs"], a["gflop"], b["dofs"],
                                  b["gflop"])
    two_sizes = sorted([r for r in rows if r["np"] == 2],
                       key=lambda r: r["dofs"])
    a, b = two_sizes[-2], two_sizes[-1]
    m["mem_exponent"] = exponent(a["dofs"], a["mumps_est_total_mb"],
                                 b["dofs"], b["mumps_est_total_mb"])
    m["fact_rate"] = m["flops0"] / big["t factorization"]
    b2 = two.get(N0)
    m["efficiency"] = (big["t factorization"] / (2 * b2["t factorization"])
                       if b2 else 1.0)
    m["mem0_mb"] = big["mumps_est_total_mb"]
    m["imbalance"] = (2 * b2["mumps_est_max_mb"] / b2["mumps_est_total_mb"]
                      if b2 and b2["mumps_est_total_mb"] > 0 else 1.0)
    dense_flops = nG0 ** 2 * nc0 + nG0 * nc0 ** 2
    m["dense_rate"] = dense_flops / max(big["t condensation"], 1e-9)
    m["solve_exponent"] = exponent(small["n_c"], small["t contact solve"],
                                   nc0, big["t contact solve"])
    m["solve0"] = big["t contact solve"]
    m["asm_rate"] = big["t assembly"] / N0
    m["asm_mb_per_dof"] = (big["mb assembly"] - small["mb assembly"]) / (
        N0 - small["dofs"])
    m["base_mb"] = big["mb assembly"] - m["asm_mb_per_dof"] * N0
    m["recovery_rate"] = 4 * big["factor_entries"] / max(big["t recovery"],
                                                        1e-9)
    m["entries0"] = big["factor_entries"]
    return m


def replicated_fraction(path, base_mb):
    """The fraction of the memory of the mesh and K (above base_mb) that
    stays on every rank with the distributed mesh: from the peak after the
    assembly of one process, T, and of rank 1 of two with the distributed
    mesh, D (both above base_mb), D = x T + (1 - x) T / 2."""
    if not path or not os.path.exists(path):
        return 1.0
    peaks = {}
    for line in open(path):
        cells = [c.strip() for c in line.split("|")[1:-1]]
        if len(cells) > 11 and cells[0] in ("np1", "np2_distributed_mesh"):
            peaks[cells[0]] = [float(x) for x in re.findall(r"[\d.]+",
                                                             cells[10])]
    if "np1" not in peaks or "np2_distributed_mesh" not in peaks:
        return 1.0
    T = peaks["np1"][0] - base_mb
    D = peaks["np2_distributed_mesh"][-1] - base_mb
    return min(1.0, max(0.0, (2 * D - T) / T))


def predict(m, N, nc, P, efficiency):
    nG = nc * m["nG0"] / m["nc0"]
    share = 1 / (P * efficiency)
    F = m["flops0"] * (N / m["N0"]) ** m["flop_exponent"]
    t = {}
    t["assembly"] = m["asm_rate"] * N
    t["factorization"] = F / m["fact_rate"] * share + nG ** 3 / 3 / m[
        "dense_rate"]
    t["condensation"] = (nG ** 2 * nc + nG * nc ** 2) / m["dense_rate"]
    t["contact solve"] = m["solve0"] * (nc / m["nc0"]) ** m["solve_exponent"]
    entries = m["entries0"] * (N / m["N0"]) ** m["mem_exponent"]
    t["recovery"] = 4 * entries / m["recovery_rate"] * share
    factor_mb = m["mem0_mb"] * (N / m["N0"]) ** m["mem_exponent"] / P * m[
        "imbalance"]
    dense_mb = 8 * (2 * nG ** 2 + nG * nc + nc ** 2) / 2 ** 20
    x = m["replicated_fraction"]
    mesh_mb = m["base_mb"] + m["asm_mb_per_dof"] * N * (x + (1 - x) / P)
    return t, {"factor per rank": factor_mb, "dense on rank 0": dense_mb,
               "mesh and K on every rank": mesh_mb,
               "total on rank 0": factor_mb + dense_mb + mesh_mb}


def main():
    rows = load(sys.argv[1])
    out = sys.argv[2]
    m = fit(rows)
    m["replicated_fraction"] = replicated_fraction(
        sys.argv[3] if len(sys.argv) > 3 else None, m["base_mb"])
    lines = ["# Cost model of the MPI route (fitted by model.py)", "",
             "Fitted on the largest run of results.csv (%d dofs, n_c = %d, "
             "n_Γ = %d):" % (m["N0"], m["nc0"], m["nG0"]), "",
             "| quantity | value |", "|---|---|"]
    for k in ["flops0", "flop_exponent", "mem0_mb",
              "mem_exponent", "fact_rate", "efficiency",
              "imbalance", "dense_rate", "solve0", "solve_exponent",
              "asm_rate", "asm_mb_per_dof", "base_mb", "replicated_fraction",
              "recovery_rate"]:
        lines.append("| %s | %.4g |" % (k, m[k]))
    lines += ["", "Prediction for a 3D body of %.0e dofs with %.0e contact "
              "unknowns (times in s, memory in GB):" % (TARGET_N, TARGET_NC),
              "", "| ranks | e | assembly | factorization | condensation | "
              "contact solve | recovery | factor per rank | dense on rank 0 "
              "| mesh and K on every rank | total on rank 0 |",
              "|---|---|---|---|---|---|---|---|---|---|---|"]
    for P, e in [(P, e) for e in [m["efficiency"], 1.0] for P in RANKS]:
        t, mem = predict(m, TARGET_N, TARGET_NC, P, e)
        lines.append("| %d | %.2f | " % (P, e) + " | ".join(
            "%.3g" % t[k] for k in ["assembly", "factorization",
                                    "condensation", "contact solve",
                                    "recovery"]) + " | " + " | ".join(
            "%.3g" % (mem[k] / 1024) for k in [
                "factor per rank", "dense on rank 0",
                "mesh and K on every rank", "total on rank 0"]) + " |")
    # Where the serial dense work on rank 0 overtakes the distributed
    # factorisation on 256 ranks, and where the dense blocks outgrow 64 GB.
    nc = 1000.0
    while nc < 1e6:
        t, mem = predict(m, TARGET_N, nc, 256, 1.0)
        if t["condensation"] + t["contact solve"] > t["factorization"]:
            break
        nc *= 1.1
    lines += ["", "On 256 ranks (e = 1) and 1e7 dofs the serial dense work "
              "(A and the contact solve) overtakes the factorisation at "
              "n_c ≈ %.2g." % nc]
    nc = 1000.0
    while nc < 1e7:
        _, mem = predict(m, TARGET_N, nc, 256, 1.0)
        if mem["dense on rank 0"] > 64 * 1024:
            break
        nc *= 1.1
    lines.append("The dense blocks S, L_S, W and A outgrow a 64 GB node at "
                 "n_c ≈ %.2g." % nc)
    open(os.path.join(out, "model.md"), "w").write("\n".join(lines) + "\n")
    print("\n".join(lines))


if __name__ == "__main__":
    main()
