"""3D solid elements (MODELISATION='3D'): reference elements and code_aster's
Gauss families, element matrices (patch tests, rigid modes, mass), loads,
mass properties, and a cantilever against beam theory with h- and
p-convergence."""

from __future__ import annotations

from itertools import product
from math import factorial

import numpy as np
import pytest
import scipy.linalg as sla
import scipy.sparse.linalg as spla

from asterlite.concepts.assembly import DofNumbering
from asterlite.fem.assemble import assemble_blocks, assemble_terms, build_numbering_dofs
from asterlite.fem.elements import element_blocks
from asterlite.fem.mass_properties import mass_properties
from asterlite.fem.solid_elements import stiffness_matrices
from asterlite.fem.solid_loads import (
    face_force_terms,
    pressure_terms,
    solid_inertia,
    volume_force_terms,
)
from asterlite.fem.solid_reference import (
    FACE_CELLS,
    REFERENCE_ELEMENTS,
    VOLUME_CELLS,
    gauss_family,
)
from tests.solid_meshes import box_mesh, solid_model

KINDS = sorted(VOLUME_CELLS)
E, NU, RHO = 2.0e11, 0.3, 7800.0


# -- reference elements ----------------------------------------------------------------


@pytest.mark.parametrize("name", sorted(REFERENCE_ELEMENTS))
def test_shape_functions_interpolate_and_reproduce_linear_fields(name):
    ref = REFERENCE_ELEMENTS[name]
    assert np.allclose(ref.values(ref.nodes), np.eye(ref.n_nodes), atol=1e-14)
    rng = np.random.default_rng(3)
    points = 0.2 + 0.2 * rng.random((6, ref.dim))  # inside every reference element
    values = ref.values(points).real
    assert np.allclose(values.sum(axis=1), 1.0)
    assert np.allclose(values @ ref.nodes, points)
    grads = ref.gradients(points)
    assert np.allclose(np.einsum("pnj,ni->pij", grads, ref.nodes), np.eye(ref.dim))
    step = 1e-6
    for axis in range(ref.dim):
        shifted = points.copy()
        shifted[:, axis] += step
        numeric = (ref.values(shifted).real - values) / step
        assert np.allclose(numeric, grads[:, :, axis], atol=1e-5)


def test_penta15_is_code_aster_quadratic_wedge():
    """The 15-node wedge's functions, written out (axis x, triangle y z)."""
    ref = REFERENCE_ELEMENTS["P15"]
    x, y, z = 0.3, 0.2, 0.15
    a = 1.0 - y - z
    expected = [
        y * (1 - x) * (2 * y - 2 - x) / 2,
        z * (1 - x) * (2 * z - 2 - x) / 2,
        a * (x - 1) * (x + 2 * y + 2 * z) / 2,
        y * (1 + x) * (2 * y - 2 + x) / 2,
        z * (1 + x) * (2 * z - 2 + x) / 2,
        a * (-x - 1) * (-x + 2 * y + 2 * z) / 2,
        2 * y * z * (1 - x),
        2 * z * a * (1 - x),
        2 * y * a * (1 - x),
        y * (1 - x * x),
        z * (1 - x * x),
        a * (1 - x * x),
        2 * y * z * (1 + x),
        2 * z * a * (1 + x),
        2 * y * a * (1 + x),
    ]
    assert np.allclose(ref.values([x, y, z])[0], expected)


def _cube_moment(powers):
    return np.prod([0.0 if p % 2 else 2.0 / (p + 1) for p in powers])


def _tetra_moment(a, b, c):
    return factorial(a) * factorial(b) * factorial(c) / factorial(a + b + c + 3)


def _triangle_moment(a, b):
    return factorial(a) * factorial(b) / factorial(a + b + 2)


def _pyramid_moment(a, b, c):
    """Over |x| + |y| <= 1 - z, 0 <= z <= 1, with a collapsed 12^3 Gauss rule."""
    t, w = np.polynomial.legendre.leggauss(12)
    u, v, s = np.meshgrid(t, t, (t + 1) / 2, indexing="ij")
    wt = np.einsum("i,j,k->ijk", w, w, w / 2)
    x, y, z = (1 - s) * (u + v) / 2, (1 - s) * (v - u) / 2, s
    return float(np.sum(wt * (1 - s) ** 2 / 2 * x**a * y**b * z**c))


