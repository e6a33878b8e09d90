"""Legacy syntax: translations of each legacy keyword family, legacy validation, porting text."""

from __future__ import annotations

import pytest
from asterlite.commands.dyna_vibra_relations import read_flambage

from asterlite.catalog import load_catalogue, validate
from asterlite.errors import ValidationError
from asterlite.lang.values import FactorDict, Unknown
from asterlite.legacy import forms
from asterlite.legacy.base import Env
from asterlite.legacy.port import port_text
from tests.validated import relation


def translate(form, kwargs, command):
    return form(kwargs, Env(command))


def comportement(translation):
    return list(translation.kwargs["COMPORTEMENT"])


def test_dyna_tran_modal_v10_renames_and_default_scheme():
    t = translate(
        forms.DYNA_TRAN_MODAL,
        {
            "MASS_GENE": "M",
            "RIGI_GENE": "K",
            "AMOR_GENE": "C",
            "INCREMENT": FactorDict(PAS=0.1, INST_FIN=1.0),
        },
        "DYNA_TRAN_MODAL",
    )
    kw = t.kwargs
    assert t.command == "DYNA_VIBRA"
    assert (kw["TYPE_CALCUL"], kw["BASE_CALCUL"]) == ("TRAN", "GENE")
    assert (kw["MATR_MASS"], kw["MATR_RIGI"], kw["MATR_AMOR"]) == ("M", "K", "C")
    assert kw["SCHEMA_TEMPS"]["SCHEMA"] == "DIFF_CENTRE"  # code_aster 10 default EULER
    assert all(n.text().startswith("deprecated: ") for n in t.notes)


def test_v11_schema_temps_default_and_rk_tolerance():
    t = translate(forms.DYNA_TRAN_MODAL, {"MATR_MASS": 1, "MATR_RIGI": 2}, "DYNA_TRAN_MODAL")
    assert t.kwargs["SCHEMA_TEMPS"]["SCHEMA"] == "NEWMARK"
    t = translate(
        forms.DYNA_TRAN_MODAL,
        {"MATR_MASS": 1, "SCHEMA_TEMPS": FactorDict(SCHEMA="RUNGE_KUTTA_54")},
        "DYNA_TRAN_MODAL",
    )
    assert t.kwargs["SCHEMA_TEMPS"]["TOLERANCE"] == 1.0e-3


def test_methode_adapt_and_increment_moves():
    increment = FactorDict(PAS=1e-4, INST_FIN=1.0, PAS_MAXI=1e-3, VITE_MIN="MAXI")
    t = translate(
        forms.DYNA_TRAN_MODAL, {"MASS_GENE": 1, "METHODE": "ADAPT", "INCREMENT": increment}, "X"
    )
    scheme = t.kwargs["SCHEMA_TEMPS"]
    assert scheme["SCHEMA"] == "ADAPT_ORDRE2"
    assert (scheme["PAS_MAXI"], scheme["VITE_MIN"]) == (1e-3, "MAXI")
    assert "PAS_MAXI" not in t.kwargs["INCREMENT"]
    # a fixed-step scheme ignored them: they are dropped, with a note
    increment = FactorDict(PAS=1e-4, INST_FIN=1.0, PAS_MAXI=1e-3)
    t = translate(
        forms.DYNA_TRAN_MODAL, {"MASS_GENE": 1, "METHODE": "NEWMARK", "INCREMENT": increment}, "X"
    )
    assert "PAS_MAXI" not in t.kwargs["SCHEMA_TEMPS"]
    assert any("removed" in n.new for n in t.notes)


