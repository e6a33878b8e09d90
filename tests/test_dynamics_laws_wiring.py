"""The laws of asterlite.dynamics.laws in the time loop (laws.kernel)."""

from __future__ import annotations

import numpy as np
import pytest
from asterlite.commands.dyna_vibra_relations import read_dis_visc

from asterlite.dynamics.excitation import tabulate_excitation
from asterlite.dynamics.integrate import integrate
from asterlite.dynamics.laws import dis_visc, rela_effo_depl
from asterlite.dynamics.laws import kernel as LK
from asterlite.dynamics.laws.kernel import V_TIME
from asterlite.dynamics.laws.tabulated import pack
from asterlite.dynamics.model import LinearSystem, ShockSpec, build_shocks
from asterlite.errors import NumericalError
from tests.validated import relation, scheme_options


def one_mode(k=100.0):
    return LinearSystem(np.eye(1), k * np.eye(1), np.zeros((1, 1)))


def spring_spec(k_extra, left="LINEAIRE", right="LINEAIRE", points=(-1.0, 1.0)):
    """RELA_EFFO_DEPL F(u) = -k u on DX of a node whose DX is the mode."""
    xs = np.array(points)
    law = np.concatenate([[0.0], pack(xs, -k_extra * xs, left, right)])
    phi = np.array([[1.0], [0.0], [0.0]])
    return ShockSpec(
        name="R", obstacle_type="PLAN_Y", node_1="N1", node_2=None,
        coord_1=np.zeros(3), coord_2=None, phi_1=phi, phi_2=None,
        norm_obst=np.array([1.0, 0.0, 0.0]), relation="RELA_EFFO_DEPL",
        law_code=LK.RELA_EFFO_DEPL, law=law, rphi_1=np.zeros((3, 1)),
    )  # fmt: skip


def run(system, specs, scheme, t_end=1.0, dt=1.0e-3):
    shocks = build_shocks(specs, system)
    exc = tabulate_excitation(1, [], 0.0, t_end, dt / 2)
    return integrate(
        system, shocks, exc, scheme, np.array([0.01]), np.zeros(1), 0.0, t_end, dt,
        np.array([t_end]), 1, scheme_options(scheme),
    )  # fmt: skip


@pytest.mark.parametrize("scheme", ["DIFF_CENTRE", "RUNGE_KUTTA_54"])
def test_linear_relation_is_a_stiffness(scheme):
    with_law = run(one_mode(100.0), [spring_spec(300.0)], scheme)
    stiffer = run(one_mode(400.0), [], scheme)
    assert np.allclose(with_law.depl, stiffer.depl, rtol=1e-6, atol=1e-12)
    # archived: VINT1 = u, VINT2 = F(u)
    vint = with_law.vint[:, 0]
    assert np.allclose(vint[:, rela_effo_depl.V_FORCE], -300.0 * vint[:, rela_effo_depl.V_VALUE])


def test_exclu_domain_stops_the_run_naming_the_law():
    spec = spring_spec(300.0, "EXCLU", "EXCLU", points=(-0.001, 0.001))
    with pytest.raises(NumericalError, match="RELA_EFFO_DEPL 'R'"):
        run(one_mode(100.0), [spec], "DIFF_CENTRE")


def test_dis_visc_state_follows_the_steps():
    """DIS_VISC between the mode's node and a fixed node: the stored state is
    the one of the last evaluation instant (V_TIME)."""
    params = dis_visc.prepare_dis_visc(
        read_dis_visc(relation("DIS_VISC", {"K1": 120.0, "K2": 10.0, "K3": 60.0, "C": 1.7}))
    )
    phi = np.array([[1.0], [0.0], [0.0]])
    spec = ShockSpec(
        name="V", obstacle_type="BI_PLAN_Y", node_1="N1", node_2="N2",
        coord_1=np.zeros(3), coord_2=np.array([1.0, 0.0, 0.0]), phi_1=phi,
        phi_2=np.zeros((3, 1)), norm_obst=np.array([1.0, 0.0, 0.0]), relation="DIS_VISC",
        law_code=LK.DIS_VISC, law=params, frame=np.eye(3),
    )  # fmt: skip
    result = run(one_mode(100.0), [spec], "DIFF_CENTRE", t_end=0.1)
    assert result.vint.shape[2] > V_TIME
    assert result.vint[-1, 0, V_TIME] == pytest.approx(0.1)
    force = result.vint[:, 0, dis_visc.V_FORCE]
    assert np.all(np.isfinite(force)) and np.any(force != 0.0)
