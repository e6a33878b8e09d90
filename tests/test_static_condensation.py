"""Static superelements (MACR_ELEM_STAT numerics) against closed forms.

A chain of springs k1..k3 between nodes 0..3 condensed on its ends is one
spring of 1/k = Σ 1/k_i; its interior moves as the linear share of the
compliance, and the condensed mass is Σ m_n φ_n φ_nᵀ over those static
shapes. The measured superelement restores the identified modes' spectral
matrices: (T Y)ᵀ K_c (T Y) = diag(ω² m) when T Y is square and invertible.
"""

from __future__ import annotations

import numpy as np
import pytest

from asterlite.substructure import static_condensation as sc

SPRINGS = np.array([2.0e3, 5.0e3, 1.0e3])
MASSES = np.array([1.0, 3.0, 2.0, 0.5])


def chain(springs, masses):
    n = len(masses)
    k = np.zeros((n, n))
    for e, ke in enumerate(springs):
        k[np.ix_([e, e + 1], [e, e + 1])] += ke * np.array([[1.0, -1.0], [-1.0, 1.0]])
    return k, np.diag(masses)


def test_a_spring_chain_condenses_to_its_series_spring():
    k, m = chain(SPRINGS, MASSES)
    condensed = sc.guyan(k, interior=np.array([1, 2]), external=np.array([0, 3]))
    series = 1.0 / np.sum(1.0 / SPRINGS)
    assert np.allclose(condensed.stiffness, series * np.array([[1, -1], [-1, 1]]), rtol=1e-13)
    # interior static shapes: node n follows the far end by its share of compliance
    share = np.cumsum(1.0 / SPRINGS)[:-1] / np.sum(1.0 / SPRINGS)
    expected = np.column_stack([1.0 - share, share])
    assert np.allclose(condensed.interior_modes, expected, rtol=1e-13)
    shapes = np.vstack([[1.0, 0.0], expected, [0.0, 1.0]])
    mass = np.einsum("n,ni,nj->ij", MASSES, shapes, shapes)
    assert np.allclose(condensed.condense(m), mass, rtol=1e-13)
    assert np.allclose(condensed.interior_values(np.array([1.0, 1.0])), 1.0)


def test_a_held_chain_condenses_to_its_end_stiffness():
    # node 0 held (not kept): the condensed stiffness of node 3 alone
    k, _ = chain(SPRINGS, MASSES)
    free = np.arange(1, 4)
    condensed = sc.guyan(k[np.ix_(free, free)], interior=np.array([0, 1]), external=np.array([2]))
    assert condensed.stiffness[0, 0] == pytest.approx(1.0 / np.sum(1.0 / SPRINGS), rel=1e-13)


def test_a_free_interior_is_refused():
    k = np.zeros((3, 3))
    k[:2, :2] = [[1.0, -1.0], [-1.0, 1.0]]  # node 2 is tied to nothing
    with pytest.raises(sc.CondensationError):
        sc.guyan(k, interior=np.array([1, 2]), external=np.array([0]))


def test_a_measured_superelement_restores_the_identified_spectrum():
    rng = np.random.default_rng(3)
    n_sensors, n_basis, n_external = 7, 5, 4
    basis_sensors = rng.normal(size=(n_sensors, n_basis))
    basis_external = rng.normal(size=(n_external, n_basis))
    # identified modes lying in the basis, seen by the sensors
    identified = basis_sensors @ rng.normal(size=(n_basis, n_external))
    omega2 = np.array([10.0, 40.0, 90.0, 250.0])
    mass = np.array([1.0, 2.0, 0.5, 4.0])
    damping = np.array([0.01, 0.02, 0.03, 0.04])
    macro = sc.measured(basis_sensors, basis_external, identified, omega2, mass, damping)
    at_interface = basis_external @ np.linalg.pinv(basis_sensors) @ identified
    for kind, weights in (("RIGI", omega2 * mass), ("MASS", mass), ("AMOR", damping * mass)):
        spectral = at_interface.T @ macro.matrix(kind) @ at_interface
        assert np.allclose(spectral, np.diag(weights), rtol=1e-9, atol=1e-9 * weights.max())
    # the interface motion of mode 2 gives back mode 2 at the sensors
    assert np.allclose(macro.sensor_values(at_interface[:, 2]), identified[:, 2], rtol=1e-9)


def test_too_few_sensors_or_interface_dofs_are_refused():
    with pytest.raises(sc.CondensationError, match="sensors"):
        sc.measured(np.ones((2, 3)), np.ones((4, 3)), np.ones((2, 2)), [1, 1], [1, 1])
    with pytest.raises(sc.CondensationError, match="external DOFs"):
        sc.measured(np.eye(3), np.ones((1, 3)), np.ones((3, 2)), [1, 1], [1, 1])


def test_relations_inside_bind_the_interior():
    k, m = chain(SPRINGS, MASSES)
    # u1 = u2 (LIAISON_DDL): spring 2 carries nothing, springs 1 and 3 in series
    tie = np.array([[0.0, 1.0, -1.0, 0.0]])
    condensed = sc.constrained_guyan(k, tie, external=np.array([0, 3]))
    series = 1.0 / (1.0 / SPRINGS[0] + 1.0 / SPRINGS[2])
    assert np.allclose(condensed.stiffness, series * np.array([[1, -1], [-1, 1]]), rtol=1e-12)
    # the tied nodes move together, at the compliance share of spring 1
    share = (1.0 / SPRINGS[0]) / (1.0 / SPRINGS[0] + 1.0 / SPRINGS[2])
    assert np.allclose(condensed.interior_modes, [[1 - share, share]] * 2, rtol=1e-12)
    # u2 = 0 (DDL_IMPO): each end held by its own springs
    held = np.array([[0.0, 0.0, 1.0, 0.0]])
    condensed = sc.constrained_guyan(k, held, external=np.array([0, 3]))
    left = 1.0 / (1.0 / SPRINGS[0] + 1.0 / SPRINGS[1])
    assert np.allclose(condensed.stiffness, np.diag([left, SPRINGS[2]]), rtol=1e-12)
    mass = condensed.condense(m)
    shapes = np.zeros((4, 2))
    shapes[0, 0], shapes[3, 1] = 1.0, 1.0
    shapes[1, 0] = (1.0 / SPRINGS[1]) / (1.0 / SPRINGS[0] + 1.0 / SPRINGS[1])
    assert np.allclose(mass, shapes.T @ m @ shapes, rtol=1e-12)


def test_a_relation_binding_an_external_dof_is_refused():
    k, _ = chain(SPRINGS, MASSES)
    with pytest.raises(sc.CondensationError):
        sc.constrained_guyan(k, np.array([[1.0, -1.0, 0.0, 0.0]]), external=np.array([0, 3]))
