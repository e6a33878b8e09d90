"""The code_aster 15 corpus (../shared/aster-corpus-v15): decks of 2020 run unmodified.

A ratchet like tests/test_corpus.py's: every deck listed in the committed
baseline still passes when run, and ``asterlite port`` turns each of them
into a code_aster 17 deck that ``asterlite check`` accepts."""

from __future__ import annotations

import json
import math
from pathlib import Path

import pytest

from asterlite.legacy.port import port_file
from asterlite.runtime.corpus import find_decks
from asterlite.runtime.runner import run_deck
from tests.conftest import ROOT, corpus_rows

# one pytest-xdist worker runs every test that reads a corpus folder's run
# (tests.conftest.corpus_rows): each folder is run once a session, not once a worker
pytestmark = pytest.mark.xdist_group("shared-corpus")

CORPUS_V15 = ROOT.parent / "shared" / "aster-corpus-v15"
BASELINE = Path(__file__).with_name("corpus_baseline_v15.json")


def baseline_passing() -> list[str]:
    return json.loads(BASELINE.read_text())["passing"]


@pytest.fixture
def corpus_v15() -> Path:
    if not CORPUS_V15.is_dir():
        pytest.skip("../shared/aster-corpus-v15 is not available")
    return CORPUS_V15


def test_baseline_is_sorted_and_unique():
    passing = baseline_passing()
    assert passing == sorted(set(passing))


@pytest.mark.corpus
@pytest.mark.parametrize("deck", baseline_passing())
def test_ported_deck_is_accepted_by_check(deck, corpus_v15, tmp_path):
    """The code_aster 17 deck `asterlite port` writes passes `asterlite check`
    beside the same files (its .export names the ported deck instead)."""
    folder = corpus_v15 / deck
    result = port_file(folder / f"{deck}.comm")
    assert result.notes, "a code_aster 15 deck has something to port"
    for path in folder.iterdir():
        target = tmp_path / path.name
        if path.suffix == ".comm":
            target.write_text(result.text if path.name == f"{deck}.comm" else path.read_text())
        elif path.suffix.startswith(".com"):  # continuation decks: ported as well
            target.write_text(port_file(path).text)
        else:
            target.symlink_to(path)
    report = run_deck(tmp_path / f"{deck}.export", check_only=True)
    assert report.status == "CHECKED", report.message
    assert not port_file(tmp_path / f"{deck}.comm").notes  # nothing legacy left


@pytest.mark.slow
@pytest.mark.corpus
@pytest.mark.parametrize("deck", baseline_passing())
def test_ported_deck_runs_to_the_same_values(deck, corpus_v15, tmp_path):
    """The ported deck (with its version line where it relies on a code_aster 15
    behaviour no keyword expresses) gives the same TEST_* values as the deck as
    written (issue 15: port and run share one translation). The deck as written
    is the run of the folder's ratchet (one run of the folder per session)."""
    from tests.test_legacy_v11_port import _ported_copy

    export, _ = _ported_copy(deck, tmp_path / "ported", corpus=corpus_v15)
    legacy = {row["deck"]: row for row in corpus_rows("aster-corpus-v15")}[deck]
    assert legacy["status"] == "PASS", legacy["message"]
    ported = run_deck(export, tmp_path / "ported_run")
    assert ported.status == "PASS", ported.message
    old = [(command, value) for command, _label, value in legacy["tests"]]
    new = [(t.command, t.value) for t in ported.tests]
    assert [c for c, _ in old] == [c for c, _ in new]
    for (_, a), (_, b) in zip(old, new, strict=True):
        if isinstance(a, str) or isinstance(b, str):
            assert a == b, (deck, a, b)
        else:
            assert math.isclose(a, b, rel_tol=1.0e-9, abs_tol=1.0e-300), (deck, a, b)


# the other corpus folders and their committed baselines (decks that pass today)
RATCHETS = {
    "aster-corpus-v15": BASELINE,
    "aster-corpus-v11": Path(__file__).with_name("corpus_baseline_v11.json"),
    "aster-corpus-wider": Path(__file__).with_name("corpus_baseline_wider.json"),
}


@pytest.mark.parametrize("name", sorted(RATCHETS))
def test_older_baselines_are_sorted_and_unique(name):
    passing = json.loads(RATCHETS[name].read_text())["passing"]
    assert passing == sorted(set(passing))


@pytest.mark.slow
@pytest.mark.corpus
@pytest.mark.parametrize("name", sorted(RATCHETS))
def test_older_corpus_ratchet(name):
    """Run a whole corpus folder; each deck of its baseline must still PASS."""
    rows = corpus_rows(name)
    passing = json.loads(RATCHETS[name].read_text())["passing"]
    status = {row["deck"]: row for row in rows}
    assert len(rows) == len(find_decks(ROOT.parent / "shared" / name))
    regressions = [
        f"{deck}: {status[deck]['status']} {status[deck]['message']}"
        for deck in passing
        if status.get(deck, {}).get("status") != "PASS"
    ]
    assert not regressions, f"decks in the {name} baseline stopped passing:\n" + "\n".join(
        regressions
    )
    newly = sorted(d for d, r in status.items() if r["status"] == "PASS" and d not in passing)
    if newly:
        print(f"decks now passing, add them to {RATCHETS[name].name}:", ", ".join(newly))
