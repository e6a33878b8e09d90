"""The Python that code_aster decks use, on the evaluator's terms (issue 27,
item 4): ``_`` names, try/except/else/finally, raise, with, f-strings,
cmath, os.path, globals(); what a deck may catch and what it never may;
the compiled path falls back to the interpreter for them."""

from __future__ import annotations

import math

import pytest

from asterlite.errors import (
    AsterliteError,
    CommandError,
    DeckRuntimeError,
    DeckSyntaxError,
    UnsupportedError,
)
from asterlite.lang import Evaluator, Limits, Unknown, base_namespace, parse_deck
from asterlite.lang.values import DeckCallable

SMALL = Limits(
    max_loop_iterations=10_000,
    max_sequence_length=100_000,
    max_int_digits=1_000,
    max_string_length=100_000,
    max_call_depth=20,
)


def run(text: str, namespace=None, limits: Limits = SMALL, compiled: bool = True, **kwargs):
    extra, namespace = (
        namespace or {},
        base_namespace(limits=limits, print_hook=kwargs.pop("hook", None)),
    )
    namespace.update(extra)
    evaluator = Evaluator(namespace, limits=limits, compile_functions=compiled, **kwargs)
    evaluator.run(parse_deck(text, "deck.comm"))
    return namespace


def error_of(text: str, kind=AsterliteError, **kwargs):
    with pytest.raises(kind) as info:
        run(text, **kwargs)
    return info.value


# ------------------------------------------------------------------ names


def test_deck_names_may_start_with_one_underscore():
    names = run(
        "_OMEGA = 6.4\n_nume_mode = (1, 2)\ntotal = 0\nfor _ in range(3):\n    total += 1\n"
        "def _f(_x):\n    return _x * _OMEGA\ny = _f(2.0)\n"
    )
    assert names["_OMEGA"] == 6.4 and names["total"] == 3 and names["y"] == 12.8
    assert names["_nume_mode"] == (1, 2)


def test_keyword_arguments_may_start_with_one_underscore():
    calls = []

    class Formula(DeckCallable):
        def deck_call(self, args, kwargs, site):
            calls.append(kwargs)

    run("_OMEGA = 6.4\nFORMULE(VALE='sin(INST*_OMEGA)', _OMEGA=_OMEGA)\n", {"FORMULE": Formula()})
    assert calls == [{"VALE": "sin(INST*_OMEGA)", "_OMEGA": 6.4}]


@pytest.mark.parametrize(
    "text, words",
    [
        ("__x = 1\n", "names starting with '__'"),
        ("x = (1).__class__\n", "attributes starting with '_'"),
        ("x = [1]._y\n", "attributes starting with '_'"),
        ("from math import _x\n", "attributes starting with '_'"),
        ("import numpy._core\n", "attributes starting with '_'"),
        ("def f(__a):\n    pass\n", "names starting with '__'"),
    ],
)
def test_double_underscores_and_underscore_attributes_stay_refused(text, words):
    error = error_of(text, DeckSyntaxError)
    assert words in error.message


# -------------------------------------------------------------------- try


def test_try_except_else_finally_run_in_python_order():
    lines = []
    run(
        "def f(v):\n"
        "    try:\n"
        "        r = 1 / v\n"
        "    except ZeroDivisionError as e:\n"
        "        print('except', e)\n"
        "        return -1\n"
        "    else:\n"
        "        print('else')\n"
        "    finally:\n"
        "        print('finally')\n"
        "    return r\n"
        "a = f(0)\nb = f(2)\n",
        hook=lines.append,
    )
    assert lines == ["except division by zero\n", "finally\n", "else\n", "finally\n"]


def test_exception_classes_follow_pythons_hierarchy():
    names = run(
        "found = []\n"
        "for text in ('k', 'i', 'z', 'v', 'n', 'a'):\n"
        "    try:\n"
        "        if text == 'k':\n            {}['x']\n"
        "        if text == 'i':\n            [][1]\n"
        "        if text == 'z':\n            1 // 0\n"
        "        if text == 'v':\n            int('x')\n"
        "        if text == 'n':\n            undefined\n"
        "        if text == 'a':\n            assert False, 'no'\n"
        "    except LookupError:\n        found.append('lookup')\n"
        "    except ArithmeticError:\n        found.append('arith')\n"
        "    except (ValueError, NameError) as e:\n        found.append(e.message[:4])\n"
        "    except Exception:\n        found.append('other')\n"
    )
    assert names["found"] == ["lookup", "lookup", "arith", "inva", "name", "other"]


