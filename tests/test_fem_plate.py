"""DKT plates (DKT triangles, DKQ quadrangles): constant-curvature and
membrane patch tests on distorted, tilted meshes, rigid modes, masses, the
offset plate as a transformed centred one, and a simply supported square
plate's frequency converging to Kirchhoff's."""

from __future__ import annotations

import numpy as np
import pytest
import scipy.sparse.linalg as spla

from asterlite.concepts.assembly import (
    DofNumbering,
    ElementCharacteristics,
    Material,
    MaterialField,
    Model,
)
from asterlite.fem.assemble import assemble_blocks, build_numbering_dofs
from asterlite.fem.elements import element_blocks
from asterlite.fem.frames import rotation_from_angles
from tests.test_fem_plane import grid_mesh

E, NU, RHO, H = 2.1e11, 0.3, 7800.0, 0.01
KINDS = ("TRIA3", "QUAD4")


def plate_model(mesh, thickness=H, offset=0.0, rotary=0.0, drz=1e-5):
    cells = range(mesh.n_cells)
    model = Model(mesh=mesh, cell_modelisation=dict.fromkeys(cells, "DKT"))
    shell = {"EPAIS": thickness, "COEF_RIGI_DRZ": drz, "INER_ROTA": rotary, "EXCENTREMENT": offset}
    characteristics = ElementCharacteristics(model=model, shells={c: dict(shell) for c in cells})
    material = Material(behaviours={"ELAS": {"E": E, "NU": NU, "RHO": RHO}})
    field = MaterialField(mesh=mesh, cell_material=dict.fromkeys(cells, material))
    return model, characteristics, field


def assembled(mesh, matrix, **shell):
    model, characteristics, field = plate_model(mesh, **shell)
    numbering = DofNumbering(mesh=mesh, dofs=build_numbering_dofs(model.node_components()))
    blocks = element_blocks(model, characteristics, matrix, materials=field)
    return numbering, assemble_blocks(blocks, numbering)


def tilted(mesh, rotation):
    mesh.coords = mesh.coords @ rotation.T
    return mesh


def nodal(numbering, mesh, rotation, field):
    """Global DOF values of local fields field(xy) -> (n, 6) (u, v, w, rx, ry, rz)."""
    xy = (mesh.coords @ rotation)[:, :2]
    local = field(xy)
    glob = np.concatenate([local[:, :3] @ rotation.T, local[:, 3:] @ rotation.T], axis=1)
    order = ("DX", "DY", "DZ", "DRX", "DRY", "DRZ")
    comps = np.array([order.index(c) for c in numbering.dof_components])
    return glob[numbering.dof_nodes, comps]


ROTATION = rotation_from_angles(np.array([[0.4, -0.3, 0.7]]))[0].T


def _area(mesh):
    total = 0.0
    for cell in mesh.cell_nodes:
        p = (mesh.coords @ ROTATION)[list(cell), :2]
        total += 0.5 * np.sum(p[:, 0] * np.roll(p[:, 1], -1) - np.roll(p[:, 0], -1) * p[:, 1])
    return total


@pytest.mark.parametrize("kind", KINDS)
def test_constant_curvature_and_membrane_patch(kind):
    """w = (a x^2 + b y^2)/2 + c x y with rotations beta = -grad w (DRY = beta_x,
    DRX = -beta_y) and a linear membrane field: the energy is half the area
    times kappa D_f kappa + eps D_m eps, exactly, on a distorted tilted mesh."""
    mesh = tilted(grid_mesh(kind, (3, 3), (1.0, 1.3), jitter=0.25, seed=2), ROTATION)
    numbering, k = assembled(mesh, "K")
    a, b, c = 1e-3, -2e-3, 5e-4
    g = np.array([[1e-4, 3e-5], [-2e-5, 2e-4]])

    def field(xy):
        x, y = xy[:, 0], xy[:, 1]
        beta_x, beta_y = -(a * x + c * y), -(b * y + c * x)
        w = 0.5 * (a * x * x + b * y * y) + c * x * y
        uv = xy @ g.T
        return np.stack([uv[:, 0], uv[:, 1], w, -beta_y, beta_x, 0 * x], axis=1)

    u = nodal(numbering, mesh, ROTATION, field)
    kappa = np.array([-a, -b, -2 * c])
    eps = np.array([g[0, 0], g[1, 1], g[0, 1] + g[1, 0]])
    law = np.array([[1, NU, 0], [NU, 1, 0], [0, 0, (1 - NU) / 2]]) * E / (1 - NU**2)
    expected = 0.5 * _area(mesh) * (H**3 / 12 * kappa @ law @ kappa + H * eps @ law @ eps)
    assert 0.5 * u @ (k @ u) == pytest.approx(expected, rel=1e-10)


