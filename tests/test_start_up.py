"""Warm start-up (issue 16, goal 2): a run parses its deck once, however
many readers (version detection, code_aster 15 names, the session) ask."""

from __future__ import annotations

import pytest

from asterlite.errors import DeckSyntaxError
from asterlite.lang import parse_deck
from asterlite.lang import parser as P


def test_the_same_text_is_parsed_once_and_located_per_caller(monkeypatch):
    calls = []
    real = P._parse_text
    monkeypatch.setattr(P, "_parse_text", lambda *a: calls.append(a) or real(*a))
    text = "A = 1.0\nB = A + 2\n"
    first = parse_deck(text, "one.comm")
    second = parse_deck(text, "two.comm")
    assert len(calls) == 1 and second.tree is first.tree
    assert (first.filename, second.filename) == ("one.comm", "two.comm")
    assert second.location(2).file == "two.comm"
    parse_deck(text + "C = 3\n", "one.comm")
    assert len(calls) == 2


def test_a_syntax_error_is_raised_every_time():
    for name in ("a.comm", "b.comm"):
        with pytest.raises(DeckSyntaxError) as error:
            parse_deck("A = (1,\n", name)
        assert error.value.location.file == name
