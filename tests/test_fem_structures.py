"""Beams, bars and materials through the real front-end commands: analytic
frequencies, Timoshenko shear, Rayleigh damping, loads, internal forces,
mass properties, and the mesh commands the beam decks use."""

from __future__ import annotations

import numpy as np
import pytest
import scipy.linalg as sla

from asterlite.concepts.assembly import DofNumbering, MaterialField
from asterlite.concepts.mesh import Mesh
from asterlite.concepts.transient import DynaTrans
from asterlite.errors import CommandError
from asterlite.fem.constraints import eliminate
from tests.test_fem_support import CO, FakeSession, run

E, NU, RHO = 2.0e11, 0.3, 7800.0
R = 0.02
AREA = np.pi * R**2
INERTIA = np.pi * R**4 / 4
CANTILEVER = np.array([1.875104069, 4.694091133, 7.854757438, 10.99554073, 14.13716839])
CLAMPED = np.array([4.730040745, 7.853204624, 10.99560784, 14.13716549, 17.27875966])


def line_mesh(n_el: int, length: float = 1.0, direction=(1.0, 0.0, 0.0)) -> Mesh:
    """Nodes N1..N(n+1) along ``direction``, SEG2 cells M1..Mn in group POUTRE,
    node groups A (first) and B (last)."""
    d = np.asarray(direction, float) / np.linalg.norm(direction)
    coords = np.linspace(0.0, length, n_el + 1)[:, None] * d
    return Mesh(
        coords=coords,
        node_names=[f"N{i + 1}" for i in range(n_el + 1)],
        cell_names=[f"M{i + 1}" for i in range(n_el)],
        cell_types=["SEG2"] * n_el,
        cell_nodes=[(i, i + 1) for i in range(n_el)],
        node_groups={"A": np.array([0]), "B": np.array([n_el])},
        cell_groups={"POUTRE": np.arange(n_el)},
    )


def beam_model(session, mesh, modelisation="POU_D_E", section=("CERCLE", ("R",), (R,)), **elas):
    material = run(session, "DEFI_MATERIAU", ELAS={"E": E, "NU": NU, "RHO": RHO, **elas})
    model = run(
        session,
        "AFFE_MODELE",
        MAILLAGE=mesh,
        AFFE={"GROUP_MA": ("POUTRE",), "PHENOMENE": "MECANIQUE", "MODELISATION": modelisation},
    )
    field = run(session, "AFFE_MATERIAU", MAILLAGE=mesh, AFFE={"TOUT": "OUI", "MATER": material})
    kind, cara, vale = section
    key = "BARRE" if "BARRE" in modelisation else "POUTRE"
    cara_elem = run(
        session,
        "AFFE_CARA_ELEM",
        MODELE=model,
        **{key: {"GROUP_MA": ("POUTRE",), "SECTION": kind, "CARA": cara, "VALE": vale}},
    )
    return model, field, cara_elem


def assembled(session, model, field, cara, ddl_impo, options=("RIGI_MECA", "MASS_MECA")):
    charge = run(session, "AFFE_CHAR_MECA", MODELE=model, DDL_IMPO=ddl_impo)
    run(
        session,
        "ASSEMBLAGE",
        MODELE=model,
        CHAM_MATER=field,
        CARA_ELEM=cara,
        CHARGE=charge,
        NUME_DDL=CO("NUM"),
        MATR_ASSE=[{"MATRICE": CO(o), "OPTION": o} for o in options],
    )
    return session.bound


def constrained_frequencies(k, m, count=5):
    b, rhs = k.numbering.constraint_matrix()
    elim = eliminate(b, rhs, k.numbering.n_dofs)
    kr = elim.reduce(k.matrix).toarray()
    mr = elim.reduce(m.matrix).toarray()
    w2 = sla.eigh(kr, mr, eigvals_only=True, subset_by_index=(0, count - 1))
    return np.sqrt(np.abs(w2)) / (2 * np.pi)


PLANE_XY = {"TOUT": "OUI", "DZ": 0.0, "DRX": 0.0, "DRY": 0.0, "DX": 0.0}


def bending_frequencies(beta_l, length=1.0):
    return beta_l**2 / (2 * np.pi * length**2) * np.sqrt(E * INERTIA / (RHO * AREA))


