"""SCHEMA='EULER' (asterlite extension for legacy decks): code_aster 10's
explicit Euler of order one (mdeul1: v_{n+1} = v_n + dt a_n, then
q_{n+1} = q_n + dt v_{n+1}, then a_{n+1} from the new state)."""

import math
from pathlib import Path

import numpy as np
import pytest

from asterlite.errors import NumericalError
from tests.test_dynamics_schemes import OMEGA, contact_duration
from tests.test_dynamics_vibra import obstacle, one_mode, run_vibra, vector

DECKS = Path(__file__).parent / "legacy_decks"
CORPUS = Path(__file__).resolve().parents[2] / "shared" / "aster-corpus"


def launched_oscillator(scheme, pas, t_end):
    """Undamped 1 Hz oscillator launched from its rest position at OMEGA."""
    gnum, m, kk = one_mode(OMEGA**2, coords=(0.0, 0.0, 0.0), shape=(1.0, 0.0, 0.0))
    return run_vibra(m, kk, scheme, pas, t_end, etat={"VITE": vector(gnum, OMEGA, "VITE")})


def quarter_period_error(pas):
    """Error at a quarter period (q = 1, a = -OMEGA**2). At whole periods
    a(t) = 0 hides the first-order velocity lag (dt/2) a(t_n) of this
    scheme, which then looks second order."""
    result = launched_oscillator("EULER", pas, 0.25)
    assert result.times[-1] == pytest.approx(0.25)
    return abs(result.depl[-1, 0] - 1.0) + abs(result.vite[-1, 0]) / OMEGA


def test_euler_is_first_order():
    errors = [quarter_period_error(pas) for pas in (0.004, 0.002, 0.001)]
    orders = [math.log2(errors[i] / errors[i + 1]) for i in range(2)]
    assert orders == [pytest.approx(1.0, abs=0.1)] * 2


def test_euler_follows_mdeul1_update():
    """Velocity first with the acceleration of the state at t, then the
    displacement with the updated velocity: the hand recursion, bit for bit."""
    pas, steps = 0.01, 37
    result = launched_oscillator("EULER", pas, steps * pas)
    q, v = 0.0, OMEGA
    a = -(OMEGA**2) * q
    expected = [(q, v, a)]
    for _ in range(steps):
        v = v + pas * a
        q = q + pas * v
        a = -(OMEGA**2) * q
        expected.append((q, v, a))
    got = np.column_stack([result.depl[:, 0], result.vite[:, 0], result.acce[:, 0]])
    np.testing.assert_allclose(got, np.array(expected), rtol=1e-13, atol=1e-13)


def test_euler_is_code_aster_14_diff_centre():
    """code_aster 14 renamed EULER as the GENE DIFF_CENTRE (dtmprep maps it
    to _SCH_EULER / inteuler): the same arithmetic as asterlite's DIFF_CENTRE."""
    euler = launched_oscillator("EULER", 0.002, 1.0)
    centre = launched_oscillator("DIFF_CENTRE", 0.002, 1.0)
    np.testing.assert_array_equal(euler.depl, centre.depl)
    np.testing.assert_array_equal(euler.vite, centre.vite)


def test_euler_step_is_checked_at_a_twentieth_of_the_period():
    """code_aster 10's mdptem: EULER's step limit is 1/20 of the shortest
    period; VERI_PAS='OUI' makes a longer step an error."""
    from asterlite.dynamics.integrate import step_limit

    gnum, m, kk = one_mode(OMEGA**2, coords=(0.0, 0.0, 0.0), shape=(1.0, 0.0, 0.0))
    with pytest.raises(NumericalError, match="1/20"):
        run_vibra(m, kk, "EULER", 0.06, 1.0, etat={"VITE": vector(gnum, OMEGA, "VITE")})
    result = run_vibra(m, kk, "EULER", 0.049, 0.49, etat={"VITE": vector(gnum, OMEGA, "VITE")})
    assert result.scheme == "EULER"
    from asterlite.dynamics.model import LinearSystem, build_shocks

    system = LinearSystem(np.eye(1), np.eye(1) * OMEGA**2, np.zeros((1, 1)))
    assert step_limit(system, build_shocks([], system), "EULER") == pytest.approx(1.0 / 20.0)