@pytest.mark.parametrize("kind", KINDS)
def test_rigid_modes_and_mass(kind):
    mesh = tilted(grid_mesh(kind, (2, 2), (1.0, 0.8), jitter=0.2, seed=1), ROTATION)
    numbering, k = assembled(mesh, "K")
    _, m = assembled(mesh, "M")
    rigid = [
        lambda xy: np.tile([1.0, 0, 0, 0, 0, 0], (len(xy), 1)),
        lambda xy: np.tile([0, 1.0, 0, 0, 0, 0], (len(xy), 1)),
        lambda xy: np.tile([0, 0, 1.0, 0, 0, 0], (len(xy), 1)),
        # rotation about local x: w = y, theta_x = 1
        lambda xy: np.stack(
            [0 * xy[:, 0]] * 2 + [xy[:, 1], 1 + 0 * xy[:, 0]] + [0 * xy[:, 0]] * 2, 1
        ),
        # in-plane rotation without DRZ: u = -y, v = x
        lambda xy: np.stack([-xy[:, 1], xy[:, 0]] + [0 * xy[:, 0]] * 4, 1),
    ]
    scale = abs(k).max()
    for field in rigid:
        u = nodal(numbering, mesh, ROTATION, field)
        assert np.abs(k @ u).max() < 1e-9 * scale
    area = _area(mesh)
    for field in rigid[:3]:
        u = nodal(numbering, mesh, ROTATION, field)
        assert u @ (m @ u) == pytest.approx(RHO * H * area, rel=1e-12)


@pytest.mark.parametrize("kind", KINDS)
def test_offset_plate_patch(kind):
    """An offset e moves the mid-surface: on the patch fields its strain is
    eps + e kappa, so the energy is half the area times
    (eps + e kappa) D_m (eps + e kappa) + kappa D_f kappa, exactly."""
    mesh = tilted(grid_mesh(kind, (3, 2), (1.0, 0.8), jitter=0.2, seed=4), ROTATION)
    offset = 0.02
    numbering, k = assembled(mesh, "K", offset=offset)
    a, b, c = 1e-3, -2e-3, 5e-4
    g = np.array([[1e-4, 3e-5], [-2e-5, 2e-4]])

    def field(xy):
        x, y = xy[:, 0], xy[:, 1]
        beta_x, beta_y = -(a * x + c * y), -(b * y + c * x)
        w = 0.5 * (a * x * x + b * y * y) + c * x * y
        uv = xy @ g.T
        return np.stack([uv[:, 0], uv[:, 1], w, -beta_y, beta_x, 0 * x], axis=1)

    u = nodal(numbering, mesh, ROTATION, field)
    kappa = np.array([-a, -b, -2 * c])
    eps = np.array([g[0, 0], g[1, 1], g[0, 1] + g[1, 0]]) + offset * kappa
    law = np.array([[1, NU, 0], [NU, 1, 0], [0, 0, (1 - NU) / 2]]) * E / (1 - NU**2)
    expected = 0.5 * _area(mesh) * (H**3 / 12 * kappa @ law @ kappa + H * eps @ law @ eps)
    assert 0.5 * u @ (k @ u) == pytest.approx(expected, rel=1e-10)


