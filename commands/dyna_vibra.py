"""DYNA_VIBRA, TYPE_CALCUL='TRAN', BASE_CALCUL='GENE': transient analysis by
modal recombination with DIS_CHOC shock and friction connections.

Reads the keywords into the numerical model of ``asterlite.dynamics`` and
returns a ``TranGene``. The numerics live in ``asterlite.dynamics``.
"""

from __future__ import annotations

import math

import numpy as np

from asterlite.concepts.titles import default_title, unique_titles
from asterlite.concepts.transient import ShockHistory, TranGene
from asterlite.dynamics import contact as C
from asterlite.dynamics.fluid_film import N_FILM, FluidFilm, film_row, integrate_film
from asterlite.dynamics.integrate import SCHEMES, SchemeOptions, integrate
from asterlite.dynamics.kernel import INFO_REJECTED, INFO_STEP
from asterlite.dynamics.model import (
    COMPONENTS,
    LinearSystem,
    ShockSpec,
    build_shocks,
    damped_step_limit,
    diagonal_damping_rates,
    modal_damping_rates,
    optimal_tangential_damping_v15,
    stability_limit,
    suggested_step,
    tabulate_excitation,
)
from asterlite.dynamics.shock_fields import ArchivedFields, column_difference
from asterlite.dynamics.shock_fields import column as archived_column
from asterlite.errors import NumericalError, missing_name
from asterlite.legacy.v15 import computes
from asterlite.modal.seismic import SeismicError, combined_static_shape

# VERI_PAS (code_aster's step check): fraction of the shortest period, shock
# stiffness included; RUNGE_KUTTA_* are not checked, NEWMARK and ADAPT_*
# only warn.
STEP_FRACTION = {"DEVOGE": 10.0, "NEWMARK": 10.0}  # others: 1/20 of the period
STEP_NOT_CHECKED = ("RUNGE_KUTTA_32", "RUNGE_KUTTA_54")
STEP_ONLY_WARNED = ("NEWMARK", "ADAPT_ORDRE1", "ADAPT_ORDRE2")
# VITESSE_VARIABLE='OUI': code_aster (dtmcalc/dtmupmat) updates C and K before
# every step of any GENE scheme; asterlite.dynamics.rotation has a loop for each
ROTATING_SCHEMES = tuple(SCHEMES)


