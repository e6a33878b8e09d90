"""CALC_TABLE operations, RECU_TABLE and EXTR_RESU on small hand-made data."""

from __future__ import annotations

import numpy as np
import pytest
from asterlite.commands import calc_table, extr_resu, recu_table

from asterlite.concepts.function import Formula
from asterlite.concepts.table import Table
from tests.test_post_support import context, kw, small_transient


def sample() -> Table:
    return Table.from_columns({"NOEUD": ["N1", "N2", "N3"], "DX": [1.0, -3.0, 2.0], "I": [1, 2, 2]})


def act(table, *actions, **extra):
    return calc_table.run(context("CALC_TABLE"), kw(TABLE=table, ACTION=list(actions), **extra))


def test_filter_extract_sort_rename():
    t = act(sample(), {"OPERATION": "FILTRE", "NOM_PARA": "DX", "CRIT_COMP": "GT", "VALE": (0.0,)})
    assert t.column("NOEUD") == ["N1", "N3"]
    t = act(sample(), {"OPERATION": "TRI", "NOM_PARA": ("DX",), "ORDRE": "DECROISSANT"},
            {"OPERATION": "EXTR", "NOM_PARA": ("NOEUD",)})  # fmt: skip
    assert t.columns == ["NOEUD"] and t.column("NOEUD") == ["N3", "N1", "N2"]
    t = act(sample(), {"OPERATION": "RENOMME", "NOM_PARA": ("DX", "UX")})
    assert "UX" in t.columns and "DX" not in t.columns


def test_unique_suppress_add():
    t = act(sample(), {"OPERATION": "UNIQUE", "NOM_PARA": ("I",)},
            {"OPERATION": "SUPPRIME", "NOM_PARA": ("DX",)},
            {"OPERATION": "AJOUT_LIGNE", "NOM_PARA": ("NOEUD", "I"), "VALE": ("N9", 9)},
            {"OPERATION": "AJOUT_COLONNE", "NOM_PARA": ("K",), "VALE": (7.5,)})  # fmt: skip
    assert t.column("NOEUD") == ["N1", "N2", "N9"]
    assert t.column("K") == [7.5, 7.5, 7.5]


def test_comb_on_keys_and_formula():
    other = Table.from_columns({"NOEUD": ["N2", "N4"], "DY": [10.0, 20.0]})
    t = act(sample(), {"OPERATION": "COMB", "TABLE": other, "NOM_PARA": ("NOEUD",)})
    assert t.column("DY") == [None, 10.0, None, 20.0]
    f = Formula("2*A + B", ("A", "B"))
    t = act(
        sample(), {"OPERATION": "OPER", "FORMULE": f, "NOM_PARA": "S", "NOM_COLONNE": ("DX", "I")}
    )
    assert t.column("S") == pytest.approx([3.0, -4.0, 6.0])


def test_calcul_keeps_sign_of_largest_magnitude():
    t = act(
        sample(), {"OPERATION": "CALCUL", "NOM_PARA": ("DX",), "TYPE_CALCUL": ("MAXI_ABS", "SOMM")}
    )
    assert t.column("DX") == [-3.0, 0.0]


def test_reuse_updates_in_place():
    table = sample()
    ctx = context("CALC_TABLE")
    ctx.reuse = table
    out = calc_table.run(
        ctx, kw(TABLE=table, ACTION=[{"OPERATION": "SUPPRIME", "NOM_PARA": ("I",)}])
    )
    assert out is table and "I" not in table.columns


def test_recu_table_modes_and_transient():
    result = small_transient()
    t = recu_table.run(context(), kw(CO=result.basis, NOM_PARA=("FREQ", "MASS_GENE")))
    assert t.column("NUME_ORDRE") == [1, 2] and t.column("FREQ") == [1.0, 2.0]
    t = recu_table.run(context(), kw(CO=result, NOM_PARA=("INST",)))
    assert len(t) == 11


def test_extr_resu_keeps_instants_and_fields():
    result = small_transient()
    out = extr_resu.run(
        context(), kw(RESULTAT=result, ARCHIVAGE=[{"INST": (0.2, 0.5), "CHAM_EXCLU": ("ACCE",)}])
    )
    assert out.times.tolist() == pytest.approx([0.2, 0.5])
    assert np.all(out.acce == 0.0) and out.depl[1, 1] == pytest.approx(0.25)
    assert out.shocks[0].fields["FN"].size == 2
