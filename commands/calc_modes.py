"""CALC_MODES: real eigenmodes of (K, M) under the numbering's kinematic relations."""

from __future__ import annotations

import numpy as np

from asterlite.concepts.assembly import AssembledMatrix, ComplexAssembledMatrix
from asterlite.concepts.modes import GeneralizedMatrix
from asterlite.extras import install_hint
from asterlite.fem import sparse_direct
from asterlite.fem.constraints import ConstraintError
from asterlite.fem.selection import as_tuple
from asterlite.modal.buckling import critical_loads, select_critical
from asterlite.modal.calc import (
    apply_norm,
    build_buckling_result,
    build_complex_generalized_result,
    build_complex_mode_result,
    build_generalized_result,
    build_mode_result,
    complex_generalized_modes,
    complex_pencil,
    constrained_pencil,
    filter_modes,
    generalized_modes,
    is_symmetric,
    residuals,
    select_modes,
)
from asterlite.modal.eigen import EigenError
from asterlite.modal.quadratic import QuadraticError
from asterlite.modal.quadratic import select as select_complex

_DEFAULT_NMAX = {"PLUS_PETITE": 10, "CENTRE": 10, "PLUS_GRANDE": 1, "TOUT": 10}


def run(ctx, kw):
    if kw.get("TYPE_RESU", "DYNAMIQUE") != "DYNAMIQUE":
        return _critical(ctx, kw)
    stiffness, mass = kw["MATR_RIGI"], kw["MATR_MASS"]
    if isinstance(stiffness, GeneralizedMatrix) and isinstance(mass, GeneralizedMatrix):
        return _generalized(ctx, kw, stiffness, mass)
    if not isinstance(stiffness, AssembledMatrix) or not isinstance(mass, AssembledMatrix):
        ctx.unsupported("CALC_MODES on these matrix types", "MATR_RIGI", kw)
    if mass.numbering is not stiffness.numbering:
        ctx.error("MATR_RIGI and MATR_MASS use different numberings", "MATR_MASS", kw)
    if kw.get("MATR_AMOR") is not None or isinstance(stiffness, ComplexAssembledMatrix):
        return _complex(ctx, kw, stiffness, mass, kw.get("MATR_AMOR"))
    if not (is_symmetric(stiffness.matrix) and is_symmetric(mass.matrix)):
        # complex eigenvalues (gyroscopic terms in K or M...): code_aster's
        # non-symmetric solvers give FREQ and AMOR_REDUIT from them
        return _complex(ctx, kw, stiffness, mass, None)
    option = kw.get("OPTION", "PLUS_PETITE")
    calc_freq = (kw.factor("CALC_FREQ") or [{}])[0]
    freq = as_tuple(calc_freq.get("FREQ"))
    nmax = calc_freq.get("NMAX_FREQ")
    if not nmax:
        nmax = _DEFAULT_NMAX.get(option, 10)
    if option == "TOUT":
        nmax = None
    if option in ("CENTRE", "BANDE", "PROCHE", "AJUSTE", "SEPARE") and not freq:
        ctx.error(f"OPTION={option!r} needs CALC_FREQ/FREQ", "CALC_FREQ", kw)
    counted = None
    if option == "BANDE" and calc_freq.get("TABLE_FREQ") is not None:
        freq, counted = band_from_table(ctx, calc_freq, freq)
    try:
        pencil = constrained_pencil(stiffness, mass)
        omega2, vecs = select_modes(pencil, option, freq, nmax or 10, _method(kw))
    except (EigenError, ConstraintError) as exc:
        ctx.error(str(exc), "OPTION", kw)
    how = pencil.last_solve
    if how and "summary" in how:  # a solver that describes itself (the MPI one)
        ctx.log(f"{pencil.n} unknowns: {how['summary']}")
    elif how:
        detail = f"{how['solves']} solves, basis of {how['dimension']}, " if "solves" in how else ""
        ctx.log(
            f"{pencil.n} unknowns: {how['method']} on a {how['backend'].upper()} "
            f"factorisation of K - σM ({detail}factorisation {how['factor_seconds']:.1f} s, "
            f"iterations {how['iteration_seconds']:.1f} s)"
        )
        if how["backend"] == "cholmod":
            ctx.log(f"{install_hint('large')} (MUMPS) factorises large models several times faster")
    elif pencil.n >= sparse_direct.LARGE_LIMIT and not sparse_direct.mumps_available():
        ctx.log(
            f"{pencil.n} unknowns solved with SuperLU and ARPACK: "
            f"{install_hint('large')} (MUMPS) is faster and leaner on large models"
        )
    if counted is not None and omega2.size != counted:
        ctx.error(
            f"{omega2.size} modes in the band, TABLE_FREQ counts {counted}", "TABLE_FREQ", calc_freq
        )
    if option == "BANDE" and calc_freq.get("NMAX_FREQ"):
        omega2, vecs = omega2[: calc_freq["NMAX_FREQ"]], vecs[:, : calc_freq["NMAX_FREQ"]]
    check_found(ctx, kw, omega2.size)
    res = residuals(pencil, omega2, vecs)
    modes = build_mode_result(stiffness, mass, omega2, pencil.expand(vecs))
    numbers = _mode_numbers(pencil, option, freq, omega2)
    if numbers is not None:
        modes.parameters["NUME_MODE"] = numbers
        ctx.log(f"NUME_MODE from the Sturm count: the first mode found is mode {numbers[0]}")
    modes.parameters["ERREUR"] = res
    _check_residuals(ctx, kw, modes.frequencies, res)
    norm = kw.factor("NORM_MODE")
    if norm:
        apply_norm(modes, norm[0].get("NORME", "TRAN_ROTA"))
    filtre = kw.factor("FILTRE_MODE")
    if filtre:
        keep = filter_modes(
            modes, filtre[0].get("CRIT_EXTR", "MASS_EFFE_UN"), float(filtre[0].get("SEUIL", 1e-3))
        )
        modes = modes.select(keep)
        modes.parameters["NUME_MODE"] = np.arange(1, modes.n_modes + 1)
    for k, (number, f) in enumerate(zip(modes.mode_numbers, modes.frequencies, strict=True)):
        ctx.log(f"mode {number:4d}  {f:14.6e} Hz  gen. mass {modes.generalized_mass[k]:12.5e}")
    return modes


