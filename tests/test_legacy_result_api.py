"""code_aster 15's Python API that v15 decks call on results: a tran_gene's
nonlinearity accessors (LIST_ARCH, VARI_INTERNE, FORCE_NORMALE/AXIALE/
RELATION), ``aster.getvectjev`` and the object names code_aster 15
generates ("0000001b")."""

from __future__ import annotations

from pathlib import Path
from types import SimpleNamespace

import numpy as np
import pytest

from asterlite.catalog.keywords import Keywords
from asterlite.concepts.function import Function
from asterlite.concepts.lists import ListReal
from asterlite.concepts.transient import ShockHistory, TranGene
from asterlite.errors import CommandError, UnsupportedError
from asterlite.lang import Evaluator, parse_deck
from asterlite.lang.values import CO, Unknown
from asterlite.legacy.v15_names import GeneratedNames
from asterlite.post import deck_api
from asterlite.runtime.deck_api import aster_module
from asterlite.runtime.jeveux import getvectjev, split_name
from asterlite.runtime.runner import run_deck

from .test_post_support import small_transient

V15 = Path(__file__).resolve().parents[2] / "shared" / "aster-corpus-v15"


def history(name: str, relation: str, n_vint: int, times, scale: float) -> ShockHistory:
    """A nonlinearity whose VINTk is scale * (k + t)."""
    fields = {f"VINT{k}": scale * (k + times) for k in range(1, n_vint + 1)}
    return ShockHistory(name, relation, "N1", "N2", fields)


def nonlinear_transient() -> TranGene:
    result = small_transient()
    times = result.times
    result.shocks = [
        history("CHOC1", "DIS_CHOC", 20, times, 1.0),
        history("SISM", "ANTI_SISM", 8, times, 10.0),
        history("VISC", "DIS_VISC", 11, times, 100.0),
        history("RELA", "RELA_EFFO_VITE", 3, times, -1.0),
    ]
    return result


def run_snippet(text: str, **names) -> dict:
    namespace = dict(names)
    Evaluator(namespace).run(parse_deck(text, "snippet.comm"))
    return namespace


@pytest.fixture
def printed():
    lines: list[str] = []
    deck_api.set_sink(lines.append)
    yield lines
    deck_api.set_sink(None)


# ------------------------------------------------------------ tran_gene methods


def test_accessors_read_each_nonlinearitys_internal_variables(printed):
    result = nonlinear_transient()
    ns = run_snippet(
        "INST = R.LIST_ARCH()\nV2 = R.VARI_INTERNE(2)\nFN = R.FORCE_NORMALE(1)\n"
        "FA2 = R.FORCE_AXIALE(2)\nFA3 = R.FORCE_AXIALE(3)\nFR = R.FORCE_RELATION(4)\n",
        R=result,
    )
    t = result.times
    assert ns["INST"] == pytest.approx(t.tolist()) and isinstance(ns["INST"], list)
    assert ns["V2"].shape == (11, 8)  # one row per archived instant, ANTI_SISM's 8 variables
    assert ns["V2"][:, 3] == pytest.approx(10.0 * (4 + t))
    assert ns["FN"] == pytest.approx(1 + t)  # DIS_CHOC: VINT1
    assert ns["FA2"] == pytest.approx(10.0 * (1 + t))  # ANTI_SISM: VINT1
    assert ns["FA3"] == pytest.approx(100.0 * (8 + t))  # DIS_VISC: VINT8
    assert ns["FR"] == pytest.approx(-(2 + t))  # RELA_EFFO_VITE: VINT2
    assert any("ANTI_SISM non linearity (index=2)" in line for line in printed)
    assert any("F_AXIAL" in line for line in printed)


def test_default_index_is_the_first_nonlinearity(printed):
    result = nonlinear_transient()
    assert result.FORCE_NORMALE() == pytest.approx(1 + result.times)
    assert any("by default the first nonlinearity" in line for line in printed)
    assert result.VARI_INTERNE(1, describe=False).shape == (11, 20)


