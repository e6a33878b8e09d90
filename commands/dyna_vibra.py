"""DYNA_VIBRA, TYPE_CALCUL='TRAN', BASE_CALCUL='GENE': transient analysis by
modal recombination with DIS_CHOC shock and friction connections.

The command builds the typed problem (``dyna_vibra_problem``: keywords read
once, by the modules ``dyna_vibra_loads``, ``dyna_vibra_shocks`` and
``dyna_vibra_time``), integrates it (``asterlite.dynamics``, which sees no
keyword) and binds the ``TranGene`` (``dyna_vibra_result``). The harmonic
and physical forms are ``dyna_vibra_harm`` and ``dyna_vibra_phys``.
"""

from __future__ import annotations

from asterlite.commands.dyna_vibra_problem import TransientProblem, build_problem
from asterlite.commands.dyna_vibra_result import appended, impression, shock_histories
from asterlite.commands.dyna_vibra_shocks import refuse_with_film
from asterlite.commands.dyna_vibra_words import TRANSIENT

from asterlite.concepts.transient import TranGene
from asterlite.dynamics.integrate import RunResult, integrate
from asterlite.dynamics.kernel import INFO_REJECTED, INFO_STEP
from asterlite.errors import NumericalError


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
    problem = build_problem(ctx, kw)
    if problem.film is not None:  # what the film loop does not combine with
        driven = problem.supports + problem.corrections
        refuse_with_film(ctx, kw, problem.implicit, problem.rotation, problem.energy, driven)
    result = integrated(ctx, problem)
    log_run(ctx, problem, result)
    return bound(ctx, kw, problem, result)


def integrated(ctx, problem: TransientProblem) -> RunResult:
    """The run of ``problem``; a numerical failure located at the command."""
    p, grid, archive = problem, problem.grid, problem.archive
    scheme, options = p.scheme.name, p.options
    try:
        if p.film is not None:  # CHOC/LAME_FLUIDE of code_aster 10-14 decks
            from asterlite.dynamics.fluid_film import integrate_film

            film_scheme = "ADAPT_ORDRE2" if options.adapt_v11 else "EULER"
            return integrate_film(
                p.system, p.shocks, p.film, p.excitation, p.initial.displacement,
                p.initial.velocity, grid.start, grid.end, grid.step, archive.instants,
                archive.period, options,
                label=f"DYNA_VIBRA {ctx.result_name or ''} {film_scheme} (LAME_FLUIDE)",
            )  # fmt: skip
        return integrate(
            p.system, p.shocks, p.excitation, scheme, p.initial.displacement,
            p.initial.velocity, grid.start, grid.end, grid.step, archive.instants,
            archive.period, options, rotation=p.rotation,
            label=f"DYNA_VIBRA {ctx.result_name or ''} {scheme}".replace("  ", " "),
            energy=p.energy, implicit_shocks=p.implicit, load_labels=list(p.load_labels),
        )  # fmt: skip
    except NumericalError as error:  # worded with the deck's keywords
        error = error.worded(TRANSIENT)
        path = f"{ctx.command}/{error.path}" if error.path else ctx.command
        raise NumericalError(error.message, ctx.location, path) from None


def log_run(ctx, problem: TransientProblem, result: RunResult) -> None:
    """The run's summary in the message log, and what the deck should know."""
    info = result.info
    ctx.log(
        f"DYNA_VIBRA {problem.scheme.name}: {info['steps']} steps "
        f"({info['rejected_steps']} rejected), "
        f"{info['archived']} archived, step {info['min_step']:.3g}"
        f"..{info['max_step']:.3g}, {info['integration_seconds']:.3f} s"
    )
    if info.get("archive_on_disk"):
        ctx.log(
            f"archive of {info['archived']} instants past its memory budget: written to "
            "disk while the loop ran, read from there (asterlite.dynamics.archive_store)"
        )
    if problem.implicit:
        ctx.log(
            f"TRAITEMENT_NONL='IMPLICITE': {info['contact_switches']} contact switches, "
            f"{info['reintegrated_steps']} steps integrated again up to a switch, "
            f"{info['relinearisations']} linearisations about a contact point that moved"
        )
    kept = info.get("steps_kept_at_nmax_iter_pas", 0)
    if kept:
        ctx.log(
            f"warning: {kept} steps kept after NMAX_ITER_PAS trials without reaching "
            "the apparent-frequency criterion (code_aster's DYNAMIQUE_18)"
        )


def bound(ctx, kw, problem: TransientProblem, result: RunResult) -> TranGene:
    """The ``TranGene`` of the run, appended to the reused result when the
    run continues it (ETAT_INIT RESULTAT with reuse=), with its energy
    table and its IMPRESSION listings."""
    info = result.info
    # the deck's step bounds (asterlite sensitivity moves them with PAS when equal to it)
    info["pas_mini"], info["pas_maxi"] = problem.step_bounds
    if problem.supports:
        info["mult_appui"] = list(problem.supports)
    if problem.corrections:
        info["corr_stat"] = list(problem.corrections)
    produced = TranGene(
        basis=problem.basis,
        times=result.times,
        order=result.order,
        depl=result.depl,
        vite=result.vite,
        acce=result.acce,
        shocks=shock_histories(problem.shocks, result.vint),
        scheme=problem.scheme.name,
        step=problem.grid.step,
        info=info,
        step_sizes=result.step_info[:, INFO_STEP],
        rejections=result.step_info[:, INFO_REJECTED],
    )
    reused = getattr(ctx, "reuse", None)
    continued = isinstance(reused, TranGene) and problem.initial.time is not None
    if result.energy is not None:
        from asterlite.dynamics import energy as E

        previous = reused.tables.get("PARA_CALC") if continued else None
        produced.tables["PARA_CALC"] = E.table(result.energy, previous, problem.grid.start)
        produced.info.update(E.summary(result.energy))
    final = produced
    if continued:
        final = appended(reused, produced)
        final.tables.update(produced.tables)
    name = (reused.name if continued else None) or ctx.result_name or ""
    impression(ctx, kw, final, name, problem.shocks.specs, problem.system)
    return final


__all__ = ["run"]
