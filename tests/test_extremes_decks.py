"""Small decks written on the fly for the extremes suite: a chain of point
masses on ground springs (DIS_T), each free along some global directions,
neighbours coupled by springs, with PLAN_Y shocks on chosen nodes.

Each helper writes a ``.comm``, its ``.mail`` and an ``.export`` into a
folder and returns the export; :func:`run` runs it with
:func:`asterlite.runtime.runner.run_deck`, saving the ``tran_gene`` results
(``results.h5``), and :func:`outputs_are_finite` scans everything written.
"""

from __future__ import annotations

import json
import math
import re
from dataclasses import dataclass, field
from pathlib import Path

import numpy as np

from asterlite.runtime.runner import run_deck

COMPONENTS = ("DX", "DY", "DZ")


@dataclass
class Shock:
    """One DIS_CHOC PLAN_Y occurrence on node ``node`` (1-based).

    ORIG_OBST is the node itself and NORM_OBST is X, so the local y axis
    is global Y: the node touches when |DY| reaches JEU (both sides); local
    z is global Z, the sliding direction."""

    node: int
    jeu: float
    k_n: float
    c_n: float = 0.0
    mu: float = 0.0
    k_t: float = 0.0
    c_t: float | None = None
    name: str | None = None

    def occurrence(self, x: float) -> str:
        name = self.name or f"C{self.node}"
        text = (
            f'_F(RELATION="DIS_CHOC", INTITULE="{name}", GROUP_NO_1="N{self.node}", '
            f"OBSTACLE=OBS, ORIG_OBST=({x!r}, 0.0, 0.0), NORM_OBST=(1.0, 0.0, 0.0), "
            f"JEU={self.jeu!r}, RIGI_NOR={self.k_n!r}"
        )
        if self.c_n:
            text += f", AMOR_NOR={self.c_n!r}"
        if self.mu:
            text += f', RIGI_TAN={self.k_t!r}, FROTTEMENT="COULOMB", COULOMB={self.mu!r}'
            if self.c_t is not None:
                text += f", AMOR_TAN={self.c_t!r}"
        return text + ")"


@dataclass
class Chain:
    """n point masses at x = 0, 1, 2... (nodes N1..Nn)."""

    masses: tuple[float, ...] = (1.0,)
    # ground stiffness of each node along DX, DY, DZ (free directions only matter)
    ground: tuple[tuple[float, float, float], ...] = ((1.0e4, 1.0e4, 1.0e4),)
    coupling: float = 0.0  # spring between neighbours (all three directions)
    free: tuple[str, ...] = ("DY",)
    depl: dict[int, tuple[float, float, float]] = field(default_factory=dict)
    vite: dict[int, tuple[float, float, float]] = field(default_factory=dict)
    shocks: list[Shock] = field(default_factory=list)
    xi: float = 0.0  # AMOR_REDUIT of every mode
    scheme: str = "DIFF_CENTRE"
    scheme_keywords: str = ""  # e.g. ', TOLERANCE=1.0e-8'
    dyna_keywords: str = ""  # more DYNA_VIBRA keywords, e.g. ', TRAITEMENT_NONL="IMPLICITE"'
    pas: float = 1.0e-4
    inst_fin: float = 0.1
    pas_arch: int | None = None  # ARCHIVAGE/PAS_ARCH (every step when None)
    veri_pas: bool = True
    post: bool = True  # RECU_FONCTION + IMPR_FONCTION, POST_DYNA_MODA_T + IMPR_TABLE

    @property
    def n(self) -> int:
        return len(self.masses)


def write(chain: Chain, folder: Path, name: str = "deck") -> Path:
    """Write the deck of ``chain`` into ``folder``; return its .export."""
    folder.mkdir(parents=True, exist_ok=True)
    (folder / f"{name}.mail").write_text(mesh_text(chain.n))
    (folder / f"{name}.comm").write_text(comm_text(chain))
    export = folder / f"{name}.export"
    export.write_text(
        "P time_limit 600\nP memory_limit 1024\nP ncpus 1\n"
        f"F comm {name}.comm D 1\nF mail {name}.mail D 20\n"
    )
    return export