def test_accessors_refuse_other_relations_and_indices(printed):
    result = nonlinear_transient()
    with pytest.raises(CommandError, match="only DIS_CHOC, FLAMBAGE"):
        result.FORCE_NORMALE(2)
    with pytest.raises(CommandError, match="only RELA_EFFO_DEPL, RELA_EFFO_VITE"):
        result.FORCE_RELATION(1)
    with pytest.raises(CommandError, match="between 1 and 4"):
        result.FORCE_AXIALE(5)
    result.shocks = []
    with pytest.raises(CommandError, match="linear calculation"):
        result.VARI_INTERNE(1)


# ---------------------------------------------------------------- getvectjev


def fake_session(**concepts):
    for name, concept in concepts.items():
        concept.name = name
    return SimpleNamespace(namespace=dict(concepts), generated_names=GeneratedNames())


def jev(structure: str, suffix: str) -> str:
    return f"{structure:<19}{suffix:<13}"


def test_getvectjev_lays_vectors_out_as_code_aster():
    result = nonlinear_transient()
    curve = Function(np.array([0.0, 1.0, 2.0]), np.array([5.0, 6.0, 7.0]))
    session = fake_session(R=result, F=curve, L=ListReal(np.array([0.5, 1.5])))
    assert getvectjev(session, jev("F", ".VALE")) == (0.0, 1.0, 2.0, 5.0, 6.0, 7.0)
    assert getvectjev(session, jev("L", ".VALE")) == (0.5, 1.5)
    depl = getvectjev(session, jev("R", ".DEPL"))
    assert depl[6:8] == pytest.approx((0.3, 0.09))  # instant 3: both modes
    assert getvectjev(session, jev("R", ".DISC"))[-1] == 1.0
    assert getvectjev(session, jev("R", ".ORDR")) == tuple(range(11))
    nl = "R".ljust(16) + ".NL"
    assert getvectjev(session, jev(nl, ".TYPE")) == (1, 3, 4, 9)
    assert getvectjev(session, jev(nl, ".VIND")) == (1, 21, 29, 40, 43)
    vint = np.array(getvectjev(session, jev(nl, ".VINT"))).reshape(11, 42)
    assert vint[:, 28:39] == pytest.approx(result.VARI_INTERNE(3, describe=False))
    assert getvectjev(session, jev(nl, ".INTI"))[5:7] == ("SISM", "N1")


def test_getvectjev_refuses_what_it_cannot_rebuild():
    session = fake_session(R=nonlinear_transient())
    with pytest.raises(UnsupportedError, match="padded to 19 characters"):
        getvectjev(session, "R.DEPL")
    with pytest.raises(UnsupportedError, match="no concept named NOPE"):
        getvectjev(session, jev("NOPE", ".VALE"))
    with pytest.raises(UnsupportedError, match=r"vector \.FCHO of TranGene R"):
        getvectjev(session, jev("R", ".FCHO"))
    with pytest.raises(UnsupportedError, match="0000001b is a name code_aster 15 generates"):
        getvectjev(session, jev("0000001b", ".VALE"))
    assert split_name(jev("R".ljust(16) + ".NL", ".VINT")) == ("R", ".NL", ".VINT")


def test_aster_module_offers_getvectjev_only_and_errors_are_located():
    session = fake_session(F=Function(np.array([0.0, 1.0]), np.array([2.0, 3.0])))

    def loader(name):
        return aster_module(session) if name == "aster" else None

    namespace: dict = {}
    text = "import aster\nv = aster.getvectjev('F                  .VALE        ')\n"
    Evaluator(namespace, module_loader=loader).run(parse_deck(text, "d.comm"))
    assert namespace["v"] == (0.0, 1.0, 2.0, 3.0)
    with pytest.raises(UnsupportedError, match="aster.getcolljev") as refused:
        deck = "import aster\nc = aster.getcolljev('X')\n"
        Evaluator({}, module_loader=loader).run(parse_deck(deck, "d.comm"))
    assert refused.value.location is not None and refused.value.location.line == 2


