"""Static modes (MODE_STATIQUE).

- constrained modes (MODE_STAT): unit displacement of one blocked DOF, the
  other blocked DOFs held at zero, the rest in static equilibrium;
- attachment modes (FORCE_NODALE): static response to a unit force on one
  free DOF;
- pseudo-modes (PSEUDO_MODE): static response to a unit acceleration of
  the whole structure along an axis, K u = M Δ.

All solve the reduced system Tᵀ K T q = Tᵀ (f - K u0) once factorised.
"""

from __future__ import annotations

import numpy as np
import scipy.sparse as sp
import scipy.sparse.linalg as spla

from asterlite.concepts.assembly import DofNumbering
from asterlite.fem.constraints import Elimination, eliminate


class StaticModeError(ValueError):
    pass


def _factor(matrix: sp.spmatrix):
    try:
        return spla.splu(sp.csc_matrix(matrix))
    except RuntimeError:
        raise StaticModeError(
            "the constrained stiffness is singular (rigid-body motion left free)"
        ) from None


def numbering_elimination(numbering: DofNumbering) -> Elimination:
    b_matrix, rhs = numbering.constraint_matrix()
    return eliminate(b_matrix, np.zeros_like(rhs), numbering.n_dofs)


def blocked_dofs(numbering: DofNumbering) -> dict[int, int]:
    """DOF index -> index of the single-term relation that blocks it."""
    out = {}
    for r, relation in enumerate(numbering.relations):
        if len(relation.terms) == 1:
            node, comp, _ = relation.terms[0]
            out.setdefault(numbering.index[(node, comp)], r)
    return out


def constrained_modes(stiffness, numbering: DofNumbering, dofs) -> np.ndarray:
    """(n_dofs, len(dofs)) unit-displacement modes of blocked DOFs."""
    elimination = numbering_elimination(numbering)
    blocked = blocked_dofs(numbering)
    rhs = np.zeros((len(numbering.relations), len(dofs)))
    for k, dof in enumerate(dofs):
        row = blocked[dof]
        coef = numbering.relations[row].terms[0][2]
        rhs[row, k] = coef  # coef * u = coef  ->  u = 1
    u0 = elimination.particular(rhs)
    k_red = elimination.reduce(stiffness)
    if k_red.shape[0] == 0:
        return u0
    lu = _factor(k_red)
    q = lu.solve(np.asarray(-(elimination.T.T @ (stiffness @ u0))))
    return u0 + elimination.T @ q.reshape(k_red.shape[0], -1)


def response_modes(stiffness, numbering: DofNumbering, loads: np.ndarray) -> np.ndarray:
    """(n_dofs, k) static responses K u = f under homogeneous relations."""
    elimination = numbering_elimination(numbering)
    k_red = elimination.reduce(stiffness)
    lu = _factor(k_red)
    q = lu.solve(np.asarray(elimination.T.T @ loads).reshape(k_red.shape[0], -1))
    return elimination.T @ q


def acceleration_modes(stiffness, mass, numbering: DofNumbering, rigid_fields) -> np.ndarray:
    """Pseudo-modes for unit accelerations along directions (PSEUDO_MODE AXE /
    DIRECTION): K u = M Δ under homogeneous relations, Δ (n_dofs, k)."""
    return response_modes(stiffness, numbering, np.asarray(mass @ np.asarray(rigid_fields)))


def dof_acceleration_modes(stiffness, mass, numbering: DofNumbering, dofs) -> np.ndarray:
    """Pseudo-modes for a unit acceleration of blocked DOFs (PSEUDO_MODE by
    node and component): K u = M ψ with ψ the constrained mode of each DOF."""
    psi = constrained_modes(stiffness, numbering, dofs)
    return response_modes(stiffness, numbering, np.asarray(mass @ psi))


def selection_mask(components, nodes, selected_nodes, with_cmp=(), without=()) -> np.ndarray:
    """DOFs on ``selected_nodes`` whose component is in ``with_cmp`` (all when
    empty) and not in ``without``."""
    comps = np.asarray(components, dtype=object)
    mask = np.isin(np.asarray(nodes), np.asarray(selected_nodes, dtype=int))
    if with_cmp:
        mask &= np.isin(comps, list(with_cmp))
    if without:
        mask &= ~np.isin(comps, list(without))
    return mask


def static_solve(stiffness, numbering: DofNumbering, loads: np.ndarray, relation_rhs=None):
    """u (n_dofs, k) with K u = f + reactions and B u = b (the numbering's
    relations; ``relation_rhs`` (n_relations, k) overrides their right-hand
    sides, default: the relations' own values)."""
    b_matrix, rhs = numbering.constraint_matrix()
    loads = np.asarray(loads, dtype=float).reshape(numbering.n_dofs, -1)
    if relation_rhs is None:
        relation_rhs = np.repeat(np.asarray(rhs, dtype=float)[:, None], loads.shape[1], axis=1)
    elimination = eliminate(b_matrix, np.zeros_like(rhs), numbering.n_dofs)
    # (a model held by no relation: n_relations = 0, one column per load still)
    relation_rhs = np.asarray(relation_rhs, dtype=float).reshape(len(rhs), loads.shape[1])
    u0 = elimination.particular(relation_rhs)
    k_red = elimination.reduce(stiffness)
    if k_red.shape[0] == 0:
        return u0
    lu = _factor(k_red)
    reduced_rhs = np.asarray(elimination.T.T @ (loads - stiffness @ u0))
    q = lu.solve(reduced_rhs.reshape(k_red.shape[0], -1))
    return u0 + elimination.T @ q


def active_components(stiffness, numbering: DofNumbering, nodes, candidates) -> list[str]:
    """Components among ``candidates`` that move under a unit force applied to
    every node of ``nodes`` at once (code_aster's test for the attachment modes
    of DYNA_LINE's nonlinearities): absent components and components blocked on
    all those nodes are inactive."""
    nodes = np.asarray(nodes, dtype=int)
    active = []
    for component in candidates:
        rows = numbering.dof_indices(nodes, component)
        rows = rows[rows >= 0]
        if rows.size == 0:
            continue
        load = np.zeros((numbering.n_dofs, 1))
        load[rows, 0] = 1.0
        response = response_modes(stiffness, numbering, load)
        if np.max(np.abs(response)) > np.finfo(float).eps:
            active.append(component)
    return active