def run(ctx, kw):
    if kw.get("TYPE_CALCUL") == "HARM":
        from asterlite.commands.dyna_vibra_harm import run_harmonic

        return run_harmonic(ctx, kw)
    if kw.get("BASE_CALCUL") == "PHYS" and kw.get("TYPE_CALCUL") == "TRAN":
        from asterlite.commands.dyna_vibra_phys import run_physical

        return run_physical(ctx, kw)
    if kw.get("BASE_CALCUL") != "GENE" or kw.get("TYPE_CALCUL") != "TRAN":
        ctx.unsupported(
            f"DYNA_VIBRA BASE_CALCUL={kw.get('BASE_CALCUL')!r} "
            f"TYPE_CALCUL={kw.get('TYPE_CALCUL')!r}"
            " (only TRAN/GENE)",
            "TYPE_CALCUL",
            kw,
        )
    if kw.get("BASE_ELAS_FLUI"):
        ctx.unsupported("BASE_ELAS_FLUI is not implemented", "BASE_ELAS_FLUI", kw)
    schema_kw = (kw.factor("SCHEMA_TEMPS") or [{}])[0]
    scheme = schema_kw.get("SCHEMA", "RUNGE_KUTTA_32")
    if scheme not in SCHEMES:
        ctx.unsupported(
            f"SCHEMA={scheme!r} (implemented: {', '.join(SCHEMES)})", "SCHEMA", schema_kw
        )
    if kw.get("VITESSE_VARIABLE", "NON") == "OUI" and scheme not in ROTATING_SCHEMES:
        ctx.unsupported(
            f"VITESSE_VARIABLE='OUI' with SCHEMA={scheme!r} "
            f"(implemented: {', '.join(ROTATING_SCHEMES)})",
            "VITESSE_VARIABLE",
            kw,
        )
    implicit = implicit_shocks(ctx, kw)

    mass_matrix = kw["MATR_MASS"]
    if getattr(mass_matrix.numbering, "constraints", None) is not None:
        # a coupled generalized model: integrate on its interface relations' null space
        from asterlite.substructure.transient import reduce_keywords

        refused = reduce_keywords(kw)
        if refused is not None:
            ctx.error("not on the numbering of MATR_MASS", refused, kw)
        mass_matrix = kw["MATR_MASS"]
    basis = mass_matrix.basis
    system = linear_system(ctx, kw)
    specs = []
    occurrences = []  # the COMPORTEMENT occurrence of each shock (fluid films)
    for occ in kw.factor("COMPORTEMENT"):
        if occ.get("RELATION") != "DIS_CHOC":  # a relation of asterlite.dynamics.laws
            specs.append(nonlinearity_spec(ctx, kw, occ, basis, system.n_modes, len(specs) + 1))
            occurrences.append(occ)
            continue
        found = shock_specs(ctx, occ, basis, system.n_modes, first=len(specs) + 1)
        specs.extend(found)
        occurrences.extend([occ] * len(found))
    for spec, title in zip(specs, unique_titles([s.name for s in specs]), strict=True):
        spec.name = title  # one name per shock (asterlite.concepts.titles)
    continue_law_states(kw, specs)
    legacy_tangential_damping(ctx, system, specs)
    if kw.factor("VERI_CHOC"):
        check_basis_for_shocks(ctx, kw, specs, basis, system)
    shocks = build_shocks(specs, system)
    film = fluid_film(ctx, kw, scheme, system, occurrences)

    q0, v0, t_init_state = initial_state(ctx, kw, system.n_modes)
    t0, t_end, dt_user, veri_pas = time_span(ctx, kw, t_init_state)
    dt = checked_step(ctx, scheme, system, shocks, dt_user, veri_pas, kw)
    if not implicit:
        warn_lagged_shocks(ctx, scheme, system, shocks, dt)
    instants, pas_arch = archiving(ctx, kw, t0, t_end)
    loads = excitations(ctx, kw, system.n_modes)
    excitation = tabulate_excitation(system.n_modes, loads, t0, t_end, dt / 2.0)
    supports = support_motions(ctx, kw, basis)
    corrections = static_corrections(ctx, kw, basis, system)
    # the shocks see the support motions and the static corrections (code_aster
    # keeps both as "multi-support" shapes times DEPL / FONC_MULT functions)
    driven = supports + corrections
    if implicit:
        refuse_moving_gaps(ctx, kw, driven)
    if driven:
        excitation.add_support_motion(
            shock_support_shapes(shocks, basis, driven),
            [(s["DEPL"], s["VITE"]) for s in driven],
            t0,
            t_end,
            dt / 2.0,
        )
    rotation = rotating_matrices(ctx, kw, system, t0, t_end, dt)
    if rotation is not None:
        damping, stiffness = rotation.matrices_at(t0)
        system = LinearSystem(system.mass, stiffness, damping)
        rotation.initial_acceleration = restart_acceleration(kw, t_init_state)
    energy = bool(kw.factor("ENERGIE"))  # asterlite extension on GENE: the energy balance
    if energy and rotation is not None:
        ctx.unsupported(
            "ENERGIE with VITESSE_VARIABLE='OUI' (the balance of a varying rotation speed)",
            "ENERGIE",
            kw,
        )
    options = SchemeOptions(
        tolerance=schema_kw.get("TOLERANCE", 1.0e-5),
        alpha=schema_kw.get("ALPHA", 0.0),
        dt_min=schema_kw.get("PAS_MINI"),
        dt_max=schema_kw.get("PAS_MAXI"),
        beta=schema_kw.get("BETA", 0.25),
        gamma=schema_kw.get("GAMMA", 0.5),
        nmax_iter_pas=int(schema_kw.get("NMAX_ITER_PAS", 16)),
        vite_min=first_value(schema_kw.get("VITE_MIN", "NORM")),
        coef_mult_pas=schema_kw.get("COEF_MULT_PAS", 1.1),
        coef_divi_pas=schema_kw.get("COEF_DIVI_PAS", 1.3333334),
        pas_limi_rela=schema_kw.get("PAS_LIMI_RELA", 1.0e-6),
        nb_poin_periode=int(schema_kw.get("NB_POIN_PERIODE", 50)),
        force_at_step_start=computes(ctx.session, "NEWMARK_FORCE_AT_STEP_START"),
        adapt_v11=scheme == "ADAPT_ORDRE2" and computes(ctx.session, "ADAPT_ORDRE2_MDADAP"),
    )
    if options.adapt_v11 and options.dt_max is None:
        options.dt_max = legacy_adapt_step_max(ctx, system, shocks)
    try:
        if film is not None:  # CHOC/LAME_FLUIDE of code_aster 10-14 decks
            refuse_with_film(ctx, kw, implicit, rotation, energy, driven)
            film_scheme = "ADAPT_ORDRE2" if options.adapt_v11 else "EULER"
            result = integrate_film(
                system, shocks, film, excitation, q0, v0, t0, t_end, dt, instants, pas_arch,
                label=f"DYNA_VIBRA {ctx.result_name or ''} {film_scheme} (LAME_FLUIDE)",
                adapt=options if options.adapt_v11 else None,
            )  # fmt: skip
        else:
            result = integrate(
                system,
                shocks,
                excitation,
                scheme,
                q0,
                v0,
                t0,
                t_end,
                dt,
                instants,
                pas_arch,
                options,
                rotation=rotation,
                label=f"DYNA_VIBRA {ctx.result_name or ''} {scheme}".replace("  ", " "),
                energy=energy,
                implicit_shocks=implicit,
                load_labels=load_labels(kw, len(loads)),
            )
    except NumericalError as error:
        path = f"{ctx.command}/{error.path}" if error.path else ctx.command
        raise NumericalError(error.message, ctx.location, path) from None
    ctx.log(
        f"DYNA_VIBRA {scheme}: {result.info['steps']} steps "
        f"({result.info['rejected_steps']} rejected), "
        f"{result.info['archived']} archived, step {result.info['min_step']:.3g}"
        f"..{result.info['max_step']:.3g}, {result.info['integration_seconds']:.3f} s"
    )
    if implicit:
        ctx.log(
            f"TRAITEMENT_NONL='IMPLICITE': {result.info['contact_switches']} contact switches, "
            f"{result.info['reintegrated_steps']} steps integrated again up to a switch, "
            f"{result.info['relinearisations']} linearisations about a contact point that moved"
        )
    # the deck's step bounds (asterlite sensitivity moves them with PAS when equal to it)
    result.info["pas_mini"] = schema_kw.get("PAS_MINI")
    result.info["pas_maxi"] = schema_kw.get("PAS_MAXI")
    if supports:
        result.info["mult_appui"] = supports
    if corrections:
        result.info["corr_stat"] = corrections
    kept = result.info.get("steps_kept_at_nmax_iter_pas", 0)
    if kept:
        ctx.log(
            f"warning: {kept} steps kept after NMAX_ITER_PAS trials without reaching "
            "the apparent-frequency criterion (code_aster's DYNAMIQUE_18)"
        )
    produced = TranGene(
        basis=basis,
        times=result.times,
        order=result.order,
        depl=result.depl,
        vite=result.vite,
        acce=result.acce,
        shocks=shock_histories(shocks, result.vint),
        scheme=scheme,
        step=dt,
        info=result.info,
        step_sizes=result.step_info[:, INFO_STEP],
        rejections=result.step_info[:, INFO_REJECTED],
    )
    reused = getattr(ctx, "reuse", None)
    continued = isinstance(reused, TranGene) and t_init_state is not None
    if result.energy is not None:
        from asterlite.dynamics import energy as E

        previous = reused.tables.get("PARA_CALC") if continued else None
        produced.tables["PARA_CALC"] = E.table(result.energy, previous, t0)
        produced.info.update(E.summary(result.energy))
    final = produced
    if continued:
        final = appended(reused, produced)
        final.tables.update(produced.tables)
    name = (reused.name if continued else None) or ctx.result_name or ""
    impression(ctx, kw, final, name, specs, system)
    return final


# schemes that integrate a fluid film: code_aster 10-12's EULER (asterlite's
# DIFF_CENTRE arithmetic, the name legacy decks are translated to), and its
# ADAPT_ORDRE2 (mdadap) in decks of those versions (FILM_ADAPT_SCHEMES)
FILM_SCHEMES = ("DIFF_CENTRE", "EULER")
FILM_ADAPT_SCHEMES = ("ADAPT_ORDRE2",)
FRICTION_KEYWORDS = ("COULOMB", "COULOMB_DYNA", "COULOMB_STAT")


def legacy_adapt_step_max(ctx, system, shocks) -> float:
    """PAS_MAXI of code_aster 10-12's ADAPT_ORDRE2 when the deck gives none
    (mdptem): a twentieth of the shortest period, shock stiffness included."""
    from asterlite.dynamics.scheme_adapt_ordre2_v11 import default_step_max

    shortest = stability_limit(system, shocks)
    dt_max = default_step_max(shortest.period)
    ctx.log(
        f"ADAPT_ORDRE2 (code_aster 10-12): PAS_MAXI={dt_max:.6g}, a twentieth of the shortest "
        f"period {shortest.period:.6g} s (that version's default), set by {shortest.cause()}"
    )
    return dt_max


