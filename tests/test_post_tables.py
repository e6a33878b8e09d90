import numpy as np
import pytest
from asterlite.commands import crea_table, impr_fonction, impr_table, test_fonction, test_table

from asterlite.concepts.function import Function
from asterlite.concepts.table import Table
from asterlite.errors import CommandError
from asterlite.io.tables import fortran_real

from .test_post_support import context, kw


def shock_table() -> Table:
    table = Table()
    table.add_column("NOEUD", "K8")
    table.add_column("CALCUL", "K16")
    table.add_column("CHOC", "I")
    table.add_column("F_MAX", "R")
    table.add_row({"NOEUD": "1", "CALCUL": "IMPACT", "CHOC": 1, "F_MAX": 10.0})
    table.add_row({"NOEUD": "1", "CALCUL": "IMPACT", "CHOC": 2, "F_MAX": 12.5})
    table.add_row({"NOEUD": "1", "CALCUL": "GLOBAL"})
    table.name = "TT"
    return table


def test_filters_and_extraction():
    table = shock_table()
    assert table.filtered("F_MAX", "GT", 11.0).column("CHOC") == [2]
    assert table.filtered("F_MAX", "EQ", 10.005, precision=1e-3).column("CHOC") == [1]
    assert table.filtered("F_MAX", "MAXI").column("CHOC") == [2]
    assert len(table.filtered("F_MAX", "VIDE")) == 1
    view = table.EXTR_TABLE()
    assert view.values()["F_MAX"] == [10.0, 12.5, None]
    assert view["CHOC", 2] == 2 and table["F_MAX", 1] == 10.0
    assert len(view) == 3


def test_test_table_with_filters():
    ctx = context("TEST_TABLE")
    filters = [{"NOM_PARA": "CALCUL", "VALE_K": "IMPACT"}, {"NOM_PARA": "CHOC", "VALE_I": 2}]
    test_table.run(
        ctx,
        kw(TABLE=shock_table(), NOM_PARA="F_MAX", FILTRE=filters, VALE_CALC=12.5, VALE_REFE=12.0,
           PRECISION=0.05, REFERENCE="ANALYTIQUE"),
    )  # fmt: skip
    (record,) = ctx.session.tests
    assert record.ok and record.strict and record.expected == 12.0
    assert record.error == pytest.approx(0.5 / 12.0)
    with pytest.raises(CommandError, match="2 rows"):
        test_table.run(ctx, kw(TABLE=shock_table(), NOM_PARA="F_MAX", VALE_CALC=1.0))
    test_table.run(ctx, kw(TABLE=shock_table(), NOM_PARA="F_MAX", TYPE_TEST="SOMM", VALE_CALC=22.5))
    assert ctx.session.tests[-1].strict


def test_absolute_criterion_near_zero_and_text_values():
    ctx = context("TEST_TABLE")
    table = Table.from_columns({"A": [1.0e-9], "K": ["OUI"]})
    test_table.run(ctx, kw(TABLE=table, NOM_PARA="A", VALE_CALC=0.0, CRITERE="ABSOLU"))
    test_table.run(ctx, kw(TABLE=table, NOM_PARA="K", VALE_CALC_K="OUI"))
    test_table.run(ctx, kw(TABLE=table, NOM_PARA="K", VALE_CALC_K="NON"))
    assert [(r.ok, r.strict) for r in ctx.session.tests] == [
        (True, True),
        (True, True),
        (False, False),
    ]


def test_test_fonction_values_and_attributes():
    ctx = context("TEST_FONCTION")
    f = Function([0.0, 1.0], [0.0, 2.0], NOM_PARA="INST", NOM_RESU="DX")
    f.name = "F"
    test_fonction.run(
        ctx,
        kw(
            VALEUR=[{"FONCTION": f, "VALE_PARA": 0.5, "VALE_CALC": 1.0}],
            ATTRIBUT=[{"FONCTION": f, "ATTR": "NOM_PARA", "ATTR_REFE": "INST"}],
        ),
    )
    assert [r.ok for r in ctx.session.tests] == [True, True]
    assert ctx.session.tests[0].label == "VALEUR[1] F(0.5)"


def test_crea_table_and_impr_table(tmp_path):
    table = crea_table.run(
        context(),
        kw(LISTE=[{"PARA": "INST", "LISTE_R": (0.0, 0.5)}, {"PARA": "N", "LISTE_I": (1, 2)}]),
    )
    assert table.types == {"INST": "R", "N": "I"}
    ctx = context("IMPR_TABLE", tmp_path)
    impr_table.run(ctx, kw(TABLE=shock_table(), UNITE=8, FORMAT="TABLEAU",
                           FILTRE=[{"NOM_PARA": "CALCUL", "VALE_K": "IMPACT"}],
                           NOM_PARA=("CHOC", "F_MAX")))  # fmt: skip
    text = (tmp_path / "fort.8").read_text().splitlines()
    assert text[-3].split() == ["CHOC", "F_MAX"]
    assert text[-1].split() == ["2", "1.25000E+01"]
    impr_table.run(ctx, kw(TABLE=shock_table(), UNITE=9, FORMAT="CSV"))
    assert (tmp_path / "fort.9").read_text().splitlines()[3].startswith("1,GLOBAL,,")


def test_impr_fonction_formats(tmp_path):
    ctx = context("IMPR_FONCTION", tmp_path)
    f = Function([0.0, 1.0], [0.0, 2.0], NOM_PARA="INST", NOM_RESU="DX")
    impr_fonction.run(ctx, kw(COURBE=[{"FONCTION": f}], UNITE=29, FORMAT="TABLEAU"))
    assert (tmp_path / "fort.29").read_text().splitlines()[-1].split() == [
        "1.00000E+00",
        "2.00000E+00",
    ]
    impr_fonction.run(ctx, kw(COURBE=[{"FONCTION": f}], UNITE=30, FORMAT="XMGRACE"))
    assert "@type xy" in (tmp_path / "fort.30").read_text()


def test_fortran_format():
    assert fortran_real(0.0155) == " 1.55000E-02"
    assert fortran_real(-np.pi, "E14.7") == "-3.1415927E+00"


def test_crea_table_liste_k_is_read_at_type_k_length():
    # code_aster reads the texts into K8 (default), K16 or K24 strings
    table = crea_table.run(
        context(),
        kw(
            LISTE=[
                {"PARA": "A", "LISTE_K": ("VALEUR  ", "TRES_LONG_NOM")},
                {"PARA": "B", "LISTE_K": ("TRES_LONG_NOM_DE_PARAMETRE",), "TYPE_K": "K16"},
            ]
        ),
    )
    assert table.types["A"] == "K8" and table.types["B"] == "K16"
    assert [row["A"] for row in table.rows] == ["VALEUR  ", "TRES_LON"]
    assert table.rows[0]["B"] == "TRES_LONG_NOM_DE"
