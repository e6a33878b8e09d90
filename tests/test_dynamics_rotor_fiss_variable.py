"""ROTOR_FISS at variable rotation speed (VITESSE_VARIABLE='OUI'): the crack
angle is ANGL_ROTA(t), evaluated in the compiled loop at the instant of each
force evaluation, as code_aster's force routine does (ANGL_INIT and VITE_ROTA
play no part in it)."""

from __future__ import annotations

import math

import numpy as np
import pytest
from asterlite.commands.dyna_vibra_relations import read_rotor_fiss

from asterlite.dynamics.laws import rotor_fiss as RF
from asterlite.dynamics.laws.connections import rotor_frame
from asterlite.dynamics.laws.tabulated import Curve
from tests.conftest import CORPUS
from tests.validated import relation

FLAT = Curve([0.0, 2.0 * math.pi], [1.0, 1.0], "CONSTANT", "CONSTANT")
ACCELERATION = 2000.0  # rad/s², the ramp Ω = ACC t, γ = ACC t² / 2


def test_angl_rota_function_gives_the_angle_and_the_speed_is_not_needed():
    """A DEFI_FONCTION ANGL_ROTA: γ(t) read on it (here 2 t, linear), the
    constant-speed parameters ignored."""
    law = RF.prepare_rotor_fiss(
        read_rotor_fiss(
            relation(
                "ROTOR_FISS",
                dict(
                    K_PHI=FLAT,
                    DK_DPHI=FLAT,
                    ANGL_INIT=45.0,
                    ANGL_ROTA=Curve([0.0, 1.0], [0.0, 2.0]),
                ),
            )
        ),
        variable_speed=True,
    )
    for t in (0.0, 0.25, 0.7):
        assert RF.rotor_angle(law, t) == pytest.approx(2.0 * t, abs=1e-15)


SDNL133A = CORPUS / "sdnl133a"
COMMON = """    MATR_MASS=MASGEN, MATR_RIGI=RIGGEN, BASE_CALCUL="GENE", TYPE_CALCUL="TRAN",
    SCHEMA_TEMPS=_F(SCHEMA="DIFF_CENTRE"), AMOR_MODAL=_F(AMOR_REDUIT=0.0),
    ARCHIVAGE=_F(PAS_ARCH=100),
    INCREMENT=_F(INST_INIT=0.0, INST_FIN=0.02, PAS=pas, VERI_PAS="NON"),
    EXCIT=(_F(VECT_ASSE_GENE=VAGFZ, FONC_MULT=RAMP), _F(VECT_ASSE_GENE=VAGFY, FONC_MULT=RAMP)),
"""
CRACK = 'RELATION="ROTOR_FISS", GROUP_NO_G="FISS_G", GROUP_NO_D="FISS_D", K_PHI=F_K, DK_DPHI=F_KP'
# without damping: at variable speed code_aster turns a diagonal modal
# damping into M diag(c/m), which differs from diag(c) on this Ritz basis
RUNS = f"""
GYRO0 = COMB_MATR_ASSE(COMB_R=_F(MATR_ASSE=RIGGEN, COEF_R=0.0))
OMEGA = -10.0 * pi
CONST = DYNA_VIBRA(
{COMMON}    VITESSE_VARIABLE="NON", VITE_ROTA=OMEGA,
    COMPORTEMENT=_F({CRACK}, ANGL_INIT=20.0),
)
VITE = FORMULE(VALE="OMEGA + 0.0 * INST", OMEGA=OMEGA, NOM_PARA="INST")
ANGLE = FORMULE(VALE="20.0 * pi / 180.0 + OMEGA * INST", OMEGA=OMEGA, NOM_PARA="INST")
VARI = DYNA_VIBRA(
{COMMON}    VITESSE_VARIABLE="OUI", VITE_ROTA=VITE, MATR_GYRO=GYRO0,
    COMPORTEMENT=_F({CRACK}, ANGL_ROTA=ANGLE),
)
ACC = {ACCELERATION}
VRAMP = FORMULE(VALE="ACC * INST", ACC=ACC, NOM_PARA="INST")
ARAMP = FORMULE(VALE="0.5 * ACC * INST ** 2", ACC=ACC, NOM_PARA="INST")
RAMPED = DYNA_VIBRA(
{COMMON}    VITESSE_VARIABLE="OUI", VITE_ROTA=VRAMP, MATR_GYRO=GYRO0,
    COMPORTEMENT=_F({CRACK}, ANGL_ROTA=ARAMP),
)
FIN()
"""


