"""Plane and axisymmetric solids (D_PLAN, C_PLAN, AXIS): code_aster's Gauss
families, patch tests on distorted meshes, rigid modes, mass, edge loads,
scikit-fem's plane-strain stiffness, and a plane-stress cantilever's
frequencies against beam theory with h-convergence."""

from __future__ import annotations

import numpy as np
import pytest
import scipy.sparse.linalg as spla

from asterlite.concepts.assembly import DofNumbering, Material, MaterialField, Model
from asterlite.concepts.mesh import Mesh
from asterlite.fem.assemble import assemble_blocks, build_numbering_dofs
from asterlite.fem.elements import ElementError, element_blocks
from asterlite.fem.plane_elements import elasticity, surface_cells
from asterlite.fem.plane_loads import edge_force_terms, edge_pressure_terms, surface_force_terms

E, NU, RHO = 2.0e11, 0.3, 7800.0
KINDS = ("TRIA3", "TRIA6", "QUAD4", "QUAD8", "QUAD9")
MODELISATIONS = ("D_PLAN", "C_PLAN", "AXIS")
_QUAD_MIDDLE = [(0, 1), (1, 2), (2, 3), (3, 0)]
_TRIA_MIDDLE = [(0, 1), (1, 2), (2, 0)]


def grid_mesh(kind, n=(2, 2), size=(1.0, 1.0), origin=(0.0, 0.0), jitter=0.0, seed=0):
    """A rectangle meshed with ``kind`` cells (counter-clockwise, code_aster's
    node order), straight edges; interior vertices moved by ``jitter`` x h."""
    nx, ny = n
    xs = np.linspace(origin[0], origin[0] + size[0], nx + 1)
    ys = np.linspace(origin[1], origin[1] + size[1], ny + 1)
    points = np.array([(x, y) for y in ys for x in xs])
    if jitter:
        rng = np.random.default_rng(seed)
        h = np.array(size) / np.array(n)
        inside = np.ones(len(points), bool)
        for axis in (0, 1):
            low, high = origin[axis], origin[axis] + size[axis]
            inside &= (points[:, axis] > low + 1e-12) & (points[:, axis] < high - 1e-12)
        points[inside] += jitter * h * rng.uniform(-1, 1, (int(inside.sum()), 2))
    vid = lambda i, j: j * (nx + 1) + i  # noqa: E731
    cells = []
    for j in range(ny):
        for i in range(nx):
            quad = [vid(i, j), vid(i + 1, j), vid(i + 1, j + 1), vid(i, j + 1)]
            if kind.startswith("QUAD"):
                cells.append(quad)
            else:
                cells += [[quad[0], quad[1], quad[2]], [quad[0], quad[2], quad[3]]]
    points = [tuple(p) for p in points]
    index = {p: k for k, p in enumerate(points)}

    def node(p):
        p = tuple(np.round(p, 14))
        if p not in index:
            index[p] = len(points)
            points.append(p)
        return index[p]

    points = [tuple(np.round(p, 14)) for p in points]
    index = {p: k for k, p in enumerate(points)}
    full = []
    for cell in cells:
        xy = np.array([points[v] for v in cell])
        extra = []
        if kind in ("TRIA6", "QUAD8", "QUAD9"):
            pairs = _TRIA_MIDDLE if kind == "TRIA6" else _QUAD_MIDDLE
            extra = [node((xy[a] + xy[b]) / 2) for a, b in pairs]
        if kind == "QUAD9":
            extra.append(node(xy.mean(axis=0)))
        full.append(tuple(cell) + tuple(extra))
    coords = np.zeros((len(points), 3))
    coords[:, :2] = points
    return Mesh(
        coords=coords,
        node_names=[f"N{i + 1}" for i in range(len(coords))],
        cell_names=[f"M{i + 1}" for i in range(len(full))],
        cell_types=[kind] * len(full),
        cell_nodes=full,
    )


def plane_model(mesh, modelisation, **extra):
    model = Model(mesh=mesh, cell_modelisation=dict.fromkeys(range(mesh.n_cells), modelisation))
    material = Material(behaviours={"ELAS": {"E": E, "NU": NU, "RHO": RHO, **extra}})
    field = MaterialField(mesh=mesh, cell_material=dict.fromkeys(range(mesh.n_cells), material))
    return model, field


