"""MODI_MAILLAGE ABSC_CURV on a bent line, CREA_CHAMP CART_ABSC_R and
CREA_TABLE of the carte; POST_RCCM's ABSC_CURV column and CHAM_GD input."""

from __future__ import annotations

import numpy as np
import pytest
from asterlite.commands import crea_champ, crea_table, modi_maillage, post_rccm

from asterlite.concepts.mesh import Mesh
from asterlite.concepts.modes import FieldOnElements
from asterlite.errors import CommandError
from asterlite.fem.abscissa import AbscissaError, arc_abscissae, curvilinear_abscissa
from tests.test_post_support import context, kw


def _on_arc(phi: float) -> list[float]:
    """Point of the quarter circle of centre (1, 1, 0), radius 1, from (1, 0, 0)."""
    return [1.0 + np.sin(phi), 1.0 - np.cos(phi), 0.0]


def bent_line() -> Mesh:
    """A (0,0,0) -> (1,0,0) straight, a quarter circle of radius 1 to (2,1,0)
    in two SEG3 arcs, then straight to (2,3,0); cells out of walking order,
    the second arc and the last leg numbered against the walk, a POI1 at (2,1,0).
    Abscissae: 0, 1, 1 + pi/8, 1 + pi/4, 1 + 3 pi/8, 1 + pi/2, 3 + pi/2."""
    coords = np.array(
        [
            [0.0, 0.0, 0.0],  # 0 A
            [1.0, 0.0, 0.0],  # 1 arc start
            _on_arc(np.pi / 8),  # 2
            _on_arc(np.pi / 4),  # 3
            _on_arc(3 * np.pi / 8),  # 4
            [2.0, 1.0, 0.0],  # 5 arc end
            [2.0, 3.0, 0.0],  # 6 B
        ]
    )
    return Mesh(
        coords=coords,
        node_names=[f"N{i + 1}" for i in range(7)],
        cell_names=["LEG2", "ARC1", "PT", "LEG1", "ARC2"],
        cell_types=["SEG2", "SEG3", "POI1", "SEG2", "SEG3"],
        cell_nodes=[(6, 5), (1, 3, 2), (5,), (0, 1), (5, 3, 4)],
        node_groups={"A": np.array([0]), "B": np.array([6]), "MID": np.array([3])},
        cell_groups={"LINE": np.array([0, 1, 2, 3, 4]), "ARCS": np.array([1, 4])},
    )


EXPECTED = {
    "LEG1": (0.0, 1.0),
    "ARC1": (1.0, 1.0 + np.pi / 4, 1.0 + np.pi / 8),
    # entered by node 2: node 1 (2,1,0) is the far end
    "ARC2": (1.0 + np.pi / 2, 1.0 + np.pi / 4, 1.0 + 3 * np.pi / 8),
    "LEG2": (3.0 + np.pi / 2, 1.0 + np.pi / 2),
    "PT": (1.0 + np.pi / 2,),
}


def test_arc_of_three_nodes_is_the_circle_arc():
    # half of a circle of radius 2 would fail acos at pi; a third of it is 2 pi/3 * 2
    a, b = np.array([2.0, 0.0, 0.0]), np.array([-1.0, np.sqrt(3.0), 0.0])
    mid = np.array([np.cos(np.pi / 3), np.sin(np.pi / 3), 0.0]) * 2.0
    s = arc_abscissae(np.array([a, b, mid]))
    assert s == pytest.approx([0.0, 4.0 * np.pi / 3.0, 2.0 * np.pi / 3.0])
    # nearly straight (turn under one degree): chords
    s = arc_abscissae(np.array([[0.0, 0, 0], [2.0, 0, 0], [1.0, 1e-3, 0]]))
    assert s[1] == pytest.approx(2.0 * np.hypot(1.0, 1e-3))


def test_abscissa_of_a_bent_line_closed_form():
    mesh = bent_line()
    carte = curvilinear_abscissa(mesh, range(mesh.n_cells), origin=0)
    for name, values in EXPECTED.items():
        assert carte[mesh.cell_names.index(name)] == pytest.approx(values, abs=1e-12), name
    # from the other end the abscissa is the length minus the first one
    back = curvilinear_abscissa(mesh, range(mesh.n_cells), origin=6)
    total = 3.0 + np.pi / 2
    for name, values in EXPECTED.items():
        expected = total - np.asarray(values)
        assert back[mesh.cell_names.index(name)] == pytest.approx(expected, abs=1e-12)


