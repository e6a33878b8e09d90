"""Every sample deck runs and passes its own checks (analytic references)."""

from __future__ import annotations

import pytest

from asterlite.runtime.runner import run_deck
from tests.conftest import SAMPLES

SAMPLE_EXPORTS = sorted(SAMPLES.glob("*/*.export"))


@pytest.mark.parametrize("export", SAMPLE_EXPORTS, ids=[p.stem for p in SAMPLE_EXPORTS])
def test_sample_passes(export, tmp_path):
    report = run_deck(export, tmp_path / "out")
    assert report.status == "PASS", report.message
    assert report.checks_total > 0
    references = [t for t in report.tests if t.reference != "NON_REGRESSION"]
    assert references, "a sample must check against an analytic or independent reference"


def test_veri_choc_stops_a_run_on_a_too_poor_basis(tmp_path):
    """Two bending modes carry none of the tube's compliance along NORM_OBST
    (its axis, the direction code_aster's check loads): with a SEUIL below the
    missed share (about 0.03 here), STOP_CRITERE='OUI' stops before integrating."""
    folder = SAMPLES / "tube_supports"
    text = (folder / "tube_supports.comm").read_text()
    check = '    VERI_CHOC=_F(STOP_CRITERE="OUI", SEUIL=0.01),\n'
    text = text.replace("NB_VECT=20", "NB_VECT=2").replace(
        "    COMPORTEMENT=SUPPORTS,\n)\n\nIMPACTS",
        "    COMPORTEMENT=SUPPORTS,\n" + check + ")\n\nIMPACTS",
    )
    assert "VERI_CHOC" in text
    (tmp_path / "tube.comm").write_text(text)
    (tmp_path / "tube.mail").write_text((folder / "tube_supports.mail").read_text())
    report = run_deck(tmp_path / "tube.comm", tmp_path / "out")
    assert report.exit_code == 2
    assert "VERI_CHOC" in report.message and "SEUIL" in report.message