def assembled(mesh, modelisation, matrix="K", **extra):
    model, field = plane_model(mesh, modelisation, **extra)
    numbering = DofNumbering(mesh=mesh, dofs=build_numbering_dofs(model.node_components()))
    blocks = element_blocks(model, None, matrix, materials=field)
    return model, field, numbering, assemble_blocks(blocks, numbering)


def _nodal(numbering, mesh, field_of_xy):
    xy = mesh.coords[numbering.dof_nodes, :2]
    values = field_of_xy(xy)
    comps = np.array([c == "DY" for c in numbering.dof_components], dtype=int)
    return values[np.arange(len(xy)), comps]


def _area(mesh):
    total = 0.0
    for cell in mesh.cell_nodes:
        n = 3 if len(cell) in (3, 6) else 4
        p = mesh.coords[list(cell[:n]), :2]
        total += 0.5 * np.sum(p[:, 0] * np.roll(p[:, 1], -1) - np.roll(p[:, 0], -1) * p[:, 1])
    return total


def test_code_aster_gauss_families():
    """MEDPTR3 ... MEAXQU9: RIGI and MASS families of code_aster's catalogue."""
    assert {k: (v.rigi, v.mass) for k, v in surface_cells("D_PLAN").items()} == {
        "TRIA3": ("FPG1", "FPG3"),
        "TRIA6": ("FPG3", "FPG6"),
        "QUAD4": ("FPG4", "FPG4"),
        "QUAD8": ("FPG9", "FPG9"),
        "QUAD9": ("FPG9", "FPG9"),
    }
    assert surface_cells("C_PLAN") == surface_cells("D_PLAN")
    assert surface_cells("AXIS")["TRIA6"].rigi == "FPG6"


@pytest.mark.parametrize("jitter", [0.0, 0.3])
@pytest.mark.parametrize("modelisation", MODELISATIONS)
@pytest.mark.parametrize("kind", KINDS)
def test_patch_test(kind, modelisation, jitter):
    """A linear displacement field (for AXIS one with u_r = a r + b z and
    u_z linear, which is exactly representable and an equilibrium state only
    for uniform strain): no force at the interior nodes, and the energy is
    half the integral of eps D eps."""
    origin = (1.0, 0.0) if modelisation == "AXIS" else (0.0, 0.0)
    mesh = grid_mesh(kind, (3, 3), (1.0, 1.2), origin, jitter=jitter, seed=7)
    _, _, numbering, k = assembled(mesh, modelisation)
    if modelisation == "AXIS":
        # u_r = a r, u_z = c z: eps = (a, c, a, 0), uniform
        a, c = 1e-3, -2e-3
        u = _nodal(numbering, mesh, lambda xy: np.stack([a * xy[:, 0], c * xy[:, 1]], 1))
        eps = np.array([a, c, a, 0.0])
    else:
        grad = np.array([[1e-3, 4e-4], [-2e-4, 2e-3]])
        u = _nodal(numbering, mesh, lambda xy: xy @ grad.T)
        eps = np.array([grad[0, 0], grad[1, 1], 0.0, grad[0, 1] + grad[1, 0]])
    f = k @ u
    xy = mesh.coords[numbering.dof_nodes, :2]
    lo, hi = np.array(origin), np.array(origin) + (1.0, 1.2)
    interior = np.all((xy > lo + 1e-9) & (xy < hi - 1e-9), axis=1)
    assert np.abs(f[interior]).max() < 1e-8 * np.abs(f).max()
    d = elasticity(modelisation, [E], [NU])[0]
    if modelisation == "AXIS":
        # int r dA of the polygon cells: area times the centroid's radius
        weight = sum(_area_moment(mesh, c) for c in range(mesh.n_cells))
    else:
        weight = _area(mesh)
    assert 0.5 * u @ f == pytest.approx(0.5 * weight * eps @ d @ eps, rel=1e-11)


