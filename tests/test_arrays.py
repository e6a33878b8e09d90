"""asterlite.arrays: what numpy does slowly, done otherwise, same results."""

from __future__ import annotations

import numpy as np
import pytest

from asterlite.arrays import sorted_unique


@pytest.mark.parametrize("dtype", [np.int32, np.int64, np.uint8, bool])
def test_sorted_unique_equals_numpy_unique(dtype):
    rng = np.random.default_rng(0)
    values = rng.integers(0, 200, (50, 7)).astype(dtype)
    result = sorted_unique(values)
    assert result.dtype == np.unique(values).dtype
    np.testing.assert_array_equal(result, np.unique(values))
    assert sorted_unique(np.zeros(0, dtype)).size == 0


def test_sorted_unique_of_floats_is_numpys_nans_included():
    values = np.array([3.0, np.nan, 1.0, np.nan, 3.0])
    np.testing.assert_array_equal(sorted_unique(values), np.unique(values))
