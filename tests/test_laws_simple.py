"""CHOC_ELAS_TRAC, RELA_EFFO_DEPL, RELA_EFFO_VITE, ROTOR_FISS."""

import math

import numpy as np
import pytest
from asterlite.commands.dyna_vibra_relations import (
    read_choc_elas_trac,
    read_nodal_relation,
    read_rotor_fiss,
    relation_words,
)
from hypothesis import given, settings
from hypothesis import strategies as st

from asterlite.concepts.mesh import Mesh
from asterlite.dynamics.laws.choc_elas_trac import (
    V_FORCE,
    V_LENGTH,
    elastic_shock_force,
    prepare_choc_elas_trac,
)
from asterlite.dynamics.laws.connections import (
    RELATIONS,
    ConnectionError_,
    internal_variable_names,
    neighbour_of,
    rotor_frame,
)
from asterlite.dynamics.laws.rela_effo_depl import (
    P_COMPONENT,
    prepare_rela_effo_depl,
    relation_force,
)
from asterlite.dynamics.laws.rela_effo_vite import prepare_rela_effo_vite
from asterlite.dynamics.laws.rotor_fiss import (
    V_ANGLE,
    cracked_rotor_moment,
    prepare_rotor_fiss,
)
from asterlite.dynamics.laws.tabulated import Curve, LawError
from tests.validated import relation

GALET = Curve(
    np.array([0.0, 2.0, 5.0, 7.0, 9.5, 10.0]) / 10.0,
    np.array([0.0, 4.0, 4.5, 6.0, 7.0, 10.0]) * 100.0,
    "EXCLU",
    "LINEAIRE",
)


def test_elastic_shock_only_in_compression():
    p = prepare_choc_elas_trac(
        read_choc_elas_trac(relation("CHOC_ELAS_TRAC", dict(FX=GALET, DIST_1=0.01, DIST_2=0.02))),
        rest_distance=0.1,
    )
    state = np.zeros(8)
    assert elastic_shock_force(p, 0.05, state) == 0.0
    assert state[V_LENGTH] == pytest.approx(0.12)
    # length 0.07 - 0.2 = -0.13: force read at DX = 0.13 on the curve, pushing node 1 back
    f = elastic_shock_force(p, -0.2, state)
    assert f == pytest.approx(-np.interp(0.13, GALET.abscissas, GALET.ordinates))
    assert state[V_FORCE] == pytest.approx(-f)
    f = elastic_shock_force(p, -1.17, state)  # beyond the last point: LINEAIRE prolongation
    assert f == pytest.approx(-1600.0)


@settings(max_examples=50, deadline=None)
@given(st.floats(-1.0, 1.0), st.floats(-1.0, 1.0))
def test_elastic_shock_conservative_and_finite(a, b):
    p = prepare_choc_elas_trac(
        read_choc_elas_trac(relation("CHOC_ELAS_TRAC", dict(FX=GALET))), rest_distance=0.0
    )
    state = np.zeros(8)
    grid = np.linspace(a, b, 2001)
    forces = np.array([elastic_shock_force(p, x, state) for x in grid])
    assert np.all(np.isfinite(forces)) and np.all(forces <= 0.0)
    back = np.array([elastic_shock_force(p, x, state) for x in grid[::-1]])
    assert np.allclose(forces, back[::-1])  # path independent: no dissipation


def test_relations_of_displacement_and_velocity():
    p = prepare_rela_effo_depl(
        read_nodal_relation(
            relation("RELA_EFFO_DEPL", dict(NOM_CMP="DY", FONCTION=Curve([-1.0, 1.0], [2.0, -2.0])))
        )
    )
    assert p[P_COMPONENT] == 1.0
    state = np.zeros(3)
    assert relation_force(p, 0.25, state) == pytest.approx(-0.5)
    assert tuple(state) == pytest.approx((0.25, -0.5, 1.0))
    assert math.isnan(relation_force(p, 2.0, state))  # EXCLU
    assert relation_force(p, 0.0, state) == 0.0 and state[2] == 0.0
    p = prepare_rela_effo_vite(
        read_nodal_relation(
            relation("RELA_EFFO_VITE", dict(NOM_CMP="DRZ", FONCTION=Curve([0.0, 1.0], [0.0, 3.0])))
        )
    )
    assert p[P_COMPONENT] == 5.0
    with pytest.raises(LawError, match="NOM_CMP"), relation_words("RELA_EFFO_VITE"):
        prepare_rela_effo_vite(
            read_nodal_relation(
                relation(
                    "RELA_EFFO_VITE", dict(NOM_CMP="TEMP", FONCTION=Curve([0.0, 1.0], [0.0, 3.0]))
                )
            )
        )


def rotor(k=2.0, dk=0.0, **kw):
    k_phi = Curve([0.0, 2.0 * math.pi], [k, k], "CONSTANT", "CONSTANT")
    dk_dphi = Curve([0.0, 2.0 * math.pi], [dk, dk], "CONSTANT", "CONSTANT")
    return prepare_rotor_fiss(
        read_rotor_fiss(relation("ROTOR_FISS", dict(K_PHI=k_phi, DK_DPHI=dk_dphi, **kw))),
        rotation_speed=3.0,
    )


