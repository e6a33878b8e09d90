"""Orthotropic elasticity (DEFI_MATERIAU ELAS_ORTH) of the 3D and plane
solids in the material frame of AFFE_CARA_ELEM MASSIF ANGL_REP: the Hooke
matrix against code_aster's closed form, its rotation against the strain
transformation code_aster applies (dpassa), and element stiffness and
stresses against homogeneous-strain closed forms (energy V/2 e.D.e, stress
D e, plane stress from the inverse of the in-plane compliance)."""

from __future__ import annotations

import numpy as np
import pytest

from asterlite.concepts.assembly import (
    DofNumbering,
    ElementCharacteristics,
    Material,
    MaterialField,
    Model,
)
from asterlite.fem.assemble import assemble_blocks, build_numbering_dofs
from asterlite.fem.element_errors import ElementError
from asterlite.fem.element_materials import elastic_values
from asterlite.fem.elements import element_blocks
from asterlite.fem.frames import rotation_from_angles
from asterlite.fem.orthotropic import isotropic_hooke, material_hooke, rotate_hooke
from asterlite.fem.solid_fields import solid_element_fields
from tests.solid_meshes import box_mesh
from tests.test_fem_plane import grid_mesh

PARAMS = {
    **{"E_L": 1.4e11, "E_T": 9.0e9, "E_N": 7.0e9},
    **{"NU_LT": 0.28, "NU_LN": 0.22, "NU_TN": 0.41},
    **{"G_LT": 5.0e9, "G_LN": 4.2e9, "G_TN": 3.1e9},
}
ORTHO = Material(behaviours={"ELAS_ORTH": {**PARAMS, "RHO": 1600.0}})
ENTRIES = ((0, 0), (1, 1), (2, 2), (0, 1), (0, 2), (1, 2))


def _closed_form(p):
    """code_aster's Hooke coefficients of an orthotropic material (its
    separ_RI_elas_3D): h11 h12 h13 h22 h23 h33."""
    e1, e2, e3 = p["E_L"], p["E_T"], p["E_N"]
    nu12, nu13, nu23 = p["NU_LT"], p["NU_LN"], p["NU_TN"]
    nu21, nu31, nu32 = e2 * nu12 / e1, e3 * nu13 / e1, e3 * nu23 / e2
    delta = 1 - nu23 * nu32 - nu31 * nu13 - nu21 * nu12 - 2 * nu23 * nu31 * nu12
    return [
        (1 - nu23 * nu32) * e1 / delta,
        (nu21 + nu31 * nu23) * e1 / delta,
        (nu31 + nu21 * nu32) * e1 / delta,
        (1 - nu13 * nu31) * e2 / delta,
        (nu32 + nu31 * nu12) * e2 / delta,
        (1 - nu21 * nu12) * e3 / delta,
    ]


def _strain_transformation(p):
    """The 6x6 map of global to local engineering strains (code_aster's dpassa)."""
    t = np.zeros((6, 6))
    for row, (a, b) in enumerate(ENTRIES):
        for col, (i, j) in enumerate(ENTRIES):
            if i == j:
                t[row, col] = p[a, i] * p[b, i] * (1.0 if a == b else 2.0)
            else:
                coef = p[a, i] * p[b, j] + p[a, j] * p[b, i]
                t[row, col] = coef * (0.5 if a == b else 1.0)
    return t


def test_hooke_matrix_is_code_aster_closed_form():
    d = material_hooke(PARAMS)
    got = [d[0, 0], d[0, 1], d[0, 2], d[1, 1], d[1, 2], d[2, 2]]
    np.testing.assert_allclose(got, _closed_form(PARAMS), rtol=1e-12)
    np.testing.assert_allclose(np.diag(d)[3:], [PARAMS[k] for k in ("G_LT", "G_LN", "G_TN")])


