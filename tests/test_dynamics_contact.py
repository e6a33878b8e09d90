"""Unit tests of the shock geometry and forces (R5.06.03 eq. 11-25)."""

import math

import numpy as np
import pytest

from asterlite.dynamics import contact as C
from asterlite.dynamics.geometry import (
    default_origin,
    local_frame,
    nautical_angles,
    rotation_matrix,
)

NO_POLAR = np.zeros((2, 2))


def gap(
    geometry,
    loc1,
    loc2=(0.0, 0.0, 0.0),
    gap0=1.0,
    d1=0.0,
    d2=0.0,
    sy=1.0,
    sz=1.0,
    polar=NO_POLAR,
    npol=0,
):
    return C.gap_and_normal(
        geometry, np.array(loc1, float), np.array(loc2, float), gap0, d1, d2, sy, sz, polar, npol
    )


def test_plan_y_distance_and_normal_eq17_18():
    d, c, s = gap(C.PLAN_Y, (5.0, 0.3, 9.0), gap0=0.5)
    assert d == pytest.approx(0.2) and (c, s) == (-1.0, 0.0)
    d, c, s = gap(C.PLAN_Y, (0.0, -0.7, 0.0), gap0=0.5)
    assert d == pytest.approx(-0.2) and (c, s) == (1.0, 0.0)  # pushes back towards the centre


def test_plan_z_distance_and_normal():
    d, c, s = gap(C.PLAN_Z, (0.0, 3.0, -1.0), gap0=0.5)
    assert d == pytest.approx(-0.5) and (c, s) == (0.0, 1.0)


def test_cercle_distance_and_normal_eq19_20():
    d, c, s = gap(C.CERCLE, (0.0, 0.3, 0.4), gap0=0.4)
    assert d == pytest.approx(-0.1)
    assert (c, s) == pytest.approx((-0.6, -0.8))


def test_bi_plan_y_eq22_23():
    # node 2 above node 1 (sign +1): the gap closes when node 1 rises
    d, c, s = gap(C.BI_PLAN_Y, (0.0, 0.1, 0.0), (0.0, 1.0, 0.0), d1=0.2, d2=0.3, sy=1.0)
    assert d == pytest.approx(0.4) and (c, s) == (-1.0, 0.0)


def test_bi_plan_z():
    d, c, s = gap(C.BI_PLAN_Z, (0.0, 0.0, 0.5), (0.0, 0.0, 0.0), d1=0.25, d2=0.25, sz=-1.0)
    assert d == pytest.approx(0.0) and (c, s) == (0.0, 1.0)


def test_bi_cercle_eq24_25():
    d, c, s = gap(C.BI_CERCLE, (0.0, 0.0, 0.0), (0.0, 0.3, 0.4), d1=0.2, d2=0.4)
    assert d == pytest.approx(-0.1)
    assert (c, s) == pytest.approx((-0.6, -0.8))  # node 2 pushes node 1 away from itself


def test_bi_cerc_int_inner_contact():
    d, c, s = gap(C.BI_CERC_INT, (0.0, 0.3, 0.4), (0.0, 0.0, 0.0), d1=0.1, d2=0.5)
    assert d == pytest.approx(-0.1)
    assert (c, s) == pytest.approx((-0.6, -0.8))  # back towards the outer centre


def test_discret_square_nearest_facet_eq21():
    # square of half-side 1 described in polar form: corners at 45, 135, 225, 315 degrees
    angles = np.radians([0.0, 45.0, 135.0, 225.0, 315.0, 360.0])
    radii = np.array([1.0, math.sqrt(2), math.sqrt(2), math.sqrt(2), math.sqrt(2), 1.0])
    polar = np.column_stack([angles, radii])
    d, c, s = gap(C.DISCRET, (0.0, 0.2, 0.9), polar=polar, npol=6)
    assert d == pytest.approx(0.1)  # facet z = 1
    assert (c, s) == pytest.approx((0.0, -1.0))
    d, c, s = gap(C.DISCRET, (0.0, -1.2, 0.1), polar=polar, npol=6)
    assert d == pytest.approx(-0.2)
    assert (c, s) == pytest.approx((1.0, 0.0))


