"""Typed float loops of compiled deck functions (asterlite.lang.compiled_loops)
and the known-callee and module-member fast paths: same values, errors,
locations and step counts as the interpreter, whether the typed version
runs, gives up mid-loop or is never entered."""

from __future__ import annotations

import math

import pytest

from asterlite.lang import Evaluator, Limits, base_namespace, parse_deck
from tests.test_lang_compiled import SMALL, assert_same, outcome

RAMPS = """
def Rampe(t):
    if t <= 0.0:
        return 0.0
    if t <= 5.0:
        return t / 5.0
    if t <= 15.0:
        return 1.0
    if t <= 20.0:
        return (20.0 - t) / 5.0
    return 0.0
def DRampe(t):
    if t <= 0.0:
        return 0.0
    elif t <= 5.0:
        return 1.0 / 5.0
    else:
        return -1.0 / 5.0
"""

CASES = {
    "sdnd124d FAccey": RAMPS
    + """
import numpy as NU
def FAccey(t):
    uu = [0.20, 0.15, 0.10]
    ff = [0.80, 1.50, 3.00]
    ww = 2.0 * NU.pi
    zz = 0.0
    for u, f in zip(uu, ff):
        zz += (
            -u * ww * ww * f * f * sin(ww * t * f) * Rampe(t)
            + u * ww * f * cos(ww * t * f) * DRampe(t)
            + u * ww * f * cos(ww * t * f) * DRampe(t)
        )
    return zz
r1 = [FAccey(t) for t in (-1.0, 0.0, 2.5, 7.3, 17.0, 30.0)]
r2 = FAccey(U); r3 = FAccey(3); r4 = FAccey(2.0)
""",
    "branches, carried and fresh locals": RAMPS
    + """
k = 0.5
def f(t, n):
    acc = 0.0
    for x in n:
        y = x * k + Rampe(x)
        if y > 1.0:
            acc = acc + y
        elif y < -1.0:
            acc -= y * 2
        else:
            z = y ** 2
            acc += z / 3.0 - t % 2.0
    return acc
r1 = f(1.5, [0.5, 3.0, 8.0, -4.0, 19.0]); r2 = f(1.5, [1, 2.0]); r3 = f(2, [1.0, 2.0])
r4 = f(1.5, []); r5 = f(1.5, (2.0, U, 3.0)); r6 = f(1.5, range(3))
""",
    "lambda callee and math functions": """
g = lambda x: 2.0 * x - 1.0
def f(n):
    s = 0.0
    for x in n:
        s += g(x) + sqrt(abs(x)) + exp(-x) + atan2(x, 2.0) + pow(x, 2.0)
    return s
r1 = f([0.5, 1.5, 2.5]); r2 = f([0.5, -1.0])
""",
    "loop else and tuples of other sizes": """
def f(pairs):
    s = 0.0
    for a, b in pairs:
        s += a * b
    else:
        s = -s
    return s
r1 = f([(1.0, 2.0), (3.0, 4.0)]); r2 = f(zip([1.0, 2.0], [3.0, 4.0]))
r3 = f([(1.0, 2.0), [3.0, 4.0]]); r4 = f([(1.0, 2.0), (3, 4.0)])
""",
    "callee rebound between calls": RAMPS
    + """
def f(t):
    s = 0.0
    for x in [1.0, 2.0]:
        s += Rampe(t) * x
    return s
r1 = f(2.5)
def Rampe(t):
    return 3
r2 = f(2.5)
""",
    "chained assignment and big constants": """
def f(n):
    s = 0.0
    for x in n:
        a = b = x * 2.0
        s += a + b
    return s
def g(n):
    s = 0.0
    for x in n:
        s += x * 123456789012345678901234567890
    return s
r1 = f([1.0, 2.0]); r2 = g([1.0, 2.5]); r3 = g([1e300])
""",
    "structural builtins": """
def f(a, b):
    n = 0
    for i, (x, y) in enumerate(zip(a, b)):
        n += i + len(a)
    return n, list(range(3)), len(U) if False else 0
r1 = f([1, 2], [3, 4]); r2 = f(U, [1])
""",
    "module members": """
import numpy as NU
import math
def f(t):
    return NU.pi * t, math.e + t, NU.sqrt(t)
r1 = f(2.0); r2 = f(U)
""",
}

