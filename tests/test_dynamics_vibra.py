"""DYNA_VIBRA TRAN/GENE on hand-made one-mode systems, against analytic results."""

import math

import numpy as np
import pytest

from asterlite.catalog.keywords import Keywords
from asterlite.concepts.assembly import DofNumbering
from asterlite.concepts.mesh import Mesh
from asterlite.concepts.modes import (
    GeneralizedMatrix,
    GeneralizedNumbering,
    GeneralizedVector,
    ModeResult,
)
from asterlite.concepts.transient import Obstacle
from asterlite.errors import NumericalError, UnsupportedError
from asterlite.runtime.context import CommandContext
from commands import defi_obstacle, dyna_vibra
from tests.validated import occurrence

ANG = math.cos(math.pi / 4.0)


class Session:
    def __init__(self):
        self.lines = []

    def log(self, text):
        self.lines.append(text)


def ctx(command="DYNA_VIBRA"):
    return CommandContext(session=Session(), command=command)


def kws(path="DYNA_VIBRA", **values):
    return Keywords(values, path=path)


def one_mode(stiffness, coords=(ANG, ANG, 0.0), shape=(ANG, ANG, 0.0), mass=1.0):
    mesh = Mesh(
        coords=np.array([coords], dtype=float),
        node_names=["NO1"],
        cell_names=[],
        cell_types=[],
        cell_nodes=[],
        node_groups={"NO1": np.array([0])},
    )
    numbering = DofNumbering(mesh=mesh, dofs=[(0, "DX"), (0, "DY"), (0, "DZ")])
    basis = ModeResult(
        numbering=numbering,
        shapes=np.array(shape, dtype=float).reshape(3, 1),
        frequencies=np.array([math.sqrt(stiffness / mass) / (2 * math.pi)]),
        generalized_mass=np.array([mass]),
        generalized_stiffness=np.array([stiffness]),
    )
    gnum = GeneralizedNumbering(basis=basis, storage="DIAG")
    m = GeneralizedMatrix(numbering=gnum, matrix=np.array([[mass]]), kind="MASS")
    k = GeneralizedMatrix(numbering=gnum, matrix=np.array([[stiffness]]), kind="RIGI")
    return gnum, m, k


def vector(gnum, value, kind="DEPL"):
    return GeneralizedVector(numbering=gnum, values=np.array([value]), kind=kind)


def obstacle(kind):
    return defi_obstacle.run(ctx("DEFI_OBSTACLE"), kws("DEFI_OBSTACLE", TYPE=kind))


def run_vibra(m, k, scheme, pas, t_end, etat=None, comportement=(), **extra):
    schema = occurrence("SCHEMA_TEMPS", {"SCHEMA": scheme, **extra.pop("schema", {})})
    kw = kws(
        TYPE_CALCUL="TRAN",
        BASE_CALCUL="GENE",
        MATR_MASS=m,
        MATR_RIGI=k,
        SCHEMA_TEMPS=[schema],
        INCREMENT=[
            kws("DYNA_VIBRA/INCREMENT", PAS=pas, INST_FIN=t_end, VERI_PAS=extra.pop("veri", "OUI"))
        ],
        ETAT_INIT=[kws("DYNA_VIBRA/ETAT_INIT", **(etat or {}))] if etat else [],
        COMPORTEMENT=[occurrence("COMPORTEMENT", c) for c in comportement],
        **extra,
    )
    return dyna_vibra.run(ctx(), kw)


def friction_shock(mu=0.1):
    return dict(
        RELATION="DIS_CHOC",
        GROUP_NO_1="NO1",
        OBSTACLE=obstacle("PLAN_Z"),
        ORIG_OBST=(0.0, 0.0, 1.0),
        NORM_OBST=(0.0, 1.0, 0.0),
        JEU=0.5,
        RIGI_NOR=20.0,
        RIGI_TAN=4.0e5,
        FROTTEMENT="COULOMB",
        COULOMB=mu,
    )


@pytest.mark.parametrize("scheme", ["DIFF_CENTRE", "DEVOGE"])
def test_friction_oscillator_decays_by_4_mu_g_over_omega2_per_cycle(scheme):
    """sdnd100a setting: M=1, K=1e4, permanent FN = 10 N = M g, mu = 0.1."""
    k, u0, mu, g = 1.0e4, 0.85e-3, 0.1, 10.0
    gnum, m, kk = one_mode(k)
    w0 = math.sqrt(k)
    if scheme == "DEVOGE":  # sdnd100b's settings, archiving exactly at the half periods
        pas, extra = 1.0e-4, {"schema": {"TOLERANCE": 1.0e-8, "PAS_MAXI": 5.0e-4}}
        extra["ARCHIVAGE"] = [
            kws("DYNA_VIBRA/ARCHIVAGE", INST=tuple(n * math.pi / w0 for n in range(1, 5)))
        ]
    else:
        pas, extra = 5.0e-4, {}
    result = run_vibra(
        m,
        kk,
        scheme,
        pas,
        0.3,
        etat={"DEPL": vector(gnum, u0)},
        comportement=[friction_shock(mu)],
        **extra,
    )
    c = mu * g / k  # static friction offset mu M g / K
    for n in range(1, 5):
        expected = (-1) ** n * (u0 - 2 * n * c)
        q = np.interp(n * math.pi / w0, result.times, result.depl[:, 0])
        assert q == pytest.approx(expected, abs=1e-3 * u0)
    fn = result.shocks[0].fields["FN"]
    assert fn[1:] == pytest.approx(10.0)
    ft = np.hypot(result.shocks[0].fields["FT1"], result.shocks[0].fields["FT2"])
    assert np.all(ft <= mu * 10.0 * (1 + 1e-12))


