"""Pieces sdld04a needs: POST_GENE_PHYS on a transient computed with a static
correction, RECU_FONCTION from a field (CHAM_GD) and CREA_CHAMP EXTR with
TYPE_MAXI='NORM_TRAN'."""

from __future__ import annotations

from types import SimpleNamespace

import numpy as np
import pytest
from asterlite.commands import crea_champ, post_gene_phys, recu_fonction

from asterlite.concepts.assembly import DofNumbering, NodalField
from asterlite.concepts.function import Function
from asterlite.errors import CommandError, UnsupportedError
from asterlite.modal.fields import norm_tran_extreme

from .test_post_support import context, kw, small_transient


def corrected_transient():
    """The small transient with a static correction ψ f(t), f(t) = 3t."""
    result = small_transient()
    psi = np.array([0.1, 0.2, 0.3, 0.4])  # on (NO1 DX, NO1 DY, NO2 DX, NO2 DY)
    ramp = Function([0.0, 1.0], [0.0, 3.0], NOM_PARA="INST")
    result.info["corr_stat"] = [{"shape": psi, "DEPL": ramp}]
    return result


def test_post_gene_phys_adds_the_static_correction():
    result = corrected_transient()
    occ = {"NOM_CHAM": "DEPL", "NOM_CMP": ("DX",), "GROUP_NO": "NO2", "INST": (0.5,)}
    table = post_gene_phys.run(context("POST_GENE_PHYS"), kw(RESU_GENE=result, OBSERVATION=[occ]))
    (row,) = table.rows
    # NO2 DX: 2 q1 + 0.5 q2 + 0.3 * 3t at t = 0.5
    assert row["VALE_R"] == pytest.approx(2 * 0.5 + 0.5 * 0.25 + 0.3 * 1.5)
    # the same value RECU_FONCTION gives with CORR_STAT='OUI'
    function = recu_fonction.run(
        context("RECU_FONCTION"),
        kw(RESU_GENE=result, NOM_CHAM="DEPL", GROUP_NO="NO2", NOM_CMP="DX", CORR_STAT="OUI"),
    )
    assert function(0.5) == pytest.approx(row["VALE_R"])


def test_post_gene_phys_correction_without_motion_for_the_field_adds_nothing():
    result = corrected_transient()
    occ = {"NOM_CHAM": "VITE", "NOM_CMP": ("DX",), "GROUP_NO": "NO2", "INST": (0.5,)}
    table = post_gene_phys.run(context(), kw(RESU_GENE=result, OBSERVATION=[occ]))
    assert table.rows[0]["VALE_R"] == pytest.approx(2 * 1.0 + 0.5 * 1.0)


def test_post_gene_phys_element_field_with_correction_is_unsupported():
    result = corrected_transient()
    occ = {"NOM_CHAM": "SIPO_ELNO", "GROUP_MA": "BAR"}
    with pytest.raises(UnsupportedError, match="static correction"):
        post_gene_phys.run(context(), kw(RESU_GENE=result, OBSERVATION=[occ]))


def nodal_field():
    mesh = small_transient().basis.numbering.mesh
    numbering = DofNumbering(mesh, [(0, "DX"), (0, "DY"), (1, "DX"), (1, "DY")])
    return NodalField(numbering, np.array([1.0, 2.0, 3.0, 4.0]))


def test_recu_fonction_cham_gd_is_a_constant_function():
    function = recu_fonction.run(
        context("RECU_FONCTION"), kw(CHAM_GD=nodal_field(), GROUP_NO="NO2", NOM_CMP="DY")
    )
    assert np.allclose(function.evaluate([-5.0, 0.1, 1e3]), 4.0)
    assert function.Parametres()["NOM_PARA"] == "TOUTPARA"
    assert function.Parametres()["NOM_RESU"] == "DY"


def test_recu_fonction_cham_gd_group_of_several_nodes_takes_the_first():
    ctx = context("RECU_FONCTION")
    function = recu_fonction.run(ctx, kw(CHAM_GD=nodal_field(), GROUP_NO="ALL", NOM_CMP="DX"))
    assert function(0.0) == pytest.approx(1.0)
    assert any("first" in m for m in ctx.session.messages)


def test_recu_fonction_cham_gd_missing_component():
    with pytest.raises(CommandError, match="no component DZ"):
        recu_fonction.run(context(), kw(CHAM_GD=nodal_field(), GROUP_NO="NO1", NOM_CMP="DZ"))


def stacked_result():
    """Node 0: DX, DY, DRZ; node 1: DX, DY, LAGR-like extra component TEMP."""
    mesh = small_transient().basis.numbering.mesh
    numbering = DofNumbering(
        mesh, [(0, "DX"), (0, "DY"), (0, "DRZ"), (1, "DX"), (1, "DY"), (1, "TEMP")]
    )
    acce = np.array(
        [
            [1.0, 0.0, 10.0, 0.0, 0.0, 7.0],
            [0.0, 3.0, 20.0, 1.0, 1.0, 8.0],  # node 0 norm 3 (largest)
            [-2.0, 0.0, 30.0, 0.0, -5.0, 9.0],  # node 1 norm 5 (largest)
        ]
    )
    return SimpleNamespace(
        numbering=numbering,
        fields={"ACCE": acce},
        order=np.array([0, 2, 4]),
        times=np.array([0.0, 0.1, 0.2]),
    )


def test_norm_tran_extreme_values_and_parameters():
    result = stacked_result()
    values = result.fields["ACCE"]
    vale = norm_tran_extreme(result.numbering, values, "VALE", result.times)
    assert vale.tolist() == [0.0, 3.0, 20.0, 0.0, -5.0, 7.0]  # TEMP keeps the first field
    inst = norm_tran_extreme(result.numbering, values, "INST", result.times)
    assert inst.tolist() == [0.1, 0.1, 0.1, 0.2, 0.2, 7.0]


def test_crea_champ_norm_tran_nume_ordre():
    field = crea_champ.run(
        context("CREA_CHAMP"),
        kw(
            OPERATION="EXTR",
            TYPE_CHAM="NOEU_DEPL_R",
            RESULTAT=stacked_result(),
            NOM_CHAM="ACCE",
            TYPE_MAXI="NORM_TRAN",
            TYPE_RESU="NUME_ORDRE",
        ),
    )
    assert field.values.tolist() == [2.0, 2.0, 2.0, 4.0, 4.0, 7.0]


def test_crea_champ_maxi_nume_ordre_gives_orders_not_instants():
    field = crea_champ.run(
        context("CREA_CHAMP"),
        kw(
            OPERATION="EXTR",
            TYPE_CHAM="NOEU_DEPL_R",
            RESULTAT=stacked_result(),
            NOM_CHAM="ACCE",
            TYPE_MAXI="MAXI",
            TYPE_RESU="NUME_ORDRE",
        ),
    )
    assert field.values.tolist() == [0.0, 2.0, 4.0, 2.0, 2.0, 4.0]
