"""What code_aster 15 computed differently with the same keywords, followed for
its decks (asterlite.legacy.v15.OLD_BEHAVIOURS and the forms around it): the
scalar buckling law, the NEWMARK right-hand side, TEST_RESU's NUME_ORDRE on a
tran_gene, POST_DYNA_MODA_T's window, node names in POST_GENE_PHYS tables,
code_aster 15's generated names (INTITULE, FILTRE, counts), numpy.savetxt."""

from __future__ import annotations

from types import SimpleNamespace

import numpy as np
import pytest
from asterlite.commands.dyna_vibra_relations import read_flambage, relation_words

from asterlite.errors import AsterliteError
from asterlite.lang import Evaluator, parse_deck, savetxt
from asterlite.legacy.v15 import OLD_BEHAVIOURS, computes, relation_title
from asterlite.legacy.v15_names import GeneratedNames, names_consumed
from commands.post_dyna_moda_t import summed_times, truncated_window
from commands.test_resu import _gene_state_index
from tests.validated import relation

# ------------------------------------------------------------------ versions


@pytest.mark.parametrize(
    ("version", "expected"), [(11, True), (15, True), (16, False), (17, False)]
)
def test_behaviours_follow_the_decks_version(version, expected):
    session = SimpleNamespace(aster_version=version)
    assert computes(session, "TEST_RESU_GENE_NUME_ORDRE_AS_POSITION") is expected
    assert computes(session, "NEWMARK_FORCE_AT_STEP_START") is (13 <= version <= 15)
    assert not computes(None, "NEWMARK_FORCE_AT_STEP_START")
    assert all(first <= last <= 15 for first, last in OLD_BEHAVIOURS.values())


# ------------------------------------------------- code_aster 15's buckling law


def scalar_law(**extra):
    from asterlite.dynamics.laws import flambage as FL

    kw = {"RIGI_NOR": 1.0, "FNOR_CRIT": 1.0, "FNOR_POST_FL": 0.5, **extra}
    params = FL.prepare_scalar_flambage(read_flambage(relation("FLAMBAGE", kw)))
    return FL, params, FL.initial_state(params)


def test_scalar_buckling_law_elastic_then_buckled_then_unloaded():
    FL, params, state = scalar_law()
    path = [(0.5, -2.0), (1.01, -1.0), (1.5, -1.0), (2.0, -0.5), (1.5, 1.0), (0.8, 1.0)]
    got = []
    for u, vn in path:
        got.append((FL.buckling_force(params, -u, vn, state, state), state[FL.V_DEFPLA]))
    assert got[0] == (0.5, 0.0)  # elastic below FNOR_CRIT / RIGI_NOR
    assert got[1] == (1.0, 1.0e-20)  # buckling starts at FNOR_CRIT
    # post-buckling: FNOR_POST_FL, the crushing follows (stiffness 0.5 reached)
    assert got[2] == (0.5, 0.5) and got[3] == (0.5, 1.0)
    assert got[4] == (0.25, 1.0)  # unloading elastic from the crushing reached
    assert got[5] == (0.0, 1.0)  # no force inside the gap the crushing opened
    assert state[FL.V_DEFMAX] == 2.0 and state[FL.V_RIGI] == 0.5


def test_scalar_buckling_law_post_buckling_points_and_excluded_damping():
    FL, params, state = scalar_law(
        DEPL_POST_FL=(2.0,), RIGI_POST_FL=(0.25,), AMOR_NOR=0.1, CRIT_AMOR="EXCLUS"
    )
    FL.buckling_force(params, -1.01, -1.0, state, state)  # buckles
    # between the branches (total penetrations 1 and 2 + 0.5/0.25 = 4): crushing halfway
    fn = FL.buckling_force(params, -2.5, -1.0, state, state)
    assert state[FL.V_DEFPLA] == pytest.approx(1.0)
    assert fn == pytest.approx(0.5 + 0.1)  # EXCLUS: damping added after the threshold


def test_scalar_buckling_law_checks_its_data():
    from asterlite.dynamics.laws.tabulated import LawError

    with pytest.raises(LawError, match="same length"):
        scalar_law(DEPL_POST_FL=(2.0,))
    with pytest.raises(LawError, match="RIGI_NOR"), relation_words("FLAMBAGE"):
        scalar_law(RIGI_NOR=0.0)


# ------------------------------------------------------------ NEWMARK


def test_newmark_of_code_aster_15_takes_the_forces_of_the_steps_start():
    from asterlite.dynamics.excitation import tabulate_excitation
    from asterlite.dynamics.integrate import integrate
    from asterlite.dynamics.model import LinearSystem, build_shocks
    from tests.validated import scheme_options

    class Ramp:  # F(t) = t on the single mode
        def evaluate(self, t):
            return np.asarray(t, dtype=float)

    system = LinearSystem(np.eye(1), 4.0 * np.eye(1), np.zeros((1, 1)))
    dt, t_end = 0.01, 0.05
    excitation = tabulate_excitation(1, [(np.ones(1), Ramp())], 0.0, t_end, dt / 2.0)

    def run(at_start):
        return integrate(
            system, build_shocks([], system), excitation, "NEWMARK", np.zeros(1), np.zeros(1), 0.0,
            t_end, dt, np.array([]), 1, scheme_options("NEWMARK", force_at_step_start=at_start),
        )  # fmt: skip

    # the trapezoidal rule by hand, with F(t_n) (code_aster 15) or F(t_n+1) (17)
    for at_start in (True, False):
        q = v = a = 0.0
        for n in range(5):
            force = n * dt if at_start else (n + 1) * dt
            keff = 4.0 / dt**2 + 4.0
            q_new = (force + 4.0 / dt**2 * q + 4.0 / dt * v + a) / keff
            a_new = 4.0 / dt**2 * (q_new - q - dt * v) - a
            v += dt / 2.0 * (a + a_new)
            q, a = q_new, a_new
        assert run(at_start).depl[-1, 0] == pytest.approx(q, rel=1e-12)


