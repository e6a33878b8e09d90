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
