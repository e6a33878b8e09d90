"""EFGE_ELNO of DKT plates: a plate in pure bending and a membrane state on a
distorted, tilted mesh give N = D_m eps, M = D_f kappa and no shear at every
node, in the output frame of ANGL_REP; complex displacements give the
complex forces; the shear of a linear moment field on a parallelogram mesh
is its divergence. (sdls01b's VALE_CALC of MXX..QY hold to 2e-11.)"""

from __future__ import annotations

import numpy as np
import pytest

from asterlite.concepts.assembly import DofNumbering
from asterlite.fem.assemble import build_numbering_dofs
from asterlite.fem.plate_fields import PLATE_EFGE_COMPONENTS, plate_element_fields
from tests.test_fem_plane import grid_mesh
from tests.test_fem_plate import KINDS, NU, ROTATION, E, H, nodal, plate_model, tilted

LAW = np.array([[1, NU, 0], [NU, 1, 0], [0, 0, (1 - NU) / 2]]) * E / (1 - NU**2)


def _rotated(tensor, c, s):
    r = np.array([[c, s], [-s, c]])
    t = np.array([[tensor[0], tensor[2]], [tensor[2], tensor[1]]])
    out = r @ t @ r.T
    return np.array([out[0, 0], out[1, 1], out[0, 1]])


def _output_axis(angles):
    """(c, s) of the projection of ANGL_REP's direction in the plate's axes."""
    alpha, beta = np.radians(angles)
    d = np.array([np.cos(beta) * np.cos(alpha), np.cos(beta) * np.sin(alpha), -np.sin(beta)])
    c, s = d @ ROTATION[:, 0], d @ ROTATION[:, 1]
    return c / np.hypot(c, s), s / np.hypot(c, s)


@pytest.mark.parametrize("kind", KINDS)
@pytest.mark.parametrize("angles", [(0.0, 0.0), (30.0, 10.0)])
def test_pure_bending_and_membrane_forces(kind, angles):
    mesh = tilted(grid_mesh(kind, (3, 3), (1.0, 1.3), jitter=0.25, seed=2), ROTATION)
    model, characteristics, field = plate_model(mesh)
    for shell in characteristics.shells.values():
        shell["ANGL_REP"] = angles
    numbering = DofNumbering(mesh=mesh, dofs=build_numbering_dofs(model.node_components()))
    a, b, c = 1e-3, -2e-3, 5e-4
    g = np.array([[1e-4, 3e-5], [-2e-5, 2e-4]])

    def state(xy):
        x, y = xy[:, 0], xy[:, 1]
        beta_x, beta_y = -(a * x + c * y), -(b * y + c * x)
        w = 0.5 * (a * x * x + b * y * y) + c * x * y
        uv = xy @ g.T
        return np.stack([uv[:, 0], uv[:, 1], w, -beta_y, beta_x, 0 * x], axis=1)

    u = nodal(numbering, mesh, ROTATION, state)
    values = np.stack([u, (1.0 - 2.0j) * u])
    cells = np.arange(mesh.n_cells)
    efge = plate_element_fields(
        model, characteristics, field, numbering, cells, values, ["EFGE_ELNO"]
    )["EFGE_ELNO"]
    assert efge.components == PLATE_EFGE_COMPONENTS
    cos, sin = _output_axis(angles)
    moments = _rotated(H**3 / 12 * LAW @ np.array([-a, -b, -2 * c]), cos, sin)
    membrane = _rotated(H * LAW @ np.array([g[0, 0], g[1, 1], g[0, 1] + g[1, 0]]), cos, sin)
    expected = np.concatenate([membrane, moments, [0.0, 0.0]])
    scale = np.abs(expected).max()
    n = len(mesh.cell_nodes[0])
    got = efge.values[0, :, :n, :]
    assert np.abs(got.imag).max() == 0.0
    # the shear takes the Jacobian at the node as constant (code_aster's
    # dkqtxy): exact on triangles, not on distorted quadrangles
    last = 8 if kind == "TRIA3" else 6
    assert np.abs(got.real - expected)[..., :last].max() < 1e-9 * scale
    assert np.abs(efge.values[1] - (1.0 - 2.0j) * efge.values[0]).max() < 1e-12 * scale


