"""Occurrences of DYNA_VIBRA's factor keywords as the command receives them.

The DYNA_VIBRA wing reads validated occurrences only: the catalogue fills
the defaults it declares, the readers restate none. A test that calls a
reader gives it a plain dict through :func:`occurrence`, which validates it
against the catalogue as a call does (one place for every such test).
"""

from __future__ import annotations

from asterlite.catalogues.dyna_vibra import DYNA_VIBRA

from asterlite.catalog.keywords import Keywords
from asterlite.catalog.model import BLOC, FACT
from asterlite.catalog.validator import validate_factor


def factor(name: str, level=DYNA_VIBRA, block: str | None = None) -> FACT:
    """The factor keyword ``name`` of the catalogue, in whichever block or,
    for a keyword several blocks define alike-named (EXCIT_RESU), in the
    block named ``block``."""
    for key, entry in level.entries.items():
        if isinstance(entry, BLOC):
            inner = None if block == key else block
            found = factor_or_none(name, entry, inner)
            if found is not None:
                return found
        elif key == name and isinstance(entry, FACT) and block is None:
            return entry
    raise KeyError(f"DYNA_VIBRA has no factor keyword {name}")


def factor_or_none(name: str, level, block: str | None = None) -> FACT | None:
    try:
        return factor(name, level, block)
    except KeyError:
        return None


def occurrence(name: str, values: dict | None = None, block: str | None = None, **more):
    """One occurrence of DYNA_VIBRA's factor keyword ``name`` (of the block
    named ``block`` if given) holding ``values``, validated as a call
    validates it (defaults filled)."""
    given = {**(values or {}), **more}
    [validated] = validate_factor(
        factor(name, block=block), [given], Keywords(path="DYNA_VIBRA"), name, context={}
    )
    return validated


def relation(name: str, values: dict | None = None, **more) -> Keywords:
    """A COMPORTEMENT occurrence of relation ``name`` holding ``values``,
    validated: the nodes its reader does not read default to N1 (and N2
    for a second node), and a law's own ``Curve`` is given as the
    DEFI_FONCTION concept a deck would give."""
    from asterlite.commands.dyna_vibra_relations import READERS

    given = {key: as_concept(value) for key, value in {**(values or {}), **more}.items()}
    for (node, group), default in zip(READERS[name].ends, ("N1", "N2"), strict=False):
        if node not in given and group not in given:
            given[node] = default
    if READERS[name].obstacle:  # FLAMBAGE's obstacle, which its law does not read
        given.setdefault("OBSTACLE", plane_obstacle())
        given.setdefault("NORM_OBST", (0.0, 1.0, 0.0))
    return occurrence("COMPORTEMENT", {"RELATION": name, **given})


def plane_obstacle():
    """A PLAN_Y obstacle, as DEFI_OBSTACLE gives it."""
    from asterlite.catalogues.defi_obstacle import DEFI_OBSTACLE
    from asterlite.commands import defi_obstacle

    from asterlite.catalog.validator import validate
    from asterlite.runtime.context import CommandContext

    class Session:
        def log(self, text):
            pass

    context = CommandContext(session=Session(), command="DEFI_OBSTACLE")
    return defi_obstacle.run(context, validate(DEFI_OBSTACLE, {"TYPE": "PLAN_Y"}))


def as_concept(value):
    """A ``laws.tabulated.Curve`` as a DEFI_FONCTION concept; anything else as is."""
    from asterlite.concepts.function import Function
    from asterlite.dynamics.laws.tabulated import Curve

    if not isinstance(value, Curve):
        return value
    return Function(
        abscissas=value.abscissas,
        ordinates=value.ordinates,
        INTERPOL=value.INTERPOL,
        PROL_GAUCHE=value.PROL_GAUCHE,
        PROL_DROITE=value.PROL_DROITE,
    )


def scheme_options(scheme: str, **fields):
    """The engine's options of ``scheme`` as a call with no SCHEMA_TEMPS
    parameter gets them from the catalogue, then ``fields`` (SchemeOptions'
    names) set as a test needs them."""
    from dataclasses import replace

    from asterlite.commands.dyna_vibra_problem import catalogue_options

    return replace(catalogue_options(scheme), **fields)


def film_controls() -> tuple[int, float, float]:
    """The fluid film's iteration controls of an empty PARA_LAME_FLUI:
    at most, tolerance, relaxation."""
    controls = occurrence("PARA_LAME_FLUI")
    return controls["NMAX_ITER"], controls["RESI_RELA"], controls["LAMBDA"]