@pytest.fixture(scope="module")
def rotor_runs(tmp_path_factory):
    """sdnl133a's cracked rotor (shortened to 0.02 s) run three times: at
    constant speed, with the same speed and angle as FORMULEs at variable
    speed, and with a speed ramp."""
    if not SDNL133A.is_dir():
        pytest.skip("../shared/aster-corpus is not available")
    from asterlite.io.export import describe_run
    from asterlite.runtime.session import Session

    folder = tmp_path_factory.mktemp("rotor")
    text = (SDNL133A / "sdnl133a.comm").read_text()
    head = text.split("TRANGEN = DYNA_VIBRA(")[0]
    (folder / "rotor.comm").write_text(head + RUNS)
    (folder / "rotor.export").write_text(
        "P time_limit 300\nF comm rotor.comm D 1\n"
        f"F mmed {SDNL133A / 'sdnl133a.mmed'} D 20\nF libr {SDNL133A / 'sdnl133a.38'} D 38\n"
    )
    (folder / "out").mkdir()
    session = Session(describe_run(folder / "rotor.export"), output_dir=folder / "out")
    session.run_all()
    return session.namespace


def test_constant_speed_as_formulas_is_the_constant_speed_run(rotor_runs):
    const, vari = rotor_runs["CONST"], rotor_runs["VARI"]
    np.testing.assert_array_equal(const.times, vari.times)
    assert np.max(np.abs(const.depl)) > 0.0
    np.testing.assert_allclose(
        vari.depl, const.depl, rtol=0.0, atol=1e-12 * np.abs(const.depl).max()
    )
    np.testing.assert_allclose(
        vari.shocks[0].fields["VINT1"], const.shocks[0].fields["VINT1"], rtol=1e-9, atol=1e-9
    )


def opening_angles(result, namespace, angle_of_time):
    """The crack opening angle φ (degrees) of each archived state, computed
    here from the archived generalized displacement with the rotor turned by
    ``angle_of_time(t)``: δθ = θ_G - θ_D of the rotation DOFs, brought to the
    rotor frame, rotated by γ, φ = atan2(δy, δz) in [0, 360)."""
    basis = result.basis
    mesh = basis.numbering.mesh
    node_d = int(mesh.node_groups["FISS_D"][0])
    node_g = int(mesh.node_groups["FISS_G"][0])
    frame = rotor_frame(mesh, node_d, node_g)
    n = result.depl.shape[1]

    def rotations(node):
        return np.array([np.asarray(basis.shape_at(node, c))[:n] for c in ("DRX", "DRY", "DRZ")])

    delta = (rotations(node_g) - rotations(node_d)) @ result.depl.T  # (3, n_instants)
    a, b = frame[1] @ delta, frame[2] @ delta
    gamma = angle_of_time(result.times)
    cg, sg = np.cos(gamma), np.sin(gamma)
    cg = np.where(np.abs(cg) < 1e-6, 0.0, cg)  # code_aster's rot3d rounding
    sg = np.where(np.abs(sg) < 1e-6, 0.0, sg)
    phi = np.degrees(np.arctan2(cg * a + sg * b, -sg * a + cg * b))
    return np.where(phi < 0.0, phi + 360.0, phi)


def test_speed_ramp_turns_the_crack_by_the_hand_computed_angle(rotor_runs):
    """Ω = ACC t: the archived opening angle is the one of the archived
    displacement seen from a rotor turned by γ = ACC t² / 2 (hand-computed),
    not by the constant-speed angle."""
    ramped = rotor_runs["RAMPED"]
    archived = ramped.shocks[0].fields["VINT1"][1:]
    expected = opening_angles(ramped, rotor_runs, lambda t: 0.5 * ACCELERATION * t**2)[1:]
    assert np.max(np.abs(ramped.depl)) > 0.0
    np.testing.assert_allclose(archived, expected, atol=1e-6)
    # γ reaches 0.4 rad at the end: an unturned rotor would be far off
    unturned = opening_angles(ramped, rotor_runs, lambda t: 0.0 * t)[1:]
    assert np.max(np.abs(archived - unturned)) > 10.0