# ------------------------------------------------------- TEST_RESU / POST_DYNA_MODA_T


def test_test_resu_gene_nume_ordre_is_a_position_for_code_aster_15():
    result = SimpleNamespace(times=np.array([0.0, 0.1, 0.2]), order=np.array([0, 10, 20]))
    logged = []

    def ctx(version):
        return SimpleNamespace(
            session=SimpleNamespace(aster_version=version), log=logged.append, error=None
        )

    assert _gene_state_index(ctx(15), {"NUME_ORDRE": 2}, result)[0] == 1
    assert "2th archived instant" in logged[-1]
    assert _gene_state_index(ctx(17), {"NUME_ORDRE": 20}, result)[0] == 2


def test_statch_window_truncates_code_asters_summed_times():
    """sdnl301a: 50000 steps of 5e-6, every 10th archived: the sums fall a rounding
    short of 0.17 and 0.25, so code_aster 15 started and ended one instant early."""
    order = np.arange(0, 50001, 10)
    times = order * 0.5e-5
    summed = summed_times(times, order)
    assert summed[3400] != 0.17 and summed[3400] == pytest.approx(0.17)
    ctx = SimpleNamespace(log=lambda text: None, error=None)
    window = truncated_window(ctx, {"INST_INIT": 0.17, "INST_FIN": 0.25}, times, order)
    assert (window.start, window.stop) == (3399, 5000)
    irregular = np.array([0.0, 0.1, 0.3])
    assert summed_times(irregular, np.array([0, 1, 2])) is irregular


# ----------------------------------------------------- generated names


def test_relation_title_of_code_aster_15():
    names = GeneratedNames()
    function = SimpleNamespace(name="FX_REL")
    names.concepts[12] = function
    names.consumed = 12
    nodes = {"N01": 0, "N03": 2}
    today = ("3       DX      FX_REL", "")
    assert relation_title("N03     DX      0000000c", nodes, names) == today
    assert relation_title("N99     DX      0000000c", nodes, names) == (None, "")  # not that form
    title, why = relation_title("N03     DX      0000000d", nodes, names)
    assert title is None and "0000000d" in why


def test_counts_of_the_commands_sdnd120a_follows():
    keywords = SimpleNamespace(peek=lambda name: None, given=())
    assert names_consumed("DEFI_GROUP", keywords, None, "MESH", {}).count == 0
    for command in ("CREA_MAILLAGE", "MODE_STATIQUE", "CALC_CHAR_SEISME", "INFO_FONCTION"):
        assert names_consumed(command, keywords, None, None, {}).count == 1
    seismic = SimpleNamespace(peek=lambda name: {}, given=("NOCI_SEISME",))
    assert names_consumed("INFO_FONCTION", seismic, None, None, {}) is None


# ------------------------------------------------------------- numpy.savetxt


def run_deck_text(text: str, writer):
    token = savetxt.set_writer(writer)
    try:
        Evaluator({}).run(parse_deck(text, "deck.comm"))
    finally:
        savetxt.reset_writer(token)


def test_savetxt_writes_through_the_runs_writer(tmp_path):
    opened = []

    def writer(name):
        opened.append(name)
        return open(tmp_path / name, "w")

    run_deck_text(
        "import numpy as np\nnp.savetxt('t.csv', np.array([[1.0, 2.0], [3.0, 4.5]]), "
        "fmt='%.2f', delimiter=',', header='a,b')\n",
        writer,
    )
    assert opened == ["t.csv"]
    assert (tmp_path / "t.csv").read_text() == "# a,b\n1.00,2.00\n3.00,4.50\n"


@pytest.mark.parametrize(
    ("call", "message"),
    [
        ("np.savetxt('../t.csv', [1.0])", "plain file name"),
        ("np.savetxt('t.csv', [1.0], fmt='%1000f')", "printf field"),
        ("np.savetxt('t.csv', [[[1.0]]])", "1-D or 2-D"),
        ("np.savetxt('t.csv', ['a'])", "real numbers"),
    ],
)
def test_savetxt_refuses_paths_formats_and_shapes(call, message):
    with pytest.raises(AsterliteError, match=message):
        run_deck_text(f"import numpy as np\n{call}\n", lambda name: pytest.fail("written"))


def test_savetxt_outside_a_run_and_under_check():
    with pytest.raises(AsterliteError, match="not available"):
        Evaluator({}).run(parse_deck("import numpy as np\nnp.savetxt('t.csv', [1.0])\n", "d"))
    run_deck_text("import numpy as np\nnp.savetxt('t.csv', [1.0])\n", lambda name: None)