def test_plate_fields_refuse_other_options():
    mesh = grid_mesh("TRIA3", (1, 1), (1.0, 1.0))
    model, characteristics, field = plate_model(mesh)
    numbering = DofNumbering(mesh=mesh, dofs=build_numbering_dofs(model.node_components()))
    with pytest.raises(ValueError, match="EPSI_ELGA is not computed for DKT plates"):
        plate_element_fields(
            model, characteristics, field, numbering, [0], np.zeros((1, 1)), ["EPSI_ELGA"]
        )


def test_shear_is_the_divergence_of_moments_on_parallelograms():
    """w = d x^3 / 6 (beta_x = -d x^2 / 2): M_xx = -D d x, M_yy = -nu D d x,
    so QX = -D d and QY = 0, on a regular (undistorted) tilted quadrangle mesh."""
    mesh = tilted(grid_mesh("QUAD4", (4, 3), (1.0, 1.3)), ROTATION)
    model, characteristics, field = plate_model(mesh)
    numbering = DofNumbering(mesh=mesh, dofs=build_numbering_dofs(model.node_components()))
    d = 2e-3

    def state(xy):
        x = xy[:, 0]
        zero = 0 * x
        return np.stack([zero, zero, d * x**3 / 6, zero, -d * x**2 / 2, zero], axis=1)

    u = nodal(numbering, mesh, ROTATION, state)
    efge = plate_element_fields(
        model, characteristics, field, numbering, np.arange(mesh.n_cells), u[None], ["EFGE_ELNO"]
    )["EFGE_ELNO"]
    rigidity = E * H**3 / (12 * (1 - NU**2))
    cos, sin = _output_axis((0.0, 0.0))
    q_local = np.array([-rigidity * d, 0.0])
    expected = np.array([[cos, sin], [-sin, cos]]) @ q_local
    assert np.abs(efge.values[0, :, :, 6:] - expected).max() < 1e-9 * rigidity * d


@pytest.mark.parametrize("kind", KINDS)
def test_layer_stresses_of_bending_and_membrane(kind):
    """SIEF_ELGA / SIGM_ELNO on 2 layers (6 sub-points: bottom, middle, top of
    each): sigma = N / h + 12 z M / h^3 for the constant state of the patch,
    SIZZ = 0, no transverse shear; SIGM_ELNO holds the same at the nodes."""
    mesh = tilted(grid_mesh(kind, (3, 3), (1.0, 1.3), jitter=0.25, seed=2), ROTATION)
    model, characteristics, field = plate_model(mesh)
    for shell in characteristics.shells.values():
        shell["COQUE_NCOU"] = 2
    numbering = DofNumbering(mesh=mesh, dofs=build_numbering_dofs(model.node_components()))
    a, b, c = 1e-3, -2e-3, 5e-4
    g = np.array([[1e-4, 3e-5], [-2e-5, 2e-4]])

    def state(xy):
        x, y = xy[:, 0], xy[:, 1]
        w = 0.5 * (a * x * x + b * y * y) + c * x * y
        uv = xy @ g.T
        return np.stack([uv[:, 0], uv[:, 1], w, b * y + c * x, -(a * x + c * y), 0 * x], axis=1)

    u = nodal(numbering, mesh, ROTATION, state)
    fields = plate_element_fields(
        model,
        characteristics,
        field,
        numbering,
        np.arange(mesh.n_cells),
        u[None],
        ["SIEF_ELGA", "SIGM_ELNO"],
    )
    cos, sin = _output_axis((0.0, 0.0))
    curvature = _rotated(LAW @ np.array([-a, -b, -2 * c]), cos, sin)
    strain = _rotated(LAW @ np.array([g[0, 0], g[1, 1], g[0, 1] + g[1, 0]]), cos, sin)
    z = H * np.array([-0.5, -0.25, 0.0, 0.0, 0.25, 0.5])
    in_plane = strain[None, :] + z[:, None] * curvature[None, :]
    expected = np.zeros((6, 6))
    expected[:, [0, 1, 3]] = in_plane
    n_points = 3 if kind == "TRIA3" else 4
    n_nodes = len(mesh.cell_nodes[0])
    for name, count in (("SIEF_ELGA", n_points), ("SIGM_ELNO", n_nodes)):
        got = fields[name].values[0, :, : count * 6].reshape(mesh.n_cells, count, 6, 6)
        assert fields[name].sub_points == 6
        # shears: exact on triangles only (see the EFGE test)
        columns = [0, 1, 2, 3, 4, 5] if kind == "TRIA3" else [0, 1, 2, 3]
        error = np.abs(got - expected[None, None])[..., columns].max()
        assert error < 1e-9 * np.abs(expected).max()