def test_raise_and_reraise():
    names = run(
        "try:\n    raise ValueError('bad', 2)\nexcept ValueError as e:\n    args = e.args\n"
        "try:\n    try:\n        raise KeyError\n    except KeyError:\n        raise\n"
        "except LookupError:\n    outer = True\n"
        "try:\n    raise AsterError('x')\nexcept Exception as e:\n    kept = str(e)\n",
        {"AsterError": __import__("asterlite.lang.exceptions").lang.exceptions.ASTER_ERROR},
    )
    assert names["args"] == ("bad", 2) and names["outer"] and names["kept"] == "x"
    assert "e" not in names  # Python 3 unbinds the name after the handler


def test_an_uncaught_raise_is_a_located_deck_error():
    error = error_of("x = 1\nraise ValueError('the study needs X')\n", DeckRuntimeError)
    assert error.message == "ValueError: the study needs X"
    assert (error.location.line, error.location.column) == (2, 7)


@pytest.mark.parametrize(
    "text, words",
    [
        ("raise\n", "no active exception"),
        ("raise 3\n", "must derive from BaseException"),
        ("try:\n    1/0\nexcept 3:\n    pass\n", "do not derive from BaseException"),
    ],
)
def test_raise_and_except_take_exception_classes(text, words):
    assert words in error_of(text, DeckRuntimeError).message


def test_except_naming_something_else_is_located_at_its_expression():
    error = error_of("try:\n    1/0\nexcept len:\n    pass\n", DeckRuntimeError)
    assert (error.location.line, error.location.column) == (3, 8)


def test_code_aster_errors_of_commands_are_caught_as_aster_error():
    from asterlite.lang.exceptions import ASTER_CLASSES

    class Failing(DeckCallable):
        def deck_call(self, args, kwargs, site):
            raise CommandError("no file is mapped to logical unit 99")

    namespace = {
        "LIRE_MAILLAGE": Failing(),
        "CA_AsterError": ASTER_CLASSES["AsterError"],
        "CA_SolverError": ASTER_CLASSES["SolverError"],
    }
    found = run(
        "try:\n    MESH = LIRE_MAILLAGE(UNITE=99)\nexcept CA_AsterError as err:\n"
        "    message = err.message\nexcept Exception:\n    message = 'wrong handler'\n",
        namespace,
    )
    assert found["message"] == "no file is mapped to logical unit 99"
    assert "MESH" not in found  # the failed call bound nothing
    # an error code_aster raises as AsterError only is not a SolverError: it goes on
    error = error_of(
        "try:\n    MESH = LIRE_MAILLAGE(UNITE=99)\nexcept CA_SolverError:\n    pass\n",
        CommandError,
        namespace=namespace,
    )
    assert "logical unit 99" in error.message

    class EmptyBand(DeckCallable):
        def deck_call(self, args, kwargs, site):
            error = CommandError("no eigenmode found for this selection")
            error.aster_exception = "SolverError"  # as CALC_MODES names it
            raise error

    namespace["CALC_MODES"] = EmptyBand()
    found = run(
        "try:\n    MODES = CALC_MODES()\nexcept CA_SolverError:\n    caught = 'solver'\n",
        namespace,
    )
    assert found["caught"] == "solver"
    # code_aster's message identifiers are refused by name, not guessed
    error = error_of(
        "try:\n    LIRE_MAILLAGE(UNITE=99)\nexcept CA_AsterError as err:\n    i = err.id_message\n",
        UnsupportedError,
        namespace=namespace,
    )
    assert "message identifiers" in error.message


@pytest.mark.parametrize(
    "body",
    [
        "while True:\n        pass",  # the step limit
        "x = [0] * 10 ** 9",  # a size limit
        "x = (1).conjugate.imag",  # a whitelist refusal
        "x = open('f')",  # a feature asterlite refuses by name
        "import os\n    os.system('rm x')",
    ],
)
def test_limits_refusals_and_unsupported_features_are_never_caught(body):
    text = f"try:\n    {body}\nexcept:\n    caught = 1\nfinally:\n    cleaned = 1\n"
    namespace = base_namespace(limits=SMALL)
    with pytest.raises(AsterliteError):
        Evaluator(namespace, limits=SMALL).run(parse_deck(text, "deck.comm"))
    assert "caught" not in namespace and "cleaned" not in namespace  # the run is over


def test_a_loop_cannot_outlive_the_step_limit_by_catching_it():
    text = (
        "n = 0\nwhile True:\n    try:\n        while True:\n            n += 1\n"
        "    except:\n        pass\n"
    )
    error = error_of(text, DeckRuntimeError)
    assert "loop iterations" in error.message


def test_finally_runs_on_break_continue_and_return():
    names = run(
        "log = []\nfor i in range(3):\n    try:\n        if i == 0:\n            continue\n"
        "        if i == 2:\n            break\n    finally:\n        log.append(i)\n"
        "def f():\n    try:\n        return 1\n    finally:\n        log.append('f')\nr = f()\n"
    )
    assert names["log"] == [0, 1, 2, "f"] and names["r"] == 1