@pytest.mark.parametrize(
    ("ends", "reference"),
    [
        ([{"GROUP_NO": ("A",), "LIAISON": "ENCASTRE"}], CANTILEVER),
        ([{"GROUP_NO": ("A", "B"), "BLOCAGE": ("DEPLACEMENT", "ROTATION")}], CLAMPED),
    ],
)
def test_euler_beam_frequencies_converge(ends, reference):
    errors = []
    for n_el in (5, 10, 40):
        session = FakeSession()
        model, field, cara = beam_model(session, line_mesh(n_el))
        mats = assembled(session, model, field, cara, [PLANE_XY, *ends])
        freqs = constrained_frequencies(mats["RIGI_MECA"], mats["MASS_MECA"])
        errors.append(np.abs(freqs / bending_frequencies(reference) - 1))
    assert np.all(errors[-1] < 1e-3)
    assert np.all(errors[2] <= errors[1]) and np.all(errors[1] <= errors[0] + 1e-12)
    assert errors[0][-1] > 10 * errors[2][-1]


def test_timoshenko_short_beam_shear_effect():
    """Simply supported short beam (L/R = 10): POU_D_T matches the Timoshenko
    frequency equation; POU_D_E overestimates."""
    length = 0.2
    kappa = 1.0 / 1.16667  # code_aster's shear coefficient of a solid circle
    g = E / (2 * (1 + NU))
    k = np.arange(1, 4) * np.pi / length
    a4 = RHO**2 * INERTIA / (kappa * g)
    a2 = RHO * AREA + RHO * INERTIA * k**2 + RHO * E * INERTIA * k**2 / (kappa * g)
    a0 = E * INERTIA * k**4
    w2 = (a2 - np.sqrt(a2**2 - 4 * a4 * a0)) / (2 * a4)
    timoshenko = np.sqrt(w2) / (2 * np.pi)
    euler = np.sqrt(E * INERTIA / (RHO * AREA)) * k**2 / (2 * np.pi)
    ends = [
        {"GROUP_NO": ("A", "B"), "DY": 0.0},
        {"TOUT": "OUI", "DX": 0.0, "DZ": 0.0, "DRX": 0.0, "DRY": 0.0},
    ]
    found = {}
    for modelisation in ("POU_D_T", "POU_D_E"):
        session = FakeSession()
        model, field, cara = beam_model(session, line_mesh(60, length), modelisation)
        mats = assembled(session, model, field, cara, ends)
        freqs = constrained_frequencies(mats["RIGI_MECA"], mats["MASS_MECA"], count=4)
        found[modelisation] = freqs[freqs > 0.01 * timoshenko[0]][:3]
    np.testing.assert_allclose(found["POU_D_T"], timoshenko, rtol=2e-3)
    np.testing.assert_allclose(found["POU_D_E"], euler, rtol=2e-3)
    assert np.all(found["POU_D_E"] > found["POU_D_T"] * 1.01)


def test_rayleigh_damping_and_lumped_mass():
    session = FakeSession()
    mesh = line_mesh(4, 2.0, direction=(1.0, 1.0, 0.5))
    model, field, cara = beam_model(session, mesh, "POU_D_T", AMOR_ALPHA=1e-4, AMOR_BETA=2.0)
    mats = assembled(
        session,
        model,
        field,
        cara,
        [{"GROUP_NO": ("A",), "LIAISON": "ENCASTRE"}],
        ("RIGI_MECA", "MASS_MECA", "AMOR_MECA", "MASS_MECA_DIAG"),
    )
    k, m, c = (mats[o].matrix.toarray() for o in ("RIGI_MECA", "MASS_MECA", "AMOR_MECA"))
    np.testing.assert_allclose(c, 1e-4 * k + 2.0 * m, rtol=1e-12, atol=1e-12 * np.abs(k).max())
    lumped = mats["MASS_MECA_DIAG"].matrix
    numbering = mats["RIGI_MECA"].numbering
    # translations are lumped (isotropic, so diagonal in any frame); the
    # rotary terms of an inclined beam are rotated to the global frame
    trans = [i for i, (_, comp) in enumerate(numbering.dofs) if comp in ("DX", "DY", "DZ")]
    block = lumped[trans][:, trans]
    off = (block - sp_diag(block)).toarray()
    assert np.abs(off).max() < 1e-12 * block.diagonal().max()
    dx = [i for i, (_, comp) in enumerate(numbering.dofs) if comp == "DX"]
    assert lumped.diagonal()[dx].sum() == pytest.approx(RHO * AREA * 2.0)
    assert mats["AMOR_MECA"].kind == "AMOR" and mats["RIGI_MECA"].model is model


