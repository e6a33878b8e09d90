"""CALC_MODES numerics: constrained pencil, mode selection, ModeResult assembly."""

from __future__ import annotations

import numpy as np
import scipy.sparse as sp

from asterlite.concepts.assembly import AssembledMatrix
from asterlite.concepts.modes import (
    BucklingModes,
    ComplexModeResult,
    GeneralizedModes,
    ModeResult,
)
from asterlite.fem.constraints import Elimination, eliminate
from asterlite.modal import normalize, quadratic
from asterlite.modal.eigen import (
    EigenError,
    ReducedPencil,
    freq_from_omega2,
    omega2_from_freq,
    sort_modes,
)
from asterlite.modal.modal_parameters import modal_parameters
from asterlite.modal.subspace_start import jacobi_basis_rule


def constrained_pencil(stiffness: AssembledMatrix, mass: AssembledMatrix) -> ReducedPencil:
    """Eliminate the numbering's relations (homogeneous: imposed values do
    not enter an eigenproblem) and reduce K and M."""
    numbering = stiffness.numbering
    b_matrix, _ = numbering.constraint_matrix(rhs_in_time=True, rhs_in_frequency=True)  # b unused
    elimination = eliminate(b_matrix, np.zeros(b_matrix.shape[0]), numbering.n_dofs)
    return ReducedPencil(stiffness.matrix, mass.matrix, elimination)


def select_modes(pencil: ReducedPencil, option: str, freq=(), nmax: int = 10, method=None):
    """(ω², reduced shapes) for a CALC_MODES OPTION, sorted by frequency.
    ``method`` is SOLVEUR_MODAL/METHODE: JACOBI decides the basis inside
    groups of equal eigenvalues as code_aster's subspace iteration does."""
    freq = np.atleast_1d(np.asarray(freq if freq is not None else (), dtype=float))
    if pencil.n == 0:
        raise EigenError("every DOF is constrained: there is no mode")
    if method == "JACOBI":
        pencil.equal_eigenvalue_basis = jacobi_basis_rule(pencil, option, freq)
    if option == "PLUS_PETITE":
        vals, vecs = pencil.smallest(nmax)
    elif option == "PLUS_GRANDE":
        vals, vecs = pencil.largest(nmax)
    elif option == "CENTRE":
        vals, vecs = pencil.nearest(float(omega2_from_freq(freq[0])), nmax)
    elif option == "BANDE":
        if freq.size < 2:
            raise EigenError("BANDE needs two frequencies")
        lo, hi = omega2_from_freq([freq.min(), freq.max()])
        vals, vecs = pencil.band(lo, hi)
    elif option in ("AJUSTE", "SEPARE") and freq.size >= 2:
        # the frequencies bound search intervals: every mode between the extreme ones
        lo, hi = omega2_from_freq([freq.min(), freq.max()])
        vals, vecs = pencil.band(lo, hi)
    elif option in ("PROCHE", "AJUSTE", "SEPARE"):
        # one mode nearest each requested frequency (inverse iteration's result)
        picked_vals, picked_vecs, taken = [], [], []
        for f in freq:
            target = float(omega2_from_freq(f))
            cand_vals, cand_vecs = pencil.nearest(target, min(len(freq) + 1, pencil.n))
            for k in range(len(cand_vals)):
                if not any(np.isclose(cand_vals[k], t, rtol=1e-10, atol=0) for t in taken):
                    picked_vals.append(cand_vals[k])
                    picked_vecs.append(cand_vecs[:, k])
                    taken.append(cand_vals[k])
                    break
        vals = np.array(picked_vals)
        vecs = np.column_stack(picked_vecs) if picked_vecs else np.zeros((pencil.n, 0))
    elif option == "TOUT":
        vals, vecs = pencil.all_modes()
    else:
        raise EigenError(f"unknown OPTION {option}")
    return sort_modes(np.asarray(vals, dtype=float), np.asarray(vecs, dtype=float))


