"""TEST_FICHIER as code_aster's test_fichier_ops: lines matching EXPR_IGNORE
dropped, reals (exponent form first, then decimal point) counted and summed,
integers apart, NB_VALE checked exactly and VALE_CALC within TOLE_MACHINE."""

from __future__ import annotations

import pytest
from asterlite.commands.test_fichier import scan

from tests.test_fem_support import run
from tests.test_harmonic_text_outputs import _Session

TEXT = """ ASTER 17.0 CONCEPT V0 CALCULE LE 29/11/2026 A 10:00:00
 CHAMP AUX NOEUDS V0
 NOEUD    DY                    DRZ
 A         2.00000000000000E+00
 B         1.00000000000000E+00  2.00000000000000D+00
 N12      -0.5  7 1.25
"""


def test_scan_counts_reals_then_integers():
    reals, integers, _ = scan(TEXT.split("\n", 1)[1])
    assert reals == [2.0, 1.0, 2.0, -0.5, 1.25]  # D exponents read as E
    assert integers == [0, 12, 7]  # V0, N12 and the lone 7


@pytest.mark.parametrize(
    ("count", "total", "verdicts"), [(5, 5.75, {"OK"}), (6, 5.75, {"NOOK", "OK"})]
)
def test_count_and_sum_of_the_kept_lines(tmp_path, count, total, verdicts):
    session = _Session(tmp_path)
    (tmp_path / "fort.81").write_text(TEXT)
    run(session, "TEST_FICHIER", FICHIER="fort.81", EXPR_IGNORE=("ASTER",), NB_VALE=count,
        VALE_CALC=total)  # fmt: skip
    assert {t.verdict for t in session.tests} == verdicts
    assert [t.value for t in session.tests] == [5, pytest.approx(5.75, rel=1e-15)]
