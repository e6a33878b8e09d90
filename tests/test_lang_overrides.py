"""Overrides of deck-level variables (``asterlite sweep --set NAME=value``).

A plain module-level ``NAME = expression`` binds the override instead of the
expression's value; the expression is still evaluated for its side effects.
"""

from __future__ import annotations

from pathlib import Path

import pytest

from asterlite.errors import DeckRuntimeError
from asterlite.lang import DeckCallable, Evaluator, base_namespace, parse_deck
from asterlite.runtime.runner import run_deck

SAMPLE = Path(__file__).resolve().parent.parent / "samples" / "friction_oscillator"


def run(text: str, overrides: dict, namespace: dict | None = None) -> tuple[dict, Evaluator]:
    namespace = base_namespace() if namespace is None else namespace
    evaluator = Evaluator(namespace, overrides=overrides)
    evaluator.run(parse_deck(text, "deck.comm"))
    return namespace, evaluator


class Counting(DeckCallable):
    """A command stand-in that counts its calls and returns a marker."""

    def __init__(self):
        self.calls = 0

    def deck_call(self, args, kwargs, site):
        self.calls += 1
        return "computed"


def test_module_assignment_binds_the_override_and_later_statements_see_it():
    names, evaluator = run("MU = 0.15\nF = MU * 10\n", {"MU": 0.3})
    assert names["MU"] == 0.3
    assert names["F"] == pytest.approx(3.0)
    assert evaluator.overrides_used == {"MU"}


def test_names_without_override_keep_their_value():
    names, evaluator = run("MU = 0.15\nK = 2\n", {"MU": 0.3})
    assert names["K"] == 2
    assert evaluator.overrides_used == {"MU"}


def test_the_right_hand_side_is_still_evaluated_for_its_side_effects():
    command = Counting()
    namespace = base_namespace()
    namespace["CMD"] = command
    names, _ = run("X = CMD(A=1)\n", {"X": 5}, namespace)
    assert command.calls == 1
    assert names["X"] == 5


def test_an_error_in_the_right_hand_side_is_still_reported():
    with pytest.raises(DeckRuntimeError, match="not defined"):
        run("MU = UNDEFINED_NAME\n", {"MU": 0.3})


def test_chained_targets_and_module_level_blocks_are_overridden():
    names, _ = run("A = B = 1\nif True:\n    C = 2\n", {"B": 7, "C": 8})
    assert (names["A"], names["B"], names["C"]) == (1, 7, 8)


def test_function_locals_loops_unpacking_and_augmented_assignment_are_left_alone():
    text = (
        "def f():\n"
        "    MU = 1\n"
        "    return MU\n"
        "Y = f()\n"
        "for I in (1, 2):\n"
        "    pass\n"
        "P, Q = 1, 2\n"
        "R = 1\n"
        "R += 1\n"
    )
    names, evaluator = run(text, {"MU": 9, "I": 9, "P": 9, "R": 10})
    assert names["Y"] == 1
    assert names["I"] == 2
    assert names["P"] == 1
    assert names["R"] == 11  # the override, then the deck's own increment
    assert evaluator.overrides_used == {"R"}


def test_no_overrides_changes_nothing():
    names, evaluator = run("MU = 0.15\n", {})
    assert names["MU"] == 0.15
    assert evaluator.overrides_used == set()


# --------------------------------------------------- through run_deck (check mode)


def test_run_deck_records_the_overrides_used():
    report = run_deck(SAMPLE / "friction_oscillator.export", check_only=True, overrides={"MU": 0.2})
    assert report.status == "CHECKED"
    assert report.overrides_used == ["MU"]
    assert report.as_dict()["overrides"] == {"MU": 0.2}


def test_run_deck_rejects_a_name_the_deck_never_assigns():
    report = run_deck(SAMPLE / "friction_oscillator.export", check_only=True, overrides={"MU2": 1})
    assert report.status == "ERROR"
    assert report.exit_code == 2
    assert report.unknown_overrides == ["MU2"]
    assert "MU2" in report.message and "did you mean MU?" in report.message
