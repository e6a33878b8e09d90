"""CREA_TABLE FONCTION as code_aster's op0036: a real function gives two
columns (its parameter and result names, or PARA); a complex function
(fonction_c) gives three real columns, the abscissa then <result>_R and
<result>_I, which CALC_TABLE and TEST_TABLE then read by those names."""

from __future__ import annotations

import numpy as np
import pytest

from asterlite.concepts.function import ComplexFunction, Function
from asterlite.errors import CommandError
from tests.test_fem_support import FakeSession, run


def test_complex_function_gives_real_and_imaginary_columns():
    func = ComplexFunction(
        np.array([1.0, 2.0]), np.array([1.0 + 2.0j, -3.0 - 0.5j]), NOM_PARA="FREQ", NOM_RESU="DX"
    )
    table = run(FakeSession(), "CREA_TABLE", FONCTION={"FONCTION": func})
    assert list(table.columns) == ["FREQ", "DX_R", "DX_I"]
    assert table.column("FREQ") == [1.0, 2.0]
    assert table.column("DX_R") == [1.0, -3.0]
    assert table.column("DX_I") == [2.0, -0.5]


def test_para_names_the_columns_of_a_complex_function():
    func = ComplexFunction(np.array([0.0]), np.array([0.5j]), NOM_PARA="FREQ", NOM_RESU="DX")
    table = run(FakeSession(), "CREA_TABLE", FONCTION={"FONCTION": func, "PARA": ("F", "U")})
    assert list(table.columns) == ["F", "U_R", "U_I"]
    assert table.column("U_I") == [0.5]


def test_real_function_keeps_two_columns_and_same_names_are_refused():
    func = Function(np.array([0.0, 1.0]), np.array([2.0, 3.0]), NOM_PARA="INST", NOM_RESU="DX")
    table = run(FakeSession(), "CREA_TABLE", FONCTION={"FONCTION": func})
    assert list(table.columns) == ["INST", "DX"] and table.column("DX") == [2.0, 3.0]
    with pytest.raises(CommandError, match="both 'X'"):
        run(FakeSession(), "CREA_TABLE", FONCTION={"FONCTION": func, "PARA": ("X", "X")})
