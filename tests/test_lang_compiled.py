"""Compiled deck functions (asterlite.lang.compiler) behave exactly as the
tree-walking interpreter: same values, same errors at the same places, same
steps counted, and the same guards (names, attributes, loop and size limits,
call depth, time)."""

from __future__ import annotations

import numpy as np
import pytest

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

SMALL = Limits(
    max_loop_iterations=5_000,
    max_sequence_length=10_000,
    max_int_digits=200,
    max_string_length=10_000,
    max_call_depth=12,
)


class Recorder(DeckCallable):
    """A command: records its keywords and the name its result is assigned to."""

    def __init__(self):
        self.calls = []

    def deck_call(self, args, kwargs, site: CallSite):
        self.calls.append((tuple(args), dict(kwargs), site.assigned_name, site.location.line))
        return len(self.calls)


def outcome(text: str, compiled: bool, limits: Limits = SMALL):
    """(names the deck bound, error, steps, command calls) with or without compiling."""
    namespace = base_namespace(limits=limits)
    namespace["U"] = Unknown
    namespace["CMD"] = Recorder()
    namespace["np"] = None
    evaluator = Evaluator(namespace, limits=limits, compile_functions=compiled)
    error = None
    try:
        evaluator.run(parse_deck(text, "deck.comm"))
    except AsterliteError as caught:
        location = caught.location
        error = (
            type(caught).__name__,
            caught.message,
            location and location.line,
            location and location.column,
        )
    names = {
        key: _comparable(value)
        for key, value in namespace.items()
        if key.startswith("r") and not callable(value)
    }
    functions = [v for v in namespace.values() if hasattr(v, "arity")]
    return names, error, evaluator.steps, namespace["CMD"].calls, functions


def _comparable(value):
    if isinstance(value, np.ndarray):
        return ("array", value.tolist())
    if isinstance(value, float) and value != value:
        return "nan"
    return repr(value)


def assert_same(text: str, limits: Limits = SMALL, must_compile: bool = True):
    interpreted = outcome(text, compiled=False, limits=limits)
    compiled = outcome(text, compiled=True, limits=limits)
    assert compiled[:4] == interpreted[:4]
    if must_compile:
        called = [f for f in compiled[4] if f.compile_tried]
        assert called and all(f.arity >= 0 for f in called), "a function was not compiled"
    return compiled


