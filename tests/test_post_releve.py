"""POST_RELEVE_T (extraction from physical results) and POST_GENE_PHYS
(physical values from a tran_gene) tables."""

from __future__ import annotations

import numpy as np
import pytest
from asterlite.commands import post_gene_phys, post_releve_t, recu_fonction, rest_gene_phys

from asterlite.concepts.assembly import ElementField, NodalField
from asterlite.concepts.function import ComplexFunction
from asterlite.concepts.harmonic import HarmGene
from asterlite.concepts.lists import ListReal
from asterlite.errors import CommandError, UnsupportedError

from .test_post_support import context, kw, small_transient


def physical():
    phys = rest_gene_phys.run(context(), kw(RESU_GENE=small_transient(), TOUT_CHAM="OUI"))
    phys.name = "DYNA"
    phys.numbering.mesh.coords[1] = [1.0, 0.0, 0.0]
    return phys


def action(**values):
    base = {"OPERATION": ("EXTRACTION",), "INTITULE": "DEP", "REPERE": "GLOBAL"}
    return kw(ACTION=[{**base, **values}])


def test_extraction_columns_and_values_at_an_instant():
    table = post_releve_t.run(
        context(),
        action(
            RESULTAT=physical(),
            NOM_CHAM="DEPL",
            GROUP_NO=("ALL",),
            NOM_CMP=("DX", "DY"),
            INST=(0.5,),
            CRITERE="RELATIF",
            PRECISION=1e-6,
        ),
    )
    assert table.columns == [
        "INTITULE", "RESU", "NOM_CHAM", "NUME_ORDRE", "INST", "NOEUD",
        "COOR_X", "COOR_Y", "COOR_Z", "DX", "DY",
    ]  # fmt: skip
    assert len(table) == 2
    no2 = table.rows[1]
    assert (no2["NOEUD"], no2["NUME_ORDRE"], no2["INST"]) == ("2", 5, 0.5)
    assert no2["COOR_X"] == 1.0
    assert no2["DX"] == pytest.approx(2 * 0.5 + 0.5 * 0.25)
    assert no2["DY"] == pytest.approx(-0.25)
    assert table.types["NOEUD"] == "K8" and table.types["INTITULE"] == "K16"


def test_extraction_every_order_filters_like_test_table():
    table = post_releve_t.run(
        context(),
        action(RESULTAT=physical(), NOM_CHAM="VITE", NOEUD=("NO1",), TOUT_CMP="OUI"),
    )
    assert len(table) == 11
    row = table.filtered("INST", "EQ", 0.3, 1e-6, "RELATIF").rows[0]
    assert row["DX"] == pytest.approx(1.0) and row["DY"] == pytest.approx(0.6)


def test_extraction_from_modes_and_from_a_nodal_field():
    basis = small_transient().basis
    basis.name = "MODES"
    table = post_releve_t.run(
        context(),
        action(RESULTAT=basis, NOM_CHAM="DEPL", GROUP_NO=("NO2",), NOM_CMP=("DX",)),
    )
    assert [(r["NUME_MODE"], r["FREQ"], r["DX"]) for r in table.rows] == [
        (1, 1.0, 2.0),
        (2, 2.0, 0.5),
    ]
    field = NodalField(basis.numbering, np.array([1.0, 2.0, 3.0, 4.0]))
    field.name = "CHNO"
    table = post_releve_t.run(context(), action(CHAM_GD=field, GROUP_NO=("ALL",), NOM_CMP=("DY",)))
    assert table.columns[:2] == ["INTITULE", "CHAM_GD"]
    assert [r["DY"] for r in table.rows] == [2.0, 4.0]


def test_resultante_and_moment_about_a_point():
    table = post_releve_t.run(
        context(),
        action(
            RESULTAT=physical(),
            NOM_CHAM="DEPL",
            GROUP_NO=("ALL",),
            RESULTANTE=("DX", "DY"),
            MOMENT=("DRZ",),
            POINT=(0.0, 0.0, 0.0),
            NUME_ORDRE=(10,),
        ),
    )
    (row,) = table.rows
    # t = 1: NO1 (0,0,0) u = (1, 1); NO2 (1,0,0) u = (2.5, -1)
    assert row["DX"] == pytest.approx(3.5) and row["DY"] == pytest.approx(0.0)
    assert row["DRZ"] == pytest.approx(-1.0)  # r × F about z: 1 * (-1)
    assert "NOEUD" not in table.columns