def sp_diag(matrix):
    import scipy.sparse as sp

    return sp.diags(matrix.diagonal())


def _static(session, model, field, cara, ddl_impo, loads):
    """Static displacement through CALC_MATR_ELEM / NUME_DDL / ASSE_* commands."""
    fixed = run(session, "AFFE_CHAR_MECA", MODELE=model, DDL_IMPO=ddl_impo)
    rigi = run(
        session,
        "CALC_MATR_ELEM",
        OPTION="RIGI_MECA",
        MODELE=model,
        CHAM_MATER=field,
        CARA_ELEM=cara,
        CHARGE=(fixed,),
    )
    numbering = run(session, "NUME_DDL", MATR_RIGI=(rigi,))
    k = run(session, "ASSE_MATRICE", MATR_ELEM=(rigi,), NUME_DDL=numbering)
    vect = run(
        session,
        "CALC_VECT_ELEM",
        OPTION="CHAR_MECA",
        CHARGE=tuple(run(session, "AFFE_CHAR_MECA", MODELE=model, **load) for load in loads),
        CHAM_MATER=field,
        CARA_ELEM=cara,
    )
    f = run(session, "ASSE_VECTEUR", VECT_ELEM=(vect,), NUME_DDL=numbering)
    b, rhs = numbering.constraint_matrix()
    elim = eliminate(b, rhs, numbering.n_dofs)
    q = np.linalg.solve(elim.reduce(k.matrix).toarray(), elim.T.T @ f.values)
    return numbering, elim.T @ q + elim.u0, f


def test_distributed_load_gravity_and_internal_forces():
    session = FakeSession()
    length, n_el = 2.0, 8
    model, field, cara = beam_model(session, line_mesh(n_el, length))
    clamp = [{"GROUP_NO": ("A", "B"), "LIAISON": "ENCASTRE"}]
    weight = RHO * AREA * 9.81
    numbering, u_q, f_q = _static(
        session, model, field, cara, clamp, [{"FORCE_POUTRE": {"TOUT": "OUI", "FY": -weight}}]
    )
    _, u_g, f_g = _static(
        session,
        model,
        field,
        cara,
        clamp,
        [{"PESANTEUR": {"GRAVITE": 9.81, "DIRECTION": (0.0, -1.0, 0.0)}}],
    )
    np.testing.assert_allclose(f_g.values, f_q.values, atol=1e-9 * weight)
    mid = numbering.dof_index("N5", "DY")
    assert u_q[mid] == pytest.approx(-weight * length**4 / (384 * E * INERTIA), rel=1e-9)

    # cantilever with a tip force: EFGE_ELNO, SIPO_ELNO and SIPO_NOEU
    session = FakeSession()
    model, field, cara = beam_model(session, line_mesh(n_el, length))
    tip = 1000.0
    numbering, u, _ = _static(
        session,
        model,
        field,
        cara,
        [{"GROUP_NO": ("A",), "LIAISON": "ENCASTRE"}],
        [{"FORCE_NODALE": {"GROUP_NO": ("B",), "FY": tip}}],
    )
    result = DynaTrans(
        numbering, np.array([0.0, 1.0]), np.array([1, 2]), {"DEPL": np.vstack([0 * u, u])}
    )
    out = run(
        session,
        "CALC_CHAMP",
        RESULTAT=result,
        CONTRAINTE=("EFGE_ELNO", "SIPO_ELNO", "SIPO_NOEU", "EFGE_ELGA"),
    )
    gauss = out.element_fields["EFGE_ELGA"]
    first = (1 - np.sqrt(0.6)) / 2 * length / n_el
    assert gauss.at(0, 0, "MFZ")[1] == pytest.approx(tip * (length - first), rel=1e-9)
    efge = out.element_fields["EFGE_ELNO"]
    x = model.mesh.coords[np.array(model.mesh.cell_nodes)][..., 0]  # (n_el, 2)
    np.testing.assert_allclose(efge.values[1, :, :, 5], tip * (length - x), atol=1e-6 * tip)
    np.testing.assert_allclose(efge.values[1, :, :, 1], tip, rtol=1e-9)
    np.testing.assert_allclose(efge.values[0], 0.0, atol=1e-12)
    sipo = out.element_fields["SIPO_ELNO"].at(0, 0, "SMFZ")
    assert sipo[1] == pytest.approx(-tip * length / INERTIA * R, rel=1e-9)
    noeu = out.node_fields["SIPO_NOEU"]
    assert noeu.at(0, "SN")[1] == pytest.approx(0.0, abs=1e-6)
    assert noeu.at(4, "SMFZ")[1] == pytest.approx(-tip * length / 2 / INERTIA * R, rel=1e-9)
    assert "EFGE_ELNO" not in getattr(result, "element_fields", {})  # a new result