# ------------------------------------------------------- code_aster 15 names


def call(**values) -> Keywords:
    keywords = Keywords(values)
    keywords.given = frozenset(values)
    return keywords


def sdnd121a_front(names: GeneratedNames) -> dict:
    """The commands of sdnd121a.comm before its RECU_FONCTION calls (concepts
    stand in as plain markers); returns the markers of the functions."""
    concepts = {}

    def run(command, concept=None, reuse=None, namespace=None, **keywords):
        names.record(command, call(**keywords), concept, reuse, None, namespace or {})

    for command in ("LIRE_MAILLAGE", "AFFE_MODELE", "AFFE_CARA_ELEM", "AFFE_CHAR_MECA"):
        run(command)
    run("AFFE_CHAR_MECA")
    outputs = {n: CO(n) for n in ("NUM_DDL", "K_ASSE", "M_ASSE", "F_ASSE")}
    run(
        "ASSEMBLAGE",
        NUME_DDL=outputs["NUM_DDL"],
        MATR_ASSE=[
            call(MATRICE=outputs["K_ASSE"], OPTION="RIGI_MECA"),
            call(MATRICE=outputs["M_ASSE"], OPTION="MASS_MECA"),
        ],
        VECT_ASSE=[call(VECTEUR=outputs["F_ASSE"], OPTION="CHAR_MECA")],
    )
    run("CALC_MODES", OPTION="CENTRE", CALC_FREQ=[call(NMAX_FREQ=1, FREQ=50.0)])
    run("FORMULE")
    run(
        "PROJ_BASE",
        MATR_ASSE_GENE=[call(MATRICE=CO("M_GENE")), call(MATRICE=CO("K_GENE"))],
        VECT_ASSE_GENE=[call(VECTEUR=CO("F_GENE"))],
    )
    run("DEFI_OBSTACLE")
    for _ in range(3):
        run("DYNA_VIBRA", BASE_CALCUL="GENE", TYPE_CALCUL="TRAN")
    for name in ("D_EULER", "V_EULER", "A_EULER", "D_ADAPT"):
        concepts[name] = Function(np.zeros(1), np.zeros(1))
        run("RECU_FONCTION", concepts[name])
    return concepts


def test_generated_names_follow_code_aster_15s_counter():
    names = GeneratedNames()
    functions = sdnd121a_front(names)
    # sdnd121a.com1 reads D_EULER as '0000001b', D_ADAPT as '0000001e'
    assert names.lookup("0000001b")[0] is functions["D_EULER"]
    assert names.lookup("0000001e")[0] is functions["D_ADAPT"]
    assert names.name_of(functions["V_EULER"]) == "0000001c"
    assert "inside ASSEMBLAGE" in names.lookup("0000000a")[1]


def test_an_uncounted_command_stops_the_correspondence():
    names = GeneratedNames()
    names.record("LIRE_MAILLAGE", call(), None, None, None, {})
    names.record("MACR_ELEM_DYNA", call(), None, None, None, {})  # not followed
    curve = Function(np.zeros(1), np.zeros(1))
    names.record("DEFI_FONCTION", call(), curve, None, None, {})
    concept, why = names.lookup("00000002")
    assert concept is None and "MACR_ELEM_DYNA" in why
    names = GeneratedNames()
    names.record("CALC_MODES", call(NORM_MODE=[call(NORME="MASS_GENE")]), None, None, None, {})
    assert names.stopped_by == "CALC_MODES"


# ------------------------------------------------------- v15 corpus decks


def truncated_deck(tmp_path, name: str, before: str, probe: str) -> Path:
    """The v15 deck up to the line starting with ``before``, then ``probe``;
    its mesh is read from the corpus."""
    folder = V15 / name
    if not folder.is_dir():
        pytest.skip("the v15 corpus is not available")
    lines = (folder / f"{name}.comm").read_text(encoding="utf-8").splitlines()
    cut = next(i for i, line in enumerate(lines) if line.startswith(before))
    deck = tmp_path / f"{name}.comm"
    deck.write_text("\n".join([*lines[:cut], probe, "FIN()", ""]), encoding="utf-8")
    mesh = next(line.split()[2] for line in (folder / f"{name}.export").read_text().splitlines()
                if line.startswith("F mail"))  # fmt: skip
    export = tmp_path / f"{name}.export"
    export.write_text(f"F comm {deck.name} D 1\nF mail {folder / mesh} D 20\n", encoding="utf-8")
    return export


