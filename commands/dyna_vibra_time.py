"""DYNA_VIBRA's time axis on a modal basis: the initial state (ETAT_INIT),
the span and step (INCREMENT) with code_aster's VERI_PAS check, the
archived instants (ARCHIVAGE)."""

from __future__ import annotations

import math

import numpy as np
from asterlite.commands.dyna_vibra_keywords import list_values
from asterlite.commands.dyna_vibra_shocks import DAMPING_KEYWORDS, STIFFNESS_KEYWORDS

from asterlite.dynamics.scheme_adapt_ordre2_v11 import default_step_max
from asterlite.dynamics.schemes import SCHEMES
from asterlite.dynamics.step_limits import (
    damped_step_limit,
    shock_damping_limit,
    stability_limit,
    suggested_step,
)
from asterlite.errors import NumericalError


def initial_state(ctx, kw, n_modes):
    """(q0, v0, t0 or None) from ETAT_INIT (vectors or a previous tran_gene)."""
    q0, v0 = np.zeros(n_modes), np.zeros(n_modes)
    occs = kw.factor("ETAT_INIT")
    if not occs:
        return q0, v0, None
    occ = occs[0]
    previous = occ.get("RESULTAT")
    if previous is not None:
        k = archived_index(ctx, occ, previous)
        return previous.depl[k].copy(), previous.vite[k].copy(), float(previous.times[k])
    if occ.get("DEPL") is not None:
        q0 = np.asarray(occ["DEPL"].values, dtype=float)[:n_modes].copy()
    if occ.get("VITE") is not None:
        v0 = np.asarray(occ["VITE"].values, dtype=float)[:n_modes].copy()
    return q0, v0, None


def restart_acceleration(kw, t_state):
    """The archived acceleration at the ETAT_INIT instant of a RESULTAT, or None."""
    occs = kw.factor("ETAT_INIT")
    previous = occs[0].get("RESULTAT") if occs else None
    if previous is None or t_state is None:
        return None
    k = int(np.argmin(np.abs(previous.times - t_state)))
    return np.array(previous.acce[k], dtype=float)


def time_span(ctx, kw, t_state):
    occ = kw.factor("INCREMENT")[0]
    veri_pas = occ.get("VERI_PAS") != "NON"
    if occ.get("LIST_INST") is not None:
        values = list_values(occ["LIST_INST"])
        steps = np.diff(values)
        dt = float(steps.min())
        if np.any(np.abs(steps - dt) >= 1.0e-6 * dt):
            ctx.error("LIST_INST must have a constant step for a GENE transient", "LIST_INST", occ)
        t0 = float(values[0]) if t_state is None else t_state
        t_end = float(values[-1])
        if occ.get("NUME_FIN") is not None and occ["NUME_FIN"] < len(values):
            t_end = float(values[occ["NUME_FIN"]])
        if occ.get("INST_FIN") is not None:
            t_end = float(occ["INST_FIN"])
    else:
        dt = float(occ["PAS"])
        t0 = t_state if t_state is not None else float(occ.get("INST_INIT") or 0.0)
        if occ.get("INST_INIT") is not None and t_state is None:
            t0 = float(occ["INST_INIT"])
        t_end = float(occ["INST_FIN"])
    if t_end <= t0:
        ctx.error(f"INST_FIN ({t_end}) must exceed the initial instant ({t0})", "INST_FIN", occ)
    refuse_too_many_steps(ctx, occ, t0, t_end, dt)
    return t0, t_end, dt, veri_pas


# steps one transient may take (docs/safety.md): bounded before it starts
MAX_TRANSIENT_STEPS = 1_000_000_000


def archived_index(ctx, occ, previous) -> int:
    """The archive row ETAT_INIT continues from in a previous result: its
    NUME_ORDRE, else the archived instant at INST_INIT (within PRECISION and
    CRITERE), else the last one."""
    if occ.get("NUME_ORDRE") is not None:
        hits = np.nonzero(np.asarray(previous.order) == occ["NUME_ORDRE"])[0]
        if not hits.size:
            ctx.error(
                f"NUME_ORDRE {occ['NUME_ORDRE']} is not archived in the result",
                "NUME_ORDRE",
                occ,
            )
        return int(hits[0])
    if occ.get("INST_INIT") is not None:
        t = occ["INST_INIT"]
        k = int(np.argmin(np.abs(previous.times - t)))
        tol = occ["PRECISION"] * (abs(t) if occ["CRITERE"] == "RELATIF" else 1.0)
        if abs(previous.times[k] - t) > max(tol, 1e-300):
            ctx.error(f"instant {t} is not archived in the result", "INST_INIT", occ)
        return k
    return len(previous.times) - 1


