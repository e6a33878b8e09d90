"""Beam-to-solid coupling over a volume overlap by the Arlequin method
(code_aster's ``AFFE_CHAR_MECA/LIAISON_ELEM OPTION='3D_POU_ARLEQUIN'``).

A beam (group 2, ``POU_D_T`` cells) runs inside a solid (group 1). The beam's
DOFs are tied to the solid's displacement by a weak (L2) projection: for
every DOF i of the beam nodes,

    sum_j M1(i, j) U_beam_j  -  sum_k C(i, k) u_solid_k  =  0

with ``M1`` the beam's consistent mass with unit density (Timoshenko,
rotary inertia included) and ``C = int_V B^T N dV``: ``N`` the solid's shape
functions, ``B`` the beam's displacement field at a point of the section,
written with the Timoshenko interpolation of the element (axial and torsion
linear, bending with shear-corrected cubics, the section rotating rigidly).

How code_aster pairs the cells, and so what this module does too:

- a solid cell belongs to the beam cell whose two nodes' X coordinates
  strictly enclose the mean X of the solid cell's nodes (the method is
  meant for beams along the global X axis);
- the point's offset from the beam's first node is taken to the beam's
  local frame, but ``B`` and ``M1`` (local-frame matrices) multiply the
  beam nodes' global DOFs, unrotated: the same for a beam along +X, what
  code_aster computes for the others (a beam along -X included);
- ``C`` of a pair is integrated on the Gauss points of the solid cell's
  RIGI family (its ``ARLQ_1`` family is the same), the point's position
  relative to the beam's first node giving the abscissa x / L and the
  offsets y, z in the section;
- ``M1`` and the shear ratios take A, IY, IZ, AY, AZ of the beam cell
  (CARA_ELEM) and E, NU of its material (CHAM_MATER). ``B`` divides by the
  shear coefficient where the mass multiplies by it (phi = 12 E I / (G A AZ L^2)
  against 12 E I AY / (G A L^2)): with AY, AZ other than 1, ``int B^T B``
  differs from ``M1`` and a rigid rotation of the beam is not met exactly by
  the solid's (0.45 % on the relations of a square section, AY = AZ = 1.2).
  sslv159a and sslv160a's VALE_CALC hold with code_aster's ratios and miss
  by 2 % and 12 % with the mass's. The mismatch grows with phi: a cantilever
  coupled over one short beam cell (L = 2 h, AY = 1.2) comes out 45 % too
  stiff, within 1 % of Timoshenko's with AY = AZ = 1
  (tests/test_liaison_arlequin.py).
"""

from __future__ import annotations

from dataclasses import dataclass

import numpy as np

from asterlite.fem.beam import beam_mass_local, shear_modulus
from asterlite.fem.element_errors import ElementError
from asterlite.fem.solid_reference import VOLUME_CELLS, tabulated

BEAM_DOFS = ("DX", "DY", "DZ", "DRX", "DRY", "DRZ")
SOLID_DOFS = ("DX", "DY", "DZ")
#: the solid cells code_aster's coupling knows (arlchi)
COUPLED_SOLIDS = ("HEXA8", "HEXA20", "PENTA6", "PENTA15", "TETRA4", "TETRA10")


@dataclass(frozen=True)
class BeamCell:
    """One SEG2 cell of the coupled beam with what the coupling reads of it."""

    name: str
    nodes: tuple[int, int]
    start: np.ndarray  # coordinates of its first node
    end: np.ndarray  # coordinates of its second node
    rotation: np.ndarray  # (3, 3) global-to-local rotation of its CARA_ELEM frame
    length: float
    young: float
    poisson: float
    area: float
    iy: float
    iz: float
    ay: float
    az: float


def beam_displacement_matrix(position, beam: BeamCell) -> np.ndarray:
    """(3, 12) B of a point: the displacement (DX, DY, DZ) there from the 12
    DOFs of the beam cell, as code_aster's Arlequin coupling writes it (arlpff)."""

    rel = beam.rotation @ (np.asarray(position, dtype=float) - beam.start)
    x0, y0, z0 = rel[0] / beam.length, rel[1], rel[2]
    L, E = beam.length, beam.young
    G = shear_modulus(E, beam.poisson)
    phiy = 12.0 * E * beam.iy / (G * beam.area * beam.az * L * L)
    phiz = 12.0 * E * beam.iz / (G * beam.area * beam.ay * L * L)
    ntc1, ntc2 = 1.0 - x0, x0
    n1 = 2.0 * x0**3 - 3.0 * x0**2 - x0 * phiy + 1.0 + phiy
    n2 = (-(x0**3) + 0.5 * (4.0 + phiy) * x0**2 - x0 * 0.5 * (2.0 + phiy)) * L
    n3 = -(2.0 * x0**3 - 3.0 * x0**2 - x0 * phiy)
    n4 = (-(x0**3) + 0.5 * (2.0 - phiy) * x0**2 + x0 * 0.5 * phiy) * L
    n5 = 6.0 * x0 * (1.0 - x0) / L
    n6 = 3.0 * x0**2 - (4.0 + phiy) * x0 + 1.0 + phiy
    n7 = -n5
    n8 = 3.0 * x0**2 + (-2.0 + phiy) * x0
    dy, dz = 1.0 / (1.0 + phiy), 1.0 / (1.0 + phiz)
    # code_aster's interpolation as it stands: the DY shapes take 1 / (1 + phiz)
    # on n1 .. n3 (which hold phiy) and 1 / (1 + phiy) on n4, so the field meets
    # the nodes' values only when phiy = phiz (square and round sections)
    return np.array(
        [
            [ntc1, y0 * dz * n5, z0 * dy * n5, 0.0, z0 * dy * n6, -y0 * dz * n6,
             ntc2, y0 * dz * n7, z0 * dy * n7, 0.0, z0 * dy * n8, -y0 * dz * n8],
            [0.0, dz * n1, 0.0, -z0 * ntc1, 0.0, -dz * n2,
             0.0, dz * n3, 0.0, -z0 * ntc2, 0.0, -dy * n4],
            [0.0, 0.0, dy * n1, y0 * ntc1, dy * n2, 0.0,
             0.0, 0.0, dy * n3, y0 * ntc2, dy * n4, 0.0],
        ]
    )  # fmt: skip