def _area_moment(mesh, cell):
    """int x dA over one straight-sided cell."""
    nodes = mesh.cell_nodes[cell]
    n = 3 if len(nodes) in (3, 6) else 4
    p = mesh.coords[list(nodes[:n]), :2]
    x, y = p[:, 0], p[:, 1]
    x1, y1 = np.roll(x, -1), np.roll(y, -1)
    cross = x * y1 - x1 * y
    return float(np.sum((x + x1) * cross) / 6.0)


@pytest.mark.parametrize("modelisation", ("D_PLAN", "C_PLAN"))
@pytest.mark.parametrize("kind", KINDS)
def test_rigid_modes_and_mass(kind, modelisation):
    mesh = grid_mesh(kind, (2, 3), (1.0, 1.5), jitter=0.25, seed=2)
    _, _, numbering, k = assembled(mesh, modelisation)
    _, _, _, m = assembled(mesh, modelisation, "M")
    for rigid in (
        lambda xy: np.stack([np.ones(len(xy)), np.zeros(len(xy))], 1),
        lambda xy: np.stack([np.zeros(len(xy)), np.ones(len(xy))], 1),
        lambda xy: np.stack([-xy[:, 1], xy[:, 0]], 1),
    ):
        u = _nodal(numbering, mesh, rigid)
        assert np.abs(k @ u).max() < 1e-6 * abs(k).max()
    ux = _nodal(numbering, mesh, lambda xy: np.stack([np.ones(len(xy)), 0 * xy[:, 0]], 1))
    assert ux @ m @ ux == pytest.approx(RHO * 1.5, rel=1e-12)
    vals = np.linalg.eigvalsh(k.toarray())
    assert np.sum(np.abs(vals) < 1e-8 * vals.max()) == 3  # exactly the rigid modes


@pytest.mark.parametrize("kind", KINDS)
def test_axis_mass_and_axial_translation(kind):
    """One radian of a ring: mass rho int r dA; only the axial translation is free."""
    mesh = grid_mesh(kind, (2, 2), (0.5, 1.0), origin=(2.0, 0.0), jitter=0.2, seed=4)
    _, _, numbering, k = assembled(mesh, "AXIS")
    _, _, _, m = assembled(mesh, "AXIS", "M")
    uz = _nodal(numbering, mesh, lambda xy: np.stack([0 * xy[:, 0], np.ones(len(xy))], 1))
    moment = sum(_area_moment(mesh, c) for c in range(mesh.n_cells))
    assert uz @ m @ uz == pytest.approx(RHO * moment, rel=1e-12)
    assert np.abs(k @ uz).max() < 1e-6 * abs(k).max()
    vals = np.linalg.eigvalsh(k.toarray())
    assert np.sum(np.abs(vals) < 1e-8 * vals.max()) == 1


def test_rayleigh_damping_and_no_lumped_mass():
    mesh = grid_mesh("QUAD4", (2, 2))
    _, _, _, k = assembled(mesh, "D_PLAN")
    _, _, _, m = assembled(mesh, "D_PLAN", "M")
    _, _, _, c = assembled(mesh, "D_PLAN", "A", AMOR_ALPHA=1e-4, AMOR_BETA=3.0)
    assert abs(c - (1e-4 * k + 3.0 * m)).max() < 1e-12 * abs(c).max()
    model, field = plane_model(mesh, "D_PLAN")
    with pytest.raises(ElementError, match="MASS_MECA_DIAG"):
        element_blocks(model, None, "M", materials=field, lumped=True)


def test_plane_strain_stiffness_matches_scikit_fem():
    """P1 triangles: asterlite's D_PLAN matrix against scikit-fem's
    linear_elasticity with the plane-strain Lame parameters."""
    skfem = pytest.importorskip("skfem")
    from skfem.models.elasticity import lame_parameters, linear_elasticity

    mesh = grid_mesh("TRIA3", (3, 2), (1.0, 0.7), jitter=0.3, seed=9)
    _, _, numbering, k = assembled(mesh, "D_PLAN")
    sk_mesh = skfem.MeshTri(mesh.coords[:, :2].T.copy(), np.array(mesh.cell_nodes).T.copy())
    basis = skfem.Basis(sk_mesh, skfem.ElementVector(skfem.ElementTriP1()))
    reference = skfem.asm(linear_elasticity(*lame_parameters(E, NU)), basis).toarray()
    # scikit-fem's DOF of (node, component) from its nodal_dofs table
    order = [
        basis.nodal_dofs[0 if c == "DX" else 1, n]
        for n, c in zip(numbering.dof_nodes, numbering.dof_components, strict=True)
    ]
    assert np.allclose(k.toarray(), reference[np.ix_(order, order)], rtol=1e-12, atol=1e-3)


