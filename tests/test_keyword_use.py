"""Every keyword a deck gives is used by its command or refused by name.

The validated keyword tree records what the command reads; after the
command returns, a keyword the deck wrote and the command never looked at
(unless the catalogue says it changes no result) stops the run as
UNSUPPORTED, located at that keyword.
"""

from __future__ import annotations

from pathlib import Path

import pytest

from asterlite.catalog import FACT, OPER, SIMP, validate
from asterlite.catalog.keywords import Keywords, unread_keywords
from asterlite.catalog.model import has_no_effect
from asterlite.runtime.runner import run_deck

CATALOGUE = OPER(
    nom="DEMO",
    sd_prod="table_sdaster",
    A=SIMP(statut="f", typ="R"),
    B=SIMP(statut="d", typ="R", defaut=2.0),
    QUIET=SIMP(statut="f", typ="TXM", no_effect="message file only"),
    INFO=SIMP(statut="f", typ="I"),
    OCC=FACT(statut="f", max="**", C=SIMP(statut="f", typ="R"), D=SIMP(statut="f", typ="R")),
)


def _validated(**given) -> Keywords:
    return validate(CATALOGUE, given)


def _unread_paths(keywords: Keywords) -> list[str]:
    return [level.where(name)[0] for level, name in unread_keywords(keywords)]


def test_given_keywords_are_recorded_apart_from_defaults():
    kw = _validated(A=1.0)
    assert kw.given == {"A"}
    assert "B" in dict.keys(kw)  # the default is filled in...
    assert _unread_paths(kw) == ["DEMO/A"]  # ...but only the given keyword is owed a read


def test_reads_by_item_get_contains_and_factor_count():
    kw = _validated(A=1.0, OCC=({"C": 1.0}, {"D": 2.0}))
    assert kw["A"] == 1.0
    assert _unread_paths(kw) == ["DEMO/OCC"]
    occurrences = kw.factor("OCC")
    assert _unread_paths(kw) == ["DEMO/OCC[1]/C", "DEMO/OCC[2]/D"]
    assert occurrences[0].get("C") == 1.0
    assert "D" in occurrences[1]
    assert _unread_paths(kw) == []


def test_iterating_a_level_reads_all_of_it():
    kw = _validated(A=1.0, OCC={"C": 1.0})
    dict(kw.items())
    occurrence = kw.factor("OCC")[0]
    list(occurrence.items())
    assert _unread_paths(kw) == []


def test_peek_and_plain_dict_access_do_not_count():
    kw = _validated(A=1.0)
    assert kw.peek("A") == 1.0
    assert dict.get(kw, "A") == 1.0
    assert _unread_paths(kw) == ["DEMO/A"]


def test_mark_used_counts_without_reading():
    kw = _validated(A=1.0, B=3.0)
    kw.mark_used("A", "B")
    assert _unread_paths(kw) == []


def test_copy_shares_the_reads():
    kw = _validated(A=1.0)
    kw.copy()["A"]
    assert _unread_paths(kw) == []


def test_no_effect_keywords_need_no_read():
    kw = _validated(QUIET="x", INFO=2)
    assert _unread_paths(kw) == []
    assert has_no_effect("INFO", CATALOGUE.entries["INFO"])
    assert not has_no_effect("A", CATALOGUE.entries["A"])


DECK = """\
DEBUT(CODE='OUI')
T = CREA_TABLE(LISTE=_F(PARA='X', LISTE_R=(1.0, 2.0)), {extra})
TEST_TABLE(TABLE=T, NOM_PARA='X', TYPE_TEST='MAX', VALE_CALC=2.0)
FIN()
"""


def _run(tmp_path: Path, extra: str):
    deck = tmp_path / "demo.comm"
    deck.write_text(DECK.format(extra=extra))
    return run_deck(deck, tmp_path / "out")


def test_an_unread_keyword_stops_the_run_located(tmp_path):
    report = _run(tmp_path, "TYPE_TABLE='TABLE'")
    assert report.status == "UNSUPPORTED", report.message
    assert "CREA_TABLE/TYPE_TABLE" in report.message
    assert "demo.comm:2" in report.message


def test_a_deck_using_every_keyword_passes(tmp_path):
    report = _run(tmp_path, "TITRE='a title'")
    assert report.status == "PASS", report.message


@pytest.mark.parametrize("name", ["INFO"])
def test_no_effect_anywhere_names_are_documented(name):
    from asterlite.catalog.model import NO_EFFECT_ANYWHERE

    assert NO_EFFECT_ANYWHERE[name]


# --- the corpora: what a deck gives is used, or the run says which keyword it refused

OTHER_CORPORA = ("aster-corpus-v15", "aster-corpus-v11", "aster-corpus-wider")
UNREAD_MARK = "asterlite does not implement what this keyword does"


@pytest.mark.slow
@pytest.mark.corpus
@pytest.mark.xdist_group("shared-corpus")  # the folders' runs of tests/test_corpus*.py
@pytest.mark.parametrize("name", OTHER_CORPORA)
def test_corpus_decks_use_every_keyword_they_give(name):
    """Every deck either uses all it gives or stops UNSUPPORTED at the keyword
    (aster-corpus itself is covered by its ratchet: a baseline deck that
    ignored a keyword would stop and fail it)."""
    import re

    from tests.conftest import corpus_rows

    rows = corpus_rows(name)
    refused = [row for row in rows if UNREAD_MARK in row["message"]]
    for row in refused:
        assert row["status"] == "UNSUPPORTED", row
        # located: deck file, line and column, then the keyword path
        located = r"\.com\w*:\d+:\d+: unsupported: [A-Z_]+(/[A-Z_]+(\[\d+\])?)+"
        assert re.search(located, row["message"]), row
