"""Front end and modal solve of a large model, through a real deck.

A chain of N nodes (2D_DIS_T: DX and DY on each node, 2·N DOFs) of springs
and point masses, both ends fixed, written as an ASTER mesh and a deck;
`asterlite run` assembles it and extracts the 50 lowest modes
(CALC_MODES PLUS_PETITE: sparse shift-invert). Prints the time of each
command and the error of the frequencies against the analytic chain.

    python benchmarks/modal_large.py [N_NODES]     # default 50 000 -> 100 000 DOFs
"""

from __future__ import annotations

import sys
import tempfile
import time
from pathlib import Path

import numpy as np

K_X, K_Y, MASS = 1.0e4, 4.0e4, 2.0


def write_mesh(path: Path, n_nodes: int) -> None:
    x = np.linspace(0.0, 1.0, n_nodes)
    lines = [" TITRE", " CHAIN", " FINSF", " %", " COOR_3D"]
    lines += [f" N{i + 1} {xi:.12E} 0.0 0.0" for i, xi in enumerate(x)]
    lines += [" FINSF", " %", " SEG2"]
    lines += [f" S{i + 1} N{i + 1} N{i + 2}" for i in range(n_nodes - 1)]
    lines += [" FINSF", " %", " POI1"]
    lines += [f" P{i + 1} N{i + 1}" for i in range(n_nodes)]
    lines += [" FINSF", " %", " GROUP_MA", " RESSORTS"]
    lines += [f" S{i + 1}" for i in range(n_nodes - 1)]
    lines += [" FINSF", " %", " GROUP_MA", " MASSES"]
    lines += [f" P{i + 1}" for i in range(n_nodes)]
    lines += [" FINSF", " %", " GROUP_NO", " ENDS", " N1", f" N{n_nodes}", " FINSF", " %", " FIN"]
    path.write_text("\n".join(lines) + "\n")


DECK = f"""
DEBUT()
MAIL = LIRE_MAILLAGE(FORMAT="ASTER")
MODELE = AFFE_MODELE(MAILLAGE=MAIL,
                     AFFE=_F(TOUT="OUI", PHENOMENE="MECANIQUE", MODELISATION="2D_DIS_T"))
CARA = AFFE_CARA_ELEM(MODELE=MODELE, DISCRET_2D=(
    _F(GROUP_MA="RESSORTS", CARA="K_T_D_L", VALE=({K_X}, {K_Y})),
    _F(GROUP_MA="MASSES", CARA="M_T_D_N", VALE={MASS}),
))
BLOC = AFFE_CHAR_MECA(MODELE=MODELE, DDL_IMPO=_F(GROUP_NO="ENDS", DX=0.0, DY=0.0))
RIGIEL = CALC_MATR_ELEM(MODELE=MODELE, CARA_ELEM=CARA, CHARGE=BLOC, OPTION="RIGI_MECA")
MASSEL = CALC_MATR_ELEM(MODELE=MODELE, CARA_ELEM=CARA, CHARGE=BLOC, OPTION="MASS_MECA")
NUME = NUME_DDL(MATR_RIGI=RIGIEL)
RIGI = ASSE_MATRICE(MATR_ELEM=RIGIEL, NUME_DDL=NUME)
MASS = ASSE_MATRICE(MATR_ELEM=MASSEL, NUME_DDL=NUME)
MODES = CALC_MODES(MATR_RIGI=RIGI, MATR_MASS=MASS, OPTION="PLUS_PETITE",
                   CALC_FREQ=_F(NMAX_FREQ=50))
FIN()
"""


def analytic_frequencies(n_nodes: int, count: int = 50) -> np.ndarray:
    free = n_nodes - 2
    j = np.arange(1, count + 1)
    base = 2 * np.sqrt(K_X / MASS) * np.sin(j * np.pi / (2 * (free + 1))) / (2 * np.pi)
    return np.sort(np.concatenate([base, np.sqrt(K_Y / K_X) * base]))[:count]


def main(n_nodes: int = 50_000) -> None:
    from asterlite.io.export import describe_run
    from asterlite.runtime.session import Session

    with tempfile.TemporaryDirectory() as tmp:
        folder = Path(tmp)
        write_mesh(folder / "chain.mail", n_nodes)
        (folder / "chain.comm").write_text(DECK)
        session = Session(describe_run(folder / "chain.comm"), output_dir=folder / "out")
        start = time.perf_counter()
        session.run_all()
        wall = time.perf_counter() - start
    print(f"chain of {n_nodes} nodes: {2 * n_nodes} DOFs, deck wall time {wall:.2f} s")
    for timing in session.timings:
        print(f"  {timing.command:<16} {timing.seconds:8.3f} s")
    found = np.sort(session.namespace["MODES"].frequencies)
    expected = analytic_frequencies(n_nodes, len(found))
    error = np.max(np.abs(found - expected) / expected)
    print(f"  {len(found)} modes, max relative error against the analytic chain: {error:.1e}")


if __name__ == "__main__":
    main(int(sys.argv[1]) if len(sys.argv) > 1 else 50_000)