def band_from_table(ctx, calc_freq, freq):
    """OPTION='BANDE' with TABLE_FREQ, an INFO_MODE table (vptabl): its rows
    within FREQ must tile it; the band becomes their effective bounds
    (BORNE_MIN_EFFECT of the first, BORNE_MAX_EFFECT of the last) and the
    number of modes the sum of their NB_MODE. Returns (band, count)."""
    table = calc_freq["TABLE_FREQ"]
    needed = {"FREQ_MIN": "R", "FREQ_MAX": "R", "NB_MODE": "I"}
    needed |= {"BORNE_MIN_EFFECT": "R", "BORNE_MAX_EFFECT": "R"}
    if any(table.types.get(name) != code for name, code in needed.items()):
        ctx.error("TABLE_FREQ is not an INFO_MODE table", "TABLE_FREQ", calc_freq)
    low, high = float(min(freq)), float(max(freq))
    eps = 100.0 * np.finfo(float).eps
    tolerance = float(calc_freq.get("PREC_SHIFT", 5e-2) or 5e-2)
    rows = [
        r
        for r in table.rows
        if r["FREQ_MIN"] >= low - eps - tolerance * abs(low)
        and r["FREQ_MAX"] <= high + eps + tolerance * abs(high)
    ]
    if not rows:
        ctx.error(f"TABLE_FREQ has no band within [{low:g}, {high:g}]", "TABLE_FREQ", calc_freq)

    def close(a, b):
        return abs(a - b) / (abs(b) if abs(b) > eps else 1.0) <= tolerance

    pairs = list(zip(rows[:-1], rows[1:], strict=True))
    joined = all(close(a["FREQ_MAX"], b["FREQ_MIN"]) for a, b in pairs)
    joined &= all(close(a["BORNE_MAX_EFFECT"], b["BORNE_MIN_EFFECT"]) for a, b in pairs)
    if not (close(rows[0]["FREQ_MIN"], low) and close(rows[-1]["FREQ_MAX"], high) and joined):
        ctx.error(
            f"the bands of TABLE_FREQ do not tile [{low:g}, {high:g}]", "TABLE_FREQ", calc_freq
        )
    band = (float(rows[0]["BORNE_MIN_EFFECT"]), float(rows[-1]["BORNE_MAX_EFFECT"]))
    if abs(band[0] - low) + abs(band[1] - high) > eps:
        ctx.log(f"alarm: TABLE_FREQ's effective bounds [{band[0]:g}, {band[1]:g}] Hz are used")
    return band, int(sum(int(r["NB_MODE"]) for r in rows))