STATIC_CASES = {
    "constant lists zipped": """
def f(t):
    uu = [0.5, -0.25, 2.0]
    ff = (1.0, 3.0, -2.0, 7.0)
    s = 0.0
    for u, v in zip(uu, ff):
        s += u * sin(v * t)
    for u in uu:
        s = s * 0.5 + u
    else:
        s = -s
    return s
r1 = f(0.3); r2 = f(3); r3 = f(U)
""",
    "constant lists read elsewhere or assigned twice": """
def f(t):
    uu = [0.5, 0.25]
    vv = [1.0, 2.0]
    ww = [1.0, 2.0]
    ww = [3.0, 4.0]
    s = 0.0
    for u in uu:
        s += u * t
    for v in vv:
        s += v * t
    for w in ww:
        s += w * t
    vv.append(3.0)
    return s, vv
r1 = f(0.3)
""",
    "loop over constant lists in a branch": """
def f(t):
    uu = [0.5, 0.25]
    s = 0.0
    if t > 0.0:
        for u in uu:
            s += u * t
    return s
r1 = f(0.3); r2 = f(-1.0)
""",
    "zip rebound": """
def f(t):
    uu = [0.5, 0.25]
    s = 0.0
    for u, v in zip(uu, uu):
        s += u * v * t
    return s
r1 = f(2.0)
def zip(a, b):
    return [(1.0, 2.0)]
r2 = f(2.0)
""",
}

ERROR_CASES = {
    "math domain over constant lists": (
        "def f(t):\n    uu = [1.0, 1e300, 2.0]\n    s = 0.0\n    for u in uu:\n"
        "        s += sin(u * t)\n    return s\nr1 = f(1.0)\nr2 = f(1e10)\n"
    ),
    "step limit over constant lists": (
        "def g(x):\n    return 2.0 * x\n"
        "def f(t):\n    uu = [1.0, 2.0, 3.0]\n    s = 0.0\n    for u in uu:\n"
        "        s += g(u) * t\n    return s\n"
        "r1 = [f(0.5) for i in range(700)]\n"
    ),
    "math domain in a typed loop": (
        "def f(n):\n    s = 0.0\n    for x in n:\n        s += sqrt(x)\n    return s\n"
        "r1 = f([1.0, 4.0])\nr2 = f([1.0, -4.0, 9.0])\n"
    ),
    "division by zero in a typed loop": (
        "def f(n, d):\n    s = 0.0\n    for x in n:\n        s = s + x / d\n    return s\n"
        "r1 = f([1.0], 2.0)\nr2 = f([1.0, 2.0], 0.0)\n"
    ),
    "overflow of a power in a typed loop": (
        "def f(n):\n    s = 0.0\n    for x in n:\n        s += x ** 2\n    return s\n"
        "r1 = f([1.0, 2.0])\nr2 = f([1.0, 1e200])\n"
    ),
    "inlined callee raising": (
        "def g(x):\n    if x >= 0.0:\n        return 1.0 / x\n    return 0.0 * x\n"
        "def f(n):\n    s = 0.0\n    for x in n:\n        s += g(x)\n    return s\n"
        "r1 = f([-1.0, 0.5])\nr2 = f([1.0, 0.0, 2.0])\n"
    ),
    "step limit inside a typed loop": (
        "def g(x):\n    return 2.0 * x\n"
        "def f():\n    s = 0.0\n    for x in [1.0] * 3000:\n"
        "        s += g(x) + g(s)\n    return s\n"
        "r1 = f()\n"
    ),
    "depth limit of an inlined callee": (
        "def g(x):\n    return 2.0 * x\n"
        "def f(n, k):\n    if k > 0:\n        return f(n, k - 1)\n    s = 0.0\n    for x in n:\n"
        "        s += g(x)\n    return s\n"
        "r1 = f([1.0], 3)\nr2 = f([1.0], 11)\n"
    ),
    "missing name read in a typed loop": (
        "def f(n):\n    s = 0.0\n    for x in n:\n        s += x * missing\n    return s\n"
        "r1 = f([])\nr2 = f([1.0])\n"
    ),
}