def refuse_too_many_steps(ctx, occ, t0: float, t_end: float, dt: float) -> None:
    """A located error when (INST_FIN - INST_INIT) / PAS passes the bound."""
    steps = (t_end - t0) / dt if dt > 0.0 else float("inf")
    if not steps <= MAX_TRANSIENT_STEPS:
        ctx.error(
            f"INST_FIN={t_end:g} and PAS={dt:g} from {t0:g} make {steps:.3g} steps, more than "
            f"the {MAX_TRANSIENT_STEPS:.0e} a transient may take: shorten INST_FIN or enlarge PAS",
            "INST_FIN",
            occ,
        )


def checked_step(ctx, scheme, system, shocks, dt_user, veri_pas, kw) -> float:
    """code_aster's VERI_PAS: the step may not exceed the fraction of the
    shortest period, shock stiffness included, that the scheme's description
    gives (:mod:`asterlite.dynamics.schemes`: 1/20, 1/10 for DEVOGE and
    NEWMARK); NEWMARK and ADAPT_* only warn, RUNGE_KUTTA_* are not checked
    (``Scheme.step_refused``, ``Scheme.step_checked``). PAS_MAXI may not
    be smaller than PAS. The refusal names what sets the shortest period
    (the shock and node, or the mode), its frequency, the critical step and
    a round step to use. DIFF_CENTRE (and EULER) are also refused above the
    stability limit of their explicit velocity update once modal damping
    and AMOR_NOR/AMOR_TAN are counted (heavy damping: about 1/(ξ ω)),
    which VERI_PAS's undamped period ignores. RUNGE_KUTTA_* and DEVOGE
    (shock forces explicit in their stages) are refused when PAS exceeds the
    stability limit of a shock's AMOR_NOR/AMOR_TAN (c·dt inside the stages'
    real stability interval), and their adaptive step never grows above it
    (:func:`asterlite.dynamics.step_limits.shock_damping_limit`)."""
    [schema_kw] = kw.factor("SCHEMA_TEMPS")
    dt_max = schema_kw.get("PAS_MAXI")
    if dt_max is not None and dt_max < dt_user:
        raise NumericalError(
            f"PAS_MAXI={dt_max:.6g} is smaller than PAS={dt_user:.6g}",
            ctx.location,
            f"{ctx.command}/SCHEMA_TEMPS/PAS_MAXI",
        )
    entry = SCHEMES[scheme]
    if entry.explicit_stages:
        # a Runge-Kutta module's tableau, or the stages' radius of DEVOGE's
        module = entry.implementation()
        tableau = getattr(module, "TABLEAU", None)
        radius = tableau.radius if tableau is not None else module.STAGE_RADIUS
        damped = shock_damping_limit(system, shocks, radius, modal=tableau is not None)
        if dt_user > damped.step:
            keyword = DAMPING_KEYWORDS[damped.damping]
            why = (
                f"{damped.cause(DAMPING_KEYWORDS)} gives a damping per unit mass of "
                f"{damped.per_mass:.6g} 1/s, {keyword}*dt/M = {damped.per_mass * dt_user:.6g} "
                f"beyond the {radius:.4g} "
                f"the explicit stages of {scheme} bear (the critical step is "
                f"{damped.step:.6g} s)"
            )
            if veri_pas:
                raise NumericalError(
                    f"PAS={dt_user:.6g} exceeds the stability limit {damped.step:.6g} of "
                    f"{scheme}: {why}; use PAS <= {damped.step:.6g} (e.g. "
                    f"PAS={suggested_step(damped.step / 2.0):.6g}) or NEWMARK",
                    ctx.location,
                    f"{ctx.command}/INCREMENT/PAS",
                )
            ctx.log(f"warning: PAS={dt_user:.6g} with VERI_PAS='NON': {why}")
        elif math.isfinite(damped.step) and (dt_max is None or dt_max > damped.step):
            ctx.log(
                f"{scheme}: the adaptive step stays below {damped.step:.6g} s, the stability "
                f"limit of its explicit stages set by {damped.cause(DAMPING_KEYWORDS)}"
            )
    if not entry.step_checked:
        return dt_user
    fraction = entry.step_fraction
    shortest = stability_limit(system, shocks)
    limit = shortest.period / fraction
    if dt_user <= limit:
        if entry.explicit_velocity:
            damped = damped_step_limit(system, shocks)
            if dt_user > damped.step:
                why = (
                    f"its explicit velocity update is unstable above {damped.step:.6g} s, "
                    f"set by {damped.cause(DAMPING_KEYWORDS)}"
                )
                if veri_pas:
                    raise NumericalError(
                        f"PAS={dt_user:.6g} exceeds the stability limit {damped.step:.6g} of "
                        f"{scheme}: {why}; use PAS <= {damped.step:.6g} (e.g. "
                        f"PAS={suggested_step(damped.step / 2.0):.6g})"
                        + (" or NEWMARK (implicit damping)" if damped.shock is None else ""),
                        ctx.location,
                        f"{ctx.command}/INCREMENT/PAS",
                    )
                ctx.log(f"warning: PAS={dt_user:.6g} with VERI_PAS='NON': {why}")
        return dt_user
    why = (
        f"the critical step is {limit:.6g} s, 1/{fraction:g} of the shortest period "
        f"{shortest.period:.6g} s ({shortest.frequency:.6g} Hz, shock stiffness included), "
        f"set by {shortest.cause(STIFFNESS_KEYWORDS)}"
    )
    if veri_pas and entry.step_refused:
        raise NumericalError(
            f"PAS={dt_user:.6g} exceeds the stability limit {limit:.6g} of {scheme}: {why}; "
            f"use PAS <= {limit:.6g} (e.g. PAS={suggested_step(limit):.6g}) or "
            "INCREMENT=_F(VERI_PAS='NON')",
            ctx.location,
            f"{ctx.command}/INCREMENT/PAS",
        )
    ctx.log(
        f"warning: PAS={dt_user:.6g} exceeds the stability estimate {limit:.6g} of {scheme}: {why}"
    )
    return dt_user