def _mode_numbers(pencil, option: str, freq, omega2) -> np.ndarray | None:
    """NUME_MODE as code_aster gives it, a mode's rank in the whole spectrum
    (the Sturm count of its shift plus its place from the shift): a band
    above rigid-body or lower modes starts past 1. None where that is 1, 2...
    (the selections from the lowest mode) or the count cannot be read.

    The count is taken just below the highest mode found, where the shifted
    matrix is regular, not at the band's lower bound: a band from 0 Hz of a
    free structure puts that bound among its rigid-body modes, whose computed
    ω² (±1e-8) fall either side of 0 as round-off has it."""
    if option in ("PLUS_PETITE", "TOUT", "PLUS_GRANDE") or not omega2.size:
        return None
    contiguous = option in ("BANDE", "CENTRE") or (
        option in ("AJUSTE", "SEPARE") and len(freq) >= 2
    )
    if not contiguous:  # PROCHE's modes need not follow one another: each its own count
        counts = [pencil.count_below(_just_below(w)) for w in omega2]
        if any(c is None for c in counts) or not any(counts):
            return None
        return np.asarray(counts) + 1
    top = float(omega2.max())
    if top <= 0.0:
        return None
    count = pencil.count_below(_just_below(top))
    if count is None:
        return None
    # the first mode of the top's cluster of equal eigenvalues has rank count + 1
    anchor = int(np.flatnonzero(omega2 >= _just_below(top))[0])
    numbers = count + 1 + np.arange(omega2.size) - anchor
    return None if numbers[0] < 1 or numbers[0] == 1 else numbers


def _just_below(omega2: float) -> float:
    """A shift below ω² and its equal eigenvalues, above any distinct one."""
    return omega2 - 1e-6 * max(abs(omega2), 1e-300)


def _method(kw) -> str | None:
    """SOLVEUR_MODAL/METHODE of a simultaneous-iteration OPTION (None for
    inverse iterations): only JACOBI changes the result, through the basis of
    multiple eigenvalues (asterlite.modal.subspace_start)."""
    solver = kw.factor("SOLVEUR_MODAL")
    return solver[0].get("METHODE") if solver else None


def _method_keeping_basis(ctx, kw, problem: str) -> str | None:
    """SOLVEUR_MODAL/METHODE where asterlite's solver keeps its own basis of
    multiple eigenvalues: TRI_DIAG, SORENSEN and QZ only change how code_aster
    reaches the same eigenpairs; JACOBI's basis is built for real modes only."""
    method = _method(kw)
    if method == "JACOBI":
        ctx.unsupported(
            f"METHODE='JACOBI' for {problem} (code_aster's basis of multiple "
            "eigenvalues is reproduced for real modes only)",
            "SOLVEUR_MODAL",
            kw,
        )
    return method


def check_found(ctx, kw, count: int, what="eigenmode", keyword="CALC_FREQ") -> None:
    """An empty selection stops the run (STOP_BANDE_VIDE='OUI', the default);
    with 'NON' code_aster makes an empty result, which asterlite does not."""
    stop = kw.get("STOP_BANDE_VIDE", "OUI") == "OUI"
    if count:
        return
    if stop:  # code_aster's MODAL_1, a SolverError
        ctx.error(f"no {what} found for this selection", keyword, kw, "SolverError")
    ctx.unsupported("an empty selection with STOP_BANDE_VIDE='NON'", "STOP_BANDE_VIDE", kw)


def _critical(ctx, kw):
    """TYPE_RESU MODE_FLAMB ((K + λ K_geo) φ = 0) and GENERAL ((A + λ B) φ = 0)."""
    if kw["TYPE_RESU"] == "MODE_FLAMB":
        a, b = kw["MATR_RIGI"], kw["MATR_RIGI_GEOM"]
        b_keyword = "MATR_RIGI_GEOM"
    else:
        a, b = kw["MATR_A"], kw["MATR_B"]
        b_keyword = "MATR_B"
    if not isinstance(a, AssembledMatrix) or not isinstance(b, AssembledMatrix):
        ctx.unsupported("critical loads of generalized matrices", b_keyword, kw)
    if a.numbering.dofs != b.numbering.dofs:
        ctx.error("the two matrices use different numberings", b_keyword, kw)
    _method_keeping_basis(ctx, kw, f"TYPE_RESU={kw['TYPE_RESU']!r}")
    option = kw.get("OPTION", "PLUS_PETITE")
    crit = (kw.factor("CALC_CHAR_CRIT") or [{}])[0]
    window = as_tuple(crit.get("CHAR_CRIT"))
    nmax = int(crit.get("NMAX_CHAR_CRIT") or 10)
    try:
        pencil = constrained_pencil(a, b)
        loads, vecs = critical_loads(pencil.k, pencil.m)
        loads, vecs = select_critical(loads, vecs, option, window, nmax)
    except (EigenError, ConstraintError) as exc:
        ctx.error(str(exc), "OPTION", kw)
    check_found(ctx, kw, loads.size, "critical load", "CALC_CHAR_CRIT")
    modes = build_buckling_result(a, b, loads, pencil.expand(vecs))
    norm = kw.factor("NORM_MODE")
    if norm:
        apply_norm(modes, norm[0].get("NORME", "TRAN_ROTA"), stiffness=a.matrix, mass=b.matrix)
    for k, value in enumerate(loads, start=1):
        ctx.log(f"mode {k:4d}  CHAR_CRIT {value:14.6e}")
    return modes


