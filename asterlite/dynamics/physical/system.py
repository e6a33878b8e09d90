"""The reduced linear system of a physical transient and its loads."""

from __future__ import annotations

from dataclasses import dataclass, field

import numpy as np
import scipy.sparse as sp
from scipy.sparse.linalg import splu

from asterlite.dynamics.physical.imposed import ImposedMotion
from asterlite.fem.constraints import Elimination, eliminate
from asterlite.io.disk_rows import DiskRows

# archived instants expanded to full fields at a time (temporaries of that size only)
EXPAND_ROWS = 64


@dataclass
class LoadHistory:
    """Forces that are a history of time and space (a seismic plane wave:
    each boundary point sees the wave with its own delay, so they are no
    vector times f(t)): ``values(times)`` gives them, ``(n_times, m)``, on
    the numbering's DOFs ``rows`` (m,), a DOF appearing as often as it
    takes a term."""

    rows: np.ndarray
    values: object


@dataclass
class Load:
    """A physical load vector (on every DOF of the numbering) times a
    multiplier: a float, or a function / one-parameter formula of time
    evaluated exactly at each instant the scheme asks for. ``history``: a
    part that is a :class:`LoadHistory`, times the same multiplier."""

    vector: np.ndarray
    multiplier: object = 1.0
    history: LoadHistory | None = None

    def coefficients(self, times: np.ndarray) -> np.ndarray:
        times = np.atleast_1d(np.asarray(times, dtype=float))
        if isinstance(self.multiplier, (int, float)):
            return np.full(times.shape, float(self.multiplier))
        return np.asarray(self.multiplier.evaluate(times), dtype=float).reshape(times.shape)


