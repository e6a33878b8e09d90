"""The code_aster decks of issue 20 built on 3D solids (or on what comes with
them: FACTORISER/RESOUDRE, CREA_RESU MULT_ELAS, INCLUDE_MATERIAU, setMesh,
SOLVEUR/NB_RHS) pass unmodified, every check at code_aster's tolerance."""

from __future__ import annotations

import json

import pytest

from asterlite.runtime.runner import run_deck
from tests.conftest import ROOT

WIDER = ROOT.parent / "shared" / "aster-corpus-wider"

DECKS = {
    # deck: number of checks (all strict)
    "forma12c": 6,  # HEXA20, gravity, BANDE modes, FACTORISER/RESOUDRE, MULT_ELAS
    "efica01a": 5,  # INCLUDE_MATERIAU, MODE_STATIQUE/SOLVEUR/NB_RHS, setMesh
    "sdlv104a": 2,  # HEXA8 modes + static modes, GENE transient (2 x 200 000 steps)
}


@pytest.mark.slow
@pytest.mark.parametrize("deck", sorted(DECKS))
def test_solid_deck_passes(deck, tmp_path):
    export = WIDER / deck / f"{deck}.export"
    if not export.is_file():
        pytest.skip(f"../shared/aster-corpus-wider/{deck} is not available")
    report = run_deck(export, tmp_path / deck)
    summary = json.loads((tmp_path / deck / "summary.json").read_text())
    assert report.status == "PASS", report.message
    assert summary["checks_ok"] == summary["strict_ok"] == DECKS[deck]
