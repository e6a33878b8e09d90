# ruff: noqa: E501 (deck text is kept on one line per command, as in the corpus)
"""Dynamic substructuring against the one-piece model (issue 19).

A beam bending in the XY plane (POU_D_E, guided out of plane) is cut in two
equal substructures glued at mid-span by a Craig-Bampton interface. The
coupled frequencies (DEFI_MODELE_GENE ... CALC_MODES on the assembled
generalized matrices) must come down to the one-piece model's as modes are
added to the bases (Craig-Bampton is a Rayleigh-Ritz method: every
frequency is an upper bound, and the full basis spans the whole half-beam,
so it gives the one-piece frequencies to round-off). The same holds for a
free-free beam (two rigid modes, then the elastic ones) and a clamped one.
"""

from __future__ import annotations

import numpy as np
import pytest

from asterlite import api

N_HALF = 8  # elements per substructure
LENGTH = 2.0
GUIDED = "DX=0.0, DZ=0.0, DRX=0.0, DRY=0.0"


def beam_mesh(n_elements: int, length: float) -> str:
    """ASTER mesh: nodes A, N1.., cells S1.., groups A, B (ends), TOUT."""
    names = ["A"] + [f"N{i}" for i in range(1, n_elements + 1)]
    lines = ["TITRE", "beam", "FINSF", "COOR_3D"]
    for k, name in enumerate(names):
        lines.append(f"{name} {k * length / n_elements:.15e} 0.0 0.0")
    lines += ["FINSF", "SEG2"]
    for k in range(n_elements):
        lines.append(f"S{k + 1} {names[k]} {names[k + 1]}")
    lines += ["FINSF", "GROUP_NO", "A", "A", "FINSF", "GROUP_NO", "B", names[-1], "FINSF"]
    lines += ["GROUP_MA", "TOUT"] + [f"S{k + 1}" for k in range(n_elements)] + ["FINSF", "FIN"]
    return "\n".join(lines) + "\n"


FRONT = """
DEBUT()
MAYA = LIRE_MAILLAGE(FORMAT="ASTER")
MAT = DEFI_MATERIAU(ELAS=_F(E=2.0e11, NU=0.3, RHO=7800.0))
CHMAT = AFFE_MATERIAU(MAILLAGE=MAYA, AFFE=_F(TOUT="OUI", MATER=MAT))
MODEL = AFFE_MODELE(MAILLAGE=MAYA, AFFE=_F(TOUT="OUI", PHENOMENE="MECANIQUE", MODELISATION="POU_D_E"))
CARA = AFFE_CARA_ELEM(MODELE=MODEL, POUTRE=_F(GROUP_MA="TOUT", SECTION="CERCLE", CARA="R", VALE=0.02))
GUIDE = AFFE_CHAR_MECA(MODELE=MODEL, DDL_IMPO=_F(TOUT="OUI", {guided}))
"""


def matrices(name: str, loads: str) -> str:
    return f"""
K_{name} = CALC_MATR_ELEM(MODELE=MODEL, CHAM_MATER=CHMAT, CARA_ELEM=CARA, OPTION="RIGI_MECA", CHARGE=({loads}))
M_{name} = CALC_MATR_ELEM(MODELE=MODEL, CHAM_MATER=CHMAT, CARA_ELEM=CARA, OPTION="MASS_MECA", CHARGE=({loads}))
NU_{name} = NUME_DDL(MATR_RIGI=K_{name})
KA_{name} = ASSE_MATRICE(MATR_ELEM=K_{name}, NUME_DDL=NU_{name})
MA_{name} = ASSE_MATRICE(MATR_ELEM=M_{name}, NUME_DDL=NU_{name})
"""


