"""``run`` never calls a valid code_aster keyword invalid.

asterlite's own catalogues hold only what asterlite computes. A keyword
they lack but the deck version's language accepts (code_aster's catalogue)
is asterlite's limit: the run stops UNSUPPORTED, naming the keyword. A
keyword code_aster does not know either stays an invalid keyword.
"""

from __future__ import annotations

from pathlib import Path

from asterlite.runtime.runner import run_deck

# ECRO_PUIS is a material of code_aster 17 (power-law hardening) that asterlite
# does not read; ECRO_PUIZ is no keyword at all
DECK = """DEBUT(CODE=_F(NIV_PUB_WEB='INTERNET'))
ACIER = DEFI_MATERIAU(ELAS=_F(E=2.0e11, NU=0.3, RHO=7800.0), {extra})
FIN()
"""


def _run(tmp_path: Path, extra: str):
    deck = tmp_path / "material.comm"
    deck.write_text(DECK.format(extra=extra))
    return run_deck(deck, tmp_path / "out", aster_version=17)


def test_a_keyword_code_aster_has_is_unsupported(tmp_path):
    report = _run(tmp_path, "ECRO_PUIS=_F(SY=2.0e8, A_PUIS=0.5, N_PUIS=3.0)")
    assert report.status == "UNSUPPORTED", report.message
    assert "material.comm:2:" in report.message
    assert "DEFI_MATERIAU/ECRO_PUIS" in report.message
    assert "valid code_aster keyword that asterlite does not implement" in report.message


def test_a_keyword_code_aster_lacks_stays_invalid(tmp_path):
    report = _run(tmp_path, "ECRO_PUIZ=_F(SY=2.0e8, A_PUIS=0.5, N_PUIS=3.0)")
    assert report.status == "ERROR", report.message
    assert "invalid keywords" in report.message and "ECRO_PUIZ" in report.message


def test_a_value_code_aster_refuses_stays_invalid(tmp_path):
    """The language check must accept the whole call: a bad value beside the
    missing keyword keeps the call invalid."""
    report = _run(tmp_path, "ECRO_PUIS=_F(SY='stiff', A_PUIS=0.5, N_PUIS=3.0)")
    assert report.status == "ERROR", report.message


PLATE_MESH = """COOR_3D
N1 0.0 0.0 0.0
N2 1.0 0.0 0.0
N3 1.0 1.0 0.0
N4 0.0 1.0 0.0
FINSF
QUAD4
M1 N1 N2 N3 N4
FINSF
GROUP_MA
PLAQ M1
FINSF
FIN
"""

PLATE_DECK = """DEBUT()
MA = LIRE_MAILLAGE(FORMAT='ASTER')
MO = AFFE_MODELE(MAILLAGE=MA, AFFE=_F(TOUT='OUI', PHENOMENE='MECANIQUE', MODELISATION='DKT'))
CH = AFFE_CHAR_MECA(MODELE=MO, PRES_REP=_F(GROUP_MA='PLAQ', PRES=1.0e5))
FIN()
"""


def test_a_load_on_elements_asterlite_does_not_load_is_unsupported(tmp_path):
    """code_aster's DKT plates carry PRES_REP; asterlite's do not yet: the
    run says so by name instead of calling the cells wrong."""
    (tmp_path / "plate.mail").write_text(PLATE_MESH)
    deck = tmp_path / "plate.comm"
    deck.write_text(PLATE_DECK)
    report = run_deck(deck, tmp_path / "out", aster_version=17)
    assert report.status == "UNSUPPORTED", report.message
    assert "PRES_REP on DKT cells" in report.message and "plate.comm:4:" in report.message
