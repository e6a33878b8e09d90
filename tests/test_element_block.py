"""Element blocks kept as packed upper triangles (asterlite.concepts.element_block)
and their assembly."""

from __future__ import annotations

from types import SimpleNamespace

import numpy as np
import pytest

from asterlite.concepts.element_block import (
    ElementBlock,
    computed_block,
    is_symmetric,
    pack,
    unpack,
)
from asterlite.fem.assemble import CHUNK_TERMS, assemble_blocks


@pytest.fixture(autouse=True)
def _pack_every_block(monkeypatch, request):
    """Blocks of any size are kept half here (the default keeps small ones whole)."""
    if "small_blocks" not in request.node.name:
        monkeypatch.setattr("asterlite.concepts.element_block.PACK_BYTES", 0)


def test_small_blocks_stay_whole():
    rng = np.random.default_rng(7)
    matrices = _symmetric(rng, 3, 4)
    block = ElementBlock(np.array([[0, 1], [1, 2], [2, 3]]), ("DX", "DY"), matrices)
    assert not block.symmetric and block.matrices is matrices
    computed = computed_block(np.arange(3)[:, None], ("DX", "DY", "DZ"), lambda a, b: matrices[a:b])
    assert not computed.symmetric


def _symmetric(rng, n_elements, d, dtype=float):
    a = rng.standard_normal((n_elements, d, d))
    if dtype is complex:
        a = a + 1j * rng.standard_normal((n_elements, d, d))
    return a + a.transpose(0, 2, 1)


def _numbering(n_nodes, components):
    dofs = [(node, c) for node in range(n_nodes) for c in components]
    return SimpleNamespace(mesh=SimpleNamespace(n_nodes=n_nodes), dofs=dofs, n_dofs=len(dofs))


def _dense_assembly(nodes, components, matrices, n_dofs):
    out = np.zeros((n_dofs, n_dofs), dtype=matrices.dtype)
    k = len(components)
    for element, cell in enumerate(nodes):
        idx = np.array([node * k + c for node in cell for c in range(k)])
        out[np.ix_(idx, idx)] += matrices[element]
    return out


def test_pack_unpack_round_trip():
    rng = np.random.default_rng(1)
    for dtype in (float, complex):
        matrices = _symmetric(rng, 7, 6, dtype)
        packed = pack(matrices)
        assert packed.shape == (7, 21)
        np.testing.assert_array_equal(unpack(packed, 6), matrices)


def test_symmetric_matrices_are_kept_half_and_others_whole():
    rng = np.random.default_rng(2)
    nodes = np.array([[0, 1], [1, 2], [2, 3]])
    symmetric = _symmetric(rng, 3, 4)
    block = ElementBlock(nodes, ("DX", "DY"), symmetric)
    assert block.symmetric and block.packed.shape == (3, 10)
    np.testing.assert_array_equal(block.matrices, symmetric)
    np.testing.assert_array_equal(block.chunk(1, 3), symmetric[1:3])
    skew = symmetric.copy()
    skew[1, 0, 3] += 1.0  # one element not symmetric: the whole block stays whole
    whole = ElementBlock(nodes, ("DX", "DY"), skew)
    assert not whole.symmetric
    assert whole.matrices is skew
    assert not is_symmetric(skew)
    # round-off asymmetry is symmetry
    nearly = symmetric.copy()
    nearly[:, 0, 1] *= 1.0 + 1e-15
    assert ElementBlock(nodes, ("DX", "DY"), nearly).symmetric


def test_scaled_block_stays_packed():
    rng = np.random.default_rng(3)
    nodes = np.array([[0, 1]])
    block = ElementBlock(nodes, ("DX",), _symmetric(rng, 1, 2))
    scaled = block.scaled(complex(1.0, 0.02))
    assert scaled.symmetric and scaled.dtype == complex
    np.testing.assert_allclose(scaled.matrices, block.matrices * complex(1.0, 0.02))


