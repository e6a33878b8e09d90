"""Python methods decks call on results, placeholders under check, and the
restitution of absolute motion (MULT_APPUI) and element fields."""

from __future__ import annotations

import numpy as np
import pytest
from asterlite.commands import defi_list_reel, recu_fonction, rest_gene_phys

from asterlite.concepts.assembly import ElementField
from asterlite.concepts.base import Placeholder
from asterlite.concepts.function import Function
from asterlite.errors import CommandError
from asterlite.lang import Evaluator, parse_deck
from asterlite.lang.values import Unknown
from asterlite.post import deck_api
from asterlite.post.checks import expectation_from, make_record
from asterlite.post.restitution import recombine_element_field, support_motion
from asterlite.runtime.runner import run_deck

from .test_post_support import context, kw, small_transient


def run_snippet(text: str, **names) -> dict:
    namespace = dict(names)
    Evaluator(namespace).run(parse_deck(text, "snippet.comm"))
    return namespace


def test_tran_gene_values_by_index_and_in_full():
    result = small_transient()
    ns = run_snippet(
        "n = R.getNumberOfModes()\nidx = R.getIndexes()\nall_q = R.getDisplacementValues()\n"
        "q3 = R.getDisplacementValues(3)\nv3 = R.getVelocityValues(3)\n"
        "a0 = R.getAccelerationValues(0)\nt = R.getTimes()\n",
        R=result,
    )
    assert ns["n"] == 2 and ns["idx"] == list(range(11))
    assert len(ns["all_q"]) == 22 and ns["all_q"][6:8] == pytest.approx([0.3, 0.09])
    assert ns["q3"] == pytest.approx([0.3, 0.09]) and ns["v3"] == pytest.approx([1.0, 0.6])
    assert ns["a0"] == [0.0, 2.0] and ns["t"][-1] == 1.0


def test_tran_gene_setters_overwrite_one_state():
    result = small_transient()
    snippet = "R.setDisplacementValues(0, [5.0, 6.0])\nR.setAccelerationValues(10, [1, 2])"
    run_snippet(snippet, R=result)
    assert result.depl[0].tolist() == [5.0, 6.0] and result.acce[10].tolist() == [1.0, 2.0]
    with pytest.raises(CommandError, match="3 values given for 2 modes"):
        result.setVelocityValues(1, [1.0, 2.0, 3.0])
    with pytest.raises(CommandError, match="outside the archive"):
        result.getDisplacementValues(11)


def test_info_nonl_prints_code_aster_summary():
    lines = []
    deck_api.set_sink(lines.append)
    try:
        rows = small_transient().INFO_NONL()
    finally:
        deck_api.set_sink(None)
    assert rows == [["DIS_CHOC", "CHOC1", "NO2", "", "", ""]]
    assert "Information regarding the considered non linearities" in lines[1]
    row = lines[5]
    assert row.split("|")[1].strip() == "1" and "DIS_CHOC" in row and "NO2" in row
    assert row.split("|")[4].strip() == "-"  # no second node
    linear = small_transient()
    linear.shocks = []
    assert deck_api.info_nonl_lines(linear.shocks)[0].startswith("Linear calculation")


def test_get_field_of_physical_result_and_modes_with_physical_dofs():
    result = small_transient()
    phys = rest_gene_phys.run(context(), kw(RESU_GENE=result, TOUT_CHAM="OUI"))
    numbering = result.basis.numbering
    ns = run_snippet(
        "dofs = NU.getPhysicalDOFs()\nu = P.getField('DEPL', 4).getValues()\n"
        "phi = M.getField('DEPL', 2).getValues()\nv = P.getField('VITE', 1.0, 'INST').getValues()",
        NU=numbering,
        P=phys,
        M=result.basis,
    )
    assert ns["dofs"] == [0, 1, 2, 3]
    assert ns["u"] == pytest.approx(result.basis.shapes @ result.depl[4])
    assert ns["phi"] == result.basis.shapes[:, 1].tolist()
    assert ns["v"] == pytest.approx(result.basis.shapes @ result.vite[10])
    with pytest.raises(CommandError, match="NUME_ORDRE 99"):
        phys.getField("DEPL", 99)


def test_placeholder_indexing_is_unknown():
    assert Placeholder("table_sdaster")["VALE_R", 1] is Unknown
    ns = run_snippet("x = T['VALE_R', 1] * 2.0\n", T=Placeholder("table_sdaster"))
    assert ns["x"] is Unknown


def test_check_mode_accepts_table_indexing(tmp_path):
    path = tmp_path / "d.comm"
    path.write_text(
        "DEBUT()\nT = CREA_TABLE(LISTE=_F(PARA='VALE_R', LISTE_R=(1.0, 2.0)))\n"
        "x = T['VALE_R', 2]\nF = DEFI_FONCTION(NOM_PARA='INST', VALE=(0.0, x, 1.0, x))\nFIN()\n"
    )
    assert run_deck(path, tmp_path / "out", check_only=True).status == "CHECKED"
    report = run_deck(path, tmp_path / "run")
    assert report.status == "DONE", report.message  # no TEST_* check


