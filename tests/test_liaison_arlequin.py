"""LIAISON_ELEM OPTION='3D_POU_ARLEQUIN' (asterlite.fem.arlequin): a beam of
square section inside a solid bar of the same section. A rigid motion of the
beam given to the solid satisfies every relation (the beam's mass with unit
density equals the integral of its interpolation over the solid when the
sections agree); the pairing of cells follows code_aster's X rule."""

from __future__ import annotations

from types import SimpleNamespace

import numpy as np
import pytest

from asterlite.fem.arlequin import (
    BeamCell,
    arlequin_relations,
    beam_displacement_matrix,
    beam_unit_mass,
    pair_cells,
)
from asterlite.fem.element_errors import ElementError
from asterlite.fem.frames import rotation_from_angles
from asterlite.fem.solid_reference import REFERENCE_ELEMENTS

H, L = 0.02, 0.06  # side of the square section, length of the bar along X
COMPS = {"DX": 0, "DY": 1, "DZ": 2, "DRX": 3, "DRY": 4, "DRZ": 5}


def _bar(kind: str, nx: int = 3, ny: int = 2, x0: float = 0.0):
    """The bar [x0, x0 + L] x [-H/2, H/2]^2 meshed with HEXA8 or HEXA20 cells,
    the beam axis being the X axis; beam nodes appended after the solid's."""
    reference = REFERENCE_ELEMENTS["HE8" if kind == "HEXA8" else "H20"]
    corners = np.array([[-1, -1, -1], [1, -1, -1], [1, 1, -1], [-1, 1, -1]] * 2, dtype=float)
    corners[4:, 2] = 1.0
    nodes: dict[tuple, int] = {}
    coords, cells = [], []
    dx, dy = L / nx, H / ny
    for i in range(nx):
        for j in range(ny):
            for k in range(ny):
                low = np.array([x0 + i * dx, -H / 2 + j * dy, -H / 2 + k * dy])
                cell = []
                for xi in np.asarray(reference.nodes, dtype=float):
                    x = low + (xi + 1.0) / 2.0 * np.array([dx, dy, dy])
                    key = tuple(np.round(x, 12))
                    if key not in nodes:
                        nodes[key] = len(coords)
                        coords.append(x)
                    cell.append(nodes[key])
                cells.append(cell)
    n_solid = len(coords)
    coords += [np.array([x0, 0.0, 0.0]), np.array([x0 + L, 0.0, 0.0])]
    mesh = SimpleNamespace(
        coords=np.array(coords),
        cell_nodes=cells,
        cell_types=[kind] * len(cells),
    )
    return mesh, n_solid


def _beam(mesh, n_solid, reverse=False, ay=1.2, az=1.2) -> BeamCell:
    first, second = (n_solid + 1, n_solid) if reverse else (n_solid, n_solid + 1)
    start, end = mesh.coords[first], mesh.coords[second]
    angles = (np.pi, 0.0, 0.0) if reverse else (0.0, 0.0, 0.0)
    return BeamCell(
        name="B1",
        nodes=(first, second),
        start=start,
        end=end,
        rotation=rotation_from_angles(angles),
        length=L,
        young=2.0e11,
        poisson=0.3,
        area=H * H,
        iy=H**4 / 12.0,
        iz=H**4 / 12.0,
        ay=ay,
        az=az,
    )


def _residuals(mesh, relations, field, beam_dofs):
    """sum coef * u of each relation, divided by the largest |coef * u| of all."""
    sums, scale = [], 0.0
    for terms, rhs in relations:
        parts = []
        for node, comp, coef in terms:
            values = beam_dofs[node] if node in beam_dofs else field(mesh.coords[node])
            parts.append(coef * values[COMPS[comp]])
        sums.append(sum(parts) - rhs)
        scale = max(scale, max(abs(p) for p in parts))
    return np.array(sums) / scale


def _rigid(translation, rotation):
    def field(x):
        return np.asarray(translation) + np.cross(rotation, x)

    return field


def _rigid_beam_dofs(mesh, beam, translation, rotation):
    return {
        n: np.concatenate([_rigid(translation, rotation)(mesh.coords[n]), rotation])
        for n in beam.nodes
    }


@pytest.mark.parametrize("kind", ["HEXA8", "HEXA20"])
@pytest.mark.parametrize("reverse", [False, True])
def test_rigid_translations_reach_the_solid(kind, reverse):
    mesh, n_solid = _bar(kind)
    beam = _beam(mesh, n_solid, reverse)
    relations = arlequin_relations(mesh, range(len(mesh.cell_nodes)), [beam])
    assert len(relations) == 12
    for translation in np.eye(3) * 1.0e-3:
        dofs = _rigid_beam_dofs(mesh, beam, translation, np.zeros(3))
        residuals = _residuals(mesh, relations, _rigid(translation, np.zeros(3)), dofs)
        assert np.abs(residuals).max() < 1.0e-12


