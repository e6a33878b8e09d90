"""FLAMBAGE: elastic branch, buckling plateau, post-buckling stiffness, crushing memory."""

import math

import numpy as np
import pytest
from asterlite.commands.dyna_vibra_relations import read_flambage
from hypothesis import given, settings
from hypothesis import strategies as st

from asterlite.dynamics.laws.flambage import (
    N_VINT,
    V_DEFMAX,
    V_DEFPLA,
    V_FN,
    buckling_force,
    initial_state,
    legacy_buckling_curves,
    prepare_flambage,
)
from asterlite.dynamics.laws.tabulated import LawError
from asterlite.errors import ValidationError
from tests.validated import relation

# sdnd105a's support: K = 1, buckling at 1, post-buckling force 0.5, reached
# crushing 1 with stiffness 0.5
LEGACY = dict(
    rigi_nor=1.0,
    fnor_crit=1.0,
    fnor_post_fl=0.5,
    larg_plat=1.0e-6,
    enfo_fl=1.0e-7,
    depl_post_fl=[1.0],
    rigi_post_fl=[0.5],
)


def support(criterion="INCLUS", **changes):
    fx, rigi, amor = legacy_buckling_curves(**dict(LEGACY, **changes))
    return prepare_flambage(
        read_flambage(
            relation("FLAMBAGE", dict(FX=fx, RIGI_NOR=rigi, AMOR_NOR=amor, CRIT_AMOR=criterion))
        )
    )


def drive(params, penetrations, velocities=None):
    """Force along a prescribed penetration history (quasi-static by default)."""
    state = initial_state(params)
    forces = []
    for i, u in enumerate(penetrations):
        vn = 0.0 if velocities is None else velocities[i]
        forces.append(buckling_force(params, -u, vn, state, state))
    return np.array(forces), state


def test_elastic_plateau_post_buckling_and_unloading():
    p = support()
    up = np.linspace(0.0, 4.0, 4001)
    down = np.linspace(4.0, 0.0, 4001)
    f_up, state = drive(p, up)
    elastic = up < 1.0
    assert np.allclose(f_up[elastic], up[elastic], atol=1e-9)  # K = 1 below the threshold
    post = up > 1.0 + 1.0e-5
    assert np.allclose(f_up[post], 0.5, atol=1e-9)  # the post-buckling force
    assert state[V_DEFPLA] == pytest.approx(3.0, abs=1e-6)  # 4 - F/k: residual crushing
    assert state[V_DEFMAX] == pytest.approx(4.0)
    f_down = np.array([buckling_force(p, -u, 0.0, state, state) for u in down])
    expected = np.maximum(0.0, 0.5 * (down - 3.0))  # unloading with the post-buckling stiffness
    assert np.allclose(f_down, expected, atol=1e-9)
    assert state[V_DEFPLA] == pytest.approx(3.0, abs=1e-6)  # crushing is kept
    # reloading follows the same line up to the threshold, no force inside the crushed gap
    assert buckling_force(p, -2.0, 0.0, state, state) == 0.0
    assert buckling_force(p, -3.5, 0.0, state, state) == pytest.approx(0.25)


def test_plateau_width_before_the_drop():
    p = support(larg_plat=0.3, enfo_fl=0.2)
    u = np.linspace(0.0, 1.5, 1501)
    f, _ = drive(p, u)
    plateau = (u > 1.0) & (u < 1.3)
    assert np.allclose(f[plateau], 1.0, atol=1e-9)
    drop = (u > 1.3) & (u < 1.5)
    assert np.all(np.diff(f[drop]) <= 1e-12)  # the force falls towards FNOR_POST_FL
    assert f[-1] == pytest.approx(0.5, abs=1e-3)


def test_damping_included_or_excluded_from_the_threshold():
    fx, rigi, amor = legacy_buckling_curves(**LEGACY, amor_nor=0.2, amor_fl=0.2)
    kw = dict(FX=fx, RIGI_NOR=rigi, AMOR_NOR=amor)
    inclusive = prepare_flambage(read_flambage(relation("FLAMBAGE", dict(kw, CRIT_AMOR="INCLUS"))))
    exclusive = prepare_flambage(read_flambage(relation("FLAMBAGE", dict(kw, CRIT_AMOR="EXCLUS"))))
    state = initial_state(inclusive)
    included = buckling_force(inclusive, -0.9, -1.0, state, state.copy())
    excluded = buckling_force(exclusive, -0.9, -1.0, state, state.copy())
    assert included == pytest.approx(1.0)  # 0.9 + 0.2 capped at the threshold
    assert excluded == pytest.approx(1.1)  # elastic part below the threshold, damping on top


def test_dynamic_buckling_of_a_unit_mass():
    """sdnd105a in one degree of freedom: m = 1 hits the support at v = 2;
    buckling at t = π/6, final crushing 3, rebound speed 1/√2."""
    p = support()
    state = initial_state(p)
    dt = 1.0e-4
    u, v, t = 0.0, 2.0, 0.0
    t_buckle = None
    for _ in range(200000):
        f = buckling_force(p, -u, -v, state, state)
        if t_buckle is None and state[V_DEFPLA] > 0.0:
            t_buckle = t
        v -= dt * f  # semi-implicit Euler: the force pushes the mass back
        u += dt * v
        t += dt
        if u < 2.0 and v < 0.0 and state[V_FN] == 0.0:
            break
    assert t_buckle == pytest.approx(math.pi / 6.0, abs=5e-4)
    assert state[V_DEFPLA] == pytest.approx(3.0, rel=1e-3)
    assert -v == pytest.approx(1.0 / math.sqrt(2.0), rel=1e-3)


def test_prepare_errors():
    fx, rigi, amor = legacy_buckling_curves(**LEGACY)
    # a missing stiffness function: the catalogue's refusal, named
    with pytest.raises(ValidationError, match="RIGI_NOR: missing mandatory keyword"):
        relation("FLAMBAGE", dict(FX=fx, AMOR_NOR=amor))
    bad = type(rigi)(rigi.abscissas, -rigi.ordinates, "CONSTANT", "CONSTANT")
    with pytest.raises(LawError, match="stiffness"):
        prepare_flambage(
            read_flambage(relation("FLAMBAGE", dict(FX=fx, RIGI_NOR=bad, AMOR_NOR=amor)))
        )
    with pytest.raises(LawError, match="increase"):
        legacy_buckling_curves(**dict(LEGACY, depl_post_fl=[0.5, 0.2], rigi_post_fl=[0.5, 0.5]))


@settings(max_examples=40, deadline=None)
@given(st.lists(st.floats(-0.5, 5.0), min_size=2, max_size=40))
def test_random_histories_finite_and_dissipative(points):
    """Along any closed penetration path the support absorbs energy, and its
    crushing never decreases."""
    p = support()
    path = np.concatenate([[0.0], np.repeat(points, 1), [0.0]])
    pairs = zip(path[:-1], path[1:], strict=True)
    fine = np.concatenate([np.linspace(a, b, 50, endpoint=False) for a, b in pairs])
    fine = np.append(fine, 0.0)
    state = np.zeros(N_VINT)
    state[:] = initial_state(p)
    forces, crushing = [], []
    for u in fine:
        forces.append(buckling_force(p, -u, 0.0, state, state))
        crushing.append(state[V_DEFPLA])
    forces = np.array(forces)
    assert np.all(np.isfinite(forces)) and np.all(forces >= 0.0)
    assert np.all(np.diff(crushing) >= -1e-12)
    absorbed = np.sum(forces[1:] * np.diff(fine))  # force evaluated at the end of each increment
    assert absorbed >= -1e-9