def test_normal_force_positive_part_eq11():
    assert C.normal_force(0.1, 0.0, 100.0, 1.0) == 0.0
    assert C.normal_force(-0.1, 0.0, 100.0, 1.0) == pytest.approx(10.0)
    assert C.normal_force(-0.1, -2.0, 100.0, 1.0) == pytest.approx(12.0)
    assert C.normal_force(-0.1, 50.0, 100.0, 1.0) == 0.0  # separating fast: no pull


def friction(fn, rel_x, rel_v, vint, mu=0.1, mus=None, kt=1.0e4, ct=0.0, unidir=False):
    return C.tangential_force(
        fn,
        np.array(rel_x, float),
        np.array(rel_v, float),
        0.0,
        1.0,
        mu,
        mu if mus is None else mus,
        kt,
        ct,
        unidir,
        vint,
    )


def test_stick_then_slip_then_stick():
    vint = np.zeros(C.N_VINT)
    # at rest: sticking, reference set on the first call
    friction(10.0, (0.0, 0.0, 0.0), (0.0, 0.0, 0.0), vint)
    ft1, ft2, vt1, vt2 = friction(10.0, (0.0, -1.0e-5, 0.0), (0.0, -1.0e-3, 0.0), vint)
    # normal (0, 0, 1): t1 = (0, -1, 0) so a -y motion is +t1; elastic stick force opposes it
    assert (
        vint[C.V_STICK] == 1.0
        and ft1 == pytest.approx(-0.1)
        and ft2 == 0.0
        and vt1 == pytest.approx(1e-3)
    )
    # larger motion: the predictor exceeds mu*FN -> slip at mu*FN against the velocity
    ft1, ft2, vt1, vt2 = friction(10.0, (0.0, -1.0e-3, 0.0), (0.0, -1.0e-2, 0.0), vint)
    assert vint[C.V_STICK] == 0.0 and ft1 == pytest.approx(-1.0) and ft2 == 0.0
    # keeps sliding while the velocity keeps its direction: Coulomb cap
    ft1, _, _, _ = friction(10.0, (0.0, -2.0e-3, 0.0), (0.0, -5.0e-3, 0.0), vint)
    assert vint[C.V_STICK] == 0.0 and ft1 == pytest.approx(-1.0)
    # velocity reverses: stick again, elastic from the last sliding force
    ft1, _, _, _ = friction(10.0, (0.0, -2.0e-3 + 1.0e-5, 0.0), (0.0, 1.0e-4, 0.0), vint)
    assert vint[C.V_STICK] == 1.0
    assert ft1 == pytest.approx(-1.0 + 1.0e4 * 1.0e-5)
    assert abs(ft1) <= 1.0


def test_coulomb_cap_in_two_directions():
    vint = np.zeros(C.N_VINT)
    friction(10.0, (0.0, 0.0, 0.0), (0.0, 0.0, 0.0), vint)
    ft1, ft2, _, _ = friction(10.0, (1.0, -1.0, 0.0), (3.0, -4.0, 0.0), vint)
    assert math.hypot(ft1, ft2) == pytest.approx(1.0)
    assert (ft1, ft2) == pytest.approx((-0.8, -0.6))  # against (vt1, vt2) = (4, 3)


def test_static_dynamic_coefficients():
    vint = np.zeros(C.N_VINT)
    friction(10.0, (0.0, 0.0, 0.0), (0.0, 0.0, 0.0), vint, mu=0.1, mus=0.3)
    ft1, _, _, _ = friction(10.0, (0.0, -2.5e-4, 0.0), (0.0, -1.0e-3, 0.0), vint, mu=0.1, mus=0.3)
    assert vint[C.V_STICK] == 1.0 and ft1 == pytest.approx(-2.5)  # below mu_s FN = 3
    ft1, _, _, _ = friction(10.0, (0.0, -4.0e-4, 0.0), (0.0, -1.0e-3, 0.0), vint, mu=0.1, mus=0.3)
    assert vint[C.V_STICK] == 0.0 and ft1 == pytest.approx(-1.0)  # slides at mu_d FN