def beam_unit_mass(beam: BeamCell) -> np.ndarray:
    """(12, 12) consistent mass of the beam cell with unit density (arlmas)."""
    return beam_mass_local(
        beam.length,
        1.0,
        beam.young,
        shear_modulus(beam.young, beam.poisson),
        beam.area,
        beam.iy,
        beam.iz,
        beam.ay,
        beam.az,
    )[0]


def solid_coupling(kind: str, coords: np.ndarray, beam: BeamCell) -> np.ndarray:
    """(12, 3 n) C = int_cell B^T N dV of one solid cell paired with a beam cell."""
    spec = VOLUME_CELLS[kind]
    values, grads, weights = tabulated(spec.reference, spec.rigi)
    n = coords.shape[0]
    out = np.zeros((12, 3 * n))
    for q in range(len(weights)):
        jacobian = grads[q].T @ coords  # (3, 3): d x_j / d xi_i
        weight = weights[q] * abs(np.linalg.det(jacobian))
        point = values[q] @ coords
        shape = np.zeros((3, 3 * n))
        for comp in range(3):
            shape[comp, comp::3] = values[q]
        out += weight * beam_displacement_matrix(point, beam).T @ shape
    return out


def pair_cells(mesh, solid_cells, beams: list[BeamCell]) -> list[tuple[int, int]]:
    """(solid cell, beam index) pairs: the beam cell whose node X coordinates
    strictly enclose the mean X of the solid cell's nodes."""
    pairs = []
    for cell in solid_cells:
        mean_x = float(np.mean(mesh.coords[list(mesh.cell_nodes[cell]), 0]))
        for k, beam in enumerate(beams):
            low, high = sorted((beam.start[0], beam.end[0]))
            if low < mean_x < high:
                pairs.append((int(cell), k))
    return pairs


def arlequin_relations(mesh, solid_cells, beams: list[BeamCell]):
    """The linear relations (terms, rhs) tying the beam nodes' six DOFs to
    the solid: one per DOF of each node of the coupled beam cells."""
    pairs = pair_cells(mesh, solid_cells, beams)
    if len(pairs) > len(solid_cells):
        raise ElementError("the beam cells of GROUP_MA_2 overlap along X")
    counts = sorted({len(mesh.cell_nodes[cell]) for cell, _ in pairs})
    if len(counts) > 1:
        # code_aster gathers the solid nodes with the node count of the last
        # pair it computed: with cells of other counts it drops some of them
        raise ElementError(
            f"the solid cells tied to the beam have {' and '.join(map(str, counts))} nodes: "
            "code_aster's Arlequin coupling takes one node count for all of them "
            "(give each cell type its own LIAISON_ELEM load)"
        )
    paired_beams = {k for _, k in pairs}
    lonely = [beams[k].name for k in range(len(beams)) if k not in paired_beams]
    if lonely:
        raise ElementError(
            f"beam cells {', '.join(lonely[:5])} enclose the centre of no solid cell "
            "of GROUP_MA_1 along X: the Arlequin coupling has nothing to tie them to"
        )
    beam_nodes: list[int] = []
    for beam in beams:
        for node in beam.nodes:
            if node not in beam_nodes:
                beam_nodes.append(node)
    row_of = {node: 6 * k for k, node in enumerate(beam_nodes)}
    n_rows = 6 * len(beam_nodes)
    beam_part = np.zeros((n_rows, n_rows))
    for beam in beams:
        rows = np.concatenate([np.arange(row_of[n], row_of[n] + 6) for n in beam.nodes])
        beam_part[np.ix_(rows, rows)] += beam_unit_mass(beam)
    solid_part: dict[tuple[int, int], np.ndarray] = {}
    for cell, k in pairs:
        beam = beams[k]
        nodes = list(mesh.cell_nodes[cell])
        coupling = solid_coupling(mesh.cell_types[cell], mesh.coords[nodes], beam)
        rows = np.concatenate([np.arange(row_of[n], row_of[n] + 6) for n in beam.nodes])
        for j, node in enumerate(nodes):
            for c in range(3):
                column = solid_part.setdefault((int(node), c), np.zeros(n_rows))
                column[rows] += coupling[:, 3 * j + c]
    relations = []
    for node in beam_nodes:
        for d in range(len(BEAM_DOFS)):
            i = row_of[node] + d
            terms = [
                (other, BEAM_DOFS[o], float(beam_part[i, row_of[other] + o]))
                for other in beam_nodes
                for o in range(6)
                if beam_part[i, row_of[other] + o] != 0.0
            ]
            terms += [
                (solid, SOLID_DOFS[c], -float(column[i]))
                for (solid, c), column in solid_part.items()
                if column[i] != 0.0
            ]
            relations.append((terms, 0.0))
    return relations