def test_post_releve_t_errors_and_unsupported_operations():
    with pytest.raises(UnsupportedError, match="MOYENNE"):
        post_releve_t.run(
            context(),
            action(OPERATION=("MOYENNE",), RESULTAT=physical(), NOM_CHAM="DEPL", GROUP_NO=("ALL",)),
        )
    with pytest.raises(CommandError, match="no field ACCE_ABSOLU"):
        post_releve_t.run(
            context(),
            action(RESULTAT=physical(), NOM_CHAM="ACCE_ABSOLU", GROUP_NO=("ALL",), TOUT_CMP="OUI"),
        )
    with pytest.raises(CommandError, match="no stored instant"):
        post_releve_t.run(
            context(),
            action(
                RESULTAT=physical(),
                NOM_CHAM="DEPL",
                GROUP_NO=("ALL",),
                TOUT_CMP="OUI",
                INST=(0.55,),
                CRITERE="RELATIF",
                PRECISION=1e-6,
            ),
        )


def observation(**values):
    return {"NOM_CHAM": "DEPL", **values}


def test_post_gene_phys_table_layout_and_values():
    result = small_transient()
    table = post_gene_phys.run(
        context(),
        kw(
            RESU_GENE=result,
            OBSERVATION=[
                observation(GROUP_NO=("ALL",), INST=(0.5, 1.0), CRITERE="RELATIF", PRECISION=1e-6),
                observation(NOM_CHAM="ACCE", GROUP_NO=("NO2",), NOM_CMP=("DY",)),
            ],
        ),
    )
    assert table.columns == [
        "NUME_OBSE", "INST", "NOM_CHAM", "NOM_CMP", "NOEUD", "MAILLE", "POINT", "VALE_R",
    ]  # fmt: skip
    first = [r for r in table.rows if r["NUME_OBSE"] == 1]
    assert len(first) == 2 * 2 * 2  # instants x components x nodes
    # components outer, nodes inner, within each instant
    assert [(r["NOM_CMP"], r["NOEUD"]) for r in first[:4]] == [
        ("DX", "1"), ("DX", "2"), ("DY", "1"), ("DY", "2"),
    ]  # fmt: skip
    no2_dx = next(r for r in first if r["NOEUD"] == "2" and r["NOM_CMP"] == "DX")
    assert no2_dx["INST"] == 0.5 and no2_dx["VALE_R"] == pytest.approx(1.0 + 0.125)
    second = [r for r in table.rows if r["NUME_OBSE"] == 2]
    assert len(second) == 11 and all(r["VALE_R"] == pytest.approx(-2.0) for r in second)
    at_end = table.filtered("INST", "EQ", 1.0).filtered("NOEUD", "EQ", "2")
    dy = at_end.filtered("NOM_CMP", "EQ", "DY").filtered("NOM_CHAM", "EQ", "DEPL")
    assert dy.rows[0]["VALE_R"] == pytest.approx(-1.0)  # DY of NO2 = -q2 at t = 1
    assert "MAILLE" in table.columns and all("MAILLE" not in r for r in table.rows)


def test_post_gene_phys_list_inst_and_absolute_acceleration():
    class Constant:
        def evaluate(self, times):
            return np.full(np.shape(times), 3.0)

    result = small_transient()
    table = post_gene_phys.run(
        context(),
        kw(
            RESU_GENE=result,
            OBSERVATION=[
                observation(
                    NOM_CHAM="ACCE_ABSOLU",
                    GROUP_NO=("NO1",),
                    NOM_CMP=("DX", "DY"),
                    LIST_INST=ListReal([0.2, 0.4]),
                    CRITERE="ABSOLU",
                    PRECISION=1e-6,
                    ACCE_MONO_APPUI=(Constant(),),
                    DIRECTION=(0.0, 1.0, 0.0),
                )
            ],
        ),
    )
    assert [r["INST"] for r in table.rows] == pytest.approx([0.2, 0.2, 0.4, 0.4])
    # relative NO1: DX = q1'' = 0, DY = q2'' = 2; plus 3 * (0, 1, 0)
    assert [r["VALE_R"] for r in table.rows] == pytest.approx([0.0, 5.0, 0.0, 5.0])


def with_modal_element_fields(result):
    """EFGE_ELNO and EFGE_ELGA of the two modes on cell EL1: mode j, point p,
    component k holds 100 j + 10 p + k."""
    j, p, k = np.meshgrid(np.arange(1, 3), np.arange(1, 4), np.arange(2), indexing="ij")
    values = (100 * j + 10 * p + k).astype(float)[:, None]  # (modes, 1 cell, 3 points, 2)
    result.basis.element_fields = {
        "EFGE_ELNO": ElementField("EFGE_ELNO", np.array([0]), ("N", "VY"), values[:, :, :2]),
        "EFGE_ELGA": ElementField("EFGE_ELGA", np.array([0]), ("N", "VY"), values),
    }
    return result


