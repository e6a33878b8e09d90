"""The keywords of DYNA_VIBRA behind the fields the dynamics room names.

A message of :mod:`asterlite.dynamics` names the problem's field a quantity
came from (``asterlite.errors.field("grid.step")``), never the keyword; the
DYNA_VIBRA wing words its errors and warnings with this vocabulary
(``error.worded(TRANSIENT)``, ``asterlite.errors.worded(text, TRANSIENT)``)
so that the user reads the keyword of the deck. A relation's own fields
are worded by its reader (``dyna_vibra_relations.Reader.words``).
"""

from __future__ import annotations

from collections.abc import Iterator
from contextlib import contextmanager

from asterlite.errors import AsterliteError

# field of the transient problem -> keyword path below DYNA_VIBRA
TRANSIENT = {
    "grid.step": "INCREMENT/PAS",
    "grid": "INCREMENT",
    "options.dt_min": "SCHEMA_TEMPS/PAS_MINI",
    "options.dt_max": "SCHEMA_TEMPS/PAS_MAXI",
    "options.tolerance": "SCHEMA_TEMPS/TOLERANCE",
    "options.alpha": "SCHEMA_TEMPS/ALPHA",
    "options.nmax_iter_pas": "SCHEMA_TEMPS/NMAX_ITER_PAS",
    "options.beta": "SCHEMA_TEMPS/BETA",
    "archive.period": "ARCHIVAGE/PAS_ARCH",
    "archive.instants": "ARCHIVAGE/LIST_INST",
    "archive": "ARCHIVAGE",
    "energy": "ENERGIE",
    "rotation.variable": "VITESSE_VARIABLE",
    "implicit": "TRAITEMENT_NONL",
    "excitation": "EXCIT",
    "excitation.function": "EXCIT/FONC_MULT",
    "excitation.coefficient": "EXCIT/COEF_MULT",
    "relations": "COMPORTEMENT",
    "relation.max_iterations": "COMPORTEMENT/ITER_INTE_MAXI",
    "relation.tolerance": "COMPORTEMENT/RESI_INTE",
    "film": "COMPORTEMENT/LAME_FLUIDE",
    "film.max_iterations": "PARA_LAME_FLUI/NMAX_ITER",
    "film.tolerance": "PARA_LAME_FLUI/RESI_RELA",
    "film.relaxation": "PARA_LAME_FLUI/LAMBDA",
}


@contextmanager
def transient_words() -> Iterator[None]:
    """An ``AsterliteError`` of the dynamics room raised inside, worded
    with the keywords of DYNA_VIBRA (its class, location unchanged)."""
    try:
        yield
    except AsterliteError as error:
        raise error.worded(TRANSIENT) from None
