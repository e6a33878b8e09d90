"""code_aster's view of a numbering with dualised constraints, for the object
API of decks (``toNumpy()``, ``getPhysicalDOFs()``, ``getValues()``...).

asterlite solves with the constraints kept as relations (eliminated, see
:mod:`asterlite.fem.constraints`); code_aster dualises each relation
``sum a_i u_i = b`` of AFFE_CHAR_MECA with two Lagrange multipliers
(λ1, λ2) that are unknowns of its numbering. This module lays the physical
DOFs and the multipliers out as code_aster's NUME_DDL does and builds the
arrays a deck reads there:

- placement: a relation's λ1 comes just before the DOFs of the first node it
  involves (in numbering order), its λ2 just after those of the last node;
  several multipliers at one place keep the relations' order; a relation of
  a load with DOUBLE_LAGRANGE='NON' has its λ1 only;
- the stiffness's terms (double Lagrange): for each relation, ``β a_i`` in
  the (u_i, λ1) and (u_i, λ2) places, ``-β`` on the two diagonal terms and
  ``β`` between λ1 and λ2, with β = (smallest nonzero + largest) absolute
  diagonal term of the physical matrix over 2 (code_aster's assma1/echmat
  conditioning); a single multiplier has the ``β a_i`` terms only (a zero
  diagonal); the other matrices (mass, damping, gyroscopy) carry no
  load terms, so their multiplier rows and columns are zero;
- a field's multiplier values: λ1 = λ2 = r_i / (2 β) for a single-term
  relation on DOF i with reaction r (the value code_aster's solution holds),
  λ1 = r_i / β for a single multiplier.

Relations of several terms (LIAISON_*) are laid out the same way, but their
multipliers have no single (node, component) to name, nor a reaction to
split: asking for those is refused by name.
"""

from __future__ import annotations

from dataclasses import dataclass

import numpy as np

from asterlite.errors import UnsupportedError


def dualised_relations(numbering) -> list:
    """The numbering's relations code_aster dualises: all but those of the
    kinematic loads (AFFE_CHAR_CINE), which it eliminates instead."""
    kinematic = {id(r) for load in numbering.kinematic_loads for r in load.relations}
    return [r for r in numbering.relations if id(r) not in kinematic]


def constrained_rows(numbering) -> np.ndarray:
    """The numbering rows of the DOFs the dualised relations involve (sorted):
    where a solve must know the reactions to give the multipliers."""
    index = numbering.index
    rows = {
        index[(node, comp)] for r in dualised_relations(numbering) for node, comp, _a in r.terms
    }
    return np.array(sorted(rows), dtype=int)


@dataclass(frozen=True)
class LagrangeLayout:
    """Positions of the physical DOFs and of the multipliers in code_aster's
    numbering of ``numbering``."""

    size: int
    physical: np.ndarray  # position of each physical DOF (numbering order)
    first: np.ndarray  # position of each relation's λ1
    second: np.ndarray  # position of each relation's λ2 (-1: a single multiplier)
    relations: tuple  # the dualised relations, in order
    labels: tuple  # (node, component) of each position; component 'LAGR:DX' for λ

    @property
    def lagrange(self) -> np.ndarray:
        return np.sort(np.concatenate([self.first, self.second[self.second >= 0]]))


def lagrange_layout(numbering) -> LagrangeLayout:
    cache = numbering.__dict__.setdefault("_lagrange_layout", {})
    relations = tuple(dualised_relations(numbering))
    key = tuple(id(r) for r in relations)
    if key not in cache:
        cache[key] = _build(numbering, relations)
    return cache[key]