# -- loads -------------------------------------------------------------------------------


def _edge_mesh(kind_edge, points, axis_model="D_PLAN"):
    coords = np.zeros((len(points), 3))
    coords[:, :2] = points
    mesh = Mesh(
        coords=coords,
        node_names=[f"N{i + 1}" for i in range(len(points))],
        cell_names=["E1"],
        cell_types=[kind_edge],
        cell_nodes=[tuple(range(len(points)))],
    )
    return Model(mesh=mesh, cell_modelisation={0: axis_model})


def _sum(terms):
    out = {}
    for node, comp, value in terms:
        out[node, comp] = out.get((node, comp), 0.0) + value
    return out


def test_edge_pressure_and_shear():
    """A pressure on an edge running along +x pushes along +y (n = (t_y, -t_x)),
    CISA_2D acts along the tangent; SEG3 splits p L as L/6, L/6, 2L/3."""
    model = _edge_mesh("SEG2", [(0.0, 0.0), (2.0, 0.0)])
    f = _sum(edge_pressure_terms(model, [0], 3.0, shear=5.0))
    assert f[0, "DY"] == pytest.approx(3.0) and f[1, "DY"] == pytest.approx(3.0)
    assert f[0, "DX"] == pytest.approx(5.0) and f[1, "DX"] == pytest.approx(5.0)
    model = _edge_mesh("SEG3", [(0.0, 0.0), (0.0, 3.0), (0.0, 1.5)])
    f = _sum(edge_pressure_terms(model, [0], 2.0))
    # tangent +y: normal (1, 0), force -p n along -x
    assert [f[n, "DX"] for n in range(3)] == pytest.approx([-1.0, -1.0, -4.0])
    f = _sum(edge_force_terms(model, [0], (0.0, 1.0)))
    assert sum(f[n, "DY"] for n in range(3)) == pytest.approx(3.0)


def test_axis_edge_and_surface_loads_carry_the_radius():
    model = _edge_mesh("SEG2", [(1.0, 0.0), (3.0, 0.0)], "AXIS")
    f = _sum(edge_force_terms(model, [0], (0.0, 1.0)))
    # int r dr from 1 to 3 = 4, split (r-weighted) 5/3 and 7/3
    assert [f[0, "DY"], f[1, "DY"]] == pytest.approx([5.0 / 3.0, 7.0 / 3.0])
    mesh = grid_mesh("QUAD8", (2, 2), (1.0, 1.0), origin=(1.0, 0.0))
    model, field = plane_model(mesh, "AXIS")
    f = _sum(surface_force_terms(model, range(mesh.n_cells), (0.0, -9.81), field, per_mass=True))
    assert sum(v for (n, c), v in f.items() if c == "DY") == pytest.approx(-9.81 * RHO * 1.5)


# -- a plane-stress cantilever against beam theory -----------------------------------------

LENGTH, DEPTH = 10.0, 1.0


def _cantilever_frequency(kind, along, across):
    mesh = grid_mesh(kind, (along, across), (LENGTH, DEPTH))
    _, _, numbering, k = assembled(mesh, "C_PLAN")
    _, _, _, m = assembled(mesh, "C_PLAN", "M")
    free = mesh.coords[numbering.dof_nodes, 0] > 1e-12
    kf, mf = k[free][:, free].tocsc(), m[free][:, free].tocsc()
    vals = spla.eigsh(kf, k=1, M=mf, sigma=-1.0, return_eigenvectors=False)
    return float(np.sqrt(vals.min()) / (2 * np.pi))