def _generalized(ctx, kw, stiffness, mass):
    """Modes of projected matrices (a mode_gene): a dense pencil, no relations."""
    if stiffness.matrix.shape != mass.matrix.shape:
        ctx.error("MATR_RIGI and MATR_MASS differ in size", "MATR_MASS", kw)
    if kw.get("MATR_AMOR") is not None or np.iscomplexobj(stiffness.matrix):
        return _generalized_complex(ctx, kw, stiffness, mass, kw.get("MATR_AMOR"))
    option = kw.get("OPTION", "PLUS_PETITE")
    calc_freq = (kw.factor("CALC_FREQ") or [{}])[0]
    freq = as_tuple(calc_freq.get("FREQ"))
    nmax = calc_freq.get("NMAX_FREQ") or _DEFAULT_NMAX.get(option, 10)
    constraints = getattr(stiffness.numbering, "constraints", None)
    try:
        if constraints is not None:  # a substructured model: its interface relations
            from asterlite.substructure.coupling import coupled_modes

            _method_keeping_basis(ctx, kw, "a substructured model")

            omega2, vecs = coupled_modes(
                stiffness.matrix, mass.matrix, constraints, option, freq, nmax
            )
        else:
            omega2, vecs = generalized_modes(
                stiffness.matrix, mass.matrix, option, freq, nmax, _method(kw)
            )
    except EigenError as exc:
        ctx.error(str(exc), "OPTION", kw)
    check_found(ctx, kw, omega2.size)
    modes = build_generalized_result(stiffness, mass, omega2, vecs)
    if constraints is None:  # a coupled model's modes satisfy its interface relations too
        _check_generalized_residuals(ctx, kw, stiffness, mass, modes)
    for k, (number, f) in enumerate(zip(modes.mode_numbers, modes.frequencies, strict=True)):
        ctx.log(f"mode {number:4d}  {f:14.6e} Hz  gen. mass {modes.generalized_mass[k]:12.5e}")
    return modes


def _check_residuals(ctx, kw, frequencies, res) -> None:
    """VERI_MODE: stop (STOP_ERREUR='OUI') when a mode's relative residual
    ``res`` exceeds SEUIL; rigid-body modes (below CALC_FREQ's SEUIL_FREQ)
    have K φ ≈ 0, so their relative residual means nothing."""
    calc_freq = (kw.factor("CALC_FREQ") or [{}])[0]
    veri = (kw.factor("VERI_MODE") or [{}])[0]
    tolerance = float(veri.get("SEUIL", 1e-6) or 1e-6)
    elastic = np.abs(frequencies) >= float(calc_freq.get("SEUIL_FREQ", 1e-2) or 1e-2)
    checked = np.where(elastic, res, 0.0)
    if veri.get("STOP_ERREUR", "OUI") == "OUI" and np.any(checked > max(tolerance, 1e-6)):
        worst = int(np.argmax(checked))
        ctx.error(
            f"mode {worst + 1} ({frequencies[worst]:.6g} Hz) has a residual "
            f"{res[worst]:.3g} above {tolerance:g}",
            "VERI_MODE",
            kw,
            "SolverError",  # code_aster's ALGELINE2_74
        )


def _check_generalized_residuals(ctx, kw, stiffness, mass, modes) -> None:
    """VERI_MODE on generalized modes, as on physical ones: the relative
    residual |K v - ω² M v| / |K v| of each mode above SEUIL_FREQ (a
    rigid-body mode's relative residual means nothing) against SEUIL."""
    k, m = np.asarray(stiffness.matrix), np.asarray(mass.matrix)
    vectors = np.asarray(modes.vectors)
    omega2 = (2.0 * np.pi * np.asarray(modes.frequencies)) ** 2
    k_v = k @ vectors
    residual = np.linalg.norm(k_v - (m @ vectors) * omega2, axis=0)
    scale = np.linalg.norm(k_v, axis=0)
    res = np.where(scale > 0.0, residual / np.where(scale > 0.0, scale, 1.0), residual)
    modes.parameters["ERREUR"] = res
    _check_residuals(ctx, kw, modes.frequencies, res)