@pytest.mark.parametrize(
    "reference, family, degree",
    [
        ("HE8", "FPG8", 3),
        ("HE8", "FPG27", 5),
        ("TE4", "FPG4", 2),
        ("TE4", "FPG5", 3),
        ("TE4", "FPG15", 5),
        ("PY5", "FPG5", 2),
        ("PY5", "FPG10", 4),
        ("QU4", "FPG4", 3),
        ("QU4", "FPG9", 5),
        ("TR3", "FPG3", 2),
        ("TR3", "FPG6", 4),
    ],
)
def test_gauss_families_are_exact_to_their_degree(reference, family, degree):
    points, weights = gauss_family(reference, family)
    dim = points.shape[1]
    for powers in product(range(degree + 1), repeat=dim):
        if sum(powers) > degree and reference not in ("HE8", "QU4"):
            continue
        if max(powers) > degree:
            continue
        numeric = np.sum(weights * np.prod(points ** np.array(powers), axis=1))
        if reference in ("HE8", "QU4"):
            exact = _cube_moment(powers)
        elif reference == "TE4":
            exact = _tetra_moment(*powers)
        elif reference == "TR3":
            exact = _triangle_moment(*powers)
        else:
            exact = _pyramid_moment(*powers)
        # the triangle's FPG6 weights are code_aster's 15-digit values
        assert numeric == pytest.approx(exact, rel=1e-12, abs=1e-14), powers


@pytest.mark.parametrize("family, degree", [("FPG6", 2), ("FPG21", 5)])
def test_wedge_families_are_products_of_axis_and_triangle_rules(family, degree):
    points, weights = gauss_family("PE6", family)
    for a, b, c in product(range(degree + 1), repeat=3):
        if b + c > degree:
            continue
        numeric = np.sum(weights * points[:, 0] ** a * points[:, 1] ** b * points[:, 2] ** c)
        exact = _cube_moment((a,)) * _triangle_moment(b, c)
        assert numeric == pytest.approx(exact, rel=1e-12, abs=1e-14)


def test_cell_kinds_use_code_aster_families():
    expected = {
        "HEXA8": ("FPG8", "FPG8"),
        "HEXA20": ("FPG27", "FPG27"),
        "HEXA27": ("FPG27", "FPG27"),
        "PENTA6": ("FPG6", "FPG6"),
        "PENTA15": ("FPG21", "FPG21"),
        "TETRA4": ("FPG1", "FPG4"),
        "TETRA10": ("FPG5", "FPG15"),
        "PYRAM5": ("FPG5", "FPG5"),
        "PYRAM13": ("FPG10", "FPG10"),
    }
    assert {k: (v.rigi, v.mass) for k, v in VOLUME_CELLS.items()} == expected
    assert FACE_CELLS["TRIA3"].rigi == "FPG3" and FACE_CELLS["QUAD8"].rigi == "FPG9"


# -- element matrices ------------------------------------------------------------------


def _elasticity(strain):
    lam = E * NU / ((1 + NU) * (1 - 2 * NU))
    mu = E / (2 * (1 + NU))
    return lam * np.trace(strain) * np.eye(3) + 2 * mu * strain


def _distorted_cell(kind, seed=0):
    ref = REFERENCE_ELEMENTS[VOLUME_CELLS[kind].reference]
    rng = np.random.default_rng(seed)
    linear = np.array([[1.2, 0.1, 0.0], [0.05, 0.9, 0.1], [0.0, -0.1, 1.1]])
    return ref.nodes @ linear.T + 0.04 * rng.standard_normal(ref.nodes.shape)


