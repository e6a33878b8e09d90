"""The reduced linear system of a physical transient and its loads."""

from __future__ import annotations

from dataclasses import dataclass, field

import numpy as np
import scipy.sparse as sp

from asterlite.fem.constraints import Elimination, eliminate


@dataclass
class Load:
    """A physical load vector (on every DOF of the numbering) times a
    multiplier: a float, or a function / one-parameter formula of time
    evaluated exactly at each instant the scheme asks for."""

    vector: np.ndarray
    multiplier: object = 1.0

    def coefficients(self, times: np.ndarray) -> np.ndarray:
        times = np.atleast_1d(np.asarray(times, dtype=float))
        if isinstance(self.multiplier, (int, float)):
            return np.full(times.shape, float(self.multiplier))
        return np.asarray(self.multiplier.evaluate(times), dtype=float).reshape(times.shape)


@dataclass
class PhysicalSystem:
    """Reduced matrices (sparse CSR on the free unknowns q) and the loads."""

    elimination: Elimination
    mass: sp.csr_matrix
    stiffness: sp.csr_matrix
    damping: sp.csr_matrix | None
    full_stiffness: sp.csr_matrix
    loads: list[Load] = field(default_factory=list)

    @property
    def n_free(self) -> int:
        return self.elimination.n_free

    @property
    def n_dofs(self) -> int:
        return self.elimination.T.shape[0]

    def reduce_vector(self, full: np.ndarray) -> np.ndarray:
        return self.elimination.T.T @ full

    def expand(self, q: np.ndarray) -> np.ndarray:
        """Full displacement(s) from reduced ones: rows are instants when 2-D."""
        if q.ndim == 1:
            return self.elimination.T @ q + self.elimination.u0
        return (self.elimination.T @ q.T).T + self.elimination.u0

    def expand_rate(self, qdot: np.ndarray) -> np.ndarray:
        """Full velocities / accelerations (the imposed part is constant)."""
        if qdot.ndim == 1:
            return self.elimination.T @ qdot
        return (self.elimination.T @ qdot.T).T

    def restrict(self, full: np.ndarray) -> np.ndarray:
        """Reduced coordinates of a full field (the values of the free DOFs)."""
        return np.asarray(full, dtype=float)[self.elimination.free]

    def forces(self, times: np.ndarray) -> np.ndarray:
        """Reduced external forces Tᵀ (F(t) - K u0) at each instant: (n_times, n_free)."""
        times = np.atleast_1d(np.asarray(times, dtype=float))
        offset = self.reduce_vector(self.full_stiffness @ self.elimination.u0)
        out = np.tile(-offset, (times.size, 1))
        for load in self.loads:
            out += np.outer(load.coefficients(times), self.reduce_vector(load.vector))
        return out

    def diagonal_mass_inverse(self) -> np.ndarray | None:
        """1/m_ii when the reduced mass is diagonal (0 for massless DOFs),
        else None."""
        off = self.mass - sp.diags(self.mass.diagonal())
        if off.count_nonzero():
            return None
        diag = self.mass.diagonal()
        inv = np.zeros_like(diag)
        nonzero = diag != 0.0
        inv[nonzero] = 1.0 / diag[nonzero]
        return inv

    def initial_acceleration(self, t0: float, q0, v0) -> np.ndarray:
        """M a0 = F(t0) - K q0 - C v0 (massless DOFs get a zero acceleration)."""
        from scipy.sparse.linalg import splu

        rhs = self.forces([t0])[0] - self.stiffness @ q0
        if self.damping is not None:
            rhs -= self.damping @ v0
        inverse = self.diagonal_mass_inverse()
        if inverse is not None:
            return inverse * rhs
        return splu(sp.csc_matrix(self.mass)).solve(rhs)


def build_system(numbering, mass, stiffness, damping, loads) -> PhysicalSystem:
    b_matrix, rhs = numbering.constraint_matrix()
    elimination = eliminate(b_matrix, rhs, numbering.n_dofs)
    stiffness = sp.csr_matrix(stiffness)
    return PhysicalSystem(
        elimination=elimination,
        mass=elimination.reduce(sp.csr_matrix(mass)),
        stiffness=elimination.reduce(stiffness),
        damping=elimination.reduce(sp.csr_matrix(damping)) if damping is not None else None,
        full_stiffness=stiffness,
        loads=list(loads),
    )