def _complex(ctx, kw, stiffness, mass, damping):
    """Damped modes (λ² M + λ C + K) φ = 0: a mode_meca_c."""
    if damping is not None:
        if not isinstance(damping, AssembledMatrix):
            ctx.unsupported("MATR_AMOR of this type with physical matrices", "MATR_AMOR", kw)
        if damping.numbering is not stiffness.numbering:
            ctx.error("MATR_AMOR and MATR_RIGI use different numberings", "MATR_AMOR", kw)
    _method_keeping_basis(ctx, kw, "damped modes")
    option = kw.get("OPTION", "PLUS_PETITE")
    calc_freq = (kw.factor("CALC_FREQ") or [{}])[0]
    freq = as_tuple(calc_freq.get("FREQ"))
    amor = calc_freq.get("AMOR_REDUIT")
    amor = as_tuple(amor) if amor is not None else (0.0,)
    nmax = calc_freq.get("NMAX_FREQ") or _DEFAULT_NMAX.get(option, 10)
    if option in ("CENTRE", "BANDE", "PROCHE", "AJUSTE", "SEPARE") and not freq:
        ctx.error(f"OPTION={option!r} needs CALC_FREQ/FREQ", "CALC_FREQ", kw)
    try:
        pencil = complex_pencil(stiffness, mass, damping)
        lam, vecs = select_complex(
            pencil, option, freq, int(nmax), amor if len(amor) > 1 else amor[0]
        )
    except (QuadraticError, ConstraintError) as exc:
        ctx.error(str(exc), "OPTION", kw)
    if option == "BANDE" and calc_freq.get("NMAX_FREQ"):
        lam, vecs = lam[: calc_freq["NMAX_FREQ"]], vecs[:, : calc_freq["NMAX_FREQ"]]
    check_found(ctx, kw, lam.size)
    res = pencil.residuals(lam, vecs)
    modes = build_complex_mode_result(stiffness, mass, damping, lam, pencil.expand(vecs))
    modes.parameters["ERREUR"] = res
    _check_residuals(ctx, kw, modes.frequencies, res)
    norm = kw.factor("NORM_MODE")
    if norm:
        apply_norm(modes, norm[0].get("NORME", "TRAN_ROTA"))
    ratios = modes.parameters["AMOR_REDUIT"]
    for k, (f, a) in enumerate(zip(modes.frequencies, ratios, strict=True), start=1):
        ctx.log(f"mode {k:4d}  {f:14.6e} Hz  reduced damping {a:12.5e}")
    return modes


def _generalized_complex(ctx, kw, stiffness, mass, damping):
    """Modes of projected matrices with damping or a complex (hysteretic)
    stiffness: a mode_gene with complex vectors."""
    if damping is not None and not isinstance(damping, GeneralizedMatrix):
        ctx.error("MATR_AMOR must be generalized like MATR_RIGI", "MATR_AMOR", kw)
    if damping is not None and damping.matrix.shape != stiffness.matrix.shape:
        ctx.error("MATR_AMOR and MATR_RIGI differ in size", "MATR_AMOR", kw)
    option = kw.get("OPTION", "PLUS_PETITE")
    calc_freq = (kw.factor("CALC_FREQ") or [{}])[0]
    freq = as_tuple(calc_freq.get("FREQ"))
    _method_keeping_basis(ctx, kw, "damped modes")
    amor = as_tuple(calc_freq.get("AMOR_REDUIT")) or (0.0,)
    nmax = calc_freq.get("NMAX_FREQ") or _DEFAULT_NMAX.get(option, 10)
    if option in ("CENTRE", "BANDE", "PROCHE", "AJUSTE", "SEPARE") and not freq:
        ctx.error(f"OPTION={option!r} needs CALC_FREQ/FREQ", "CALC_FREQ", kw)
    try:
        lam, vecs, _res = complex_generalized_modes(
            stiffness.matrix,
            mass.matrix,
            None if damping is None else damping.matrix,
            option,
            freq,
            int(nmax),
            amor if len(amor) > 1 else amor[0],
        )
    except QuadraticError as exc:
        ctx.error(str(exc), "OPTION", kw)
    check_found(ctx, kw, lam.size)
    modes = build_complex_generalized_result(stiffness, mass, damping, lam, vecs)
    ratios = modes.parameters["AMOR_REDUIT"]
    for k, (f, a) in enumerate(zip(modes.frequencies, ratios, strict=True), start=1):
        ctx.log(f"mode {k:4d}  {f:14.6e} Hz  reduced damping {a:12.5e}")
    return modes