def test_rotation_is_the_strain_transformation_and_keeps_isotropy():
    d = material_hooke(PARAMS)
    p = rotation_from_angles(np.radians([30.0, -20.0, 55.0]))
    t = _strain_transformation(p)
    np.testing.assert_allclose(rotate_hooke(d, p), t.T @ d @ t, rtol=1e-10, atol=1e-6)
    iso = isotropic_hooke(np.array([2.0e11]), np.array([0.3]))[0]
    np.testing.assert_allclose(rotate_hooke(iso, p), iso, atol=1e-9 * iso.max())
    # a quarter turn about Z: L along Y, T along -X
    turned = rotate_hooke(d, rotation_from_angles(np.radians([90.0, 0.0, 0.0])))
    assert turned[1, 1] == pytest.approx(d[0, 0]) and turned[0, 0] == pytest.approx(d[1, 1])
    assert turned[3, 3] == pytest.approx(PARAMS["G_LT"])
    assert turned[4, 4] == pytest.approx(PARAMS["G_TN"])


def _setup(mesh, modelisation, angles):
    model = Model(mesh=mesh, cell_modelisation=dict.fromkeys(range(mesh.n_cells), modelisation))
    field = MaterialField(mesh=mesh, cell_material=dict.fromkeys(range(mesh.n_cells), ORTHO))
    cara = ElementCharacteristics(model=model)
    cara.material_angles = dict.fromkeys(range(mesh.n_cells), np.radians(angles))
    numbering = DofNumbering(mesh=mesh, dofs=build_numbering_dofs(model.node_components()))
    return model, field, cara, numbering


def _linear_state(numbering, mesh, gradient):
    dim = gradient.shape[0]
    xyz = mesh.coords[numbering.dof_nodes][:, :dim]
    axis = np.array([["DX", "DY", "DZ"].index(c) for c in numbering.dof_components])
    return (xyz @ gradient.T)[np.arange(len(axis)), axis]


def _voigt(gradient):
    eps = np.zeros((3, 3))
    n = gradient.shape[0]
    eps[:n, :n] = 0.5 * (gradient + gradient.T)
    return eps, np.array([eps[i, j] * (1 if i == j else 2) for i, j in ENTRIES])


@pytest.mark.parametrize("kind", ["HEXA8", "TETRA10", "PENTA6"])
def test_3d_stiffness_energy_and_stresses_of_a_homogeneous_strain(kind):
    size = (1.0, 0.8, 1.2)
    mesh = box_mesh(kind, (2, 2, 2), size, jitter=0.2, seed=2)
    angles = (30.0, -20.0, 55.0)
    model, field, cara, numbering = _setup(mesh, "3D", angles)
    d = rotate_hooke(material_hooke(PARAMS), rotation_from_angles(np.radians(angles)))
    gradient = np.array([[1e-3, 2e-4, 0.0], [-1e-4, -5e-4, 3e-4], [4e-4, 0.0, 2e-4]])
    u = _linear_state(numbering, mesh, gradient)
    k = assemble_blocks(element_blocks(model, cara, "K", materials=field), numbering)
    _, e = _voigt(gradient)
    assert 0.5 * u @ (k @ u) == pytest.approx(0.5 * np.prod(size) * e @ d @ e, rel=1e-10)
    fields = solid_element_fields(
        model,
        field,
        numbering,
        np.arange(mesh.n_cells),
        u[None],
        ["SIEF_ELGA"],
        characteristics=cara,
    )
    values = fields["SIEF_ELGA"].values[0]
    expected = d @ e
    np.testing.assert_allclose(
        values[~np.isnan(values[..., 0])],
        np.broadcast_to(expected, values[~np.isnan(values[..., 0])].shape),
        rtol=1e-9,
        atol=1e-9 * abs(expected).max(),
    )