@pytest.mark.parametrize("kind", KINDS)
def test_single_cell_rigid_modes_and_constant_strain_energy(kind):
    spec = VOLUME_CELLS[kind]
    coords = _distorted_cell(kind)
    k = stiffness_matrices(coords[None], spec.reference, spec.rigi, [E], [NU])[0]
    assert np.allclose(k, k.T, rtol=0, atol=1e-9 * np.abs(k).max())
    rigid = [np.tile(e, len(coords)) for e in np.eye(3)]
    rigid += [np.cross(e, coords).ravel() for e in np.eye(3)]
    for mode in rigid:
        assert np.abs(k @ mode).max() < 1e-9 * np.abs(k).max() * np.abs(mode).max()
    strain = np.array([[1.0, 0.3, -0.2], [0.3, -0.5, 0.4], [-0.2, 0.4, 0.7]]) * 1e-3
    u = (coords @ strain.T).ravel()
    volume = float(np.sum(_volumes(kind, coords[None])))
    energy = volume * np.sum(strain * _elasticity(strain))
    assert u @ k @ u == pytest.approx(energy, rel=1e-10)


def _volumes(kind, coords):
    from asterlite.fem.solid_elements import jacobians
    from asterlite.fem.solid_reference import tabulated

    spec = VOLUME_CELLS[kind]
    _, grads, weights = tabulated(spec.reference, spec.mass)
    _, det = jacobians(coords, grads)
    return det @ weights


def _assembled(mesh, matrix="K", lumped=False, **material):
    model, field = solid_model(mesh, **material)
    numbering = DofNumbering(mesh=mesh, dofs=build_numbering_dofs(model.node_components()))
    blocks = element_blocks(model, None, matrix, materials=field, lumped=lumped)
    return model, field, numbering, assemble_blocks(blocks, numbering)


@pytest.mark.parametrize("jitter", [0.0, 0.25])
@pytest.mark.parametrize("kind", KINDS)
def test_patch_test_on_a_distorted_mesh(kind, jitter):
    """A linear displacement field: no force at the interior nodes.

    The 13-node pyramid is rational and its 10-point rule (code_aster's) is
    not exact once the cells are no longer affine: it passes on the regular
    mesh, and to 1e-3 only on the distorted one."""
    mesh = box_mesh(kind, (2, 2, 2), (1.0, 1.2, 0.8), jitter=jitter, seed=5)
    _, _, numbering, k = _assembled(mesh)
    gradient = np.array([[2.0, 0.5, -1.0], [0.1, -0.4, 0.3], [0.7, 0.2, 1.1]]) * 1e-3
    nodes = numbering.dof_nodes
    comps = np.array([["DX", "DY", "DZ"].index(c) for c in numbering.dof_components])
    u = np.einsum("di,di->d", gradient[comps], mesh.coords[nodes]) + 1e-4
    force = k @ u
    coords = mesh.coords[nodes]
    inside = np.all((coords > 1e-9) & (coords < np.array([1.0, 1.2, 0.8]) - 1e-9), axis=1)
    assert inside.any()
    tolerance = 1e-3 if (kind == "PYRAM13" and jitter) else 1e-9
    assert np.abs(force[inside]).max() < tolerance * np.abs(force).max()


@pytest.mark.parametrize("kind", KINDS)
def test_mass_total_and_diagonal_lumping(kind):
    mesh = box_mesh(kind, (2, 1, 1), (2.0, 1.0, 0.5), jitter=0.0)
    _, _, numbering, m = _assembled(mesh, "M")
    _, _, _, lumped = _assembled(mesh, "M", lumped=True)
    x_rows = np.array([c == "DX" for c in numbering.dof_components])
    ones = x_rows.astype(float)
    assert ones @ m @ ones == pytest.approx(RHO * 1.0, rel=1e-12)
    assert ones @ lumped @ ones == pytest.approx(RHO * 1.0, rel=1e-12)
    assert lumped.nnz == numbering.n_dofs and np.all(lumped.diagonal() > 0)


def test_rayleigh_damping_of_solids():
    mesh = box_mesh("HEXA8", (1, 1, 1))
    _, _, _, k = _assembled(mesh, "K")
    _, _, _, m = _assembled(mesh, "M")
    _, _, _, c = _assembled(mesh, "A", AMOR_ALPHA=1e-4, AMOR_BETA=2.0)
    assert np.allclose(c.toarray(), 1e-4 * k.toarray() + 2.0 * m.toarray())