def mesh_text(n: int) -> str:
    lines = [" TITRE", " ASTERLITE EXTREMES - CHAIN", " FINSF", " %", " COOR_3D"]
    lines += [f" N{i + 1} {float(i)!r} 0.0 0.0" for i in range(n)]
    lines += [" FINSF", " %", " POI1"]
    lines += [f" P{i + 1} N{i + 1}" for i in range(n)]
    lines += [" FINSF", " %"]
    if n > 1:
        lines += [" SEG2"] + [f" S{i + 1} N{i + 1} N{i + 2}" for i in range(n - 1)]
        lines += [" FINSF", " %"]
    for i in range(n):
        lines += [" GROUP_NO", f" N{i + 1}", f" N{i + 1}", " FINSF", " %"]
    for i in range(n):
        lines += [" GROUP_MA", f" P{i + 1}", f" P{i + 1}", " FINSF", " %"]
    lines += [" GROUP_MA", " MASSES", " " + " ".join(f"P{i + 1}" for i in range(n)), " FINSF"]
    if n > 1:
        lines += [" %", " GROUP_MA", " RESSORTS"]
        lines += [" " + " ".join(f"S{i + 1}" for i in range(n - 1)), " FINSF"]
    lines += [" %", " FIN", ""]
    return "\n".join(lines)


def _field(chain: Chain, values: dict, name: str, kind: str) -> str:
    occurrences = ", ".join(
        f'_F(GROUP_NO="N{node}", NOM_CMP=("DX", "DY", "DZ"), VALE={tuple(map(float, v))!r})'
        for node, v in sorted(values.items())
    )
    return (
        f'{name}PHY = CREA_CHAMP(OPERATION="AFFE", TYPE_CHAM="NOEU_DEPL_R", MAILLAGE=MAIL, '
        f"AFFE=({occurrences},))\n"
        f"{name}GEN = PROJ_VECT_BASE(BASE=MODES, VECT_ASSE={name}PHY, NUME_DDL_GENE=NUMEGE, "
        f'TYPE_VECT="{kind}")\n'
    )