@pytest.mark.parametrize("name", sorted(CASES))
def test_typed_loops_compute_what_the_interpreter_computes(name):
    namespace_names, error, _, _, _ = assert_same(CASES[name])
    assert error is None, error
    assert namespace_names


@pytest.mark.parametrize("name", sorted(STATIC_CASES))
def test_loops_over_constant_lists_compute_what_the_interpreter_computes(name):
    namespace_names, error, _, _, _ = assert_same(STATIC_CASES[name])
    assert error is None, error
    assert namespace_names


@pytest.mark.parametrize("name", sorted(ERROR_CASES))
def test_typed_loops_fail_as_the_interpreter_fails(name):
    _, error, _, _, _ = assert_same(ERROR_CASES[name])
    assert error is not None and error[2] is not None


def test_the_typed_loop_runs_and_takes_the_same_steps():
    """The sdnd124d function takes the typed path (its hoisted callees) and
    counts one step per iteration and per inlined call."""
    text = CASES["sdnd124d FAccey"]
    from asterlite.lang import compiled_loops

    built = []
    original = compiled_loops.FastLoop.build

    def spy(self, *args):
        result = original(self, *args)
        built.append(self.calls)
        return result

    compiled_loops.FastLoop.build = spy
    try:
        interpreted = outcome(text, compiled=False)
        compiled = outcome(text, compiled=True)
    finally:
        compiled_loops.FastLoop.build = original
    assert built == [3]
    assert compiled[:4] == interpreted[:4]


def test_step_limit_trips_at_the_same_step_across_deadline_periods():
    """Steps cross several deadline periods (256) and the limit inside a
    typed loop: the same count and the same error as the interpreter."""
    for limit in (255, 256, 257, 700, 1023, 1024, 1025):
        limits = Limits(max_loop_iterations=limit, max_call_depth=12)
        text = (
            "def g(x):\n    return 2.0 * x\n"
            "def f(m):\n    s = 0.0\n    for x in [1.0] * m:\n        s += g(x) + g(s) + g(x)\n"
            "    return s\n"
            "r1 = f(50)\nr2 = f(400)\n"
        )
        assert_same(text, limits=limits)


def test_typed_loop_values_match_python_exactly():
    namespace = base_namespace(limits=SMALL)
    definitions = CASES["sdnd124d FAccey"].split("r1 =")[0]
    Evaluator(namespace, limits=SMALL).run(parse_deck(definitions, "deck.comm"))
    ww = 2.0 * math.pi

    def rampe(t):
        return (
            0.0
            if t <= 0.0
            else t / 5.0
            if t <= 5.0
            else 1.0
            if t <= 15.0
            else ((20.0 - t) / 5.0 if t <= 20.0 else 0.0)
        )

    def drampe(t):
        return 0.0 if t <= 0.0 else 1.0 / 5.0 if t <= 5.0 else -1.0 / 5.0

    for t in (0.3, 7.3, 16.1):
        expected = 0.0
        for u, f in zip([0.20, 0.15, 0.10], [0.80, 1.50, 3.00], strict=True):
            expected += (
                -u * ww * ww * f * f * math.sin(ww * t * f) * rampe(t)
                + u * ww * f * math.cos(ww * t * f) * drampe(t)
                + u * ww * f * math.cos(ww * t * f) * drampe(t)
            )
        assert namespace["FAccey"](t) == expected
