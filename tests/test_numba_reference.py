"""numba's results kept as fingerprints (tests/numba_reference.py): the
fingerprint tells apart what assert_array_equal tells apart, and only that;
a difference fails, by field; the stored file was recorded from today's
sources and names only tests that exist."""

from __future__ import annotations

import json
import re

import numpy as np
import pytest

from tests import numba_reference as R


def test_fingerprints_equal_where_assert_array_equal_does():
    a = np.array([[1.0, -0.0, np.nan], [2.5, 3.0, 4.0]])
    b = a.copy()
    b[0, 1] = 0.0  # assert_array_equal: -0.0 == 0.0
    b[0, 2] = -np.nan  # and NaN == NaN, whatever its sign and payload
    np.testing.assert_array_equal(a, b)
    assert R.fingerprint(a) == R.fingerprint(b)
    c = a.copy()
    c[1, 0] = np.nextafter(2.5, 3.0)  # one unit in the last place
    assert R.fingerprint(c) != R.fingerprint(a)
    assert R.fingerprint(a.reshape(3, 2)) != R.fingerprint(a)  # shape
    assert R.fingerprint(a.astype(np.float32)) != R.fingerprint(a)  # type
    assert R.fingerprint(np.arange(3)) != R.fingerprint(np.arange(3.0))
    assert R.fingerprint(-0.0) == R.fingerprint(0.0) and R.fingerprint(0.1) == "0.1"
    with pytest.raises(TypeError, match="no fingerprint for a object"):
        R.fingerprint(object())


def test_a_difference_fails_and_names_its_field():
    numba = R.fingerprint({"depl": np.ones(3), "info": {"steps": 7}})
    R.assert_same({"depl": np.ones(3), "info": {"steps": 7}}, numba, "run")
    with pytest.raises(AssertionError, match="run: differs from numba's in depl"):
        R.assert_same({"depl": np.nextafter(np.ones(3), 2.0), "info": {"steps": 7}}, numba, "run")
    stored = R.Stored(R.digest_of(numba))
    R.assert_same({"depl": np.ones(3), "info": {"steps": 7}}, stored, "run")
    with pytest.raises(AssertionError, match="run: differs from numba's"):
        R.assert_same({"depl": np.ones(3), "info": {"steps": 8}}, stored, "run")
    with pytest.raises(AssertionError, match="failure"):
        R.assert_same("stopped at t=1", R.fingerprint("stopped at t=2"), "failure")


def test_another_platform_computes_numbas_side_even_in_ci(monkeypatch, tmp_path):
    """A file recorded on another platform is not read: the reference is
    computed, in CI too (its last bits may differ there, not its sources)."""
    store = tmp_path / "fingerprints.json"
    key = "tests/test_numba_reference.py::test_another_platform_computes_numbas_side_even_in_ci#0"
    entry = {key: R.digest_of(R.fingerprint(1.0))}
    text = json.dumps({"sources": R.sources_digest(), "platform": "elsewhere", "entries": entry})
    store.write_text(text)
    monkeypatch.setattr(R, "STORE", store)
    monkeypatch.setattr(R, "_stored", None)
    monkeypatch.setenv("CI", "true")
    monkeypatch.delenv(R.MODE_VARIABLE, raising=False)

    class Request:
        node = type("Node", (), {"nodeid": key[:-2], "get_closest_marker": lambda *a: None})()

    assert not R.same_platform() and R.stored() == {}
    assert R.reference(Request(), lambda: 2.0) == R.fingerprint(2.0)  # computed, not read


def test_the_stored_fingerprints_are_current():
    data = json.loads(R.STORE.read_text())
    if data.get("platform") != R.platform_signature():
        pytest.skip(
            f"recorded on {data.get('platform')!r}, not {R.platform_signature()!r}: "
            "numba's side is computed by the tests themselves here"
        )
    assert data["sources"] == R.sources_digest(), (
        "numba's sources or the native tests changed since the fingerprints were "
        "recorded: run `python tests/numba_reference.py` (it compiles numba's loops)"
    )
    assert data["entries"], "no fingerprint recorded"
    for key in data["entries"]:
        path, name = re.fullmatch(r"(tests/[\w.]+)::(\w+)(?:\[.*\])?#\d+", key).groups()
        source = (R.ROOT / path).read_text()
        assert f"def {name}(" in source, f"{key}: no such test (record them again)"