def test_post_gene_phys_element_fields_rows_as_code_aster():
    result = with_modal_element_fields(small_transient())
    table = post_gene_phys.run(
        context(),
        kw(
            RESU_GENE=result,
            OBSERVATION=[
                observation(NOM_CHAM="EFGE_ELNO", GROUP_MA=("BAR",), INST=(0.5,)),
                observation(NOM_CHAM="EFGE_ELGA", MAILLE=("EL1",), NOM_CMP=("VY",), INST=(1.0,)),
            ],
        ),
    )
    elno = [r for r in table.rows if r["NUME_OBSE"] == 1]
    # components outer, then cells, then the cell's nodes
    assert [(r["NOM_CMP"], r["MAILLE"], r["NOEUD"]) for r in elno] == [
        ("N", "1", "1"), ("N", "1", "2"), ("VY", "1", "1"), ("VY", "1", "2"),
    ]  # fmt: skip
    assert all("POINT" not in r for r in elno)
    q1, q2 = 0.5, 0.25
    expected = [q1 * (100 + 10 * p + k) + q2 * (200 + 10 * p + k) for k in (0, 1) for p in (1, 2)]
    assert [r["VALE_R"] for r in elno] == pytest.approx(expected)
    elga = [r for r in table.rows if r["NUME_OBSE"] == 2]
    assert [r["POINT"] for r in elga] == ["PT 1", "PT 2", "PT 3"]
    assert all(r["MAILLE"] == "1" and "NOEUD" not in r for r in elga)
    assert elga[2]["VALE_R"] == pytest.approx((131 + 231) * 1.0)


def test_post_gene_phys_errors():
    result = small_transient()
    with pytest.raises(CommandError, match="component DRZ"):
        post_gene_phys.run(
            context(),
            kw(RESU_GENE=result, OBSERVATION=[observation(GROUP_NO=("ALL",), NOM_CMP=("DRZ",))]),
        )
    with pytest.raises(CommandError, match="SIPO_ELNO is not computed"):
        post_gene_phys.run(
            context(),
            kw(
                RESU_GENE=result, OBSERVATION=[observation(NOM_CHAM="SIPO_ELNO", GROUP_MA=("BAR",))]
            ),
        )
    with pytest.raises(CommandError, match="no archived instant"):
        post_gene_phys.run(
            context(),
            kw(
                RESU_GENE=result,
                OBSERVATION=[
                    observation(GROUP_NO=("ALL",), INST=(0.55,), CRITERE="RELATIF", PRECISION=1e-6)
                ],
            ),
        )


def small_harmonic():
    """The basis of small_transient with q(f) = (1 + i f, 2 - i) at f = 10, 20, 30 Hz."""
    basis = small_transient().basis
    freqs = np.array([10.0, 20.0, 30.0])
    q = np.column_stack([1.0 + 1j * freqs, np.full(3, 2.0 - 1j)])
    return HarmGene(
        basis=basis, numbering=None, frequencies=freqs, order=np.arange(1, 4), fields={"DEPL": q}
    )


def test_post_gene_phys_of_a_harm_gene_gives_complex_values_by_frequency():
    table = post_gene_phys.run(
        context(),
        kw(RESU_GENE=small_harmonic(), OBSERVATION=[observation(GROUP_NO=("NO2",), FREQ=20.0)]),
    )
    assert table.columns == [
        "NUME_OBSE", "FREQ", "NOM_CHAM", "NOM_CMP", "NOEUD", "MAILLE", "POINT", "VALE_C",
    ]  # fmt: skip
    assert table.types["VALE_C"] == "C"
    # NO2: DX = 2 q1 + 0.5 q2, DY = -q2 at f = 20
    q1, q2 = 1.0 + 20j, 2.0 - 1j
    assert [(r["NOM_CMP"], r["FREQ"]) for r in table.rows] == [("DX", 20.0), ("DY", 20.0)]
    assert table.rows[0]["VALE_C"] == pytest.approx(2 * q1 + 0.5 * q2)
    assert table.rows[1]["VALE_C"] == pytest.approx(-q2)
    # a VALE_C column makes a fonction_c of RECU_FONCTION TABLE
    every = post_gene_phys.run(
        context(),
        kw(
            RESU_GENE=small_harmonic(),
            OBSERVATION=[observation(GROUP_NO=("NO1",), NOM_CMP=("DY",))],
        ),
    )
    function = recu_fonction.run(context(), kw(TABLE=every, PARA_X="FREQ", PARA_Y="VALE_C"))
    assert isinstance(function, ComplexFunction)
    np.testing.assert_allclose(function.abscissas, [10.0, 20.0, 30.0])
    np.testing.assert_allclose(function.ordinates, np.full(3, 2.0 - 1j))
    with pytest.raises(UnsupportedError, match="DEPL_ABSOLU"):
        post_gene_phys.run(
            context(),
            kw(
                RESU_GENE=small_harmonic(),
                OBSERVATION=[observation(NOM_CHAM="DEPL_ABSOLU", GROUP_NO=("NO1",))],
            ),
        )
    with pytest.raises(CommandError, match="INST applies to transient"):
        post_gene_phys.run(
            context(),
            kw(
                RESU_GENE=small_harmonic(),
                OBSERVATION=[observation(GROUP_NO=("NO1",), INST=(1.0,))],
            ),
        )
