"""POST_DYNA_MODA_T / RELA_EFFO_DEPL: the phases a displacement-force
relation spends in its nonlinear zone."""

import numpy as np
import pytest
from asterlite.commands import post_dyna_moda_t

from asterlite.concepts.transient import ShockHistory
from asterlite.errors import CommandError
from asterlite.post import shocks

from .test_post_support import context, kw, small_transient

T = np.round(np.arange(10) * 0.1, 12)


def test_phases_close_on_the_first_linear_sample():
    value = np.array([0.0, 2.0, -3.0, 1.0, 0.0, 0.0, -1.0, 1.0, 0.5, 0.0])
    active = (np.abs(value) > 0.2).astype(float)
    first, second = shocks.nonlinear_phases(T, value, active)
    assert (first.number, first.start, first.end) == (1, 0.1, 0.4)
    assert (first.extreme, first.instant) == (-3.0, 0.2)  # signed, largest magnitude
    assert (second.number, second.start, second.end) == (2, 0.6, 0.9)
    assert (second.extreme, second.instant) == (-1.0, 0.6)  # first of equal magnitudes


def test_phase_open_at_both_ends():
    value = np.array([5.0, 4.0, 0.0, 0.0, 1.0, 2.0, 3.0, 3.5, 4.0, 6.0])
    active = value != 0
    first, second = shocks.nonlinear_phases(T, value, active)
    assert (first.start, first.end, first.extreme, first.instant) == (0.0, 0.2, 5.0, 0.0)
    # still nonlinear at the last instant: INST_FIN is that instant
    assert (second.start, second.end, second.extreme, second.instant) == (0.4, 0.9, 6.0, 0.9)


def test_no_nonlinear_sample_no_phase():
    assert shocks.nonlinear_phases(T, np.ones(10), np.zeros(10)) == []


def transient_with_relation(archive_value: bool = True):
    """small_transient (NO2 DX = 2 q1 + 0.5 q2) with q1 oscillating, q2 = 0,
    and a RELA_EFFO_DEPL relation at NO2/DX active when |DX| > 0.1."""
    result = small_transient()
    q1 = np.array([0.0, 0.04, 0.1, 0.06, 0.0, -0.04, -0.12, -0.08, 0.0, 0.03, 0.07])
    result.depl = np.column_stack([q1, np.zeros_like(q1)])
    dx = 2 * q1
    force = np.where(np.abs(dx) > 0.1, 10 * dx, 0.0)
    fields = {"VINT2": force, "VINT3": (force != 0).astype(float)}
    if archive_value:
        fields["VINT1"] = dx
    name = f"{'2':<8}{'DX':<8}F_NL"  # node number, component, function
    relation = ShockHistory(name, "RELA_EFFO_DEPL", "NO2", None, fields, {"LAW": np.zeros(3)})
    result.shocks = [result.shocks[0], relation]
    return result


@pytest.mark.parametrize("archive_value", [True, False])
def test_command_rows(archive_value):
    result = transient_with_relation(archive_value)
    table = post_dyna_moda_t.run(
        context(), kw(RESU_GENE=result, RELA_EFFO_DEPL=[{"GROUP_NO": "NO2", "NOM_CMP": "DX"}])
    )
    assert table.columns == [
        "RELATION", "NOEUD", "CMP", "PHASE", "INST_INIT", "INST_FIN", "MAXI", "INST_MAXI",
    ]  # fmt: skip
    assert [r["PHASE"] for r in table.rows] == [1, 2, 3]
    assert {(r["RELATION"], r["NOEUD"], r["CMP"]) for r in table.rows} == {("F_NL", "2", "DX")}
    expected = [(0.2, 0.4, 0.2, 0.2), (0.6, 0.8, -0.24, 0.6), (1.0, 1.0, 0.14, 1.0)]
    got = [(r["INST_INIT"], r["INST_FIN"], r["MAXI"], r["INST_MAXI"]) for r in table.rows]
    np.testing.assert_allclose(got, expected)


def test_command_by_node_name_and_no_phase():
    result = transient_with_relation()
    result.shocks[1].fields["VINT3"] = np.zeros(11)
    table = post_dyna_moda_t.run(
        context(), kw(RESU_GENE=result, RELA_EFFO_DEPL=[{"NOEUD": "NO2", "NOM_CMP": "DX"}])
    )
    assert len(table) == 0 and len(table.columns) == 8


def test_command_unknown_relation_fails():
    result = transient_with_relation()
    with pytest.raises(CommandError):
        post_dyna_moda_t.run(
            context(), kw(RESU_GENE=result, RELA_EFFO_DEPL=[{"GROUP_NO": "NO2", "NOM_CMP": "DY"}])
        )