def test_the_deck_is_told_of_what_it_catches():
    seen = []
    namespace = base_namespace(limits=SMALL)
    evaluator = Evaluator(namespace, limits=SMALL)
    evaluator.caught_hook = lambda error, location: seen.append((error.message, location.line))
    evaluator.run(parse_deck("x = 1\ntry:\n    1/0\nexcept ZeroDivisionError:\n    pass\n", "d"))
    assert seen == [("ZeroDivisionError: division by zero", 4)]


def test_a_bare_except_must_be_last():
    error = error_of("try:\n    pass\nexcept:\n    pass\nexcept E:\n    pass\n", DeckSyntaxError)
    assert "must be last" in error.message and error.location.line == 3


# ------------------------------------------------------------------- with


class Context:
    def __init__(self, swallow=False):
        self.events = []
        self.swallow = swallow

    def deck_enter(self):
        self.events.append("enter")
        return 42

    def deck_exit(self, error, kind):
        self.events.append(("exit", None if kind is None else kind.name))
        return self.swallow


def test_with_takes_the_context_managers_asterlite_provides():
    plain, swallowing = Context(), Context(swallow=True)
    names = run(
        "with c as v:\n    x = v\nwith s:\n    1 / 0\ny = 2\n", {"c": plain, "s": swallowing}
    )
    assert names["x"] == 42 and names["y"] == 2
    assert plain.events == ["enter", ("exit", None)]
    assert swallowing.events == ["enter", ("exit", "ZeroDivisionError")]


def test_with_refuses_other_objects_and_skips_exits_when_the_run_ends():
    error = error_of("with [1, 2]:\n    pass\n", DeckRuntimeError)
    assert "cannot be used in a 'with' block" in error.message
    error = error_of("with open('f') as f:\n    pass\n", UnsupportedError)
    assert "open()" in error.message
    context = Context(swallow=True)
    with pytest.raises(DeckRuntimeError):
        run("with c:\n    while True:\n        pass\n", {"c": context})
    assert context.events == ["enter"]


# -------------------------------------------------------------- f-strings


def test_f_strings_format_as_python_does():
    names = run(
        "temp = 20.25\nw = 8\nd = {'T': [1.5]}\nname = 'abc'\n"
        "a = f'{temp:.1f}'\nb = f'{temp:>{w}.2f}|'\nc = f\"{d['T'][0]:.1f} {name!r} {name}\"\n"
        "e = f'{temp=}'\nf = f'{{}} {1 + 2}' 'x' f'{name.upper()}'\ng = F'''{temp\n:g}'''\n"
        "h = rf'\\n{name}'\n"
    )
    assert names["a"] == "20.2"
    assert names["b"] == "   20.25|"
    assert names["c"] == "1.5 'abc' abc"
    assert names["e"] == "temp=20.25"
    assert names["f"] == "{} 3xABC"
    assert names["g"] == "20.25"
    assert names["h"] == "\\nabc"


def test_f_strings_show_engine_objects_neutrally_and_respect_limits():
    names = run("x = f'{len} {print!r}'\n")
    assert names["x"] == "<function len> <function print>"
    error = error_of("x = f'{1:99999999}'\n", DeckRuntimeError)
    assert "string length" in error.message
    error = error_of("x = 'a' * 60000\ny = f'{x}{x}'\n", DeckRuntimeError)
    assert "string length" in error.message
    assert run("y = f'{x}'\n", {"x": Unknown})["y"] is Unknown


@pytest.mark.parametrize(
    "text, column, words",
    [
        ("x = f'{y.__dict__}'\n", 10, "attributes starting with '_'"),
        ("x = f'{__import__}'\n", 8, "names starting with '__'"),
        ("x = f'ab{c d}'\n", 10, "invalid expression"),
        ("x = f'{a'\n", 7, "not closed"),
    ],
)
def test_f_string_fields_are_checked_and_located(text, column, words):
    error = error_of(text, DeckSyntaxError)
    assert words in error.message and error.location.column == column


def test_an_error_inside_a_field_points_into_the_field():
    error = error_of("y = 0\nx = f'value: {1 / y:.3f}'\n", DeckRuntimeError)
    assert (error.location.line, error.location.column) == (2, 15)


# ---------------------------------------------------------- cmath, os.path


def test_cmath_and_os_path_string_functions():
    names = run(
        "from cmath import *\nimport cmath\nimport os.path as osp\nimport os\n"
        "r = sqrt(-4)\np = cmath.phase(-1)\nj = osp.join('a', 'b.med')\n"
        "s = os.path.splitext('x.resu.med')\nb = osp.basename('/a/b')\nsep = os.sep\n"
        "e = os.path.exists('fort.8')\n"
    )
    assert names["r"] == 2j and abs(names["p"] - 3.141592653589793) < 1e-15
    assert names["j"] == "a/b.med" and names["s"] == ("x.resu", ".med") and names["b"] == "b"
    assert names["sep"] == "/" and names["e"] is False  # no run, no output folder