def test_uncracked_rotor_is_a_rotational_spring_orthogonal_to_the_axis():
    p = rotor(ANGL_INIT=30.0)
    state = np.zeros(3)
    for t in (0.0, 0.4, 1.7):
        m = cracked_rotor_moment(p, t, np.eye(3), 0.3, 0.1, -0.2, state)
        assert m == pytest.approx((0.0, 0.2, -0.4))  # K δθ without the axial component


def test_crack_angle_follows_the_rotation():
    p = rotor(k=1.0, dk=0.5)
    state = np.zeros(3)
    # δθ along global z: φ = atan2(δy, δz) in the turning frame, γ = 3 t
    cracked_rotor_moment(p, 0.0, np.eye(3), 0.0, 0.0, 1.0, state)
    assert state[V_ANGLE] == pytest.approx(0.0)
    t = 0.2
    cracked_rotor_moment(p, t, np.eye(3), 0.0, 0.0, 1.0, state)
    assert state[V_ANGLE] == pytest.approx(math.degrees(3.0 * t))  # code_aster 17: degrees
    m = np.array(cracked_rotor_moment(p, t, np.eye(3), 0.0, 0.0, 1.0, state))
    assert m[0] == 0.0 and np.linalg.norm(m) == pytest.approx(math.hypot(1.0, 0.25))


def test_rotor_angle_rounds_small_sines_to_zero_like_rot3d():
    # γ = 3 t = π/2 + 3e-7: cos γ = -3e-7 counts as 0, so δθ_z lies exactly on y of the
    # turning frame (φ = 90° exactly) and the moment has no global y component
    p = rotor(k=1.0)
    state = np.zeros(3)
    t = (0.5 * math.pi + 3.0e-7) / 3.0
    m = cracked_rotor_moment(p, t, np.eye(3), 0.0, 0.0, 1.0, state)
    assert m[0] == 0.0 and m[1] == 0.0 and m[2] == pytest.approx(1.0)
    assert state[V_ANGLE] == 90.0


def rotor_mesh(direction, crack_length=0.0):
    """Nodes 0-1-2 | 3-4-5 along ``direction``; the crack between D = 3 and G = 2
    (D on the far side), its own SEG2 2-3 (ignored for the axis), a POI1 on D."""
    u = np.asarray(direction, dtype=float)
    positions = [0.0, 1.0, 2.0, 2.0 + crack_length, 3.0 + crack_length, 4.0 + crack_length]
    return Mesh(
        coords=np.array([x * u for x in positions]),
        node_names=[f"N{i + 1}" for i in range(6)],
        cell_names=["M1", "M2", "M3", "M4", "M5", "M6"],
        cell_types=["SEG2", "SEG2", "SEG2", "SEG2", "SEG2", "POI1"],
        cell_nodes=[(0, 1), (1, 2), (3, 4), (4, 5), (2, 3), (3,)],
    )


@pytest.mark.parametrize("crack_length", [0.0, 0.1])
@pytest.mark.parametrize("direction", [(1.0, 0.0, 0.0), (0.0, 1.0, 0.0), (0.0, 0.6, 0.8)])
def test_rotor_axis_runs_from_the_neighbour_of_g_to_the_neighbour_of_d(direction, crack_length):
    frame = rotor_frame(rotor_mesh(direction, crack_length), 3, 2)
    assert frame[0] == pytest.approx(np.array(direction), abs=1e-12)
    assert frame @ frame.T == pytest.approx(np.eye(3), abs=1e-12)
    # D and G swapped: the axis turns round
    assert rotor_frame(rotor_mesh(direction, crack_length), 2, 3)[0] == pytest.approx(
        -np.array(direction), abs=1e-12
    )


def test_rotor_axis_neighbour_rule_and_missing_neighbour():
    mesh = rotor_mesh((0.0, 1.0, 0.0))
    assert neighbour_of(mesh, 3, 2, 0) == 4  # first node of M3: its second node
    assert neighbour_of(mesh, 2, 3, 1) == 1  # second node of M2: its first node
    lone = Mesh(
        coords=np.zeros((2, 3)), node_names=["N1", "N2"], cell_names=["M1"],
        cell_types=["SEG2"], cell_nodes=[(0, 1)],
    )  # fmt: skip
    with pytest.raises(ConnectionError_, match="rotor axis"):
        rotor_frame(lone, 1, 0)


def test_registry():
    for name, entry in RELATIONS.items():
        assert len(internal_variable_names(name)) == entry.module.N_VINT
    with pytest.raises(LawError, match="ANGL_ROTA"), relation_words("ROTOR_FISS"):
        flat = Curve([0.0, 1.0], [1.0, 1.0])
        slope = Curve([0.0, 1.0], [0.0, 0.0])
        prepare_rotor_fiss(
            read_rotor_fiss(relation("ROTOR_FISS", dict(K_PHI=flat, DK_DPHI=slope))),
            variable_speed=True,
        )
