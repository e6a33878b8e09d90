"""Static superelements (code_aster's MACR_ELEM_STAT): matrices condensed
on the external DOFs.

Two ways, as op0086 builds them:

- from the finite elements (Guyan): the interior DOFs i are eliminated by
  the static response to the external ones e, u_i = Φ_ie u_e with
  Φ_ie = -K_ii⁻¹ K_ie; K_c = K_ee + K_ei Φ_ie (the Schur complement) and
  M_c = Φᵀ M Φ with Φ = [Φ_ie; I] (ssriu2, ssmau2);
- from a measured projection (PROJ_MESU, crmeri / crmema / crmeam): with
  B_s the projection basis at the sensors, B_e at the external DOFs and Y
  the identified modes at the sensors, T = B_e B_s⁺ carries sensor values
  to the interface, V = (T Y)⁺ interface values to the identified modes'
  coordinates, and K_c = Vᵀ diag(ω² m) V, M_c = Vᵀ diag(m) V,
  C_c = Vᵀ diag(a m) V (m the generalized masses, a the AMOR_GENE values,
  used as code_aster uses them). The identified modes at the sensors are
  Y V u_e (DEPL_INTERNE).
"""

from __future__ import annotations

from dataclasses import dataclass

import numpy as np
import scipy.sparse as sp
import scipy.sparse.linalg as spla

from asterlite.fem.constraints import eliminate

#: code_aster's cut of the pseudo-inverses (rslsvd with 100 machine precisions)
PSEUDO_INVERSE_EPS = 100.0 * np.finfo(float).eps


class CondensationError(ValueError):
    """A superelement that cannot be built (singular interior, too few sensors)."""


@dataclass
class GuyanCondensation:
    """Interior static modes and the condensed stiffness of a superelement."""

    interior: np.ndarray  # DOF indices (of the model's numbering) eliminated
    external: np.ndarray  # DOF indices kept, in the superelement's order
    interior_modes: np.ndarray  # Φ_ie, (n_interior, n_external)
    stiffness: np.ndarray  # K_c, (n_external, n_external)

    def condense(self, matrix) -> np.ndarray:
        """Φᵀ A Φ of another matrix of the same DOFs (mass, damping)."""
        a = sp.csr_matrix(matrix)
        i, e, phi = self.interior, self.external, self.interior_modes
        a_ee = a[e][:, e].toarray()
        a_ie = a[i][:, e].toarray()
        a_ei = a[e][:, i].toarray()
        a_ii = a[i][:, i]
        out = a_ee + a_ei @ phi + phi.T @ a_ie + phi.T @ (a_ii @ phi)
        return 0.5 * (out + out.T)

    def interior_values(self, external_values: np.ndarray) -> np.ndarray:
        """u_i = Φ_ie u_e (several columns allowed)."""
        return self.interior_modes @ external_values


def guyan(stiffness, interior: np.ndarray, external: np.ndarray) -> GuyanCondensation:
    """Condense a symmetric stiffness on ``external`` (DOF indices)."""
    k = sp.csr_matrix(stiffness)
    interior = np.asarray(interior, dtype=int)
    external = np.asarray(external, dtype=int)
    k_ee = k[external][:, external].toarray()
    if interior.size == 0:
        return GuyanCondensation(interior, external, np.zeros((0, external.size)), k_ee)
    k_ii = sp.csc_matrix(k[interior][:, interior])
    k_ie = k[interior][:, external].toarray()
    try:
        lu = spla.splu(k_ii)
    except RuntimeError as exc:
        raise CondensationError(
            "the interior stiffness is singular: the superelement's interior is not held "
            "(add external nodes or CHAR_MACR_ELEM conditions)"
        ) from exc
    phi = -lu.solve(k_ie)
    if not np.all(np.isfinite(phi)):
        raise CondensationError("the interior stiffness is singular")
    k_c = k_ee + k[external][:, interior].toarray() @ phi
    return GuyanCondensation(interior, external, phi, 0.5 * (k_c + k_c.T))


def constrained_guyan(stiffness, relations, external: np.ndarray) -> GuyanCondensation:
    """Guyan condensation under homogeneous linear relations B u = 0 (the
    superelement's CHAR_MACR_ELEM: code_aster keeps their multipliers
    inside, its matrices do not depend on the imposed values): u = T q on
    the relations' null space, the condensation done on q, the static shapes
    brought back to every DOF. ``external`` DOFs must stay free of the
    relations (a multiplier outside would leave the superelement)."""
    k = sp.csr_matrix(stiffness)
    n = k.shape[0]
    external = np.asarray(external, dtype=int)
    b_matrix = sp.csr_matrix(relations)
    if b_matrix[:, external].nnz:
        raise CondensationError("a relation of the superelement binds an external DOF")
    elimination = eliminate(b_matrix, np.zeros(b_matrix.shape[0]), n)
    position = np.full(n, -1)
    position[elimination.free] = np.arange(elimination.free.size)
    kept = position[external]
    masters = np.setdiff1d(np.arange(elimination.free.size), kept)
    reduced = guyan(elimination.reduce(k), masters, kept)
    t = sp.csc_matrix(elimination.T)
    shapes = t[:, masters] @ reduced.interior_modes + t[:, kept].toarray()
    interior = np.setdiff1d(np.arange(n), external)
    return GuyanCondensation(interior, external, np.asarray(shapes)[interior], reduced.stiffness)


