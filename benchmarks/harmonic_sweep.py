"""Harmonic sweeps (DYNA_VIBRA TYPE_CALCUL='HARM', asterlite.harmonic).

1. Generalized basis: 100 modes, 1000 frequencies, right-hand side
   F(f) = Φᵀ f for one load, solved by ``asterlite.harmonic.modal.solve``:
   - diagonal M, K with modal damping (AMOR_MODAL): element-wise;
   - diagonal M, K with a full, non-proportional damping matrix (a projected
     MATR_AMOR of localised dampers): the first-order operator's
     eigen-decomposition once, then two matrix products per sweep, each
     frequency's backward error checked;
   - the same sweep by stacked LU solves (what code_aster does, one
     factorisation per frequency), for comparison.
2. Physical basis: a 20 000-DOF model assembled by asterlite from a deck
   (a clamped steel tube line of POU_D_E beams on spring supports, Rayleigh
   damping), ``asterlite.harmonic.physical``: the reduction under the
   boundary conditions once, then one SuperLU factorisation per frequency.
   With ``--grid`` a plate-like grid of beams instead (a two-dimensional
   pattern: much more fill per factorisation).

    python benchmarks/harmonic_sweep.py [--frequencies 1000] [--grid] [--repeat 3]

Times are best-of-N wall seconds of the solve (the deck's assembly is not
counted), printed with the machine's load average.
"""

from __future__ import annotations

import argparse
import os
import tempfile
import time
from pathlib import Path

# one BLAS thread, as the other benchmarks: on a shared 2-core machine
# OpenBLAS's second thread waits for a busy core (an eigen-decomposition of
# 200 x 200 took seconds instead of milliseconds)
os.environ.setdefault("OPENBLAS_NUM_THREADS", "1")

import numpy as np  # noqa: E402

from asterlite.fem import sparse_direct  # noqa: E402
from asterlite.harmonic import HarmonicLoad, modal, physical  # noqa: E402
from asterlite.harmonic.loads import SweepLoads  # noqa: E402


def best_of(repeat, function):
    times, out = [], None
    for _ in range(repeat):
        start = time.perf_counter()
        out = function()
        times.append(time.perf_counter() - start)
    return min(times), out


# ----------------------------------------------------------------------------- generalized


def generalized(n_modes: int, n_freq: int, repeat: int) -> None:
    rng = np.random.default_rng(0)
    frequencies = np.sort(rng.uniform(1.0, 300.0, n_modes))
    omega = 2 * np.pi * frequencies
    mass = np.eye(n_modes)
    stiffness = np.diag(omega**2)
    sweep = np.linspace(0.5, 320.0, n_freq)
    shapes = rng.normal(size=(50, n_modes))
    force = shapes.T @ rng.normal(size=50)
    rhs = SweepLoads.of([HarmonicLoad(force, 1.0)], sweep, n_modes)
    modal_damping = np.diag(2 * 0.02 * omega)
    # localised dampers seen by the modes: a full, non-proportional matrix
    dampers = rng.normal(size=(6, n_modes))
    full_damping = modal_damping + 5.0 * dampers.T @ dampers
    cases = (
        ("diagonal (AMOR_MODAL)", modal_damping, "auto"),
        ("full damping, state space", full_damping, "auto"),
        ("full damping, LU per frequency", full_damping, "direct"),
    )
    print(f"generalized basis: {n_modes} modes, {n_freq} frequencies")
    reference = None
    for label, damping, method in cases:
        seconds, (q, info) = best_of(
            repeat,
            lambda d=damping, m=method: modal.solve(mass, stiffness, d, sweep, rhs, method=m),
        )
        note = f", {info.redone} solved again directly" if info.redone else ""
        if damping is full_damping:
            if reference is None:
                reference = q
            else:
                gap = np.abs(q - reference).max() / np.abs(reference).max()
                note += f", max gap to the state-space answer {gap:.1e}"
        print(f"  {label:32s} {seconds * 1e3:8.1f} ms  ({info.method}{note})")


# ----------------------------------------------------------------------------- physical