def fluid_film(ctx, kw, scheme, system, occurrences) -> FluidFilm | None:
    """The fluid films of the shocks (COMPORTEMENT/LAME_FLUIDE='OUI', an
    asterlite extension reached from code_aster 10-14 decks), or None."""
    films = [occ for occ in occurrences if occ.get("LAME_FLUIDE") == "OUI"]
    if not films:
        return None
    where = films[0]
    legacy_adapt = scheme in FILM_ADAPT_SCHEMES and computes(ctx.session, "ADAPT_ORDRE2_MDADAP")
    if scheme not in FILM_SCHEMES and not legacy_adapt:
        ctx.unsupported(
            f"LAME_FLUIDE='OUI' with SCHEMA={scheme!r} (only code_aster 10-12's EULER, "
            "SCHEMA='DIFF_CENTRE' here, and that version's ADAPT_ORDRE2 in its decks)",
            "LAME_FLUIDE",
            where,
        )
    if not system.diagonal:
        ctx.unsupported(
            "LAME_FLUIDE='OUI' with non-diagonal generalized matrices (code_aster 11 "
            "modifies a diagonal modal mass only)",
            "LAME_FLUIDE",
            where,
        )
    for occ in occurrences:
        if occ.get("RELATION") != "DIS_CHOC":
            ctx.unsupported(
                f"LAME_FLUIDE='OUI' together with RELATION={occ.get('RELATION')!r}",
                "RELATION",
                occ,
            )
    for occ in films:
        for key in FRICTION_KEYWORDS:
            if occ.get(key):
                ctx.unsupported(f"{key} on a shock with LAME_FLUIDE='OUI'", key, occ)
    rows = np.zeros((len(occurrences), N_FILM))
    for s, occ in enumerate(occurrences):
        if occ.get("LAME_FLUIDE") == "OUI":
            rows[s] = film_row(occ["ALPHA"], occ["BETA"], occ["CHI"], occ["DELTA"])
    controls = (kw.factor("PARA_LAME_FLUI") or [{}])[0]
    return FluidFilm(
        rows,
        max_iterations=int(controls.get("NMAX_ITER", 20)),
        tolerance=float(controls.get("RESI_RELA", 1.0e-3)),
        relaxation=float(controls.get("LAMBDA", 10.0)),
    )


def refuse_with_film(ctx, kw, implicit, rotation, energy, driven) -> None:
    """What the fluid film loop does not combine with, refused by keyword."""
    refused = (
        (implicit, "TRAITEMENT_NONL", "TRAITEMENT_NONL='IMPLICITE'"),
        (rotation is not None, "VITESSE_VARIABLE", "VITESSE_VARIABLE='OUI'"),
        (energy, "ENERGIE", "ENERGIE"),
        (bool(driven), "EXCIT", "support motions (MULT_APPUI) or static corrections"),
    )
    for present, keyword, what in refused:
        if present:
            ctx.unsupported(f"{what} with LAME_FLUIDE='OUI'", keyword, kw)


def impression(ctx, kw, result, name, specs, system) -> None:
    """IMPRESSION: the DIS_VISC / DIS_ECRO_TRAC histories on their logical
    units (asterlite.io.relation_history), the shocks' local quantities in
    the message log (asterlite.io.shock_listing)."""
    from asterlite.io import relation_history, shock_listing

    occs = kw.factor("IMPRESSION")
    if not occs:
        return
    occ = occs[0]
    units = {k: occ.get(k) for k in relation_history.UNIT_KEYWORDS if occ.get(k) is not None}
    for note in relation_history.write_histories(ctx.session, result, name, units):
        ctx.log(note)
    levels = shock_listing.requested_levels(occ.get("NIVEAU"), occ.get("TOUT"))
    first, last = occ.get("INST_INIT"), occ.get("INST_FIN")
    if not levels:
        if first is not None or last is not None:  # code_aster lists nothing either
            ctx.log("IMPRESSION/INST_INIT, INST_FIN: nothing listed without NIVEAU or TOUT='OUI'")
        return
    rates = restitution_rates(ctx, kw, occ, specs, system) if "TAUX_CHOC" in levels else None
    for line in shock_listing.listing_lines(result, levels, first, last, rates):
        ctx.log(line)


def restitution_rates(ctx, kw, occ, specs, system) -> dict:
    """{(shock, node): static restitution rate of the basis} (VERI_CHOC's)."""
    from asterlite.dynamics.basis_check import node_checks

    basis = kw["MATR_MASS"].basis
    if getattr(basis, "stiffness", None) is None:  # also a mode_gene
        keyword = "NIVEAU" if occ.get("NIVEAU") else "TOUT"
        ctx.unsupported(
            "IMPRESSION TAUX_CHOC (restitution rate) on a basis without its assembled stiffness",
            keyword,
            occ,
        )
    checks = node_checks(specs, basis, np.diag(system.stiffness))
    return {(check.shock, check.node): check.restitution for check in checks}


def implicit_shocks(ctx, kw) -> bool:
    """TRAITEMENT_NONL='IMPLICITE': whether the shocks' normal forces are
    treated implicitly (:mod:`asterlite.dynamics.implicit_shocks`). As in
    code_aster (dtmprep_noli), only DIS_CHOC connections are concerned:
    without any, the run is the explicit one."""
    if kw.get("TRAITEMENT_NONL", "EXPLICITE") != "IMPLICITE":
        return False
    if not any(occ.get("RELATION") == "DIS_CHOC" for occ in kw.factor("COMPORTEMENT")):
        ctx.log(
            "TRAITEMENT_NONL='IMPLICITE' without DIS_CHOC: explicit treatment, as code_aster "
            "(its implicit treatment only concerns DIS_CHOC connections)"
        )
        return False
    if kw.get("VITESSE_VARIABLE", "NON") == "OUI":
        ctx.unsupported(
            "TRAITEMENT_NONL='IMPLICITE' with VITESSE_VARIABLE='OUI' (the contact "
            "linearisation and the rotation speed would both rewrite K and C)",
            "TRAITEMENT_NONL",
            kw,
        )
    return True


# energy an elastic impact gains, per unit of ω_c·dt, when the shock force of
# the previous state enters an implicit step (code_aster's EXPLICITE
# treatment with these schemes), measured on elastic bounces (docs/accuracy.md)
LAGGED_IMPACT_GAIN = {"NEWMARK": 2.2, "TRBDF2": 1.1}
IMPACT_GAIN_WARNED = 0.01


def warn_lagged_shocks(ctx, scheme, system, shocks, dt) -> None:
    """NEWMARK and TRBDF2 with TRAITEMENT_NONL='EXPLICITE' take the shock
    forces of the previous state into their implicit step: every elastic
    impact gains energy, about LAGGED_IMPACT_GAIN·ω_c·dt of it with ω_c the
    pulsation of the mode stiffened by the shock. Warn, naming the shock and
    the steps that keep the gain below 1 %, when it exceeds 1 %."""
    factor = LAGGED_IMPACT_GAIN.get(scheme)
    if factor is None or not shocks.count:
        return
    from asterlite.dynamics.model import contact_limit

    limit = contact_limit(system, shocks)
    if limit.shock is None:
        return
    omega = 2.0 * math.pi / limit.period
    gain = factor * omega * dt
    if gain <= IMPACT_GAIN_WARNED:
        return
    step = IMPACT_GAIN_WARNED / (factor * omega)
    ctx.log(
        f"warning: {scheme} with TRAITEMENT_NONL='EXPLICITE' applies the shock forces of "
        f"the previous state: each elastic impact gains about {100.0 * gain:.3g} % of its "
        f"energy at PAS={dt:.6g} ({factor:g}·ω·dt, ω = {omega:.6g} rad/s set by "
        f"{limit.cause()}); use TRAITEMENT_NONL='IMPLICITE' (energy-consistent impacts) or "
        f"PAS <= {step:.3g} for less than 1 %"
    )