def run_probe(tmp_path, name: str, before: str, probe: str) -> dict:
    report = run_deck(truncated_deck(tmp_path, name, before, probe), tmp_path / "out")
    assert report.status in ("PASS", "DONE"), report.message
    return report.namespace


@pytest.mark.slow
def test_sdnd125a_normal_force_matches_its_recu_fonction_check(tmp_path):
    ns = run_probe(
        tmp_path,
        "sdnd125a",
        "np.savetxt",
        "i = [abs(t - 0.68044) < 1e-9 for t in INST].index(True)\nFN_AT = FN_CH1[i]\n",
    )
    # the deck's own TEST_FONCTION of VINT1 of CHOC1 at 0.68044
    assert ns["FN_AT"] == pytest.approx(1698.44669074479, rel=1e-6)
    assert ns["VINT_CH2"].shape == (len(ns["INST"]), 20)
    assert ns["FN_CH2"] == pytest.approx(ns["VINT_CH2"][:, 0])


@pytest.mark.slow
def test_sdnd125c_axial_force_matches_its_recu_fonction_check(tmp_path):
    probe = (
        "F_AXIAL2 = INTEGR.FORCE_AXIALE(2)\nINST = INTEGR.LIST_ARCH()\n"
        "F_AT = F_AXIAL2[[abs(t - 0.5) < 1e-9 for t in INST].index(True)]\n"
    )
    ns = run_probe(tmp_path, "sdnd125c", "F_AXIAL2", probe)
    assert ns["F_AT"] == pytest.approx(-351.3009178233, rel=1e-6)  # F_DEV_2 at 0.5


@pytest.mark.slow
def test_sdnd125g_relation_force_and_generated_function_name(tmp_path):
    probe = (
        "import aster\nV = aster.getvectjev('0000001b           .VALE        ')\n"
        "F_REL = INTEGR.FORCE_RELATION()\nINST = INTEGR.LIST_ARCH()\n"
        "F_AT = F_REL[[abs(t - 0.45) < 1e-9 for t in INST].index(True)]\n"
    )
    ns = run_probe(tmp_path, "sdnd125g", "INTEGR.INFO_NONL", probe)
    # the deck names FV_REL '0000001b' in its INTITULE
    assert ns["V"] == tuple(ns["FV_REL"].getValues())
    assert ns["F_AT"] == pytest.approx(9.562489444456, rel=1e-6)  # its VINT2 check at 0.45


@pytest.mark.slow
def test_sdnd121a_reads_its_functions_by_generated_name(tmp_path):
    export = V15 / "sdnd121a" / "sdnd121a.export"
    if not export.is_file():
        pytest.skip("the v15 corpus is not available")
    # its three 10^6-instant results need more than the export's 1024 MB
    report = run_deck(export, tmp_path / "out", memory_limit=3000)
    assert report.status == "PASS", report.message
    assert report.checks_total == 283


def test_check_reads_no_vector_but_checks_the_names_form():
    session = fake_session()
    session.check_only = True

    def loader(name):
        return aster_module(session) if name == "aster" else None

    namespace: dict = {}
    text = "import aster\nv = aster.getvectjev('0000001b           .VALE        ')\n"
    Evaluator(namespace, module_loader=loader).run(parse_deck(text, "d.comm"))
    assert namespace["v"] is Unknown
    with pytest.raises(UnsupportedError, match="padded to 19 characters"):
        Evaluator({}, module_loader=loader).run(
            parse_deck("import aster\nv = aster.getvectjev('X.VALE')\n", "d.comm")
        )