@pytest.mark.parametrize(
    ("family", "occurrence", "relation", "renamed"),
    [
        ("CHOC", {"GROUP_NO_1": "N1", "OBSTACLE": "O", "NORM_OBST": (0, 1, 0)}, "DIS_CHOC", {}),
        ("ANTI_SISM", {"GROUP_NO_1": "A", "GROUP_NO_2": "B", "RIGI_K1": 1.0}, "ANTI_SISM", {}),
        ("FLAMBAGE", {"GROUP_NO_1": "A", "FX": "F", "RIGI_NOR": "R", "AMOR_NOR": "C"},
         "FLAMBAGE", {}),
        ("DIS_VISC", {"GROUP_NO_1": "A", "GROUP_NO_2": "B", "RESI_INTE_RELA": 1e-6}, "DIS_VISC",
         {"RESI_INTE": 1e-6}),
        ("RELA_EFFO_DEPL", {"NOEUD": "N1", "NOM_CMP": "DX", "RELATION": "F"}, "RELA_EFFO_DEPL",
         {"FONCTION": "F"}),
        ("RELA_EFFO_VITE", {"NOEUD": "N1", "NOM_CMP": "DX", "RELATION": "F"}, "RELA_EFFO_VITE",
         {"FONCTION": "F"}),
        ("ROTOR_FISS", {"GROUP_NO_G": "G", "GROUP_NO_D": "D", "K_PHI": "K", "DK_DPHI": "D"},
         "ROTOR_FISS", {}),
    ],
)  # fmt: skip
def test_nonlinearity_families_become_comportement(family, occurrence, relation, renamed):
    kwargs = {"TYPE_CALCUL": "TRAN", "BASE_CALCUL": "GENE", family: FactorDict(occurrence)}
    t = translate(forms.DYNA_VIBRA, kwargs, "DYNA_VIBRA")
    (behaviour,) = comportement(t)
    assert behaviour["RELATION"] == relation
    for key, value in renamed.items():
        assert behaviour[key] == value
    assert family not in t.kwargs
    assert t.kwargs["SCHEMA_TEMPS"]["SCHEMA"] == "NEWMARK"  # code_aster 13's default


def test_modern_dyna_vibra_is_not_legacy():
    kwargs = {"TYPE_CALCUL": "TRAN", "BASE_CALCUL": "GENE", "COMPORTEMENT": FactorDict()}
    assert translate(forms.DYNA_VIBRA, kwargs, "DYNA_VIBRA") is None


def test_mode_iter_simult_to_calc_modes():
    kwargs = {
        "MATR_A": "K",
        "MATR_B": "M",
        "METHODE": "TRI_DIAG",
        "OPTION": "MODE_RIGIDE",
        "CALC_FREQ": FactorDict(OPTION="BANDE", FREQ=(1.0, 5.0), DIM_SOUS_ESPACE=20),
        "STOP_FREQ_VIDE": "NON",
    }
    t = translate(forms.MODE_ITER_SIMULT, kwargs, "MODE_ITER_SIMULT")
    kw = t.kwargs
    assert t.command == "CALC_MODES"
    assert (kw["MATR_RIGI"], kw["MATR_MASS"], kw["OPTION"]) == ("K", "M", "BANDE")
    assert dict(kw["CALC_FREQ"]) == {"FREQ": (1.0, 5.0)}
    assert kw["SOLVEUR_MODAL"] == {
        "METHODE": "TRI_DIAG",
        "MODE_RIGIDE": "OUI",
        "DIM_SOUS_ESPACE": 20,
    }
    assert kw["STOP_BANDE_VIDE"] == "NON"


def test_mode_iter_inv_default_option_and_calc_mode():
    kwargs = {
        "MATR_RIGI": "K",
        "MATR_MASS": "M",
        "CALC_FREQ": FactorDict(FREQ=(10.0,), PREC_AJUSTE=1e-5),
        "CALC_MODE": FactorDict(OPTION="RAYLEIGH", NMAX_ITER=40),
    }
    kw = translate(forms.MODE_ITER_INV, kwargs, "MODE_ITER_INV").kwargs
    assert kw["OPTION"] == "AJUSTE"  # legacy default, not CALC_MODES' PLUS_PETITE
    assert kw["SOLVEUR_MODAL"] == {
        "PREC_AJUSTE": 1e-5,
        "OPTION_INV": "RAYLEIGH",
        "NMAX_ITER_INV": 40,
    }


