"""Stresses, strains and energies of solid elements (CALC_CHAMP on 3D and
plane cells): Gauss-to-node extrapolation as code_aster's, uniform states
against Hooke's law, energies against the element matrices, complex states."""

from __future__ import annotations

import numpy as np
import pytest

from asterlite.concepts.assembly import DofNumbering
from asterlite.fem.assemble import build_numbering_dofs
from asterlite.fem.elements import element_blocks
from asterlite.fem.solid_fields import gauss_to_nodes, solid_element_fields
from asterlite.fem.solid_reference import REFERENCE_ELEMENTS, gauss_family
from tests.solid_meshes import box_mesh, solid_model
from tests.test_fem_plane import NU, E, grid_mesh, plane_model

FAMILIES = [
    ("QU4", "FPG4"),
    ("QU8", "FPG9"),
    ("QU9", "FPG9"),
    ("TR6", "FPG3"),
    ("TR6", "FPG6"),
    ("HE8", "FPG8"),
    ("H20", "FPG27"),
    ("T10", "FPG5"),
    ("PE6", "FPG6"),
    ("P15", "FPG21"),
]


@pytest.mark.parametrize(("reference", "family"), FAMILIES)
def test_gauss_to_nodes_reproduces_linear_fields(reference, family):
    """The least-squares fit on the vertex functions keeps any field of the
    linear element, at the vertices and (as means) at the other nodes."""
    ref = REFERENCE_ELEMENTS[reference]
    points = gauss_family(reference, family)[0]
    rng = np.random.default_rng(1)
    coefficients = rng.normal(size=ref.dim + 1)
    linear = lambda x: coefficients[0] + x @ coefficients[1:]  # noqa: E731
    assert np.allclose(gauss_to_nodes(reference, family) @ linear(points), linear(ref.nodes))


def test_gauss_to_nodes_of_one_point_and_of_the_quadrangle():
    assert np.array_equal(gauss_to_nodes("TR3", "FPG1"), np.ones((3, 1)))
    # four points, four vertices: the exact inverse of the point values
    points = gauss_family("QU4", "FPG4")[0]
    at_points = REFERENCE_ELEMENTS["QU4"].values(points).real
    assert np.allclose(gauss_to_nodes("QU4", "FPG4") @ at_points, np.eye(4))


def _numbering(model, mesh):
    return DofNumbering(mesh=mesh, dofs=build_numbering_dofs(model.node_components()))


def _state(numbering, mesh, gradient):
    xyz = mesh.coords[numbering.dof_nodes]
    axis = np.array([["DX", "DY", "DZ"].index(c) for c in numbering.dof_components])
    dim = gradient.shape[0]
    return np.einsum("ni,ni->n", xyz[:, :dim] @ gradient.T, np.eye(dim)[axis])[None, :]


def _hooke(eps):
    lam = E * NU / ((1 + NU) * (1 - 2 * NU))
    mu = E / (2 * (1 + NU))
    return lam * np.trace(eps) * np.eye(3) + 2 * mu * eps


