"""AFFE_CHAR_MECA_F (values as functions of the geometry), FORCE_POUTRE varying
linearly along each cell (code_aster's ptfop1), and CALC_CHAMP's EXCIT taking
the distributed loads off the beam internal forces, against exact beam
solutions."""

from __future__ import annotations

import numpy as np
import pytest

from asterlite.concepts.function import Formula
from asterlite.concepts.transient import DynaTrans
from asterlite.errors import UnsupportedError
from asterlite.fem.constraints import eliminate
from asterlite.fem.loads import load_history, load_terms
from tests.test_fem_structures import INERTIA, E, beam_model, line_mesh
from tests.test_fem_support import FakeSession, run

LENGTH, N_EL, Q0 = 2.0, 8, 1500.0
CLAMPED = {"GROUP_NO": ("A", "B"), "BLOCAGE": ("DEPLACEMENT", "ROTATION")}


def _triangular(session, model):
    ramp = Formula(VALE=f"{Q0} * X / {LENGTH}", NOM_PARA=("X",))
    return run(session, "AFFE_CHAR_MECA_F", MODELE=model, FORCE_POUTRE={"TOUT": "OUI", "FY": ramp})


def _static(session, model, field, cara, load):
    fixed = run(session, "AFFE_CHAR_MECA", MODELE=model, DDL_IMPO=CLAMPED)
    common = {"MODELE": model, "CHAM_MATER": field, "CARA_ELEM": cara}
    rigi = run(session, "CALC_MATR_ELEM", OPTION="RIGI_MECA", CHARGE=(fixed,), **common)
    numbering = run(session, "NUME_DDL", MATR_RIGI=(rigi,))
    k = run(session, "ASSE_MATRICE", MATR_ELEM=(rigi,), NUME_DDL=numbering)
    vect = run(session, "CALC_VECT_ELEM", OPTION="CHAR_MECA", CHARGE=(load,), **common)
    f = run(session, "ASSE_VECTEUR", VECT_ELEM=(vect,), NUME_DDL=numbering)
    b, rhs = numbering.constraint_matrix()
    elim = eliminate(b, rhs, numbering.n_dofs)
    q = np.linalg.solve(elim.reduce(k.matrix).toarray(), elim.T.T @ f.values)
    return numbering, elim.T @ q + elim.u0


def _exact_triangular_deflection(x):
    """EI w'''' = Q0 x / L, w = w' = 0 at both ends."""
    ei = E * INERTIA
    # w = Q0 x^5 / (120 EI L) + c3 x^3 + c2 x^2
    a = np.array([[LENGTH**3, LENGTH**2], [3 * LENGTH**2, 2 * LENGTH]])
    rhs = -np.array([Q0 * LENGTH**4 / (120 * ei), 5 * Q0 * LENGTH**3 / (120 * ei)])
    c3, c2 = np.linalg.solve(a, rhs)
    return Q0 * x**5 / (120 * ei * LENGTH) + c3 * x**3 + c2 * x**2


def test_linear_line_load_resultants_and_deflection():
    session = FakeSession()
    model, field, cara = beam_model(session, line_mesh(N_EL, LENGTH))
    load = _triangular(session, model)
    terms = load_terms(load, cara)
    x = model.mesh.coords[:, 0]
    force = sum(v for n, c, v in terms if c == "DY")
    moment = sum(v * x[n] for n, c, v in terms if c == "DY") + sum(
        v for _, c, v in terms if c == "DRZ"
    )
    assert force == pytest.approx(Q0 * LENGTH / 2, rel=1e-13)
    assert moment == pytest.approx(Q0 * LENGTH**2 / 3, rel=1e-13)
    numbering, u = _static(session, model, field, cara, load)
    for node in (2, 4, 5):
        dy = numbering.dof_indices([node], "DY")[0]
        assert u[dy] == pytest.approx(_exact_triangular_deflection(x[node]), rel=1e-9)


def test_forces_of_time_are_a_history_and_nodal_values_are_evaluated():
    session = FakeSession()
    model, _, _ = beam_model(session, line_mesh(4, 1.0))
    of_time = Formula(VALE="2 * INST", NOM_PARA=("INST",))
    timed = run(
        session, "AFFE_CHAR_MECA_F", MODELE=model, FORCE_NODALE={"GROUP_NO": "B", "FX": of_time}
    )
    assert timed.nodal_forces == []
    nodes, components, values = load_history(timed, None)(np.array([0.0, 0.5, 2.0]))
    assert nodes.tolist() == [4] and components == ["DX"]
    assert values[:, 0] == pytest.approx([0.0, 1.0, 4.0])
    with pytest.raises(UnsupportedError, match="INST"):
        load_terms(timed)  # where a fixed vector is taken
    of_x = Formula(VALE="3 * X + 1", NOM_PARA=("X",))
    load = run(
        session,
        "AFFE_CHAR_MECA_F",
        MODELE=model,
        DDL_IMPO={"TOUT": "OUI", "DY": of_x},
        FORCE_NODALE={"GROUP_NO": "B", "MZ": of_x},
    )
    assert [r.rhs for r in load.relations] == pytest.approx([1.0, 1.75, 2.5, 3.25, 4.0])
    assert load.nodal_forces == [(4, "DRZ", 4.0)]