def test_debut_code_factor():
    t = translate(forms.START, {"CODE": FactorDict(NOM="SDND100A")}, "DEBUT")
    assert t.kwargs["CODE"] == "OUI"
    assert translate(forms.START, {"CODE": "OUI"}, "DEBUT") is None


def test_lire_maillage_without_format(tmp_path):
    mesh = tmp_path / "mesh.mail"
    mesh.write_text("COOR_3D\nN1 0. 0. 0.\nFINSF\nFIN\n")
    env = Env("LIRE_MAILLAGE", unit_path=lambda unit: mesh if unit == 20 else None)
    assert forms.LIRE_MAILLAGE({}, env).kwargs == {"FORMAT": "ASTER"}
    assert forms.LIRE_MAILLAGE({"FORMAT": "MED"}, env) is None


def test_legacy_catalogue_reports_misspellings():
    catalogue = load_catalogue("DYNA_TRAN_MODAL")
    with pytest.raises(ValidationError, match="did you mean RIGI_NOR"):
        validate(
            catalogue,
            {"MASS_GENE": Unknown, "RIGI_GENE": Unknown,
             "INCREMENT": FactorDict(PAS=1.0, INST_FIN=2.0),
             "CHOC": FactorDict(GROUP_NO_1="N1", OBSTACLE=Unknown, NORM_OBST=(0.0, 1.0, 0.0),
                                RIGI_NORM=1.0)},
        )  # fmt: skip


PORT_DECK = """\
# a comment kept
DEBUT(CODE=_F(NOM='X'))
MODES = MODE_ITER_SIMULT(MATR_A=K, MATR_B=M,  # stiffness and mass
                         CALC_FREQ=_F(OPTION='PLUS_PETITE', NMAX_FREQ=NB))
RES = DYNA_TRAN_MODAL(
    METHODE='NEWMARK',
    MASS_GENE=MG,
    RIGI_GENE=KG,
    # the shock
    CHOC=_F(GROUP_NO_1='N1', OBSTACLE=OBS, NORM_OBST=(0., 1., 0.), RIGI_NOR=KN * 2),
    INCREMENT=_F(INST_FIN=T, PAS=DT),
)
X = 1  # untouched
"""


def test_port_rewrites_only_legacy_calls():
    result = port_text(PORT_DECK, "deck.comm")
    text = result.text
    assert text.startswith('# a comment kept\nDEBUT(CODE="OUI")\n')
    assert text.endswith("X = 1  # untouched\n")
    assert "MATR_RIGI=K" in text and "NMAX_FREQ=NB" in text and "# stiffness and mass" in text
    assert "RIGI_NOR=KN * 2" in text and "# the shock" in text
    assert 'RELATION="DIS_CHOC"' in text and "DYNA_TRAN_MODAL" not in text
    assert {n.line for n in result.notes} >= {2, 3, 5, 6, 7, 10}
    compile(text, "ported", "exec")  # still Python


def test_port_leaves_non_inline_factors():
    deck = "CH = _F(GROUP_NO_1='N1')\nR = DYNA_TRAN_MODAL(MASS_GENE=M, CHOC=CH)\n"
    result = port_text(deck, "deck.comm")
    assert result.text == deck
    assert result.skipped and "left as written" in result.skipped[0]


