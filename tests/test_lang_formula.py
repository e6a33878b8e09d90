"""The FORMULE front end (asterlite.lang.formula): the deck's parser, one
whitelist, one checked tree, read by the vectorised and the kernel back
ends; the function table (asterlite.lang.numeric) gives both the same
meaning."""

from __future__ import annotations

import numpy as np
import pytest

from asterlite.concepts.function import Formula
from asterlite.lang import numeric
from asterlite.lang.formula import (
    Binary,
    Call,
    Compare,
    ExpressionError,
    Name,
    Number,
    Unary,
    parse_formula,
)
from asterlite.lang.limits import Limits
from asterlite.post.expression import CompiledExpression


def test_chains_nest_left_to_right_as_python_evaluates_them():
    body = parse_formula("a - b - 2 * c ** -d").body
    assert body == Binary(
        "-",
        Binary("-", Name("a"), Name("b")),
        Binary("*", Number(2), Binary("**", Name("c"), Unary("-", Name("d")))),
    )
    compare = parse_formula("0 < x <= f(y, 1.E+04)").body
    assert compare == Compare(
        Number(0), ("<", "<="), (Name("x"), Call("f", (Name("y"), Number(1.0e4))))
    )
    tree = parse_formula("f(x) + g(y) * pi")
    assert tree.names == ("pi", "x", "y") and tree.called == ("f", "g")


def test_a_vale_over_several_lines_is_one_expression():
    tree = parse_formula("\n  2. * INST\n    + 1.\n")
    assert tree.body == Binary("+", Binary("*", Number(2.0), Name("INST")), Number(1.0))


@pytest.mark.parametrize(
    ("text", "message"),
    [
        ("x.real", "an attribute is not allowed in a FORMULE"),
        ("x[0]", "an index is not allowed in a FORMULE"),
        ("x, y", "a tuple is not allowed in a FORMULE"),
        ("[x for x in y]", "a comprehension is not allowed in a FORMULE"),
        ("lambda: 1", "a lambda is not allowed in a FORMULE"),
        ("x in y", "'in' is not allowed in a FORMULE"),
        ("x is y", "'is' is not allowed in a FORMULE"),
        ("~x", "'~' is not allowed in a FORMULE"),
        ("x | 1", "'|' is not allowed in a FORMULE"),
        ("f(x, k=1)", "only calls like f(x, y) of named functions are allowed"),
        ("f(*x)", "only calls like f(x, y) of named functions are allowed"),
        ("g(x)(y)", "only calls like f(x, y) of named functions are allowed"),
        ("'abc'", "constant 'abc' is not a number"),
        ("None", "constant None is not a number"),
        ("x +", "does not parse"),
        ("x <> 1", "does not parse at column 3: '<>' is Python 2"),
        ("__import__('os')", "does not parse at column 1: names starting with '__' are not"),
    ],
)
def test_one_whitelist_refuses_by_name(text, message):
    with pytest.raises(ExpressionError, match="formula") as error:
        parse_formula(text)
    assert message in error.value.message


def test_nesting_is_bounded_by_the_deck_limit():
    bound = Limits().max_tree_depth
    parse_formula("+".join(["x"] * (bound - 1)))  # a chain nests one level per term
    for text in ("+".join(["x"] * (bound + 2)), "-" * (bound + 2) + "x", "-" * 100_000 + "x"):
        with pytest.raises(ExpressionError, match="nested too deeply"):
            parse_formula(text)


def test_the_tree_is_parsed_once_per_text():
    assert parse_formula("sin(W * INST)") is parse_formula("sin(W * INST)")
    first, second = CompiledExpression("2 * x"), CompiledExpression("2 * x")
    assert first.tree is second.tree


def test_python_integers_stay_exact_and_are_guarded_like_deck_integers():
    assert CompiledExpression("(2**53 + 1) - 2**53").evaluate({}) == 1.0
    with pytest.raises(ExpressionError, match="limit exceeded"):
        CompiledExpression("10 ** 10 ** 6").evaluate({})


def _table_rows():
    for name, row in sorted(numeric.FUNCTIONS.items()):
        for arity in sorted(row.kernel):
            yield name, arity
    yield "min", 4
    yield "max", 3


@pytest.mark.parametrize(("name", "arity"), list(_table_rows()))
def test_every_kernel_code_of_the_table_computes_what_the_vector_column_does(name, arity):
    """The same FORMULE run by the kernel program and by numpy, on points
    inside and outside the function's domain, agree to the last bits (the
    kernels use the C library's functions where numpy may use its own)."""
    pytest.importorskip("numba")
    from asterlite.dynamics.formula import STACK_DEPTH, formula_program, run_program

    arguments = ", ".join(["INST"] + [f"{0.3 * k:.1f} - INST" for k in range(1, arity)])
    formula = Formula(VALE=f"{name}({arguments})", NOM_PARA="INST")
    program = formula_program(formula)
    assert program is not None, formula.VALE
    codes, constants = program
    table_codes = np.array([[len(codes), *codes]], dtype=np.int64)
    table_constants = np.array([[0.0, *constants]])
    stack = np.zeros(STACK_DEPTH)
    instants = np.array([-2.5, -1.0, -0.4, 0.0, 0.25, 0.5, 1.0, 1.7, 3.0, 12.0])
    with np.errstate(all="ignore"):
        expected = formula.compiled.evaluate({"INST": instants})
    expected = np.broadcast_to(expected, instants.shape)
    kernel = np.array([run_program(table_codes, table_constants, 0, t, stack) for t in instants])
    assert np.array_equal(np.isnan(kernel), np.isnan(expected)), (kernel, expected)
    finite = np.isfinite(expected)
    assert np.array_equal(np.isinf(kernel), np.isinf(expected))
    np.testing.assert_allclose(kernel[finite], expected[finite], rtol=4e-16, atol=0.0)


def test_names_without_a_kernel_code_keep_the_sampled_path():
    assert numeric.FUNCTIONS["heaviside"].kernel == {}
    formula = Formula(VALE="heaviside(INST - 1.0)", NOM_PARA="INST")
    from asterlite.dynamics.formula import formula_program

    assert formula_program(formula) is None
    assert formula.evaluate(np.array([0.0, 2.0])).tolist() == [0.0, 1.0]


def test_a_parse_error_names_its_column_in_the_text():
    with pytest.raises(ExpressionError) as error:
        parse_formula("  x +* 2")
    assert error.value.message == (
        "formula '  x +* 2' does not parse at column 6: invalid syntax: unexpected '*'"
    )