def test_post_elem_mass_inertia_of_a_rod_and_a_point_mass():
    session = FakeSession()
    mesh = line_mesh(6, 3.0)
    mesh.add_cells(["P"], "POI1", [(6,)])
    mesh.cell_groups["MASSE"] = np.array([6])
    model, field, cara = beam_model(session, mesh)
    model = run(
        session,
        "AFFE_MODELE",
        MAILLAGE=mesh,
        AFFE=[
            {"GROUP_MA": ("POUTRE",), "PHENOMENE": "MECANIQUE", "MODELISATION": "POU_D_E"},
            {"GROUP_MA": ("MASSE",), "PHENOMENE": "MECANIQUE", "MODELISATION": "DIS_T"},
        ],
    )
    cara = run(
        session,
        "AFFE_CARA_ELEM",
        MODELE=model,
        POUTRE={"GROUP_MA": ("POUTRE",), "SECTION": "CERCLE", "CARA": ("R",), "VALE": (R,)},
        DISCRET={"GROUP_MA": ("MASSE",), "CARA": "M_T_D_N", "VALE": (5.0,)},
    )
    table = run(
        session,
        "POST_ELEM",
        MODELE=model,
        CHAM_MATER=field,
        CARA_ELEM=cara,
        MASS_INER=[{"TOUT": "OUI"}, {"GROUP_MA": ("POUTRE",)}],
    )
    rod = RHO * AREA * 3.0
    whole, beam_only = table.rows
    assert whole["MASSE"] == pytest.approx(rod + 5.0)
    assert whole["CDG_X"] == pytest.approx((rod * 1.5 + 5.0 * 3.0) / (rod + 5.0))
    assert beam_only["MASSE"] == pytest.approx(rod)
    # code_aster's te0038: m L^2 / 12 plus the section's own inertia rho L I
    section = np.pi * R**4 / 4.0
    assert beam_only["IZ_G"] == pytest.approx(rod * 9.0 / 12 + RHO * 3.0 * section, rel=1e-12)
    assert beam_only["IX_G"] == pytest.approx(2.0 * RHO * 3.0 * section, rel=1e-12)
    assert beam_only["CDG_Y"] == pytest.approx(0.0, abs=1e-12)


def test_post_elem_mass_inertia_of_an_inclined_rectangular_beam():
    """An inclined beam of a rectangular section: the tensor in its own frame
    (rho L (IY + IZ), rho L (IY + A L^2/12), rho L (IZ + A L^2/12)) turned to
    the global frame, and the same principal moments whatever the direction."""
    hy, hz, length = 0.1, 0.04, 2.0
    area, iy, iz = hy * hz, hy * hz**3 / 12.0, hz * hy**3 / 12.0
    section = ("RECTANGLE", ("HY", "HZ"), (hy, hz))
    expected = (
        RHO * length * np.array([iy + iz, iy + area * length**2 / 12, iz + area * length**2 / 12])
    )
    for direction in ((1.0, 0.0, 0.0), (1.0, 2.0, 2.0)):
        session = FakeSession()
        model, field, cara = beam_model(session, line_mesh(4, length, direction), section=section)
        row = run(
            session, "POST_ELEM", MODELE=model, CHAM_MATER=field, CARA_ELEM=cara,
            MASS_INER={"TOUT": "OUI"},
        ).rows[0]  # fmt: skip
        principal = [row[f"{axis}_PRIN_G"] for axis in ("IX", "IY", "IZ")]
        np.testing.assert_allclose(principal, np.sort(expected), rtol=1e-12)
        axis = np.asarray(direction) / np.linalg.norm(direction)
        centre = [row[f"CDG_{c}"] for c in "XYZ"]
        np.testing.assert_allclose(centre, axis * length / 2.0, atol=1e-14)