def test_packed_needs_the_size_of_the_cells():
    with pytest.raises(ValueError, match="need 21 terms"):
        ElementBlock(np.array([[0, 1]]), ("DX", "DY", "DZ"), packed=np.zeros((1, 20)))
    with pytest.raises(ValueError, match="either matrices or packed"):
        ElementBlock(np.array([[0, 1]]), ("DX",))


@pytest.mark.parametrize("dtype", [float, complex])
def test_assembly_of_packed_blocks_matches_whole_matrices(dtype, monkeypatch):
    rng = np.random.default_rng(4)
    n_nodes, components = 9, ("DX", "DY", "DZ")
    nodes = np.array([rng.choice(n_nodes, 3, replace=False) for _ in range(40)])
    matrices = _symmetric(rng, 40, 9, dtype)
    numbering = _numbering(n_nodes, components)
    expected = _dense_assembly(nodes, components, matrices, numbering.n_dofs)
    # small chunks: the chunked assembly is exercised
    monkeypatch.setattr("asterlite.fem.assemble.CHUNK_TERMS", 200)
    assert CHUNK_TERMS > 200
    packed = assemble_blocks([ElementBlock(nodes, components, matrices)], numbering)
    whole_matrices = matrices.copy()
    whole_matrices[:, 0, 1] += 1.0  # not symmetric: assembled from whole matrices
    whole = assemble_blocks([ElementBlock(nodes, components, whole_matrices)], numbering)
    np.testing.assert_allclose(packed.toarray(), expected, rtol=1e-14, atol=1e-13)
    dense_whole = _dense_assembly(nodes, components, whole_matrices, numbering.n_dofs)
    np.testing.assert_allclose(whole.toarray(), dense_whole, rtol=1e-14, atol=1e-13)
    # a packed block assembles into an exactly symmetric matrix
    assert abs(packed - packed.T).max() == 0.0


def test_an_assembly_given_its_blocks_drops_each_once_summed(monkeypatch):
    rng = np.random.default_rng(8)
    n_nodes, components = 9, ("DX", "DY")
    numbering = _numbering(n_nodes, components)
    blocks = [
        ElementBlock(
            np.array([rng.choice(n_nodes, 2, replace=False) for _ in range(30)]),
            components,
            _symmetric(rng, 30, 4, dtype),
        )
        for dtype in (float, complex)
    ]
    monkeypatch.setattr("asterlite.fem.assemble.CHUNK_TERMS", 100)
    kept = list(blocks)
    summed = assemble_blocks(kept, numbering)
    assert kept == blocks  # the caller's list, untouched
    given = list(blocks)
    consumed = assemble_blocks(given, numbering, consume=True)
    assert given == []  # each block left the list once its terms were in
    assert (consumed != summed).nnz == 0  # the same sums, term for term
    for array in (summed.data, summed.indices):  # no room of the sums left over
        assert array.base is None or array.base.nbytes == array.nbytes


def test_computed_block_packs_chunk_by_chunk_or_keeps_all_whole():
    rng = np.random.default_rng(5)
    nodes = np.arange(10)[:, None]
    symmetric = _symmetric(rng, 10, 3)
    block = computed_block(nodes, ("DX", "DY", "DZ"), lambda a, b: symmetric[a:b], chunk=3)
    assert block.symmetric
    np.testing.assert_array_equal(block.matrices, symmetric)
    late = symmetric.copy()
    late[8, 0, 2] += 1.0  # the last chunk is not symmetric: earlier ones are unpacked
    block = computed_block(nodes, ("DX", "DY", "DZ"), lambda a, b: late[a:b], chunk=3)
    assert not block.symmetric
    np.testing.assert_array_equal(block.matrices, late)


