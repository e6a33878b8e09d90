"""Wall time and peak memory of a large 3D solid's modes, through `asterlite run`.

The clamped HEXA8 bar of ``solid_modal.py`` (10 x 1 x 1, steel), cut into
NX x NY x NZ cells, to its 50 lowest modes (CALC_MODES PLUS_PETITE). Each
size runs as its own `asterlite run` process; the table gives its wall time,
its CPU time (all threads), the time of CALC_MODES, its peak resident memory
(the child's ru_maxrss, from wait4), the eigen solver message.log names, and
the first frequency.

    python benchmarks/large_modal.py                      # 10k, 25k, 50k, 98k DOFs
    python benchmarks/large_modal.py 100x17x17            # the 98 172-DOF bar only
    python benchmarks/large_modal.py 100x17x17 --solver cholmod   # without MUMPS
    python benchmarks/large_modal.py 100x17x17 --solver superlu   # the old path
    python benchmarks/large_modal.py 40x8x8 --modes 20
    python benchmarks/large_modal.py 100x17x17 --mpi "mpirun -n 2" --mpi-python /usr/bin/python3

``--solver`` sets ASTERLITE_SPARSE_SOLVER for the child (auto: the block
Lanczos method from asterlite.fem.sparse_direct.LARGE_LIMIT unknowns on, on a
MUMPS factor when python-mumps imports, else on CHOLMOD's (cholespy);
cholmod: CHOLMOD even where MUMPS is installed; superlu: SuperLU and ARPACK,
the old path, whatever the size).
"""

from __future__ import annotations

import argparse
import datetime
import os
import platform
import re
import subprocess
import sys
import tempfile
import time
from pathlib import Path

import numpy as np

sys.path.insert(0, str(Path(__file__).resolve().parent))

import solid_modal  # noqa: E402  (the mesh writer and the deck)

SIZES = ("40x8x8", "60x11x11", "80x14x13", "100x17x17")


def prepare(folder: Path, cells: tuple[int, int, int], n_modes: int) -> int:
    dofs = solid_modal.write_mesh(folder / "bar.mail", cells)
    deck = solid_modal.DECK.format(
        E=solid_modal.E, NU=solid_modal.NU, RHO=solid_modal.RHO, N_MODES=n_modes
    )
    # every frequency at full precision, to compare solvers
    deck = deck.replace(
        "FIN()",
        'freqs = RECU_TABLE(CO=modes, NOM_PARA="FREQ")\n'
        'print("frequencies", repr(freqs.EXTR_TABLE().values()["FREQ"]))\nFIN()',
    )
    (folder / "bar.comm").write_text(deck)
    (folder / "bar.export").write_text("F comm bar.comm D 1\nF mail bar.mail D 20\n")
    return dofs


def run_one(cells, n_modes: int, solver: str, mpi: list[str] = ()) -> dict:
    with tempfile.TemporaryDirectory(prefix="asterlite-large-") as tmp:
        folder = Path(tmp)
        dofs = prepare(folder, cells, n_modes)
        env = dict(os.environ, ASTERLITE_SPARSE_SOLVER=solver)
        command = [
            sys.executable, "-m", "asterlite", "run", str(folder / "bar.export"),
            "-o", str(folder / "out"), "-q", "--time-limit", "0", "--memory-limit", "0",
            *mpi,
        ]  # fmt: skip
        start = time.perf_counter()
        child = subprocess.Popen(command, env=env, stdout=subprocess.PIPE, stderr=subprocess.STDOUT)
        output = child.stdout.read().decode(errors="replace")
        _, status, usage = os.wait4(child.pid, 0)
        child.returncode = os.waitstatus_to_exitcode(status)
        wall = time.perf_counter() - start
        log_path = folder / "out" / "message.log"
        log = log_path.read_text(errors="replace") if log_path.exists() else output
    calc = re.search(r"CALC_MODES.*?([0-9.]+) s", log)
    timing = [ln for ln in log.splitlines() if "CALC_MODES" in ln and " s" in ln]
    seconds = None
    for line in timing:
        found = re.findall(r"([0-9]+\.[0-9]+) s\b", line)
        if found:
            seconds = float(found[-1])
    how = next(
        (ln.strip() for ln in log.splitlines() if "factorisation of K" in ln or "MPI ranks" in ln),
        "",
    )
    listed = re.search(r"^frequencies \[(.*)\]", log, re.MULTILINE)
    frequencies = [float(f) for f in listed.group(1).split(",")] if listed else []
    first = next((ln.strip() for ln in log.splitlines() if ln.strip().startswith("mode    1")), "")
    return {
        "cells": "x".join(map(str, cells)),
        "dofs": dofs,
        "exit": child.returncode,
        "wall": wall,
        "calc_modes": seconds if seconds is not None else (float(calc.group(1)) if calc else None),
        "peak_mb": usage.ru_maxrss / 1024.0,
        # CPU seconds of the child (every thread): on a machine loaded by
        # other work, wall time stretches, CPU time much less
        "cpu": usage.ru_utime + usage.ru_stime,
        "how": how,
        "first": first,
        "frequencies": frequencies,
        "tail": "" if child.returncode == 0 else output[-2000:],
    }