def test_euler_bounce_on_a_stop():
    k, kn, gap = 1.0, 1.0e6, 0.01
    gnum, m, kk = one_mode(k, coords=(0.0, 0.0, 0.0), shape=(0.0, 1.0, 0.0))
    origin, axis = (0.0, 0.0, 0.0), (1.0, 0.0, 0.0)
    stop = dict(RELATION="DIS_CHOC", NOEUD_1="NO1", OBSTACLE=obstacle("PLAN_Y"),
                ORIG_OBST=origin, NORM_OBST=axis, JEU=gap, RIGI_NOR=kn)  # fmt: skip
    result = run_vibra(m, kk, "EULER", 2.0e-5, 0.016, etat={"VITE": vector(gnum, 1.0, "VITE")},
                       comportement=[stop])  # fmt: skip
    assert contact_duration(result, gap) == pytest.approx(math.pi / math.sqrt(kn + k), rel=0.01)
    after = np.nonzero(result.times > 0.0145)[0][0]
    assert result.vite[after, 0] == pytest.approx(-1.0, rel=0.01)


def test_catalogue_lists_euler_for_gene_only():
    from asterlite.catalog import load_catalogue

    modern = load_catalogue("DYNA_VIBRA")
    gene = modern.entries["b_schema_gene"].entries["SCHEMA_TEMPS"].entries["SCHEMA"].into
    assert "EULER" in gene
    phys = modern.entries["b_schema_phys"].entries["SCHEMA_TEMPS"].entries["SCHEMA"].into
    assert "EULER" not in phys


# ----------------------------------------------------------------- legacy deck

needs_corpus = pytest.mark.skipif(not CORPUS.is_dir(), reason="aster-corpus is absent")

# euler_v10 with an initial displacement and a test of the generalized
# displacement, so that the legacy and ported runs compare actual values
INITIAL_STATE = """DEPLPHYS = CREA_CHAMP(
    OPERATION='AFFE', PROL_ZERO='OUI', TYPE_CHAM='NOEU_DEPL_R', MAILLAGE=POUTRE, NUME_DDL=NUMEROTA,
    AFFE=_F(TOUT='OUI', NOM_CMP='DX', VALE=1.0e-3),
)
DEPINI = PROJ_VECT_BASE(BASE=MODES, VECT_ASSE=DEPLPHYS, NUME_DDL_GENE=NUMEGE, TYPE_VECT='DEPL')
DYNAMODA = DYNA_TRAN_MODAL(
    ETAT_INIT=_F(DEPL=DEPINI),"""
CHECK = """DXGENE = RECU_FONCTION(RESU_GENE=DYNAMODA, NOM_CHAM='DEPL', NUME_CMP_GENE=1)
TEST_FONCTION(VALEUR=(
    _F(VALE_CALC=1.0e-3, VALE_PARA=0.0, FONCTION=DXGENE),
    _F(VALE_CALC={calc!r}, VALE_REFE={refe!r}, REFERENCE='ANALYTIQUE', PRECISION=1.0e-2,
       VALE_PARA=0.1, FONCTION=DXGENE),
))
FIN()"""


def euler_recursion(q, omega2, c, dt, steps):
    """mdeul1 by hand on one mode (unit generalized mass)."""
    v = 0.0
    a = -omega2 * q - c * v
    for _ in range(steps):
        v = v + dt * a
        q = q + dt * v
        a = -omega2 * q - c * v
    return q


