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
                   help="runs per level, the fastest kept (at least "
                   f"{SHORT_RUNS} for a level whose first run took less "
                   f"than {SHORT} s)")
    p.add_argument("family", nargs="*")
    return p


def fastest(runs):
    """The run of least solve time: on a shared machine the minimum is the
    time least disturbed by other work (the answers are the same)."""
    return min(runs, key=lambda r: r.get("solve_time", float("inf")))


# A level whose first run solved in less than SHORT seconds is run at least
# SHORT_RUNS times: its runs cost little, and times of milliseconds are the
# ones other work on the machine disturbs most (the same level of the same
# binary took 2.7 ms in one sitting and 4.8 ms in another).
SHORT = 0.1
SHORT_RUNS = 5


def fastest_of_runs(run_once, repeat):
    """The fastest of repeat runs of a level (run_once() runs it once and
    returns its record), or of SHORT_RUNS if its first run was short."""
    runs = [run_once()]
    if runs[0].get("solve_time", float("inf")) < SHORT:
        repeat = max(repeat, SHORT_RUNS)
    runs += [run_once() for _ in range(repeat - 1)]
    return fastest(runs)


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