def test_bar_and_orientation_and_errors():
    session = FakeSession()
    mesh = line_mesh(1, 5.0, direction=(3.0, 4.0, 0.0))
    model, field, cara = beam_model(session, mesh, "BARRE", ("CERCLE", ("R",), (R,)))
    mats = assembled(session, model, field, cara, [])
    k = mats["RIGI_MECA"].matrix.toarray()
    axis = np.array([0.6, 0.8, 0.0])
    expected = E * AREA / 5.0 * np.outer(axis, axis)
    np.testing.assert_allclose(k[:3, :3], expected, rtol=1e-12, atol=1e-6)
    # VECT_Y orientation of a rectangular beam: stiffness about the right axis
    session = FakeSession()
    model, field, _ = beam_model(session, line_mesh(1, 1.0), "POU_D_E")
    cara = run(
        session,
        "AFFE_CARA_ELEM",
        MODELE=model,
        POUTRE={
            "GROUP_MA": ("POUTRE",),
            "SECTION": "RECTANGLE",
            "CARA": ("HY", "HZ"),
            "VALE": (0.01, 0.04),
        },
        ORIENTATION={"GROUP_MA": ("POUTRE",), "CARA": "VECT_Y", "VALE": (0.0, 0.0, 1.0)},
    )
    mats = assembled(session, model, field, cara, [])
    k = mats["RIGI_MECA"].matrix
    num = mats["RIGI_MECA"].numbering
    # local y is global Z: the stiff bending (IY = HY HZ^3/12 about local y) acts along global Y
    kyy = k[num.dof_index("N2", "DY"), num.dof_index("N2", "DY")]
    kzz = k[num.dof_index("N2", "DZ"), num.dof_index("N2", "DZ")]
    assert kyy / kzz == pytest.approx(16.0)
    with pytest.raises(CommandError, match="material field"):
        run(session, "CALC_MATR_ELEM", OPTION="RIGI_MECA", MODELE=model, CARA_ELEM=cara)
    discrete = run(
        session,
        "AFFE_MODELE",
        MAILLAGE=line_mesh(1),
        AFFE={"TOUT": "OUI", "PHENOMENE": "MECANIQUE", "MODELISATION": "DIS_T"},
    )
    with pytest.raises(CommandError, match="carries a DIS_T element"):
        run(
            session,
            "AFFE_CARA_ELEM",
            MODELE=discrete,
            POUTRE={"GROUP_MA": ("POUTRE",), "SECTION": "CERCLE", "CARA": ("R",), "VALE": (R,)},
        )


def test_liaison_unif_and_solide_relations():
    session = FakeSession()
    model, field, cara = beam_model(session, line_mesh(4, 4.0))
    load = run(
        session,
        "AFFE_CHAR_MECA",
        MODELE=model,
        LIAISON_UNIF={"GROUP_NO": ("A", "B"), "DDL": ("DY",)},
        LIAISON_SOLIDE={"GROUP_MA": ("POUTRE",)},
    )
    numbering = DofNumbering(
        mesh=model.mesh,
        dofs=[(n, c) for n in range(5) for c in ("DX", "DY", "DZ", "DRX", "DRY", "DRZ")],
        relations=load.relations,
    )
    b, rhs = numbering.constraint_matrix()
    elim = eliminate(b, rhs, numbering.n_dofs)
    # rigid body (6) with DY(A) = DY(B): a rotation about Z is excluded
    assert elim.n_free == 5
    u = elim.T.toarray()
    dz = [numbering.dof_index(n, "DZ") for n in range(5)]
    assert np.linalg.matrix_rank(u[dz]) == 2  # translation DZ and rotation about Y