@pytest.mark.parametrize("kind", ["HEXA8", "TETRA10", "HEXA27"])
def test_eigenvalues_match_scikit_fem(kind):
    """The same mesh in scikit-fem (its own elements and quadrature, exact on
    these straight-sided cells): the same free-free spectrum."""
    skfem = pytest.importorskip("skfem")
    from skfem.helpers import dot
    from skfem.models.elasticity import lame_parameters, linear_elasticity

    n, size = (3, 2, 2), (1.5, 1.0, 0.8)
    mesh = box_mesh(kind, n, size)
    _, _, _, k = _assembled(mesh, "K")
    _, _, _, m = _assembled(mesh, "M")
    ours = sla.eigh(k.toarray(), m.toarray(), eigvals_only=True)[6:20]
    if kind == "TETRA10":
        tets = box_mesh("TETRA4", n, size)
        sk_mesh = skfem.MeshTet(tets.coords.T, np.array(tets.cell_nodes).T)
        element = skfem.ElementVector(skfem.ElementTetP2())
    else:
        axes = [np.linspace(0.0, s, k + 1) for s, k in zip(size, n, strict=True)]
        sk_mesh = skfem.MeshHex.init_tensor(*axes)
        base = skfem.ElementHex1() if kind == "HEXA8" else skfem.ElementHex2()
        element = skfem.ElementVector(base)
    basis = skfem.Basis(sk_mesh, element, intorder=6)

    @skfem.BilinearForm
    def mass(u, v, _):
        return RHO * dot(u, v)

    k_sk = linear_elasticity(*lame_parameters(E, NU)).assemble(basis)
    m_sk = mass.assemble(basis)
    theirs = sla.eigh(k_sk.toarray(), m_sk.toarray(), eigvals_only=True)[6:20]
    assert np.allclose(ours, theirs, rtol=1e-9)


# -- loads and mass properties ----------------------------------------------------------


def _face_mesh(kind_3d, kind_face):
    """A box with its six sides as face cells (ordered outwards)."""
    from asterlite.concepts.mesh import Mesh

    mesh = box_mesh(kind_3d, (1, 1, 1), (2.0, 1.0, 0.5))
    ref = REFERENCE_ELEMENTS[FACE_CELLS[kind_face].reference]
    coords = mesh.coords
    lo, hi = coords.min(axis=0), coords.max(axis=0)
    faces = []
    for axis, side in product(range(3), (0, 1)):
        level = (lo, hi)[side][axis]
        u, v = [a for a in range(3) if a != axis]
        if side == 0:
            u, v = v, u  # keep u x v pointing out of the box
        on = np.nonzero(np.isclose(coords[:, axis], level))[0]
        local = np.zeros((len(on), 2))
        local[:, 0] = (coords[on, u] - lo[u]) / (hi[u] - lo[u])
        local[:, 1] = (coords[on, v] - lo[v]) / (hi[v] - lo[v])
        target = ref.nodes if ref.name.startswith("QU") else None
        if target is None:
            continue
        target = (target + 1.0) / 2.0
        face = [int(on[np.argmin(np.linalg.norm(local - t, axis=1))]) for t in target]
        faces.append(tuple(face))
    cells = list(mesh.cell_nodes) + faces
    types = list(mesh.cell_types) + [kind_face] * len(faces)
    return Mesh(
        coords=coords,
        node_names=mesh.node_names,
        cell_names=[f"M{i + 1}" for i in range(len(cells))],
        cell_types=types,
        cell_nodes=cells,
    )


@pytest.mark.parametrize("volume, face", [("HEXA8", "QUAD4"), ("HEXA20", "QUAD8")])
def test_pressure_on_a_closed_box_cancels_and_pushes_inwards(volume, face):
    mesh = _face_mesh(volume, face)
    faces = [c for c, t in enumerate(mesh.cell_types) if t == face]
    total = np.zeros(3)
    for _, comp, value in pressure_terms(mesh, faces, 1.0e5):
        total["XYZ".index(comp[1])] += value
    assert np.allclose(total, 0.0, atol=1e-6)
    top = [c for c in faces if np.allclose(mesh.coords[list(mesh.cell_nodes[c]), 2], 0.5)]
    force = np.zeros(3)
    for _, comp, value in pressure_terms(mesh, top, 1.0e5):
        force["XYZ".index(comp[1])] += value
    assert np.allclose(force, [0.0, 0.0, -1.0e5 * 2.0])