CASES = {
    "float arithmetic": """
def f(t, a=2.0):
    return a * t ** 2 - t / 3.0 + 1 // 2 + t % 1.5 - -t
r1 = f(1.5); r2 = f(2, 3); r3 = f(U); r4 = f(3, a=U)
""",
    "int and mixed arithmetic": """
def f(i, j):
    return i * j + i // j - i % j + i ** 2 - 2 ** j, i / j
r1 = f(7, 3); r2 = f(7.0, 3); r3 = f(2, 0.5); r4 = f(True, 2)
""",
    "sequences": """
def f(s, n):
    return s * n, n * s, s + s, s[1], s[-1:], s[::2]
r1 = f("abc", 3); r2 = f([1, 2], 2); r3 = f((1, 2, 3), 2)
""",
    "string formatting": """
def f(x):
    return "%s=%5.2f" % ("x", x), "v" + str(x), "a" * 3
r1 = f(1.25)
""",
    "comparisons and chains": """
def f(x, y):
    return (x < y, x <= y < 10, 0 < x < y < 5, x == y, x != y, x in [1, 2], x not in (3,),
            x is None, x is not None, "a" < "b", y > 1 > x)
r1 = f(1, 2); r2 = f(3, 1); r3 = f(U, 2); r4 = f(1, U); r5 = f(1.5, 1.5)
""",
    "boolean logic and ternary": """
def f(x):
    a = x and 1 or 2
    b = not x
    c = 1 if x else 0
    return a, b, c, not not x
r1 = f(0); r2 = f(3); r3 = f(U); r4 = f([])
""",
    "branches": """
def Rampe(t):
    if t <= 0.0:
        return 0.0
    if t <= 5.0:
        return t / 5.0
    elif t <= 15.0:
        return 1.0
    else:
        if t <= 20.0:
            return (20.0 - t) / 5.0
    return 0.0
r1 = [Rampe(t) for t in (-1.0, 2.5, 10, 17.5, 30.0)]; r2 = Rampe(U)
""",
    "loops": """
def f(n):
    total = 0.0
    for i in range(n):
        if i == 2:
            continue
        if i > 6:
            break
        total += i * 0.5
    else:
        total = -total
    k = 0
    while k < n:
        k += 1
    else:
        k = k * 10
    return total, k
r1 = f(4); r2 = f(20); r3 = f(U)
""",
    "tuple unpacking": """
def f(pairs):
    out = []
    for u, (v, w) in pairs:
        a, b = v, w
        [c, d] = [u, a]
        out.append(c + d + b)
    return out
r1 = f([(1, (2, 3)), (4, [5, 6])]); r2 = f(U)
""",
    "items and stores": """
def f(x):
    d = {"a": 1, (1, 2): 3}
    d["b"] = x
    lst = [0, 0, 0]
    lst[1] = x
    lst[-1] += 5
    lst[0:2] = [7]
    s = {1, 2}
    return d, lst, d[(1, 2)], s
r1 = f(4); r2 = f(U)
""",
    "unknown into a list": """
def f(x):
    lst = [1, 2]
    lst[0] = x
    return lst
r1 = f(3); r2 = f(U)
""",
    "locals fall back to deck names": """
g = 10
def f(flag):
    if flag:
        g = 1
    return g
def h():
    g = g + 1
    return g
r1 = f(True); r2 = f(False); r3 = h()
""",
    "augmented names from the deck": """
acc = [1]
def f(v):
    acc += [v]
    return acc
r1 = f(2); r2 = acc
""",
    "calls of deck functions": """
def sq(x):
    return x * x
def f(x, k=1):
    return sq(x) + sq(k) + sq(x=2) + len([x]) + abs(-x) + max(x, k)
def g():
    pass
r1 = f(3); r2 = f(3, 2); r3 = f(3, k=4); r4 = g(); r5 = f(U)
""",
    "star arguments": """
def add(a, b, c=0):
    return a + b + c
def f(args, kw):
    return add(*args), add(1, **kw), max(*args)
r1 = f((1, 2), {"b": 5, "c": 1})
""",
    "commands from functions": """
def f(n):
    res = CMD(n, KEY=n * 2)
    CMD(res)
    return res
r1 = f(5)
""",
    "attributes": """
import math
def f(x, s):
    return math.pi * x, s.upper(), s.split(","), (1.5).is_integer(), [3, 1].count(1)
r1 = f(2.0, "a,b"); r2 = f(U, U)
""",
    "methods mutate": """
def f(n):
    out = []
    for i in range(n):
        out.append(i * i)
    out.extend([9])
    return out
r1 = f(4)
""",
    "math functions": """
def f(t):
    return sin(t) + cos(t) * exp(-t) + sqrt(abs(t)) + pow(t, 2) + atan2(t, 1.0)
r1 = f(0.3); r2 = f(U)
""",
    "recursion": """
def fact(n):
    if n <= 1:
        return 1
    return n * fact(n - 1)
r1 = fact(10)
""",
    "format of engine objects": """
def f():
    return '%s' % CMD, '{} {}'.format(1, 'a')
r1 = f()
""",
    "float locals and swaps": """
def f(t, s):
    k = 2.5
    if t > 1:
        k = -0.5
    a, b = t, k
    a, b = b, a
    c = d = 1.0
    return k * t, k * s, s * k, a, b, c / k, k ** 2
r1 = f(2.0, 3); r2 = f(U, 2); r3 = f(0.5, U)
""",
    "signed constants": """
def f(t):
    return -0.5 * t, -2 * t, +3 - t, t ** -1, -1.0 / 5.0, -2 ** 2, [1, 2] * -1
r1 = f(2.0); r2 = f(3); r3 = f(U)
""",
    "lambda": """
sq = lambda x, k=2: x ** k + 1
r1 = sq(3); r2 = list(map(sq, [1.0, 2.0])); r3 = sq(U)
""",
    "numpy arrays": """
import numpy as np
def f(a, b):
    return a * 2.0 + b, a[1], (a > 1.5).tolist(), np.sqrt(a) * b
r1 = f(np.array([1.0, 2.0, 3.0]), 1.0); r2 = f(np.linspace(0.0, 1.0, 3), np.ones(3))
""",
}

