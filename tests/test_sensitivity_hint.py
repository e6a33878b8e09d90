"""``asterlite sensitivity`` on a deck without TEST_* says why and what to do.

It printed an empty table (and ran the deck nine times for it): with no
check there is nothing whose spread it could measure.
"""

from __future__ import annotations

from asterlite.cli import main
from tests.test_extremes_decks import Chain, Shock, write


def test_deck_without_checks(tmp_path, capsys):
    chain = Chain(shocks=[Shock(1, 5.0e-4, 1.0e6)], depl={1: (0.0, 1.0e-3, 0.0)}, post=False)
    export = write(chain, tmp_path / "deck")
    code = main(["sensitivity", str(export), "-q", "-o", str(tmp_path / "out")])
    err = capsys.readouterr().err
    assert code == 2
    assert "the deck has no TEST_* check" in err
    assert "TEST_RESU" in err and "VALE_CALC" in err and "asterlite converge" in err