def test_uniform_pressure_on_quad8_loads_corners_negatively():
    """Consistent loads of the 8-node face: -1/12 at corners, 1/3 at midsides."""
    mesh = _face_mesh("HEXA20", "QUAD8")
    top = [
        c
        for c, t in enumerate(mesh.cell_types)
        if t == "QUAD8" and np.allclose(mesh.coords[list(mesh.cell_nodes[c]), 2], 0.5)
    ]
    terms = [t for t in pressure_terms(mesh, top, -1.0) if t[1] == "DZ"]
    values = np.array([v for _, _, v in terms]) / 2.0  # area 2
    assert np.allclose(values[:4], -1.0 / 12.0) and np.allclose(values[4:], 1.0 / 3.0)


def test_face_force_and_volume_forces_sum_to_the_resultants():
    mesh = _face_mesh("HEXA8", "QUAD4")
    faces = [c for c, t in enumerate(mesh.cell_types) if t == "QUAD4"]
    terms = face_force_terms(mesh, faces[:1], [10.0, 0.0, -3.0])
    sums = {c: sum(v for _, comp, v in terms if comp == c) for c in ("DX", "DY", "DZ")}
    area = 1.0 * 0.5  # the x = 0 side
    assert sums["DX"] == pytest.approx(10.0 * area) and sums["DZ"] == pytest.approx(-3 * area)
    for kind in KINDS:
        box = box_mesh(kind, (2, 1, 1), (2.0, 1.0, 0.5), jitter=0.0)
        model, field = solid_model(box)
        cells = np.arange(box.n_cells)
        weight = volume_force_terms(box, cells, [0.0, 0.0, -9.81], field, per_mass=True)
        total = sum(v for _, c, v in weight if c == "DZ")
        assert total == pytest.approx(-9.81 * RHO * 1.0, rel=1e-12), kind


def test_gravity_terms_of_a_solid_model_use_the_weight():
    from asterlite.concepts.assembly import MechanicalLoad
    from asterlite.fem.loads import load_terms

    mesh = box_mesh("TETRA10", (2, 1, 1), (2.0, 1.0, 0.5))
    model, field = solid_model(mesh)
    load = MechanicalLoad(model=model)
    load.extra["PESANTEUR"] = {"GRAVITE": 300.0, "DIRECTION": (-1.0, 0.0, 1.0), "CELLS": None}
    numbering = DofNumbering(mesh=mesh, dofs=build_numbering_dofs(model.node_components()))
    vector = assemble_terms(load_terms(load, None, field), numbering)
    comps = np.array(numbering.dof_components)
    g = 300.0 / np.sqrt(2.0)
    assert vector[comps == "DX"].sum() == pytest.approx(-g * RHO, rel=1e-12)
    assert vector[comps == "DZ"].sum() == pytest.approx(g * RHO, rel=1e-12)


def test_mass_properties_of_a_box():
    mesh = box_mesh("HEXA20", (2, 2, 1), (2.0, 1.0, 0.5), jitter=0.0)
    model, field = solid_model(mesh)
    props = mass_properties(model, materials=field)
    m = RHO * 1.0
    assert props["MASSE"] == pytest.approx(m)
    assert [props[k] for k in ("CDG_X", "CDG_Y", "CDG_Z")] == pytest.approx([1.0, 0.5, 0.25])
    assert props["IX_G"] == pytest.approx(m * (1.0 + 0.25) / 12)
    assert props["IZ_G"] == pytest.approx(m * (4.0 + 1.0) / 12)
    assert props["IXY_G"] == pytest.approx(0.0, abs=1e-9)