def _timoshenko_frequency():
    """First bending frequency of a clamped-free Timoshenko beam (rectangle,
    shear coefficient 5/6): the root of the free-end determinant of the
    transfer matrix of w' = psi + V/kGA, psi' = M/EI, M' = -V - rho I w^2 psi,
    V' = -rho A w^2 w."""
    import scipy.linalg as sla
    from scipy.optimize import brentq

    area, inertia = DEPTH, DEPTH**3 / 12.0
    shear = E / (2 * (1 + NU)) * 5.0 / 6.0 * area

    def free_end(omega):
        a = np.zeros((4, 4))
        a[0, 1], a[0, 3] = 1.0, 1.0 / shear
        a[1, 2] = 1.0 / (E * inertia)
        a[2, 3], a[2, 1] = -1.0, -RHO * inertia * omega**2
        a[3, 0] = -RHO * area * omega**2
        t = sla.expm(a * LENGTH)
        return np.linalg.det(t[2:, 2:])  # M, V at the tip from M, V at the root

    euler = 1.875104**2 * np.sqrt(E * inertia / (RHO * area * LENGTH**4))
    omega = brentq(free_end, 0.9 * euler, 1.0 * euler)
    return omega / (2 * np.pi), euler / (2 * np.pi)


def test_cantilever_converges_to_beam_theory():
    """Plane stress, L/h = 10: the QUAD8 frequency converges (error falling
    with h) to within 0.5 % of Timoshenko's, below Euler-Bernoulli's."""
    timoshenko, euler = _timoshenko_frequency()
    assert timoshenko < euler
    errors = []
    for along, across in ((10, 1), (20, 2), (40, 4)):
        errors.append(abs(_cantilever_frequency("QUAD8", along, across) / timoshenko - 1))
    assert errors[0] > errors[1] > errors[2]
    assert errors[2] < 5e-3
    # the linear quadrangle locks in bending: stiffer, converging from above
    coarse, fine = (_cantilever_frequency("QUAD4", n, m) for n, m in ((20, 2), (80, 8)))
    assert coarse > fine > timoshenko * 0.995


def test_folded_cells_are_found_as_code_aster_does():
    """VERI_JACOBIEN: a QUAD8 whose mid-side node crosses the opposite side
    has Jacobians of both signs; a cell numbered clockwise (negative
    everywhere) is not flagged, as in code_aster's te0328."""
    from asterlite.fem.jacobian_check import folded_cells

    mesh = grid_mesh("QUAD8", (2, 1))
    model, _ = plane_model(mesh, "D_PLAN")
    assert folded_cells(model) == []
    middle = mesh.cell_nodes[0][4]  # the middle of side 1-2
    mesh.coords[middle, 1] += 1.2
    assert folded_cells(model) == [0]
    mesh = grid_mesh("QUAD4", (1, 1))
    mesh.cell_nodes[0] = tuple(reversed(mesh.cell_nodes[0]))
    assert folded_cells(plane_model(mesh, "C_PLAN")[0]) == []


def test_axis_cells_left_of_the_axis_are_found():
    from asterlite.fem.jacobian_check import negative_radius_nodes

    mesh = grid_mesh("QUAD4", (2, 1), (1.0, 1.0), origin=(0.0, 0.0))
    model, _ = plane_model(mesh, "AXIS")
    assert negative_radius_nodes(model) == []
    mesh.coords[0, 0] = -0.1
    assert negative_radius_nodes(model) == [(0, 0)]


def test_plane_models_are_two_dimensional():
    """A model of plane solids (with their absorbing edges or 2D discrete
    elements) is 2D: FACE_IMPO DNOR, LIAISON_SOLIDE use edge normals and DRZ."""
    mesh = grid_mesh("QUAD4", (1, 1))
    for names in (("D_PLAN",), ("C_PLAN", "2D_DIS_T"), ("AXIS",), ("D_PLAN", "D_PLAN_ABSO")):
        model = Model(mesh=mesh, cell_modelisation={0: names[0]}, node_modelisation={})
        for k, name in enumerate(names[1:]):
            model.node_modelisation[k] = name
        assert model.dim == 2
    assert Model(mesh=mesh, cell_modelisation={0: "DKT"}).dim == 3
