"""CALC_CHAMP's beam fields are computed by blocks of orders (bounded
temporaries) with products that round the same whatever the block: the
fields of every order are identical bit for bit for any block size, and
agree with the element matrices applied order by order."""

from __future__ import annotations

import numpy as np
import pytest

import asterlite.fem.element_fields as element_fields
from asterlite.concepts.transient import DynaTrans
from asterlite.fem.beam_elements import per_cell_products
from tests.test_fem_structures import _static, beam_model, line_mesh
from tests.test_fem_support import FakeSession, run

OPTIONS = ("EFGE_ELNO", "SIEF_ELNO", "SIPO_ELNO", "SIPM_ELNO", "SIEF_ELGA")
N_ORDERS = 23


def _result(modelisation, with_acce):
    """A cantilever's dyna_trans of N_ORDERS random states (values spread
    over many magnitudes, signs mixed: cancellations round)."""
    session = FakeSession()
    model, field, cara = beam_model(session, line_mesh(9, 2.0, (1.0, 0.7, 0.2)), modelisation)
    numbering, u, _ = _static(
        session,
        model,
        field,
        cara,
        [{"GROUP_NO": ("A",), "LIAISON": "ENCASTRE"}],
        [{"FORCE_NODALE": {"GROUP_NO": ("B",), "FX": 1.0, "FY": -2.0, "MZ": 0.3}}],
    )
    rng = np.random.default_rng(7)
    shape = (N_ORDERS, u.size)
    depl = u[None, :] * rng.normal(size=(N_ORDERS, 1)) + rng.normal(size=shape) * 10.0 ** (
        rng.integers(-12, 3, size=shape)
    )
    fields = {"DEPL": depl, "VITE": np.zeros(shape)}
    if with_acce:
        fields["ACCE"] = rng.normal(size=shape) * 1e3
    result = DynaTrans(numbering, np.arange(N_ORDERS) * 1e-3, np.arange(N_ORDERS), fields)
    return session, result


def _fields(session, result, monkeypatch, block_bytes):
    blocks = []
    original = element_fields.element_displacements

    def recorded(mesh, numbering, cells, values, *args):
        blocks.append(values.shape[0])
        return original(mesh, numbering, cells, values, *args)

    monkeypatch.setattr(element_fields, "BLOCK_BYTES", block_bytes)
    monkeypatch.setattr(element_fields, "element_displacements", recorded)
    out = run(session, "CALC_CHAMP", RESULTAT=result, CONTRAINTE=OPTIONS)
    return {name: out.element_fields[name].values for name in OPTIONS}, blocks


@pytest.mark.parametrize("modelisation", ["POU_D_E", "POU_D_T"])
@pytest.mark.parametrize("with_acce", [False, True])
def test_fields_do_not_depend_on_the_blocks_of_orders(modelisation, with_acce, monkeypatch):
    session, result = _result(modelisation, with_acce)
    whole, blocks = _fields(session, result, monkeypatch, 1 << 30)
    assert blocks == [N_ORDERS] * (2 if with_acce else 1)  # one block: every order
    per_order = 8 * 12 * 9  # one order's DOFs of the 9 cells
    for orders in (1, 4, 7):
        chunked, blocks = _fields(session, result, monkeypatch, orders * per_order)
        assert max(blocks) == orders and sum(blocks) == N_ORDERS * (2 if with_acce else 1)
        for name in OPTIONS:
            assert np.array_equal(chunked[name], whole[name]), (name, orders)
    if not with_acce:  # one array holds EFGE_ELNO and SIEF_ELNO (same values)
        assert whole["EFGE_ELNO"] is whole["SIEF_ELNO"]


def test_per_cell_products_are_the_matrix_products():
    rng = np.random.default_rng(3)
    matrices = rng.normal(size=(5, 12, 12))
    values = rng.normal(size=(17, 5, 12))
    expected = np.einsum("eij,oej->oei", matrices, values)
    np.testing.assert_allclose(
        per_cell_products(matrices, values), expected, rtol=1e-13, atol=1e-13
    )
    one_by_one = np.concatenate([per_cell_products(matrices, values[o : o + 1]) for o in range(17)])
    assert np.array_equal(one_by_one, per_cell_products(matrices, values))