def test_port_reads_names_bound_once_to_a_literal():
    """sdnd103a: METHODE=METHOD1 with METHOD1 = 'EULER' ported as the run translates it;
    a name bound twice (or in a function only) stays a variable."""
    deck = (
        "METHOD1 = 'EULER'\nMETHOD2 = 'DEVOGE'\nNODE = 'N01'\nTWICE = 'EULER'\nTWICE = 'ADAPT'\n"
        "def f(X):\n    LOCAL = 'EULER'\n    return X\n"
        "A = DYNA_TRAN_MODAL(METHODE=METHOD1, MASS_GENE=M, RIGI_GENE=K,\n"
        "    RELA_EFFO_DEPL=_F(NOEUD=NODE, NOM_CMP='DX', RELATION=F))\n"
        "B = DYNA_TRAN_MODAL(METHODE=METHOD2, MASS_GENE=M, RIGI_GENE=K)\n"
        "C = DYNA_TRAN_MODAL(METHODE=TWICE, MASS_GENE=M, RIGI_GENE=K)\n"
        "D = DYNA_TRAN_MODAL(METHODE=LOCAL, MASS_GENE=M, RIGI_GENE=K)\n"
    )
    text = port_text(deck, "deck.comm", node_group={"N01": "G01"}.get).text
    calls = text.split("DYNA_VIBRA(")[1:]
    assert 'SCHEMA_TEMPS=_F(SCHEMA="DIFF_CENTRE")' in calls[0] and 'GROUP_NO="G01"' in calls[0]
    assert 'SCHEMA="DEVOGE"' in calls[1]
    assert "SCHEMA=TWICE" in calls[2] and "SCHEMA=LOCAL" in calls[3]
    compile(text, "ported", "exec")


def test_flambage_scalar_form_becomes_functions():
    kwargs = {
        "MASS_GENE": 1,
        "FLAMBAGE": FactorDict(
            GROUP_NO_1="A", OBSTACLE="O", NORM_OBST=(0, 1, 0),
            RIGI_NOR=1.0e4, FNOR_CRIT=100.0, FNOR_POST_FL=50.0, RIGI_NOR_POST_FL=1.0e4,
        ),
    }  # fmt: skip
    (behaviour,) = comportement(translate(forms.DYNA_TRAN_MODAL, kwargs, "DYNA_TRAN_MODAL"))
    fx = behaviour["FX"]
    assert fx.command == "DEFI_FONCTION"
    values = fx.kwargs["VALE"]
    assert values[:4] == (0.0, 100.0, 0.01, 100.0) and values[5] == 50.0
    assert behaviour["RIGI_NOR"].kwargs["VALE"][5] == 1.0e4
    assert "FNOR_CRIT" not in behaviour


def test_port_hoists_buckling_functions():
    deck = (
        "R = DYNA_TRAN_MODAL(MASS_GENE=M, RIGI_GENE=K, INCREMENT=_F(PAS=DT, INST_FIN=T),\n"
        "    FLAMBAGE=_F(GROUP_NO_1='A', OBSTACLE=O, NORM_OBST=(0., 1., 0.), RIGI_NOR=KN,\n"
        "                FNOR_CRIT=FC, FNOR_POST_FL=FP, RIGI_NOR_POST_FL=KP))\n"
    )
    text = port_text(deck, "deck.comm").text
    assert text.startswith("FL_FX_1 = DEFI_FONCTION(")
    assert "(FC) / (KN)" in text and "FX=FL_FX_1" in text and "AMOR_NOR=FL_AMOR_1" in text
    compile(text, "ported", "exec")


def test_flambage_curves_reproduce_the_legacy_scalar_law():
    """sdnd105a's analytical case (code_aster 10 form): unit mass at 2 m/s on a
    support RIGI_NOR=1 buckling at FNOR_CRIT=1 to FNOR_POST_FL=0.5 with
    RIGI_NOR_POST_FL=0.5: buckling at t = pi/6, residual crushing 3."""
    import math

    import numpy as np

    from asterlite.dynamics.laws import flambage
    from asterlite.dynamics.laws.tabulated import Curve

    occurrence = FactorDict(
        GROUP_NO_1="A", RIGI_NOR=1.0, FNOR_CRIT=1.0, FNOR_POST_FL=0.5, RIGI_NOR_POST_FL=0.5
    )
    (behaviour,) = comportement(
        translate(forms.DYNA_TRAN_MODAL, {"MASS_GENE": 1, "FLAMBAGE": occurrence}, "X")
    )

    def curve(call):
        values = np.asarray(call.kwargs["VALE"], float)
        return Curve(values[0::2], values[1::2], "CONSTANT", "CONSTANT")

    params = flambage.prepare_flambage(
        read_flambage(
            relation(
                "FLAMBAGE", {key: curve(behaviour[key]) for key in ("FX", "RIGI_NOR", "AMOR_NOR")}
            )
        )
    )
    state = flambage.initial_state(params)
    x, v, dt, t, buckled_at = 0.0, 2.0, 2.0e-4, 0.0, None
    force = flambage.buckling_force(params, -x, v, state, state)
    while t < 4.5:
        v += 0.5 * dt * (-force)
        x += dt * v
        force = flambage.buckling_force(params, -x, v, state, state)
        v += 0.5 * dt * (-force)
        t += dt
        if buckled_at is None and state[flambage.V_DEFPLA] > 0.0:
            buckled_at = t
    assert abs(buckled_at - math.pi / 6) < 1e-3
    assert abs(state[flambage.V_DEFPLA] - 3.0) < 1e-2


