"""The coupled generalized model: placement, interface pairing, compatibility.

Each substructure k has generalized unknowns q_k; its interface DOFs are
u_I = Φ_I q_k in its own frame, R_k Φ_I q_k in the global one. A link
glues paired nodes: R_1 Φ_1,I q_1 - R_2 Φ_2,I q_2 = 0, one row per
global component of the interface. code_aster dualises these rows with
Lagrange multipliers (or eliminates them, NUME_DDL_GENE METHODE='ELIMINE');
both give the modes of the pencil restricted to the null space of B,
which is what :func:`coupled_modes` computes."""

from __future__ import annotations

import numpy as np
import scipy.linalg as la
import scipy.sparse as sp

from asterlite.fem.constraints import Elimination
from asterlite.fem.dofs import ROTATIONS, TRANSLATIONS
from asterlite.fem.frames import rotation_from_angles
from asterlite.modal.calc import select_modes
from asterlite.modal.eigen import ReducedPencil


class CouplingError(ValueError):
    """Interfaces that cannot be glued (message for the user)."""


def placement_rotation(angles_deg) -> np.ndarray:
    """Local-to-global rotation of ANGL_NAUT (degrees): Rz(α) Ry(β) Rx(γ)."""
    angles = np.zeros(3)
    given = np.asarray(angles_deg, dtype=float).ravel()[:3]
    angles[: given.size] = given
    return rotation_from_angles(np.radians(angles)).T


def interface_nodes_global(sub, interface) -> np.ndarray:
    """(n_nodes, 3) coordinates of an interface's nodes in the global frame."""
    return sub.to_global(sub.macro.mesh.coords[interface.nodes])


def pair_nodes(sub1, interface1, sub2, interface2, precision, relative=True):
    """[(i, j)] pairs interface1.nodes[i] <-> interface2.nodes[j], each node
    of side 1 matched to the nearest node of side 2 (code_aster's rule);
    the largest gap must stay below ``precision`` (relative to the largest
    distance of an interface node to the origin when ``relative``)."""
    x1 = interface_nodes_global(sub1, interface1)
    x2 = interface_nodes_global(sub2, interface2)
    if len(x1) != len(x2):
        raise CouplingError(
            f"interface {interface1.name} of {sub1.name} has {len(x1)} nodes,"
            f" interface {interface2.name} of {sub2.name} has {len(x2)}"
        )
    distance = np.linalg.norm(x1[:, None, :] - x2[None, :, :], axis=2)
    nearest = np.argmin(distance, axis=1)
    if len(set(nearest.tolist())) != len(nearest):
        raise CouplingError(
            f"two nodes of interface {interface1.name} of {sub1.name} face the same node"
            f" of interface {interface2.name} of {sub2.name}"
        )
    gap = float(np.max(distance[np.arange(len(x1)), nearest])) if len(x1) else 0.0
    if relative:
        scale = max(float(np.max(np.linalg.norm(np.vstack([x1, x2]), axis=1))), 0.0)
        if scale == 0.0:
            raise CouplingError("the interface nodes are all at the origin")
        gap /= scale
    if gap > precision:
        raise CouplingError(
            f"the nodes of interface {interface1.name} of {sub1.name} and"
            f" {interface2.name} of {sub2.name} do not coincide (gap {gap:.3g}"
            f" > PRECISION {precision:g})"
        )
    return [(i, int(j)) for i, j in enumerate(nearest)]


def _global_components(rotation, local: set[str], group) -> tuple[str, ...]:
    """The global components a node's local ``group`` components map onto;
    a rotation that mixes kept and masked components cannot be glued."""
    kept = [k for k, c in enumerate(group) if c in local]
    if not kept:
        return ()
    image = np.abs(rotation[:, kept]) > 1e-9
    rows = np.flatnonzero(np.any(image, axis=1))
    if len(rows) != len(kept):
        raise CouplingError(
            "the substructure's rotation mixes interface components with masked ones"
        )
    return tuple(group[r] for r in rows)


def node_block(sub, interface, position) -> tuple[dict[str, np.ndarray], tuple[str, ...]]:
    """Global interface displacement rows of one interface node: component
    -> (n_modes,) row of R Φ, and the components that are constrained."""
    basis = sub.macro.basis
    numbering = basis.numbering
    node = int(interface.nodes[position])
    rows = interface.dofs[interface.dof_nodes == node]
    local = {numbering.dofs[r][1]: basis.shapes[r] for r in rows}
    out, comps = {}, ()
    for group in (TRANSLATIONS, ROTATIONS):
        block = np.array([local.get(c, np.zeros(basis.n_modes)) for c in group])
        rotated = sub.rotation @ block
        out.update({c: rotated[k] for k, c in enumerate(group)})
        comps += _global_components(sub.rotation, set(local), group)
    return out, comps


def constraint_rows(model, offsets) -> np.ndarray:
    """B (n_rows, n_gene): the compatibility relations of every link."""
    n = int(offsets[-1])
    index = {sub.name: k for k, sub in enumerate(model.substructures)}
    rows = []
    for link in model.links:
        s1 = model.substructures[index[link.substructure_1]]
        s2 = model.substructures[index[link.substructure_2]]
        i1 = s1.macro.interfaces.find(link.interface_1)
        i2 = s2.macro.interfaces.find(link.interface_2)
        o1, o2 = offsets[index[s1.name]], offsets[index[s2.name]]
        for p1, p2 in link.pairs:
            b1, c1 = node_block(s1, i1, p1)
            b2, c2 = node_block(s2, i2, p2)
            if set(c1) != set(c2):
                raise CouplingError(
                    f"interfaces {i1.name} of {s1.name} and {i2.name} of {s2.name} do not"
                    f" hold the same components ({' '.join(c1)} / {' '.join(c2)})"
                )
            for comp in c1:
                row = np.zeros(n)
                row[o1 : o1 + s1.macro.n_modes] += b1[comp]
                row[o2 : o2 + s2.macro.n_modes] -= b2[comp]
                rows.append(row)
    return np.array(rows).reshape(len(rows), n)


def null_space_basis(constraints: np.ndarray, n: int) -> np.ndarray:
    """(n, n_free) orthonormal basis of {q : B q = 0} (redundant rows allowed)."""
    if constraints.size == 0:
        return np.eye(n)
    scale = np.linalg.norm(constraints, axis=1)
    scaled = constraints[scale > 0] / scale[scale > 0, None]
    return la.null_space(scaled, rcond=1e-10)


def coupled_modes(stiffness, mass, constraints, option, freq, nmax):
    """(ω², vectors on the full generalized unknowns) of the constrained pencil."""

    n = stiffness.shape[0]
    basis = null_space_basis(np.asarray(constraints, dtype=float), n)
    elimination = Elimination(
        sp.csr_matrix(basis), np.zeros(n), np.arange(basis.shape[1]), np.array([], dtype=int)
    )
    pencil = ReducedPencil(np.asarray(stiffness), np.asarray(mass), elimination)
    omega2, vecs = select_modes(pencil, option, freq, nmax)
    return omega2, pencil.expand(vecs)