@pytest.mark.parametrize("layers", [1, 2, 5])
def test_efge_elga_integrates_the_layer_stresses_back(layers):
    """EFGE_ELGA (te0451): Simpson's rule on each layer integrates the linear
    in-plane and parabolic shear profiles exactly, giving back N, M and Q."""
    from asterlite.fem.plate_fields import _layer_stresses, through_thickness_forces

    rng = np.random.default_rng(layers)
    forces = rng.normal(size=(2, 3, 4, 8)) + 1j * rng.normal(size=(2, 3, 4, 8))
    thickness = np.array([0.01, 0.2, 1.5])
    sigma = _layer_stresses(forces, thickness, layers)
    back = through_thickness_forces(sigma, thickness)
    np.testing.assert_allclose(back, forces, rtol=1e-12, atol=1e-12 * np.abs(forces).max())


@pytest.mark.parametrize("kind", KINDS)
def test_efge_elga_of_the_constant_patch(kind):
    """On the bending and membrane patch, EFGE_ELGA holds at every Gauss
    point the constant N and M of EFGE_ELNO, and on triangles no shear
    (ANGL_REP (30, 10), 3 layers)."""
    mesh = tilted(grid_mesh(kind, (3, 3), (1.0, 1.3), jitter=0.25, seed=2), ROTATION)
    model, characteristics, field = plate_model(mesh)
    for shell in characteristics.shells.values():
        shell["ANGL_REP"], shell["COQUE_NCOU"] = (30.0, 10.0), 3
    numbering = DofNumbering(mesh=mesh, dofs=build_numbering_dofs(model.node_components()))
    a, b, c = 1e-3, -2e-3, 5e-4
    g = np.array([[1e-4, 3e-5], [-2e-5, 2e-4]])

    def state(xy):
        x, y = xy[:, 0], xy[:, 1]
        w = 0.5 * (a * x * x + b * y * y) + c * x * y
        uv = xy @ g.T
        return np.stack([uv[:, 0], uv[:, 1], w, b * y + c * x, -(a * x + c * y), 0 * x], axis=1)

    u = nodal(numbering, mesh, ROTATION, state)
    cells = np.arange(mesh.n_cells)
    efge = plate_element_fields(
        model, characteristics, field, numbering, cells, u[None], ["EFGE_ELGA"]
    )["EFGE_ELGA"]
    cos, sin = _output_axis((30.0, 10.0))
    moments = _rotated(H**3 / 12 * LAW @ np.array([-a, -b, -2 * c]), cos, sin)
    membrane = _rotated(H * LAW @ np.array([g[0, 0], g[1, 1], g[0, 1] + g[1, 0]]), cos, sin)
    expected = np.concatenate([membrane, moments])
    points = 3 if kind == "TRIA3" else 4
    got = efge.values[0, :, :points, :]
    assert np.abs(got[..., :6] - expected).max() < 1e-9 * np.abs(expected).max()
    if kind == "TRIA3":  # the shear of distorted quadrangles is approximate (dkqtxy)
        assert np.abs(got[..., 6:]).max() < 1e-9 * np.abs(expected).max()
