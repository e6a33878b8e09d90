"""NaN and infinite inputs are refused where they enter, with a located
message; FORMULE computes with Python's numbers (exact integers, no 64-bit
wrap), in the Python evaluation and in the kernels' programs alike.

A NaN gap or stiffness silently switches a shock off (every comparison with
NaN is false) and used to let the run PASS; an infinite stiffness or end
instant ended in an unlocated traceback.
"""

from __future__ import annotations

import math
import re
from pathlib import Path

import numpy as np
import pytest

from asterlite.concepts.function import Formula
from asterlite.dynamics.formula import STACK_DEPTH, formula_program, program_tables, run_program
from asterlite.runtime.runner import run_deck
from tests.test_extremes_decks import Chain, Shock, write

# ------------------------------------------------------------------ DYNA_VIBRA keywords


def shock_deck(folder: Path, old: str, new: str) -> tuple[Path, int]:
    """A one-mass deck with a frictional PLAN_Y shock, ``old`` replaced by
    ``new``; returns the export and the line of the DYNA_VIBRA call."""
    chain = Chain(
        shocks=[Shock(1, 0.001, 1.0e6, c_n=5.0, mu=0.3, k_t=1.0e5)], depl={1: (0, 0.01, 0)}
    )
    export = write(chain, folder)
    comm = export.with_suffix(".comm")
    text = comm.read_text()
    assert text.count(old) == 1, old
    text = text.replace(old, new)
    comm.write_text(text)
    line = text[: text.index("DYNA_VIBRA(")].count("\n") + 1
    return export, line


CHOC, K_N = "COMPORTEMENT[1]", "RIGI_NOR=1000000.0"
SHOCK_CASES = [
    ("NaN JEU", "JEU=0.001", 'JEU=float("nan")', f"{CHOC}/JEU", "nan"),
    ("NaN RIGI_NOR", K_N, 'RIGI_NOR=float("nan")', f"{CHOC}/RIGI_NOR", "nan"),
    ("NaN AMOR_NOR", "AMOR_NOR=5.0", 'AMOR_NOR=float("nan")', f"{CHOC}/AMOR_NOR", "nan"),
    ("NaN COULOMB", "COULOMB=0.3", 'COULOMB=float("nan")', f"{CHOC}/COULOMB", "nan"),
    # a literal beyond the float range is inf in Python
    ("inf RIGI_NOR", K_N, "RIGI_NOR=1.0E+999", f"{CHOC}/RIGI_NOR", "inf"),
    ("inf INST_FIN", "INST_FIN=0.1", 'INST_FIN=float("inf")', "INCREMENT[1]/INST_FIN", "inf"),
    ("numpy NaN scalar", "JEU=0.001", "JEU=np.float32(np.nan)", f"{CHOC}/JEU", "nan"),
    ("integer beyond floats", K_N, "RIGI_NOR=10**400", f"{CHOC}/RIGI_NOR", "range"),
]


def assert_located(report, deck: Path, line: int, *fragments: str) -> None:
    assert report.exit_code == 2, (report.status, report.message)
    assert f"{deck}:{line}:" in report.message, report.message
    for fragment in fragments:
        assert fragment in report.message, f"{fragment!r} not in:\n{report.message}"


@pytest.mark.parametrize("check_only", [True, False], ids=["check", "run"])
@pytest.mark.parametrize(
    "name, old, new, path, shown", SHOCK_CASES, ids=[c[0] for c in SHOCK_CASES]
)
def test_non_finite_dyna_vibra_keyword_is_refused(
    tmp_path, check_only, name, old, new, path, shown
):
    export, line = shock_deck(tmp_path / "deck", old, new)
    if "np." in new:
        comm = export.with_suffix(".comm")
        comm.write_text("import numpy as np\n" + comm.read_text())
        line += 1
    target = export.with_suffix(".comm") if check_only else export
    report = run_deck(target, None if check_only else tmp_path / "out", check_only=check_only)
    comm = export.with_suffix(".comm").resolve()
    assert_located(report, comm, line, f"DYNA_VIBRA/{path}", "finite", shown)
    assert not (tmp_path / "out" / "results.h5").exists()


