"""A planar impacting orbit in circular supports with Coulomb friction:
does it stay planar? (../shared/tube-references/tube_planar23)

The tube is axisymmetric and driven along the Y = Z diagonal: its orbit is
planar in exact arithmetic. Whether round-off (or any small sideways
perturbation) grows is decided, below the slip floor of the friction law
(|v_T| <= 1e-6 m/s), by the linearised stick phase: its tangential spring
RIGI_TAN and damper AMOR_TAN act on the out-of-plane motion during each
contact. The perturbation equations along the planar orbit are derived
here by hand (no engine code) and iterated with DIFF_CENTRE's arithmetic:

    F_perp = -K_T (p - p_a) - C_T p' + p [K_T (ρ - ρ_a)/ρ + C_T ρ'/ρ - F_N/|ρ|]

at a support in contact (p the out-of-plane displacement, ρ the in-plane
one, *_a their values at the last evaluation out of contact, F_N the normal
force of the planar orbit; no friction while F_N = 0), zero out of contact.

- code_aster 17's default AMOR_TAN (8.0e3 N s/m here: the mode with most
  mass in the tangential motion, ξ = AMOR_DIA / 2ω, floored at 0) damps the
  stick phase: a kick of 1e-6 of the impact velocity decays, asterlite and
  the perturbation equations agree, and round-off never leaves the plane.
- code_aster 13-15's default (-1.2e6 N s/m: the mode of largest mass, its
  AMOR_DIA = 2ξω taken for ξ, no floor) makes each stick step multiply the
  out-of-plane velocity by 1 + |C_T| dt Σ φ²/m ≈ 125: round-off reaches the
  slip floor within a contact and the orbit whirls at the Coulomb cap, which
  is what code_aster 15.2 computed (wear 7.39e-4, 1.46e-3 W);
  ``--aster-version 15`` reproduces it.
"""

from __future__ import annotations

import os

import numpy as np
import pytest

from tests.conftest import CORPUS

REFERENCES = CORPUS.parent / "tube-references"
DECK = REFERENCES / "tube_planar23.comm"
T_KICK, T_END, DT, JEU, K_T = 0.5, 0.75, 1.0e-5, 1.0e-4, 2.0e6
XI = 0.01
KICK = """
KICK = AFFE_CHAR_MECA(MODELE=MODELE, FORCE_NODALE=_F(NOEUD="N17", FY=1.0, FZ=-1.0))
K_EL = CALC_VECT_ELEM(OPTION="CHAR_MECA", CHARGE=KICK)
K_AS = ASSE_VECTEUR(VECT_ELEM=K_EL, NUME_DDL=NUME)
K_GEN = PROJ_VECT_BASE(BASE=MODES, NUME_DDL_GENE=NUMG, VECT_ASSE=K_AS, TYPE_VECT="FORC")
PULSE = DEFI_FONCTION(NOM_PARA="INST", VALE=(0.0, 0.0, TK, 0.0, TK + 1.0e-4, AK,
                                             TK + 2.0e-4, 0.0, 10.0, 0.0))
"""
NODES = ("N11", "N21", "N31")
E0 = np.array([1.0, 1.0]) / np.sqrt(2.0)  # the plane of the orbit (Y = Z)
EP = np.array([-1.0, 1.0]) / np.sqrt(2.0)  # out of it


def kicked_deck(folder):
    """The deck with a sideways force pulse (FY = -FZ at N17, 2e-4 s long, peak
    AK N at TK), archived at every step, ending at TEND."""
    text = DECK.read_text()
    text = text.replace("FREQ = 23.0", f"FREQ = 23.0\nTK = {T_KICK}\nAK = 0.0")
    text = text.replace("INST_FIN=2.0", f"INST_FIN={T_END}")
    text = text.replace("ARCHIVAGE=_F(PAS_ARCH=10)", "ARCHIVAGE=_F(PAS_ARCH=1)")
    anchor = (
        'F_GEN = PROJ_VECT_BASE(BASE=MODES, NUME_DDL_GENE=NUMG, VECT_ASSE=F_AS, TYPE_VECT="FORC")'
    )
    assert anchor in text
    text = text.replace(anchor, anchor + "\n" + KICK)
    excit = "EXCIT=_F(VECT_ASSE_GENE=F_GEN, FONC_MULT=FY),"
    assert excit in text
    text = text.replace(
        excit, "EXCIT=(_F(VECT_ASSE_GENE=F_GEN, FONC_MULT=FY), _F(VECT_ASSE_GENE=K_GEN, "
        "FONC_MULT=PULSE)),"
    )  # fmt: skip
    (folder / "kick.comm").write_text(text)
    (folder / "kick.export").write_text(
        f"P time_limit 600\nF comm kick.comm D 1\nF mail {REFERENCES / 'tube.mail'} D 20\n"
    )
    return folder / "kick.export"


