"""POST_NEWMARK's safety factors on a slip circle from a static (gravity)
result and a dynamic one (RESULTAT_PESANTEUR with RAYON), in the steps of
post_newmark_ops.py: the disc mesh (buildDisk, RAFF_CERCLE), its slip line
inside the structure, the Gauss stresses of the static result's last instant
and of every instant of the dynamic one brought there by ECLA_PG and turned
into SIG_N/SIG_TN (SIRO_ELEM), PHI and cohesion (CHAM_PHI X1, CHAM_COHESION
X2) collocated at the line's nodes and averaged on each segment (CREA_CHAMP
DISC), then the safety factor at each instant.

Where asterlite departs from code_aster: code_aster carries PHI and cohesion
onto a separate line mesh by a 1.5D projection, which gives each node the
value of one of the segments it belongs to; asterlite gives each segment
the mean of its own two nodes. Both agree where PHI and cohesion are the
same on neighbouring segments.
"""

from __future__ import annotations

import numpy as np

from asterlite.fem.disk_mesh import disk_mesh
from asterlite.post import slip_circle, slip_line_safety
from asterlite.post.field_projection import place_nodes
from asterlite.post.sliding_block import SURFACES


class SafetyError(ValueError):
    """Input the safety factors cannot be computed from."""


def _gauss_stresses(result, order: int, label: str):
    """(cells, per-cell (n_gauss, 4) stresses) of a result's SIEF_ELGA."""
    field = getattr(result, "element_fields", {}).get("SIEF_ELGA")
    if field is None:
        raise SafetyError(f"{label} holds no SIEF_ELGA (CALC_CHAMP CONTRAINTE='SIEF_ELGA')")
    mesh = result.model.mesh
    wanted = ("SIXX", "SIYY", "SIZZ", "SIXY")
    columns = [field.components.index(c) for c in wanted]
    cells, values = [], []
    for row, cell in enumerate(field.cells):
        if mesh.cell_types[int(cell)] not in SURFACES:
            continue
        points = field.values[order, row][:, columns]
        defined = ~np.isnan(points[:, 0])
        cells.append(int(cell))
        values.append(points[defined])
    if not cells:
        raise SafetyError(f"{label}'s SIEF_ELGA holds no plane cell")
    return np.array(cells), values


def _segment_means(field, component: str, line, disc, label: str) -> np.ndarray:
    """A nodal field's component collocated at the slip line's nodes (from
    its mesh's plane cells), then the mean of each segment's two nodes."""
    mesh = field.numbering.mesh
    nodal = np.zeros(mesh.n_nodes)
    held = np.zeros(mesh.n_nodes, dtype=bool)
    for k, (node, name) in enumerate(field.numbering.dofs):
        if name == component:
            nodal[node] = field.values[k]
            held[node] = True
    if not held.any():
        raise SafetyError(f"{label} has no component {component}")
    cells = np.array([c for c in range(mesh.n_cells) if mesh.cell_types[c] in SURFACES])
    ends = np.array([disc.cell_nodes[c] for c in line.segments])
    nodes = np.unique(ends)
    placement = place_nodes(mesh, cells, disc, nodes)
    at_node = {}
    for node in nodes:
        # PROL_ZERO: a node the projection leaves out, or a source node without
        # the component, counts 0
        conn, weights = placement.nodes.get(int(node), (np.zeros(0, dtype=int), np.zeros(0)))
        at_node[int(node)] = float(np.sum(np.where(held[conn], nodal[conn], 0.0) * weights))
    return np.array([0.5 * (at_node[int(a)] + at_node[int(b)]) for a, b in ends])


def dynamic_safety_factors(
    dynamic, static, phi_field, cohesion_field, centre, radius, refine, sign
) -> np.ndarray:
    """The safety factor of the slip circle at each instant of ``dynamic``."""
    disc = disk_mesh(radius, refine, centre)
    mesh = dynamic.model.mesh
    cells, _ = _gauss_stresses(dynamic, 0, "RESULTAT")
    try:
        line = slip_circle.slip_line(disc, mesh, cells)
    except ValueError as exc:
        raise SafetyError(str(exc)) from exc

    projections = {}  # placed once for the instants of a result on the same cells

    def tractions(result, order, label):
        source_cells, values = _gauss_stresses(result, order, label)
        n_gauss = tuple(len(v) for v in values)
        key = (id(result.model.mesh), source_cells.tobytes(), n_gauss)
        if key not in projections:
            projections[key] = slip_circle.gauss_stress_projection(
                result.model.mesh, source_cells, n_gauss, disc, line
            )
        gauss = slip_circle.projected_gauss_stresses(projections[key], values, line)
        return slip_circle.line_stresses(line, gauss)

    static_n, static_tn = tractions(static, len(static.times) - 1, "RESULTAT_PESANTEUR")
    phi = _segment_means(phi_field, "X1", line, disc, "CHAM_PHI")
    cohesion = _segment_means(cohesion_field, "X2", line, disc, "CHAM_COHESION")
    dynamic_n, dynamic_tn = [], []
    for order in range(len(dynamic.times)):
        normal, shear = tractions(dynamic, order, "RESULTAT")
        dynamic_n.append(normal)
        dynamic_tn.append(shear)
    return slip_line_safety.dynamic_safety_factors(
        (static_n, static_tn), (np.array(dynamic_n), np.array(dynamic_tn)), phi, cohesion, sign
    )
