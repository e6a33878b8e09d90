"""Packed tabulated functions: interpolation and code_aster's prolongations."""

import math

import numpy as np
import pytest
from hypothesis import given, settings
from hypothesis import strategies as st

from asterlite.concepts.function import interpolate
from asterlite.dynamics.laws.tabulated import (
    Curve,
    LawError,
    function_table,
    pack,
    table_size,
    value,
    value_and_slope,
)

X = np.array([0.0, 1.0, 3.0, 4.0])
Y = np.array([1.0, 3.0, -1.0, 2.0])


@pytest.mark.parametrize("left", ["CONSTANT", "LINEAIRE", "EXCLU"])
@pytest.mark.parametrize("right", ["CONSTANT", "LINEAIRE", "EXCLU"])
def test_matches_reference_interpolation(left, right):
    table = np.concatenate([[7.0, 7.0], pack(X, Y, left, right)])  # offset 2 inside a larger array
    for x in np.linspace(-2.0, 6.0, 81):
        outside = (x < X[0] and left == "EXCLU") or (x > X[-1] and right == "EXCLU")
        got = value(table, 2, x)
        if outside:
            assert math.isnan(got)
        else:
            assert got == pytest.approx(float(interpolate(x, X, Y, left=left, right=right)))
    assert table_size(table, 2) == 3 + 2 * X.size


def test_slope_and_single_point():
    table = pack(X, Y, "LINEAIRE", "CONSTANT")
    assert value_and_slope(table, 0, 2.0) == pytest.approx((1.0, -2.0))
    assert value_and_slope(table, 0, -1.0) == pytest.approx((-1.0, 2.0))
    assert value_and_slope(table, 0, 9.0) == pytest.approx((2.0, 0.0))
    single = pack([2.0], [5.0], "CONSTANT", "EXCLU")
    assert value(single, 0, 1.0) == 5.0
    assert math.isnan(value(single, 0, 3.0))


def test_function_table_checks():
    with pytest.raises(LawError, match="increase strictly"):
        pack([0.0, 0.0], [1.0, 2.0])
    with pytest.raises(LawError, match="INTERPOL"):
        function_table(Curve(X, Y, INTERPOL=("LOG", "LIN")), "F")
    with pytest.raises(LawError, match="prolongation"):
        pack(X, Y, "NOPE")
    block = function_table(Curve(X, Y, "LINEAIRE", "LINEAIRE"), "F")
    assert value(block, 0, 5.0) == pytest.approx(5.0)


@settings(max_examples=60, deadline=None)
@given(
    st.lists(st.floats(-1e3, 1e3), min_size=2, max_size=12, unique=True),
    st.floats(-2e3, 2e3),
    st.sampled_from(["CONSTANT", "LINEAIRE"]),
)
def test_random_tables_agree_with_numpy(xs, x, side):
    xs = np.sort(np.asarray(xs))
    if np.any(np.diff(xs) < 1e-6):
        return
    ys = np.cos(xs)
    table = pack(xs, ys, side, side)
    expected = float(interpolate(x, xs, ys, left=side, right=side))
    assert value(table, 0, x) == pytest.approx(expected, rel=1e-9, abs=1e-9)