# ------------------------------------------------------------- decks of a few commands


def small_deck(folder: Path, text: str, files: dict[str, tuple[str | bytes, int]] = ()) -> Path:
    """A deck and its data files (name -> (content, unit)); returns the export."""
    folder.mkdir(parents=True, exist_ok=True)
    (folder / "deck.comm").write_text(text)
    lines = ["P time_limit 60", "F comm deck.comm D 1"]
    for name, (content, unit) in dict(files).items():
        path = folder / name
        if isinstance(content, bytes):
            path.write_bytes(content)
        else:
            path.write_text(content)
        lines.append(f"F {'mmed' if name.endswith('.med') else 'libr'} {name} D {unit}")
    export = folder / "deck.export"
    export.write_text("\n".join(lines) + "\n")
    return export


def line_of(text: str, fragment: str) -> int:
    return text[: text.index(fragment)].count("\n") + 1


NUMPY_DECK = """import numpy as np
DEBUT()
VALUES = np.array([0.0, 1.0, 1.0, np.nan])
F = DEFI_FONCTION(NOM_PARA="INST", VALE=VALUES)
FIN()
"""


@pytest.mark.parametrize("check_only", [True, False], ids=["check", "run"])
def test_numpy_array_with_nan_given_to_a_keyword(tmp_path, check_only):
    export = small_deck(tmp_path / "deck", NUMPY_DECK)
    target = export.with_suffix(".comm") if check_only else export
    report = run_deck(target, None if check_only else tmp_path / "out", check_only=check_only)
    comm = export.with_suffix(".comm").resolve()
    line = line_of(NUMPY_DECK, "DEFI_FONCTION")
    assert_located(report, comm, line, "DEFI_FONCTION/VALE", "value 4", "finite", "nan")


def test_list_with_inf_given_to_defi_list_reel(tmp_path):
    text = 'DEBUT()\nL = DEFI_LIST_REEL(VALE=[0.0, 1.0, float("-inf")])\nFIN()\n'
    export = small_deck(tmp_path / "deck", text)
    report = run_deck(export.with_suffix(".comm"), check_only=True)
    comm = export.with_suffix(".comm").resolve()
    assert_located(report, comm, 2, "DEFI_LIST_REEL/VALE", "value 3", "-inf")


def test_defi_list_reel_span_beyond_the_float_range(tmp_path):
    text = (
        "DEBUT()\nL = DEFI_LIST_REEL(DEBUT=-1.0E+308,\n"
        "    INTERVALLE=_F(JUSQU_A=1.0E+308, NOMBRE=2))\nFIN()\n"
    )
    export = small_deck(tmp_path / "deck", text)
    report = run_deck(export, tmp_path / "out")
    comm = export.with_suffix(".comm").resolve()
    assert_located(report, comm, 3, "DEFI_LIST_REEL/INTERVALLE[1]/JUSQU_A", "range")


# -------------------------------------------------------------------------------- meshes

MESH_DECK = """DEBUT()
MAIL = LIRE_MAILLAGE(FORMAT="{fmt}", UNITE=20)
FIN()
"""


def test_nan_coordinate_in_an_aster_mesh(tmp_path):
    mesh = " COOR_3D\n N1 0.0 0.0 0.0\n N2 1.0 nan 0.0\n FINSF\n SEG2\n S1 N1 N2\n FINSF\n FIN\n"
    export = small_deck(tmp_path / "deck", MESH_DECK.format(fmt="ASTER"), {"deck.mail": (mesh, 20)})
    report = run_deck(export, tmp_path / "out")
    comm = export.with_suffix(".comm").resolve()
    mail = (tmp_path / "deck" / "deck.mail").resolve()
    assert_located(report, comm, 2, "LIRE_MAILLAGE/UNITE", f"{mail}:3:", "node N2", "nan")


