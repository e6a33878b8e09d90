"""Modal damping at variable rotation speed on a basis whose mass is full.

code_aster keeps a damping given per mode (AMOR_MODAL, or a MATR_AMOR stored
DIAG) as the rates a_i = c_i / m_i (AMOR_DIA, dtmprep / dtmprep_damp). At
constant speed its acceleration applies diag(a) M v (dtmacce); with
VITESSE_VARIABLE='OUI' it first builds the full damping M diag(a)
(dtmupmat, prmama), then adds Ω(t) G. On a Ritz basis (M full) the two are
transposes of each other and the motions differ: on sdnl133c (sdnl133a's
cracked rotor at 50 % reduced damping, 'OUI') code_aster's displacement at
0.9 s is 1.6 % away from the 'NON' run's.

The closed form: with a constant speed, G = 0 and a constant load, the
generalized system M q'' + C q' + K q = F is linear with constant
coefficients, and its state at t is exp(A t) y0 + ∫_0^t exp(A s) ds b,
both read from the exponential of the augmented matrix [[A, b], [0, 0]].
"""

from __future__ import annotations

import numpy as np
import pytest
from scipy.linalg import expm

from asterlite.dynamics.model import modal_damping_rates
from tests.conftest import CORPUS

SDNL133A = CORPUS / "sdnl133a"
T_END = 0.01
RUNS = f"""
GYRO0 = COMB_MATR_ASSE(COMB_R=_F(MATR_ASSE=RIGGEN, COEF_R=0.0))
UN = DEFI_FONCTION(NOM_PARA="INST", VALE=(0.0, 1.0, 1.0, 1.0))
OM = FORMULE(VALE="-10.0 * pi + 0.0 * INST", NOM_PARA="INST")
COMMON = dict(
    MATR_MASS=MASGEN, MATR_RIGI=RIGGEN, BASE_CALCUL="GENE", TYPE_CALCUL="TRAN",
    SCHEMA_TEMPS=_F(SCHEMA="RUNGE_KUTTA_54", TOLERANCE=1.0e-10),
    AMOR_MODAL=_F(AMOR_REDUIT=0.5), ARCHIVAGE=_F(INST=({T_END},)),
    INCREMENT=_F(INST_INIT=0.0, INST_FIN={T_END}, PAS=1.0e-5),
    EXCIT=_F(VECT_ASSE_GENE=VAGFY, FONC_MULT=UN),
)
CONST = DYNA_VIBRA(**COMMON)
VARI = DYNA_VIBRA(VITESSE_VARIABLE="OUI", VITE_ROTA=OM, MATR_GYRO=GYRO0, **COMMON)
FIN()
"""


@pytest.fixture(scope="module")
def runs(tmp_path_factory):
    """sdnl133a's generalized rotor (a Ritz basis of two mode families: full
    M and K), without its crack, under the constant load MY = -1 at PAL_D."""
    if not SDNL133A.is_dir():
        pytest.skip("../shared/aster-corpus is not available")
    from asterlite.io.export import describe_run
    from asterlite.runtime.session import Session

    folder = tmp_path_factory.mktemp("rotor_damping")
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


def exact_state(mass, stiffness, damping, load, t):
    """(q, v) at t from rest under a constant load: the augmented exponential."""
    n = mass.shape[0]
    minv = np.linalg.inv(mass)
    a = np.zeros((2 * n + 1, 2 * n + 1))
    a[:n, n : 2 * n] = np.eye(n)
    a[n : 2 * n, :n] = -minv @ stiffness
    a[n : 2 * n, n : 2 * n] = -minv @ damping
    a[n : 2 * n, 2 * n] = minv @ load
    y = expm(a * t)[:, 2 * n]  # from y0 = 0 with the unit last component
    return y[:n], y[n : 2 * n]


def test_variable_speed_damps_with_mass_times_rates(runs):
    mass = np.asarray(runs["MASGEN"].matrix, dtype=float)
    stiffness = np.asarray(runs["RIGGEN"].matrix, dtype=float)
    load = np.asarray(runs["VAGFY"].values, dtype=float)
    assert np.max(np.abs(mass - np.diag(np.diag(mass)))) > 1e-3 * np.max(np.abs(mass))
    rates = modal_damping_rates(mass, stiffness, [0.5])
    q_oui, _ = exact_state(mass, stiffness, mass * rates[None, :], load, T_END)
    q_non, _ = exact_state(mass, stiffness, rates[:, None] * mass, load, T_END)
    scale = np.max(np.abs(q_non))
    # the two conventions are far apart on this basis: the test can tell them
    assert np.max(np.abs(q_oui - q_non)) > 1e-3 * scale
    const, vari = runs["CONST"], runs["VARI"]
    np.testing.assert_allclose(const.depl[-1], q_non, rtol=0.0, atol=1e-6 * scale)
    np.testing.assert_allclose(vari.depl[-1], q_oui, rtol=0.0, atol=1e-6 * scale)