def test_abscissa_errors():
    mesh = bent_line()
    with pytest.raises(AbscissaError, match="not an end"):
        curvilinear_abscissa(mesh, range(mesh.n_cells), origin=3)
    with pytest.raises(AbscissaError, match="free ends"):
        curvilinear_abscissa(mesh, [0, 1, 3], origin=0)  # ARC2 missing: two pieces
    mesh.add_cells(["BRANCH"], "SEG2", [(5, 0)])
    with pytest.raises(AbscissaError, match="more than two"):
        curvilinear_abscissa(mesh, [0, 1, 3, 4, 5, 2], origin=6)
    mesh.add_cells(["TRI"], "TRIA3", [(0, 1, 2)])
    with pytest.raises(AbscissaError, match="TRIA3"):
        curvilinear_abscissa(mesh, [6], origin=0)


def test_modi_maillage_crea_champ_crea_table():
    mesh = bent_line()
    occ = {"GROUP_MA": ("LINE",), "GROUP_NO_ORIG": "A"}
    assert modi_maillage.run(context("MODI_MAILLAGE"), kw(MAILLAGE=mesh, ABSC_CURV=[occ])) is mesh
    carte = crea_champ.run(
        context("CREA_CHAMP"),
        kw(OPERATION="EXTR", TYPE_CHAM="CART_ABSC_R", NOM_CHAM="ABSC_CURV", MAILLAGE=mesh),
    )
    carte.name = "CHABSC"
    assert carte.components == ("ABSC1", "ABSC2", "ABSC3", "ABSC4")
    table = crea_table.run(
        context("CREA_TABLE"), kw(RESU=[{"CHAM_GD": carte, "TOUT": "OUI", "TOUT_CMP": "OUI"}])
    )
    assert table.columns == [
        "CHAM_GD", "MAILLE", "COOR_X", "COOR_Y", "COOR_Z", "ABSC1", "ABSC2", "ABSC3",
    ]  # fmt: skip
    assert table.column("MAILLE") == ["1", "2", "3", "4", "5"]  # mesh order
    row = table.filtered("MAILLE", "EQ", "5").rows[0]
    assert row["CHAM_GD"] == "CHABSC" and "COOR_X" not in row
    assert [row["ABSC1"], row["ABSC2"], row["ABSC3"]] == pytest.approx(EXPECTED["ARC2"])
    assert "ABSC2" not in table.filtered("MAILLE", "EQ", "3").rows[0]  # the POI1
    picked = crea_table.run(
        context("CREA_TABLE"),
        kw(RESU=[{"CHAM_GD": carte, "GROUP_MA": ("ARCS",), "NOM_CMP": ("ABSC2",)}]),
    )
    assert picked.column("ABSC2") == pytest.approx([1.0 + np.pi / 4, 1.0 + np.pi / 4])
    # an origin that is not an end of the line: the keyword path and message
    bad = {"TOUT": "OUI", "GROUP_NO_ORIG": "MID"}
    with pytest.raises(CommandError, match="not an end"):
        modi_maillage.run(context("MODI_MAILLAGE"), kw(MAILLAGE=bent_line(), ABSC_CURV=[bad]))


def test_crea_champ_without_abscissa_is_an_error():
    with pytest.raises(CommandError, match="MODI_MAILLAGE ABSC_CURV first"):
        crea_champ.run(
            context("CREA_CHAMP"),
            kw(
                OPERATION="EXTR",
                TYPE_CHAM="CART_ABSC_R",
                NOM_CHAM="ABSC_CURV",
                MAILLAGE=bent_line(),
            ),
        )


def _straight_beam() -> Mesh:
    """Three SEG2 along x, nodes at 0, 0.5, 1.5, 3 (cell 2 numbered backwards)."""
    return Mesh(
        coords=np.array([[0.0, 0, 0], [0.5, 0, 0], [1.5, 0, 0], [3.0, 0, 0]]),
        node_names=["N1", "N2", "N3", "N4"],
        cell_names=["M1", "M2", "M3"],
        cell_types=["SEG2"] * 3,
        cell_nodes=[(0, 1), (2, 1), (2, 3)],
        node_groups={"A": np.array([0])},
        cell_groups={"M3": np.array([2])},
    )


