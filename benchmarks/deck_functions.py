"""Deck-defined functions: calls per second, before and after compilation.

The functions are read from the corpus decks themselves (``def`` blocks of
sdnd124d, sdnd110c, sdnd124b, sdld102f in ../shared/aster-corpus*), with the
deck-level constants they use, plus a two-branch function of the kind
users write for a nonlinear force. Each is measured

- called from Python (``map(f, values)``, ``f(x)``): the function alone;
- behind a FORMULE (``VALE="F(INST)"``) tabulated on 20 000 instants, as
  CALC_FONC_INTERP does.

"before" is the tree-walking evaluator of the commit given by ``--before``
(default: the last commit before deck functions were compiled), loaded from
git into a scratch module; "after" is the working tree's evaluator, which
compiles deck functions (asterlite.lang.compiler). "python" is the same
source run by CPython, for scale. Each figure is the best of 5 runs, each
run in freshly compiled measuring code, timed in CPU seconds of the process
(steadier than wall time on a shared machine) (CPython's call-site specialisation
would otherwise carry over from one function to the next).

    python benchmarks/deck_functions.py [--before COMMIT] [--points N]
"""

from __future__ import annotations

import argparse
import importlib.util
import math
import re
import subprocess
import sys
import tempfile
import time
from pathlib import Path

import numpy as np

from asterlite.lang import Evaluator, Limits, base_namespace, parse_deck

ROOT = Path(__file__).resolve().parents[1]
SHARED = ROOT.parent / "shared"
BASELINE_COMMIT = "41d4f8f"
LIMITS = Limits(max_loop_iterations=10**10)  # the benchmark makes millions of calls

# (deck, function, constants it reads from the deck, argument of the calls)
CORPUS_FUNCTIONS = [
    ("sdnd124d", "Rampe", "", 7.3),
    ("sdnd124d", "FDeplax", "", 7.3),
    ("sdnd124d", "FAccey", "", 7.3),
    ("sdnd110c", "PyAcce", "f1, f2, f3 = 2.0, 5.0, 11.0\na1, a2, a3 = 0.1, 0.02, 0.005\n", 0.37),
    ("sdnd124b", "FctRp", "Sy, Su, Kp, Puiss = 200.0, 400.0, 1.0e5, 2.0\n", 0.002),
    ("sdld102f", "KX", "k = 1.0e4\n", 0.01),
]
# helpers some functions call, defined in the same decks
HELPERS = {"FDeplax": ["Rampe"], "FAccey": ["Rampe", "DRampe"]}
TWO_BRANCH = """
def FORCE(DX):
    if DX < 0.0:
        return 0.0
    return 1.0e4 * DX
"""

BENCH_SOURCE = """
def run(function, argument, count):
    for _ in range(count):
        function(argument)
"""


def find_deck(name: str) -> Path | None:
    for folder in sorted(SHARED.glob("aster-corpus*")):
        path = folder / name / f"{name}.comm"
        if path.is_file():
            return path
    return None


def function_source(text: str, name: str) -> str:
    """The ``def name(...)`` block of a deck, up to the next unindented line."""
    match = re.search(rf"^def {name}\(.*?(?=^\S)", text, re.S | re.M)
    if match is None:
        raise SystemExit(f"no function {name} in the deck")
    return match.group(0)


def benchmark_sources() -> dict[str, str]:
    """{function name: deck text defining it (numpy as NU, math names, constants)}."""
    sources = {"FORCE": TWO_BRANCH}
    for deck, name, constants, _ in CORPUS_FUNCTIONS:
        path = find_deck(deck)
        if path is None:
            print(f"(skipped {name}: {deck} not found under {SHARED})")
            continue
        text = path.read_text(encoding="utf-8", errors="replace")
        blocks = [function_source(text, n) for n in [*HELPERS.get(name, []), name]]
        sources[name] = "import numpy as NU\n" + constants + "\n".join(blocks)
    return sources


