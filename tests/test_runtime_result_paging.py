"""Results' fields and assembled matrices moved to disk past their share of the run's memory limit
(asterlite.runtime.result_paging): the same values, read from a map."""

from __future__ import annotations

import numpy as np
import pytest

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


def _matrix(n=4000, seed=0, complex_values=False):
    """A symmetric assembled matrix of about 1.2 MB of terms and 0.6 MB of
    column indices per 1e5 terms (data and indices past MIN_FIELD_BYTES)."""
    import scipy.sparse as sp

    from asterlite.concepts.assembly import AssembledMatrix, ComplexAssembledMatrix

    rng = np.random.default_rng(seed)
    a = sp.random(n, n, density=0.02, format="csr", random_state=rng)
    a = (a + a.T + sp.identity(n) * n).tocsr()
    a.sum_duplicates()
    kind = AssembledMatrix
    if complex_values:
        a, kind = (a * (1.0 + 0.05j)).tocsr(), ComplexAssembledMatrix
    return kind(small_transient().basis.numbering, a)


@pytest.mark.parametrize("complex_values", [False, True])
def test_past_the_share_the_newest_matrix_goes_to_disk_and_reads_the_same(complex_values):
    import scipy.sparse as sp
    import scipy.sparse.linalg as spla

    held, new = _matrix(seed=1), _matrix(seed=2, complex_values=complex_values)
    expected = new.matrix.copy()
    one = RP.held_in_memory({"OLD": held})
    assert one == held.matrix.data.nbytes + held.matrix.indices.nbytes  # indptr: small
    limit_mb = 1.5 * one / RP.watchdog.MEGABYTE / RP.RESULT_MEMORY_SHARE  # one fits, not two
    assert RP.page_out({"OLD": held}, held, limit_mb) == []
    assert RP.page_out({"OLD": held}, new, limit_mb) == ["matrix.data", "matrix.indices"]
    m = new.matrix
    assert RP.on_disk(m.data) and RP.on_disk(m.indices) and not RP.on_disk(m.indptr)
    assert not RP.on_disk(held.matrix.data)
    assert m.data.dtype == expected.data.dtype and m.indices.dtype == expected.indices.dtype
    np.testing.assert_array_equal(m.data, expected.data)
    np.testing.assert_array_equal(m.indices, expected.indices)
    # the readers of a matrix get the same values from the maps, bit for bit
    v = np.random.default_rng(3).normal(size=m.shape[0])
    rows = np.arange(0, m.shape[0], 3)
    for read in (
        lambda x: (x + 2.0 * x).toarray(),
        lambda x: x @ v,
        lambda x: (x @ x).toarray(),
        lambda x: x[100:900][:, rows].toarray(),
        lambda x: x.tocsc().toarray(),
        lambda x: x.copy().toarray(),
        lambda x: sp.triu(x, format="csc").toarray(),
        lambda x: spla.splu(x.tocsc()).solve(v.astype(x.dtype)),
    ):
        np.testing.assert_array_equal(read(m), read(expected))
    assert RP.held_in_memory({"OLD": held, "NEW": new}) == one  # on disk: not counted
    assert RP.page_out({"OLD": held, "NEW": new}, new, limit_mb) == []  # already on disk


def test_the_share_counts_results_and_matrices_together():
    result, matrix = _result(seed=6), _matrix(seed=7)
    both = RP.held_in_memory({"R": result, "M": matrix})
    fields = RP.held_in_memory({"R": result})
    assert both == fields + matrix.matrix.data.nbytes + matrix.matrix.indices.nbytes
    limit_mb = (fields + 1024) / RP.watchdog.MEGABYTE / RP.RESULT_MEMORY_SHARE
    assert RP.page_out({"R": result}, matrix, limit_mb) == ["matrix.data", "matrix.indices"]
    assert not any(RP.on_disk(values) for values in result.fields.values())


def test_without_a_memory_limit_matrices_stay_in_memory():
    matrix = _matrix(seed=8)
    assert RP.page_out({"A": _matrix(seed=9), "B": _result(seed=10)}, matrix, 0) == []
    assert not RP.on_disk(matrix.matrix.data) and not RP.on_disk(matrix.matrix.indices)


def test_a_concept_declares_its_pageable_arrays():
    from asterlite.concepts.assembly import AssembledMatrix, ComplexAssembledMatrix, NodalField

    assert AssembledMatrix.PAGED_ARRAYS == ("matrix.data", "matrix.indices")
    assert ComplexAssembledMatrix.PAGED_ARRAYS == AssembledMatrix.PAGED_ARRAYS
    field = NodalField(small_transient().basis.numbering, np.arange(200_000.0))
    assert RP.page_out({}, field, 1e-6) == ["values"]
    assert RP.on_disk(field.values)
    np.testing.assert_array_equal(field.values, np.arange(200_000.0))
