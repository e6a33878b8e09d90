"""VALE_REFE and VALE_CALC verdicts told apart, and why a variant is NOOK.

A variant of the sample (MU=0.1 instead of the deck's MU = 0.15) was NOOK
with no word that the deck's VALE_CALC values are its own results for
MU = 0.15, and ``asterlite sweep`` showed 5 NOOK of 6 for that reason. Now
message.log, summary.json, the sweep table and the API count the two kinds
of comparison apart and a note names the deck's own values.
"""

from __future__ import annotations

import json

import pytest

from asterlite.runtime import sweep
from asterlite.runtime.runner import run_deck
from asterlite.runtime.verdicts import deck_assignments, verdicts
from tests.conftest import SAMPLES

EXPORT = SAMPLES / "friction_oscillator" / "friction_oscillator.export"


@pytest.fixture(scope="module")
def variant(tmp_path_factory):
    out = tmp_path_factory.mktemp("variant") / "out"
    return run_deck(EXPORT, out, overrides={"MU": 0.1}), out


def test_variant_says_why_it_is_nook(variant):
    report, out = variant
    assert report.status == "NOOK"
    assert verdicts(report.tests) == {
        "VALE_REFE": {"ok": 4, "total": 4},
        "VALE_CALC": {"ok": 0, "total": 4},
    }
    summary = json.loads((out / "summary.json").read_text())
    assert summary["deck_values"]["MU"]["text"] == "MU = 0.15"
    assert "instead of MU = 0.15 (friction_oscillator.comm:15)" in summary["note"]
    log = (out / "message.log").read_text()
    assert "VALE_REFE (references): 4/4 hold; VALE_CALC (non-regression): 0/4 hold" in log
    assert "note: run with MU=0.1 instead of MU = 0.15" in log


def test_the_deck_as_written_has_no_note(tmp_path):
    report = run_deck(EXPORT, tmp_path / "out")
    assert report.status == "PASS" and "note" not in report.extras
    assert report.extras["verdicts"]["VALE_CALC"] == {"ok": 4, "total": 4}


def test_sweep_table_counts_the_kinds_apart(variant, tmp_path):
    report, _ = variant
    own = run_deck(EXPORT, tmp_path / "own", overrides={"MU": 0.15})
    rows = [sweep.report_row({"MU": 0.1}, report), sweep.report_row({"MU": 0.15}, own)]
    assert (rows[0]["VALE_REFE"], rows[0]["VALE_CALC"]) == ("4/4", "0/4")
    assert (rows[1]["VALE_REFE"], rows[1]["VALE_CALC"]) == ("4/4", "4/4")
    table = sweep.format_sweep_table(rows, ["MU"])
    header = table.splitlines()[0].split()
    assert header[:6] == ["MU", "status", "seconds", "checks", "VALE_REFE", "VALE_CALC"]
    assert "1 of the 1 NOOK variants fail only VALE_CALC checks" in table
    columns = sweep.table_columns(rows, ["MU"])  # sweep.csv: the counts and the note
    assert columns[: 1 + len(sweep.FIXED_COLUMNS)] == ["MU", *sweep.FIXED_COLUMNS]
    assert {"VALE_REFE", "VALE_CALC", "note"} <= set(sweep.FIXED_COLUMNS)


def test_api_verdicts_and_note():
    import asterlite

    run = asterlite.run(asterlite.sample("friction_oscillator"), U0=4.0e-3)
    assert run.status == "NOOK"
    assert run.verdicts == {"VALE_REFE": "4/4", "VALE_CALC": "0/4"}
    assert "instead of U0 = 3.0e-03" in run.note


def test_deck_assignments(tmp_path):
    deck = tmp_path / "d.comm"
    deck.write_text("A = 1\nB=2 # two\nif A:\n    C = 3\nA == 1\n")
    found = deck_assignments([deck], ["A", "B", "C"])
    assert found["A"] == {"text": "A = 1", "file": "d.comm", "line": 1}
    assert found["B"]["text"] == "B = 2" and "C" not in found
