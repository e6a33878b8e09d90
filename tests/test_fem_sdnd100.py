"""The front end of sdnd100a / sdnd100b / sdnd101a, built command by command
from the corpus meshes (skipped when ../shared/aster-corpus is absent)."""

from __future__ import annotations

from math import cos, pi, sqrt

import numpy as np
import pytest

from tests.conftest import CORPUS
from tests.test_fem_support import CO, FakeSession, run

K, M = 1.0e4, 1.0
ANG = cos(pi / 4.0)


def _mesh(session):
    mesh = run(session, "LIRE_MAILLAGE", FORMAT="ASTER", UNITE=20)
    return run(session, "DEFI_GROUP", MAILLAGE=mesh, CREA_GROUP_MA={"NOM": "TOUT", "TOUT": "OUI"})


def _front_end(session, mass=M, ddl_impo=None, liaison=True, freq=15.9):
    mesh = _mesh(session)
    model = run(
        session,
        "AFFE_MODELE",
        MAILLAGE=mesh,
        AFFE={"TOUT": "OUI", "PHENOMENE": "MECANIQUE", "MODELISATION": "DIS_T"},
    )
    cara = run(
        session,
        "AFFE_CARA_ELEM",
        MODELE=model,
        DISCRET=[
            {"GROUP_MA": "TOUT", "CARA": "K_T_D_N", "VALE": (K, K, K)},
            {"GROUP_MA": "TOUT", "CARA": "M_T_D_N", "VALE": mass},
        ],
    )
    char = {"MODELE": model, "DDL_IMPO": ddl_impo or [{"TOUT": "OUI", "DZ": 0.0}]}
    if liaison:
        char["LIAISON_DDL"] = {
            "GROUP_NO": ("NO1", "NO1"),
            "DDL": ("DX", "DY"),
            "COEF_MULT": (ANG, -ANG),
            "COEF_IMPO": 0.0,
        }
    charge = run(session, "AFFE_CHAR_MECA", **char)
    force = run(
        session, "AFFE_CHAR_MECA", MODELE=model, FORCE_NODALE={"GROUP_NO": "NO1", "FX": 1.0}
    )
    common = {"MODELE": model, "CHARGE": charge, "CARA_ELEM": cara}
    rigi = run(session, "CALC_MATR_ELEM", OPTION="RIGI_MECA", **common)
    mass_el = run(session, "CALC_MATR_ELEM", OPTION="MASS_MECA", **common)
    vect = run(session, "CALC_VECT_ELEM", CHARGE=force, OPTION="CHAR_MECA")
    numbering = run(session, "NUME_DDL", MATR_RIGI=rigi)
    k = run(session, "ASSE_MATRICE", MATR_ELEM=rigi, NUME_DDL=numbering)
    m = run(session, "ASSE_MATRICE", MATR_ELEM=mass_el, NUME_DDL=numbering)
    f = run(session, "ASSE_VECTEUR", VECT_ELEM=vect, NUME_DDL=numbering)
    modes = run(
        session,
        "CALC_MODES",
        MATR_RIGI=k,
        MATR_MASS=m,
        OPTION="PROCHE",
        CALC_FREQ={"FREQ": (freq,), "NMAX_FREQ": 1},
    )
    return mesh, numbering, k, m, f, modes


@pytest.fixture
def sdnd100a():
    path = CORPUS / "sdnd100a" / "sdnd100a.mail"
    if not path.exists():
        pytest.skip("../shared/aster-corpus is not available")
    return FakeSession({20: path})


def test_sdnd100a_front_end(sdnd100a):
    mesh, numbering, k, m, f, modes = _front_end(sdnd100a)
    assert mesh.cell_groups["TOUT"].tolist() == [0]
    assert numbering.dofs == [(0, "DX"), (0, "DY"), (0, "DZ")]
    assert len(numbering.relations) == 2
    np.testing.assert_allclose(k.matrix.toarray(), K * np.eye(3))
    np.testing.assert_allclose(m.matrix.toarray(), M * np.eye(3))
    np.testing.assert_allclose(f.values, [1.0, 0.0, 0.0])
    # one mode: DX = DY, DZ = 0; largest component normalised to +1
    assert modes.n_modes == 1
    np.testing.assert_allclose(modes.frequencies, [sqrt(K / M) / (2 * pi)], rtol=1e-12)
    np.testing.assert_allclose(modes.shapes[:, 0], [1.0, 1.0, 0.0], atol=1e-12)
    np.testing.assert_allclose(modes.generalized_mass, [2 * M])
    np.testing.assert_allclose(modes.generalized_stiffness, [2 * K])
    np.testing.assert_allclose(modes.shape_at("NO1", "DY"), [1.0])
    np.testing.assert_allclose(modes.shapes_at(["NO1", "NO1"], ["DX", "DRX"]), [[1.0], [0.0]])

    u1 = 0.85e-3 * ANG
    depl = run(
        sdnd100a,
        "CREA_CHAMP",
        OPERATION="AFFE",
        PROL_ZERO="OUI",
        TYPE_CHAM="NOEU_DEPL_R",
        MAILLAGE=mesh,
        CHAM_NO=f,
        AFFE={"TOUT": "OUI", "NOM_CMP": ("DX", "DY"), "VALE": (u1, u1)},
    )
    np.testing.assert_allclose(depl.values, [u1, u1, 0.0])
    numegen = run(sdnd100a, "NUME_DDL_GENE", BASE=modes, STOCKAGE="DIAG")
    q0 = run(
        sdnd100a,
        "PROJ_VECT_BASE",
        BASE=modes,
        VECT_ASSE=depl,
        NUME_DDL_GENE=numegen,
        TYPE_VECT="DEPL",
    )
    np.testing.assert_allclose(q0.values, [u1])
    mgen = run(sdnd100a, "PROJ_MATR_BASE", BASE=modes, NUME_DDL_GENE=numegen, MATR_ASSE=m)
    kgen = run(sdnd100a, "PROJ_MATR_BASE", BASE=modes, NUME_DDL_GENE=numegen, MATR_ASSE=k)
    np.testing.assert_allclose(mgen.matrix, [[2 * M]])
    np.testing.assert_allclose(kgen.matrix, [[2 * K]])
    fgen = run(sdnd100a, "PROJ_VECT_BASE", BASE=modes, VECT_ASSE=f, NUME_DDL_GENE=numegen)
    np.testing.assert_allclose(fgen.values, [1.0])


