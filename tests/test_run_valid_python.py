"""``run`` never calls valid Python wrong: Python that asterlite's deck
parser or evaluator refuses by design (a class, a module it does not
provide) stops the run UNSUPPORTED, with the deck's file and line; what
Python itself would refuse (an undefined name, a syntax error) stays an
ERROR."""

from __future__ import annotations

from pathlib import Path

import pytest

from asterlite.runtime.runner import run_deck


def _run(tmp_path: Path, statement: str):
    deck = tmp_path / "study.comm"
    deck.write_text(f"DEBUT()\n{statement}\nFIN()\n")
    return run_deck(deck, tmp_path / "out", aster_version=17)


@pytest.mark.parametrize(
    ("statement", "why"),
    [
        ("import json", "a module asterlite does not provide"),
        ("class Probe:\n    pass", "a construct asterlite's deck parser does not take"),
        ("global X", "a construct asterlite's deck parser does not take"),
    ],
)
def test_valid_python_asterlite_refuses_is_unsupported(tmp_path, statement, why):
    report = _run(tmp_path, statement)
    assert report.status == "UNSUPPORTED", report.message
    assert "study.comm:2:" in report.message and why in report.message


@pytest.mark.parametrize(
    ("statement", "what"),
    [
        ("X = UNDEFINED_NAME + 1", "UNDEFINED_NAME"),
        ("X = (1,", "syntax error"),
        ("X = 1 / 0", "division"),
    ],
)
def test_what_python_refuses_stays_an_error(tmp_path, statement, what):
    report = _run(tmp_path, statement)
    assert report.status == "ERROR", report.message
    assert what in report.message