def line_mesh(n_nodes: int, length: float) -> str:
    x = np.linspace(0.0, length, n_nodes)
    lines = [" TITRE", " TUBE LINE", " FINSF", " %", " COOR_3D"]
    lines += [f" N{i + 1} {xi:.12E} 0.0 0.0" for i, xi in enumerate(x)]
    lines += [" FINSF", " %", " SEG2"]
    lines += [f" S{i + 1} N{i + 1} N{i + 2}" for i in range(n_nodes - 1)]
    lines += [" FINSF", " %", " POI1"]
    supports = range(0, n_nodes, 50)
    lines += [f" P{i + 1} N{i + 1}" for i in supports]
    lines += [" FINSF", " %", " GROUP_MA", " TUBE"]
    lines += [f" S{i + 1}" for i in range(n_nodes - 1)]
    lines += [" FINSF", " %", " GROUP_MA", " APPUIS"]
    lines += [f" P{i + 1}" for i in supports]
    lines += [" FINSF", " %", " GROUP_NO", " ENDS", " N1", f" N{n_nodes}", " FINSF", " %"]
    lines += [" GROUP_NO", " LOAD", f" N{n_nodes // 3}", " FINSF", " %", " FIN"]
    return "\n".join(lines) + "\n"


def grid_mesh(n_side: int, length: float) -> str:
    x = np.linspace(0.0, length, n_side)
    name = lambda i, j: f"N{i * n_side + j + 1}"  # noqa: E731
    lines = [" TITRE", " GRID", " FINSF", " %", " COOR_3D"]
    lines += [
        f" {name(i, j)} {x[i]:.12E} {x[j]:.12E} 0.0" for i in range(n_side) for j in range(n_side)
    ]
    lines += [" FINSF", " %", " SEG2"]
    cells = []
    for i in range(n_side):
        for j in range(n_side):
            if i + 1 < n_side:
                cells.append((name(i, j), name(i + 1, j)))
            if j + 1 < n_side:
                cells.append((name(i, j), name(i, j + 1)))
    lines += [f" S{k + 1} {a} {b}" for k, (a, b) in enumerate(cells)]
    lines += [" FINSF", " %", " POI1", " P1 N1", " FINSF", " %"]
    lines += [" GROUP_MA", " TUBE"] + [f" S{k + 1}" for k in range(len(cells))]
    lines += [" FINSF", " %", " GROUP_MA", " APPUIS", " P1", " FINSF", " %"]
    edge = [name(0, j) for j in range(n_side)]
    lines += [" GROUP_NO", " ENDS"] + [f" {n}" for n in edge] + [" FINSF", " %"]
    lines += [" GROUP_NO", " LOAD", f" {name(n_side // 2, n_side // 2)}", " FINSF", " %", " FIN"]
    return "\n".join(lines) + "\n"


DECK = """
DEBUT()
MAIL = LIRE_MAILLAGE(FORMAT="ASTER")
MODELE = AFFE_MODELE(MAILLAGE=MAIL, AFFE=(
    _F(GROUP_MA="TUBE", PHENOMENE="MECANIQUE", MODELISATION="POU_D_E"),
    _F(GROUP_MA="APPUIS", PHENOMENE="MECANIQUE", MODELISATION="DIS_T")))
ACIER = DEFI_MATERIAU(ELAS=_F(E=2.0e11, NU=0.3, RHO=7800.0, AMOR_ALPHA=1.0e-5, AMOR_BETA=2.0))
CHMAT = AFFE_MATERIAU(MAILLAGE=MAIL, AFFE=_F(GROUP_MA="TUBE", MATER=ACIER))
CARA = AFFE_CARA_ELEM(MODELE=MODELE,
    POUTRE=_F(GROUP_MA="TUBE", SECTION="CERCLE", CARA=("R", "EP"), VALE=(0.01, 0.001)),
    DISCRET=(_F(GROUP_MA="APPUIS", CARA="K_T_D_N", VALE=(1.0e5, 1.0e5, 1.0e5)),
             _F(GROUP_MA="APPUIS", CARA="M_T_D_N", VALE=0.0)))
BLOC = AFFE_CHAR_MECA(MODELE=MODELE,
    DDL_IMPO=_F(GROUP_NO="ENDS", DX=0.0, DY=0.0, DZ=0.0, DRX=0.0, DRY=0.0, DRZ=0.0))
FORCE = AFFE_CHAR_MECA(MODELE=MODELE, FORCE_NODALE=_F(GROUP_NO="LOAD", FY=5.0))
ASSEMBLAGE(MODELE=MODELE, CHAM_MATER=CHMAT, CARA_ELEM=CARA, CHARGE=BLOC, NUME_DDL=CO("NUM"),
    MATR_ASSE=(_F(MATRICE=CO("RIGI"), OPTION="RIGI_MECA"),
               _F(MATRICE=CO("MASS"), OPTION="MASS_MECA"),
               _F(MATRICE=CO("AMOR"), OPTION="AMOR_MECA")),
    VECT_ASSE=_F(VECTEUR=CO("F"), OPTION="CHAR_MECA", CHARGE=FORCE))
FIN()
"""


