"""DYNA_VIBRA TYPE_CALCUL='TRAN', BASE_CALCUL='GENE' as a typed problem.

:func:`build_problem` reads the validated keywords once and returns a
:class:`TransientProblem`: the linear system, the shocks and other
relations, the loads, the scheme (its description in
:mod:`asterlite.dynamics.schemes`) and its options, the time grid, the
archiving and the outputs asked for. ``asterlite.dynamics`` receives what
it holds and never a keyword; the command (``commands/dyna_vibra.py``)
integrates it and binds the result.
"""

from __future__ import annotations

from dataclasses import dataclass, replace
from typing import TYPE_CHECKING

import numpy as np
from asterlite.catalogues.dyna_vibra import DYNA_VIBRA
from asterlite.commands.dyna_vibra_keywords import first_value
from asterlite.commands.dyna_vibra_loads import (
    excitations,
    linear_system,
    load_labels,
    rotating_matrices,
    shock_support_shapes,
    static_corrections,
    support_motions,
)
from asterlite.commands.dyna_vibra_shocks import (
    check_basis_for_shocks,
    continue_law_states,
    fluid_film,
    implicit_shocks,
    legacy_tangential_damping,
    refuse_moving_gaps,
    shock_specs,
    warn_lagged_shocks,
)
from asterlite.commands.dyna_vibra_time import (
    archiving,
    checked_step,
    initial_state,
    legacy_adapt_step_max,
    restart_acceleration,
    time_span,
)

from asterlite.catalog.keywords import Keywords
from asterlite.catalog.validator import validate_factor
from asterlite.concepts.titles import unique_titles
from asterlite.dynamics.excitation import Excitation, tabulate_excitation
from asterlite.dynamics.integrate import SchemeOptions
from asterlite.dynamics.model import LinearSystem, ShockSet, build_shocks
from asterlite.dynamics.schemes import SCHEMES, Scheme
from asterlite.legacy.v15 import computes

if TYPE_CHECKING:
    from asterlite.dynamics.fluid_film import FluidFilm


@dataclass(frozen=True)
class TimeGrid:
    """INCREMENT, with ETAT_INIT's instant: from ``start`` to ``end`` by
    ``step`` (checked by VERI_PAS)."""

    start: float
    end: float
    step: float


@dataclass(frozen=True)
class Archiving:
    """ARCHIVAGE: the instants the run lands on and the period in steps."""

    instants: np.ndarray
    period: int


@dataclass(frozen=True)
class InitialState:
    """ETAT_INIT: generalized displacement and velocity, and the instant of
    the previous result they come from (None: given vectors or rest)."""

    displacement: np.ndarray
    velocity: np.ndarray
    time: float | None


@dataclass(frozen=True)
class TransientProblem:
    """Everything a GENE transient integrates, read from the keywords."""

    scheme: Scheme
    options: SchemeOptions
    basis: object  # the modal basis of the generalized matrices
    system: LinearSystem
    shocks: ShockSet  # DIS_CHOC and the relations of dynamics.laws, in COMPORTEMENT order
    film: FluidFilm | None  # LAME_FLUIDE (code_aster 10-14 decks)
    implicit: bool  # TRAITEMENT_NONL='IMPLICITE' with DIS_CHOC shocks
    excitation: Excitation  # EXCIT, EXCIT_RESU, and the support motions the shocks see
    load_labels: tuple[str, ...]  # how the deck names each load row
    supports: tuple[dict, ...]  # MULT_APPUI supports (shape, DEPL, VITE, ACCE)
    corrections: tuple[dict, ...]  # CORR_STAT static corrections
    rotation: object | None  # VITESSE_VARIABLE='OUI': dynamics.rotation.Rotation
    initial: InitialState
    grid: TimeGrid
    archive: Archiving
    energy: bool  # ENERGIE: the energy balance (asterlite extension on GENE)
    step_bounds: tuple[float | None, float | None]  # the deck's PAS_MINI, PAS_MAXI