def test_bouncing_contact_duration_is_half_period_of_shock_spring():
    """Free flight onto a PLAN_Y stop: contact lasts pi sqrt(m / (K_N + k))."""
    k, kn, gap = 1.0, 1.0e6, 0.01
    gnum, m, kk = one_mode(k, coords=(0.0, 0.0, 0.0), shape=(0.0, 1.0, 0.0))
    stop = dict(RELATION="DIS_CHOC", NOEUD_1="NO1", OBSTACLE=obstacle("PLAN_Y"),
                ORIG_OBST=(0.0, 0.0, 0.0),
                NORM_OBST=(1.0, 0.0, 0.0), JEU=gap, RIGI_NOR=kn)  # fmt: skip
    result = run_vibra(
        m,
        kk,
        "DIFF_CENTRE",
        1.0e-6,
        0.02,
        etat={"VITE": vector(gnum, 1.0, "VITE")},
        comportement=[stop],
    )
    fn = result.shocks[0].fields["FN"]
    in_contact = result.times[fn > 0.0]
    first = in_contact[in_contact < in_contact[0] + 0.005]
    duration = first[-1] - first[0] + 1.0e-6
    assert duration == pytest.approx(math.pi * math.sqrt(1.0 / (kn + k)), rel=0.01)
    assert result.shocks[0].fields["DYLOC"].max() > gap
    after = np.nonzero(result.times > first[-1] + 1.0e-5)[0][0]
    assert result.vite[after, 0] == pytest.approx(-1.0, rel=1e-3)  # elastic bounce


@pytest.mark.parametrize("scheme, order", [("DIFF_CENTRE", 2.0), ("DEVOGE", 4.0)])
def test_convergence_order_on_linear_oscillator(scheme, order):
    gnum, m, kk = one_mode((2 * math.pi) ** 2, coords=(0.0, 0.0, 0.0), shape=(1.0, 0.0, 0.0))
    errors = []
    for pas in (0.004, 0.002):
        fixed = {"PAS_MINI": pas, "PAS_MAXI": pas} if scheme == "DEVOGE" else {}
        result = run_vibra(m, kk, scheme, pas, 1.0, etat={"DEPL": vector(gnum, 1.0)}, schema=fixed)
        errors.append(abs(result.depl[-1, 0] - 1.0) + abs(result.vite[-1, 0]) / (2 * math.pi))
    assert math.log2(errors[0] / errors[1]) == pytest.approx(order, abs=0.35)


def test_archiving_instants_are_reached_exactly_and_pas_arch():
    gnum, m, kk = one_mode(100.0)
    arch = [kws("DYNA_VIBRA/ARCHIVAGE", INST=(0.0123, 0.05), PAS_ARCH=10)]
    result = run_vibra(
        m, kk, "DIFF_CENTRE", 1.0e-3, 0.1, etat={"DEPL": vector(gnum, 1.0)}, ARCHIVAGE=arch
    )
    assert result.times[0] == 0.0 and result.order[0] == 0
    assert 0.0123 in result.times and 0.05 in result.times
    assert result.times[-1] == pytest.approx(0.1)
    assert np.all(np.diff(result.times) > 0)
    assert len(result.times) < 20


def test_veri_pas_rejects_unstable_step_and_names_the_limit():
    gnum, m, kk = one_mode(1.0e4)
    with pytest.raises(NumericalError, match="PAS="):
        run_vibra(m, kk, "DIFF_CENTRE", 0.01, 0.1, etat={"DEPL": vector(gnum, 1.0)})


def test_divergence_is_reported_with_time_and_step():
    gnum, m, kk = one_mode(1.0e4)
    with pytest.raises(NumericalError, match=r"t=.*try PAS"):
        run_vibra(m, kk, "DIFF_CENTRE", 0.05, 200.0, etat={"DEPL": vector(gnum, 1.0)}, veri="NON")


def test_modal_damping_and_constant_load_reach_static_deflection():
    gnum, m, kk = one_mode(100.0)
    load = [kws("DYNA_VIBRA/EXCIT", VECT_ASSE_GENE=vector(gnum, 5.0, "FORC"), COEF_MULT=2.0)]
    amor = [kws("DYNA_VIBRA/AMOR_MODAL", AMOR_REDUIT=(0.5,))]
    result = run_vibra(m, kk, "DIFF_CENTRE", 1.0e-3, 5.0, EXCIT=load, AMOR_MODAL=amor)
    assert result.depl[-1, 0] == pytest.approx(10.0 / 100.0, rel=1e-4)
    assert result.acce[-1, 0] == pytest.approx(0.0, abs=1e-4)