ERROR_CASES = {
    "unpack error": "def f(x):\n    a, b = x\n    return a\nr1 = f((1, 2))\nr2 = f((1, 2, 3))\n",
    "float local times a list": "def f(s):\n    k = 2.5\n    return k * s\nr1 = f([1])\n",
    "undefined name": "def f(x):\n    return x + missing\nr1 = f(1)\n",
    "undefined after branch": (
        "def f(x):\n    if x:\n        y = 1\n    return y\nr1 = f(1)\nr2 = f(0)\n"
    ),
    "division by zero": "def f(x):\n    a = 1.0\n    return a / x\nr1 = f(2)\nr2 = f(0.0)\n",
    "nested error": (
        "def g(x):\n    return [1][x]\ndef f(x):\n    return 1 + g(x)\nr1 = f(0)\nr2 = f(3)\n"
    ),
    "type error": "def f(x):\n    return x + 'a'\nr1 = f(1.0)\n",
    "bad attribute": "def f(x):\n    return x.hex()\nr1 = f(1.0)\n",
    "module attribute": "import math\ndef f():\n    return math.nothing\nr1 = f()\n",
    "not callable": "def f(x):\n    return x(1)\nr1 = f(2.0)\n",
    "arity": "def g(a):\n    return a\ndef f():\n    return g(1, 2)\nr1 = f()\n",
    "missing argument": "def g(a):\n    return a\ndef f():\n    return g()\nr1 = f()\n",
    "math domain": "def f(x):\n    return sqrt(x)\nr1 = f(-1.0)\n",
    "index error": "def f(x):\n    lst = [1]\n    lst[x] = 2\n    return lst\nr1 = f(5)\n",
    "truth of an array": (
        "import numpy as np\ndef f(a):\n    if a > 0:\n        return 1\n    return 0\n"
        "r1 = f(np.ones(3))\n"
    ),
    "for over a number": "def f(x):\n    for i in x:\n        pass\nr1 = f(3)\n",
    "unpack in for": "def f(x):\n    for a, b in x:\n        pass\nr1 = f([(1, 2, 3)])\n",
    "string repeat limit": "def f(n):\n    return 'ab' * n\nr1 = f(3)\nr2 = f(10 ** 6)\n",
    "list repeat limit": "def f(n):\n    x = [0]\n    return x * n\nr1 = f(10 ** 6)\n",
    "integer size limit": "def f(n):\n    return 10 ** n\nr1 = f(5)\nr2 = f(10 ** 4)\n",
    "integer product limit": "def f(n):\n    a = 10 ** 150\n    return a * a\nr1 = f(1)\n",
    "concat limit": ("def f(n):\n    s = 'x' * 6000\n    return s + s\nr1 = f(1)\n"),
    "list store limit": (
        "def f():\n    lst = [0] * 6000\n    lst[0:0] = lst\n    return lst\nr1 = f()\n"
    ),
    "loop limit": "def f():\n    while True:\n        pass\nr1 = f()\n",
    "for loop limit": (
        "def f():\n    n = 0\n    for i in range(4000):\n        for j in range(4):\n"
        "            n += 1\n    return n\nr1 = f()\n"
    ),
    "call depth": "def f(n):\n    return f(n + 1)\nr1 = f(0)\n",
    "mutual recursion depth": "def f(n):\n    return g(n)\ndef g(n):\n    return f(n)\nr1 = f(0)\n",
    "deep tuple key": (
        "def f(n):\n    t = 1\n    for i in range(n):\n        t = (t,)\n    d = {}\n"
        "    d[t] = 1\n    return d\nr1 = f(3)\nr2 = f(200)\n"
    ),
}


@pytest.mark.parametrize("name", sorted(CASES))
def test_compiled_functions_compute_what_the_interpreter_computes(name):
    names, error, _, _, _ = assert_same(CASES[name])
    assert error is None, error
    assert names


@pytest.mark.parametrize("name", sorted(ERROR_CASES))
def test_compiled_functions_fail_as_the_interpreter_fails(name):
    _, error, _, _, _ = assert_same(ERROR_CASES[name])
    assert error is not None
    assert error[2] is not None  # located


