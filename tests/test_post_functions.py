import numpy as np
import pytest
from asterlite.commands import (
    calc_fonc_interp,
    defi_constante,
    defi_fonction,
    defi_list_enti,
    defi_list_reel,
    formule,
)

from asterlite.concepts.function import Formula, Function, FunctionDomainError
from asterlite.errors import CommandError
from asterlite.post.expression import CompiledExpression, ExpressionError

from .test_post_support import context, kw


def test_linear_interpolation_and_prolongations():
    f = Function([0.0, 1.0, 3.0], [0.0, 2.0, 6.0], PROL_GAUCHE="CONSTANT", PROL_DROITE="LINEAIRE")
    assert np.allclose(f.evaluate([-1.0, 0.5, 2.0, 4.0]), [0.0, 1.0, 4.0, 8.0])
    assert f(0.5) == pytest.approx(1.0)


def test_exclu_raises_outside_range():
    f = Function([0.0, 1.0], [0.0, 1.0])
    with pytest.raises(FunctionDomainError, match="PROL_DROITE"):
        f(1.5)


def test_log_log_interpolation_follows_power_law():
    f = Function([1.0, 10.0], [1.0, 100.0], INTERPOL=("LOG", "LOG"))
    assert f(np.sqrt(10.0)) == pytest.approx(10.0)


def test_deck_methods_follow_code_aster_layout():
    f = Function([0.0, 1.0], [5.0, 6.0], NOM_PARA="INST", NOM_RESU="DX")
    assert f.Valeurs() == [[0.0, 1.0], [5.0, 6.0]]
    assert f.getValues() == [0.0, 1.0, 5.0, 6.0]
    assert f.Parametres()["NOM_PARA"] == "INST"


def test_defi_fonction_from_vale_pairs_and_bad_order():
    ctx = context("DEFI_FONCTION")
    f = defi_fonction.run(ctx, kw(NOM_PARA="INST", VALE=(0.0, 1.0, 2.0, 3.0)))
    assert f.abscissas.tolist() == [0.0, 2.0] and f.ordinates.tolist() == [1.0, 3.0]
    with pytest.raises(CommandError, match="increase"):
        defi_fonction.run(ctx, kw(NOM_PARA="INST", VALE=(1.0, 1.0, 0.0, 3.0)))


def test_defi_fonction_complex_values():
    f = defi_fonction.run(context(), kw(NOM_PARA="FREQ", VALE_C=(0.0, 1.0, 2.0, 1.0, 3.0, 4.0)))
    assert f.aster_type == "fonction_c"
    assert f(0.5) == pytest.approx(2.0 + 3.0j)


def test_defi_constante_is_constant_everywhere():
    f = defi_constante.run(context(), kw(VALE=3.5))
    assert np.allclose(f.evaluate([-10.0, 0.0, 1e6]), 3.5)


def test_defi_list_reel_intervals_with_pas_and_nombre():
    occ = [{"JUSQU_A": 1.0, "PAS": 0.25}, {"JUSQU_A": 2.0, "NOMBRE": 2}]
    values = defi_list_reel.run(context(), kw(DEBUT=0.0, INTERVALLE=occ)).Valeurs()
    assert values == pytest.approx([0.0, 0.25, 0.5, 0.75, 1.0, 1.5, 2.0])


def test_defi_list_reel_step_that_does_not_divide_ends_on_jusqu_a():
    # code_aster's op0024: the whole steps, then one shorter step to JUSQU_A
    occ = [{"JUSQU_A": 1.0, "PAS": 0.3}]
    values = defi_list_reel.run(context(), kw(DEBUT=0.0, INTERVALLE=occ)).Valeurs()
    assert np.allclose(values, [0.0, 0.3, 0.6, 0.9, 1.0])


def test_defi_list_reel_rejects_a_step_longer_than_its_interval():
    with pytest.raises(CommandError, match="PAS"):
        defi_list_reel.run(context(), kw(DEBUT=0.0, INTERVALLE=[{"JUSQU_A": 1.0, "PAS": 1.5}]))


def test_defi_list_enti():
    occ = [{"JUSQU_A": 5, "PAS": 2}]
    assert defi_list_enti.run(context(), kw(DEBUT=1, INTERVALLE=occ)).Valeurs() == [1, 3, 5]


def test_formula_with_extra_constants_and_functions():
    acc = Function([0.0, 1.0], [0.0, 10.0], NOM_PARA="INST")
    extra = {"OMEGA": 2.0, "ACC": acc}
    f = formule.run(
        context(), kw(VALE="sin(OMEGA*INST) + ACC(INST)", NOM_PARA=("INST",), _extra=extra)
    )
    t = np.array([0.0, 0.25, 0.5])
    assert np.allclose(f.evaluate(t), np.sin(2 * t) + 10 * t)
    assert f(0.5) == pytest.approx(np.sin(1.0) + 5.0)


def test_formula_two_parameters_and_conditional():
    f = Formula("DX if DX > 0 else -2*DY", ("DX", "DY"))
    assert np.allclose(f.evaluate(np.array([1.0, -1.0]), np.array([3.0, 3.0])), [1.0, -6.0])


def test_formula_calls_a_plain_callable_point_by_point():
    f = Formula("G(X) * 2", ("X",), extra={"G": lambda x: x + 1.0 if x > 0 else 0.0})
    assert np.allclose(f.evaluate(np.array([-1.0, 1.0])), [0.0, 4.0])


@pytest.mark.parametrize(
    "text", ["__import__('os')", "X.real", "X[0]", "(lambda: 1)()", "'a'", "f(x=1)"]
)
def test_expression_whitelist_rejects_unsafe_constructs(text):
    with pytest.raises(ExpressionError):
        CompiledExpression(text)


def test_formula_unknown_name_is_reported():
    with pytest.raises(CommandError, match="OMEGA"):
        formule.run(context(), kw(VALE="sin(OMEGA*INST)", NOM_PARA=("INST",)))


def test_calc_fonc_interp_of_a_formula():
    f = Formula("2*INST", ("INST",))
    out = calc_fonc_interp.run(
        context(),
        kw(FONCTION=f, VALE_PARA=(0.0, 1.0, 2.0), NOM_RESU="Y", PROL_DROITE="CONSTANT"),
    )
    assert out.ordinates.tolist() == [0.0, 2.0, 4.0]
    assert out.NOM_PARA == "INST" and out.NOM_RESU == "Y"
    assert out(5.0) == 4.0
