"""AFFE_CHAR_MECA/FORCE_ELEC (Laplace forces on beam conductors) and
DEFI_FONC_ELEC (their intensity in time) against closed forms: two infinite
parallel currents attract with mu0 i1 i2 / (2 pi d) per unit length, a finite
segment's field is Biot and Savart's, and the short-circuit currents are
sqrt(2) I (cos(w t + phi) - exp(-t / T) cos phi)."""

from __future__ import annotations

import math

import numpy as np
import pytest
from scipy.integrate import quad

from asterlite.fem.laplace_force import FINITE, INFINITE, SecondConductor, laplace_vectors
from asterlite.fem.loads import load_terms
from tests.test_fem_structures import beam_model, line_mesh
from tests.test_fem_support import FakeSession, run, validated_run

MU0 = 4.0e-7 * math.pi
LENGTH, N_EL, D = 2.0, 8, 0.35


def _load_vector(session, model, cara, **force_elec):
    load = run(session, "AFFE_CHAR_MECA", MODELE=model, FORCE_ELEC=force_elec)
    total = {}
    for node, comp, value in load_terms(load, cara):
        total[(node, comp)] = total.get((node, comp), 0.0) + value
    return total


def _component(total, comp, n_nodes):
    return np.array([total.get((n, comp), 0.0) for n in range(n_nodes)])


def test_parallel_conductors_every_form_gives_one_over_d():
    """The second conductor along y = D given as an infinite line, a parallel
    at DIST through a point, a translation, or the force itself: the same
    consistent loads, 1/D per unit length towards it, q L^2 / 12 end moments."""
    session = FakeSession()
    model, _, cara = beam_model(session, line_mesh(N_EL, LENGTH))
    forms = [
        {"POSITION": "INFI", "POINT1": (0.0, D, 0.0), "POINT2": (1.0, D, 0.0)},
        {"POSITION": "PARA", "DIST": D, "POINT2": (5.0, D, 0.0)},
        {"POSITION": "PARA", "TRANS": (0.0, D, 0.0)},
        {"FY": 1.0 / D},
    ]
    vectors = [_load_vector(session, model, cara, TOUT="OUI", **form) for form in forms]
    n_nodes = N_EL + 1
    h = LENGTH / N_EL
    for form, total in zip(forms, vectors, strict=True):
        # INFI integrates along the cell with 100 midpoints (as code_aster):
        # the end moments carry the midpoint rule's error, h^2/24 of q L
        moment_tolerance = 1e-4 if form.get("POSITION") == "INFI" else 1e-12
        fy = _component(total, "DY", n_nodes)
        assert fy.sum() == pytest.approx(LENGTH / D, rel=1e-12)
        assert fy[1:-1] == pytest.approx(np.full(N_EL - 1, h / D), rel=1e-12)
        mz = _component(total, "DRZ", n_nodes)
        assert mz[0] == pytest.approx(h**2 / (12 * D), rel=moment_tolerance)
        assert mz[-1] == pytest.approx(-(h**2) / (12 * D), rel=moment_tolerance)
        assert np.abs(mz[1:-1]).max() < 1e-12
        for comp in ("DX", "DZ", "DRX", "DRY"):
            assert np.abs(_component(total, comp, n_nodes)).max() < 1e-12
    # opposite directions of the second conductor's current: repulsion
    reverse = _load_vector(
        session,
        model,
        cara,
        TOUT="OUI",
        POSITION="INFI",
        POINT1=(1.0, D, 0.0),
        POINT2=(0.0, D, 0.0),
    )
    assert _component(reverse, "DY", n_nodes).sum() == pytest.approx(-LENGTH / D, rel=1e-12)


def test_force_between_two_currents_closed_form():
    """FORCE_ELEC times DEFI_FONC_ELEC at an instant is mu0 i1 i2 L / (2 pi d)."""
    session = FakeSession()
    model, _, cara = beam_model(session, line_mesh(N_EL, LENGTH))
    total = _load_vector(
        session, model, cara, TOUT="OUI", POSITION="INFI", POINT1=(0, D, 0), POINT2=(1, D, 0)
    )
    spatial = _component(total, "DY", N_EL + 1).sum()
    i1, i2, tau, phi2 = 15600.0, 9000.0, 0.066, 30.0
    func = validated_run(
        session,
        "DEFI_FONC_ELEC",
        COUR={
            "INTE_CC_1": i1,
            "TAU_CC_1": tau,
            "PHI_CC_1": 0.0,
            "INTE_CC_2": i2,
            "TAU_CC_2": tau,
            "PHI_CC_2": phi2,
            "INST_CC_INIT": 0.0,
            "INST_CC_FIN": 0.2,
        },
    )
    t = 0.0125  # a sampled instant (step 1/2000 s)

    def current(rms, phi):
        a = math.radians(phi)
        return (
            math.sqrt(2)
            * rms
            * (math.cos(100 * math.pi * t + a) - math.exp(-t / tau) * math.cos(a))
        )

    expected = MU0 * current(i1, 0.0) * current(i2, phi2) * LENGTH / (2 * math.pi * D)
    assert float(func.evaluate(t)) * spatial == pytest.approx(expected, rel=1e-12)


