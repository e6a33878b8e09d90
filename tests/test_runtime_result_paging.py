"""Results' fields moved to disk past their share of the run's memory limit
(asterlite.runtime.result_paging): the same values, read from a map."""

from __future__ import annotations

import numpy as np

from asterlite.concepts.transient import DynaTrans
from asterlite.runtime import result_paging as RP
from tests.test_post_support import small_transient


def _result(n_instants=200, n_dofs=1000, seed=0):
    numbering = small_transient().basis.numbering
    rng = np.random.default_rng(seed)
    fields = {name: rng.normal(size=(n_instants, n_dofs)) for name in ("DEPL", "VITE")}
    fields["SMALL"] = np.ones((3, 4))
    return DynaTrans(numbering, np.arange(n_instants, dtype=float), np.arange(n_instants), fields)


def test_past_the_share_the_newest_results_fields_go_to_disk_with_their_values():
    held, new = _result(seed=1), _result(seed=2)  # 3.05 MB of large fields each
    expected = {name: values.copy() for name, values in new.fields.items()}
    namespace = {"OLD": held, "N": 3}
    limit_mb = 4.5 / RP.RESULT_MEMORY_SHARE  # 4.5 MB allowed: one result fits, not two
    assert RP.page_out(namespace, held, limit_mb) == []  # within the share
    moved = RP.page_out(namespace, new, limit_mb)
    assert moved == ["DEPL", "VITE"]
    for name, values in new.fields.items():
        assert RP.on_disk(values) == (name != "SMALL")
        assert values.shape == expected[name].shape and values.dtype == expected[name].dtype
        np.testing.assert_array_equal(values, expected[name])
    assert not any(RP.on_disk(values) for values in held.fields.values())
    assert RP.held_in_memory(namespace | {"NEW": new}) == RP.held_in_memory(namespace)
    assert RP.page_out(namespace | {"NEW": new}, new, limit_mb) == []  # already on disk


def test_without_a_memory_limit_results_stay_in_memory():
    result = _result()
    assert RP.page_out({"A": _result(seed=3)}, result, 0) == []
    assert not any(RP.on_disk(values) for values in result.fields.values())


def test_a_field_on_disk_is_written_into_as_before():
    values = RP.to_disk(np.arange(24.0).reshape(2, 3, 4))
    assert RP.on_disk(values) and values.shape == (2, 3, 4)
    values[1, 2, 3] = -5.0  # a copy-on-write map: this process's copy only
    assert values[1, 2, 3] == -5.0 and values.sum() == np.arange(24.0).sum() - 23.0 - 5.0
    assert not RP.on_disk(np.ones(3)) and RP.on_disk(values[0])


def test_a_field_the_disk_cannot_take_stays_in_memory(monkeypatch, tmp_path):
    held, new = _result(seed=4), _result(seed=5)
    limit_mb = 4.5 / RP.RESULT_MEMORY_SHARE

    def full(values, folder=None):
        raise OSError(28, "No space left on device")

    monkeypatch.setattr(RP, "to_disk", full)
    assert RP.page_out({"OLD": held}, new, limit_mb, tmp_path) == []
    monkeypatch.undo()
    monkeypatch.setattr(RP, "_file_cap", lambda: 1024)  # every field past the output limit
    assert RP.page_out({"OLD": held}, new, limit_mb, tmp_path) == []
    assert not any(RP.on_disk(values) for values in new.fields.values())
    monkeypatch.undo()
    assert RP.page_out({"OLD": held}, new, limit_mb, tmp_path) == ["DEPL", "VITE"]