@pytest.mark.parametrize(
    "text, kind, words",
    [
        ("import os\nx = os.environ\n", UnsupportedError, "os.environ"),
        ("import os\nos.getcwd()\n", UnsupportedError, "os.getcwd"),
        ("import os.path\nos.path.abspath('x')\n", UnsupportedError, "os.path.abspath"),
        ("import os\nos.path.exists('/etc/passwd')\n", DeckRuntimeError, "file name of the run"),
        ("import os\nos.path.isfile('../x')\n", DeckRuntimeError, "file name of the run"),
        ("import os\nos.path.join('a', 1)\n", DeckRuntimeError, "takes strings"),
    ],
)
def test_os_reaches_no_file_outside_the_run(text, kind, words):
    assert words in error_of(text, kind).message


def test_os_path_file_tests_see_the_output_folder_only(tmp_path):
    from asterlite.lang import stdlib

    (tmp_path / "fort.50").write_text("x")
    module = stdlib.os_module(lambda: tmp_path, SMALL)
    names = run("e = os.path.exists('fort.50')\nf = os.path.isfile('fort.51')\n", {"os": module})
    assert names["e"] is True and names["f"] is False


def test_globals_is_a_read_only_view_of_the_deck_names():
    names = run("A = 1\ng = globals()\nyes = 'A' in g\nno = 'B' in g\nv = g['A']\n")
    assert names["yes"] and not names["no"] and names["v"] == 1
    error = error_of("g = globals()\ng['A'] = 2\n", DeckRuntimeError)
    assert "does not support item assignment" in error.message


def test_an_import_of_a_module_asterlite_lacks_may_be_caught():
    names = run(
        "try:\n    import matplotlib\n    has = True\nexcept ImportError:\n    has = False\n"
    )
    assert names["has"] is False


# ------------------------------------------------------------- compiled path


@pytest.mark.parametrize(
    "body",
    [
        "    try:\n        return 1.0 / x\n    except ZeroDivisionError:\n        return -1.0\n",
        "    if x == 0.0:\n        raise ValueError('zero')\n    return 1.0 / x\n",
        "    return f'{x:.2f}'\n",
        "    with c:\n        y = 2.0 * x\n    return y\n",
    ],
)
def test_functions_with_the_new_constructs_run_interpreted_with_the_same_results(body):
    text = f"def f(x):\n{body}a = f(2.0)\ntry:\n    b = f(0.0)\nexcept ValueError:\n    b = 'v'\n"
    results = []
    for compiled in (False, True):
        names = run(text, {"c": Context()}, compiled=compiled)
        results.append((names["a"], names["b"]))
        assert names["f"].arity == -1  # refused by the compiler: interpreted
    assert results[0] == results[1]


def test_a_caught_error_shows_file_names_not_paths():
    class Failing(DeckCallable):
        def deck_call(self, args, kwargs, site):
            raise CommandError("the export /home/user/study/study.export maps units 20")

    from asterlite.lang.exceptions import ASTER_ERROR

    names = run(
        "try:\n    F()\nexcept E as err:\n    m = err.message\n    s = str(err)\n",
        {"F": Failing(), "E": ASTER_ERROR},
    )
    assert names["m"] == names["s"] == "the export study.export maps units 20"


def test_exception_arguments_are_text_within_the_limits():
    error = error_of("x = [[0] * 10 ** 5] * 10 ** 5\ne = ValueError(x)\n", DeckRuntimeError)
    assert "elements to convert to text" in error.message
    names = run("e = ValueError(len)\n")
    assert str(names["e"]) == "<function len>"


@pytest.mark.parametrize("compiled", [True, False])
def test_math_functions_take_one_element_arrays_as_numpy_1_did(compiled):
    # code_aster's numpy converts a one-element array to a float for math.sin;
    # numpy 2 refuses it, decks (shll102a) rely on it
    text = (
        "import numpy as NP\n"
        "def f(a):\n    return sin(a) + sqrt(a * a)\n"
        "x = NP.zeros([2, 1])\nx[0] = 0.5\ny = f(x[0])\nz = cos(NP.array([0.0, 1.0])[1:])\n"
    )
    namespace = run(text, compiled=compiled)
    assert namespace["y"] == pytest.approx(math.sin(0.5) + 0.5)
    assert namespace["z"] == pytest.approx(math.cos(1.0))
    with pytest.raises(AsterliteError):
        run("import numpy as NP\nw = sin(NP.array([0.0, 1.0]))\n", compiled=compiled)
