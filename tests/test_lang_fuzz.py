"""Property tests: whatever text a deck holds, parsing and evaluating it either
succeeds or raises an AsterliteError, never another exception, never a hang."""

from __future__ import annotations

from pathlib import Path

import pytest
from hypothesis import HealthCheck, given, settings
from hypothesis import strategies as st

from asterlite.errors import AsterliteError
from asterlite.lang import (
    CallSite,
    DeckCallable,
    Evaluator,
    Limits,
    Unknown,
    base_namespace,
    parse_deck,
)

CORPUS = Path(__file__).resolve().parents[1].parent / "shared" / "aster-corpus"

# tight limits keep every example fast, whatever loop or allocation it writes
LIMITS = Limits(
    max_loop_iterations=2_000,
    max_sequence_length=20_000,
    max_int_digits=300,
    max_string_length=20_000,
    max_call_depth=16,
)
FUZZ = settings(
    max_examples=50,
    deadline=None,
    suppress_health_check=[HealthCheck.too_slow, HealthCheck.data_too_large],
)

SYNTHETIC_DECK = """\
from math import *
import numpy as np
DEBUT(CODE="OUI")
E = 2.1E+11
L = [1., 2.5e-3, -3]
def f(x, k=2):
    if x > 1:
        return x ** k
    elif x < -1:
        return -x
    else:
        return sqrt(abs(x))
t = np.linspace(0.0, 1.0, 11)
s = 0.0
for i, v in enumerate(L):
    s += f(v) * t[i]
MA = LIRE_MAILLAGE(FORMAT="ASTER", UNITE=20)
CH = AFFE_CHAR_MECA(MODELE=MA, DDL_IMPO=(_F(GROUP_NO="A", DX=0.0),), INFO=1)
n = 0
while n < 5:
    n += 1
names = ["N%d" % i for i in range(3) if i != 1]
M = {"a": (1, 2), "b": [x * 2 for x in L]}
print("done", MA.getName(), len(names), M["b"][1:])
FIN()
"""

TOKENS = [
    "x",
    "y",
    "MA",
    "f",
    "np",
    "L",
    "=",
    "==",
    "+",
    "-",
    "*",
    "**",
    "/",
    "//",
    "%",
    "(",
    ")",
    "[",
    "]",
    "{",
    "}",
    ",",
    ":",
    ".",
    ";",
    "1",
    "2.5",
    "1.E+04",
    "0",
    "10**9",
    "'s'",
    '"""t"""',
    "_F",
    "CO",
    "(",
    "if",
    "else",
    "elif",
    "for",
    "in",
    "while",
    "def",
    "return",
    "lambda",
    "not",
    "and",
    "or",
    "is",
    "None",
    "True",
    "pass",
    "break",
    "import",
    "from",
    "as",
    "numpy",
    "math",
    "print",
    "range",
    "len",
    "*",
    "\n",
    "\n    ",
    " ",
    "#",
    "\\\n",
    "@",
    "$",
    "class",
    "__class__",
    "del",
    "assert",
    "getName",
]


class Stub:
    """What a recorded command returns: every method yields Unknown."""

    deck_methods = frozenset({"getName"})

    def getName(self):  # noqa: N802
        return Unknown

    def deck_getattr(self, name):
        return Unknown


class Command(DeckCallable):
    def deck_call(self, args, kwargs, site: CallSite):
        return Stub()


class AutoCommands(dict):
    """A namespace where every undefined UPPERCASE name is a command, so mutated
    corpus decks run past their first command call."""

    def __missing__(self, name):
        if name.isupper():
            return Command()
        raise KeyError(name)


def fresh_namespace() -> dict:
    return AutoCommands(base_namespace(print_hook=lambda text: None, limits=LIMITS))


def check_text(text: str) -> None:
    """Parse and run text: only AsterliteErrors may escape."""
    try:
        module = parse_deck(text, "fuzz.comm")
        Evaluator(fresh_namespace(), limits=LIMITS).run(module)
    except AsterliteError as error:
        assert error.location is None or error.location.line >= 1
        str(error)  # rendering must not fail either


def mutate(text: str, data) -> str:
    """Apply a few random character- or line-level edits."""
    for _ in range(data.draw(st.integers(1, 4), label="edits")):
        if not text:
            break
        kind = data.draw(st.sampled_from(["delete", "duplicate", "swap", "lines", "insert"]))
        i = data.draw(st.integers(0, len(text) - 1), label="position")
        if kind == "delete":
            j = min(len(text), i + data.draw(st.integers(1, 5)))
            text = text[:i] + text[j:]
        elif kind == "duplicate":
            j = min(len(text), i + data.draw(st.integers(1, 8)))
            text = text[:j] + text[i:j] + text[j:]
        elif kind == "swap":
            j = data.draw(st.integers(0, len(text) - 1))
            chars = list(text)
            chars[i], chars[j] = chars[j], chars[i]
            text = "".join(chars)
        elif kind == "insert":
            text = text[:i] + data.draw(st.sampled_from(TOKENS)) + text[i:]
        else:
            lines = text.split("\n")
            a = data.draw(st.integers(0, len(lines) - 1))
            b = data.draw(st.integers(0, len(lines) - 1))
            lines[a], lines[b] = lines[b], lines[a]
            text = "\n".join(lines)
    return text


def test_synthetic_deck_runs_unmutated():
    namespace = fresh_namespace()
    Evaluator(namespace, limits=LIMITS).run(parse_deck(SYNTHETIC_DECK, "synthetic.comm"))
    assert namespace["n"] == 5 and namespace["names"] == ["N0", "N2"]


@FUZZ
@given(st.lists(st.sampled_from(TOKENS), max_size=40))
def test_token_soup(tokens):
    check_text(" ".join(tokens))


@FUZZ
@given(st.text(alphabet=st.characters(codec="utf-8"), max_size=80))
def test_arbitrary_text(text):
    check_text(text)


@FUZZ
@given(st.data())
def test_mutated_synthetic_deck(data):
    check_text(mutate(SYNTHETIC_DECK, data))


def _corpus_texts() -> list[str]:
    if not CORPUS.is_dir():
        return []
    paths = sorted(CORPUS.glob("*/*.comm"))[::6]  # a spread of decks keeps this fast
    return [path.read_text(encoding="utf-8")[:6000] for path in paths]


@FUZZ
@given(st.data())
def test_mutated_corpus_decks(data):
    texts = _corpus_texts()
    if not texts:
        pytest.skip("../shared/aster-corpus is absent")
    text = data.draw(st.sampled_from(texts), label="deck")
    check_text(mutate(text, data))