def legacy_adapt_step_max(ctx, system, shocks) -> float:
    """PAS_MAXI of code_aster 10-12's ADAPT_ORDRE2 when the deck gives none
    (mdptem): a twentieth of the shortest period, shock stiffness included."""

    shortest = stability_limit(system, shocks)
    dt_max = default_step_max(shortest.period)
    ctx.log(
        f"ADAPT_ORDRE2 (code_aster 10-12): PAS_MAXI={dt_max:.6g}, a twentieth of the shortest "
        f"period {shortest.period:.6g} s (that version's default), set by "
        f"{shortest.cause(STIFFNESS_KEYWORDS)}"
    )
    return dt_max


def archiving(ctx, kw, t0, t_end):
    """(instants to land on, period in steps); default: every step."""
    eps = np.finfo(float).eps
    occs = kw.factor("ARCHIVAGE")
    instants, pas_arch = [], 1
    if occs:
        occ = occs[0]
        if occ.get("LIST_INST") is not None:
            instants = list(list_values(occ["LIST_INST"]))
        elif occ.get("INST") is not None:
            instants = list(np.atleast_1d(np.asarray(occ["INST"], dtype=float)))
        pas_arch = int(occ["PAS_ARCH"]) if occ.get("PAS_ARCH") is not None else 2**62
        if pas_arch <= 0:
            pas_arch = 2**62
    kept = []
    for t in instants:
        if t < t0 - eps or t > t_end + eps:
            ctx.error(f"archiving instant {t} outside [{t0}, {t_end}]", "ARCHIVAGE")
        if abs(t - t0) > eps:
            kept.append(float(t))
    if not kept or abs(kept[-1] - t_end) > eps:
        kept.append(t_end)
    if np.any(np.diff(kept) <= 0.0):
        ctx.error("archiving instants must increase", "ARCHIVAGE")
    return np.array(kept), pas_arch