def test_defi_list_reel_keeps_repeated_values():
    listed = defi_list_reel.run(context(), kw(VALE=(0.01, 0.01, 0.02)))
    assert listed.values.tolist() == [0.01, 0.01, 0.02]


def with_support(result):
    """One support moving as s(t) = 3t along ψ = (0, 1, 0, 0.5)."""
    ramp = Function(np.array([0.0, 1.0]), np.array([0.0, 3.0]), NOM_PARA="INST")
    speed = Function(np.array([0.0, 1.0]), np.array([3.0, 3.0]), NOM_PARA="INST")
    shape = np.array([0.0, 1.0, 0.0, 0.5])
    result.info["mult_appui"] = [{"shape": shape, "DEPL": ramp, "VITE": speed, "ACCE": None}]
    return result


def test_support_motion_sums_static_modes_times_motion():
    result = with_support(small_transient())
    extra = support_motion(result.info["mult_appui"], [1, 3], [0.0, 0.5], "DEPL")
    assert extra.tolist() == [[0.0, 0.0], [1.5, 0.75]]
    assert not support_motion(result.info["mult_appui"], [1], [0.5], "ACCE").any()


def test_recu_fonction_mult_appui_gives_absolute_motion():
    result = with_support(small_transient())
    common = dict(RESU_GENE=result, NOM_CHAM="DEPL", GROUP_NO="NO2", NOM_CMP="DY")
    relative = recu_fonction.run(context(), kw(**common))
    absolute = recu_fonction.run(context(), kw(**common, MULT_APPUI="OUI"))
    assert np.allclose(absolute.ordinates - relative.ordinates, 0.5 * 3.0 * result.times)
    phys = rest_gene_phys.run(context(), kw(RESU_GENE=result, NOM_CHAM=("DEPL",), MULT_APPUI="OUI"))
    assert np.allclose(phys.fields["DEPL"][:, 3], absolute.ordinates)
    with pytest.raises(CommandError, match="without multi-support"):
        fixed_supports = {**common, "RESU_GENE": small_transient()}
        recu_fonction.run(context(), kw(**fixed_supports, MULT_APPUI="OUI"))


def modes_with_element_field(result):
    """An ELNO field per mode on the one cell: (2 modes, 1 cell, 2 nodes, 2 cmp)."""
    values = np.array([[[[1.0, 10.0], [2.0, 20.0]]], [[[3.0, 30.0], [4.0, 40.0]]]])
    field = ElementField("SIPO_ELNO", np.array([0]), ("SN", "SVY"), values)
    result.basis.element_fields = {"SIPO_ELNO": field}
    return field


def test_recombine_element_field():
    field = modes_with_element_field(small_transient())
    q = np.array([[1.0, 0.0], [0.5, 2.0]])
    out = recombine_element_field(field, q)
    assert out.values.shape == (2, 1, 2, 2)
    assert out.values[1, 0, 1].tolist() == [0.5 * 2 + 2 * 4, 0.5 * 20 + 2 * 40]


def test_rest_gene_phys_element_field_then_recu_fonction():
    result = small_transient()
    modes_with_element_field(result)
    phys = rest_gene_phys.run(
        context(), kw(RESU_GENE=result, NOM_CHAM=("DEPL", "SIPO_ELNO"), TOUT_ORDRE="OUI")
    )
    stress = phys.element_fields["SIPO_ELNO"]
    assert stress.values.shape == (11, 1, 2, 2)
    f = recu_fonction.run(
        context(),
        kw(RESULTAT=phys, NOM_CHAM="SIPO_ELNO", NOM_CMP="SVY", GROUP_MA="BAR", GROUP_NO="NO2"),
    )
    assert np.allclose(f.ordinates, 20 * result.times + 40 * result.times**2)
    with pytest.raises(CommandError, match="CALC_CHAMP"):
        rest_gene_phys.run(context(), kw(RESU_GENE=result, NOM_CHAM=("EFGE_ELNO",)))


def test_two_criteria_apply_to_calc_then_reference():
    exp = expectation_from(kw(VALE_CALC=4.635, VALE_REFE=4.6, CRITERE=("RELATIF",), PRECISION=1e-2))
    assert make_record("TEST_RESU", "f", 4.635, exp).ok
    exp = expectation_from(
        kw(VALE_CALC=4.635, VALE_REFE=4.6, CRITERE=("RELATIF", "ABSOLU"), PRECISION=1e-2)
    )
    record = make_record("TEST_RESU", "f", 4.635, exp)
    assert not record.ok and record.criterion == "ABSOLU"