@pytest.fixture(scope="module")
def runs(tmp_path_factory):
    if not DECK.is_file():
        pytest.skip("../shared/tube-references is not available")
    from asterlite.runtime.runner import run_deck

    folder = tmp_path_factory.mktemp("planar")
    deck = kicked_deck(folder)
    out = {}
    # a kick of about 1e-6 of the impact velocity (measured below)
    for name, amplitude in (("base", 0.0), ("kick", 1.3e-4)):
        report = run_deck(
            deck, folder / f"out-{name}-{os.getpid()}", overrides={"AK": amplitude}, time_limit=0
        )
        assert report.status == "DONE", report.message
        out[name] = report.namespace
    return out


def planar_model(namespace):
    tran = namespace["TRAN"]
    mass = np.asarray(namespace["MASG"].matrix, dtype=float)
    stiffness = np.asarray(namespace["RIGG"].matrix, dtype=float)
    n = mass.shape[0]
    shapes = {
        c: np.array([np.asarray(tran.basis.shape_at(node, c))[:n] for node in NODES])
        for c in ("DY", "DZ")
    }
    in_plane = E0[0] * shapes["DY"] + E0[1] * shapes["DZ"]  # (3 supports, n modes)
    out_of_plane = EP[0] * shapes["DY"] + EP[1] * shapes["DZ"]
    return mass, stiffness, in_plane, out_of_plane


def perturbation(namespace, kicked, c_t, i0):
    """Iterate the out-of-plane perturbation equations from the archived state
    difference at index i0 (DIFF_CENTRE: v += dt a, q += dt v, a from the new
    state) along the unkicked planar orbit; returns the out-of-plane velocity
    of the mid-span support at each later step."""
    base = namespace["TRAN"]
    mass, stiffness, in_plane, out_of_plane = planar_model(namespace)
    rates = 2.0 * XI * np.sqrt(np.diag(stiffness) / np.diag(mass))
    damping = rates[:, None] * mass
    minv = np.linalg.inv(mass)
    rho = in_plane @ base.depl.T  # (3, steps)
    rho_dot = in_plane @ base.vite.T
    normal = np.array([base.shocks[s].fields["FN"] for s in range(3)])
    anchors = [kicked.shocks[s].fields for s in range(3)], [base.shocks[s].fields for s in range(3)]
    # the stick anchor (VINT16..18: local x, y, z of the relative position at its start)
    p_a = np.array(
        [
            EP[0] * (anchors[0][s]["VINT17"][i0] - anchors[1][s]["VINT17"][i0])
            + EP[1] * (anchors[0][s]["VINT18"][i0] - anchors[1][s]["VINT18"][i0])
            for s in range(3)
        ]
    )
    rho_a = np.array(
        [
            E0[0] * anchors[1][s]["VINT17"][i0] + E0[1] * anchors[1][s]["VINT18"][i0]
            for s in range(3)
        ]
    )
    dq = kicked.depl[i0] - base.depl[i0]
    dv = kicked.vite[i0] - base.vite[i0]
    da = kicked.acce[i0] - base.acce[i0]
    out = np.full(len(base.times), np.nan)
    with np.errstate(over="ignore", invalid="ignore"):
        for j in range(i0 + 1, len(base.times)):
            dv = dv + DT * da
            dq = dq + DT * dv
            p, p_dot = out_of_plane @ dq, out_of_plane @ dv
            force = np.zeros(len(dq))
            for s in range(3):
                r = rho[s, j]
                if JEU - abs(r) > 0.0 or normal[s, j] <= 0.0:  # free, or no friction
                    p_a[s], rho_a[s] = p[s], r
                    if JEU - abs(r) > 0.0:
                        continue
                    f_perp = 0.0
                else:
                    f_perp = (
                        -K_T * (p[s] - p_a[s])
                        + K_T * p[s] * (r - rho_a[s]) / r
                        - c_t * p_dot[s]
                        + c_t * p[s] * rho_dot[s, j] / r
                        - normal[s, j] * p[s] / abs(r)
                    )
                force += f_perp * out_of_plane[s]
            da = minv @ (force - stiffness @ dq - damping @ dv)
            out[j] = out_of_plane[1] @ dv
    return out


def decay_rate(times, values, window=0.025):
    starts = np.arange(times[0], times[-1] - window, window)
    peaks = [np.max(np.abs(values[(times >= a) & (times < a + window)])) for a in starts]
    return np.polyfit(starts + window / 2.0, np.log(peaks), 1)[0]