def test_check_reports_legacy_misspelling_with_the_legacy_path(tmp_path):
    from pathlib import Path

    from asterlite.runtime.runner import run_deck

    decks = Path(__file__).parent / "legacy_decks"
    mesh = Path(__file__).resolve().parents[2] / "shared/aster-corpus/sdnd100a/sdnd100a.mail"
    if not mesh.exists():
        pytest.skip("aster-corpus is absent")
    text = (decks / "sdnd100a_v10.comm").read_text().replace("RIGI_NOR=20.0", "RIGI_NORM=20.0")
    (tmp_path / "old.comm").write_text(text)
    (tmp_path / "old.export").write_text(f"F comm old.comm D 1\nF mail {mesh} D 20\n")
    report = run_deck(tmp_path / "old.export", check_only=True)
    assert report.status == "ERROR"
    assert "DYNA_TRAN_MODAL/CHOC[1]/RIGI_NORM" in report.message
    assert "did you mean RIGI_NOR?" in report.message


def test_cli_port_writes_the_deck_and_lists_changes(tmp_path, capsys):
    from asterlite.cli import main

    old = tmp_path / "old.comm"
    old.write_text(
        "DEBUT(CODE=_F(NOM='X'))\nM = MODE_ITER_INV(MATR_A=K, MATR_B=M0, CALC_FREQ=_F(FREQ=1.0))\n"
    )
    new = tmp_path / "new.comm"
    assert main(["port", str(old), "-o", str(new)]) == 0
    out = capsys.readouterr().out
    assert "line 1: DEBUT(CODE=_F(NOM=...)) -> DEBUT(CODE='OUI')" in out
    assert "line 2: MODE_ITER_INV -> CALC_MODES" in out
    assert 'OPTION="AJUSTE"' in new.read_text()


def _nodes(mapping):
    return Env("DYNA_TRAN_MODAL", node_group=mapping.get)


def test_shock_nodes_become_their_groups():
    env = _nodes({"N6": "N6", "N7": "G7"})
    shock = FactorDict(NOEUD_1="N6", NOEUD_2="N7", OBSTACLE="O", NORM_OBST=(0.0, 1.0, 0.0))
    t = forms.DYNA_TRAN_MODAL({"MASS_GENE": 1, "CHOC": shock}, env)
    (behaviour,) = comportement(t)
    assert (behaviour["GROUP_NO_1"], behaviour["GROUP_NO_2"]) == ("N6", "G7")
    assert "NOEUD_1" not in behaviour and list(behaviour)[:3] == [
        "RELATION",
        "GROUP_NO_1",
        "GROUP_NO_2",
    ]
    assert any("NOEUD_1='N6' (mesh node)" in n.old for n in t.notes)
    # no group of its own: the node name stays (code_aster 17 still takes it, hidden)
    t = forms.DYNA_TRAN_MODAL({"MASS_GENE": 1, "CHOC": shock}, _nodes({"N6": "N6"}))
    (behaviour,) = comportement(t)
    assert (behaviour["NOEUD_1"], behaviour["NOEUD_2"]) == ("N6", "N7")


