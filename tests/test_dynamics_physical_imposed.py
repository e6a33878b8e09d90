"""Imposed motion in a PHYS transient: a DDL_IMPO load times a function
of time (EXCIT FONC_MULT), the constrained DOFs following the Newmark
scheme as in code_aster's dlnew0."""

from __future__ import annotations

import numpy as np
import scipy.sparse as sp

from asterlite.concepts.assembly import LinearRelation
from asterlite.dynamics.physical import newmark
from asterlite.dynamics.physical.archive import Archive
from asterlite.dynamics.physical.imposed import newmark_states
from asterlite.dynamics.physical.system import build_system


class Sine:
    """sin(ω t) with the ``evaluate`` of a deck function."""

    def __init__(self, omega):
        self.omega = omega

    def evaluate(self, times):
        return np.sin(self.omega * np.asarray(times, dtype=float))


class ThreeNodes:
    """Nodes 0-1-2 on one component: springs 1e7 (0-1) and 1 (1-2), unit masses."""

    def __init__(self):
        self.dofs = [(0, "DX"), (1, "DX"), (2, "DX")]
        self.index = {dof: i for i, dof in enumerate(self.dofs)}
        self.n_dofs = 3
        self.relations = [LinearRelation([(0, "DX", 1.0)], 1.0)]

    def constraint_matrix(self):
        from asterlite.fem.constraints import relation_matrix

        return relation_matrix(self.relations, self.index, self.n_dofs)


def spring_chain():
    k1, k2 = 1.0e7, 1.0
    stiffness = np.array([[k1, -k1, 0.0], [-k1, k1 + k2, -k2], [0.0, -k2, k2]])
    return sp.csr_matrix(np.eye(3)), sp.csr_matrix(stiffness)


def test_base_driven_oscillator_matches_the_analytic_solution():
    # code_aster's sdld110a: node 0 moves as sin(2t), node 2 hangs on a unit
    # spring: x'' + x = sin(2t) from rest, x = (2 sin t - sin 2t) / 3
    numbering = ThreeNodes()
    mass, stiffness = spring_chain()
    system = build_system(numbering, mass, stiffness, None, [], [(np.array([1.0]), Sine(2.0))])
    times = np.linspace(0.0, 9.0, 361)
    q = np.zeros(system.n_free)
    archive = Archive(system.n_free)
    newmark.integrate(system, times, q, q.copy(), q.copy(), np.ones(times.size, bool), archive)
    out_t, out_q, _, _ = archive.arrays()
    depl = system.expand(out_q) + system.imposed_fields(np.arange(times.size))[0]
    exact = (2.0 * np.sin(out_t) - np.sin(2.0 * out_t)) / 3.0
    assert np.max(np.abs(depl[:, 2] - exact)) < 1.0e-3
    # code_aster's value of the same case (sdld110a, max |error| of DX at node 2)
    assert abs(np.max(np.abs(depl[:, 2] - exact)) - 4.491310788155012e-4) < 1.0e-9
    np.testing.assert_allclose(depl[:, 0], np.sin(2.0 * out_t), atol=1e-15)


def test_newmark_state_of_an_imposed_ramp_is_the_trapezoidal_rule():
    # average acceleration: (ċ_n + ċ_{n+1}) / 2 = (c_{n+1} - c_n) / dt, from ċ_0 = 0
    times = np.linspace(0.0, 1.0, 11)
    values = (3.0 * times)[:, None]
    c, c_dot, c_ddot = newmark_states(values, times, 0.25, 0.5)
    dt = times[1] - times[0]
    np.testing.assert_allclose((c_dot[1:] + c_dot[:-1]) / 2.0, np.diff(c, axis=0) / dt)
    np.testing.assert_allclose(c_dot[:, 0], np.where(np.arange(11) % 2 == 1, 6.0, 0.0), atol=1e-12)
    np.testing.assert_allclose((c_ddot[1:] + c_ddot[:-1]) / 2.0, np.diff(c_dot, axis=0) / dt)