def test_guards_hold_on_the_compiled_path():
    """The size, loop and depth guards raise their own messages from compiled code."""
    cases = {
        "string repeat limit": "limit exceeded: string length",
        "list repeat limit": "limit exceeded: sequence length",
        "integer size limit": "limit exceeded: integer size in digits",
        "list store limit": "limit exceeded: sequence length",
        "loop limit": "limit exceeded: loop iterations and calls",
        "for loop limit": "limit exceeded: loop iterations and calls",
        "call depth": "limit exceeded: depth of nested function calls",
        "deep tuple key": "limit exceeded: levels of nested containers",
    }
    for name, message in cases.items():
        _, error, _, _, functions = outcome(ERROR_CASES[name], compiled=True)
        assert error is not None and error[1].startswith(message), (name, error)
        assert all(f.arity >= 0 for f in functions if f.compile_tried), name


def test_time_limit_stops_a_compiled_loop():
    limits = Limits(max_loop_iterations=10**12, max_seconds=0.3)
    text = "def f():\n    n = 0\n    while True:\n        n += 1\nr1 = f()\n"
    _, error, steps, _, functions = outcome(text, compiled=True, limits=limits)
    assert error[1].startswith("limit exceeded: seconds of deck evaluation")
    assert functions[0].arity == 0 and steps > 256


def test_compiled_code_reaches_no_python_builtins():
    """Names not bound by the deck are deck errors, never Python's builtins."""
    for name in ("eval", "exec", "getattr", "type", "object", "vars", "setattr"):
        text = f"def f():\n    return {name}\nr1 = f()\n"
        _, error, _, _, functions = outcome(text, compiled=True)
        assert error[1] == f"name '{name}' is not defined", name
        assert functions[0].arity == 0


def test_attributes_stay_whitelisted_on_the_compiled_path():
    text = "def f(x):\n    return x.conjugate(), x.real\nr1 = f(1.5)\n"
    names, error, _, _, _ = assert_same(text)
    assert error is None
    for attribute in ("mro", "format_map", "count"):
        text = f"def f(x):\n    return x.{attribute}\nr1 = f(2.0)\n"
        _, error, _, _, functions = outcome(text, compiled=True)
        assert "no attribute" in error[1] and functions[0].arity == 1


def test_functions_outside_the_compiled_subset_are_interpreted():
    text = """
def f(x):
    assert x > 0
    return [v * 2 for v in range(x)]
r1 = f(3)
"""
    compiled = assert_same(text, must_compile=False)
    assert compiled[4][0].arity == -1 and compiled[0]["r1"] == "[0, 2, 4]"


def test_formula_calls_go_through_evaluate_many():
    namespace = base_namespace()
    Evaluator(namespace).run(parse_deck("def f(t):\n    return 2.0 * t\n", "deck.comm"))
    function = namespace["f"]
    values = function.evaluate_many(np.array([[1.0, 2.0], [3.0, 4.0]]))
    assert values.tolist() == [[2.0, 4.0], [6.0, 8.0]] and function.arity == 1
    assert function.evaluate_many(np.float64(1.5)) == 3.0


def test_private_deck_names_do_not_meet_compiled_internals():
    """Helper files may use names with one underscore (code_aster's material
    files): the compiled code's own names start with two."""
    text = (
        "_b = 2.0\n_t1 = 3.0\ndef _f(_G, _T=1.0):\n    _U = _G * _b + _t1\n"
        "    return _U * _T\nr1 = _f(2.0)\n"
    )
    results = []
    for compiled in (False, True):
        namespace = base_namespace(limits=SMALL)
        evaluator = Evaluator(namespace, limits=SMALL, compile_functions=compiled)
        evaluator.run(parse_deck(text, "helper.py", private_names=True))
        results.append(namespace["r1"])
        if compiled:
            assert namespace["_f"].arity == 2
    assert results == [7.0, 7.0]


def test_deeply_nested_bodies_compile_or_fall_back_with_the_same_result():
    depth = 60
    expression = "(" * depth + "t" + " + 1.0)" * depth
    text = f"def f(t):\n    return {expression}\nr1 = f(0.5)\n"
    names, error, _, _, _ = assert_same(text, must_compile=False)
    assert error is None and names["r1"] == repr(60.5)
