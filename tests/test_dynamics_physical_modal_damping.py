"""AMOR_MODAL of a physical transient (asterlite.dynamics.physical.modal_damping):
code_aster's explicit modal damping force f = Σ 2ξ/(m ω³) (Kφ)(Kφ)ᵀ v."""

from __future__ import annotations

import numpy as np
import pytest
import scipy.linalg as sla
import scipy.sparse as sp

from asterlite.dynamics.physical import newmark, wilson
from asterlite.dynamics.physical.archive import Archive
from asterlite.dynamics.physical.modal_damping import (
    ModalDamping,
    build_modal_damping,
    damping_ratios,
)
from asterlite.dynamics.physical.system import Load, PhysicalSystem
from asterlite.fem.constraints import eliminate


def chain(n=3, k=1.0e4, m=2.0):
    stiffness = np.zeros((n, n))
    for i in range(n):
        stiffness[i, i] += k
        if i + 1 < n:
            stiffness[i, i] += k
            stiffness[i, i + 1] = stiffness[i + 1, i] = -k
    return m * np.eye(n), stiffness


def free_elimination(n):
    return eliminate(sp.csr_matrix((0, n)), np.zeros(0), n)


def system_of(mass, stiffness, force, damping=None):
    n = mass.shape[0]
    return PhysicalSystem(
        elimination=free_elimination(n),
        mass=sp.csr_matrix(mass),
        stiffness=sp.csr_matrix(stiffness),
        damping=None if damping is None else sp.csr_matrix(damping),
        full_stiffness=sp.csr_matrix(stiffness),
        loads=[Load(force, 1.0)],
    )


def modes_of(mass, stiffness):
    omega2, phi = sla.eigh(stiffness, mass)  # mass-normalised: φᵀ M φ = 1
    return np.sqrt(omega2) / (2.0 * np.pi), phi, np.ones(phi.shape[1])


def test_equivalent_matrix_is_m_phi_diag_phi_t_m():
    mass, stiffness = chain()
    freq, phi, masses = modes_of(mass, stiffness)
    xi = np.array([0.01, 0.02, 0.05])
    modal = build_modal_damping(free_elimination(3), stiffness @ phi, freq, masses, xi)
    omega = 2.0 * np.pi * freq
    expected = mass @ phi @ np.diag(2.0 * xi * omega / masses) @ phi.T @ mass
    np.testing.assert_allclose(modal.matrix(), expected, rtol=1e-10, atol=1e-12)
    # in modal coordinates: diag(2 ξ ω)
    np.testing.assert_allclose(phi.T @ modal.matrix() @ phi, np.diag(2 * xi * omega), atol=1e-9)
    v = np.array([0.3, -1.0, 2.0])
    np.testing.assert_allclose(modal.force(v), expected @ v, rtol=1e-10)


def test_generalized_mass_and_truncated_basis():
    mass, stiffness = chain()
    freq, phi, _ = modes_of(mass, stiffness)
    scale = np.array([2.0, 0.5])
    shapes = phi[:, :2] * scale  # MASS_GENE = scale²
    modal = build_modal_damping(
        free_elimination(3), stiffness @ shapes, freq[:2], scale**2, [0.02] * 2
    )
    omega = 2.0 * np.pi * freq[:2]
    expected = mass @ phi[:, :2] @ np.diag(2 * 0.02 * omega) @ phi[:, :2].T @ mass
    np.testing.assert_allclose(modal.matrix(), expected, rtol=1e-10, atol=1e-12)
    assert modal.n_modes == 2


def test_damping_ratios_repeat_the_last_value_and_cut_extra_ones():
    values, too_many = damping_ratios([0.01, 0.02], 4)
    np.testing.assert_array_equal(values, [0.01, 0.02, 0.02, 0.02])
    assert not too_many
    values, too_many = damping_ratios([0.01, 0.02, 0.03], 2)
    np.testing.assert_array_equal(values, [0.01, 0.02])
    assert too_many
    values, _ = damping_ratios(0.001, 3)
    np.testing.assert_array_equal(values, [0.001] * 3)


def test_zero_frequency_mode_is_refused():
    mass, stiffness = chain()
    _, phi, masses = modes_of(mass, stiffness)
    with pytest.raises(ValueError, match="zero frequency"):
        build_modal_damping(
            free_elimination(3), stiffness @ phi, [0.0, 1.0, 2.0], masses, [0.01] * 3
        )


def test_a_negative_frequency_keeps_its_sign_as_in_code_aster():
    # a free structure's rigid-body modes come out at ±1e-6 Hz, the sign set by
    # round-off: ω = 2π FREQ keeps it (code_aster's dampModalPreparation), so
    # 2ξ/(m ω³) (K φ)(K φ)ᵀ = 2ξ ω/m (M φ)(M φ)ᵀ for exact modes, of either sign
    mass, stiffness = chain()
    freq, phi, masses = modes_of(mass, stiffness)
    signed = freq * np.array([-1.0, 1.0, 1.0])
    shapes = stiffness @ phi
    shapes[:, 0] = (2.0 * np.pi * signed[0]) ** 2 * (mass @ phi[:, 0])  # K φ = ω² M φ
    xi = np.array([0.01, 0.02, 0.05])
    modal = build_modal_damping(free_elimination(3), shapes, signed, masses, xi)
    omega = 2.0 * np.pi * signed
    expected = mass @ phi @ np.diag(2.0 * xi * omega / masses) @ phi.T @ mass
    np.testing.assert_allclose(modal.matrix(), expected, rtol=1e-10, atol=1e-12)


