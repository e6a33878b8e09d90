"""Kinematic link between a face of a 3D solid and a beam node (code_aster's
``AFFE_CHAR_MECA/LIAISON_ELEM OPTION='3D_POU'``, reference R3.03.03).

The beam node P carries the mean motion of the face S: its translation is
the mean displacement of the face and its rotation the one whose moment
about the face's centroid G matches that of the face displacement,

    int_S u dS = S u_P
    int_S GM x u dS = I_G theta_P,   I_G = int_S (|GM|^2 Id - GM GM^T) dS

six linear relations between the DX, DY, DZ of the face nodes and the six
DOFs of P. With u = sum_i N_i u_i on each face cell the coefficients of
node i are ``a_i = int_S N_i dS`` and ``b_i = int_S N_i GM dS`` (code_aster's
CARA_SECT_POUT3/4 options, on the RIGI family of its face elements).
"""

from __future__ import annotations

from dataclasses import dataclass

import numpy as np

from asterlite.fem.element_errors import ElementError
from asterlite.fem.solid_reference import FACE_CELLS, tabulated


@dataclass(frozen=True)
class FaceSection:
    """Integrals of a face set: its nodes, a_i (n,), b_i (n, 3), area, centroid
    and inertia tensor about the centroid."""

    nodes: np.ndarray
    shape_integrals: np.ndarray
    moment_integrals: np.ndarray
    area: float
    centroid: np.ndarray
    inertia: np.ndarray


def _quadrature(mesh, cells):
    """For each face cell type: connectivity (e, n), shape values (q, n),
    weights x area jacobian (e, q) and Gauss point coordinates (e, q, 3)."""
    grouped: dict[str, list[int]] = {}
    for cell in np.asarray(cells, dtype=int):
        kind = mesh.cell_types[cell]
        if kind not in FACE_CELLS:
            raise ElementError(
                f"cell {mesh.cell_names[cell]} ({kind}) is not a face cell (TRIA3/6, QUAD4/8/9)"
            )
        grouped.setdefault(kind, []).append(int(cell))
    for kind, members in grouped.items():
        spec = FACE_CELLS[kind]
        values, grads, weights = tabulated(spec.reference, spec.rigi)
        conn = np.array([mesh.cell_nodes[c] for c in members], dtype=int)
        coords = mesh.coords[conn]  # (e, n, 3)
        tangents = np.einsum("qnj,eni->eqji", grads, coords)
        normal = np.cross(tangents[:, :, 0, :], tangents[:, :, 1, :])
        jac = np.linalg.norm(normal, axis=2)
        points = np.einsum("qn,eni->eqi", values, coords)
        yield conn, values, weights[None, :] * jac, points


def face_section(mesh, cells) -> FaceSection:
    """Area, centroid, inertia and nodal integrals of a set of face cells."""
    rules = list(_quadrature(mesh, cells))
    area = sum(float(wa.sum()) for _, _, wa, _ in rules)
    if area <= 0.0:
        raise ElementError("the faces have no area")
    centroid = sum(np.einsum("eq,eqi->i", wa, x) for _, _, wa, x in rules) / area
    nodes = np.unique(np.concatenate([conn.ravel() for conn, _, _, _ in rules]))
    index = {int(n): k for k, n in enumerate(nodes)}
    a = np.zeros(len(nodes))
    b = np.zeros((len(nodes), 3))
    inertia = np.zeros((3, 3))
    for conn, values, wa, points in rules:
        gm = points - centroid  # (e, q, 3)
        local_a = np.einsum("eq,qn->en", wa, values)
        local_b = np.einsum("eq,qn,eqi->eni", wa, values, gm)
        rows = np.vectorize(index.__getitem__)(conn)
        np.add.at(a, rows, local_a)
        np.add.at(b, rows, local_b)
        r2 = np.einsum("eqi,eqi->eq", gm, gm)
        inertia += np.einsum("eq,eq->", wa, r2) * np.eye(3)
        inertia -= np.einsum("eq,eqi,eqj->ij", wa, gm, gm)
    return FaceSection(nodes, a, b, area, centroid, inertia)


def solid_beam_relations(section: FaceSection, beam_node: int):
    """The six relations as (terms, rhs) with terms (node, component, coef):
    three for the translations, three for the rotations (code_aster's order)."""
    relations = []
    nodes = [int(n) for n in section.nodes]
    for comp in ("DX", "DY", "DZ"):
        terms = [(n, comp, float(c)) for n, c in zip(nodes, section.shape_integrals, strict=True)]
        terms.append((beam_node, comp, -section.area))
        relations.append((terms, 0.0))
    b = section.moment_integrals
    # component k of sum_i b_i x u_i: (b_j u_l - b_l u_j) with (k, j, l) cyclic
    cyclic = ((0, 1, 2), (1, 2, 0), (2, 0, 1))
    comps = ("DX", "DY", "DZ")
    for k, j, l in cyclic:
        terms = []
        for n, bi in zip(nodes, b, strict=True):
            terms.append((n, comps[l], float(bi[j])))
            terms.append((n, comps[j], -float(bi[l])))
        for r, rot in enumerate(("DRX", "DRY", "DRZ")):
            terms.append((beam_node, rot, -float(section.inertia[k, r])))
        relations.append((terms, 0.0))
    return relations