def refuse_moving_gaps(ctx, kw, driven) -> None:
    """Implicit shocks linearise each gap into K q plus a constant force; a
    support motion (MULT_APPUI, CORR_STAT) moves the gap with time."""
    if driven:
        ctx.unsupported(
            "TRAITEMENT_NONL='IMPLICITE' with support motions seen by the shocks "
            "(MULT_APPUI or CORR_STAT): the linearised gap would not follow the supports; "
            "use TRAITEMENT_NONL='EXPLICITE'",
            "TRAITEMENT_NONL",
            kw,
        )


def appended(previous: TranGene, new: TranGene) -> TranGene:
    """reuse= continuation: the reused states before the new start, then the
    new run, its NUME_ORDRE continuing the reused ones."""
    t0 = new.times[0]
    keep = previous.times < t0 - 1.0e-12 * max(1.0, abs(t0))
    start = int(previous.order[np.flatnonzero(~keep)[0]]) if np.any(~keep) else 0
    shocks = []
    for old, fresh in zip(previous.shocks, new.shocks, strict=False):
        fields = {
            k: np.concatenate([old.fields[k][keep], v])
            for k, v in fresh.fields.items()
            if k in old.fields
        }
        shocks.append(
            ShockHistory(
                fresh.name, fresh.relation, fresh.node_1, fresh.node_2, fields, fresh.parameters
            )
        )
    info = dict(new.info)
    for key in ("mult_appui", "corr_stat"):
        if key in previous.info and key not in info:
            info[key] = previous.info[key]
    return TranGene(
        basis=new.basis,
        times=np.concatenate([previous.times[keep], new.times]),
        order=np.concatenate([previous.order[keep], start + new.order]),
        depl=np.concatenate([previous.depl[keep], new.depl]),
        vite=np.concatenate([previous.vite[keep], new.vite]),
        acce=np.concatenate([previous.acce[keep], new.acce]),
        shocks=shocks if previous.shocks else new.shocks,
        scheme=new.scheme,
        step=new.step,
        info=info,
        step_sizes=_joined(previous.step_sizes, new.step_sizes, keep),
        rejections=_joined(previous.rejections, new.rejections, keep),
    )


def _joined(previous, new, keep):
    """An archived-instant history of a continuation (None if either part lacks it)."""
    if previous is None or new is None:
        return None
    return np.concatenate([previous[keep], new])


# ----------------------------------------------------------------------------- matrices


def legacy_tangential_damping(ctx, system, specs) -> None:
    """A deck of code_aster 13 to 15 giving RIGI_TAN without AMOR_TAN: the
    default AMOR_TAN those versions computed (it can be negative), set on
    the shock before the model is built; code_aster 17's otherwise."""
    if not computes(ctx.session, "AMOR_TAN_DEFAULT_MAX_MODAL_MASS"):
        return
    for spec in specs:
        if spec.relation != "DIS_CHOC" or spec.c_t is not None:
            continue
        if spec.k_t > np.finfo(float).eps:
            spec.c_t = optimal_tangential_damping_v15(spec, system)
            ctx.log(
                f"{spec.name}: AMOR_TAN = {spec.c_t:.6g} as code_aster 13-15 computed it "
                "(mode of largest generalized mass, its AMOR_DIA taken for the reduced "
                "damping, not floored at 0)"
            )


def linear_system(ctx, kw) -> LinearSystem:
    mass = np.array(kw["MATR_MASS"].matrix, dtype=float)
    stiffness = np.array(kw["MATR_RIGI"].matrix, dtype=float)
    rates = None  # code_aster's AMOR_DIA (LinearSystem.damping_rates)
    if kw.get("MATR_AMOR") is not None:
        damping = np.array(kw["MATR_AMOR"].matrix, dtype=float)
        numbering = getattr(kw["MATR_AMOR"], "numbering", None)
        if getattr(numbering, "storage", "PLEIN") == "DIAG" and damping.shape == mass.shape:
            rates = diagonal_damping_rates(mass, stiffness, damping)
    else:
        damping = np.zeros_like(mass)
        for occ in kw.factor("AMOR_MODAL"):
            ratios = occ.get("AMOR_REDUIT")
            if ratios is None and occ.get("LIST_AMOR") is not None:
                ratios = list_values(occ["LIST_AMOR"])
            if ratios is not None:
                ratios = np.atleast_1d(np.asarray(ratios, dtype=float))
                if ratios.size > mass.shape[0]:
                    ctx.error(
                        f"{ratios.size} damping ratios for {mass.shape[0]} modes",
                        "AMOR_REDUIT",
                        occ,
                    )
                rates = modal_damping_rates(mass, stiffness, ratios)
                damping = rates[:, None] * mass  # modal_damping
    if mass.shape != stiffness.shape or mass.shape != damping.shape:
        ctx.error("MATR_MASS, MATR_RIGI and the damping do not have the same size")
    return LinearSystem(mass, stiffness, damping, damping_rates=rates)


def list_values(obj) -> np.ndarray:
    """Values of a listr8 concept (or of a plain sequence)."""
    for attr in ("values", "vale", "VALE"):
        if hasattr(obj, attr):
            return np.asarray(getattr(obj, attr), dtype=float)
    return np.asarray(obj, dtype=float)


# ----------------------------------------------------------------------------- shocks


def nonlinearity_spec(ctx, kw, occ, basis, n_modes, number) -> ShockSpec:
    """A COMPORTEMENT occurrence of a relation other than DIS_CHOC
    (``asterlite.dynamics.laws``)."""
    from asterlite.dynamics.laws.connections import ConnectionError_, law_spec
    from asterlite.dynamics.laws.tabulated import LawError

    if occ.get("SOUS_STRUC_1") or occ.get("SOUS_STRUC_2"):
        ctx.unsupported("two-node nonlinearities on substructures", "SOUS_STRUC_1", occ)
    if not occ.get("SOUS_STRUC") and not hasattr(basis.numbering, "mesh"):
        ctx.error("the basis is a mode_gene: name the node's substructure", "SOUS_STRUC", occ)
    if occ.get("SOUS_STRUC"):  # the node's modes seen on its substructure
        from asterlite.substructure.shocks import SubstructureError, substructure_view

        try:
            basis = substructure_view(basis, occ["SOUS_STRUC"], "SOUS_STRUC")
        except SubstructureError as exc:
            ctx.error(str(exc), exc.keyword, occ)
    options = {k: kw.get(k) for k in ("INFO", "VITE_ROTA", "VITESSE_VARIABLE")}
    try:
        return law_spec(occ, basis, n_modes, number, options)
    except ConnectionError_ as error:
        ctx.error(str(error), error.keyword, occ)
    except LawError as error:
        ctx.error(str(error), "RELATION", occ)


