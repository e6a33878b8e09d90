"""Command catalogues in code_aster's vocabulary, and the call validator.

Catalogue files (``catalogues/<command>.py``) build their command with
``OPER``/``PROC``/``MACRO``, ``SIMP``, ``FACT``, ``BLOC``, the rules and the
condition helpers; the runtime calls :func:`validate` to turn a deck call
into :class:`Keywords` and :func:`result_type` for the produced type.
Nothing here imports numpy: ``asterlite check`` must start quickly.
"""

from asterlite.catalog.conditions import (
    Condition,
    absent,
    equal_to,
    exists,
    greater_than,
    is_in,
    less_than,
)
from asterlite.catalog.keywords import Keywords
from asterlite.catalog.loader import load_catalogue
from asterlite.catalog.model import BLOC, FACT, MACRO, OPER, PROC, SIMP, Command
from asterlite.catalog.rules import (
    AU_MOINS_UN,
    ENSEMBLE,
    EXCLUS,
    PRESENT_ABSENT,
    PRESENT_PRESENT,
    TOUT_OU_RIEN,
    UN_PARMI,
    Rule,
)
from asterlite.catalog.validator import result_type, validate

__all__ = [
    "AU_MOINS_UN",
    "BLOC",
    "ENSEMBLE",
    "EXCLUS",
    "FACT",
    "MACRO",
    "OPER",
    "PRESENT_ABSENT",
    "PRESENT_PRESENT",
    "PROC",
    "SIMP",
    "TOUT_OU_RIEN",
    "UN_PARMI",
    "Command",
    "Condition",
    "Keywords",
    "Rule",
    "absent",
    "equal_to",
    "exists",
    "greater_than",
    "is_in",
    "less_than",
    "load_catalogue",
    "result_type",
    "validate",
]
