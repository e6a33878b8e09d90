"""POST_RCCM B3600 MOMENT_EQUIVALENT and CREA_TABLE RESU on a small beam result."""

from __future__ import annotations

import numpy as np
import pytest
from asterlite.commands import crea_table, post_rccm

from asterlite.concepts.assembly import DofNumbering, ElementField, NodalComponentField
from asterlite.concepts.mesh import Mesh
from asterlite.concepts.transient import DynaTrans
from asterlite.post.rccm import equivalent_moment, max_magnitude, moment_equivalent_values
from tests.test_post_support import context, kw

EFGE = ("N", "VY", "VZ", "MT", "MFY", "MFZ")


def beam_result() -> DynaTrans:
    """Two SEG2 cells (N1-N2, N2-N3) on the x axis, 3 instants; EFGE_ELNO
    value = 100*order + 10*cell + point, except the moments below."""
    mesh = Mesh(
        coords=np.array([[0.0, 0.0, 0.0], [1.0, 0.0, 0.0], [2.0, 0.0, 0.0]]),
        node_names=["N1", "N2", "N3"],
        cell_names=["M1", "M2"],
        cell_types=["SEG2", "SEG2"],
        cell_nodes=[(0, 1), (1, 2)],
        cell_groups={"G2": np.array([1])},
    )
    numbering = DofNumbering(mesh, [(n, "DY") for n in range(3)])
    times = np.array([0.0, 0.5, 1.0])
    result = DynaTrans(numbering, times, np.array([1, 2, 3]), {"DEPL": np.zeros((3, 3))})
    values = np.zeros((3, 2, 2, 6))
    for k in range(3):
        for c in range(2):
            for p in range(2):
                values[k, c, p, :] = 100 * k + 10 * c + p
    # cell 2, node N3 (point 2): moments (3, -4, 12) then (-6, 0, 1) then (0, 5, 0)
    values[:, 1, 1, 3:] = [[3.0, -4.0, 12.0], [-6.0, 0.0, 1.0], [0.0, 5.0, 0.0]]
    result.name = "RESU"
    result.element_fields = {"EFGE_ELNO": ElementField("EFGE_ELNO", np.array([0, 1]), EFGE, values)}
    result.node_fields = {}
    return result


def test_equivalent_moment_and_maxima():
    moments = np.array([[3.0, -4.0, 12.0], [-6.0, 0.0, 1.0]])
    out = equivalent_moment(moments)
    assert out[:, 3] == pytest.approx([13.0, np.sqrt(37.0)])
    # the value of largest magnitude keeps its sign (code_aster's MAXI_ABS of values)
    assert max_magnitude(out) == pytest.approx([-6.0, -4.0, 12.0, 13.0])


def test_moment_equivalent_values_component_by_component():
    field = beam_result().element_fields["EFGE_ELNO"]
    out = moment_equivalent_values(field.values, EFGE, [0, 1, 2])
    assert out.shape == (2, 2, 4)
    assert out[1, 1] == pytest.approx([-6.0, 5.0, 12.0, 13.0])
    only_second = moment_equivalent_values(field.values, EFGE, [1])
    assert only_second[1, 1] == pytest.approx([-6.0, 0.0, 1.0, np.sqrt(37.0)])
    with pytest.raises(ValueError, match="MT"):
        moment_equivalent_values(field.values[..., :3], ("N", "VY", "VZ"), [0])


def run_rccm(zone, **resu):
    resu = {"RESULTAT": beam_result(), "NOM_CHAM": "EFGE_ELNO", **resu}
    return post_rccm.run(
        context("POST_RCCM"),
        kw(
            TYPE_RESU_MECA="B3600",
            OPTION="MOMENT_EQUIVALENT",
            ZONE_ANALYSE=[zone],
            RESU_MECA=[resu],
        ),
    )


def test_post_rccm_table():
    table = run_rccm({"TOUT": "OUI"}, TOUT_ORDRE="OUI")
    assert table.columns == ["RESULTAT", "NOM_CHAM", "MAILLE", "NOEUD", "MT", "MFY", "MFZ", "MEQ"]
    assert table.column("MAILLE") == ["1", "1", "2", "2"]
    assert table.column("NOEUD") == ["1", "2", "2", "3"]
    row = table.filtered("MAILLE", "EQ", "2").filtered("NOEUD", "EQ", "3").rows[0]
    assert [row[c] for c in ("MT", "MFY", "MFZ", "MEQ")] == pytest.approx([-6.0, 5.0, 12.0, 13.0])
    # cell 1 node 1: MT = MFY = MFZ = 200 at the last order
    assert table.rows[0]["MEQ"] == pytest.approx(200.0 * np.sqrt(3.0))


def test_post_rccm_group_and_orders():
    table = run_rccm({"GROUP_MA": ("G2",)}, NUME_ORDRE=(2,))
    assert table.column("MAILLE") == ["2", "2"]
    assert table.rows[1]["MEQ"] == pytest.approx(np.sqrt(37.0))
    table = run_rccm({"TOUT": "OUI"}, INST=(1.0,))
    assert table.rows[3]["MFY"] == pytest.approx(5.0)


def test_crea_table_resu_elno():
    result = beam_result()
    occ = {
        "RESULTAT": result,
        "NOM_CHAM": "EFGE_ELNO",
        "NOM_CMP": ("MT", "MFZ"),
        "TOUT": "OUI",
        "TOUT_ORDRE": "OUI",
    }
    table = crea_table.run(context("CREA_TABLE"), kw(RESU=[occ]))
    assert table.columns[:6] == ["RESULTAT", "NOM_CHAM", "INST", "NUME_ORDRE", "MAILLE", "NOEUD"]
    assert table.columns[-5:] == ["COOR_X", "COOR_Y", "COOR_Z", "MT", "MFZ"]
    assert len(table) == 3 * 4
    picked = table.filtered("MAILLE", "EQ", "2").filtered("NOEUD", "EQ", "3")
    assert picked.column("NUME_ORDRE") == [1, 2, 3]
    assert picked.column("INST") == pytest.approx([0.0, 0.5, 1.0])
    assert picked.column("MFZ") == pytest.approx([12.0, 1.0, 0.0])
    assert picked.column("COOR_X") == pytest.approx([2.0, 2.0, 2.0])
    occ = dict(occ, TOUT=None, GROUP_MA=("G2",), TOUT_ORDRE=None, NUME_ORDRE=(3,))
    table = crea_table.run(context("CREA_TABLE"), kw(RESU=[occ]))
    assert table.column("MAILLE") == ["2", "2"] and table.column("MT") == pytest.approx([210.0, 0])


def test_crea_table_resu_noeu():
    result = beam_result()
    values = np.arange(3 * 3 * 2, dtype=float).reshape(3, 3, 2)
    result.node_fields = {
        "SIPO_NOEU": NodalComponentField("SIPO_NOEU", np.array([0, 1, 2]), ("SN", "SMFY"), values)
    }
    occ = {"RESULTAT": result, "NOM_CHAM": "SIPO_NOEU", "TOUT_CMP": "OUI", "TOUT": "OUI"}
    table = crea_table.run(context("CREA_TABLE"), kw(RESU=[occ]))
    assert "MAILLE" not in table.columns
    assert table.column("NOEUD")[:3] == ["1", "2", "3"]
    assert table.column("SMFY")[-1] == pytest.approx(17.0)