def continue_law_states(kw, specs) -> None:
    """ETAT_INIT=_F(RESULTAT=...): the laws' internal variables (crushing,
    viscous state...) continue from the previous run's state at that instant."""
    occs = kw.factor("ETAT_INIT")
    previous = occs[0].get("RESULTAT") if occs else None
    if previous is None or not getattr(previous, "shocks", None):
        return
    occ = occs[0]
    if occ.get("NUME_ORDRE") is not None:
        hits = np.nonzero(previous.order == occ["NUME_ORDRE"])[0]
        k = int(hits[0]) if hits.size else len(previous.times) - 1
    elif occ.get("INST_INIT") is not None:
        k = int(np.argmin(np.abs(previous.times - occ["INST_INIT"])))
    else:
        k = len(previous.times) - 1
    for index, spec in enumerate(specs):
        if spec.relation == "DIS_CHOC" or index >= len(previous.shocks):
            continue
        old = previous.shocks[index]
        if old.relation != spec.relation or spec.law_state is None and "VINT1" not in old.fields:
            continue
        values = []
        while f"VINT{len(values) + 1}" in old.fields:
            values.append(float(np.asarray(old.fields[f"VINT{len(values) + 1}"])[k]))
        if values:
            spec.law_state = np.array(values)


def shock_specs(ctx, occ, basis, n_modes, first: int = 1) -> list[ShockSpec]:
    """The shocks of one DIS_CHOC occurrence; ``first``: the rank of its
    first among the call's nonlinearities (code_aster's default INTITULE)."""
    relation = occ.get("RELATION")
    if relation != "DIS_CHOC":
        ctx.unsupported(f"COMPORTEMENT RELATION={relation!r} (only DIS_CHOC)", "RELATION", occ)
    basis_1, basis_2, norm_obst, orig = substructured_views(ctx, occ, basis)
    mesh = basis_1.numbering.mesh
    obstacle = occ["OBSTACLE"]
    kind = obstacle.obstacle_type
    if basis_2 is basis_1:
        pairs = node_pairs(ctx, occ, mesh)
    else:  # nodes of two substructures: each looked up in its own mesh
        pairs = [
            (
                single_node(ctx, occ, mesh, "NOEUD_1", "GROUP_NO_1"),
                single_node(ctx, occ, basis_2.numbering.mesh, "NOEUD_2", "GROUP_NO_2"),
            )
        ]
    mesh_2 = basis_2.numbering.mesh
    two_nodes = kind.startswith("BI_")
    specs = []
    for index, (n1, n2) in enumerate(pairs):
        if two_nodes and n2 is None:
            ctx.error(
                f"obstacle {kind} needs a second node (NOEUD_2/GROUP_NO_2 or GROUP_MA)",
                "OBSTACLE",
                occ,
            )
        friction = occ.get("FROTTEMENT", "NON")
        mu_dyn = mu_stat = 0.0
        if friction == "COULOMB":
            mu_dyn = mu_stat = float(occ["COULOMB"])
        elif friction == "COULOMB_STAT_DYNA":
            mu_dyn, mu_stat = float(occ["COULOMB_DYNA"]), float(occ["COULOMB_STAT"])
        name = occ.get("INTITULE") or default_title("DIS_CHOC", first + index)
        if occ.get("INTITULE") and len(pairs) > 1:
            name = f"{occ['INTITULE']}_{index + 1}"
        spec = ShockSpec(
            name=name,
            obstacle_type=kind,
            node_1=mesh.node_names[n1],
            node_2=mesh_2.node_names[n2] if n2 is not None else None,
            coord_1=np.array(mesh.coords[n1], dtype=float),
            coord_2=np.array(mesh_2.coords[n2], dtype=float) if n2 is not None else None,
            phi_1=node_shape(basis_1, n1, n_modes),
            phi_2=node_shape(basis_2, n2, n_modes) if n2 is not None else None,
            norm_obst=norm_obst,
            angl_vril=occ.get("ANGL_VRIL"),
            orig_obst=np.asarray(orig, dtype=float) if orig is not None else None,
            gap=float(occ.get("JEU", 1.0)),
            dist_1=float(occ.get("DIST_1") or 0.0),
            dist_2=float(occ.get("DIST_2") or 0.0),
            k_n=float(occ["RIGI_NOR"]),
            c_n=float(occ.get("AMOR_NOR", 0.0)),
            k_t=float(occ.get("RIGI_TAN", 0.0)),
            c_t=float(occ["AMOR_TAN"]) if occ.get("AMOR_TAN") is not None else None,
            mu_dyn=mu_dyn,
            mu_stat=mu_stat,
            unidirectional=occ.get("UNIDIRECTIONNEL", "NON") == "OUI",
            polar=obstacle.polar if kind == "DISCRET" else None,
        )
        if kind == "BI_CERC_INT" and spec.dist_2 < spec.dist_1:
            ctx.error("BI_CERC_INT needs DIST_2 (outer radius) >= DIST_1", "DIST_2", occ)
        specs.append(spec)
    return specs


def substructured_views(ctx, occ, basis):
    """(basis of node 1, basis of node 2, NORM_OBST, ORIG_OBST): with
    SOUS_STRUC_1/2 the modes seen on those substructures in the global
    frame, and the obstacle's frame REPERE turned into the global one
    (asterlite.substructure.shocks); otherwise ``basis`` twice."""
    from asterlite.substructure.shocks import SubstructureError, in_global_frame
    from asterlite.substructure.shocks import substructure_view as view

    norm, orig = np.asarray(occ["NORM_OBST"], dtype=float), occ.get("ORIG_OBST")
    orig = np.asarray(orig, dtype=float) if orig is not None else None
    names = (occ.get("SOUS_STRUC_1"), occ.get("SOUS_STRUC_2"))
    repere = occ.get("REPERE", "GLOBAL")
    if names[0] is None and not hasattr(basis.numbering, "mesh"):  # modes of a mode_gene
        ctx.error("the basis is a mode_gene: name the node's substructure", "SOUS_STRUC_1", occ)
    if names == (None, None) and repere == "GLOBAL":
        return basis, basis, norm, orig
    if occ.get("GROUP_MA") or occ.get("MAILLE"):
        ctx.unsupported("GROUP_MA/MAILLE shocks on substructures", "GROUP_MA", occ)
    try:
        basis_1 = view(basis, names[0], "SOUS_STRUC_1") if names[0] else basis
        basis_2 = basis_1
        if names[1] and names[1] != names[0]:
            basis_2 = view(basis, names[1], "SOUS_STRUC_2")
        orig, norm = in_global_frame(basis, repere, orig, norm)
    except SubstructureError as exc:
        ctx.error(str(exc), exc.keyword, occ)
    return basis_1, basis_2, norm, orig


def node_pairs(ctx, occ, mesh) -> list[tuple[int, int | None]]:
    """(node 1, node 2) indices: one pair per SEG2 cell of GROUP_MA/MAILLE,
    or the single NOEUD_1/GROUP_NO_1 (+ NOEUD_2/GROUP_NO_2)."""
    cells = []
    for group in as_tuple(occ.get("GROUP_MA")):
        if group not in mesh.cell_groups:
            ctx.error(missing_name("cell group", group, mesh.cell_groups), "GROUP_MA", occ)
        cells.extend(int(c) for c in mesh.cell_groups[group])
    for name in as_tuple(occ.get("MAILLE")):
        cells.append(mesh.cell_index[name])
    if cells:
        pairs = []
        for c in cells:
            nodes = mesh.cell_nodes[c]
            if len(nodes) != 2:
                ctx.error(f"cell {mesh.cell_names[c]} is not a SEG2", "GROUP_MA", occ)
            pairs.append((int(nodes[0]), int(nodes[1])))
        return pairs
    n1 = single_node(ctx, occ, mesh, "NOEUD_1", "GROUP_NO_1")
    n2 = single_node(ctx, occ, mesh, "NOEUD_2", "GROUP_NO_2")
    return [(n1, n2)]