def assembled_model(grid: bool):
    from asterlite.io.export import describe_run
    from asterlite.runtime.session import Session

    folder = Path(tempfile.mkdtemp(prefix="harmonic_sweep_"))
    mesh = grid_mesh(58, 2.0) if grid else line_mesh(3334, 40.0)
    (folder / "m.mail").write_text(mesh)
    (folder / "d.comm").write_text(DECK)
    (folder / "d.export").write_text("F comm d.comm D 1\nF mail m.mail D 20\n")
    session = Session(describe_run(folder / "d.export"), output_dir=folder / "out")
    session.run_all()
    return {name: session.namespace[name] for name in ("RIGI", "MASS", "AMOR", "F", "NUM")}


def physical_sweep(n_freq: int, repeat: int, grid: bool) -> None:
    from asterlite.fem.constraints import eliminate

    start = time.perf_counter()
    model = assembled_model(grid)
    assembled = time.perf_counter() - start
    numbering = model["NUM"]
    b_matrix, _ = numbering.constraint_matrix()

    def prepare():
        elimination = eliminate(b_matrix, np.zeros(b_matrix.shape[0]), numbering.n_dofs)
        return physical.prepare(
            elimination, model["RIGI"].matrix, model["MASS"].matrix, model["AMOR"].matrix
        )

    prepare_seconds, sweep = best_of(repeat, prepare)
    frequencies = np.linspace(1.0, 200.0, n_freq)
    vectors = np.asarray(model["F"].values)[None, :]
    coefficients = np.ones((n_freq, 1), dtype=complex)

    def timed_sweep(backend, symmetric=True, count=n_freq, times=repeat):
        """Best of ``times`` sweeps, each on a fresh sweep (a sweep drops its
        matrices at its last frequency), the preparation not counted."""
        best = None
        for _ in range(times):
            fresh = prepare()
            fresh.backend, fresh.symmetric = backend, symmetric
            started = time.perf_counter()
            out = physical.solve(fresh, frequencies[:count], vectors, coefficients[:count])
            seconds = time.perf_counter() - started
            if best is None or seconds < best[0]:
                best = (seconds, out)
        return best

    kind = "plate-like grid of beams" if grid else "tube line of beams"
    print(
        f"physical basis: {kind}, {numbering.n_dofs} DOFs ({sweep.n_free} free), "
        f"{n_freq} frequencies (deck assembled in {assembled:.1f} s)"
    )
    print(f"  reduction under the boundary conditions  {prepare_seconds:8.3f} s")
    print(f"  solver chosen                            {sweep.backend}")
    backends = ["ldl"] + (["mumps"] if sparse_direct.mumps_available() else [])
    for backend in backends:
        seconds, (u, info) = timed_sweep(backend)
        print(
            f"  sweep, {backend:5s}                             {seconds:8.3f} s "
            f"({seconds / n_freq * 1e3:.2f} ms per frequency; LDLT {info['ldl']}, "
            f"MUMPS {info['mumps']}, refined {info['refined']}, SuperLU {info['superlu']}, "
            f"fill {info.get('fill')})"
        )
    count = min(100, n_freq)
    superlu, _ = timed_sweep("ldl", symmetric=False, count=count, times=1)
    print(
        f"  SuperLU alone                            {superlu / count * 1e3:8.2f} ms per frequency"
    )
    # a check of the last frequency's answer: the residual of the full system
    w = 2 * np.pi * frequencies[-1]
    t = sweep.elimination.T
    a = (
        t.T
        @ (model["RIGI"].matrix - w * w * model["MASS"].matrix + 1j * w * model["AMOR"].matrix)
        @ t
    )
    q = u[-1][sweep.elimination.free]
    residual = np.abs(a @ q - t.T @ vectors[0]).max() / np.abs(vectors).max()
    print(f"  relative residual at {frequencies[-1]:g} Hz           {residual:.1e}")


def main() -> None:
    parser = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    parser.add_argument("--frequencies", type=int, default=1000)
    parser.add_argument("--modes", type=int, default=100)
    parser.add_argument("--repeat", type=int, default=3)
    parser.add_argument("--grid", action="store_true", help="plate-like grid instead of a line")
    parser.add_argument("--skip-physical", action="store_true")
    args = parser.parse_args()
    print(f"load average {os.getloadavg()[0]:.2f}, {os.cpu_count()} cores")
    generalized(args.modes, args.frequencies, args.repeat)
    if not args.skip_physical:
        physical_sweep(args.frequencies, args.repeat, args.grid)


if __name__ == "__main__":
    main()