def test_mass_properties_of_tetra4_use_the_one_point_rule():
    """code_aster integrates MASS_INER on the RIGI family: one point for TETRA4,
    so each tetrahedron counts as a point mass at its centroid."""
    mesh = box_mesh("TETRA4", (1, 1, 1), (1.0, 1.0, 1.0))
    model, field = solid_model(mesh)
    rigid = solid_inertia(model, field)
    cells = np.array(mesh.cell_nodes)
    centroids = mesh.coords[cells].mean(axis=1)
    masses = RHO * _volumes("TETRA4", mesh.coords[cells])
    second = np.einsum("e,ei,ej->ij", masses, centroids, centroids)
    assert np.allclose(rigid[3:, 3:], np.trace(second) * np.eye(3) - second)


# -- a cantilever against beam theory ----------------------------------------------------

LENGTH, SIDE = 1.0, 0.1


def _cantilever_frequencies(kind, along, across, count=6):
    mesh = box_mesh(kind, (along, across, across), (LENGTH, SIDE, SIDE))
    _, _, numbering, k = _assembled(mesh, "K")
    _, _, _, m = _assembled(mesh, "M")
    free = mesh.coords[numbering.dof_nodes, 0] > 1e-12
    kf, mf = k[free][:, free].tocsc(), m[free][:, free].tocsc()
    vals, vecs = spla.eigsh(kf, k=count, M=mf, sigma=-1.0)
    order = np.argsort(vals)
    return np.sqrt(vals[order]) / (2 * np.pi), vecs[:, order], numbering, free


def _beam_theory():
    shear = E / (2 * (1 + NU))
    inertia = SIDE**4 / 12
    area = SIDE**2
    bending = 1.875104**2 / (2 * np.pi) * np.sqrt(E * inertia / (RHO * area * LENGTH**4))
    torsion_constant = 0.1406 * SIDE**4  # square section (Saint-Venant)
    torsion = np.sqrt(shear * torsion_constant / (RHO * 2 * inertia)) / (4 * LENGTH)
    return bending, torsion


def _torsion_frequency(freqs, vecs, numbering, free):
    """The mode whose tip rotates about x (DY, DZ antisymmetric about the axis)."""
    comps = np.array(numbering.dof_components)[free]
    coords = numbering.mesh.coords[numbering.dof_nodes[free]]
    y, z = coords[:, 1] - SIDE / 2, coords[:, 2] - SIDE / 2
    twist = np.where(comps == "DY", -z, 0.0) + np.where(comps == "DZ", y, 0.0)
    share = [abs(twist @ v) / (np.linalg.norm(twist) * np.linalg.norm(v)) for v in vecs.T]
    return freqs[int(np.argmax(share))]


def test_cantilever_bending_and_torsion_against_beam_theory():
    bending, torsion = _beam_theory()
    freqs, vecs, numbering, free = _cantilever_frequencies("HEXA20", 10, 2)
    # the two bending directions are equivalent on a square section
    assert freqs[0] == pytest.approx(freqs[1], rel=1e-6)
    # slenderness 10: within 1 % of Euler-Bernoulli (shear and rotary inertia
    # lower the exact value a little, the coarse mesh raises it a little)
    assert freqs[0] == pytest.approx(bending, rel=0.01)
    # warping held at the clamp stiffens the section a little
    assert _torsion_frequency(freqs, vecs, numbering, free) == pytest.approx(torsion, rel=0.03)


@pytest.mark.slow
def test_cantilever_converges_with_h_and_element_order():
    reference = _cantilever_frequencies("HEXA20", 20, 3, count=2)[0][0]
    coarse = abs(_cantilever_frequencies("HEXA8", 10, 2, count=2)[0][0] - reference)
    fine = abs(_cantilever_frequencies("HEXA8", 20, 4, count=2)[0][0] - reference)
    quadratic = abs(_cantilever_frequencies("HEXA20", 10, 2, count=2)[0][0] - reference)
    tets = abs(_cantilever_frequencies("TETRA10", 10, 2, count=2)[0][0] - reference)
    # linear hexahedra lock in bending: halving h cuts their error about 4 times
    assert fine < coarse / 3
    # quadratic elements on the coarse mesh beat linear ones on the fine mesh
    assert quadratic < fine / 5 and tets < fine
    assert quadratic / reference < 5e-3
    # the converged 3D frequency sits just below Euler-Bernoulli (Timoshenko effects)
    bending, _ = _beam_theory()
    assert 0.99 * bending < reference < bending