def residuals(pencil: ReducedPencil, omega2, vecs) -> np.ndarray:
    """Relative residual ||K φ - ω² M φ|| / ||K φ|| of each reduced eigenpair."""
    kv = pencil.k @ vecs
    r = kv - (pencil.m @ vecs) * omega2[None, :]
    scale = np.maximum(np.linalg.norm(kv, axis=0), 1e-300)
    return np.linalg.norm(r, axis=0) / scale


def apply_norm(modes: ModeResult, norme: str, stiffness=None, mass=None) -> None:
    """NORM_MODE's NORME choices, in place."""
    if isinstance(modes, ComplexModeResult):
        apply_complex_norm(modes, norme, stiffness=stiffness, mass=mass)
        return
    comps = modes.numbering.dof_components
    if norme == "MASS_GENE":
        m = mass if mass is not None else modes.mass.matrix
        factors = normalize.generalized(modes.shapes, m)
    elif norme == "RIGI_GENE":
        k = stiffness if stiffness is not None else modes.stiffness.matrix
        factors = normalize.generalized(modes.shapes, k)
    elif norme == "EUCL":
        factors = normalize.euclidean(modes.shapes)
    elif norme == "EUCL_TRAN":
        factors = normalize.euclidean(modes.shapes, normalize.component_mask(comps, normalize.TRAN))
    elif norme == "TRAN":
        factors = normalize.largest_component(
            modes.shapes, normalize.component_mask(comps, normalize.TRAN)
        )
    elif norme == "TRAN_ROTA":
        factors = normalize.largest_component(
            modes.shapes, normalize.component_mask(comps, normalize.TRAN_ROTA)
        )
    else:
        raise ValueError(f"unknown norm {norme}")
    modes.rescale(factors, norme)


def build_mode_result(
    stiffness: AssembledMatrix,
    mass: AssembledMatrix,
    omega2: np.ndarray,
    shapes: np.ndarray,
    damping: AssembledMatrix | None = None,
) -> ModeResult:
    """A ModeResult with code_aster's default normalisation (largest component +1)."""
    numbering = stiffness.numbering
    shapes = np.asarray(shapes, dtype=float).reshape(numbering.n_dofs, -1)
    shapes = shapes * normalize.largest_component(shapes)[None, :]
    params = modal_parameters(
        shapes, stiffness.matrix, mass.matrix, numbering.dof_components, omega2
    )
    return ModeResult(
        numbering=numbering,
        shapes=shapes,
        frequencies=freq_from_omega2(omega2),
        generalized_mass=params["MASS_GENE"].copy(),
        generalized_stiffness=params["RIGI_GENE"].copy(),
        mass=mass,
        stiffness=stiffness,
        kind="dynamic",
        parameters=params,
        norm="SANS_CMP: LAGR",
        damping=damping,
    )


def filter_modes(modes: ModeResult, criterion: str, threshold: float) -> np.ndarray:
    """Indices of modes passing FILTRE_MODE's CRIT_EXTR (MASS_EFFE_UN / MASS_GENE)."""
    if criterion == "MASS_EFFE_UN":
        fractions = np.vstack(
            [
                np.asarray(modes.parameters.get(f"MASS_EFFE_UN_{c}", np.zeros(modes.n_modes)))
                for c in ("DX", "DY", "DZ")
            ]
        )
        return np.flatnonzero(np.max(np.abs(fractions), axis=0) > threshold)
    if criterion == "MASS_GENE":
        mass = np.asarray(modes.generalized_mass)
        return np.flatnonzero(mass > threshold)
    raise ValueError(f"unknown CRIT_EXTR {criterion}")


