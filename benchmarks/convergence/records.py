"""What the dpana sweep (sweep.py) and the GetFEM sweep (getfem/sweep.py)
share: their command line, the choice of the fastest of repeated runs of
a level, the progress line of a level and the results file of a family
(results/<family>.json for dpana, getfem_<family>.json for GetFEM: the code,
the load average at the start and one record per level)."""

import argparse
import json
import os


def parser(description):
    """The arguments of both sweeps (each adds its own)."""
    p = argparse.ArgumentParser(description=description)
    p.add_argument("--out", required=True, help="results directory")
    p.add_argument("--full", action="store_true",
                   help="also the finer levels of --full")
    p.add_argument("--timeout", type=float, default=900,
                   help="seconds per run")
    p.add_argument("--repeat", type=int, default=1,
                   help="runs per level, the fastest kept")
    p.add_argument("family", nargs="*")
    return p


def fastest(runs):
    """The run of least solve time: on a shared machine the minimum is the
    time least disturbed by other work (the answers are the same)."""
    return min(runs, key=lambda r: r.get("solve_time", float("inf")))


def progress(record):
    """Prints the line of one level; False when the sweep must stop (the
    run failed or did not converge)."""
    if "failed" in record:
        print(f"  level {record['level']}: FAILED ({record['failed']})",
              flush=True)
        return False
    print(f"  level {record['level']}: h = {record['h']:.4g}, dofs "
          f"{record['dofs']}, contact unknowns {record['contact_unknowns']},"
          f" solve {record['solve_time']:.3g} s, N_max {record['N_max']:.6g}"
          + ("" if record["converged"] else " NOT converged"), flush=True)
    return bool(record["converged"])


def write(out, name, code, records, load):
    prefix = "" if code == "dpana" else f"{code}_"
    with open(os.path.join(out, f"{prefix}{name}.json"), "w") as f:
        json.dump({"family": name, "code": code, "loadavg": load,
                   "records": records}, f, indent=1)


def load_average():
    with open("/proc/loadavg") as f:
        return f.read().split()[:3]