def test_absolute_acceleration_from_a_drive_acceleration():
    result = small_transient()
    drive = Function(np.array([0.0, 1.0]), np.array([10.0, 20.0]), NOM_PARA="INST")
    common = dict(RESU_GENE=result, NOM_CHAM="ACCE", GROUP_NO="NO2", NOM_CMP="DX")
    relative = recu_fonction.run(context(), kw(**common))
    absolute = recu_fonction.run(context(), kw(**common, ACCE_MONO_APPUI=drive))
    assert np.allclose(absolute.ordinates - relative.ordinates, 10 + 10 * result.times)
    phys = rest_gene_phys.run(
        context(),
        kw(
            RESU_GENE=result,
            NOM_CHAM=("ACCE", "ACCE_ABSOLU"),
            ACCE_MONO_APPUI=drive,
            DIRECTION=(0.0, 1.0, 0.0),
        ),
    )
    added = phys.fields["ACCE_ABSOLU"] - phys.fields["ACCE"]
    assert np.allclose(added[:, [0, 2]], 0.0)  # DX untouched, DY gets the drive
    assert np.allclose(added[:, 3], 10 + 10 * result.times)


def test_static_correction_uses_the_same_recombination():
    result = with_support(small_transient())
    result.info["corr_stat"] = result.info.pop("mult_appui")
    common = dict(RESU_GENE=result, NOM_CHAM="DEPL", GROUP_NO="NO2", NOM_CMP="DY")
    corrected = recu_fonction.run(context(), kw(**common, CORR_STAT="OUI"))
    relative = recu_fonction.run(context(), kw(**common))
    assert np.allclose(corrected.ordinates - relative.ordinates, 1.5 * result.times)
    with pytest.raises(CommandError, match="multi-support"):
        recu_fonction.run(context(), kw(**common, MULT_APPUI="OUI"))
    with pytest.raises(CommandError, match="static correction"):
        recu_fonction.run(
            context(), kw(**{**common, "RESU_GENE": small_transient()}, CORR_STAT="OUI")
        )


def test_test_resu_reads_element_fields_of_results_and_fields():
    from asterlite.commands import test_resu

    result = small_transient()
    modes_with_element_field(result)
    phys = rest_gene_phys.run(context(), kw(RESU_GENE=result, NOM_CHAM=("SIPO_ELNO",)))
    phys.name = "PHYS"
    ctx = context("TEST_RESU")
    occurrence = dict(RESULTAT=phys, NOM_CHAM="SIPO_ELNO", GROUP_MA="BAR", GROUP_NO="NO1")
    test_resu.run(ctx, kw(RESU=[{**occurrence, "NOM_CMP": "SN", "INST": 1.0, "VALE_CALC": 4.0}]))

    class ElementFieldConcept:  # what CREA_CHAMP EXTR hands TEST_RESU
        name, mesh = "EXTR", result.basis.numbering.mesh
        element_field = ElementField(
            "SIPO_ELNO", np.array([0]), ("SN",), np.array([[[[7.0], [8.0]]]])
        )

    occurrence = dict(CHAM_GD=ElementFieldConcept(), GROUP_MA="BAR", NOM_CMP="SN")
    test_resu.run(ctx, kw(CHAM_ELEM=[{**occurrence, "GROUP_NO": "NO2", "VALE_CALC": 8.0}]))
    assert [t.ok for t in ctx.session.tests] == [True, True]


def test_shock_quantities_interpolated_on_list_para_and_second_node():
    from asterlite.concepts.lists import ListReal

    result = small_transient()
    shock = result.shocks[0]
    shock.node_1, shock.node_2 = "NO1", "NO2"
    shock.fields["DXLOC"] = np.zeros(11)
    shock.fields["DXLOC_2"] = np.arange(11.0)
    fn = recu_fonction.run(
        context(),
        kw(RESU_GENE=result, NOEUD_CHOC="NO2", PARA_Y="FN", LIST_PARA=ListReal([0.05])),
    )
    assert fn.ordinates[0] == pytest.approx(0.5 * np.sin(0.1 * np.pi))
    dx = recu_fonction.run(context(), kw(RESU_GENE=result, NOEUD_CHOC="NO2", PARA_Y="DXLOC"))
    assert dx.ordinates.tolist() == list(range(11))


def test_rest_gene_phys_of_generalized_modes():
    from asterlite.concepts.modes import GeneralizedModes, GeneralizedNumbering

    basis = small_transient().basis
    vectors = np.array([[1.0, 0.0], [1.0, 2.0]])
    modes = GeneralizedModes(
        GeneralizedNumbering(basis), vectors, np.array([3.0, 5.0]), np.ones(2), np.ones(2)
    )
    restored = rest_gene_phys.run(context(), kw(RESU_GENE=modes, NOM_CHAM="DEPL"))
    assert np.allclose(restored.shapes, basis.shapes @ vectors)
    second = rest_gene_phys.run(context(), kw(RESU_GENE=modes, NUME_ORDRE=(2,), GROUP_NO="NO2"))
    assert np.allclose(second.shapes[:, 0], (basis.shapes @ vectors)[2:, 1])
    assert second.frequencies.tolist() == [5.0]