def test_overflowing_coordinate_in_an_aster_mesh(tmp_path):
    mesh = " COOR_2D\n N1 0.0 0.0\n N2 1.0D+999 0.0\n FINSF\n POI1\n P1 N1\n FINSF\n FIN\n"
    export = small_deck(tmp_path / "deck", MESH_DECK.format(fmt="ASTER"), {"deck.mail": (mesh, 20)})
    report = run_deck(export, tmp_path / "out")
    comm = export.with_suffix(".comm").resolve()
    assert_located(report, comm, 2, "deck.mail:3:", "node N2", "inf")


def test_nan_coordinate_in_a_med_mesh(tmp_path):
    mc = pytest.importorskip("medcoupling")
    coords = mc.DataArrayDouble([0.0, 0.0, 0.0, 1.0, math.nan, 0.0, 2.0, 0.0, 0.0], 3, 3)
    coords.setInfoOnComponents(["X", "Y", "Z"])
    segments = mc.MEDCouplingUMesh("BAR", 1)
    segments.allocateCells(2)
    segments.insertNextCell(mc.NORM_SEG2, [0, 1])
    segments.insertNextCell(mc.NORM_SEG2, [1, 2])
    segments.finishInsertingCells()
    segments.setCoords(coords)
    med = mc.MEDFileUMesh()
    med.setName("BAR")
    med.setMeshAtLevel(0, segments)
    med.setNameFieldAtLevel(1, mc.DataArrayAsciiChar([n.ljust(16) for n in ("A", "B", "C")]))
    folder = tmp_path / "deck"
    folder.mkdir()
    med.write(str(folder / "bar.med"), 2)
    export = small_deck(folder, MESH_DECK.format(fmt="MED"), {})
    export.write_text(export.read_text() + "F mmed bar.med D 20\n")
    report = run_deck(export, tmp_path / "out")
    comm = export.with_suffix(".comm").resolve()
    assert_located(report, comm, 2, "LIRE_MAILLAGE/UNITE", "bar.med", "node B", "nan")


# -------------------------------------------------------------------------- LIRE_FONCTION

LIRE_DECK = """DEBUT()
F = LIRE_FONCTION(UNITE=21, NOM_PARA="INST", INDIC_PARA=(2, 1), INDIC_RESU=(2, 2))
FIN()
"""


@pytest.mark.parametrize("bad", ["nan", "-inf", "1.0D+999"])
def test_non_finite_value_in_a_lire_fonction_file(tmp_path, bad):
    data = f"first block\n0.0 1.0\n\nsecond block\n0.0 1.0\n1.0 2.0\n2.0 {bad}\n"
    export = small_deck(tmp_path / "deck", LIRE_DECK, {"data.txt": (data, 21)})
    report = run_deck(export, tmp_path / "out")
    comm = export.with_suffix(".comm").resolve()
    assert_located(report, comm, 2, "LIRE_FONCTION/UNITE", "data.txt", "unit 21", "block 2, line 7")


# ------------------------------------------------------------------------------- FORMULE


def run_program_at(formula: Formula, t: float) -> float:
    program = formula_program(formula)
    assert program is not None, formula.VALE
    codes, constants = program_tables([program])
    return run_program(codes, constants, 0, t, np.zeros(STACK_DEPTH))


def test_formula_integer_powers_are_python_integers():
    """10**19 exceeds int64: Python computes it exactly, numpy used to wrap it."""
    formula = Formula(VALE="X * 10**19", NOM_PARA="X")
    assert formula(1.0) == 1.0e19
    np.testing.assert_array_equal(formula.evaluate(np.array([1.0, -2.0])), [1.0e19, -2.0e19])
    exact = Formula(VALE="X * ((2**53 + 1) - 2**53) + 3**40 // 3**39", NOM_PARA="X")
    assert exact(2.0) == 2.0 + 3.0
    assert Formula(VALE="X * N**K", NOM_PARA="X", extra={"N": 10, "K": 19})(1.0) == 1.0e19