def test_post_rccm_cham_gd_with_abscissa():
    """EFGE_ELNO given alone: signed MT, MFY, MFZ as they are, MEQ their norm,
    ABSC_CURV the node's distance from N1 along the beam."""
    mesh = _straight_beam()
    modi_maillage.run(
        context("MODI_MAILLAGE"),
        kw(MAILLAGE=mesh, ABSC_CURV=[{"TOUT": "OUI", "GROUP_NO_ORIG": "A"}]),
    )
    values = np.zeros((3, 2, 6))
    values[:, :, 3] = [[1.0, -2.0], [2.0, -2.0], [0.0, 3.0]]  # MT
    values[:, :, 4] = [[2.0, 0.0], [-1.0, 0.0], [4.0, 0.0]]  # MFY
    values[:, :, 5] = [[-2.0, 0.0], [0.0, 0.0], [0.0, 4.0]]  # MFZ
    field = FieldOnElements(
        mesh=mesh,
        field_type="ELNO_SIEF_R",
        field_name="EFGE_ELNO",
        cells=np.arange(3),
        components=("N", "VY", "VZ", "MT", "MFY", "MFZ"),
        values=values,
    )
    field.name = "CHMOM"
    table = post_rccm.run(
        context("POST_RCCM"),
        kw(
            TYPE_RESU_MECA="B3600",
            OPTION="MOMENT_EQUIVALENT",
            ZONE_ANALYSE=[{"TOUT": "OUI"}],
            RESU_MECA=[{"CHAM_GD": field}],
        ),
    )
    assert table.columns == [
        "CHAM_GD", "MAILLE", "NOEUD", "ABSC_CURV", "MT", "MFY", "MFZ", "MEQ",
    ]  # fmt: skip
    assert table.column("NOEUD") == ["1", "2", "3", "2", "3", "4"]
    assert table.column("ABSC_CURV") == pytest.approx([0.0, 0.5, 1.5, 0.5, 1.5, 3.0])
    assert table.column("MT") == pytest.approx([1.0, -2.0, 2.0, -2.0, 0.0, 3.0])
    assert table.column("MEQ") == pytest.approx([3.0, 2.0, np.sqrt(5.0), 2.0, 4.0, 5.0])
    zone = post_rccm.run(
        context("POST_RCCM"),
        kw(
            TYPE_RESU_MECA="B3600",
            OPTION="MOMENT_EQUIVALENT",
            ZONE_ANALYSE=[{"GROUP_MA": ("M3",)}],
            RESU_MECA=[{"CHAM_GD": field}],
        ),
    )
    assert zone.column("MAILLE") == ["3", "3"] and zone.column("MFY") == pytest.approx([4.0, 0.0])
    # a field of another option is refused, as code_aster does
    other = FieldOnElements(mesh, "ELNO_SIEF_R", "SIEF_ELNO", field.cells, field.components, values)
    with pytest.raises(CommandError, match="EFGE_ELNO"):
        post_rccm.run(
            context("POST_RCCM"),
            kw(
                TYPE_RESU_MECA="B3600",
                OPTION="MOMENT_EQUIVALENT",
                ZONE_ANALYSE=[{"TOUT": "OUI"}],
                RESU_MECA=[{"CHAM_GD": other}],
            ),
        )


def test_test_resu_carte_and_geometry():
    from asterlite.commands import test_resu

    mesh = bent_line()
    mesh.cell_groups["ARC2_ONLY"] = np.array([4])
    modi_maillage.run(
        context("MODI_MAILLAGE"),
        kw(MAILLAGE=mesh, ABSC_CURV=[{"TOUT": "OUI", "GROUP_NO_ORIG": "A"}]),
    )
    carte = crea_champ.run(
        context("CREA_CHAMP"),
        kw(OPERATION="EXTR", TYPE_CHAM="CART_ABSC_R", NOM_CHAM="ABSC_CURV", MAILLAGE=mesh),
    )
    ctx = context("TEST_RESU")
    occ = {"CHAM_GD": carte, "GROUP_MA": "ARC2_ONLY", "NOM_CMP": "ABSC3"}
    test_resu.run(ctx, kw(CARTE=[dict(occ, VALE_CALC=1.0 + 3 * np.pi / 8)]))
    test_resu.run(ctx, kw(CARTE=[dict(occ, VALE_CALC=1.0)]))
    assert [t.ok for t in ctx.session.tests] == [True, False]
    with pytest.raises(CommandError, match="has 2 cells"):
        test_resu.run(ctx, kw(CARTE=[dict(occ, GROUP_MA="ARCS", VALE_CALC=1.0)]))
    with pytest.raises(CommandError, match="no ABSC4"):
        test_resu.run(ctx, kw(CARTE=[dict(occ, NOM_CMP="ABSC4", VALE_CALC=1.0)]))
    geometry = crea_champ.run(
        context("CREA_CHAMP"),
        kw(OPERATION="EXTR", TYPE_CHAM="NOEU_GEOM_R", NOM_CHAM="GEOMETRIE", MAILLAGE=mesh),
    )
    assert geometry.values.reshape(-1, 3) == pytest.approx(mesh.coords)
    assert geometry.numbering.dofs[:3] == [(0, "X"), (0, "Y"), (0, "Z")]