def build_problem(ctx, kw) -> TransientProblem:
    """The typed problem of a validated DYNA_VIBRA TRAN/GENE call; refuses
    by name what asterlite does not integrate."""
    if kw.get("BASE_ELAS_FLUI"):
        ctx.unsupported("BASE_ELAS_FLUI is not implemented", "BASE_ELAS_FLUI", kw)
    [schema_kw] = kw.factor("SCHEMA_TEMPS")  # statut 'd': always there, defaults filled
    scheme = schema_kw["SCHEMA"]
    if scheme not in SCHEMES:
        ctx.unsupported(
            f"SCHEMA={scheme!r} (implemented: {', '.join(SCHEMES)})", "SCHEMA", schema_kw
        )
    entry = SCHEMES[scheme]
    if kw.get("VITESSE_VARIABLE") == "OUI" and not entry.shared_loops:
        rotating = [s.name for s in SCHEMES.values() if s.shared_loops]
        ctx.unsupported(
            f"VITESSE_VARIABLE='OUI' with SCHEMA={scheme!r} (implemented: {', '.join(rotating)})",
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
    specs, occurrences = relations(ctx, kw, basis, system)
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
    options = scheme_options(ctx, entry, schema_kw)
    if options.adapt_v11 and options.dt_max is None:
        options = replace(options, dt_max=legacy_adapt_step_max(ctx, system, shocks))
    return TransientProblem(
        scheme=entry,
        options=options,
        basis=basis,
        system=system,
        shocks=shocks,
        film=film,
        implicit=implicit,
        excitation=excitation,
        load_labels=tuple(load_labels(kw, len(loads))),
        supports=tuple(supports),
        corrections=tuple(corrections),
        rotation=rotation,
        initial=InitialState(q0, v0, t_init_state),
        grid=TimeGrid(t0, t_end, dt),
        archive=Archiving(instants, pas_arch),
        energy=energy,
        step_bounds=(schema_kw.get("PAS_MINI"), schema_kw.get("PAS_MAXI")),
    )


def relations(ctx, kw, basis, system):
    """(shock specifications, the COMPORTEMENT occurrence of each): DIS_CHOC
    occurrences give one shock per node pair, the other relations one row
    each (``asterlite.dynamics.laws``); each gets a name of its own."""
    specs = []
    occurrences = []  # the COMPORTEMENT occurrence of each shock (fluid films)
    for rank, occ in enumerate(kw.factor("COMPORTEMENT"), start=1):
        if occ.get("RELATION") != "DIS_CHOC":  # a relation of asterlite.dynamics.laws
            # the relations' readers and laws: imported for the decks that have one
            from asterlite.commands.dyna_vibra_relations import nonlinearity_spec

            found = [nonlinearity_spec(ctx, kw, occ, basis, system.n_modes, len(specs) + 1)]
        else:
            found = shock_specs(ctx, occ, basis, system.n_modes, first=len(specs) + 1)
        for spec in found:
            spec.source = f"COMPORTEMENT[{rank}]"  # where a failure message points
        specs.extend(found)
        occurrences.extend([occ] * len(found))
    for spec, title in zip(specs, unique_titles([s.name for s in specs]), strict=True):
        spec.name = title  # one name per shock (asterlite.concepts.titles)
    return specs, occurrences


# SCHEMA_TEMPS keywords -> SchemeOptions fields, and how the value is read
# (None: as validated). The catalogue fills the defaults of the scheme's BLOC;
# a keyword of another scheme's BLOC is absent and its field is None, which
# the scheme does not read.
OPTION_KEYWORDS = {
    "TOLERANCE": ("tolerance", None),
    "ALPHA": ("alpha", None),
    "PAS_MINI": ("dt_min", None),
    "PAS_MAXI": ("dt_max", None),
    "BETA": ("beta", None),
    "GAMMA": ("gamma", None),
    "NMAX_ITER_PAS": ("nmax_iter_pas", int),
    "VITE_MIN": ("vite_min", first_value),
    "COEF_MULT_PAS": ("coef_mult_pas", None),
    "COEF_DIVI_PAS": ("coef_divi_pas", None),
    "PAS_LIMI_RELA": ("pas_limi_rela", None),
    "NB_POIN_PERIODE": ("nb_poin_periode", int),
}


def scheme_options(ctx, entry: Scheme, schema_kw) -> SchemeOptions:
    """SCHEMA_TEMPS's parameters of the scheme, and the behaviours of the
    deck's code_aster version (asterlite.legacy.v15.OLD_BEHAVIOURS); an
    archive past its memory budget goes to the run's folder."""
    options = options_from_schema(
        schema_kw,
        force_at_step_start=computes(ctx.session, "NEWMARK_FORCE_AT_STEP_START"),
        adapt_v11=entry.legacy_module is not None and computes(ctx.session, "ADAPT_ORDRE2_MDADAP"),
    )
    return replace(options, archive_folder=getattr(ctx.session, "output_dir", None))


def options_from_schema(
    schema_kw, force_at_step_start: bool = False, adapt_v11: bool = False
) -> SchemeOptions:
    """The :class:`SchemeOptions` of a validated SCHEMA_TEMPS occurrence
    (today's behaviours unless the flags say otherwise)."""
    values = {}
    for keyword, (field, read) in OPTION_KEYWORDS.items():
        value = schema_kw.get(keyword)
        values[field] = value if value is None or read is None else read(value)
    return SchemeOptions(**values, force_at_step_start=force_at_step_start, adapt_v11=adapt_v11)


def catalogue_options(scheme: str, **given) -> SchemeOptions:
    """The options of ``SCHEMA_TEMPS=_F(SCHEMA=scheme, **given)`` on the
    generalized basis, validated by DYNA_VIBRA's catalogue (its defaults
    filled): for the callers of the engine that have no deck (benchmarks,
    tests)."""
    fact = DYNA_VIBRA.entries["b_schema_gene"].entries["SCHEMA_TEMPS"]
    [occurrence] = validate_factor(
        fact, [{"SCHEMA": scheme, **given}], Keywords(path="DYNA_VIBRA"), "SCHEMA_TEMPS", {}
    )
    return options_from_schema(occurrence)
