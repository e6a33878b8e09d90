"""The code_aster decks of issue 20 built on 3D solids (or on what comes with
them: FACTORISER/RESOUDRE, CREA_RESU MULT_ELAS, INCLUDE_MATERIAU, setMesh,
SOLVEUR/NB_RHS) pass unmodified, every check at code_aster's tolerance."""

from __future__ import annotations

import pytest

from tests.conftest import ROOT, corpus_rows

# one pytest-xdist worker runs every test that reads a corpus folder's run
# (tests.conftest.corpus_rows): each folder is run once a session, not once a worker
pytestmark = pytest.mark.xdist_group("shared-corpus")

WIDER = ROOT.parent / "shared" / "aster-corpus-wider"

DECKS = {
    # deck: number of checks (all strict)
    "forma12c": 6,  # HEXA20, gravity, BANDE modes, FACTORISER/RESOUDRE, MULT_ELAS
    "efica01a": 5,  # INCLUDE_MATERIAU, MODE_STATIQUE/SOLVEUR/NB_RHS, setMesh
    "sdlv104a": 2,  # HEXA8 modes + static modes, GENE transient (2 x 200 000 steps)
}


@pytest.mark.slow
@pytest.mark.parametrize("deck", sorted(DECKS))
def test_solid_deck_passes(deck):
    # the folder's run of this session (tests/test_corpus_v15.py's ratchet shares it)
    if not (WIDER / deck / f"{deck}.export").is_file():
        pytest.skip(f"../shared/aster-corpus-wider/{deck} is not available")
    row = {row["deck"]: row for row in corpus_rows("aster-corpus-wider")}[deck]
    assert row["status"] == "PASS", row["message"]
    assert row["checks_ok"] == row["strict_ok"] == DECKS[deck]