def test_unidirectional_friction_ignores_norm_obst_axis():
    vint = np.zeros(C.N_VINT)
    friction(10.0, (0.0, 0.0, 0.0), (0.0, 0.0, 0.0), vint, unidir=True)
    ft1, ft2, _, _ = friction(10.0, (1.0, -1.0, 0.0), (3.0, -4.0, 0.0), vint, unidir=True)
    assert ft2 == 0.0 and ft1 == pytest.approx(-1.0)


def test_frame_from_norm_obst_and_vrille():
    rot = local_frame("PLAN_Z", (0.0, 1.0, 0.0), None, (0.7, 0.7, 0.0))
    assert rot @ np.array([0.0, 1.0, 0.0]) == pytest.approx([1.0, 0.0, 0.0])  # x_loc = NORM_OBST
    assert rot @ np.array([1.0, 0.0, 0.0]) == pytest.approx([0.0, -1.0, 0.0])
    rot90 = local_frame("PLAN_Y", (1.0, 0.0, 0.0), 90.0, (0.0, 0.0, 0.0))
    assert rot90 @ np.array([0.0, 0.0, 1.0]) == pytest.approx([0.0, 1.0, 0.0])
    alpha, beta = nautical_angles((1.0, 1.0, math.sqrt(2)))
    x = rotation_matrix(alpha, beta, 0.3) @ np.array([1.0, 1.0, math.sqrt(2)]) / 2.0
    assert x == pytest.approx([1.0, 0.0, 0.0])


def test_bi_plan_frame_follows_the_nodes():
    rot = local_frame("BI_PLAN_Y", (0.0, 0.0, 1.0), None, (0.0, 0.0, 0.0), (1.0, 1.0, 0.0))
    assert rot @ np.array([1.0, 1.0, 0.0]) / math.sqrt(2) == pytest.approx([0.0, 1.0, 0.0])
    rot = local_frame("BI_PLAN_Z", (0.0, 0.0, 1.0), None, (0.0, 0.0, 0.0), (1.0, 0.0, 0.0))
    assert rot @ np.array([1.0, 0.0, 0.0]) == pytest.approx([0.0, 0.0, 1.0])


def test_default_origin():
    assert default_origin((1.0, 2.0, 3.0), (3.0, 2.0, 1.0)) == pytest.approx([2.0, 2.0, 2.0])
    assert default_origin((1.0, 2.0, 3.0)) == pytest.approx(
        [0.5, 1.0, 1.5]
    )  # code_aster's single-node rule


def test_shock_forces_sdnd100a_setting():
    """Node at (0.707, 0.707, 0), PLAN_Z, ORIG_OBST=(0,0,1), NORM_OBST=(0,1,0),
    JEU=0.5, RIGI_NOR=20: permanent penetration of 0.5 -> FN = 10 N along +Z."""
    rot = local_frame("PLAN_Z", (0.0, 1.0, 0.0), None, (0.707, 0.707, 0.0))
    flags = np.array([[C.PLAN_Z, 0, 0, 0]], dtype=np.int64)
    params = np.zeros((1, C.N_PARAMS))
    params[0, C.P_GAP], params[0, C.P_KN] = 0.5, 20.0
    params[0, C.P_ORIGIN + 2] = 1.0
    params[0, C.P_COORD1 : C.P_COORD1 + 3] = (0.707, 0.707, 0.0)
    phis = np.zeros((1, 2, 3, 3))
    phis[0, 0] = np.eye(3)  # three "modes" = the three global translations
    out = np.zeros(3)
    vint = np.zeros((1, C.N_VINT))
    status = C.shock_forces(
        np.zeros(3),
        np.zeros(3),
        flags,
        params,
        rot[None],
        phis,
        np.zeros((1, 2, 2)),
        vint,
        np.zeros((5, 3)),
        out,
    )
    assert status == -1
    assert out == pytest.approx([0.0, 0.0, 10.0])
    assert vint[0, C.V_FN] == pytest.approx(10.0)
    assert vint[0, C.V_LOC1 + 2] == pytest.approx(-1.0)