def test_sdnd100b_proj_base_binds_outputs():
    path = CORPUS / "sdnd100b" / "sdnd100b.mail"
    if not path.exists():
        pytest.skip("../shared/aster-corpus is not available")
    session = FakeSession({20: path})
    mesh, numbering, k, m, f, modes = _front_end(
        session,
        ddl_impo=[{"TOUT": "OUI", "DZ": 0.0}, {"GROUP_NO": "NO2", "DX": 0.0, "DY": 0.0}],
        freq=15.0,
    )
    assert numbering.n_dofs == 6
    assert modes.n_modes == 1
    np.testing.assert_allclose(modes.frequencies, [sqrt(K / M) / (2 * pi)], rtol=1e-12)
    np.testing.assert_allclose(modes.shapes[:, 0], [1, 1, 0, 0, 0, 0], atol=1e-12)
    depl = run(
        session,
        "CREA_CHAMP",
        OPERATION="AFFE",
        PROL_ZERO="OUI",
        TYPE_CHAM="NOEU_DEPL_R",
        MAILLAGE=mesh,
        CHAM_NO=f,
        AFFE={"TOUT": "OUI", "NOM_CMP": ("DX", "DY"), "VALE": (1e-3, 1e-3)},
    )
    result = run(
        session,
        "PROJ_BASE",
        BASE=modes,
        STOCKAGE="DIAG",
        MATR_ASSE_GENE=[
            {"MATRICE": CO("MASSEGEN"), "MATR_ASSE": m},
            {"MATRICE": CO("RIGIDGEN"), "MATR_ASSE": k},
        ],
        VECT_ASSE_GENE={"VECTEUR": CO("DEPINI"), "TYPE_VECT": "DEPL", "VECT_ASSE": depl},
    )
    assert result is None
    np.testing.assert_allclose(session.bound["MASSEGEN"].matrix, [[2 * M]])
    np.testing.assert_allclose(session.bound["RIGIDGEN"].matrix, [[2 * K]])
    # both nodes carry 1e-3 on DX, DY but NO2's part is outside the basis: the
    # Euclidean fit keeps NO1's part
    np.testing.assert_allclose(session.bound["DEPINI"].values, [1e-3])


def test_sdnd101a_velocity_projection():
    path = CORPUS / "sdnd101a" / "sdnd101a.mail"
    if not path.exists():
        pytest.skip("../shared/aster-corpus is not available")
    session = FakeSession({20: path})
    mesh, numbering, k, m, f, modes = _front_end(
        session,
        mass=100.0,
        ddl_impo=[{"TOUT": "OUI", "DY": 0.0, "DZ": 0.0}],
        liaison=False,
        freq=1.5,
    )
    np.testing.assert_allclose(modes.frequencies, [sqrt(K / 100.0) / (2 * pi)], rtol=1e-12)
    np.testing.assert_allclose(modes.shapes[:, 0], [1.0, 0.0, 0.0])
    vite = run(
        session,
        "CREA_CHAMP",
        OPERATION="AFFE",
        PROL_ZERO="OUI",
        TYPE_CHAM="NOEU_DEPL_R",
        MAILLAGE=mesh,
        CHAM_NO=f,
        AFFE={"TOUT": "OUI", "NOM_CMP": "DX", "VALE": 1.0},
    )
    numegen = run(session, "NUME_DDL_GENE", BASE=modes, STOCKAGE="DIAG")
    v0 = run(
        session,
        "PROJ_VECT_BASE",
        BASE=modes,
        VECT_ASSE=vite,
        NUME_DDL_GENE=numegen,
        TYPE_VECT="VITE",
    )
    np.testing.assert_allclose(v0.values, [1.0])
    assert v0.kind == "VITE"


def test_unknown_group_is_a_located_error(sdnd100a):
    from asterlite.errors import CommandError

    mesh = _mesh(sdnd100a)
    with pytest.raises(CommandError, match="no cell group 'NOPE'"):
        run(
            sdnd100a,
            "AFFE_MODELE",
            MAILLAGE=mesh,
            AFFE={"GROUP_MA": "NOPE", "PHENOMENE": "MECANIQUE", "MODELISATION": "DIS_T"},
        )