@dataclass
class PhysicalSystem:
    """Reduced matrices (sparse CSR on the free unknowns q) and the loads.
    ``stiffness`` (read it through :meth:`reduced_stiffness`) may be let go
    of while an implicit step factorises (:meth:`release_stiffness`): it is
    reduced again from ``full_stiffness`` when next asked for."""

    elimination: Elimination
    mass: sp.csr_matrix
    stiffness: sp.csr_matrix | None
    damping: sp.csr_matrix | None
    full_stiffness: sp.csr_matrix
    full_mass: sp.csr_matrix | None = None
    full_damping: sp.csr_matrix | None = None
    loads: list[Load] = field(default_factory=list)
    # relations whose right-hand side a function of time multiplies
    imposed: ImposedMotion | None = None
    # the scheme's state of the imposed multipliers at every step instant,
    # and the reduced forces Tᵀ K w, Tᵀ C w, Tᵀ M w it drives (follow_imposed)
    _imposed_state: tuple | None = field(default=None, repr=False)
    _imposed_operators: tuple | None = field(default=None, repr=False)
    # Tᵀ S of each load history (S gathers its terms onto the DOFs), made once
    _history_maps: dict = field(default_factory=dict, repr=False)
    # Tᵀ (K u0) and each load's Tᵀ F, made at the first block of forces
    _reduced_loads: tuple | None = field(default=None, repr=False)

    @property
    def n_free(self) -> int:
        return self.elimination.n_free

    def reduced_stiffness(self) -> sp.csr_matrix:
        """Tᵀ K T, reduced again (the same bits) after :meth:`release_stiffness`."""
        if self.stiffness is None:
            self.stiffness = self.elimination.reduce(self.full_stiffness)
        return self.stiffness

    def release_stiffness(self) -> None:
        """Lets Tᵀ K T go (the steps of NEWMARK and WILSON use M and C only):
        the factorisation of their step matrix does not hold it beside its
        factor. Kept when there is no assembled stiffness to reduce again."""
        if self.full_stiffness is not None:
            self.stiffness = None

    @property
    def n_dofs(self) -> int:
        return self.elimination.T.shape[0]

    def reduce_vector(self, full: np.ndarray) -> np.ndarray:
        return self.elimination.T.T @ full

    def expand(self, q: np.ndarray, store: DiskRows | None = None) -> np.ndarray:
        """Full displacement(s) from reduced ones: rows are instants when 2-D
        (written to ``store`` and read back from it when given)."""
        if q.ndim == 1:
            return self.elimination.T @ q + self.elimination.u0
        return self._expand_rows(q, self.elimination.u0, store)

    def expand_rate(self, qdot: np.ndarray, store: DiskRows | None = None) -> np.ndarray:
        """Full velocities / accelerations (the imposed part is constant)."""
        if qdot.ndim == 1:
            return self.elimination.T @ qdot
        return self._expand_rows(qdot, None, store)

    def _expand_rows(self, reduced: np.ndarray, offset, store) -> np.ndarray:
        # by blocks of instants: the archive's only full-size array is the result
        out = np.empty((reduced.shape[0], self.n_dofs)) if store is None else None
        for start in range(0, reduced.shape[0], EXPAND_ROWS):
            block = (self.elimination.T @ reduced[start : start + EXPAND_ROWS].T).T
            if offset is not None:
                block = block + offset
            if store is None:
                out[start : start + EXPAND_ROWS] = block
            else:
                store.append(block)
        return out if store is None else store.array()

    def restrict(self, full: np.ndarray) -> np.ndarray:
        """Reduced coordinates of a full field (the values of the free DOFs)."""
        return np.asarray(full, dtype=float)[self.elimination.free]

    def forces(self, times: np.ndarray) -> np.ndarray:
        """Reduced external forces Tᵀ (F(t) - K u0) at each instant: (n_times, n_free)."""
        times = np.atleast_1d(np.asarray(times, dtype=float))
        if self._reduced_loads is None:  # the same at every block of instants: made once
            offset = self.reduce_vector(self.full_stiffness @ self.elimination.u0)
            self._reduced_loads = (offset, [self.reduce_vector(load.vector) for load in self.loads])
        offset, vectors = self._reduced_loads
        out = np.tile(-offset, (times.size, 1))
        for load, vector in zip(self.loads, vectors, strict=True):
            coefficients = load.coefficients(times)
            out += np.outer(coefficients, vector)
            if load.history is not None:
                out += coefficients[:, None] * self.reduced_history(load.history, times)
        return out

    def follow_imposed(self, states) -> None:
        """Sets the scheme's (c, ċ, c̈) of the imposed multipliers, each
        (n_times, k) over the step instants (see ``imposed``)."""
        self._imposed_state = states
        if self._imposed_operators is None:
            shapes = self.imposed.shapes
            damping = self.full_damping
            self._imposed_operators = (
                np.asarray(self.elimination.T.T @ (self.full_stiffness @ shapes)),
                None if damping is None else np.asarray(self.elimination.T.T @ (damping @ shapes)),
                np.asarray(self.elimination.T.T @ (self.full_mass @ shapes)),
            )

    def imposed_forces(self, start: int, stop: int) -> np.ndarray:
        """-Tᵀ (K w c + C w ċ + M w c̈) at step instants start..stop-1: the
        reduced forces of the imposed motion, (stop - start, n_free)."""
        c, c_dot, c_ddot = (values[start:stop] for values in self._imposed_state)
        stiffness, damping, mass = self._imposed_operators
        out = -(c @ stiffness.T) - c_ddot @ mass.T
        if damping is not None:
            out -= c_dot @ damping.T
        return out

    def imposed_fields(self, steps: np.ndarray):
        """Full displacement, velocity and acceleration of the imposed
        motion at the step indices ``steps``: three (len(steps), n_dofs)."""
        shapes = self.imposed.shapes
        return tuple(values[steps] @ shapes.T for values in self._imposed_state)

    def reduced_history(self, history: LoadHistory, times: np.ndarray) -> np.ndarray:
        """A load history's reduced forces Tᵀ F(t), (n_times, n_free): its
        terms go through one sparse map, with no full vector per instant."""
        key = id(history)
        if key not in self._history_maps:
            rows = np.asarray(history.rows, dtype=int)
            gather = sp.csr_matrix(
                (np.ones(rows.size), (rows, np.arange(rows.size))), shape=(self.n_dofs, rows.size)
            )
            self._history_maps[key] = sp.csr_matrix(self.elimination.T.T @ gather)
        values = np.asarray(history.values(times), dtype=float)
        return np.asarray((self._history_maps[key] @ values.T).T)

    def load_vector(self, load: Load, t: float) -> np.ndarray:
        """The reduced vector a load multiplies by its coefficient at ``t``."""
        vector = self.reduce_vector(load.vector)
        if load.history is not None:
            vector = vector + self.reduced_history(load.history, np.array([t]))[0]
        return vector

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

        rhs = self.forces([t0])[0] - self.reduced_stiffness() @ q0
        if self.damping is not None:
            rhs -= self.damping @ v0
        inverse = self.diagonal_mass_inverse()
        if inverse is not None:
            return inverse * rhs
        return splu(sp.csc_matrix(self.mass)).solve(rhs)


def build_system(numbering, mass, stiffness, damping, loads, imposed=()) -> PhysicalSystem:
    """``imposed``: (rhs, multiplier) pairs, rhs over the numbering's
    relations, for the relations a function of time multiplies; those
    relations get no constant right-hand side."""
    b_matrix, rhs = numbering.constraint_matrix(rhs_in_time=True)
    rhs = np.array(rhs, dtype=float)
    for varying, _ in imposed:
        rhs[np.asarray(varying) != 0.0] = 0.0
    elimination = eliminate(b_matrix, rhs, numbering.n_dofs)
    stiffness = sp.csr_matrix(stiffness)
    mass = sp.csr_matrix(mass)
    damping = sp.csr_matrix(damping) if damping is not None else None
    motion = None
    if imposed:
        shapes = elimination.particular(np.stack([np.asarray(r, float) for r, _ in imposed], 1))
        motion = ImposedMotion(shapes, [m for _, m in imposed])
    return PhysicalSystem(
        elimination=elimination,
        mass=elimination.reduce(mass),
        stiffness=elimination.reduce(stiffness),
        damping=elimination.reduce(damping) if damping is not None else None,
        full_stiffness=stiffness,
        full_mass=mass,
        full_damping=damping,
        loads=list(loads),
        imposed=motion,
    )