def single_node(ctx, occ, mesh, node_kw, group_kw) -> int | None:
    if occ.get(node_kw) is not None:
        name = occ[node_kw]
        index = mesh.find_node(name)  # also code_aster 17's positional N<i> names
        if index is None:
            ctx.error(f"no node {name!r} in the mesh", node_kw, occ)
        return index
    if occ.get(group_kw) is not None:
        group = occ[group_kw]
        if group not in mesh.node_groups:
            ctx.error(missing_name("node group", group, mesh.node_groups), group_kw, occ)
        nodes = mesh.node_groups[group]
        if len(nodes) != 1:
            ctx.error(
                f"group {group!r} must hold exactly one node (it has {len(nodes)})", group_kw, occ
            )
        return int(nodes[0])
    return None


def node_shape(basis, node: int, n_modes: int) -> np.ndarray:
    return np.array([basis.shape_at(node, c)[:n_modes] for c in COMPONENTS], dtype=float)


def first_value(value):
    """A simple keyword given as a one-element tuple (``VITE_MIN=("MAXI",)``)."""
    if isinstance(value, (list, tuple)):
        return value[0] if value else None
    return value


def as_tuple(value) -> tuple:
    if value is None:
        return ()
    if isinstance(value, (list, tuple)):
        return tuple(value)
    return (value,)


# ----------------------------------------------------------------------------- time


def initial_state(ctx, kw, n_modes):
    """(q0, v0, t0 or None) from ETAT_INIT (vectors or a previous tran_gene)."""
    q0, v0 = np.zeros(n_modes), np.zeros(n_modes)
    occs = kw.factor("ETAT_INIT")
    if not occs:
        return q0, v0, None
    occ = occs[0]
    previous = occ.get("RESULTAT")
    if previous is not None:
        if occ.get("NUME_ORDRE") is not None:
            hits = np.nonzero(previous.order == occ["NUME_ORDRE"])[0]
            if not hits.size:
                ctx.error(
                    f"NUME_ORDRE {occ['NUME_ORDRE']} is not archived in the result",
                    "NUME_ORDRE",
                    occ,
                )
            k = int(hits[0])
        elif occ.get("INST_INIT") is not None:
            t = occ["INST_INIT"]
            k = int(np.argmin(np.abs(previous.times - t)))
            tol = occ.get("PRECISION", 1.0e-6) * (
                abs(t) if occ.get("CRITERE", "RELATIF") == "RELATIF" else 1.0
            )
            if abs(previous.times[k] - t) > max(tol, 1e-300):
                ctx.error(f"instant {t} is not archived in the result", "INST_INIT", occ)
        else:
            k = len(previous.times) - 1
        return previous.depl[k].copy(), previous.vite[k].copy(), float(previous.times[k])
    if occ.get("DEPL") is not None:
        q0 = np.asarray(occ["DEPL"].values, dtype=float)[:n_modes].copy()
    if occ.get("VITE") is not None:
        v0 = np.asarray(occ["VITE"].values, dtype=float)[:n_modes].copy()
    return q0, v0, None


def time_span(ctx, kw, t_state):
    occ = kw.factor("INCREMENT")[0]
    veri_pas = occ.get("VERI_PAS", "OUI") == "OUI"
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
    """code_aster's VERI_PAS: the step may not exceed 1/20 (1/10 for DEVOGE
    and NEWMARK) of the shortest period, shock stiffness included; NEWMARK
    and ADAPT_* only warn, RUNGE_KUTTA_* are not checked. PAS_MAXI may not
    be smaller than PAS. The refusal names what sets the shortest period
    (the shock and node, or the mode), its frequency, the critical step and
    a round step to use. DIFF_CENTRE (and EULER) are also refused above the
    stability limit of their explicit velocity update once modal damping
    and AMOR_NOR/AMOR_TAN are counted (heavy damping: about 1/(ξ ω)),
    which VERI_PAS's undamped period ignores. RUNGE_KUTTA_* and DEVOGE
    (shock forces explicit in their stages) are refused when PAS exceeds the
    stability limit of a shock's AMOR_NOR/AMOR_TAN (c·dt inside the stages'
    real stability interval), and their adaptive step never grows above it
    (:func:`asterlite.dynamics.model.shock_damping_limit`)."""
    schema_kw = (kw.factor("SCHEMA_TEMPS") or [{}])[0]
    dt_max = schema_kw.get("PAS_MAXI")
    if dt_max is not None and dt_max < dt_user:
        raise NumericalError(
            f"PAS_MAXI={dt_max:.6g} is smaller than PAS={dt_user:.6g}",
            ctx.location,
            f"{ctx.command}/SCHEMA_TEMPS/PAS_MAXI",
        )
    if scheme in ("RUNGE_KUTTA_32", "RUNGE_KUTTA_54", "DEVOGE"):
        from asterlite.dynamics.model import shock_damping_limit
        from asterlite.dynamics.scheme_devoge import STAGE_RADIUS
        from asterlite.dynamics.scheme_runge_kutta import TABLEAUX

        tableau = TABLEAUX.get(scheme)
        radius = tableau.radius if tableau is not None else STAGE_RADIUS
        damped = shock_damping_limit(system, shocks, radius, modal=tableau is not None)
        if dt_user > damped.step:
            why = (
                f"{damped.cause()} gives a damping per unit mass of {damped.per_mass:.6g} 1/s, "
                f"{damped.damping}*dt/M = {damped.per_mass * dt_user:.6g} beyond the {radius:.4g} "
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
                f"limit of its explicit stages set by {damped.cause()}"
            )
    if scheme in STEP_NOT_CHECKED:
        return dt_user
    fraction = STEP_FRACTION.get(scheme, 20.0)
    shortest = stability_limit(system, shocks)
    limit = shortest.period / fraction
    if dt_user <= limit:
        if scheme in ("DIFF_CENTRE", "EULER"):  # explicit velocity update
            damped = damped_step_limit(system, shocks)
            if dt_user > damped.step:
                why = (
                    f"its explicit velocity update is unstable above {damped.step:.6g} s, "
                    f"set by {damped.cause()}"
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
        f"set by {shortest.cause()}"
    )
    if veri_pas and scheme not in STEP_ONLY_WARNED:
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


