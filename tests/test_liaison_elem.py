"""LIAISON_ELEM OPTION='3D_POU': face integrals against the analytic values of a
rectangle, and the six relations against rigid-body motions (which they must
leave free) and a bending field (whose rotation they must give)."""

from __future__ import annotations

from types import SimpleNamespace

import numpy as np
import pytest

from asterlite.fem.solid_beam_link import face_section, solid_beam_relations

A, B = 2.0, 0.5  # rectangle sides along x and y, in the plane z = 1, corner at (1, -1)
ORIGIN = np.array([1.0, -1.0, 1.0])


def _rectangle(kind: str, nx: int = 4, ny: int = 3):
    """A rectangle meshed with QUAD4 or TRIA3 cells (nodes in code_aster's order)."""
    xs, ys = np.linspace(0.0, A, nx + 1), np.linspace(0.0, B, ny + 1)
    coords = np.array([ORIGIN + (x, y, 0.0) for y in ys for x in xs])
    cells = []
    for j in range(ny):
        for i in range(nx):
            n0 = j * (nx + 1) + i
            quad = (n0, n0 + 1, n0 + nx + 2, n0 + nx + 1)
            if kind == "QUAD4":
                cells.append(quad)
            else:
                cells += [(quad[0], quad[1], quad[2]), (quad[0], quad[2], quad[3])]
    return SimpleNamespace(
        coords=coords,
        cell_nodes=cells,
        cell_types=[kind] * len(cells),
        cell_names=[f"M{k}" for k in range(len(cells))],
        node_names=[f"N{k}" for k in range(len(coords))],
    )


@pytest.mark.parametrize("kind", ["QUAD4", "TRIA3"])
def test_face_section_of_a_rectangle(kind):
    mesh = _rectangle(kind)
    section = face_section(mesh, range(len(mesh.cell_nodes)))
    assert section.area == pytest.approx(A * B, rel=1e-14)
    assert section.centroid == pytest.approx(ORIGIN + (A / 2, B / 2, 0.0), rel=1e-14)
    ixx, iyy = A * B**3 / 12.0, B * A**3 / 12.0  # int y'^2, int x'^2
    expected = np.diag([ixx, iyy, ixx + iyy])
    assert np.allclose(section.inertia, expected, rtol=0, atol=1e-14)
    assert section.shape_integrals.sum() == pytest.approx(A * B, rel=1e-14)
    assert np.allclose(section.moment_integrals.sum(axis=0), 0.0, atol=1e-14)


def _residuals(mesh, section, relations, field, beam_dofs):
    """sum coef * u of each relation with u of the face nodes from field(x)
    and the beam node's six DOFs."""
    beam = len(mesh.coords)
    comps = {"DX": 0, "DY": 1, "DZ": 2, "DRX": 3, "DRY": 4, "DRZ": 5}
    out = []
    for terms, rhs in relations:
        total = -rhs
        for node, comp, coef in terms:
            values = beam_dofs if node == beam else field(mesh.coords[node])
            value = values[comps[comp]]
            total += coef * value
        out.append(total)
    return np.array(out)


@pytest.mark.parametrize("kind", ["QUAD4", "TRIA3"])
def test_rigid_motions_satisfy_the_relations(kind):
    mesh = _rectangle(kind)
    section = face_section(mesh, range(len(mesh.cell_nodes)))
    relations = solid_beam_relations(section, beam_node=len(mesh.coords))
    assert len(relations) == 6
    translation = np.array([0.3, -0.2, 0.7])
    rotation = np.array([0.01, -0.03, 0.02])
    g = section.centroid

    def rigid(x):
        return translation + np.cross(rotation, x - g)

    beam = np.concatenate([translation, rotation])
    assert np.allclose(_residuals(mesh, section, relations, rigid, beam), 0.0, atol=1e-14)
    # the same face motion with another beam rotation breaks the rotation relations only
    wrong = np.concatenate([translation, rotation + (0.0, 0.0, 1e-3)])
    res = _residuals(mesh, section, relations, rigid, wrong)
    assert np.allclose(res[:3], 0.0, atol=1e-14)
    assert abs(res[5]) == pytest.approx(1e-3 * section.inertia[2, 2], rel=1e-12)


def test_plane_section_bending_gives_the_mean_rotation():
    """u_z = kappa (y - y_G) is the plane section turned by theta_x = kappa
    (u = theta x GM): the relations hold for the beam rotation (kappa, 0, 0)
    and zero translation, and a beam at rest leaves kappa I_xx unbalanced."""
    mesh = _rectangle("QUAD4", 6, 5)
    section = face_section(mesh, range(len(mesh.cell_nodes)))
    relations = solid_beam_relations(section, beam_node=len(mesh.coords))
    kappa = 0.004
    g = section.centroid

    def bending(x):
        return np.array([0.0, 0.0, kappa * (x[1] - g[1])])

    res = _residuals(mesh, section, relations, bending, np.array([0, 0, 0, kappa, 0, 0.0]))
    assert np.allclose(res, 0.0, atol=1e-15)
    res = _residuals(mesh, section, relations, bending, np.zeros(6))
    assert abs(res[3]) == pytest.approx(kappa * A * B**3 / 12.0, rel=1e-12)


def test_cells_that_are_not_faces_are_refused():
    from asterlite.fem.elements import ElementError

    mesh = _rectangle("QUAD4")
    mesh.cell_types[0] = "SEG2"
    with pytest.raises(ElementError, match="not a face cell"):
        face_section(mesh, [0])