def condensed_load(
    condensation: GuyanCondensation, stiffness, relations, values, forces
) -> tuple[np.ndarray, np.ndarray]:
    """A load case of a Guyan superelement (CAS_CHARGE): the response u_p to
    the forces f and the relations' imposed values with the external DOFs
    held, and the condensed load f_c = Uᵀ (f - K u_p) on the external DOFs
    (U the static shapes [Φ; I]): the superelement then moves as U u_e + u_p."""
    k = sp.csr_matrix(stiffness)
    n = k.shape[0]
    external = condensation.external
    held = sp.csr_matrix(
        (np.ones(external.size), (np.arange(external.size), external)), shape=(external.size, n)
    )
    b_matrix = sp.vstack([sp.csr_matrix(relations), held]).tocsr()
    rhs = np.concatenate([np.asarray(values, dtype=float), np.zeros(external.size)])
    elimination = eliminate(b_matrix, rhs, n)
    u_p = elimination.particular(rhs)
    forces = np.asarray(forces, dtype=float)
    if elimination.n_free:
        reduced = sp.csc_matrix(elimination.reduce(k))
        try:
            q = spla.splu(reduced).solve(np.asarray(elimination.T.T @ (forces - k @ u_p)))
        except RuntimeError as exc:
            raise CondensationError("the held superelement is singular") from exc
        u_p = u_p + elimination.T @ q
    shapes = np.zeros((n, external.size))
    shapes[condensation.interior] = condensation.interior_modes
    shapes[external, np.arange(external.size)] = 1.0
    return shapes.T @ (forces - k @ u_p), u_p


def pseudo_inverse(matrix: np.ndarray) -> np.ndarray:
    """Moore-Penrose inverse keeping singular values above code_aster's cut."""
    u, s, vt = np.linalg.svd(matrix, full_matrices=False)
    if s.size == 0 or s[0] == 0.0:
        raise CondensationError("a matrix of the measured projection is zero")
    keep = s > PSEUDO_INVERSE_EPS * s[0]
    return (vt[keep].T / s[keep]) @ u[:, keep].T


@dataclass
class MeasuredCondensation:
    """The superelement of a measured projection (PROJ_MESU)."""

    to_modes: np.ndarray  # V, (n_identified, n_external)
    identified_at_sensors: np.ndarray  # Y, (n_sensors, n_identified)
    omega2: np.ndarray
    generalized_mass: np.ndarray
    generalized_damping: np.ndarray | None

    def matrix(self, kind: str) -> np.ndarray:
        """K_c (RIGI), M_c (MASS) or C_c (AMOR)."""
        if kind == "RIGI":
            weights = self.omega2 * self.generalized_mass
        elif kind == "MASS":
            weights = self.generalized_mass
        else:
            if self.generalized_damping is None:
                raise CondensationError("the identified modes have no AMOR_GENE")
            weights = self.generalized_damping * self.generalized_mass
        out = self.to_modes.T @ (weights[:, None] * self.to_modes)
        return 0.5 * (out + out.T)

    def sensor_values(self, external_values: np.ndarray) -> np.ndarray:
        """The identified modes' combination at the sensors, Y V u_e."""
        return self.identified_at_sensors @ (self.to_modes @ external_values)


def measured(
    basis_at_sensors: np.ndarray,
    basis_at_external: np.ndarray,
    identified_at_sensors: np.ndarray,
    omega2: np.ndarray,
    generalized_mass: np.ndarray,
    generalized_damping: np.ndarray | None = None,
) -> MeasuredCondensation:
    """The PROJ_MESU superelement (see the module's docstring)."""
    n_sensors, n_basis = basis_at_sensors.shape
    n_external = basis_at_external.shape[0]
    n_identified = identified_at_sensors.shape[1]
    if n_sensors < n_basis:
        raise CondensationError(
            f"{n_sensors} sensors for {n_basis} basis vectors: the projection basis "
            "cannot be inverted at the sensors"
        )
    if n_external < n_identified:
        raise CondensationError(
            f"{n_external} external DOFs for {n_identified} identified modes: "
            "the interface cannot determine them"
        )
    to_interface = basis_at_external @ pseudo_inverse(basis_at_sensors)
    to_modes = pseudo_inverse(to_interface @ identified_at_sensors)
    return MeasuredCondensation(
        to_modes=to_modes,
        identified_at_sensors=identified_at_sensors,
        omega2=np.asarray(omega2, dtype=float),
        generalized_mass=np.asarray(generalized_mass, dtype=float),
        generalized_damping=(
            None if generalized_damping is None else np.asarray(generalized_damping, dtype=float)
        ),
    )