def test_finite_segment_is_biot_savart_and_tends_to_the_infinite_line():
    """A conductor parallel to the segment P1 P2 (half-length a) at distance d:
    the force is (1 / 2d) [sqrt((x + a)^2 + d^2) - sqrt((x - a)^2 + d^2)] between
    its ends (the integral of (cos a1 - cos a2) / (2 d)); a very long segment
    gives the infinite line's 1/d."""
    x1 = np.array([[-0.4, 0.0, 0.0], [0.1, 0.0, 0.0]])
    x2 = np.array([[0.1, 0.0, 0.0], [0.9, 0.0, 0.0]])
    a, d = 0.5, 0.2
    finite = SecondConductor(FINITE, (-a, d, 0.0), (a, d, 0.0))
    total = laplace_vectors(x1, x2, finite)[:, [1, 7]].sum()

    def primitive(x):
        return (math.hypot(x + a, d) - math.hypot(x - a, d)) / (2 * d)

    assert total == pytest.approx(primitive(0.9) - primitive(-0.4), rel=1e-5)
    long = SecondConductor(FINITE, (-1e6, d, 0.0), (1e6, d, 0.0))
    infinite = SecondConductor(INFINITE, (-1e6, d, 0.0), (1e6, d, 0.0))
    np.testing.assert_allclose(
        laplace_vectors(x1, x2, long), laplace_vectors(x1, x2, infinite), rtol=1e-9
    )


def test_varying_field_is_spread_as_code_aster_spreads_it():
    """A cell from r = 1 to r = 3, radial to an infinite line along z: the
    field 1/r pushes it along z with ln 3 in all. code_aster's te0145 weights
    the point at distance (1 - alpha) L from the first node with the first
    node's shape functions at alpha; asterlite gives the same vector."""
    x1, x2 = np.array([[1.0, 0.0, 0.0]]), np.array([[3.0, 0.0, 0.0]])
    vector = laplace_vectors(x1, x2, SecondConductor(INFINITE, (0, 0, 0), (0, 0, 1)))[0]
    length = 2.0
    # 100 midpoints: the rule's error (h^2 / 24) [f'], 1.5e-5 here
    assert vector[2] + vector[8] == pytest.approx(math.log(3.0), rel=2e-5)

    def q(xi):  # the field at the point code_aster pairs with alpha = xi
        return 1.0 / (1.0 + (1.0 - xi) * length)

    shapes = {
        2: lambda s: 1 - 3 * s**2 + 2 * s**3,
        8: lambda s: 3 * s**2 - 2 * s**3,
    }
    for row, shape in shapes.items():
        expected = quad(lambda s, shape=shape: shape(s) * q(s) * length, 0.0, 1.0)[0]
        assert vector[row] == pytest.approx(expected, rel=1e-4)
    # the far node takes the larger share (the mirrored spread)
    assert vector[8] > vector[2]
    # moments about -y (force along z on an x-axis cell), L times the cubic's rotations
    expected = quad(lambda s: (s - 2 * s**2 + s**3) * length * q(s) * length, 0.0, 1.0)[0]
    assert vector[4] == pytest.approx(-expected, rel=1e-4)


def test_later_occurrence_replaces_earlier_on_its_cells():
    session = FakeSession()
    model, _, cara = beam_model(session, line_mesh(2, 1.0))
    load = run(
        session,
        "AFFE_CHAR_MECA",
        MODELE=model,
        FORCE_ELEC=[
            {"TOUT": "OUI", "FY": 3.0},
            {"GROUP_MA": ("POUTRE",), "FZ": 2.0},
        ],
    )
    terms = load_terms(load, cara)
    assert sum(v for _, c, v in terms if c == "DY") == 0.0
    assert sum(v for _, c, v in terms if c == "DZ") == pytest.approx(2.0)


def test_axial_force_is_lumped_without_moments():
    vector = laplace_vectors(
        np.zeros((1, 3)), np.array([[2.0, 0.0, 0.0]]), SecondConductor("DIRECT", (5.0, 0.0, 0.0))
    )[0]
    np.testing.assert_allclose(vector, [5, 0, 0, 0, 0, 0, 5, 0, 0, 0, 0, 0])


