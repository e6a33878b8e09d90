"""Paraxial absorbing boundaries (3D_ABSO, D_PLAN_ABSO): the dashpot
densities rho c_p (normal) and rho c_s (tangential) on flat and inclined
boundaries, LONG_CARA springs, and a plane-strain column whose absorbing
base makes it behave as a semi-infinite one (input impedance rho c_p)."""

from __future__ import annotations

import numpy as np
import pytest
import scipy.sparse.linalg as spla

from asterlite.concepts.assembly import DofNumbering, Material, MaterialField, Model
from asterlite.concepts.mesh import Mesh
from asterlite.fem.assemble import assemble_blocks, build_numbering_dofs
from asterlite.fem.elements import element_blocks
from tests.test_fem_plane import grid_mesh

E, NU, RHO = 3.0e10, 0.25, 2450.0
LAM = E * NU / ((1 + NU) * (1 - 2 * NU))
MU = E / (2 * (1 + NU))
RHO_CP = np.sqrt((LAM + 2 * MU) * RHO)
RHO_CS = np.sqrt(MU * RHO)


def _single(kind, points, modelisation, **material):
    coords = np.zeros((len(points), 3))
    coords[:, : np.shape(points)[1]] = points
    mesh = Mesh(
        coords=coords,
        node_names=[f"N{i + 1}" for i in range(len(points))],
        cell_names=["B1"],
        cell_types=[kind],
        cell_nodes=[tuple(range(len(points)))],
    )
    model = Model(mesh=mesh, cell_modelisation={0: modelisation})
    behaviour = {"E": E, "NU": NU, "RHO": RHO, **material}
    field = MaterialField(mesh=mesh, cell_material={0: Material(behaviours={"ELAS": behaviour})})
    numbering = DofNumbering(mesh=mesh, dofs=build_numbering_dofs(model.node_components()))
    return model, field, numbering


def _matrix(model, field, numbering, matrix):
    return assemble_blocks(element_blocks(model, None, matrix, materials=field), numbering)


def _rigid(numbering, direction):
    comps = ("DX", "DY", "DZ")
    return np.array([direction[comps.index(c)] for c in numbering.dof_components], dtype=float)


@pytest.mark.parametrize(
    ("kind", "points"),
    [
        ("TRIA3", [(0, 0, 0), (2, 0, 0), (0, 1.5, 0)]),
        ("QUAD4", [(0, 0, 0), (2, 0, 0), (2.2, 1.5, 0), (0.1, 1.2, 0)]),
        (
            "QUAD8",
            [
                (0, 0, 0),
                (2, 0, 0),
                (2, 1, 0),
                (0, 1, 0),
                (1, 0, 0),
                (2, 0.5, 0),
                (1, 1, 0),
                (0, 0.5, 0),
            ],
        ),
    ],
)
def test_face_dashpots(kind, points):
    """A flat face of area A normal to z: a rigid motion along z meets
    A rho c_p, along x A rho c_s, in any rotated position."""
    rotation = np.linalg.qr(np.random.default_rng(3).normal(size=(3, 3)))[0]
    points = np.array(points, dtype=float) @ rotation.T
    model, field, numbering = _single(kind, points, "3D_ABSO")
    c = _matrix(model, field, numbering, "A")
    p = np.array(points) @ rotation
    area = 0.5 * abs(np.sum(p[:4, 0] * np.roll(p[:4, 1], -1) - np.roll(p[:4, 0], -1) * p[:4, 1]))
    if kind == "TRIA3":
        area = 1.5
    normal, tangent = rotation[:, 2], rotation[:, 0]
    assert _rigid(numbering, normal) @ c @ _rigid(numbering, normal) == pytest.approx(area * RHO_CP)
    assert _rigid(numbering, tangent) @ c @ _rigid(numbering, tangent) == pytest.approx(
        area * RHO_CS
    )
    assert _rigid(numbering, normal) @ c @ _rigid(numbering, tangent) == pytest.approx(
        0, abs=1e-6 * RHO_CP
    )
    assert _matrix(model, field, numbering, "M").nnz == 0
    assert _matrix(model, field, numbering, "K").nnz == 0  # no LONG_CARA: no springs