def excitations(ctx, kw, n_modes):
    loads = []
    for occ in kw.factor("EXCIT"):
        if occ.get("VECT_ASSE_GENE") is None:
            # a load on one generalized coordinate (code_aster's mdfext: f(NUME_ORDRE) += ...)
            number = int(occ["NUME_ORDRE"])
            if not 1 <= number <= n_modes:
                ctx.error(
                    f"NUME_ORDRE={number}: the basis has {n_modes} generalized coordinates",
                    "NUME_ORDRE",
                    occ,
                )
            vector = np.zeros(n_modes)
            vector[number - 1] = 1.0
        else:
            vector = np.asarray(occ["VECT_ASSE_GENE"].values, dtype=float)[:n_modes]
        mult = occ.get("FONC_MULT")
        if occ.get("ACCE") is not None:
            mult = occ["ACCE"]  # relative motion: the load is Φᵀ(-M ψ d) γ(t)
        elif mult is None:
            mult = float(occ.get("COEF_MULT", 1.0))
        loads.append((vector, mult))
    loads.extend(result_excitations(ctx, kw, n_modes))
    return loads


def load_labels(kw, count: int) -> list[str]:
    """How the deck names each excitation row: EXCIT[k], then EXCIT_RESU."""
    labels = [f"EXCIT[{k}]" for k in range(1, len(kw.factor("EXCIT")) + 1)]
    return (labels + ["EXCIT_RESU"] * count)[:count]


def result_excitations(ctx, kw, n_modes):
    """EXCIT_RESU (code_aster's mdrecf): the DEPL field of a tran_gene on
    the same modal basis, read as a generalized force history times
    COEF_MULT. Each generalized coordinate j gets a load on itself (as an
    EXCIT NUME_ORDRE=j) whose multiplier is the function of INST through
    the result's archived instants and values COEF_MULT DEPL_j, linear
    interpolation, PROL_GAUCHE/PROL_DROITE='EXCLU'."""
    from asterlite.concepts.function import Function

    basis = kw["MATR_MASS"].basis
    loads = []
    for number, occ in enumerate(kw.factor("EXCIT_RESU"), start=1):
        result = occ["RESULTAT"]
        alpha = float(occ.get("COEF_MULT", 1.0))
        same_basis = result.basis is basis or (
            result.basis.name is not None and result.basis.name == basis.name
        )
        if not same_basis:
            ctx.error(
                f"EXCIT_RESU occurrence {number}: the result {result.name or ''} is on the "
                f"modal basis {result.basis.name or '?'}, the generalized matrices on "
                f"{basis.name or '?'} (code_aster requires the same basis, ALGORITH17_18)",
                "RESULTAT",
                occ,
            )
        times = np.asarray(result.times, dtype=float)
        depl = np.asarray(result.depl, dtype=float)
        if depl.ndim != 2 or depl.shape[1] != n_modes:
            ctx.error(
                f"EXCIT_RESU occurrence {number}: the result holds {depl.shape[-1]} "
                f"generalized coordinates, the system {n_modes}",
                "RESULTAT",
                occ,
            )
        if times.size == 0 or np.any(np.diff(times) <= 0.0):
            ctx.error(
                f"EXCIT_RESU occurrence {number}: the result's instants must increase "
                "strictly (they become the abscissas of the force functions)",
                "RESULTAT",
                occ,
            )
        for j in range(n_modes):
            vector = np.zeros(n_modes)
            vector[j] = 1.0
            history = Function(
                abscissas=times.copy(),
                ordinates=alpha * depl[:, j],
                NOM_PARA="INST",
                INTERPOL=("LIN", "LIN"),
                PROL_GAUCHE="EXCLU",
                PROL_DROITE="EXCLU",
            )
            history.name = f"EXCIT_RESU{number}_{j + 1}"
            loads.append((vector, history))
    return loads


def static_corrections(ctx, kw, basis, system) -> list[dict]:
    """EXCIT CORR_STAT='OUI' (code_aster's mdrecf): for occurrence i, the
    static response to the load (field i of MODE_CORR) minus what the modes
    already carry, ψ_i = u_i - Σ_m (F_m / k_m) φ_m, times FONC_MULT,
    D_FONC_DT and D_FONC_DT2 for the DEPL / VITE / ACCE fields that
    REST_GENE_PHYS and RECU_FONCTION add. The generalized load itself is
    not modified (the shocks see ψ_i FONC_MULT as a support motion)."""
    from asterlite.modal.renumber import transfer

    corrections = []
    occs = kw.factor("EXCIT")
    for index, occ in enumerate(occs):
        if occ.get("CORR_STAT") != "OUI":
            continue
        static = kw.get("MODE_CORR")
        if static is None:
            ctx.error("EXCIT CORR_STAT='OUI' needs MODE_CORR", "MODE_CORR", kw)
        if occ.get("VECT_ASSE_GENE") is None or occ.get("FONC_MULT") is None:
            ctx.error("CORR_STAT='OUI' needs VECT_ASSE_GENE and FONC_MULT", "CORR_STAT", occ)
        fields = getattr(static, "fields", None)
        if fields is None:
            fields = static.shapes
        fields = np.asarray(fields, dtype=float)
        if index >= fields.shape[1]:
            ctx.error(
                f"MODE_CORR holds {fields.shape[1]} fields, EXCIT occurrence {index + 1} "
                "needs its own (code_aster pairs them by position)",
                "MODE_CORR",
                kw,
            )
        shape = transfer(fields[:, index], static.numbering, basis.numbering).copy()
        vector = np.asarray(occ["VECT_ASSE_GENE"].values, dtype=float)[: system.n_modes]
        stiffness = np.diag(system.stiffness)
        shapes = np.asarray(basis.shapes, dtype=float)
        for m in range(system.n_modes):
            shape -= vector[m] / stiffness[m] * shapes[:, m]
        corrections.append(
            {
                "shape": shape,
                "DEPL": occ["FONC_MULT"],
                "VITE": occ["D_FONC_DT"],
                "ACCE": occ["D_FONC_DT2"],
            }
        )
    return corrections


def restart_acceleration(kw, t_state):
    """The archived acceleration at the ETAT_INIT instant of a RESULTAT, or None."""
    occs = kw.factor("ETAT_INIT")
    previous = occs[0].get("RESULTAT") if occs else None
    if previous is None or t_state is None:
        return None
    k = int(np.argmin(np.abs(previous.times - t_state)))
    return np.array(previous.acce[k], dtype=float)


def rotating_matrices(ctx, kw, system, t0, t_end, dt):
    """VITESSE_VARIABLE='OUI': C + Ω(t) G and K + Ω'(t) K_gy (or None)."""
    if kw.get("VITESSE_VARIABLE", "NON") != "OUI":
        return None
    from asterlite.dynamics.rotation import Rotation

    n = system.n_modes
    gyro = np.array(kw["MATR_GYRO"].matrix, dtype=float)
    rigy = kw.get("MATR_RIGY")
    rigy = np.array(rigy.matrix, dtype=float) if rigy is not None else np.zeros((n, n))
    for name, matrix in (("MATR_GYRO", gyro), ("MATR_RIGY", rigy)):
        if matrix.shape != (n, n):
            ctx.error(f"{name} is {matrix.shape}, the system has {n} modes", name, kw)
    # code_aster (dtmupmat): a damping given per mode (AMOR_DIA: AMOR_MODAL, or a
    # MATR_AMOR stored DIAG) becomes M diag(c_i / m_i) there, the transpose of the
    # diag(c_i / m_i) M its constant-speed path applies (dtmacce); a full MATR_AMOR
    # is used as it is
    damping = system.damping
    if system.damping_rates is not None:
        damping = system.mass * system.damping_rates[None, :]
    # without ACCE_ROTA code_aster takes Ω' = 0 (and then ignores MATR_RIGY)
    acceleration = kw.get("ACCE_ROTA") if kw.get("MATR_RIGY") is not None else None
    rotation = Rotation(damping, system.stiffness, gyro, rigy, kw["VITE_ROTA"], acceleration)
    rotation.tabulate(t0, t_end, dt / 2.0)
    return rotation