def test_formula_compiled_program_follows_python_integers():
    """The kernels' program gives Python's value: integer arithmetic is done
    exactly once (float steps made (2**53 + 1) - 2**53 zero)."""
    for text, expected in [
        ("INST * 10**19", 2.0e19),
        ("INST * ((2**53 + 1) - 2**53)", 2.0),
        ("INST * N**K", 2.0e19),
    ]:
        formula = Formula(VALE=text, NOM_PARA="INST", extra={"N": 10, "K": 19})
        assert run_program_at(formula, 2.0) == expected, text
        assert formula(2.0) == expected, text


def test_formula_integer_overflowing_floats_is_located(tmp_path):
    """Python raises where an integer exceeds the floats: no compiled inf, a
    located error from the Python evaluation."""
    formula = Formula(VALE="INST * 10**400", NOM_PARA="INST")
    assert formula_program(formula) is None  # left to the sampled path, which reports it
    text = 'DEBUT()\nF = FORMULE(VALE="INST * 10**400", NOM_PARA="INST")\nV = F(1.0)\nFIN()\n'
    export = small_deck(tmp_path / "deck", text)
    report = run_deck(export, tmp_path / "out")
    comm = export.with_suffix(".comm").resolve()
    assert_located(report, comm, 3, "INST * 10**400", "too large")


def test_formula_overflow_checked_in_a_deck(tmp_path):
    text = (
        "DEBUT()\n"
        'F = FORMULE(VALE="X * 10**19", NOM_PARA="X")\n'
        "TEST_FONCTION(VALEUR=_F(FONCTION=F, VALE_PARA=1.0, VALE_CALC=1.0E+19))\n"
        "FIN()\n"
    )
    report = run_deck(small_deck(tmp_path / "deck", text), tmp_path / "out")
    assert report.status == "PASS", report.message


def test_formula_non_finite_value_names_the_formula_and_the_point(tmp_path):
    text = 'DEBUT()\nRATIO = FORMULE(VALE="1.0 / (X - 2.0)", NOM_PARA="X")\nV = RATIO(2.0)\nFIN()\n'
    export = small_deck(tmp_path / "deck", text)
    report = run_deck(export, tmp_path / "out")
    comm = export.with_suffix(".comm").resolve()
    assert_located(report, comm, 3, "formula RATIO", "inf", "X=2.0")


def test_formula_nan_extra_value_is_refused(tmp_path):
    text = 'DEBUT()\nF = FORMULE(VALE="X if X < A else 0.0", A=float("nan"), NOM_PARA="X")\nFIN()\n'
    export = small_deck(tmp_path / "deck", text)
    report = run_deck(export, tmp_path / "out")
    comm = export.with_suffix(".comm").resolve()
    assert_located(report, comm, 2, "FORMULE", "A=nan", "finite")


def test_formula_scalar_condition_evaluates_only_the_branch_taken():
    formula = Formula(VALE="X + (1 // 0 if N < 0 else 2)", NOM_PARA="X", extra={"N": 1})
    assert formula(1.0) == 3.0
    with pytest.raises(Exception, match=re.escape("integer //")):
        Formula(VALE="X + (1 // 0 if N > 0 else 2)", NOM_PARA="X", extra={"N": 1})(1.0)


# ------------------------------------------------------------------ catalogue values


@pytest.mark.parametrize(
    "types, value",
    [
        (("R",), math.nan),
        (("R", "fonction_sdaster"), -math.inf),
        (("C",), complex(0.0, math.nan)),
        (("C",), ("RI", 1.0, math.inf)),
        (("C",), ("MP", math.nan, 0.0)),
        (("R",), np.float64(np.inf)),
    ],
)
def test_catalogue_refuses_non_finite_reals_and_complexes(types, value):
    from asterlite.catalog.values import TypeMismatch, accept

    with pytest.raises(TypeMismatch, match="finite"):
        accept(types, value)


def test_catalogue_keeps_large_finite_reals():
    from asterlite.catalog.values import accept

    assert accept(("R",), 1.0e99) == 1.0e99
    assert accept(("R",), 10**300) == 1.0e300
    assert accept(("C",), ("RI", 1.0e300, -1.0e300)) == complex(1.0e300, -1.0e300)