def _rotation_residuals(shear):
    mesh, n_solid = _bar("HEXA20")
    beam = _beam(mesh, n_solid, ay=shear, az=shear)
    relations = arlequin_relations(mesh, range(len(mesh.cell_nodes)), [beam])
    out = []
    for rotation in np.eye(3) * 1.0e-3:
        dofs = _rigid_beam_dofs(mesh, beam, np.zeros(3), rotation)
        out.append(np.abs(_residuals(mesh, relations, _rigid(np.zeros(3), rotation), dofs)).max())
    return out


def test_rigid_rotations_reach_the_solid():
    """HEXA20's 27 points integrate the cubic interpolation times a linear
    field exactly; with shear coefficients 1 the bending and torsion DOFs of
    the beam follow the solid's rotation exactly."""
    assert max(_rotation_residuals(1.0)) < 1.0e-12


def test_shear_coefficients_other_than_one_bend_differently():
    """code_aster's interpolation divides by AY, AZ where the beam's mass
    multiplies: torsion stays exact, bending rotations leave 0.45 % (AY = 1.2)."""
    torsion, about_y, about_z = _rotation_residuals(1.2)
    assert torsion < 1.0e-12
    assert about_y == pytest.approx(4.48e-3, rel=1e-2)
    assert about_z == pytest.approx(4.48e-3, rel=1e-2)


def test_a_bending_motion_of_the_solid_is_not_a_beam_rotation():
    """The relations can fail: a shear field u_y = x^2 of the solid given with a
    beam at rest leaves residuals."""
    mesh, n_solid = _bar("HEXA20")
    beam = _beam(mesh, n_solid)
    relations = arlequin_relations(mesh, range(len(mesh.cell_nodes)), [beam])
    dofs = {n: np.zeros(6) for n in beam.nodes}
    residuals = _residuals(mesh, relations, lambda x: np.array([0.0, x[0] ** 2, 0.0]), dofs)
    assert np.abs(residuals).max() > 0.5


def test_interpolation_reproduces_the_nodes():
    """B at the beam's nodes gives the nodes' translations (on the axis) when
    the two shear ratios agree; code_aster's formula multiplies the DY
    shapes of one plane by the factor of the other, so they must."""
    mesh, n_solid = _bar("HEXA8")
    beam = _beam(mesh, n_solid, ay=1.5, az=1.5)
    dofs = np.arange(1.0, 13.0)
    assert beam_displacement_matrix(beam.start, beam) @ dofs == pytest.approx(dofs[:3])
    assert beam_displacement_matrix(beam.end, beam) @ dofs == pytest.approx(dofs[6:9])


def test_unit_mass_is_the_beam_volume():
    mesh, n_solid = _bar("HEXA8")
    mass = beam_unit_mass(_beam(mesh, n_solid))
    translation = np.tile([1.0, 0.0, 0.0, 0.0, 0.0, 0.0], 2)
    assert translation @ mass @ translation == pytest.approx(H * H * L, rel=1e-14)


def test_cells_pair_by_the_x_of_their_centre():
    """Only the solid cells whose mean node X is strictly inside the beam cell's
    X range are tied to it (code_aster's arlchi)."""
    mesh, n_solid = _bar("HEXA8", nx=3, x0=0.0)
    short = _beam(mesh, n_solid)
    short = BeamCell(**{**short.__dict__, "end": short.start + (L / 2, 0.0, 0.0), "length": L / 2})
    pairs = pair_cells(mesh, range(len(mesh.cell_nodes)), [short])
    centres = [np.mean(mesh.coords[mesh.cell_nodes[c], 0]) for c, _ in pairs]
    assert len(pairs) == 4  # the first slice of 2 x 2 cells (centre L/6); L/2 is its end
    assert max(centres) < L / 2


def test_a_beam_cell_with_no_solid_cell_is_refused():
    mesh, n_solid = _bar("HEXA8")
    far = _beam(mesh, n_solid)
    far = BeamCell(**{**far.__dict__, "start": far.start + 10.0, "end": far.end + 10.0})
    with pytest.raises(ElementError, match="enclose the centre of no solid cell"):
        arlequin_relations(mesh, range(len(mesh.cell_nodes)), [far])
