"""The acceptance corpus: every deck passes `asterlite check`, and every deck
listed in the committed baseline still passes when run (a ratchet: the
baseline only grows)."""

from __future__ import annotations

import json
from pathlib import Path

import pytest

from asterlite.runtime.corpus import find_decks
from asterlite.runtime.runner import run_deck
from tests.conftest import CORPUS, corpus_decks, corpus_rows

# one pytest-xdist worker runs every test that reads a corpus folder's run
# (tests.conftest.corpus_rows): each folder is run once a session, not once a worker
pytestmark = pytest.mark.xdist_group("shared-corpus")

BASELINE = Path(__file__).with_name("corpus_baseline.json")


def baseline_passing() -> list[str]:
    return json.loads(BASELINE.read_text())["passing"]


@pytest.mark.corpus
@pytest.mark.parametrize("deck", corpus_decks())
def test_check_accepts_corpus_deck(deck):
    export = next(e for e in find_decks(CORPUS) if e.parent.name == deck)
    report = run_deck(export, check_only=True)
    assert report.status == "CHECKED", report.message


@pytest.mark.corpus
def test_corpus_has_54_decks(corpus_dir):
    assert len(find_decks(corpus_dir)) == 54


def test_baseline_is_sorted_and_unique():
    passing = baseline_passing()
    assert passing == sorted(set(passing))


@pytest.mark.slow
@pytest.mark.corpus
def test_corpus_ratchet(corpus_dir, tmp_path):
    """Run the whole corpus; each baseline deck must still PASS."""
    rows = corpus_rows("aster-corpus")
    (tmp_path / "corpus.json").write_text(json.dumps({"decks": rows}, indent=1))
    status = {row["deck"]: row for row in rows}
    assert len(rows) == 54
    regressions = [
        f"{deck}: {status[deck]['status']} {status[deck]['message']}"
        for deck in baseline_passing()
        if status.get(deck, {}).get("status") != "PASS"
    ]
    assert not regressions, "decks in the baseline stopped passing:\n" + "\n".join(regressions)
    newly = sorted(
        d for d, r in status.items() if r["status"] == "PASS" and d not in baseline_passing()
    )
    if newly:
        print("decks now passing, add them to tests/corpus_baseline.json:", ", ".join(newly))