def test_edge_dashpots_and_springs():
    """An inclined SEG3 edge of length L: normal L rho c_p, tangential
    L rho c_s; COEF_AMOR scales them, LONG_CARA adds (lambda + 2 mu)/L0 springs."""
    angle = 0.6
    t = np.array([np.cos(angle), np.sin(angle)])
    points = [(0.0, 0.0), tuple(3.0 * t), tuple(1.5 * t)]
    model, field, numbering = _single("SEG3", points, "D_PLAN_ABSO", COEF_AMOR=0.5, LONG_CARA=20.0)
    c = _matrix(model, field, numbering, "A")
    k = _matrix(model, field, numbering, "K")
    n = np.array([t[1], -t[0], 0.0])
    tangent = np.array([t[0], t[1], 0.0])
    assert _rigid(numbering, n) @ c @ _rigid(numbering, n) == pytest.approx(3.0 * 0.5 * RHO_CP)
    assert _rigid(numbering, tangent) @ c @ _rigid(numbering, tangent) == pytest.approx(
        3.0 * 0.5 * RHO_CS
    )
    assert _rigid(numbering, n) @ k @ _rigid(numbering, n) == pytest.approx(
        3.0 * (LAM + 2 * MU) / 20.0
    )
    assert _rigid(numbering, tangent) @ k @ _rigid(numbering, tangent) == pytest.approx(
        3.0 * MU / 20.0
    )


def test_column_on_absorbing_base_is_semi_infinite():
    """A plane-strain column (lateral motion blocked: a 1D P wave) of depth
    D on a D_PLAN_ABSO base, loaded harmonically at the top: the top's
    impedance F / (i omega u) is rho c_p per unit width, as for a
    semi-infinite column (no wave comes back), within the mesh's dispersion
    (1e-6 and 1.4e-3 at 5 Hz)."""
    width, depth, cells = 1.0, 200.0, 200
    mesh = grid_mesh("QUAD8", (1, cells), (width, depth))
    base = [k for k in range(len(mesh.coords)) if abs(mesh.coords[k, 1]) < 1e-9]
    base.sort(key=lambda k: mesh.coords[k, 0])
    base = [base[0], base[-1], base[1]]  # SEG3: ends, then the middle
    mesh.cell_types.append("SEG3")
    mesh.cell_nodes.append(tuple(base))
    mesh.cell_names.append("BASE")
    n_cells = len(mesh.cell_types)
    modelisation = {c: "D_PLAN" for c in range(n_cells - 1)}
    modelisation[n_cells - 1] = "D_PLAN_ABSO"
    model = Model(mesh=mesh, cell_modelisation=modelisation)
    material = Material(behaviours={"ELAS": {"E": E, "NU": NU, "RHO": RHO}})
    field = MaterialField(mesh=mesh, cell_material=dict.fromkeys(range(n_cells), material))
    numbering = DofNumbering(mesh=mesh, dofs=build_numbering_dofs(model.node_components()))
    k, m, c = (_matrix(model, field, numbering, x) for x in ("K", "M", "A"))
    vertical = np.array([comp == "DY" for comp in numbering.dof_components])
    top = vertical & (np.abs(mesh.coords[numbering.dof_nodes, 1] - depth) < 1e-9)
    keep = vertical  # DX = 0 everywhere
    cp = RHO_CP / RHO
    for frequency in (2.0, 5.0):
        omega = 2 * np.pi * frequency
        assert cp / frequency > 20 * depth / cells  # many elements per wavelength
        system = (k - omega**2 * m + 1j * omega * c)[keep][:, keep].tocsc()
        load = np.zeros(int(keep.sum()), dtype=complex)
        load[top[keep]] = 1.0 / top.sum() * width  # unit total force, spread
        u = spla.spsolve(system, load)
        impedance = width / (1j * omega * u[top[keep]].mean())
        assert impedance.real == pytest.approx(RHO_CP * width, rel=1e-4)
        assert abs(impedance.imag) < 5e-3 * RHO_CP * width
