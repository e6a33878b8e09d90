"""The deck language: a lark grammar for the Python subset decks use, and a
safe tree-walking evaluator. Importing this package loads no numerical stack."""

from asterlite.lang.evaluator import DeckFunction, Evaluator
from asterlite.lang.library import DeckModule, base_namespace
from asterlite.lang.limits import Limits
from asterlite.lang.parser import Module, parse_deck, parse_expression
from asterlite.lang.values import (
    CO,
    CallSite,
    DeckCallable,
    FactorDict,
    Unknown,
    is_unknown,
)

__all__ = [
    "CO",
    "CallSite",
    "DeckCallable",
    "DeckFunction",
    "DeckModule",
    "Evaluator",
    "FactorDict",
    "Limits",
    "Module",
    "Unknown",
    "base_namespace",
    "is_unknown",
    "parse_deck",
    "parse_expression",
]