def test_large_elementary_matrices_are_released_and_made_again(monkeypatch):
    from asterlite.concepts.assembly import ElementaryMatrices

    rng = np.random.default_rng(6)
    nodes = np.array([[0, 1], [1, 2]])
    matrices = _symmetric(rng, 2, 2)
    made = []

    def recompute():
        made.append(1)
        return [ElementBlock(nodes, ("DX",), matrices)]

    small = ElementaryMatrices(
        model=None, option="RIGI_MECA", blocks=recompute(), recompute=recompute
    )
    small.release()  # under RELEASE_BYTES: kept
    assert small.blocks is not None
    monkeypatch.setattr(ElementaryMatrices, "RELEASE_BYTES", 8)
    large = ElementaryMatrices(
        model=None, option="RIGI_MECA", blocks=recompute(), recompute=recompute
    )
    large.release()
    assert large.blocks is None and len(made) == 2
    again = large.element_blocks()
    assert len(made) == 3
    np.testing.assert_array_equal(again[0].matrices, matrices)
    kept = ElementaryMatrices(model=None, option="RIGI_MECA", blocks=recompute())
    kept.release()  # nothing to make them again with: kept
    assert kept.blocks is not None


def test_symmetry_is_judged_element_by_element():
    """A soft element's asymmetry is not hidden by a stiff element's scale."""
    stiff = np.eye(2)[None] * 1.0e20
    soft = np.array([[[1.0e3, 1.0], [0.0, 1.0e3]]])
    assert not is_symmetric(np.concatenate([stiff, soft]))
    assert is_symmetric(np.concatenate([stiff, stiff]))


@pytest.mark.parametrize("dtype", [float, complex])
def test_an_assembly_sums_in_place_on_its_pattern_as_chunk_sums_did(dtype, monkeypatch):
    """The chunks' sums (rows of a chunk summed in ranges) added in place on
    the pattern are those of adding the chunks' matrices, bit for bit."""
    import scipy.sparse as sp

    from asterlite.fem import assemble

    rng = np.random.default_rng(12)
    n_nodes, components = 30, ("DX", "DY", "DZ")
    numbering = _numbering(n_nodes, components)
    nodes = np.array([rng.choice(n_nodes, 4, replace=False) for _ in range(60)])
    symmetric = _symmetric(rng, 60, 12, dtype)
    symmetric[:, 0, 4] = symmetric[:, 4, 0] = 0.0  # terms whose sums are exactly zero
    whole = rng.standard_normal((60, 12, 12)).astype(dtype)
    others = np.array([rng.choice(n_nodes // 2, 4, replace=False) for _ in range(60)])
    blocks = [
        ElementBlock(nodes, components, packed=pack(symmetric)),
        ElementBlock(others, components, whole),
    ]
    monkeypatch.setattr(assemble, "CHUNK_TERMS", 1000)
    # the sums as chunk matrices added one after the other
    expected = None
    for block in blocks:
        idx = assemble.block_dof_indices(block, numbering).astype(np.int32)
        for chunk in assemble._block_chunks(block, idx, numbering.n_dofs):
            expected = chunk if expected is None else expected + chunk
    expected = sp.csr_matrix(expected)
    expected.eliminate_zeros()
    pattern = assemble._pattern(
        [assemble.block_dof_indices(b, numbering).astype(np.int32) for b in blocks],
        numbering.n_dofs,
    )
    assert pattern.nnz > expected.nnz  # some sums are zero: not stored
    for piece in (50, 10**9):  # rows of a chunk summed in ranges, or all at once
        monkeypatch.setattr(assemble, "PIECE_TERMS", piece)
        summed = assemble_blocks(list(blocks), numbering, consume=True)
        np.testing.assert_array_equal(summed.indptr, expected.indptr)
        np.testing.assert_array_equal(summed.indices, expected.indices)
        assert summed.data.tobytes() == expected.data.tobytes()
        for array in (summed.data, summed.indices):  # no room of the pattern left over
            assert array.base is None or array.base.nbytes == array.nbytes