@pytest.mark.parametrize("kind", ["HEXA20", "TETRA10", "PENTA6"])
def test_3d_uniform_strain_and_energies(kind):
    mesh = box_mesh(kind, (2, 2, 2), (1.0, 0.8, 1.2), jitter=0.2, seed=3)
    model, field = solid_model(mesh)
    numbering = _numbering(model, mesh)
    gradient = np.array([[1e-3, 2e-4, 0.0], [-1e-4, -5e-4, 3e-4], [4e-4, 0.0, 2e-4]])
    u = _state(numbering, mesh, gradient)
    cells = np.arange(mesh.n_cells)
    names = ["SIEF_ELGA", "EPSI_ELGA", "SIGM_ELNO", "EPOT_ELEM", "ECIN_ELEM"]
    fields = solid_element_fields(model, field, numbering, cells, u, names, velocities=u)
    eps = 0.5 * (gradient + gradient.T)
    sig = _hooke(eps)
    entries = [(0, 0), (1, 1), (2, 2), (0, 1), (0, 2), (1, 2)]
    assert np.allclose(fields["SIEF_ELGA"].values[0], [sig[e] for e in entries], equal_nan=True)
    assert np.allclose(fields["SIGM_ELNO"].values[0], [sig[e] for e in entries], equal_nan=True)
    assert np.allclose(fields["EPSI_ELGA"].values[0], [eps[e] for e in entries], equal_nan=True)
    # EPOT = u_e K_e u_e / 2 and ECIN = v_e M_e v_e / 2 with the element matrices
    for matrix, name in (("K", "EPOT_ELEM"), ("M", "ECIN_ELEM")):
        (block,) = element_blocks(model, None, matrix, materials=field)
        rows = numbering.dof_indices(
            np.repeat(block.nodes.ravel(), 3), ["DX", "DY", "DZ"] * block.nodes.size
        )
        ue = u[0, rows].reshape(len(cells), -1)
        expected = 0.5 * np.einsum("ei,eij,ej->e", ue, block.matrices, ue)
        assert np.allclose(fields[name].values[0, :, 0, 0], expected, rtol=1e-10)


@pytest.mark.parametrize("modelisation", ["D_PLAN", "C_PLAN", "AXIS"])
@pytest.mark.parametrize("kind", ["QUAD8", "TRIA3", "TRIA6"])
def test_plane_uniform_states(kind, modelisation):
    origin = (1.0, 0.0) if modelisation == "AXIS" else (0.0, 0.0)
    mesh = grid_mesh(kind, (2, 2), (1.0, 1.0), origin, jitter=0.2, seed=5)
    model, field = plane_model(mesh, modelisation)
    numbering = _numbering(model, mesh)
    if modelisation == "AXIS":
        gradient = np.array([[1e-3, 0.0], [0.0, -2e-3]])  # u_r = a r, u_z = c z
    else:
        gradient = np.array([[1e-3, 3e-4], [1e-4, -2e-3]])
    u = _state(numbering, mesh, gradient)
    names = ["SIEF_ELGA", "EPSI_ELNO", "SIGM_ELNO"]
    fields = solid_element_fields(model, field, numbering, np.arange(mesh.n_cells), u, names)
    eps = np.zeros((3, 3))
    eps[:2, :2] = 0.5 * (gradient + gradient.T)
    if modelisation == "AXIS":
        eps[2, 2] = gradient[0, 0]
    if modelisation == "C_PLAN":
        eps[2, 2] = -NU / (1 - NU) * (eps[0, 0] + eps[1, 1])
    sig = _hooke(eps)
    assert sig[2, 2] == pytest.approx(0.0, abs=1e-6 * abs(sig).max()) or modelisation != "C_PLAN"
    expected_sig = [sig[0, 0], sig[1, 1], sig[2, 2], sig[0, 1]]
    expected_eps = [eps[0, 0], eps[1, 1], eps[2, 2], eps[0, 1]]
    scale = abs(sig).max()
    values = fields["SIEF_ELGA"].values[0]
    assert np.nanmax(np.abs(values - expected_sig)) < 1e-9 * scale
    values = fields["SIGM_ELNO"].values[0]
    assert np.nanmax(np.abs(values - expected_sig)) < 1e-9 * scale
    values = fields["EPSI_ELNO"].values[0]
    assert np.nanmax(np.abs(values - expected_eps)) < 1e-12


