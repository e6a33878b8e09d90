"""Front end and modal solve of a 3D solid model, through a real deck.

A clamped bar 10 x 1 x 1 cut into NX x NY x NZ HEXA8 cells (3 DOFs per node),
written as an ASTER mesh and a deck; `asterlite run` assembles it
(MODELISATION='3D') and extracts the lowest modes (CALC_MODES PLUS_PETITE).
Prints the time of each command and the first frequency against
Euler-Bernoulli beam theory.

    python benchmarks/solid_modal.py NX NY NZ [N_MODES]
    python benchmarks/solid_modal.py 100 18 17 50     # 103 626 DOFs
    python benchmarks/solid_modal.py 100 18 17 0      # the same, front end only
"""

from __future__ import annotations

import sys
import tempfile
import time
from pathlib import Path

import numpy as np

E, NU, RHO = 2.1e11, 0.3, 7800.0
SIZE = (10.0, 1.0, 1.0)


def write_mesh(path: Path, n: tuple[int, int, int]) -> int:
    axes = [np.linspace(0.0, s, k + 1) for s, k in zip(SIZE, n, strict=True)]
    grid = np.stack(np.meshgrid(*axes, indexing="ij"), axis=-1).reshape(-1, 3)
    index = np.arange(len(grid)).reshape(n[0] + 1, n[1] + 1, n[2] + 1) + 1
    i, j, k = (a.ravel() for a in np.meshgrid(*(np.arange(m) for m in n), indexing="ij"))
    corners = [(0, 0, 0), (1, 0, 0), (1, 1, 0), (0, 1, 0)]
    corners += [(0, 0, 1), (1, 0, 1), (1, 1, 1), (0, 1, 1)]
    cells = np.stack([index[i + a, j + b, k + c] for a, b, c in corners], axis=1)
    lines = ["TITRE", "BAR", "FINSF", "COOR_3D"]
    lines += [f"N{p + 1} {x:.12E} {y:.12E} {z:.12E}" for p, (x, y, z) in enumerate(grid)]
    lines += ["FINSF", "HEXA8"]
    lines += [f"M{c + 1} " + " ".join(f"N{v}" for v in cell) for c, cell in enumerate(cells)]
    lines += ["FINSF", "GROUP_NO", "CLAMP"]
    lines += [f"N{v}" for v in index[0].ravel()]
    lines += ["FINSF", "FIN"]
    path.write_text("\n".join(lines) + "\n")
    return 3 * len(grid)


DECK = """DEBUT()
mesh = LIRE_MAILLAGE(FORMAT="ASTER", UNITE=20)
model = AFFE_MODELE(MAILLAGE=mesh, AFFE=_F(TOUT="OUI", PHENOMENE="MECANIQUE", MODELISATION="3D"))
steel = DEFI_MATERIAU(ELAS=_F(E={E}, NU={NU}, RHO={RHO}))
chmat = AFFE_MATERIAU(MAILLAGE=mesh, AFFE=_F(TOUT="OUI", MATER=steel))
clamp = AFFE_CHAR_MECA(MODELE=model, DDL_IMPO=_F(GROUP_NO="CLAMP", DX=0.0, DY=0.0, DZ=0.0))
ASSEMBLAGE(MODELE=model, CHAM_MATER=chmat, CHARGE=clamp, NUME_DDL=CO("nume"),
           MATR_ASSE=(_F(MATRICE=CO("rigi"), OPTION="RIGI_MECA"),
                      _F(MATRICE=CO("mass"), OPTION="MASS_MECA")))
modes = CALC_MODES(MATR_RIGI=rigi, MATR_MASS=mass, OPTION="PLUS_PETITE",
                   CALC_FREQ=_F(NMAX_FREQ={N_MODES}))
FIN()
"""


def main() -> None:
    from asterlite.runtime.runner import run_deck

    n = tuple(int(a) for a in sys.argv[1:4]) if len(sys.argv) >= 4 else (40, 8, 8)
    n_modes = int(sys.argv[4]) if len(sys.argv) > 4 else 50
    with tempfile.TemporaryDirectory() as tmp:
        folder = Path(tmp)
        dofs = write_mesh(folder / "bar.mail", n)
        deck = DECK.format(E=E, NU=NU, RHO=RHO, N_MODES=n_modes)
        if n_modes == 0:  # the front end alone
            deck = deck[: deck.index("modes = ")] + "FIN()\n"
        (folder / "bar.comm").write_text(deck)
        (folder / "bar.export").write_text("F comm bar.comm D 1\nF mail bar.mail D 20\n")
        start = time.perf_counter()
        report = run_deck(folder / "bar.export", folder / "out")
        total = time.perf_counter() - start
        log = (folder / "out" / "message.log").read_text()
    print(f"{n[0]} x {n[1]} x {n[2]} HEXA8, {dofs} DOFs: {report.status}, whole run {total:.1f} s")
    for line in log.splitlines():
        if line.startswith("  ") and " s" in line and "line" in line:
            print(line)
    first = next((ln for ln in log.splitlines() if ln.strip().startswith("mode    1")), "")
    inertia, area = SIZE[1] ** 4 / 12, SIZE[1] * SIZE[2]
    beam = 1.875104**2 / (2 * np.pi) * np.sqrt(E * inertia / (RHO * area * SIZE[0] ** 4))
    print(f"first mode: {first.strip()}  (Euler-Bernoulli: {beam:.6e} Hz)")


if __name__ == "__main__":
    main()