def test_modi_maillage_and_defi_group_options():
    session = FakeSession()
    mesh = line_mesh(4, 4000.0)
    run(session, "MODI_MAILLAGE", MAILLAGE=mesh, ECHELLE=1.0e-3)
    np.testing.assert_allclose(mesh.coords[-1], [4.0, 0.0, 0.0])
    run(
        session,
        "MODI_MAILLAGE",
        MAILLAGE=mesh,
        ROTATION={"POIN_1": (0.0, 0.0, 0.0), "ANGLE": 90.0, "DIR": (0.0, 0.0, 1.0)},
        TRANSLATION=(1.0, 0.0, 0.0),
    )
    np.testing.assert_allclose(mesh.coords[-1], [0.0, 5.0, 0.0], atol=1e-12)
    run(
        session,
        "DEFI_GROUP",
        MAILLAGE=mesh,
        CREA_GROUP_NO=[
            {
                "NOM": "C",
                "OPTION": "ENV_SPHERE",
                "POINT": (0.0, 3.0),
                "RAYON": 0.001,
                "PRECISION": 0.001,
            },
            {"NOM": "ORDO", "OPTION": "NOEUD_ORDO", "GROUP_MA": ("POUTRE",), "GROUP_NO_ORIG": "B"},
            {
                "NOM": "SEG",
                "OPTION": "SEGM_DROI_ORDO",
                "GROUP_NO": ("ORDO",),
                "GROUP_NO_ORIG": "A",
                "GROUP_NO_EXTR": "B",
                "PRECISION": 1e-6,
                "CRITERE": "RELATIF",
            },
            {"GROUP_MA": ("POUTRE",), "NOM": ("TOUS",)},
        ],
    )
    assert mesh.node_groups["C"].tolist() == [2]
    assert mesh.node_groups["ORDO"].tolist() == [4, 3, 2, 1, 0]
    assert mesh.node_groups["SEG"].tolist() == [0, 1, 2, 3, 4]
    assert sorted(mesh.node_groups["TOUS"].tolist()) == [0, 1, 2, 3, 4]


def test_material_from_constant_functions_and_impr_co():
    from asterlite.concepts.function import Function

    session = FakeSession()
    young = Function(np.array([0.0, 100.0]), np.array([E, E]), NOM_PARA="TEMP")
    poisson = Function(np.array([0.0]), np.array([NU]), NOM_PARA="TEMP")
    material = run(session, "DEFI_MATERIAU", ELAS_FO={"E": young, "NU": poisson})
    assert material.young == E and material.poisson == NU
    material.name = "MAT"
    session.namespace = {"MAT": material}
    run(session, "IMPR_CO", CONCEPT={"NOM": (material,)})
    assert any("mater_sdaster" in line for line in session.lines)
    # a temperature-dependent E is kept with the material (code_aster too only
    # needs its value where an element is computed), and refused there
    varying = Function(np.array([0.0, 100.0]), np.array([E, 0.9 * E]), NOM_PARA="TEMP")
    kept = run(session, "DEFI_MATERIAU", ELAS_FO={"E": varying, "NU": poisson})
    assert kept.behaviours["ELAS_VARYING"] == {"E": "TEMP"}
    field = MaterialField(mesh=None, cell_material={0: kept})
    with pytest.raises(ValueError, match="varies with TEMP"):
        field.values([0], "E")


def test_lire_maillage_med_of_a_beam_deck(corpus_dir):
    path = corpus_dir / "forma02d" / "forma02d.mmed"
    if not path.is_file():
        pytest.skip("forma02d mesh not available")
    session = FakeSession({20: path})
    mesh = run(session, "LIRE_MAILLAGE", FORMAT="MED", UNITE=20)
    assert mesh.n_nodes > 0 and "TUYAU" in mesh.cell_groups
    assert set(mesh.cell_types[c] for c in mesh.cell_groups["TUYAU"]) == {"SEG2"}
    with pytest.raises(CommandError, match="no mesh named"):
        run(session, "LIRE_MAILLAGE", FORMAT="MED", UNITE=20, NOM_MED="NOPE")