def test_function_multiplier_is_tabulated():
    class Ramp:
        def evaluate(self, t):
            return np.asarray(t) * 3.0

    gnum, m, kk = one_mode(1.0e6)
    load = [kws("DYNA_VIBRA/EXCIT", VECT_ASSE_GENE=vector(gnum, 1.0, "FORC"), FONC_MULT=Ramp())]
    amor = [kws("DYNA_VIBRA/AMOR_MODAL", AMOR_REDUIT=(1.0,))]
    result = run_vibra(m, kk, "DIFF_CENTRE", 1.0e-4, 0.5, EXCIT=load, AMOR_MODAL=amor)
    assert result.depl[-1, 0] == pytest.approx(3.0 * 0.5 / 1.0e6, rel=1e-2)  # quasi-static


def test_unsupported_scheme_is_named():
    gnum, m, kk = one_mode(100.0)
    with pytest.raises(UnsupportedError, match="ITMI"):
        run_vibra(m, kk, "ITMI", 1.0e-3, 0.1)


def test_discret_obstacle_polygon():
    ob = defi_obstacle.run(
        ctx("DEFI_OBSTACLE"),
        kws("DEFI_OBSTACLE", TYPE="DISCRET", VALE=(0.0, 1.0, 180.0, 1.0, 360.0, 1.0)),
    )
    assert isinstance(ob, Obstacle) and ob.polar.shape == (3, 2)


def test_normal_damping_energy_loss_matches_the_clipped_dashpot_impact():
    """AMOR_NOR dissipates energy in an impact: with the force's positive
    part (seed eq. 11) the contact ends when K_N x + C_N v reaches zero; the
    rebound speed of that damped half-oscillation is computed in closed form
    and compared with the integrated one."""
    from scipy.optimize import brentq

    k, kn, gap, zeta = 1.0, 1.0e6, 0.01, 0.1
    cn = 2.0 * zeta * math.sqrt(kn * 1.0)
    gnum, m, kk = one_mode(k, coords=(0.0, 0.0, 0.0), shape=(0.0, 1.0, 0.0))
    stop = dict(RELATION="DIS_CHOC", NOEUD_1="NO1", OBSTACLE=obstacle("PLAN_Y"),
                ORIG_OBST=(0.0, 0.0, 0.0), NORM_OBST=(1.0, 0.0, 0.0), JEU=gap,
                RIGI_NOR=kn, AMOR_NOR=cn)  # fmt: skip
    result = run_vibra(
        m,
        kk,
        "DIFF_CENTRE",
        2.0e-7,
        0.013,
        etat={"VITE": vector(gnum, 1.0, "VITE")},
        comportement=[stop],
    )
    # penetration x(t) = v0/wd e^(-zeta w t) sin(wd t) from contact onset, v0 = 1
    omega = math.sqrt(kn)
    damped = omega * math.sqrt(1.0 - zeta**2)

    def penetration(t):
        return math.exp(-zeta * omega * t) * math.sin(damped * t) / damped

    def speed(t):
        return math.exp(-zeta * omega * t) * (
            math.cos(damped * t) - zeta * omega * math.sin(damped * t) / damped
        )

    separation = brentq(
        lambda t: kn * penetration(t) + cn * speed(t), 1e-3 / omega, math.pi / damped
    )
    rebound = speed(separation)  # negative: moving back out of the stop
    fn = result.shocks[0].fields["FN"]
    assert fn.min() >= 0.0  # the positive part: the stop never pulls
    assert np.all(result.shocks[0].fields["FN"][result.shocks[0].fields["DYLOC"] < gap] == 0.0)
    assert result.vite[-1, 0] == pytest.approx(rebound, rel=5e-3)
    lost = 0.5 * (1.0 - rebound**2)
    assert 0.5 * (1.0 - result.vite[-1, 0] ** 2) == pytest.approx(lost, rel=1e-2)


def test_divergence_from_heavy_damping_suggests_a_step_below_the_failing_one():
    """ξ = 150 at ω = 100 rad/s: the explicit update diverges at dt = 2e-4,
    far below 1/20 of the period; the advice names the damping and a smaller step."""
    gnum, m, kk = one_mode(1.0e4)
    with pytest.raises(NumericalError) as raised:
        run_vibra(
            m,
            kk,
            "DIFF_CENTRE",
            2.0e-4,
            1.0,
            etat={"DEPL": vector(gnum, 1.0)},
            veri="NON",
            AMOR_MODAL=[kws("DYNA_VIBRA/AMOR_MODAL", AMOR_REDUIT=(150.0,))],
        )
    message = str(raised.value)
    assert "modal damping of mode 1" in message
    suggested = float(message.split("e.g. PAS=")[1].split(";")[0])
    assert suggested < 2.0e-4
