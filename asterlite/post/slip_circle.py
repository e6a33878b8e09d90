"""The slip line of POST_NEWMARK's disc (RAYON) and the stresses on it, as
post_newmark_ops.py obtains them from a structure's Gauss-point stresses.

The slip line is the outer circle's SEG2 of the disc mesh
(:func:`asterlite.fem.disk_mesh.disk_mesh`) whose two vertices lie inside
the structure's cells (DEFI_GROUP INCLUSION, within 1 % of the disc's
smallest edge, then APPUI SOMMET); each segment keeps the circle's
anticlockwise direction, so its normal ``t x e_z`` points out of the disc
(ORIE_PEAU against the disc's cells). The structure's stresses reach the
Gauss points of each segment's 2D neighbour by PROJ_CHAMP ECLA_PG
(:mod:`asterlite.post.gauss_explosion`), are extrapolated to its nodes
(SIEF_ELNO) and averaged over the segment's two nodes (SIRO_ELEM, mearcc
then te0554) before being turned into SIG_N and SIG_TN.
"""

from __future__ import annotations

from dataclasses import dataclass

import numpy as np

from asterlite.fem.solid_fields import gauss_to_nodes
from asterlite.fem.solid_reference import REFERENCE_ELEMENTS, gauss_family
from asterlite.post import slip_line_safety as safety
from asterlite.post.gauss_explosion import gauss_projection
from asterlite.post.sliding_block import points_in_cells, smallest_edge

_SUPPORT = ("QU4", "FPG4")  # the disc's outer ring: QUAD4 in plane strain


@dataclass
class SlipLine:
    """Segments of the slip line (disc cell indices), the QUAD4 of the disc
    beside each, the positions of the segment's vertices in that QUAD4, and
    the segments' frames."""

    segments: np.ndarray
    supports: np.ndarray
    vertex_slots: np.ndarray  # (n, 2)
    tangent: np.ndarray
    normal: np.ndarray


def slip_line(disc, structure, structure_cells) -> SlipLine:
    """The slip line of ``disc`` within the structure's ``structure_cells``."""
    tolerance = 0.01 * smallest_edge(disc)
    inside = points_in_cells(disc.coords, structure, structure_cells, tolerance)
    segments, supports, slots = [], [], []
    surfaces = [c for c in range(disc.n_cells) if disc.cell_types[c] in ("TRIA3", "QUAD4")]
    for cell in disc.cell_groups["REXT"]:
        a, b = disc.cell_nodes[int(cell)]
        if not (inside[a] and inside[b]):
            continue
        beside = [c for c in surfaces if a in disc.cell_nodes[c] and b in disc.cell_nodes[c]]
        if len(beside) != 1 or disc.cell_types[beside[0]] != "QUAD4":
            raise ValueError("a segment of the disc's circle without its one QUAD4 beside it")
        conn = list(disc.cell_nodes[beside[0]])
        segments.append(int(cell))
        supports.append(beside[0])
        slots.append((conn.index(a), conn.index(b)))
    if not segments:
        raise ValueError("no segment of the slip circle lies inside the structure")
    ends = np.array([disc.cell_nodes[c] for c in segments])
    tangent, normal = safety.line_frames(disc.coords[ends[:, 0]], disc.coords[ends[:, 1]])
    return SlipLine(np.array(segments), np.array(supports), np.array(slots), tangent, normal)


def support_gauss_points(disc, line: SlipLine) -> np.ndarray:
    """(n_segments * 4, 2) positions of the Gauss points of the QUAD4s beside
    the segments, in the order of the segments then of the points."""
    at_points = REFERENCE_ELEMENTS[_SUPPORT[0]].values(gauss_family(*_SUPPORT)[0]).real
    corners = disc.coords[np.array([disc.cell_nodes[c] for c in line.supports])][..., :2]
    return np.einsum("qn,cnd->cqd", at_points, corners).reshape(-1, 2)


def line_stresses(line: SlipLine, gauss_stresses: np.ndarray) -> tuple[np.ndarray, np.ndarray]:
    """SIG_N and SIG_TN of the segments from the stresses (n_segments, 4,
    >=4 components SIXX SIYY SIZZ SIXY) at their QUAD4's Gauss points."""
    at_nodes = np.einsum("nq,sqc->snc", gauss_to_nodes(*_SUPPORT), gauss_stresses)
    rows = np.arange(len(line.segments))
    mean = 0.5 * (at_nodes[rows, line.vertex_slots[:, 0]] + at_nodes[rows, line.vertex_slots[:, 1]])
    return safety.line_tractions(mean, line.tangent, line.normal)


def gauss_stress_projection(structure, structure_cells, n_gauss, disc, line: SlipLine):
    """ECLA_PG's placement of the Gauss points of the QUAD4s beside the slip
    line among the structure's cells (structure_cells[i] with n_gauss[i]
    Gauss points): one for every instant of a result on those cells."""
    return gauss_projection(structure, structure_cells, n_gauss, support_gauss_points(disc, line))


def projected_gauss_stresses(projection, gauss_values, line: SlipLine) -> np.ndarray:
    """The structure's Gauss-point stresses (gauss_values[i] of its i-th
    cell) at the Gauss points of the QUAD4s beside the slip line, by ECLA_PG
    (0 at points it cannot place: PROL_ZERO)."""
    return projection.apply(gauss_values).reshape(len(line.segments), 4, -1)