def test_complex_states_give_complex_stresses_and_summed_energies():
    mesh = grid_mesh("QUAD4", (2, 1))
    model, field = plane_model(mesh, "D_PLAN")
    numbering = _numbering(model, mesh)
    rng = np.random.default_rng(0)
    real, imag = rng.normal(size=(2, 1, numbering.n_dofs)) * 1e-4
    names = ["SIEF_ELGA", "EPOT_ELEM", "ECIN_ELEM"]
    cells = np.arange(mesh.n_cells)
    both = solid_element_fields(
        model, field, numbering, cells, real + 1j * imag, names, velocities=real + 1j * imag
    )
    parts = [
        solid_element_fields(model, field, numbering, cells, p, names, velocities=p)
        for p in (real, imag)
    ]
    sief = parts[0]["SIEF_ELGA"].values + 1j * parts[1]["SIEF_ELGA"].values
    assert np.allclose(both["SIEF_ELGA"].values, sief)
    for name in ("EPOT_ELEM", "ECIN_ELEM"):
        assert not np.iscomplexobj(both[name].values)
        assert np.allclose(both[name].values, parts[0][name].values + parts[1][name].values)


def test_only_the_gauss_fields_asked_for_are_kept(monkeypatch):
    """SIEF_ELGA alone allocates its own Gauss-point array, not those of the
    strains and energy densities (each the size of the result times the
    points), and gives the values it gives beside them, bit for bit."""
    from asterlite.fem import solid_fields

    mesh = box_mesh("HEXA20", (2, 2, 1), (1.0, 0.8, 1.2), jitter=0.2, seed=3)
    model, field = solid_model(mesh)
    numbering = _numbering(model, mesh)
    gradient = np.array([[1e-3, 2e-4, 0.0], [-1e-4, -5e-4, 3e-4], [4e-4, 0.0, 2e-4]])
    u = np.concatenate([_state(numbering, mesh, gradient), 2.0 * _state(numbering, mesh, gradient)])
    cells = np.arange(mesh.n_cells)
    every = ["SIEF_ELGA", "EPSI_ELGA", "ENEL_ELGA", "EPOT_ELEM"]
    reference = solid_element_fields(model, field, numbering, cells, u, every)
    shapes = []
    full = np.full

    def recording(shape, *args, **kwargs):
        shapes.append(tuple(np.atleast_1d(shape)))
        return full(shape, *args, **kwargs)

    monkeypatch.setattr(solid_fields.np, "full", recording)
    alone = solid_element_fields(model, field, numbering, cells, u, ["SIEF_ELGA"])
    per_point = [shape for shape in shapes if len(shape) == 4 and shape[2] > 1]
    assert per_point == [reference["SIEF_ELGA"].values.shape]
    assert list(alone) == ["SIEF_ELGA"]
    assert np.array_equal(alone["SIEF_ELGA"].values, reference["SIEF_ELGA"].values, equal_nan=True)


def test_orders_are_computed_by_chunks_of_bounded_bytes_with_the_same_values(monkeypatch):
    """The (orders, cells, points, 3, 3) work tensors hold as many orders as
    fit WORK_BYTES (at least one); one order at a time gives the values of
    every order at once, bit for bit."""
    from asterlite.fem import solid_fields

    assert solid_fields.orders_per_chunk(10, 27, 8) == solid_fields.WORK_BYTES // (10 * 27 * 72)
    assert solid_fields.orders_per_chunk(10**9, 27, 8) == 1
    mesh = box_mesh("HEXA20", (2, 2, 1), (1.0, 0.8, 1.2), jitter=0.2, seed=3)
    model, field = solid_model(mesh)
    numbering = _numbering(model, mesh)
    rng = np.random.default_rng(7)
    u = rng.normal(scale=1e-3, size=(5, numbering.n_dofs))
    cells = np.arange(mesh.n_cells)
    names = ["SIEF_ELGA", "EPSI_ELGA", "ENEL_ELGA", "SIGM_ELNO", "EPOT_ELEM", "ECIN_ELEM"]
    monkeypatch.setattr(solid_fields, "WORK_BYTES", 1)
    chunked = solid_element_fields(model, field, numbering, cells, u, names, velocities=u)
    monkeypatch.setattr(solid_fields, "WORK_BYTES", 1 << 40)
    whole = solid_element_fields(model, field, numbering, cells, u, names, velocities=u)
    for name in names:
        assert np.array_equal(chunked[name].values, whole[name].values, equal_nan=True), name