def substructured_deck(nmax: int, clamped: bool, interface: str = "CRAIGB") -> str:
    """Left half: interface B (its right end); right half (the same mesh moved
    by L/2): interface A. Clamped: each half clamped at its outer end."""
    deck = FRONT.format(guided=GUIDED)
    deck += 'JONC_B = AFFE_CHAR_MECA(MODELE=MODEL, DDL_IMPO=_F(GROUP_NO="B", DY=0.0, DRZ=0.0))\n'
    deck += 'JONC_A = AFFE_CHAR_MECA(MODELE=MODEL, DDL_IMPO=_F(GROUP_NO="A", DY=0.0, DRZ=0.0))\n'
    left = "GUIDE, JONC_B" + (", JONC_A" if clamped else "")
    right = "GUIDE, JONC_A" + (", JONC_B" if clamped else "")
    deck += matrices("L", left) + matrices("R", right)
    for side, node, name in (("L", "B", "DROITE"), ("R", "A", "GAUCHE")):
        deck += f"""
MO_{side} = CALC_MODES(MATR_RIGI=KA_{side}, MATR_MASS=MA_{side}, CALC_FREQ=_F(NMAX_FREQ={nmax}))
IN_{side} = DEFI_INTERF_DYNA(NUME_DDL=NU_{side}, INTERFACE=_F(NOM="{name}", TYPE="{interface}",
    GROUP_NO="{node}", MASQUE=("DX", "DZ", "DRX", "DRY")))
BA_{side} = DEFI_BASE_MODALE(CLASSIQUE=_F(INTERF_DYNA=IN_{side}, MODE_MECA=MO_{side}, NMAX_MODE={nmax}))
ME_{side} = MACR_ELEM_DYNA(BASE_MODALE=BA_{side})
"""
    deck += f"""
MODEGE = DEFI_MODELE_GENE(
    SOUS_STRUC=(_F(NOM="COTE1", MACR_ELEM_DYNA=ME_L, ANGL_NAUT=(0.0, 0.0, 0.0), TRANS=(0.0, 0.0, 0.0)),
                _F(NOM="COTE2", MACR_ELEM_DYNA=ME_R, ANGL_NAUT=(0.0, 0.0, 0.0), TRANS=({LENGTH / 2}, 0.0, 0.0))),
    LIAISON=_F(SOUS_STRUC_1="COTE1", INTERFACE_1="DROITE", SOUS_STRUC_2="COTE2", INTERFACE_2="GAUCHE"),
)
NUMEGE = NUME_DDL_GENE(MODELE_GENE=MODEGE)
KGEN = ASSE_MATR_GENE(NUME_DDL_GENE=NUMEGE, OPTION="RIGI_GENE")
MGEN = ASSE_MATR_GENE(NUME_DDL_GENE=NUMEGE, OPTION="MASS_GENE")
RESGEN = CALC_MODES(MATR_RIGI=KGEN, MATR_MASS=MGEN, CALC_FREQ=_F(NMAX_FREQ=5))
FIN()
"""
    return deck


def one_piece_deck(clamped: bool) -> str:
    deck = FRONT.format(guided=GUIDED)
    deck += (
        'ENDS = AFFE_CHAR_MECA(MODELE=MODEL, DDL_IMPO=_F(GROUP_NO=("A", "B"), DY=0.0, DRZ=0.0))\n'
    )
    deck += matrices("W", "GUIDE, ENDS" if clamped else "GUIDE")
    deck += "MODES = CALC_MODES(MATR_RIGI=KA_W, MATR_MASS=MA_W, CALC_FREQ=_F(NMAX_FREQ=5))\nFIN()\n"
    return deck


def run_case(folder, name: str, deck: str, mesh: str):
    folder.mkdir(parents=True, exist_ok=True)
    (folder / f"{name}.comm").write_text(deck)
    (folder / f"{name}.mail").write_text(mesh)
    result = api.run(folder / f"{name}.comm")
    assert result.status == "DONE", result.message
    return result


def frequencies(result, name: str) -> np.ndarray:
    return np.asarray(result.concepts.raw[name].frequencies, dtype=float)


@pytest.fixture(scope="module")
def reference(tmp_path_factory):
    """One-piece frequencies: {clamped: array}."""
    out = {}
    for clamped in (False, True):
        folder = tmp_path_factory.mktemp(f"whole_{clamped}")
        mesh = beam_mesh(2 * N_HALF, LENGTH)
        out[clamped] = frequencies(
            run_case(folder, "whole", one_piece_deck(clamped), mesh), "MODES"
        )
    return out


@pytest.mark.parametrize("clamped", [False, True], ids=["free-free", "clamped"])
def test_craig_bampton_converges_to_the_one_piece_model(tmp_path, reference, clamped):
    mesh = beam_mesh(N_HALF, LENGTH / 2)
    exact = reference[clamped]
    elastic = slice(2, 5) if not clamped else slice(0, 3)
    errors = []
    # a half beam has 2 (N_HALF + 1) in-plane DOFs; the interface holds 2,
    # a clamped end 2 more: with every fixed-interface mode the basis spans it
    full = 2 * (N_HALF + 1) - 2 - (2 if clamped else 0)
    for nmax in (2, 3, 5, full):
        result = run_case(tmp_path / f"n{nmax}", "cut", substructured_deck(nmax, clamped), mesh)
        coupled = frequencies(result, "RESGEN")
        assert np.all(coupled[elastic] >= exact[elastic] * (1 - 1e-9))  # Rayleigh-Ritz bounds
        errors.append(np.abs(coupled[elastic] / exact[elastic] - 1.0))
    errors = np.array(errors)
    print("relative errors of the first 3 elastic frequencies by NMAX_MODE:", errors)
    assert np.all(np.diff(errors, axis=0) <= 1e-12)  # never worse with more modes
    assert errors[0].max() > 1e-3  # two modes per half are visibly coarse
    assert errors[-1].max() < 1e-8  # the full bases give the one-piece model
    if not clamped:  # two rigid-body modes (translation and rotation in the plane)
        assert np.all(np.abs(coupled[:2]) < 1e-3 * exact[2])


