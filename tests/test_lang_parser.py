"""The deck grammar and parser: what parses, literal values, located syntax errors."""

from __future__ import annotations

import pytest

from asterlite.errors import DeckSyntaxError
from asterlite.lang import Module, parse_deck, parse_expression
from asterlite.lang.tree_checks import decode_string_literal, node_position


def statements(text: str) -> list:
    return parse_deck(text, "deck.comm").tree.children


def expression(text: str):
    return parse_expression(text, "expr").tree.children[0]


def const_value(text: str):
    node = expression(text)
    assert node.data == "const", node
    return node.children[0]


def syntax_error(text: str) -> DeckSyntaxError:
    with pytest.raises(DeckSyntaxError) as info:
        parse_deck(text, "deck.comm")
    return info.value


# ------------------------------------------------------------------ literals


@pytest.mark.parametrize(
    "text, value",
    [
        ("1.E+04", 1.0e4),
        ("0.5e-3", 0.5e-3),
        ("1.", 1.0),
        (".5", 0.5),
        ("2E3", 2000.0),
        ("1_000", 1000),
        ("0x1F", 31),
        ("0o17", 15),
        ("0b101", 5),
        ("3j", 3j),
        ("007.5", 7.5),
        ("0", 0),
    ],
)
def test_number_literals(text, value):
    result = const_value(text)
    assert result == value and type(result) is type(value)


@pytest.mark.parametrize(
    "text, value",
    [
        ("'abc'", "abc"),
        ('"a\'b"', "a'b"),
        ("'a' \"b\" 'c'", "abc"),
        ('"""line1\nline2"""', "line1\nline2"),
        ("'''x'''", "x"),
        (r"'tab\there'", "tab\there"),
        (r"'\x41\u00e9\101'", "Aé" + "A"),
        (r"r'\n'", "\\n"),
        (r"'\q'", "\\q"),
        ("u'été'", "été"),
        (r"'\N{GREEK SMALL LETTER ALPHA}'", "α"),
    ],
)
def test_string_literals(text, value):
    assert const_value(text) == value


def test_string_continuation_inside_brackets_and_backslash():
    module = parse_deck('X = ("a"\n     "b")\nY = 1 + \\\n    2\n', "d")
    assign = module.tree.children[0]
    assert assign.children[1].children[0] == "ab"
    assert len(module.tree.children) == 2


def test_decode_string_literal_rejects_garbage():
    with pytest.raises(ValueError):
        decode_string_literal("abc")


# ---------------------------------------------------------------- statements


@pytest.mark.parametrize(
    "text, kind",
    [
        ("x = 1", "assign"),
        ("a, b = 1, 2", "assign"),
        ("a[i, :] = 0", "assign"),
        ("a = b = 3", "assign"),
        ("x += 1", "augassign"),
        ("x **= 2", "augassign"),
        ("del x, y[0]", "del_stmt"),
        ("pass", "pass_stmt"),
        ("f(1, K=2, *a, **kw)", "expr_stmt"),
        ("import numpy as np", "import_name"),
        ("import a.b, c", "import_name"),
        ("from math import *", "import_from"),
        ("from x import (a, b as c,)", "import_from"),
        ("assert x, 'msg'", "assert_stmt"),
        ("if a:\n    pass\nelif b:\n    pass\nelse:\n    pass", "if_stmt"),
        ("for i, (a, b) in enumerate(zip(x, y)):\n    continue", "for_stmt"),
        ("while x:\n    break\nelse:\n    pass", "while_stmt"),
        ("def f(a, b=1, c=(1, 2)):\n    return a", "funcdef"),
        ("def f():\n    return", "funcdef"),
    ],
)
def test_statement_kinds(text, kind):
    assert statements(text + "\n")[0].data == kind


@pytest.mark.parametrize(
    "text, kind",
    [
        ("a if c else b", "ternary"),
        ("lambda x, y=2: x + y", "lambdef"),
        ("not a", "not_"),
        ("a < b <= c", "comparison"),
        ("a not in b", "comparison"),
        ("a is not None", "comparison"),
        ("a or b or c", "or_test"),
        ("a and b", "and_test"),
        ("-x", "unary"),
        ("x ** -2", "power"),
        ("a - b + c", "arith_expr"),
        ("a * b // c % d / e", "term"),
        ("a | b", "or_expr"),
        ("a & b", "and_expr"),
        ("a ^ b", "xor_expr"),
        ("[x for x in y if x if x > 1 for z in w]", "listcomp"),
        ("(x for x in y)", "listcomp"),
        ("{k: v for k, v in d.items()}", "dictcomp"),
        ("{1: 2, 'a': [3]}", "dict"),
        ("{1, 2}", "set"),
        ("()", "tuple"),
        ("(1,)", "tuple"),
        ("[]", "list"),
        ("a[::2]", "getitem"),
        ("a.b.c", "getattr"),
        ("f()", "funccall"),
        ("None", "const_none"),
        ("True", "const_true"),
        ("False", "const_false"),
    ],
)
def test_expression_kinds(text, kind):
    assert expression(text).data == kind


def test_slices_have_three_parts():
    index = expression("a[1:, ::2, :3:]").children[1]
    assert index.data == "subscript_tuple"
    for part in index.children:
        assert part.data == "slice" and len(part.children) == 3


def test_comments_blank_lines_and_semicolons():
    text = "# header\n\nx = 1  # trailing\n\n\ny = 2; z = 3;\n"
    kinds = [s.data for s in statements(text)]
    assert kinds == ["assign", "simple_stmt"]


