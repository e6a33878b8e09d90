"""The structural DYNA_VIBRA corpus (../shared/aster-corpus-dyna, issue 29):
a ratchet like tests/test_corpus.py's, every deck of the committed baseline
still passes when the whole folder is run (the baseline only grows)."""

from __future__ import annotations

import json
from pathlib import Path

import pytest

from asterlite.runtime.corpus import find_decks
from tests.conftest import ROOT, corpus_rows

# one pytest-xdist worker runs every test that reads a corpus folder's run
# (tests.conftest.corpus_rows): each folder is run once a session, not once a worker
pytestmark = pytest.mark.xdist_group("shared-corpus")

NAME = "aster-corpus-dyna"
BASELINE = Path(__file__).with_name("corpus_baseline_dyna.json")


def baseline_passing() -> list[str]:
    return json.loads(BASELINE.read_text())["passing"]


def test_dyna_baseline_is_sorted_and_unique():
    passing = baseline_passing()
    assert passing == sorted(set(passing))
    assert passing, "the baseline lists the decks that pass"


@pytest.mark.slow
@pytest.mark.corpus
def test_dyna_corpus_ratchet():
    """Run the whole folder; each baseline deck must still PASS."""
    rows = corpus_rows(NAME)
    status = {row["deck"]: row for row in rows}
    assert len(rows) == len(find_decks(ROOT.parent / "shared" / NAME))
    regressions = [
        f"{deck}: {status[deck]['status']} {status[deck]['message']}"
        for deck in baseline_passing()
        if status.get(deck, {}).get("status") != "PASS"
    ]
    assert not regressions, f"decks in the {NAME} baseline stopped passing:\n" + "\n".join(
        regressions
    )
    newly = sorted(
        d for d, r in status.items() if r["status"] == "PASS" and d not in baseline_passing()
    )
    if newly:
        print(f"decks now passing, add them to {BASELINE.name}:", ", ".join(newly))