def comm_text(chain: Chain) -> str:
    n = chain.n
    blocked = [c for c in COMPONENTS if c not in chain.free]
    discrets = [
        f'_F(GROUP_MA="P{i + 1}", CARA="K_T_D_N", VALE={tuple(map(float, chain.ground[i]))!r})'
        for i in range(n)
    ] + [f'_F(GROUP_MA="P{i + 1}", CARA="M_T_D_N", VALE={chain.masses[i]!r})' for i in range(n)]
    if n > 1:
        kc = float(chain.coupling)
        discrets += [
            f'_F(GROUP_MA="RESSORTS", CARA="K_T_D_L", VALE=({kc!r}, {kc!r}, {kc!r}))',
            '_F(GROUP_MA="RESSORTS", CARA="M_T_D_L", VALE=0.0)',
        ]
    n_free = n * len(chain.free)
    text = [
        'DEBUT(CODE="OUI")',
        'MAIL = LIRE_MAILLAGE(FORMAT="ASTER")',
        'MODELE = AFFE_MODELE(MAILLAGE=MAIL, AFFE=_F(TOUT="OUI", PHENOMENE="MECANIQUE", '
        'MODELISATION="DIS_T"))',
        "CARA = AFFE_CARA_ELEM(MODELE=MODELE, DISCRET=(" + ", ".join(discrets) + ",))",
    ]
    if blocked:
        imposed = ", ".join(f"{c}=0.0" for c in blocked)
        text.append(f'BLOCAGE = AFFE_CHAR_MECA(MODELE=MODELE, DDL_IMPO=_F(TOUT="OUI", {imposed}))')
        load = "CHARGE=BLOCAGE, "
    else:
        load = ""
    text += [
        f'RIGIELEM = CALC_MATR_ELEM(MODELE=MODELE, {load}CARA_ELEM=CARA, OPTION="RIGI_MECA")',
        f'MASSELEM = CALC_MATR_ELEM(MODELE=MODELE, {load}CARA_ELEM=CARA, OPTION="MASS_MECA")',
        "NUMEROTA = NUME_DDL(MATR_RIGI=RIGIELEM)",
        "MATRRIGI = ASSE_MATRICE(MATR_ELEM=RIGIELEM, NUME_DDL=NUMEROTA)",
        "MATRMASS = ASSE_MATRICE(MATR_ELEM=MASSELEM, NUME_DDL=NUMEROTA)",
        'MODES = CALC_MODES(MATR_RIGI=MATRRIGI, MATR_MASS=MATRMASS, OPTION="PLUS_PETITE", '
        f"CALC_FREQ=_F(NMAX_FREQ={n_free}))",
        'NUMEGE = NUME_DDL_GENE(BASE=MODES, STOCKAGE="DIAG")',
        "MASSEGEN = PROJ_MATR_BASE(BASE=MODES, NUME_DDL_GENE=NUMEGE, MATR_ASSE=MATRMASS)",
        "RIGIDGEN = PROJ_MATR_BASE(BASE=MODES, NUME_DDL_GENE=NUMEGE, MATR_ASSE=MATRRIGI)",
    ]
    state = []
    if chain.depl:
        text.append(_field(chain, chain.depl, "DEP", "DEPL"))
        state.append("DEPL=DEPGEN")
    if chain.vite:
        text.append(_field(chain, chain.vite, "VIT", "VITE"))
        state.append("VITE=VITGEN")
    keywords = [
        'TYPE_CALCUL="TRAN"',
        'BASE_CALCUL="GENE"',
        f'SCHEMA_TEMPS=_F(SCHEMA="{chain.scheme}"{chain.scheme_keywords})',
        "MATR_MASS=MASSEGEN",
        "MATR_RIGI=RIGIDGEN",
        f"AMOR_MODAL=_F(AMOR_REDUIT={float(chain.xi)!r})",
        "INCREMENT=_F(INST_INIT=0.0, INST_FIN={!r}, PAS={!r}{})".format(
            float(chain.inst_fin), float(chain.pas), "" if chain.veri_pas else ', VERI_PAS="NON"'
        ),
    ]
    if state:
        keywords.append("ETAT_INIT=_F(" + ", ".join(state) + ")")
    if chain.pas_arch is not None:
        keywords.append(f"ARCHIVAGE=_F(PAS_ARCH={chain.pas_arch})")
    if chain.shocks:
        text.append('OBS = DEFI_OBSTACLE(TYPE="PLAN_Y")')
        occurrences = ", ".join(s.occurrence(float(s.node - 1)) for s in chain.shocks)
        keywords.append(f"COMPORTEMENT=({occurrences},)")
    text.append("TRAN = DYNA_VIBRA(" + ", ".join(keywords) + chain.dyna_keywords + ")")
    if chain.post and chain.shocks:
        for k, s in enumerate(chain.shocks):
            text.append(
                f'FN{k} = RECU_FONCTION(RESU_GENE=TRAN, GROUP_NO_CHOC="N{s.node}", '
                'PARA_X="INST", PARA_Y="FN")'
            )
        curves = ", ".join(f"_F(FONCTION=FN{k})" for k in range(len(chain.shocks)))
        text += [
            f'IMPR_FONCTION(FORMAT="TABLEAU", UNITE=30, COURBE=({curves},))',
            'STATS = POST_DYNA_MODA_T(RESU_GENE=TRAN, CHOC=_F(OPTION="IMPACT"))',
            "IMPR_TABLE(TABLE=STATS, UNITE=31)",
        ]
    text.append("FIN()")
    return "\n".join(text) + "\n"


# ----------------------------------------------------------------------------- running


@dataclass
class Outcome:
    report: object
    out: Path
    times: np.ndarray | None = None
    depl: np.ndarray | None = None  # (n, m) generalized
    vite: np.ndarray | None = None
    acce: np.ndarray | None = None
    mass: np.ndarray | None = None  # (m,) generalized mass
    stiffness: np.ndarray | None = None  # (m,) generalized stiffness
    shapes: np.ndarray | None = None  # (dofs, m)
    dof_labels: list[str] | None = None
    shocks: dict[str, dict] = field(default_factory=dict)  # name -> fields and attrs
    scheme: str = ""
    step: float = 0.0

    @property
    def complete(self) -> bool:
        return self.report.status in ("PASS", "NOOK", "DONE")

    def physical(self, label: str) -> np.ndarray:
        """Displacement history of one DOF ("N1 DY")."""
        return self.depl @ self.shapes[self.dof_labels.index(label)]

    def physical_velocity(self, label: str) -> np.ndarray:
        return self.vite @ self.shapes[self.dof_labels.index(label)]

    def velocity(self) -> np.ndarray:
        """Generalized velocities at the archived instants. DIFF_CENTRE
        archives code_aster's v_n, the velocity that carried q_{n-1} to q_n
        (a mid-step velocity: v_{n+1} = v_n + dt a_n, q_{n+1} = q_n + dt
        v_{n+1}); half a step of the archived acceleration brings it to t_n,
        so that the energy below is second-order accurate for every scheme."""
        if self.scheme == "DIFF_CENTRE":
            synchronised = self.vite + 0.5 * self.step * self.acce
            synchronised[0] = self.vite[0]  # the initial state is the deck's own
            return synchronised
        return self.vite

    def penetration(self, name: str) -> np.ndarray:
        """Penetration of a PLAN_Y shock at the archived displacements: |DY|
        of its node (at the obstacle's origin) beyond JEU, 0 when apart. Not
        the archived DYLOC: NEWMARK and TRBDF2 evaluate the shocks, and so
        archive their local quantities, at the previous state."""
        shock = self.shocks[name]
        node_dy = self.physical(f"{shock['node_1']} DY")
        return np.maximum(0.0, np.abs(node_dy) - float(shock["JEU"]))

    def energy(self, contact: bool = True) -> np.ndarray:
        """Mechanical energy at the archived instants: ½ vᵀMv + ½ qᵀKq (modal,
        diagonal) plus, for each shock, the energy stored in its normal
        spring ½ K_N p² (p the penetration)."""
        e = 0.5 * (self.velocity() ** 2 @ self.mass + self.depl**2 @ self.stiffness)
        if contact:
            for name, shock in self.shocks.items():
                e = e + 0.5 * float(shock["RIGI_NOR"]) * self.penetration(name) ** 2
        return e