def _build(numbering, relations) -> LagrangeLayout:
    node_order: dict[int, int] = {}
    blocks: dict[int, list[int]] = {}
    for row, (node, _comp) in enumerate(numbering.dofs):
        node_order.setdefault(node, len(node_order))
        blocks.setdefault(node, []).append(row)
    before: dict[int, list[int]] = {}
    after: dict[int, list[int]] = {}
    for k, relation in enumerate(relations):
        nodes = sorted({n for n, _c, _a in relation.terms}, key=lambda n: node_order[n])
        before.setdefault(nodes[0], []).append(k)
        if relation.double_lagrange:
            after.setdefault(nodes[-1], []).append(k)
    physical = np.empty(numbering.n_dofs, dtype=int)
    first = np.empty(len(relations), dtype=int)
    second = np.full(len(relations), -1, dtype=int)
    labels: list[tuple[int, str]] = []
    for node in sorted(blocks, key=lambda n: node_order[n]):
        for k in before.get(node, ()):
            first[k] = len(labels)
            labels.append((node, _lagrange_component(relations[k])))
        for row in blocks[node]:
            physical[row] = len(labels)
            labels.append(numbering.dofs[row])
        for k in after.get(node, ()):
            second[k] = len(labels)
            labels.append((node, _lagrange_component(relations[k])))
    return LagrangeLayout(len(labels), physical, first, second, relations, tuple(labels))


def _lagrange_component(relation) -> str:
    """code_aster names a DDL_IMPO multiplier after the DOF it holds
    ('LAGR:DX'); a relation of several terms has no such name."""
    return f"LAGR:{relation.terms[0][1]}" if len(relation.terms) == 1 else ""


def lagrange_coefficient(matrix) -> float:
    """β: the mean of the smallest nonzero and the largest absolute diagonal
    term of the physical matrix (1 when it has none)."""
    if isinstance(matrix, np.ndarray):
        diagonal = np.abs(np.diagonal(matrix))
    else:  # sparse: a block of rows at a time, a matrix on disk is not read whole
        from asterlite.fem import matrix_rows

        diagonal = np.abs(matrix_rows.diagonal(matrix))
    nonzero = diagonal[diagonal > np.finfo(float).eps]
    if nonzero.size == 0:
        return 1.0
    return 0.5 * (float(nonzero.min()) + float(nonzero.max()))


def full_matrix(assembled, dense: np.ndarray, with_load_terms: bool) -> np.ndarray:
    """``dense`` (the physical matrix) laid out with the multipliers; the
    double-Lagrange terms when the matrix carries the loads' terms."""
    layout = lagrange_layout(assembled.numbering)
    full = np.zeros((layout.size, layout.size), dtype=dense.dtype)
    full[np.ix_(layout.physical, layout.physical)] = dense
    if not with_load_terms:
        return full
    beta = lagrange_coefficient(assembled.matrix)
    index = assembled.numbering.index
    for relation, one, two in zip(layout.relations, layout.first, layout.second, strict=True):
        for node, comp, coef in relation.terms:
            u = layout.physical[index[(node, comp)]]
            for lam in (one, two) if two >= 0 else (one,):
                full[u, lam] += beta * coef
                full[lam, u] += beta * coef
        if two < 0:
            continue
        full[one, one] += -beta
        full[two, two] += -beta
        full[one, two] += beta
        full[two, one] += beta
    return full


def full_vector(numbering, values, reactions=None, beta: float = 1.0) -> np.ndarray:
    """A field's values laid out with the multipliers: λ1 = λ2 = r / (2 β) of
    each single-term relation (λ1 = r / β under DOUBLE_LAGRANGE='NON';
    ``reactions`` per physical DOF); refused without reactions or for a
    relation of several terms."""
    layout = lagrange_layout(numbering)
    values = np.asarray(values)
    full = np.zeros(layout.size, dtype=values.dtype)
    full[layout.physical] = values
    if not layout.relations:
        return full
    if reactions is None:
        raise UnsupportedError(
            "the values of code_aster's Lagrange multipliers (the reactions of the "
            f"{len(layout.relations)} dualised constraints) are not computed for this field"
        )
    for relation, one, two in zip(layout.relations, layout.first, layout.second, strict=True):
        if len(relation.terms) != 1:
            raise UnsupportedError(
                "the Lagrange multipliers of a relation of several terms (LIAISON_*) "
                "are not computed"
            )
        node, comp, coef = relation.terms[0]
        reaction = reactions[numbering.index[(node, comp)]]
        if two < 0:
            full[one] = reaction / (beta * coef)
        else:
            full[one] = full[two] = reaction / (2.0 * beta * coef)
    return full