def build_buckling_result(a: AssembledMatrix, b: AssembledMatrix, loads, shapes) -> BucklingModes:
    """Critical-load modes: largest component +1, CHAR_CRIT per mode."""
    numbering = a.numbering
    shapes = np.asarray(shapes, dtype=float).reshape(numbering.n_dofs, -1)
    shapes = shapes * normalize.largest_component(shapes)[None, :]
    n = shapes.shape[1]
    gb = np.einsum("ij,ij->j", shapes, b.matrix @ shapes)
    ga = np.einsum("ij,ij->j", shapes, a.matrix @ shapes)
    params = {
        "NUME_MODE": np.arange(1, n + 1),
        "CHAR_CRIT": np.asarray(loads, dtype=float),
        "FREQ": np.zeros(n),
        "MASS_GENE": gb,
        "RIGI_GENE": ga,
    }
    return BucklingModes(
        numbering=numbering,
        shapes=shapes,
        frequencies=np.zeros(n),
        generalized_mass=gb.copy(),
        generalized_stiffness=ga.copy(),
        mass=b,
        stiffness=a,
        kind="buckling",
        parameters=params,
        norm="SANS_CMP: LAGR",
    )


def generalized_modes(k_gene, m_gene, option: str, freq=(), nmax: int = 10, method=None):
    """(ω², vectors) of a projected pencil (dense, unconstrained)."""

    n = k_gene.shape[0]
    identity = Elimination(
        sp.identity(n, format="csr"), np.zeros(n), np.arange(n), np.array([], dtype=int)
    )
    pencil = ReducedPencil(
        np.asarray(k_gene, dtype=float), np.asarray(m_gene, dtype=float), identity
    )
    return select_modes(pencil, option, freq, nmax, method)


def build_generalized_result(stiffness, mass, omega2, vecs) -> GeneralizedModes:
    """A mode_gene: largest generalized component +1, per-mode MASS_GENE/RIGI_GENE."""
    vecs = np.asarray(vecs, dtype=float)
    vecs = vecs * normalize.largest_component(vecs)[None, :]
    gm = np.einsum("ij,ij->j", vecs, np.asarray(mass.matrix) @ vecs)
    gk = np.einsum("ij,ij->j", vecs, np.asarray(stiffness.matrix) @ vecs)
    n = vecs.shape[1]
    return GeneralizedModes(
        numbering=stiffness.numbering,
        vectors=vecs,
        frequencies=freq_from_omega2(omega2),
        generalized_mass=gm,
        generalized_stiffness=gk,
        parameters={
            "NUME_MODE": np.arange(1, n + 1),
            "FREQ": freq_from_omega2(omega2),
            "OMEGA2": np.asarray(omega2, dtype=float),
            "MASS_GENE": gm,
            "RIGI_GENE": gk,
        },
    )


def apply_complex_norm(modes: ComplexModeResult, norme: str, stiffness=None, mass=None) -> None:
    """NORM_MODE on complex modes (norms of :mod:`asterlite.modal.quadratic`)."""
    comps = modes.numbering.dof_components
    lam = np.asarray(modes.eigenvalues)
    damping = modes.damping.matrix if modes.damping is not None else None
    if norme == "MASS_GENE":
        m = mass if mass is not None else modes.mass.matrix
        factors = quadratic.mass_gene(modes.shapes, lam, m, damping)
    elif norme == "RIGI_GENE":
        k = stiffness if stiffness is not None else modes.stiffness.matrix
        m = mass if mass is not None else modes.mass.matrix
        factors = quadratic.rigi_gene(modes.shapes, lam, k, m)
    elif norme == "EUCL":
        factors = quadratic.hermitian(modes.shapes)
    elif norme == "EUCL_TRAN":
        mask = normalize.component_mask(comps, normalize.TRAN)
        factors = quadratic.hermitian(modes.shapes, mask)
    elif norme in ("TRAN", "TRAN_ROTA"):
        selected = normalize.TRAN if norme == "TRAN" else normalize.TRAN_ROTA
        mask = normalize.component_mask(comps, selected)
        factors = quadratic.largest_modulus(modes.shapes, mask)
    else:
        raise ValueError(f"unknown norm {norme}")
    modes.rescale(factors, norme)


