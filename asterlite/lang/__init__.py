"""The deck language: a lark grammar for the Python subset decks use, and a
safe tree-walking evaluator. Importing this package loads no numerical stack."""

from asterlite.lang.values import (
    CO,
    CallSite,
    DeckCallable,
    FactorDict,
    Unknown,
    is_unknown,
)

__all__ = ["CO", "CallSite", "DeckCallable", "FactorDict", "Unknown", "is_unknown"]
