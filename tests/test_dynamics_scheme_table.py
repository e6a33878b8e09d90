"""Each GENE scheme is described once (asterlite.dynamics.schemes): the
catalogue, the warmup and the driver read the table, and no other module of
the transient keeps a table of scheme names."""

from __future__ import annotations

import ast
from pathlib import Path

from asterlite.catalogues.dyna_vibra import GENE_DEFAULT_SCHEME, GENE_SCHEMES

from asterlite.dynamics import schemes, warmup
from asterlite.dynamics.integrate import scheme_run_loop
from asterlite.dynamics.loop import scheme_loop

ROOT = Path(__file__).resolve().parent.parent
# where a scheme's name may still be written: its description, the tableaux of
# the Runge-Kutta pairs (their own names), the labels of the fluid-film runs
# (code_aster 10-12's EULER and ADAPT_ORDRE2), the scheme the warmup runs in
# the loops shared by every scheme
ALLOWED = {
    "asterlite/dynamics/schemes.py": None,
    "asterlite/dynamics/scheme_runge_kutta.py": 2,
    "asterlite/dynamics/fluid_film.py": 2,
    "commands/dyna_vibra.py": 2,
    "asterlite/dynamics/warmup.py": 1,
}


def test_every_described_scheme_has_its_module_and_is_in_the_catalogue():
    for entry in schemes.TABLE:
        module = entry.implementation()
        assert callable(module.prepare) and hasattr(module.step, "py_func"), entry.name
        assert entry.name in GENE_SCHEMES
    assert GENE_DEFAULT_SCHEME in schemes.SCHEMES


def test_each_loop_of_a_scheme_is_the_one_time_loop_or_its_fast_loop():
    """A scheme's own loop is its module's fast_loop when it has one
    (DIFF_CENTRE on diagonal and full matrices, NEWMARK), else the one time
    loop around its step; its general path is always that time loop."""
    fast = {"DIFF_CENTRE", "EULER", "NEWMARK"}
    for entry in schemes.TABLE:
        module = entry.implementation()
        for loop in entry.loop_names():
            run_loop = scheme_run_loop(entry, module, loop)
            if entry.name in fast and loop != schemes.GENERAL_PATH.format(entry.kernel):
                assert run_loop is module.fast_loop, (entry.name, loop)
            else:
                assert run_loop is scheme_loop(module.step), (entry.name, loop)
    assert {e.name for e in schemes.TABLE if hasattr(e.implementation(), "fast_loop")} == fast


def test_the_warmup_compiles_every_loop_of_the_table():
    assert set(schemes.kernels()) <= set(warmup.LOOPS)
    assert schemes.LEGACY_ADAPT_LOOP in warmup.LOOPS


def test_the_veri_pas_fractions_are_data_of_the_table():
    fractions = {entry.name: entry.step_fraction for entry in schemes.TABLE}
    assert fractions["NEWMARK"] == fractions["DEVOGE"] == 10.0
    assert fractions["DIFF_CENTRE"] == fractions["TRBDF2"] == 20.0
    assert not schemes.SCHEMES["RUNGE_KUTTA_32"].step_checked


def test_no_other_table_of_scheme_names():
    names = {entry.name for entry in schemes.TABLE} | {e.kernel for e in schemes.TABLE}
    files = sorted((ROOT / "asterlite" / "dynamics").glob("*.py"))
    files += sorted((ROOT / "commands").glob("dyna_vibra*.py"))
    found = {}
    for path in files:
        rel = path.relative_to(ROOT).as_posix()
        if rel in ("commands/dyna_vibra_phys.py", "commands/dyna_vibra_harm.py"):
            continue  # the physical and harmonic schemes are another family
        tree = ast.parse(path.read_text())
        count = sum(
            isinstance(node, ast.Constant) and node.value in names for node in ast.walk(tree)
        )
        if count:
            found[rel] = count
    for rel, count in found.items():
        assert rel in ALLOWED, f"{rel} names schemes {count} times"
        assert ALLOWED[rel] is None or count <= ALLOWED[rel], f"{rel}: {count}"