def test_calc_champ_excit_takes_the_line_load_off_the_internal_forces():
    session = FakeSession()
    model, field, cara = beam_model(session, line_mesh(N_EL, LENGTH))
    q = 800.0
    load = run(session, "AFFE_CHAR_MECA", MODELE=model, FORCE_POUTRE={"TOUT": "OUI", "FY": -q})
    numbering, u = _static(session, model, field, cara, load)
    ramp = run(session, "DEFI_FONCTION", NOM_PARA="INST", VALE=(0.0, 0.0, 1.0, 1.0))
    fields = {"DEPL": np.vstack([0 * u, u]), "ACCE": np.zeros((2, u.size))}
    result = DynaTrans(numbering, np.array([0.0, 1.0]), np.array([1, 2]), fields)
    out = run(
        session,
        "CALC_CHAMP",
        RESULTAT=result,
        CONTRAINTE=("EFGE_ELNO", "SIEF_ELNO"),
        EXCIT={"CHARGE": load, "FONC_MULT": ramp},
    )
    efge = out.element_fields["EFGE_ELNO"]
    mfz = efge.components.index("MFZ")
    vy = efge.components.index("VY")
    # element 1 starts at the clamped end A, element N_EL/2 ends at midspan
    assert abs(efge.values[1, 0, 0, mfz]) == pytest.approx(q * LENGTH**2 / 12, rel=1e-9)
    assert abs(efge.values[1, 0, 0, vy]) == pytest.approx(q * LENGTH / 2, rel=1e-9)
    middle = N_EL // 2 - 1
    assert abs(efge.values[1, middle, 1, mfz]) == pytest.approx(q * LENGTH**2 / 24, rel=1e-9)
    assert abs(efge.values[1, middle, 1, vy]) < 1e-9 * q * LENGTH
    np.testing.assert_allclose(efge.values[0], 0.0, atol=1e-12)
    # SIEF_ELNO keeps K u (code_aster gives its option no load)
    sief = out.element_fields["SIEF_ELNO"]
    assert abs(sief.values[1, middle, 1, mfz] - efge.values[1, middle, 1, mfz]) > 1e-3 * q


def test_onde_plane_is_kept_as_a_wave_and_refused_as_a_vector():
    from asterlite.concepts.assembly import Model
    from tests.solid_meshes import box_mesh, with_side_faces

    mesh = with_side_faces(box_mesh("HEXA8", n=(1, 1, 1)), {"BASE": (2, 0.0)})
    modelisation = {c: "3D" for c in range(mesh.n_cells)}
    modelisation.update({int(c): "3D_ABSO" for c in mesh.cell_groups["BASE"]})
    model = Model(mesh=mesh, cell_modelisation=modelisation)
    signal = Formula(VALE="sin(INST)", NOM_PARA=("INST",))
    load = run(
        FakeSession(),
        "AFFE_CHAR_MECA_F",
        MODELE=model,
        ONDE_PLANE={
            "DIRECTION": (0.0, 0.0, 1.0),
            "TYPE_ONDE": "P",
            "FONC_SIGNAL": signal,
            "COOR_SOURCE": (0.0, 0.0, -1.0),
            "GROUP_MA": "BASE",
        },
    )
    (item,) = load.extra["ONDE_PLANE"]
    assert item["CELLS"].tolist() == mesh.cell_groups["BASE"].tolist()
    assert item["WAVE"].kind == "P" and item["WAVE"].source.tolist() == [0.0, 0.0, -1.0]
    with pytest.raises(UnsupportedError, match="ONDE_PLANE"):
        load_terms(load)


def test_two_onde_plane_occurrences_add_their_histories():
    from asterlite.concepts.assembly import Material, MaterialField, Model
    from asterlite.fem.loads import load_history
    from asterlite.fem.plane_wave import plane_wave_history
    from tests.solid_meshes import box_mesh, with_side_faces

    mesh = with_side_faces(box_mesh("HEXA8", n=(1, 1, 1)), {"BASE": (2, 0.0)})
    modelisation = {c: "3D" for c in range(mesh.n_cells)}
    modelisation.update({int(c): "3D_ABSO" for c in mesh.cell_groups["BASE"]})
    model = Model(mesh=mesh, cell_modelisation=modelisation)
    field = MaterialField(
        mesh=mesh,
        cell_material={
            c: Material(behaviours={"ELAS": {"E": 3.0e10, "NU": 0.25, "RHO": 2450.0}})
            for c in range(mesh.n_cells)
        },
    )
    signal = Formula(VALE="sin(40*INST)", NOM_PARA=("INST",))
    waves = [
        {
            "DIRECTION": (0.0, 0.0, 1.0),
            "TYPE_ONDE": kind,
            "FONC_SIGNAL": signal,
            "COOR_SOURCE": (0.0, 0.0, -1.0),
            "GROUP_MA": "BASE",
        }
        for kind in ("P", "SH")
    ]
    load = run(FakeSession(), "AFFE_CHAR_MECA_F", MODELE=model, ONDE_PLANE=waves)
    times = np.linspace(0.0, 0.1, 11)
    nodes, comps, values = load_history(load, field)(times)
    total = {}
    for item in load.extra["ONDE_PLANE"]:
        n, c, v = plane_wave_history(model, field, item["CELLS"], item["WAVE"], times)
        for k, key in enumerate(zip(n.tolist(), c, strict=True)):
            total[key] = total.get(key, 0.0) + v[:, k]
    summed = {}
    for k, key in enumerate(zip(nodes.tolist(), comps, strict=True)):
        summed[key] = summed.get(key, 0.0) + values[:, k]
    assert len(load.extra["ONDE_PLANE"]) == 2
    assert summed.keys() == total.keys()
    assert all(np.allclose(summed[key], total[key]) for key in total)
    # the SH wave moves the base sideways, the P wave up: both are there
    horizontal = sum(np.abs(v).max() for (n, c), v in summed.items() if c != "DZ")
    vertical = sum(np.abs(v).max() for (n, c), v in summed.items() if c == "DZ")
    assert horizontal > 0.0 and vertical > 0.0