def complex_pencil(stiffness, mass, damping=None) -> quadratic.QuadraticPencil:
    """The quadratic problem reduced on the numbering's relations."""
    numbering = stiffness.numbering
    b_matrix, _ = numbering.constraint_matrix(rhs_in_time=True, rhs_in_frequency=True)  # b unused
    elimination = eliminate(b_matrix, np.zeros(b_matrix.shape[0]), numbering.n_dofs)
    c = damping.matrix if damping is not None else None
    return quadratic.QuadraticPencil(stiffness.matrix, c, mass.matrix, elimination)


def _stiffness_only(stiffness, damping) -> bool:
    """A complex stiffness without damping matrix: code_aster's generalized
    (not quadratic) problem, whose FREQ is |λ|/2π."""
    return damping is None and np.issubdtype(stiffness.matrix.dtype, np.complexfloating)


def build_complex_mode_result(stiffness, mass, damping, eigenvalues, shapes) -> ComplexModeResult:
    """A mode_meca_c: largest component 1 + 0i, code_aster's per-mode parameters."""
    numbering = stiffness.numbering
    shapes = np.asarray(shapes, dtype=complex).reshape(numbering.n_dofs, -1)
    shapes = shapes * quadratic.largest_modulus(shapes)[None, :]
    lam = np.asarray(eigenvalues, dtype=complex)
    c = damping.matrix if damping is not None else None
    params = {"NUME_MODE": np.arange(1, lam.size + 1)}
    params.update(quadratic.modal_quantities(lam, _stiffness_only(stiffness, damping)))
    params.update(quadratic.generalized_parameters(shapes, stiffness.matrix, c, mass.matrix))
    return ComplexModeResult(
        numbering=numbering,
        shapes=shapes,
        frequencies=params["FREQ"].copy(),
        generalized_mass=params["MASS_GENE"].copy(),
        generalized_stiffness=params["RIGI_GENE"].copy(),
        mass=mass,
        stiffness=stiffness,
        kind="dynamic",
        parameters=params,
        norm="SANS_CMP: LAGR",
        damping=damping,
        eigenvalues=lam,
    )


def complex_generalized_modes(k_gene, m_gene, c_gene, option: str, freq=(), nmax=10, amor=0.0):
    """(λ, vectors, residuals) of a projected quadratic problem (dense, unconstrained)."""

    n = np.asarray(k_gene).shape[0]
    identity = Elimination(
        sp.identity(n, format="csr"), np.zeros(n), np.arange(n), np.array([], dtype=int)
    )
    pencil = quadratic.QuadraticPencil(
        np.asarray(k_gene),
        None if c_gene is None else np.asarray(c_gene),
        np.asarray(m_gene),
        identity,
    )
    lam, vecs = quadratic.select(pencil, option, freq, nmax, amor)
    return lam, vecs, pencil.residuals(lam, vecs)


def build_complex_generalized_result(stiffness, mass, damping, lam, vecs) -> GeneralizedModes:
    """A mode_gene of complex modes: largest component 1 + 0i, FREQ = Im(λ)/2π,
    AMOR_REDUIT and the generalized parameters as for a mode_meca_c."""
    vecs = np.asarray(vecs, dtype=complex)
    vecs = vecs * quadratic.largest_modulus(vecs)[None, :]
    c = None if damping is None else np.asarray(damping.matrix)
    params = {"NUME_MODE": np.arange(1, vecs.shape[1] + 1)}
    params.update(quadratic.modal_quantities(lam, _stiffness_only(stiffness, damping)))
    params.update(
        quadratic.generalized_parameters(
            vecs, np.asarray(stiffness.matrix), c, np.asarray(mass.matrix)
        )
    )
    params["EIGENVALUE"] = np.asarray(lam, dtype=complex)
    return GeneralizedModes(
        numbering=stiffness.numbering,
        vectors=vecs,
        frequencies=params["FREQ"].copy(),
        generalized_mass=params["MASS_GENE"].copy(),
        generalized_stiffness=params["RIGI_GENE"].copy(),
        parameters=params,
    )