def mirrored_deck(nmax: int) -> str:
    """One half (clamped at A, interface B) used twice: the second copy turned
    half a turn about Z (ANGL_NAUT 180) and moved to x = L, so that its A is
    the far clamped end and its B meets the first copy's B at mid-span."""
    deck = FRONT.format(guided=GUIDED)
    deck += (
        'ENDS = AFFE_CHAR_MECA(MODELE=MODEL, DDL_IMPO=_F(GROUP_NO=("A", "B"), DY=0.0, DRZ=0.0))\n'
    )
    deck += matrices("H", "GUIDE, ENDS")
    deck += f"""
MO_H = CALC_MODES(MATR_RIGI=KA_H, MATR_MASS=MA_H, CALC_FREQ=_F(NMAX_FREQ={nmax}))
IN_H = DEFI_INTERF_DYNA(NUME_DDL=NU_H, INTERFACE=_F(NOM="MILIEU", TYPE="CRAIGB",
    GROUP_NO="B", MASQUE=("DX", "DZ", "DRX", "DRY")))
BA_H = DEFI_BASE_MODALE(CLASSIQUE=_F(INTERF_DYNA=IN_H, MODE_MECA=MO_H, NMAX_MODE={nmax}))
ME_H = MACR_ELEM_DYNA(BASE_MODALE=BA_H)
MODEGE = DEFI_MODELE_GENE(
    SOUS_STRUC=(_F(NOM="COTE1", MACR_ELEM_DYNA=ME_H, ANGL_NAUT=(0.0, 0.0, 0.0), TRANS=(0.0, 0.0, 0.0)),
                _F(NOM="COTE2", MACR_ELEM_DYNA=ME_H, ANGL_NAUT=(180.0, 0.0, 0.0), TRANS=({LENGTH}, 0.0, 0.0))),
    LIAISON=_F(SOUS_STRUC_1="COTE1", INTERFACE_1="MILIEU", SOUS_STRUC_2="COTE2", INTERFACE_2="MILIEU"),
)
NUMEGE = NUME_DDL_GENE(MODELE_GENE=MODEGE)
KGEN = ASSE_MATR_GENE(NUME_DDL_GENE=NUMEGE, OPTION="RIGI_GENE")
MGEN = ASSE_MATR_GENE(NUME_DDL_GENE=NUMEGE, OPTION="MASS_GENE")
RESGEN = CALC_MODES(MATR_RIGI=KGEN, MATR_MASS=MGEN, CALC_FREQ=_F(NMAX_FREQ=5))
SQUEL = DEFI_SQUELETTE(MODELE_GENE=MODEGE, SOUS_STRUC=(_F(NOM="COTE1", TOUT="OUI"), _F(NOM="COTE2", TOUT="OUI")))
MODGLO = REST_SOUS_STRUC(RESU_GENE=RESGEN, SQUELETTE=SQUEL, TOUT_ORDRE="OUI")
FIN()
"""
    return deck


def test_a_rotated_substructure_glues_to_its_mirror(tmp_path, reference):
    """ANGL_NAUT turns the interface DOFs (DY changes sign, DRZ does not
    under half a turn about Z) and the interface nodes are paired by
    position: the mirrored halves make the clamped-clamped beam exactly."""
    full = 2 * (N_HALF + 1) - 4
    result = run_case(tmp_path, "mirror", mirrored_deck(full), beam_mesh(N_HALF, LENGTH / 2))
    coupled = frequencies(result, "RESGEN")
    np.testing.assert_allclose(coupled, reference[True][:5], rtol=1e-8)
    # the skeleton: both copies in place, the first symmetric mode symmetric about mid-span
    restored = result.concepts.raw["MODGLO"]
    skeleton = restored.numbering.mesh
    assert skeleton.n_nodes == 2 * (N_HALF + 1)
    assert skeleton.node_names[:2] == ["N1", "N2"]
    np.testing.assert_allclose(np.sort(skeleton.coords[:, 0])[[0, -1]], [0.0, LENGTH])
    dy = {
        skeleton.coords[n, 0]: restored.shapes[i, 0]
        for i, (n, c) in enumerate(restored.numbering.dofs)
        if c == "DY"
    }
    xs = np.array(sorted(dy))
    values = np.array([dy[x] for x in xs])
    np.testing.assert_allclose(values, values[::-1], atol=1e-9 * np.abs(values).max())