def test_eliminated_dofs_are_projected_with_t():
    # DOF 0 fixed: the reduced basis is Tᵀ K φ, the blocked row is dropped
    mass, stiffness = chain(4)
    b_matrix = sp.csr_matrix(([1.0], ([0], [0])), shape=(1, 4))
    elimination = eliminate(b_matrix, np.zeros(1), 4)
    reduced_k = stiffness[1:, 1:]
    freq, phi_r, masses = modes_of(mass[1:, 1:], reduced_k)
    phi = np.vstack([np.zeros((1, 3)), phi_r])
    modal = build_modal_damping(elimination, stiffness @ phi, freq, masses, [0.03] * 3)
    expected = mass[1:, 1:] @ phi_r @ np.diag(2 * 0.03 * 2 * np.pi * freq) @ phi_r.T @ mass[1:, 1:]
    np.testing.assert_allclose(modal.matrix(), expected, rtol=1e-10, atol=1e-12)


class Constant:
    def __init__(self, value):
        self.value = value

    def evaluate(self, times):
        return np.full(np.shape(times), self.value)


def test_support_velocity_is_added_before_projection():
    basis = np.array([[1.0, 0.0], [2.0, 1.0], [0.0, 3.0]])
    shape = np.array([1.0, 1.0, 1.0, 5.0])  # the 4th DOF: a support DOF (not free)
    full = np.vstack([basis, [[1.0, 2.0]]])
    elimination = eliminate(sp.csr_matrix(([1.0], ([0], [3])), shape=(1, 4)), np.zeros(1), 4)
    modal = build_modal_damping(
        elimination, full, [1.0, 2.0], [1.0, 1.0], [0.1, 0.2], [(shape, Constant(0.5))]
    )
    v = np.array([0.2, -0.1, 0.4])
    c = 2.0 * np.array([0.1, 0.2]) / (2.0 * np.pi * np.array([1.0, 2.0])) ** 3
    absolute = np.concatenate([v, [0.0]]) + 0.5 * shape
    expected = basis @ (c * (full.T @ absolute))
    np.testing.assert_allclose(modal.force(v, 0.0), expected, rtol=1e-12)
    np.testing.assert_allclose(modal.force(v), basis @ (c * (basis.T @ v)), rtol=1e-12)


def newmark_reference(mass, stiffness, c_modal, force, times, q, v, beta=0.25, gamma=0.5):
    """Dense NEWMARK with the modal force explicit in the start-of-step velocity."""
    c = newmark.coefficients(times[1] - times[0], beta, gamma)
    keff = stiffness + c[0] * mass
    a = np.zeros_like(q)
    out = [q.copy()]
    for _ in times[1:]:
        rhs = force - c_modal @ v + mass @ (c[0] * q + c[2] * v + c[3] * a)
        q_new = np.linalg.solve(keff, rhs)
        a_new = c[0] * (q_new - q) - c[2] * v - c[3] * a
        v = v + c[6] * a + c[7] * a_new
        q, a = q_new, a_new
        out.append(q.copy())
    return np.array(out)


def test_newmark_applies_the_modal_force_explicitly():
    mass, stiffness = chain()
    freq, phi, masses = modes_of(mass, stiffness)
    modal = build_modal_damping(free_elimination(3), stiffness @ phi, freq, masses, [0.05] * 3)
    force = np.array([0.0, 0.0, 10.0])
    times = 1.0e-3 * np.arange(301)
    archive = Archive(3)
    system = system_of(mass, stiffness, force)
    newmark.integrate(
        system,
        times,
        np.zeros(3),
        np.zeros(3),
        np.zeros(3),
        np.ones(times.size, bool),
        archive,
        modal=modal,
    )
    _, q, _, _ = archive.arrays()
    expected = newmark_reference(
        mass, stiffness, modal.matrix(), force, times, np.zeros(3), np.zeros(3)
    )
    np.testing.assert_allclose(q, expected, rtol=1e-9, atol=1e-14)


@pytest.mark.parametrize("scheme", ["NEWMARK", "WILSON"])
def test_free_vibration_decays_at_the_modal_rate(scheme):
    m, k, xi = 2.0, 8.0e3, 0.02
    mass, stiffness = np.array([[m]]), np.array([[k]])
    omega = np.sqrt(k / m)
    modal = build_modal_damping(
        free_elimination(1),
        stiffness @ np.array([[1.0 / np.sqrt(m)]]),
        [omega / (2 * np.pi)],
        [1.0],
        [xi],
    )
    period = 2 * np.pi / omega
    times = np.linspace(0.0, 10 * period, 4001)
    system = system_of(mass, stiffness, np.zeros(1))
    q0 = np.array([1.0e-3])
    a0 = system.initial_acceleration(0.0, q0, np.zeros(1))
    archive = Archive(1)
    mask = np.ones(times.size, bool)
    if scheme == "NEWMARK":
        newmark.integrate(system, times, q0, np.zeros(1), a0, mask, archive, modal=modal)
    else:
        wilson.integrate(system, times, q0, np.zeros(1), a0, mask, archive, modal=modal)
    _, q, _, _ = archive.arrays()
    expected = 1.0e-3 * np.exp(-xi * omega * times[-1])  # after 10 periods
    assert abs(q[-1, 0] - expected) < 0.01 * expected
    # undamped reference keeps its amplitude: the decay is the modal force's
    archive = Archive(1)
    newmark.integrate(system, times, q0, np.zeros(1), a0, mask, archive)
    assert archive.arrays()[1][-1, 0] > 0.99e-3


def test_modal_damping_is_low_rank():
    modal = ModalDamping(basis=np.ones((1000, 2)), coefficients=np.array([1.0, 2.0]))
    assert modal.force(np.ones(1000)).shape == (1000,)
