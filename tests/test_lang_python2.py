"""Python 2 decks (code_aster 13 and older): their syntax read, their
meaning kept (integer division, lists), refused in Python 3 decks, and
written as Python 3 by ``asterlite port``."""

from __future__ import annotations

import pytest

from asterlite.errors import DeckSyntaxError
from asterlite.lang import Evaluator, Limits, base_namespace, parse_deck
from asterlite.legacy.port_python2 import to_python3
from asterlite.legacy.version import PYTHON2_LAST, deck_version

SMALL = Limits(max_loop_iterations=10_000, max_sequence_length=100_000)

PYTHON2_DECK = """\
DEBUT()
x = 0777 + 10L
n = 7 / 2
m = -7 / 2
y = 7 / 2.
if x <> 3:
    print "x =", x,
    print `n`
print
try:
    a = 1 / 0
except ZeroDivisionError, e:
    print "caught", e
s = ur'a\\n'
d = {'k': 1}
first = d.keys()[0]
has = d.has_key('k')
squares = map(lambda v: v * v, range(3))
pairs = zip([1, 2], 'ab')
k = 9
k /= 2
try:
    raise ValueError, "old style"
except ValueError, e:
    old = e.message
FIN()
"""


def run(text: str):
    lines = []
    namespace = base_namespace(limits=SMALL, print_hook=lines.append)
    module = parse_deck(text, "deck.comm")
    Evaluator(namespace, limits=SMALL).run(module)
    return namespace, lines, module


class Stub:
    deck_unknown_policy = "store"

    def __call__(self, *args, **kwargs):
        return None


def test_a_python2_deck_parses_and_runs_with_python2_meaning():
    lines = []
    namespace = base_namespace(limits=SMALL, print_hook=lines.append)
    namespace.update(DEBUT=Stub(), FIN=Stub())
    module = parse_deck(PYTHON2_DECK, "deck.comm")
    assert module.python2 and "invalid syntax" in module.python3_error.message
    Evaluator(namespace, limits=SMALL).run(module)
    assert namespace["x"] == 521 and namespace["n"] == 3 and namespace["m"] == -4
    assert namespace["y"] == 3.5 and namespace["k"] == 4
    assert namespace["s"] == "a\\n"
    assert namespace["first"] == "k" and namespace["has"] is True
    assert namespace["squares"] == [0, 1, 4] and namespace["pairs"] == [(1, "a"), (2, "b")]
    assert namespace["old"] == "old style"
    assert "e" in namespace  # Python 2 keeps the except name bound
    assert lines == ["x = 521 3\n", "\n", "caught integer division or modulo by zero\n"]


def test_future_division_keeps_true_division():
    namespace, _, module = run("from __future__ import division\nprint 'a'\nn = 7 / 2\n")
    assert module.python2 and "division" in module.future and namespace["n"] == 3.5


@pytest.mark.parametrize(
    "text, words",
    [
        ("x = 0777\n", "Python 2 octal literal 0777"),
        ("x = 10L\n", "Python 2 long literal"),
        ("x = 1 <> 2\n", "'<>' is Python 2"),
        ("x = `1`\n", "backquoted expression"),
        ("try:\n    pass\nexcept E, e:\n    pass\n", "'except E, name' is Python 2"),
        ("raise E, 'm'\n", "'raise E, message'"),
        ("print 'x'\n", "invalid syntax"),
    ],
)
def test_python2_forms_are_refused_in_python3_decks(text, words):
    with pytest.raises(DeckSyntaxError) as info:
        parse_deck(text, "deck.comm", python2=False)
    assert words in info.value.message


def test_print_is_a_function_in_python3_decks_and_a_statement_in_python2_decks():
    _, lines, module = run("print('a', 1)\n")
    assert not module.python2 and lines == ["a 1\n"]
    lines = []
    namespace = base_namespace(limits=SMALL, print_hook=lines.append)
    module = parse_deck("print('a', 1)\n", "deck.comm", python2=True)
    Evaluator(namespace, limits=SMALL).run(module)
    assert lines == ["('a', 1)\n"]  # Python 2 prints the tuple


def test_a_python2_deck_is_of_code_aster_13_or_older():
    assert deck_version("DEBUT()\nprint 'x'\nFIN()\n") == PYTHON2_LAST
    assert deck_version("DEBUT()\nprint('x')\nFIN()\n") == 17


def test_python2_functions_compile_unless_they_use_python2_meaning():
    text = (
        "print 'python 2'\ndef f(x):\n    return x * 2.0\ndef g(x):\n    return x / 2\n"
        "def h(d):\n    return d.keys()\na = f(1.0)\nb = g(7)\nc = h({1: 2})\n"
    )
    namespace, _, _ = run(text)
    assert namespace["f"].arity == 1  # compiled
    assert namespace["g"].arity == -1 and namespace["b"] == 3  # '/' of Python 2: interpreted
    assert namespace["h"].arity == -1 and namespace["c"] == [1]


def test_port_writes_python2_syntax_as_python3():
    text, notes, skipped = to_python3(PYTHON2_DECK, "deck.comm")
    assert not skipped
    module = parse_deck(text, "deck.comm", python2=False)
    assert not module.python2
    for expected in (
        "x = 0o777 + 10\n",
        "n = 7 // 2\n",
        "y = 7 / 2.\n",
        "if x != 3:\n",
        'print("x =", x, end=" ")\n',
        "print(repr(n))\n",
        "print()\n",
        "except ZeroDivisionError as e:\n",
        "s = r'a\\n'\n",
        'raise ValueError("old style")\n',
    ):
        assert expected in text, expected
    changes = {(note.old, note.line) for note in notes}
    assert ("a /= b", 21) in changes  # kept, and said
    assert ("d.has_key()", 17) in changes


def test_port_leaves_a_python3_deck_alone():
    text = "DEBUT()\nx = 7 / 2\nprint(x)\nFIN()\n"
    assert to_python3(text, "deck.comm") == (text, [], [])