def _square_plate_frequency(kind, n):
    side = 1.0
    mesh = grid_mesh(kind, (n, n), (side, side))
    numbering, k = assembled(mesh, "K")
    _, m = assembled(mesh, "M")
    xy = mesh.coords[numbering.dof_nodes, :2]
    edge = np.any((np.abs(xy) < 1e-12) | (np.abs(xy - side) < 1e-12), axis=1)
    comps = np.array(numbering.dof_components)
    # simply supported, membrane and drilling held
    fixed = (edge & (comps == "DZ")) | np.isin(comps, ["DX", "DY", "DRZ"])
    free = ~fixed
    kf, mf = k[free][:, free].tocsc(), m[free][:, free].tocsc()
    value = spla.eigsh(kf, k=1, M=mf, sigma=0.0, return_eigenvectors=False)[0]
    return np.sqrt(value) / (2 * np.pi)


@pytest.mark.parametrize("kind", KINDS)
def test_simply_supported_square_plate_converges(kind):
    """f_11 = pi/2 * 2/a^2 sqrt(D / rho h) (Kirchhoff), error falling with h."""
    rigidity = E * H**3 / (12 * (1 - NU**2))
    exact = np.pi / 2 * 2.0 * np.sqrt(rigidity / (RHO * H))
    errors = [abs(_square_plate_frequency(kind, n) / exact - 1) for n in (4, 8, 16)]
    assert errors[0] > errors[1] > errors[2]
    assert errors[2] < 3e-3


@pytest.mark.parametrize("kind", KINDS)
def test_gravity_spreads_the_weight_on_the_corners(kind):
    """PESANTEUR on plates: rho h g A in total, no moments; a rectangle's
    corners take a quarter each (code_aster's te0032)."""
    from asterlite.fem.loads import gravity_terms

    mesh = tilted(grid_mesh(kind, (2, 2), (1.0, 0.8), jitter=0.2, seed=6), ROTATION)
    model, characteristics, field = plate_model(mesh)
    terms = gravity_terms(model, characteristics, 9.81, (0.0, 0.0, -1.0), materials=field)
    total = np.zeros(3)
    for _, comp, value in terms:
        assert comp in ("DX", "DY", "DZ")
        total[("DX", "DY", "DZ").index(comp)] += value
    assert total == pytest.approx([0.0, 0.0, -9.81 * RHO * H * _area(mesh)], abs=1e-9)
    if kind == "QUAD4":
        square = grid_mesh("QUAD4", (1, 1), (2.0, 1.0))
        model, characteristics, field = plate_model(square)
        forces = [
            v
            for _, c, v in gravity_terms(model, characteristics, 1.0, (0, 0, 1), field)
            if c == "DZ"
        ]
        assert forces == pytest.approx([RHO * H * 2.0 / 4] * 4)


@pytest.mark.parametrize("kind", KINDS)
def test_diagonal_mass(kind):
    """MASS_MECA_DIAG: diagonal, each translation summing to rho h A per cell,
    rotations scaled like their translation (code_aster's dialum)."""
    mesh = tilted(grid_mesh(kind, (1, 1), (1.0, 0.8), jitter=0.0), ROTATION)
    model, characteristics, field = plate_model(mesh)
    (block,) = element_blocks(model, characteristics, "M", materials=field, lumped=True)
    (full,) = element_blocks(model, characteristics, "M", materials=field)
    for lumped, consistent in zip(block.matrices, full.matrices, strict=True):
        assert np.count_nonzero(lumped - np.diag(np.diag(lumped))) == 0
        d, c = np.diag(lumped).reshape(-1, 6), np.diag(consistent).reshape(-1, 6)
        area = RHO * H * _area(mesh) / (2 if kind == "TRIA3" else 1)
        assert d[:, :3].sum(axis=0) == pytest.approx([area] * 3)
        ratio = d[:, :3].sum(axis=0) / c[:, :3].sum(axis=0)
        nonzero = c[:, 3:] != 0.0
        assert np.allclose(d[:, 3:][nonzero], (c[:, 3:] * ratio)[nonzero])
