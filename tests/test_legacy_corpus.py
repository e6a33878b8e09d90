"""Legacy twins of corpus decks compute what the corpus decks compute.

Each legacy deck in tests/legacy_decks that translates a corpus deck into
old syntax (named ``<corpus deck>_v<version>``) holds the same TEST_* checks
as the corpus deck; run unmodified, it must give every checked value of the
corpus deck, label by label, to rounding. The corpus decks are read from
../shared/aster-corpus, never copied.

sdnd105a_v10 is not a translation: code_aster 10 described buckling by four
scalars (FNOR_CRIT...), which cannot express the tabulated law of today's
sdnd105a; its two buckling values must agree with the corpus deck's at the
corpus deck's own PRECISION.
"""

from __future__ import annotations

import math
from pathlib import Path

import pytest

from asterlite.runtime.runner import run_deck
from tests.conftest import corpus_rows
from tests.test_legacy_decks import node_blind

DECKS = Path(__file__).parent / "legacy_decks"
CORPUS = Path(__file__).resolve().parents[2] / "shared" / "aster-corpus"
TWINS = {  # legacy twin -> corpus deck it translates
    "sdnd100a_v10": "sdnd100a",
    "sdnd101a_v13": "sdnd101a",
    "sdnd102a_v10": "sdnd102a",
    "sdld34b_v13": "sdld34b",
    "sdnd125c_v11": "sdnd125c",
    "sdnd103a_v10": "sdnd103a",
    "sdld29a_v10": "sdld29a",
}
RELATIVE = 1.0e-9  # rounding only: the same arithmetic after translation

# xdist_group: see tests/test_corpus.py
pytestmark = [
    pytest.mark.skipif(not CORPUS.is_dir(), reason="aster-corpus is absent"),
    pytest.mark.xdist_group("shared-corpus"),
]


def _run(export: Path, folder: Path):
    report = run_deck(export, folder)
    assert report.status == "PASS", f"{export.name}: {report.message}"
    return report


def _checked(report) -> list[tuple[str, str, float]]:
    return [(t.command, node_blind(t.label), t.value) for t in report.tests]


def _corpus_run(deck: str) -> list[tuple[str, str, float]]:
    """The corpus deck's TEST_* values from the folder's run of the session
    (tests/test_corpus.py's ratchet): the deck is not run again."""
    row = {row["deck"]: row for row in corpus_rows("aster-corpus")}[deck]
    assert row["status"] == "PASS", f"{deck}: {row['message']}"
    return [(command, node_blind(label), value) for command, label, value in row["tests"]]


def test_every_twin_is_listed():
    """A legacy deck named after a corpus deck is compared here (or said not to be)."""
    named = {p.stem for p in DECKS.glob("*.export") if (CORPUS / p.stem.split("_v")[0]).is_dir()}
    assert named == set(TWINS) | {"sdnd105a_v10"}


@pytest.mark.slow  # compared with the corpus folder's run (all 54 decks, once a session)
@pytest.mark.parametrize("twin", list(TWINS))
def test_legacy_twin_matches_its_corpus_deck(twin, tmp_path):
    corpus = TWINS[twin]
    legacy = _checked(_run(DECKS / f"{twin}.export", tmp_path / "legacy"))
    modern = _corpus_run(corpus)
    assert modern, f"{corpus} records no TEST_* value"
    assert [(c, label) for c, label, _ in legacy] == [(c, label) for c, label, _ in modern]
    for (_, label, old), (_, _, new) in zip(legacy, modern, strict=True):
        assert math.isclose(old, new, rel_tol=RELATIVE, abs_tol=1e-300), (label, old, new)


@pytest.mark.slow
def test_sdnd105a_v10_scalar_buckling_law_agrees_with_the_corpus_deck(tmp_path):
    legacy = _run(DECKS / "sdnd105a_v10.export", tmp_path / "legacy")
    values = {label: value for _command, label, value in _corpus_run("sdnd105a")}
    compared = 0
    for test in legacy.tests:
        label = node_blind(test.label)
        if label in values:  # ECRAS_RESI and INST_FLAMB of the support
            assert math.isclose(test.value, values[label], rel_tol=1.0e-3), test.label
            compared += 1
    assert compared == 2