def run(export: Path, out: Path, **kwargs) -> Outcome:
    """Run the deck, saving its tran_gene results; load them if complete."""
    import h5py

    report = run_deck(export, out, save_results=True, **kwargs)
    outcome = Outcome(report, out)
    store = out / "results.h5"
    if not outcome.complete or not store.exists():
        return outcome
    with h5py.File(store, "r") as f:
        g = f["TRAN"]
        outcome.times = g["times"][()]
        outcome.depl = g["depl"][()]
        outcome.vite = g["vite"][()]
        outcome.acce = g["acce"][()]
        outcome.scheme = str(g.attrs["scheme"])
        outcome.step = float(g.attrs["step"])
        basis = g["basis"]
        outcome.mass = basis["generalized_mass"][()]
        outcome.stiffness = basis["generalized_stiffness"][()]
        outcome.shapes = basis["shapes"][()]
        outcome.dof_labels = list(basis["dof_labels"].asstr()[()])
        if "shocks" in g:
            for name, group in g["shocks"].items():
                data = {key: group[key][()] for key in group}
                data.update({key: group.attrs[key] for key in group.attrs})
                outcome.shocks[str(group.attrs.get("name", name))] = data
    return outcome


NON_FINITE = re.compile(r"(?<![A-Za-z_])[-+]?(nan|inf|infinity)(?![A-Za-z_])", re.IGNORECASE)


def outputs_are_finite(out: Path) -> list[str]:
    """Every non-finite value written under ``out``: HDF5 datasets, JSON
    numbers, and 'nan'/'inf' tokens in the text files (tables, functions,
    message.log). Returns the offending places (empty when clean)."""

    bad = []
    for path in sorted(out.rglob("*")):
        if not path.is_file():
            continue
        if path.suffix == ".h5":
            bad += [f"{path.name}:{name}" for name in h5_non_finite(path)]
        elif path.suffix == ".json":
            constants = []  # NaN, Infinity, -Infinity: not JSON numbers
            json.loads(path.read_text(), parse_constant=constants.append)
            bad += [f"{path.name}: {c}" for c in constants]
        else:
            text = path.read_text(errors="replace")
            for match in NON_FINITE.finditer(text):
                line = text.count("\n", 0, match.start()) + 1
                bad.append(f"{path.name}:{line}: {match.group(0)}")
    return bad


def h5_non_finite(path: Path) -> list[str]:
    """Names of the float datasets of an HDF5 file holding a NaN or an inf."""
    import h5py

    names = []

    def visit(name, node):
        if isinstance(node, h5py.Dataset) and node.dtype.kind in "fc":
            if not np.all(np.isfinite(node[()])):
                names.append(name)

    with h5py.File(path, "r") as f:
        f.visititems(visit)
    return names


def nothing_complete(outcome: Outcome) -> bool:
    """A refused run: exit status 2 and no result saved as if complete."""
    out = outcome.out
    return (
        outcome.report.exit_code == 2
        and not (out / "results.h5").exists()
        and not any(out.glob("fort.*"))
    )


def omega(k: float, m: float) -> float:
    return math.sqrt(k / m)
