"""``run`` never calls a valid code_aster keyword invalid.

asterlite's own catalogues hold only what asterlite computes. A keyword
they lack but the deck version's language accepts (code_aster's catalogue)
is asterlite's limit: the run stops UNSUPPORTED, naming the keyword. A
keyword code_aster does not know either stays an invalid keyword.
"""

from __future__ import annotations

from pathlib import Path

from asterlite.runtime.runner import run_deck

# DIS_CONTACT is a material of code_aster 17 (discrete contact) that asterlite
# does not read; DIS_CONTAKT is no keyword at all
DECK = """DEBUT(CODE=_F(NIV_PUB_WEB='INTERNET'))
ACIER = DEFI_MATERIAU(ELAS=_F(E=2.0e11, NU=0.3, RHO=7800.0), {extra})
FIN()
"""


def _run(tmp_path: Path, extra: str):
    deck = tmp_path / "material.comm"
    deck.write_text(DECK.format(extra=extra))
    return run_deck(deck, tmp_path / "out", aster_version=17)


def test_a_keyword_code_aster_has_is_unsupported(tmp_path):
    report = _run(tmp_path, "DIS_CONTACT=_F(RIGI_NOR=1.0e6)")
    assert report.status == "UNSUPPORTED", report.message
    assert "material.comm:2:" in report.message
    assert "DEFI_MATERIAU/DIS_CONTACT" in report.message
    assert "valid code_aster keyword that asterlite does not implement" in report.message


def test_a_keyword_code_aster_lacks_stays_invalid(tmp_path):
    report = _run(tmp_path, "DIS_CONTAKT=_F(RIGI_NOR=1.0e6)")
    assert report.status == "ERROR", report.message
    assert "invalid keywords" in report.message and "DIS_CONTAKT" in report.message


def test_a_value_code_aster_refuses_stays_invalid(tmp_path):
    """The language check must accept the whole call: a bad value beside the
    missing keyword keeps the call invalid."""
    report = _run(tmp_path, "DIS_CONTACT=_F(RIGI_NOR='stiff')")
    assert report.status == "ERROR", report.message
