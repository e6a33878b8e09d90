"""`asterlite check` against `asterlite run` on every deck of the five corpus
folders of ../shared: the run outcomes are recorded in
``corpus_run_outcomes.json`` (status, and where a failed run stopped), made
from ``asterlite corpus DIR --json`` with ``python -m
tests.test_check_corpus_agreement run_FOLDER.json...``.

asterlite's own verdict (``run_deck(check_only=True)``, what run meets):

- where check reports an error, the run stopped there or earlier (on
  something only computing shows);
- where the run failed on validation (or a syntax error), check reports an
  error at that very place.

``asterlite check``'s two verdicts (:func:`check_deck`):

- every deck is valid code_aster of its version: never INVALID (nor ERROR);
- a deck the run carried to its end (PASS, NOOK, DONE) has no invalid and
  no unsupported finding: valid code_aster, all of it computed;
- where the run stopped on validation or a syntax error, check has a
  finding (invalid or unsupported) at that place.
"""

from __future__ import annotations

import json
import re
import sys
from pathlib import Path

import pytest

from asterlite.runtime.check_deck import check_deck
from asterlite.runtime.corpus import find_decks
from asterlite.runtime.runner import run_deck
from tests.conftest import CORPUS

OUTCOMES = Path(__file__).with_name("corpus_run_outcomes.json")
FOLDERS = (
    "aster-corpus",
    "aster-corpus-v15",
    "aster-corpus-v11",
    "aster-corpus-wider",
    "aster-corpus-dyna",
)
RAN = ("PASS", "NOOK", "DONE")
# run failures check must see: they come before anything is computed
SEEN_BY_CHECK = ("invalid keywords", "syntax error")
POSITION = re.compile(r"(?P<file>[^\s:]+\.com[m0-9]):(?P<line>\d+)(?::\d+)?: (?P<kind>[a-z ]+):")


def failure_of(message: str) -> dict | None:
    """Deck file, line and error kind of the first deck position in a message."""
    found = POSITION.search(message)
    if found is None:
        return None
    return {"file": Path(found["file"]).name, "line": int(found["line"]), "kind": found["kind"]}


def recorded() -> dict:
    return json.loads(OUTCOMES.read_text()) if OUTCOMES.exists() else {}


def cases() -> list[tuple[str, str]]:
    return [(folder, deck) for folder, decks in recorded().items() for deck in sorted(decks)]


def order_key(position: dict, export: Path) -> tuple[int, int]:
    """(deck file rank in the run, line), to compare positions across .comN files."""
    lines = export.read_text().splitlines()
    names = [Path(line.split()[2]).name for line in lines if line.startswith("F comm")]
    names = names or [export.with_suffix(".comm").name]
    rank = names.index(position["file"]) if position["file"] in names else 0
    return rank, position["line"]


@pytest.mark.slow
@pytest.mark.corpus
@pytest.mark.parametrize("folder, deck", cases(), ids=[f"{f}/{d}" for f, d in cases()])
def test_check_agrees_with_the_recorded_run(folder, deck):
    root = CORPUS.parent / folder
    if not root.is_dir():
        pytest.skip(f"../shared/{folder} is not available")
    export = next(e for e in find_decks(root) if e.parent.name == deck)
    run = recorded()[folder][deck]
    check = run_deck(export, check_only=True)
    run_failure = run.get("failure")
    if check.errors:
        first = failure_of(check.errors[0])
        assert first is not None, check.errors[0]
        assert run["status"] in ("ERROR", "UNSUPPORTED"), (
            f"check reports an error the run did not meet:\n{check.errors[0]}"
        )
        if run_failure is not None:
            assert order_key(run_failure, export) <= order_key(first, export), (
                f"run went past check's first error:\ncheck: {check.errors[0]}\nrun: {run}"
            )
    if run_failure is not None and run_failure["kind"] in SEEN_BY_CHECK:
        positions = [failure_of(error) for error in check.errors]
        assert run_failure in positions, f"check misses the run's error {run}:\n{check.message}"


@pytest.mark.slow
@pytest.mark.corpus
@pytest.mark.parametrize("folder, deck", cases(), ids=[f"{f}/{d}" for f, d in cases()])
def test_two_verdicts_agree_with_the_recorded_run(folder, deck):
    root = CORPUS.parent / folder
    if not root.is_dir():
        pytest.skip(f"../shared/{folder} is not available")
    export = next(e for e in find_decks(root) if e.parent.name == deck)
    run = recorded()[folder][deck]
    check = check_deck(export)
    shown = "\n".join(f.text() for f in check.findings)
    # every deck of ../shared is valid code_aster of its version (acceptance)
    assert check.status not in ("ERROR", "INVALID"), f"{check.message}\n{shown}"
    if run["status"] in RAN:
        refused = [f for f in check.findings if f.kind in ("invalid", "unsupported")]
        assert not refused, f"the run went to its end ({run['status']}), check says:\n{shown}"
    failure = run.get("failure")
    if failure is not None and failure["kind"] in SEEN_BY_CHECK:
        places = [
            {"file": Path(f.file).name, "line": f.line}
            for f in check.findings
            if f.file and f.kind in ("invalid", "unsupported")
        ]
        where = {"file": failure["file"], "line": failure["line"]}
        assert where in places, f"check has no finding where the run stopped {run}:\n{shown}"


def record(json_files: list[str]) -> dict:
    """The outcomes file from `asterlite corpus DIR --json FILE` outputs, one per folder
    (the folder is the file's name after ``run_``: run_aster-corpus-v15.json)."""
    outcomes = {}
    for name in json_files:
        folder = Path(name).stem.removeprefix("run_")
        rows = json.loads(Path(name).read_text())["decks"]
        outcomes[folder] = {
            row["deck"]: {"status": row["status"], "failure": failure_of(row["message"])}
            for row in rows
        }
    return outcomes


if __name__ == "__main__":  # python -m tests.test_check_corpus_agreement run_*.json
    OUTCOMES.write_text(json.dumps(record(sys.argv[1:]), indent=1, sort_keys=True) + "\n")
