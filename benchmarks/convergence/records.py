"""What the dpana sweep (sweep.py) and the GetFEM sweep (getfem/sweep.py)
share: their command line, the choice of the fastest of repeated runs of
a level, the progress line of a level and the results file of a family
(results/<family>.json for dpana, getfem_<family>.json for GetFEM: the code,
the load average at the start and one record per level)."""

import argparse
import ctypes
import functools
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
                   + ", ".join(f"{n} for a level whose first run took "
                               f"less than {t} s"
                               for t, n in RUNS_FOR_SHORT) + ")")
    p.add_argument("family", nargs="*")
    return p


def fastest(runs):
    """The run of least solve time: on a shared machine the minimum is the
    time least disturbed by other work (the answers are the same)."""
    return min(runs, key=lambda r: r.get("solve_time", float("inf")))


# A level whose first run was short is run more often: its runs cost
# little, and the shorter a time the more other work on the machine
# disturbs it (the same level of the same binary took 2.7 ms in one sitting
# and 4.8 ms in another; a single run of 0.12 s stood where the sitting
# before had measured 0.036 s). The same rule holds for both codes: a first
# run of less than LENGTH seconds makes at least RUNS runs.
RUNS_FOR_SHORT = ((0.1, 5), (1.0, 3))  # (LENGTH, RUNS), shortest first


def fastest_of_runs(run_once, repeat):
    """The fastest of repeat runs of a level (run_once() runs it once and
    returns its record), or of more if its first run was short
    (RUNS_FOR_SHORT)."""
    runs = [run_once()]
    first = runs[0].get("solve_time", float("inf"))
    for length, n in RUNS_FOR_SHORT:
        if first < length:
            repeat = max(repeat, n)
            break
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
                   "processor": processor(),
                   "blas_kernels": kernels_in_use(),
                   "records": records}, f, indent=1)


@functools.lru_cache(maxsize=None)
def openblas_core():
    """The kernels OpenBLAS runs in this process (its own choice, or the
    OPENBLAS_CORETYPE of this environment); None without OpenBLAS."""
    try:
        blas = ctypes.CDLL("libopenblas.so.0")
    except OSError:
        return None
    blas.openblas_get_corename.restype = ctypes.c_char_p
    return blas.openblas_get_corename().decode()


@functools.lru_cache(maxsize=None)
def blas_kernels():
    """The OpenBLAS kernels that the dpana command names for its runs
    (OPENBLAS_CORETYPE, source/launcher/launcher.cc: the AVX2 kernels when
    OpenBLAS would run its generic "Prescott" ones on a processor with AVX2
    and FMA, as OpenBLAS 0.3.21 does on the Xeons it does not know), or
    None where OpenBLAS keeps its own choice. The GetFEM sweep gives its
    runs the same kernels: both codes compute their dense blocks with the
    same BLAS on the same instructions."""
    if "OPENBLAS_CORETYPE" in os.environ:
        return None
    core = openblas_core()
    if core is None or core.lower() != "prescott":
        return None
    flags = cpuinfo().get("flags", "").split()
    return "Haswell" if {"avx2", "fma"} <= set(flags) else None


def kernels_in_use():
    """The OpenBLAS kernels the runs of a sweep compute with: the given
    OPENBLAS_CORETYPE, else those the dpana command names, else OpenBLAS'
    own choice on this processor (None without OpenBLAS). Recorded in each
    results file, so that records of different days, perhaps on different
    processors, say which kernels they ran."""
    return (os.environ.get("OPENBLAS_CORETYPE") or blas_kernels()
            or openblas_core())


@functools.lru_cache(maxsize=None)
def cpuinfo():
    """The entries of /proc/cpuinfo, each with the value of its first line
    (that of the first processor); empty where the file is not there."""
    entries = {}
    try:
        with open("/proc/cpuinfo") as f:
            for line in f:
                key, colon, value = line.partition(":")
                if colon:
                    entries.setdefault(key.strip(), value.strip())
    except OSError:
        pass
    return entries


def processor():
    """The processor's model name with its family and model numbers, as
    the runs' summary.json says it (/proc/cpuinfo; None where it has no
    model name): the machine a cloud gives differs from day to day, and so
    do its times."""
    entries = cpuinfo()
    name = entries.get("model name")
    if name and "cpu family" in entries and "model" in entries:
        name += " (family %s, model %s)" % (entries["cpu family"],
                                            entries["model"])
    return name


def load_average():
    with open("/proc/loadavg") as f:
        return f.read().split()[:3]
