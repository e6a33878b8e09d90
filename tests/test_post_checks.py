"""TEST_* comparisons (asterlite.post.checks): VALE_ABS='OUI' compares the
modulus of the value with the modulus of each reference, as code_aster's
tresu_print does (sdld21c of code_aster 17 tests complex mode components
against complex VALE_REFE_C this way)."""

from __future__ import annotations

from asterlite.post.checks import Expectation, make_record


def test_vale_abs_compares_moduli_of_complex_values_and_references():
    reference = 4.32587e-3 - 4.32587e-3j
    # the mode's component up to a phase: the same modulus, another argument
    value = abs(reference) * 1j
    exp = Expectation(kind="C", calc=(reference,), refe=(reference,), absolute_value=True)
    record = make_record("TEST_RESU", "DX", value, exp)
    assert record.ok and record.strict
    assert not make_record("TEST_RESU", "DX", 1.01 * value, exp).ok
    plain = Expectation(kind="C", calc=(reference,), refe=(reference,))
    assert not make_record("TEST_RESU", "DX", value, plain).ok


def test_vale_abs_on_reals():
    exp = Expectation(kind="R", calc=(-2.5,), refe=(-2.5,), absolute_value=True)
    assert make_record("TEST_RESU", "DY", 2.5, exp).strict
    assert make_record("TEST_RESU", "DY", -2.5, exp).strict