@pytest.mark.parametrize("modelisation", ["D_PLAN", "C_PLAN"])
def test_plane_stiffness_and_stresses_in_a_turned_material_frame(modelisation):
    mesh = grid_mesh("QUAD8", (2, 2), (1.0, 0.7), (0.0, 0.0), jitter=0.2, seed=4)
    model, field, cara, numbering = _setup(mesh, modelisation, (35.0, 0.0, 0.0))
    d3 = rotate_hooke(material_hooke(PARAMS), rotation_from_angles(np.radians([35.0, 0, 0])))
    in_plane = [0, 1, 3]
    if modelisation == "D_PLAN":
        d = d3[np.ix_(in_plane, in_plane)]
    else:
        # plane stress: the inverse of the in-plane compliance
        d = np.linalg.inv(np.linalg.inv(d3)[np.ix_(in_plane, in_plane)])
    gradient = np.array([[1e-3, 3e-4], [1e-4, -2e-3]])
    u = _linear_state(numbering, mesh, gradient)
    k = assemble_blocks(element_blocks(model, cara, "K", materials=field), numbering)
    _, e = _voigt(gradient)
    strain = e[in_plane]
    assert 0.5 * u @ (k @ u) == pytest.approx(0.5 * 0.7 * strain @ d @ strain, rel=1e-10)
    fields = solid_element_fields(
        model,
        field,
        numbering,
        np.arange(mesh.n_cells),
        u[None],
        ["SIEF_ELGA", "EPSI_ELGA"],
        characteristics=cara,
    )
    sig = fields["SIEF_ELGA"].values[0]
    eps = fields["EPSI_ELGA"].values[0]
    stress = d @ strain
    np.testing.assert_allclose(
        sig[..., [0, 1, 3]],
        np.broadcast_to(stress, sig[..., :3].shape),
        rtol=1e-9,
        atol=1e-9 * abs(stress).max(),
    )
    if modelisation == "D_PLAN":
        expected_zz = d3[2, in_plane] @ strain
        np.testing.assert_allclose(sig[..., 2], expected_zz, rtol=1e-9)
        np.testing.assert_allclose(eps[..., 2], 0.0, atol=1e-18)
    else:
        np.testing.assert_allclose(sig[..., 2], 0.0, atol=1e-9 * abs(stress).max())
        # eps_zz from the compliance: S_zx sig_xx + S_zy sig_yy + S_z,xy tau_xy
        expected_zz = np.linalg.inv(d3)[2, in_plane] @ stress
        np.testing.assert_allclose(eps[..., 2], expected_zz, rtol=1e-9)


def test_isotropic_values_in_elas_orth_give_the_elas_stiffness():
    mesh = box_mesh("HEXA20", (1, 1, 1), jitter=0.0)
    young, poisson = 2.0e11, 0.3
    shear = young / (2 * (1 + poisson))
    iso_params = dict.fromkeys(("E_L", "E_T", "E_N"), young)
    iso_params |= dict.fromkeys(("NU_LT", "NU_LN", "NU_TN"), poisson)
    iso_params |= dict.fromkeys(("G_LT", "G_LN", "G_TN"), shear)
    model = Model(mesh=mesh, cell_modelisation={0: "3D"})
    numbering = DofNumbering(mesh=mesh, dofs=build_numbering_dofs(model.node_components()))
    out = []
    for material in (
        Material(behaviours={"ELAS_ORTH": iso_params}),
        Material(behaviours={"ELAS": {"E": young, "NU": poisson}}),
    ):
        field = MaterialField(mesh=mesh, cell_material={0: material})
        out.append(assemble_blocks(element_blocks(model, None, "K", materials=field), numbering))
    np.testing.assert_allclose(out[0].toarray(), out[1].toarray(), atol=1e-6 * abs(out[1]).max())


def test_families_without_orthotropy_refuse_it_and_missing_moduli_are_named():
    mesh = box_mesh("HEXA8", n=(1, 1, 1))
    field = MaterialField(mesh=mesh, cell_material={0: ORTHO})
    with pytest.raises(ElementError, match="ELAS_ORTH"):
        elastic_values(field, [0], mesh, "DKT", need_density=False)
    partial = Material(
        behaviours={"ELAS_ORTH": {"E_L": 1.0, "E_T": 1.0, "NU_LT": 0.1, "G_LT": 1.0}}
    )
    model = Model(mesh=mesh, cell_modelisation={0: "3D"})
    with pytest.raises(ElementError, match="E_N, NU_LN, NU_TN, G_LN, G_TN"):
        element_blocks(
            model, None, "K", materials=MaterialField(mesh=mesh, cell_material={0: partial})
        )