def test_no_final_newline_and_crlf():
    assert len(statements("x = 1\r\ny = 2")) == 2


def test_module_keeps_lines_and_locations():
    module = parse_deck("x = 1\n  \ny = foo(2)\n", "deck.comm")
    assert isinstance(module, Module)
    assert module.lines[2] == "y = foo(2)"
    call = module.tree.children[1].children[1]
    assert node_position(call) == (3, 5)
    location = module.location(3, 5)
    assert location.file == "deck.comm" and location.source_line == "y = foo(2)"


# --------------------------------------------------------------- bad input


@pytest.mark.parametrize(
    "text, line, column, words",
    [
        ("x = (1,\n", 1, 8, "unexpected end of file"),
        ("x = 1 +\n", 1, 8, "unexpected end of line"),
        ("x = 1 $ 2\n", 1, 7, "unexpected character '$'"),
        ("x = 'abc\n", 1, 5, "unterminated string"),
        ("x = 1\ny = )\n", 2, 5, "unmatched ')'"),
        ("if 1:\n    x = 1\n  y = 2\n", 3, 3, "unindent does not match"),
        ("x = 1\n    y = 2\n", 2, 5, "unexpected indentation"),
        ("class A:\n    pass\n", 1, 1, "class definitions are not supported"),
        ("try:\n    pass\nexcept:\n    pass\nexcept E:\n    pass\n", 3, 1, "must be last"),
        ("x = 1\nglobal x\n", 2, 1, "'global' declarations are not supported"),
        ("def f():\n    yield 1\n", 2, 5, "generators"),
        ("nonlocal x\n", 1, 1, "'nonlocal' declarations are not supported"),
        ("async def f():\n    pass\n", 1, 1, "'async' is not supported"),
        ("@decorator\ndef f():\n    pass\n", 1, 1, "decorators"),
        ("x = f'{y}}'\n", 1, 10, "single '}' is not allowed"),
        ("x = f'a{y +}'\n", 1, 9, "invalid expression in an f-string field"),
        ("x = f'{y.__class__}'\n", 1, 10, "attributes starting with '_'"),
        ("x = f'{y!z}'\n", 1, 9, "conversion must be"),
        ("x = b'y'\n", 1, 5, "bytes literals are not supported"),
        ("x = ().__class__\n", 1, 8, "attributes starting with '_'"),
        ("x = a._b\n", 1, 7, "attributes starting with '_'"),
        ("__import__('os')\n", 1, 1, "names starting with '__'"),
        ("def f(__a):\n    pass\n", 1, 7, "names starting with '__'"),
        ("from _x import y\n", 1, 6, "attributes starting with '_'"),
        ("from x import _y\n", 1, 15, "attributes starting with '_'"),
        ("import os._x\n", 1, 11, "attributes starting with '_'"),
        ("return 1\n", 1, 1, "'return' outside a function"),
        ("break\n", 1, 1, "'break' outside a loop"),
        ("def f():\n    continue\n", 2, 5, "'continue' outside a loop"),
        ("for i in x:\n    def g():\n        break\n", 3, 9, "'break' outside a loop"),
        ("f(a=1, a=2)\n", 1, 8, "keyword argument repeated"),
        ("f(a=1, 2)\n", 1, 8, "positional argument follows keyword"),
        ("f(x.y=1)\n", 1, 3, "keyword argument must be a plain name"),
        ("x.y = 1\n", 1, 1, "cannot assign to an attribute"),
        ("f() = 1\n", 1, 1, "cannot assign to a function call"),
        ("1 = x\n", 1, 1, "cannot assign to a literal"),
        ("a, f() = 1, 2\n", 1, 4, "cannot assign to a function call"),
        ("for f() in x:\n    pass\n", 1, 5, "cannot assign to a function call"),
        ("del f()\n", 1, 5, "cannot delete a function call"),
        ("(a, b) += 1\n", 1, 2, "cannot use += on"),
        ("def f(a=1, b):\n    pass\n", 1, 12, "without a default"),
        ("def f(a, a):\n    pass\n", 1, 10, "duplicate parameter"),
        ("x = 99999" + "9" * 5000 + "\n", 1, 5, "number literal too large"),
    ],
)
def test_syntax_errors_are_located(text, line, column, words):
    error = syntax_error(text)
    assert words in error.message
    assert (error.location.line, error.location.column) == (line, column)
    assert error.location.file == "deck.comm"
    rendered = str(error)
    assert "syntax error" in rendered and "^" in rendered


def test_error_excerpt_points_at_the_column():
    error = syntax_error("x = 1\ny = 2 $\n")
    excerpt = error.location.excerpt().splitlines()
    assert excerpt[0].strip() == "y = 2 $"
    assert excerpt[1].index("^") == excerpt[0].index("$")


def test_unmatched_bracket_after_newline_is_reported():
    error = syntax_error("x = [1,\n2]]\n")
    assert error.location.line == 2


def test_deep_nesting_is_a_syntax_or_deck_error_not_a_crash():
    text = "x = " + "(" * 3000 + "1" + ")" * 3000 + "\n"
    try:
        parse_deck(text, "d")
    except DeckSyntaxError:
        pass


def test_parse_expression_rejects_statements():
    with pytest.raises(DeckSyntaxError):
        parse_expression("x = 1", "formula")
    assert parse_expression("  A0 * sin(W0*INST) ", "formula").tree.data == "eval_input"


def test_soft_keywords_stay_names():
    assert statements("match = 1\ncase = match\n")[1].data == "assign"