def variant_deck(tmp_path: Path) -> tuple[Path, float]:
    """euler_v10 with ETAT_INIT and a TEST_FONCTION; the expected q(0.1)."""
    zeta, omega = 0.01, 10.0  # K_T_D_N 1e4, M_T_D_N 100, AMOR_REDUIT 0.01
    calc = euler_recursion(1.0e-3, omega**2, 2.0 * zeta * omega, 1.0e-3, 100)
    wd, t = omega * math.sqrt(1.0 - zeta**2), 0.1
    refe = (
        1.0e-3
        * math.exp(-zeta * omega * t)
        * (math.cos(wd * t) + zeta / math.sqrt(1.0 - zeta**2) * math.sin(wd * t))
    )
    source = (DECKS / "euler_v10.comm").read_text()
    assert source.count("DYNAMODA = DYNA_TRAN_MODAL(") == 1 and source.count("FIN()") == 1
    source = source.replace("DYNAMODA = DYNA_TRAN_MODAL(", INITIAL_STATE)
    source = source.replace("FIN()", CHECK.format(calc=calc, refe=refe))
    comm = tmp_path / "euler_state_v10.comm"
    comm.write_text(source)
    lines = []
    for line in (DECKS / "euler_v10.export").read_text().splitlines():
        fields = line.split()
        if fields[:2] == ["F", "comm"]:
            fields[2] = comm.name
        elif fields[:1] == ["F"]:
            fields[2] = str((DECKS / fields[2]).resolve())
        lines.append(" ".join(fields))
    export = tmp_path / "euler_state_v10.export"
    export.write_text("\n".join(lines) + "\n")
    return export, calc


def ported_copy(export: Path, tmp_path: Path) -> Path:
    from asterlite.legacy.port import port_file

    comm = export.with_suffix(".comm")
    if not comm.exists():
        comm = DECKS / f"{export.stem}.comm"
    result = port_file(comm)
    assert not result.skipped
    ported = tmp_path / f"{export.stem}_ported.comm"
    ported.write_text(result.text, encoding="utf-8")
    lines = []
    for line in export.read_text().splitlines():
        fields = line.split()
        if fields[:2] == ["F", "comm"]:
            fields[2] = ported.name
        elif fields[:1] == ["F"]:
            fields[2] = str((export.parent / fields[2]).resolve())
        lines.append(" ".join(fields))
    out = tmp_path / f"{export.stem}_ported.export"
    out.write_text("\n".join(lines) + "\n")
    return out


def deprecations(folder: Path) -> list[str]:
    log = (folder / "message.log").read_text()
    return [line for line in log.splitlines() if line.startswith("deprecated: ")]


@needs_corpus
def test_euler_legacy_deck_runs_and_matches_its_ported_twin(tmp_path):
    from asterlite.runtime.runner import run_deck

    legacy_export = DECKS / "euler_v10.export"
    ported_export = ported_copy(legacy_export, tmp_path)
    # code_aster 17 has no EULER: the legacy layer writes the generalized DIFF_CENTRE,
    # the same explicit update
    assert 'SCHEMA_TEMPS=_F(SCHEMA="DIFF_CENTRE")' in ported_export.with_suffix(".comm").read_text()
    reports = {}
    for name, export in (("legacy", legacy_export), ("ported", ported_export)):
        assert run_deck(export, check_only=True).status == "CHECKED"
        reports[name] = run_deck(export, tmp_path / name)
        assert reports[name].status == "DONE", reports[name].message  # no TEST_*
        (transient,) = reports[name].transients
        assert transient["scheme"] == "DIFF_CENTRE" and transient["steps"] == 100
    assert any("legacy default EULER" in line for line in deprecations(tmp_path / "legacy"))
    assert not deprecations(tmp_path / "ported")


@needs_corpus
def test_euler_legacy_deck_values_match_mdeul1(tmp_path):
    """With an initial displacement: legacy and ported runs give the same
    TEST_FONCTION values, the hand recursion's to 1e-12, within 1 % of the
    analytic damped response."""
    from asterlite.runtime.runner import run_deck

    export, calc = variant_deck(tmp_path)
    legacy = run_deck(export, tmp_path / "legacy")
    ported = run_deck(ported_copy(export, tmp_path), tmp_path / "ported")
    for report in (legacy, ported):
        assert report.status == "PASS", report.message
        assert report.checks_total == 2 and report.strict_ok == report.checks_total
    values = [(t.label, t.value) for t in legacy.tests]
    assert values == [(t.label, t.value) for t in ported.tests]
    assert values[-1][1] == pytest.approx(calc, rel=1e-12)
