"""Nodal forces of a physical result (CALC_CHAMP FORCE: FORC_NODA, REAC_NODA).

code_aster (ccfnrn) computes, at each order of a ``dyna_trans`` (at each
frequency of a ``dyna_harmo``, on complex values):

- FORC_NODA, the element internal forces assembled on the result's DOFs;
  for linear elastic elements they are K_e u summed over the elements, K
  being the RIGI_MECA matrices of the model (not the deck's MATR_RIGI);
- REAC_NODA = FORC_NODA - F(t) + M a, F the nodal terms of the loads (the
  CALC_CHAMP EXCIT loads, else the result's own list: the DYNA_VIBRA EXCIT
  occurrences that give a CHARGE, each times its FONC_MULT; for a dyna_harmo
  the EXCIT of CALC_CHAMP, each times its c(f)), M the result's
  mass matrix and a its ACCE field. code_aster leaves the damping forces C v
  out (its warning CALCCHAMP_4), and so does this module.
"""

from __future__ import annotations

import numpy as np

from asterlite.fem.assemble import assemble_blocks, assemble_terms
from asterlite.fem.loads import load_terms
from asterlite.fem.options import option_blocks

FORCE_OPTIONS = ("FORC_NODA", "REAC_NODA")


class NodalForceError(ValueError):
    """A nodal force that cannot be computed from what the result holds."""


def internal_forces(
    model, characteristics, materials, numbering, displacements, cells=None
) -> np.ndarray:
    """(n_orders, n_dofs) K u, K the model's element stiffness assembled on
    ``numbering`` (linear elastic elements: their internal forces); with
    ``cells``, of those cells only (CALC_CHAMP GROUP_MA)."""
    blocks = option_blocks(model, characteristics, "RIGI_MECA", materials=materials, cells=cells)
    stiffness = assemble_blocks(blocks, numbering)
    return np.asarray(stiffness @ np.asarray(displacements).T).T


def load_forces(loads, characteristics, materials, numbering, times) -> np.ndarray:
    """(n_orders, n_dofs) Σ f_k(t) F_k of (load, FONC_MULT or coefficient)
    pairs at the result's instants; Dirichlet conditions give no term on the
    physical DOFs (their dual terms live on code_aster's Lagrange DOFs)."""
    total = np.zeros((len(times), numbering.n_dofs))
    for load, mult in loads:
        vector = assemble_terms(load_terms(load, characteristics, materials), numbering)
        if not np.any(vector):
            continue
        if callable(mult):
            coefficients = np.array([float(mult(float(t))) for t in times])
        else:
            coefficients = np.full(len(times), float(mult))
        total += np.outer(coefficients, vector)
    return total


def nodal_forces(result, option, model, characteristics, materials, load_values, log, cells=None):
    """FORC_NODA or REAC_NODA (n_orders, n_dofs) of a dyna_trans or a
    dyna_harmo ``result`` (see the module docstring); ``load_values`` the
    (n_orders, n_dofs) load terms F, None for none. A dyna_harmo's fields are
    complex, its element stiffness real (as code_aster's vefnme_cplx).
    ``cells`` restricts FORC_NODA to those cells' elements."""
    numbering = result.numbering
    depl = np.asarray(result.fields["DEPL"])
    displacements = depl if np.iscomplexobj(depl) else depl.astype(float)
    values = internal_forces(model, characteristics, materials, numbering, displacements, cells)
    if option == "FORC_NODA":
        return values
    if load_values is not None:
        values = values - load_values
    acce = result.fields.get("ACCE")
    if acce is None:
        log(f"warning: REAC_NODA of a {result.aster_type} without ACCE: no inertia forces M a")
        return values
    if result.mass_matrix is None:
        raise NodalForceError(
            f"REAC_NODA of a {result.aster_type} needs the mass matrix the result was "
            "computed with (M a), and this result does not know it"
        )
    mass = result.mass_matrix.matrix
    if mass.shape[0] != numbering.n_dofs:
        raise NodalForceError("the result's mass matrix is not on the result's numbering")
    values = values + np.asarray(mass @ np.asarray(acce).T).T
    log(
        f"warning: the damping forces C v are left out of REAC_NODA on a {result.aster_type}, "
        "as code_aster does (CALCCHAMP_4)"
    )
    return values