def test_rela_effo_node_becomes_group():
    occurrence = FactorDict(NOEUD="N1", NOM_CMP="DX", RELATION="F")
    kwargs = {"TYPE_CALCUL": "TRAN", "BASE_CALCUL": "GENE", "RELA_EFFO_DEPL": occurrence}
    (behaviour,) = comportement(
        forms.DYNA_VIBRA(kwargs, Env("DYNA_VIBRA", node_group={"N1": "GN1"}.get))
    )
    assert behaviour["GROUP_NO"] == "GN1" and behaviour["FONCTION"] == "F"


def test_excit_support_nodes_need_a_group():
    from asterlite.errors import UnsupportedError

    excit = FactorDict(VECT_ASSE_GENE="V", ACCE="A", VITE="B", DEPL="C", MULT_APPUI="OUI",
                       NOEUD=("NO1", "NO11"))  # fmt: skip
    t = forms.DYNA_TRAN_MODAL({"MASS_GENE": 1, "EXCIT": excit}, _nodes({"NO1": "NO1", "NO11": "G"}))
    assert t.kwargs["EXCIT"]["GROUP_NO"] == ("NO1", "G") and "NOEUD" not in t.kwargs["EXCIT"]
    with pytest.raises(UnsupportedError, match="EXCIT/NOEUD='NO11'.*no group holding just"):
        forms.DYNA_TRAN_MODAL({"MASS_GENE": 1, "EXCIT": excit}, _nodes({"NO1": "NO1"}))
    # a code_aster 13 DYNA_VIBRA whose only legacy form is a support named by a node
    kwargs = {"TYPE_CALCUL": "TRAN", "BASE_CALCUL": "GENE", "EXCIT": (excit,)}
    t = forms.DYNA_VIBRA(kwargs, Env("DYNA_VIBRA", node_group={"NO1": "A", "NO11": "B"}.get))
    assert t.kwargs["EXCIT"][0]["GROUP_NO"] == ("A", "B")


def test_euler_is_written_as_diff_centre():
    kwargs = {"TYPE_CALCUL": "TRAN", "BASE_CALCUL": "GENE",
              "SCHEMA_TEMPS": FactorDict(SCHEMA="EULER")}  # fmt: skip
    t = translate(forms.DYNA_VIBRA, kwargs, "DYNA_VIBRA")
    assert t.kwargs["SCHEMA_TEMPS"]["SCHEMA"] == "DIFF_CENTRE"
    assert any("same explicit update" in n.new for n in t.notes)
    t = translate(forms.DYNA_TRAN_MODAL, {"MASS_GENE": 1, "METHODE": "EULER"}, "DYNA_TRAN_MODAL")
    assert t.kwargs["SCHEMA_TEMPS"]["SCHEMA"] == "DIFF_CENTRE"


def test_group_resolver_reads_the_run_meshes(tmp_path):
    from asterlite.legacy.nodes import group_resolver

    one = tmp_path / "a.mail"
    one.write_text(
        "COOR_3D\nN1 0. 0. 0.\nN2 1. 0. 0.\nFINSF\nSEG2\nE1 N1 N2\nFINSF\n"
        "GROUP_NO\nN1\nN1\nFINSF\nGROUP_NO\nBOTH\nN1 N2\nFINSF\nGROUP_NO\nEND\nN2\nFINSF\nFIN\n"
    )
    other = tmp_path / "b.mail"
    other.write_text(
        "COOR_3D\nN2 0. 0. 0.\nFINSF\nPOI1\nP1 N2\nFINSF\nGROUP_NO\nTIP\nN2\nFINSF\nFIN\n"
    )
    resolve = group_resolver([one, other, tmp_path / "missing.mail"])
    assert resolve("N1") == "N1"  # the group named like the node
    assert resolve("N2") is None  # END in one mesh, TIP in the other: no common group
    assert group_resolver([one])("N2") == "END"
    assert resolve("N9") is None