def support_motions(ctx, kw, basis) -> list[dict]:
    """MULT_APPUI supports: ψ = Σ_nodes Σ_c DIRECTION_c · (static mode of the
    node's component c) on the basis DOFs, with the support's DEPL / VITE /
    ACCE functions (REST_GENE_PHYS adds Σ ψ_k d_k(t) for absolute motion)."""
    supports = []
    kw.mark_used("MODE_STAT")  # support_shape reads it: code_aster uses it for MULT_APPUI only
    for occ in kw.factor("EXCIT"):
        if occ.get("MULT_APPUI") != "OUI":
            # without MULT_APPUI, code_aster (mdrecf) reads neither VITE nor DEPL:
            # ACCE alone multiplies the load vector
            occ.mark_used("VITE", "DEPL")
            continue
        shape = support_shape(ctx, kw, occ)
        supports.append(
            {"shape": shape, "DEPL": occ["DEPL"], "VITE": occ["VITE"], "ACCE": occ["ACCE"]}
        )
    return supports


def shock_support_shapes(shocks, basis, supports) -> np.ndarray:
    """ψ_k at each shock node: (n_shocks, 2, 3, n_supports)."""
    out = np.zeros((shocks.count, 2, 3, len(supports)))
    numbering = basis.numbering
    for s, spec in enumerate(shocks.specs):
        for j, node in enumerate((spec.node_1, spec.node_2)):
            if node is None:
                continue
            for c, comp in enumerate(COMPONENTS):
                try:
                    row = numbering.dof_index(node, comp)
                except KeyError:
                    continue
                for k, support in enumerate(supports):
                    out[s, j, c, k] = support["shape"][row]
    return out


# ----------------------------------------------------------------------------- result


def shock_histories(shocks, vint) -> list[ShockHistory]:
    """Archived local quantities, named as code_aster's NOEUD_CHOC parameters."""
    histories = []
    for s, spec in enumerate(shocks.specs):
        v = vint[:, s, :]
        if spec.relation != "DIS_CHOC":  # a relation of asterlite.dynamics.laws
            from asterlite.dynamics.laws.connections import law_fields

            fields = law_fields(spec.relation, v)
            histories.append(
                ShockHistory(
                    name=spec.name,
                    relation=spec.relation,
                    node_1=spec.node_1,
                    node_2=spec.node_2,
                    fields={k: np.ascontiguousarray(a) for k, a in fields.items()},
                    parameters=shocks.parameters(s),
                )
            )
            continue
        # each named column is copied from the archive when first read
        named = {
            "FN": C.V_FN,
            "FT1": C.V_FT1,
            "FT2": C.V_FT2,
            "DXLOC": C.V_LOC1,
            "DYLOC": C.V_LOC1 + 1,
            "DZLOC": C.V_LOC1 + 2,
            "DXLOC_2": C.V_LOC2,
            "DYLOC_2": C.V_LOC2 + 1,
            "DZLOC_2": C.V_LOC2 + 2,
            "VN": C.V_VN,
            "VT1": C.V_VT1,
            "VT2": C.V_VT2,
            "ADHERENCE": C.V_STICK,
        }
        recipes = {name: archived_column(v, j) for name, j in named.items()}
        two = spec.node_2 is not None and spec.obstacle_type.startswith("BI_")
        for axis, i in (("X", 0), ("Y", 1), ("Z", 2)):
            recipes[f"D{axis}REL"] = column_difference(
                v, C.V_LOC1 + i, C.V_LOC2 + i if two else None
            )
        for i in range(C.N_VINT):
            recipes[f"VINT{i + 1}"] = archived_column(v, i)
        histories.append(
            ShockHistory(
                name=spec.name,
                relation="DIS_CHOC",
                node_1=spec.node_1,
                node_2=spec.node_2,
                fields=ArchivedFields(recipes),
                parameters=shocks.parameters(s),
            )
        )
    return histories


__all__ = ["run", "math"]


def check_basis_for_shocks(ctx, kw, specs, basis, system) -> None:
    """VERI_CHOC: warn, or stop with STOP_CRITERE='OUI', when the basis misses
    too much of a shock node's static compliance (asterlite.dynamics.basis_check)."""
    from asterlite.dynamics.basis_check import node_checks

    occ = kw.factor("VERI_CHOC")[0]
    stop = occ["STOP_CRITERE"] == "OUI"
    if getattr(basis, "stiffness", None) is None:  # also a mode_gene (no physical matrices)
        ctx.unsupported("VERI_CHOC on a basis without its assembled stiffness", "VERI_CHOC", kw)
    checks = node_checks(specs, basis, np.diag(system.stiffness))
    for check in checks:
        ctx.log(
            f"VERI_CHOC {check.shock} node {check.node}: static flexibility "
            f"{check.static_flexibility:.4g}, restitution by the modes {check.restitution:.4f}, "
            f"criterion {check.criterion:.4g}"
        )
    worst = max((c.criterion for c in checks), default=0.0)
    if worst > occ["SEUIL"]:
        message = (
            f"the modal basis misses the static deflection of a shock node: criterion "
            f"{worst:.4g} > SEUIL {occ['SEUIL']:g} (add modes or static modes at the shock nodes)"
        )
        if stop:
            ctx.error(message, "VERI_CHOC", kw)
        ctx.log(f"warning: {message}")


def support_shape(ctx, kw, occ) -> np.ndarray:
    """Static shape of one EXCIT support (MULT_APPUI): Σ of MODE_STAT's modes
    at its nodes along DIRECTION, on MODE_STAT's numbering."""
    static = kw.get("MODE_STAT")
    if static is None:
        ctx.error("EXCIT MULT_APPUI='OUI' needs MODE_STAT", "MODE_STAT", kw)
    mesh = static.numbering.mesh
    nodes = []
    for group in as_tuple(occ.get("GROUP_NO")):
        if group not in mesh.node_groups:
            ctx.error(missing_name("node group", group, mesh.node_groups), "GROUP_NO", occ)
        nodes.extend(int(n) for n in mesh.node_groups[group])
    for name in as_tuple(occ.get("NOEUD")):
        index = mesh.find_node(name)
        if index is None:
            ctx.error(f"no node {name!r} in the mesh", "NOEUD", occ)
        nodes.append(index)
    direction = np.asarray(as_tuple(occ.get("DIRECTION")) or (1.0, 0.0, 0.0), dtype=float)
    try:
        return combined_static_shape(static, [mesh.node_names[n] for n in nodes], direction)
    except SeismicError as error:
        ctx.error(f"MODE_STAT: {error}", "MODE_STAT", kw)
