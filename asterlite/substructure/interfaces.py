"""Interface DOFs and the static modes of classical reduction bases.

A CRAIGB (Craig-Bampton) basis is the fixed-interface modes plus one
constraint mode per interface DOF (unit displacement there, the other
interface DOFs held); CB_HARMO does the same with K - ω² M at the
interface FREQ; an MNEAL (MacNeal) basis is the free-interface modes plus
one attachment mode per interface DOF (static response to a unit force);
AUCUN adds nothing."""

from __future__ import annotations

import numpy as np

from asterlite.concepts.assembly import DofNumbering
from asterlite.modal.static_modes import blocked_dofs, constrained_modes, response_modes


class InterfaceError(ValueError):
    """An interface the reduction cannot be built on (message for the user)."""


def interface_dofs(numbering: DofNumbering, nodes, masked) -> tuple[np.ndarray, np.ndarray]:
    """(DOF indices, their nodes): every component the numbering carries at
    each node (nodes in the given order, components in numbering order),
    less the MASQUE components."""
    masked = set(masked)
    by_node: dict[int, list[int]] = {}
    for i, (node, comp) in enumerate(numbering.dofs):
        if comp not in masked:
            by_node.setdefault(node, []).append(i)
    dofs, owners = [], []
    for node in nodes:
        for i in by_node.get(int(node), []):
            dofs.append(i)
            owners.append(int(node))
    return np.array(dofs, dtype=int), np.array(owners, dtype=int)


def static_modes(kind: str, dofs, numbering, stiffness, mass=None, frequency=1.0):
    """(modes (n_dofs, k), the k interface DOFs they belong to) of one
    interface of type ``kind``.

    CRAIGB / CB_HARMO give one constraint mode per interface DOF that the
    matrices' loads block (DDL_IMPO): the unit displacement replaces that
    blocking, as code_aster imposes it through the DOF's Lagrange
    multiplier; an interface DOF left free has no constraint mode (its
    motion is carried by the fixed-interface modes)."""
    dofs = np.asarray(dofs, dtype=int)
    if kind == "AUCUN" or dofs.size == 0:
        return np.zeros((numbering.n_dofs, 0)), np.zeros(0, dtype=int)
    blocked = blocked_dofs(numbering)
    if kind in ("CRAIGB", "CB_HARMO"):
        held = np.array([d for d in dofs if int(d) in blocked], dtype=int)
        if held.size == 0:
            raise InterfaceError(
                f"no DOF of this {kind} interface is blocked in the matrices: the"
                " fixed-interface modes need the interface held (DDL_IMPO)"
            )
        matrix = stiffness
        if kind == "CB_HARMO":
            if mass is None:
                raise InterfaceError("CB_HARMO needs the mass matrix of the modes")
            matrix = stiffness - (2.0 * np.pi * frequency) ** 2 * mass
        return constrained_modes(matrix, numbering, held), held
    if kind == "MNEAL":
        # a DOF the matrices block (DDL_IMPO) carries no attachment mode: a
        # unit force there would move nothing (code_aster leaves it out of
        # the interface's deformations too)
        dofs = np.array([d for d in dofs if int(d) not in blocked], dtype=int)
        loads = np.zeros((numbering.n_dofs, dofs.size))
        loads[dofs, np.arange(dofs.size)] = 1.0
        return response_modes(stiffness, numbering, loads), dofs
    raise InterfaceError(f"unknown interface type {kind!r}")