def c_t_v17(namespace):
    mass, stiffness, *_ = planar_model(namespace)
    m, k = mass[-1, -1], stiffness[-1, -1]  # mode 20, the axial one, dominates here
    return 2.0 * np.sqrt(m * (k + K_T)) - 2.0 * XI * np.sqrt(k * m)


def test_kick_of_1e6_of_the_impact_velocity_decays_as_the_perturbation_equations_say(runs):
    base, kicked = runs["base"]["TRAN"], runs["kick"]["TRAN"]
    _, _, in_plane, out_of_plane = planar_model(runs["base"])
    t = base.times
    impact = np.max(np.abs(in_plane[1] @ base.vite[(t > 0.4) & (t < T_KICK)].T))
    after = t > T_KICK + 1.0e-3
    measured = out_of_plane[1] @ (kicked.vite - base.vite).T
    assert 3e-7 < np.max(np.abs(measured[after])) / impact < 3e-6  # about 1e-6
    # the unkicked orbit stays planar to round-off, the kicked one decays
    assert np.max(np.abs(out_of_plane[1] @ base.vite.T)) < 1e-12
    i0 = int(np.searchsorted(t, T_KICK + 1.0e-3))
    c_t = c_t_v17(runs["base"])
    assert c_t == pytest.approx(8042.47, rel=1e-4)  # what the engine took (code_aster 17's)
    model = perturbation(runs["base"], kicked, c_t, i0)
    sel = slice(i0 + 1, None)
    scale = np.max(np.abs(measured[sel]))
    np.testing.assert_allclose(model[sel], measured[sel], rtol=0.0, atol=1e-6 * scale)
    rate = decay_rate(t[sel], measured[sel])
    assert rate == pytest.approx(decay_rate(t[sel], model[sel]), rel=1e-4)
    assert rate < -5.0  # measured -8.6 /s over 0.5-0.75 s


def test_code_aster_15_default_amor_tan_makes_the_plane_unstable(runs):
    """The same perturbation with code_aster 13-15's AMOR_TAN: each stick step
    multiplies it by about 1 + |C_T| dt Σ φ_perp²/m (closed form)."""
    from asterlite.dynamics.model import (
        LinearSystem,
        ShockSpec,
        modal_damping_rates,
        optimal_tangential_damping_v15,
    )

    mass, stiffness, _, out_of_plane = planar_model(runs["base"])
    rates = modal_damping_rates(mass, stiffness, [XI])
    system = LinearSystem(mass, stiffness, rates[:, None] * mass, damping_rates=rates)
    spec = ShockSpec(
        name="S", obstacle_type="CERCLE", node_1="N21", node_2=None, coord_1=np.zeros(3),
        coord_2=None, phi_1=np.zeros((3, mass.shape[0])), phi_2=None,
        norm_obst=np.array([1.0, 0.0, 0.0]), k_t=K_T,
    )  # fmt: skip
    c_t = optimal_tangential_damping_v15(spec, system)
    assert c_t == pytest.approx(-1.2052e6, rel=1e-4)
    factor = 1.0 + abs(c_t) * DT * np.sum(out_of_plane[1] ** 2 / np.diag(mass))
    assert 120.0 < factor < 130.0
    base, kicked = runs["base"]["TRAN"], runs["kick"]["TRAN"]
    i0 = int(np.searchsorted(base.times, T_KICK + 1.0e-3))
    model = perturbation(runs["base"], kicked, c_t, i0)
    finite = np.isfinite(model[i0 + 1 :])
    start = np.max(np.abs(model[i0 + 1 : i0 + 100]))
    grown = np.nanmax(np.abs(model[i0 + 1 :][finite]))
    assert grown > 1e30 * start  # the perturbation equations blow up in the first contact


def test_aster_version_15_reproduces_code_aster_15_whirl(tmp_path):
    """The deck as code_aster 15.2 ran it (2 s): its orbit leaves the plane and
    wears the two busy supports as code_aster 15.2's did."""
    if not DECK.is_file():
        pytest.skip("../shared/tube-references is not available")
    from asterlite.runtime.runner import run_deck

    report = run_deck(
        REFERENCES / "tube_planar23.export", tmp_path / "out", aster_version=15, time_limit=0
    )
    assert report.status == "DONE", report.message
    wear = {s["shock"]: s["wear_power"] for s in report.shocks}
    # code_aster 15.2 (tube_planar23.code_aster_15.2.txt): 7.38958e-4, 1.45575e-3 W
    assert wear["SUPPORT_1"] == pytest.approx(7.38958e-4, rel=0.03)
    assert wear["SUPPORT_2"] == pytest.approx(1.45575e-3, rel=0.03)