def _cour(**changes):
    base = {
        "INTE_CC_1": 1000.0,
        "TAU_CC_1": 0.05,
        "PHI_CC_1": 0.0,
        "INTE_CC_2": 2000.0,
        "TAU_CC_2": 0.08,
        "PHI_CC_2": 180.0,
        "INST_CC_INIT": 0.0,
        "INST_CC_FIN": 0.1,
    }
    return base | changes


def test_defi_fonc_elec_sampling_gaps_and_continuation():
    """Steps of 1 / (40 FREQ); a zero where a short circuit ends before the
    next starts, the next counting its own time; an occurrence starting where
    the first ends continues its wave; a zero two steps after the end."""
    session = FakeSession()
    func = validated_run(
        session,
        "DEFI_FONC_ELEC",
        FREQ=60.0,
        COUR=[_cour(), _cour(INST_CC_INIT=0.3, INST_CC_FIN=0.4)],
    )
    step = 1.0 / 2400.0
    x, y = func.abscissas, func.ordinates
    first = x[x < 0.1]
    np.testing.assert_allclose(np.diff(first), step, rtol=1e-9)
    assert 0.1 in x.tolist() and y[x.tolist().index(0.1)] == 0.0
    assert x[-1] == pytest.approx(x[-2] + 2 * step) and y[-1] == 0.0
    assert func.PROL_GAUCHE == "CONSTANT" and func.PROL_DROITE == "CONSTANT"
    # the second short circuit starts from zero current at 0.3
    assert y[x.tolist().index(0.3)] == pytest.approx(0.0, abs=1e-9)
    continued = validated_run(
        session,
        "DEFI_FONC_ELEC",
        COUR=[_cour(), _cour(INST_CC_INIT=0.1, INST_CC_FIN=0.2)],
    )
    one = validated_run(session, "DEFI_FONC_ELEC", COUR=[_cour(INST_CC_FIN=0.2)])
    t = 0.15
    assert float(continued.evaluate(t)) == pytest.approx(float(one.evaluate(t)), rel=1e-9)


def test_defi_fonc_elec_continu_is_the_period_average():
    """SIGNAL='CONTINU' is COMPLET averaged over a period (exactly so when the
    offsets do not decay)."""
    session = FakeSession()
    slow = {"TAU_CC_1": 1e12, "TAU_CC_2": 1e12, "PHI_CC_1": 20.0, "PHI_CC_2": 75.0}
    complete = validated_run(session, "DEFI_FONC_ELEC", COUR=_cour(INST_CC_FIN=1.0, **slow))
    averaged = validated_run(
        session, "DEFI_FONC_ELEC", SIGNAL="CONTINU", COUR=_cour(INST_CC_FIN=1.0, **slow)
    )
    period = complete.ordinates[400:440]  # one period, 40 steps, from 0.2 s
    assert complete.abscissas[400] == pytest.approx(0.2)
    assert float(averaged.evaluate(0.5)) == pytest.approx(period.mean(), rel=1e-9)


def test_defi_fonc_elec_refuses_what_code_aster_cannot_compute(tmp_path):
    """COUR_PRIN and INTC_CC_*: valid code_aster 17, which its own
    macro-command cannot compute; check and run both refuse them by name."""
    from asterlite.runtime.check_deck import check_deck
    from asterlite.runtime.runner import run_deck

    occurrence = "INTE_CC_1=1.0, TAU_CC_1=0.1, PHI_CC_1=0.0, INST_CC_INIT=0.0, INST_CC_FIN=0.1"
    decks = {
        "COUR_PRIN": f"F = DEFI_FONC_ELEC(COUR_PRIN=_F({occurrence}),\n"
        "    COUR_SECO=_F(INTE_CC_2=1.0, TAU_CC_2=0.1, PHI_CC_2=0.0))\n",
        "INTC_CC_2": f"F = DEFI_FONC_ELEC(COUR=_F({occurrence}, INTE_CC_2=1.0,\n"
        "    TAU_CC_2=0.1, INTC_CC_2=3.0))\n",
    }
    for keyword, body in decks.items():
        deck = tmp_path / f"{keyword}.comm"
        deck.write_text(f"DEBUT()\n{body}FIN()\n")
        checked = check_deck(deck)
        assert any(f.kind == "unsupported" and keyword in f.text() for f in checked.findings), (
            checked.message
        )
        outcome = run_deck(deck, tmp_path / keyword)
        assert outcome.status == "UNSUPPORTED" and keyword in outcome.message