def main() -> None:
    parser = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    parser.add_argument("sizes", nargs="*", default=list(SIZES), help="NXxNYxNZ cells")
    parser.add_argument("--modes", type=int, default=50)
    parser.add_argument("--solver", default="auto", choices=("auto", "mumps", "cholmod", "superlu"))
    parser.add_argument("--mpi", help="asterlite run --mpi LAUNCHER (PETSc/SLEPc ranks)")
    parser.add_argument("--mpi-python", help="asterlite run --mpi-python PYTHON")
    parser.add_argument(
        "--compare", action="store_true", help="also run the default solver; print the largest "
        "relative difference of the frequencies",
    )  # fmt: skip
    args = parser.parse_args()
    mpi = ["--mpi", args.mpi] if args.mpi else []
    if args.mpi_python:
        mpi += ["--mpi-python", args.mpi_python]
    load = os.getloadavg()
    print(
        f"# {datetime.datetime.now(datetime.UTC):%Y-%m-%d %H:%M} UTC, {platform.node()}, "
        f"{os.cpu_count()} CPUs, Python {platform.python_version()}, "
        f"load average {load[0]:.1f} {load[1]:.1f} {load[2]:.1f}, solver {args.solver}"
    )
    print(
        f"{'cells':>10} {'DOFs':>7} {'wall s':>7} {'CPU s':>6} {'CALC_MODES s':>12} "
        f"{'peak MB':>8}  solver"
    )
    for size in args.sizes:
        cells = tuple(int(c) for c in size.lower().split("x"))
        row = run_one(cells, args.modes, args.solver, mpi)
        calc = f"{row['calc_modes']:.1f}" if row["calc_modes"] is not None else "?"
        print(
            f"{row['cells']:>10} {row['dofs']:>7} {row['wall']:>7.1f} {row['cpu']:>6.1f} "
            f"{calc:>12} "
            f"{row['peak_mb']:>8.0f}  {row['how'] or '(SuperLU + ARPACK)'}",
            flush=True,
        )
        if row["first"]:
            print(f"{'':>10} {row['first']}")
        if row["exit"] != 0:
            print(f"  exit {row['exit']}:\n{row['tail']}")
        if args.compare and row["exit"] == 0:
            other = run_one(cells, args.modes, args.solver)
            new, old = np.array(row["frequencies"]), np.array(other["frequencies"])
            if new.shape == old.shape and new.size:
                worst = float(np.max(np.abs(new - old) / np.abs(old)))
                print(f"{'':>10} {new.size} frequencies; largest relative difference from "
                      f"{other['how'] or 'the default solver'} ({other['wall']:.1f} s wall, "
                      f"{other['peak_mb']:.0f} MB): {worst:.1e}", flush=True)  # fmt: skip
            else:
                print(f"{'':>10} frequencies differ in number: {new.size} and {old.size}")
    load = os.getloadavg()
    print(f"# load average at the end {load[0]:.1f} {load[1]:.1f} {load[2]:.1f}")


if __name__ == "__main__":
    main()