def load_evaluator(commit: str):
    """The Evaluator class of ``commit``, from git, in a scratch module."""
    text = subprocess.run(
        ["git", "show", f"{commit}:asterlite/lang/evaluator.py"],
        cwd=ROOT,
        capture_output=True,
        text=True,
        check=True,
    ).stdout
    folder = Path(tempfile.mkdtemp(prefix="asterlite-before-"))
    path = folder / "evaluator_before.py"
    path.write_text(text, encoding="utf-8")
    spec = importlib.util.spec_from_file_location("evaluator_before", path)
    module = importlib.util.module_from_spec(spec)
    spec.loader.exec_module(module)
    return module.Evaluator


def deck_function(evaluator_class, source: str, name: str):
    namespace = base_namespace(limits=LIMITS)
    evaluator_class(namespace, limits=LIMITS).run(parse_deck(source, f"{name}.comm"))
    return namespace[name]


def python_function(source: str, name: str):
    """The same source run by CPython (for scale only)."""
    namespace = {"NU": np, **{k: getattr(math, k) for k in dir(math) if not k.startswith("_")}}
    exec(compile(source.replace("import numpy as NU\n", ""), name, "exec"), namespace)  # noqa: S102
    return namespace[name]


def calls_per_second(function, argument, budget: float = 0.3) -> float:
    """Best of 5 runs of about ``budget`` seconds each."""
    namespace: dict = {}
    exec(compile(BENCH_SOURCE, "<bench>", "exec"), namespace)  # noqa: S102 - fresh call site
    run = namespace["run"]
    function(argument)  # compiles it, if it compiles
    count = 10
    while True:
        start = time.process_time()
        run(function, argument, count)
        elapsed = time.process_time() - start
        if elapsed > budget / 10 or count > 10**7:
            break
        count *= 4
    count = max(int(count * budget / max(elapsed, 1e-9)), 1)
    best = math.inf
    for _ in range(5):
        start = time.process_time()
        run(function, argument, count)
        best = min(best, time.process_time() - start)
    return count / best


def formula_calls_per_second(function, name: str, points: int) -> float:
    """Points per second of a FORMULE calling ``function``, tabulated at once."""
    from asterlite.concepts.function import Formula

    formula = Formula(VALE=f"{name}(INST)", NOM_PARA=("INST",), extra={name: function})
    instants = np.linspace(0.0, 20.0, points)
    formula.evaluate(instants[:10])
    best = math.inf
    for _ in range(3):
        start = time.process_time()
        formula.evaluate(instants)
        best = min(best, time.process_time() - start)
    return points / best


def main(argv=None) -> None:
    parser = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    parser.add_argument(
        "--before", default=BASELINE_COMMIT, help="commit of the 'before' evaluator"
    )
    parser.add_argument("--points", type=int, default=20_000, help="instants of the FORMULE runs")
    options = parser.parse_args(argv)
    before_class = load_evaluator(options.before)
    sources = benchmark_sources()
    arguments = {name: argument for _, name, _, argument in CORPUS_FUNCTIONS}
    arguments["FORCE"] = 0.01
    print(f"python {sys.version.split()[0]}, calls per second (best of 5)")
    header = f"{'function':10} {'python':>10} {'before':>10} {'after':>10} {'speed-up':>9}"
    print(header + f"   {'FORMULE before':>15} {'FORMULE after':>14} {'speed-up':>9}")
    for name, source in sources.items():
        argument = arguments[name]
        native = calls_per_second(python_function(source, name), argument)
        old = deck_function(before_class, source, name)
        new = deck_function(Evaluator, source, name)
        before = calls_per_second(old, argument, budget=0.2)
        after = calls_per_second(new, argument)
        old_points = min(options.points, 2_000)  # the old path is slow: fewer points
        formula_before = formula_calls_per_second(old, name, old_points)
        formula_after = formula_calls_per_second(new, name, options.points)
        compiled = "" if new.arity >= 0 else "  (not compiled)"
        print(
            f"{name:10} {native:10.3g} {before:10.3g} {after:10.3g} {after / before:8.1f}x"
            f"   {formula_before:15.3g} {formula_after:14.3g} "
            f"{formula_after / formula_before:8.1f}x{compiled}"
        )


if __name__ == "__main__":
    main()
