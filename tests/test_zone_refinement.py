"""HOMARD-like refinement by zones (asterlite.fem.zone_refinement,
MACR_ADAP_MAIL ADAPTATION='RAFF_DERA_ZONE') and POST_NEWMARK VERI_MASSE."""

from __future__ import annotations

from collections import Counter
from pathlib import Path

import numpy as np
import pytest

from asterlite.concepts.mesh import Mesh
from asterlite.fem.refinement import RefinementError, refine_uniformly
from asterlite.fem.zone_refinement import Zone, plane_height, refine_zones

DECK_MESH = Path("/work/shared/aster-corpus-dyna/zzzz402d/zzzz402a.mmed")


def _grid(nx: int, ny: int, quadratic: bool = False) -> Mesh:
    """Unit squares, QUAD4 (or QUAD8) cells counter-clockwise, group ALL."""
    points = [(float(i), float(j), 0.0) for j in range(ny + 1) for i in range(nx + 1)]
    cells = []
    for j in range(ny):
        for i in range(nx):
            a = j * (nx + 1) + i
            cells.append((a, a + 1, a + nx + 2, a + nx + 1))
    kind = "QUAD4"
    if quadratic:
        kind, middles = "QUAD8", {}
        for c, quad in enumerate(cells):
            extra = []
            for k in range(4):
                key = tuple(sorted((quad[k], quad[(k + 1) % 4])))
                if key not in middles:
                    middles[key] = len(points)
                    points.append(tuple(0.5 * (np.array(points[key[0]]) + points[key[1]])))
                extra.append(middles[key])
            cells[c] = quad + tuple(extra)
    return Mesh(
        coords=np.array(points, dtype=float),
        node_names=[f"N{k + 1}" for k in range(len(points))],
        cell_names=[f"M{k + 1}" for k in range(len(cells))],
        cell_types=[kind] * len(cells),
        cell_nodes=cells,
        cell_groups={"ALL": np.arange(len(cells))},
        dim=2,
    )


def _area(mesh: Mesh, cell: int) -> float:
    n = 4 if mesh.cell_types[cell].startswith("QUAD") else 3
    xy = mesh.coords[list(mesh.cell_nodes[cell][:n]), :2]
    x, y = xy[:, 0], xy[:, 1]
    return 0.5 * float(np.dot(x, np.roll(y, -1)) - np.dot(np.roll(x, -1), y))


def _free_edge_length(mesh: Mesh) -> float:
    """Total length of the vertex edges used by one face only: the perimeter
    of a conforming mesh, more when a node hangs inside."""
    uses: Counter = Counter()
    for c, kind in enumerate(mesh.cell_types):
        n = 4 if kind.startswith("QUAD") else 3
        v = mesh.cell_nodes[c][:n]
        uses.update(tuple(sorted((v[k], v[(k + 1) % n]))) for k in range(n))
    return sum(
        float(np.linalg.norm(mesh.coords[a] - mesh.coords[b]))
        for (a, b), count in uses.items()
        if count == 1
    )


def _rectangle(x0, x1, y0, y1) -> Zone:
    return Zone("RECTANGLE", {"X_MINI": x0, "X_MAXI": x1, "Y_MINI": y0, "Y_MAXI": y1})


def test_a_zone_holding_one_node_cuts_nothing():
    mesh = _grid(2, 2)
    adapted = refine_zones(mesh, [_rectangle(0.9, 1.1, 0.9, 1.1)])  # the centre node only
    assert adapted.counts["cut_edges"] == 0
    assert adapted.mesh.n_cells == 4 and adapted.mesh.n_nodes == 9
    assert not adapted.mesh.zone_adapted


def test_one_cut_edge_splits_each_quadrangle_in_three_triangles():
    # two squares side by side; the zone holds their shared edge x = 1
    mesh = _grid(2, 1)
    adapted = refine_zones(mesh, [_rectangle(0.9, 1.1, -0.1, 1.1)])
    fine = adapted.mesh
    assert adapted.counts == {"zone_edges": 1, "cut_edges": 1, "split": 0, "conformity": 2}
    assert Counter(fine.cell_types) == {"TRIA3": 6}
    assert fine.n_nodes == 6 + 1
    np.testing.assert_allclose(fine.coords[6], (1.0, 0.5, 0.0))
    areas = [_area(fine, c) for c in range(fine.n_cells)]
    assert min(areas) > 0.0 and sum(areas) == pytest.approx(2.0)
    assert sorted(areas) == pytest.approx([0.25] * 4 + [0.5] * 2)
    assert _free_edge_length(fine) == pytest.approx(6.0)  # conforming
    assert adapted.parent.tolist() == [0, 0, 0, 1, 1, 1]
    assert sorted(fine.cell_groups["ALL"].tolist()) == list(range(6))
    assert fine.zone_adapted and fine.node_names[6] == "N7"


def test_two_opposite_and_two_adjacent_cut_edges():
    # a 3 x 1 strip and a zone holding x in [1, 2]: the middle square's four
    # edges are cut, it splits in four, and its neighbours see one cut edge
    strip = refine_zones(_grid(3, 1), [_rectangle(0.9, 2.1, -0.1, 1.1)])
    assert strip.counts["split"] == 1 and strip.counts["conformity"] == 2
    # a single square whose bottom and right edges are in two zones
    square = _grid(1, 1)
    opposite = refine_zones(
        square, [_rectangle(-0.1, 1.1, -0.1, 0.1), _rectangle(-0.1, 1.1, 0.9, 1.1)]
    )
    assert Counter(opposite.mesh.cell_types) == {"QUAD4": 2}
    assert [_area(opposite.mesh, c) for c in range(2)] == pytest.approx([0.5, 0.5])
    adjacent = refine_zones(
        square, [_rectangle(-0.1, 1.1, -0.1, 0.1), _rectangle(0.9, 1.1, -0.1, 1.1)]
    )
    fine = adjacent.mesh
    assert Counter(fine.cell_types) == {"QUAD4": 3}
    # the two middles and the centre (the mean of the vertices)
    np.testing.assert_allclose(fine.coords[4:], [(0.5, 0, 0), (1, 0.5, 0), (0.5, 0.5, 0)])
    assert sorted(_area(fine, c) for c in range(3)) == pytest.approx([0.25, 0.375, 0.375])
    assert _free_edge_length(fine) == pytest.approx(4.0)


def test_the_two_neighbours_rule_spreads_the_cuts():
    # a zone holding the nodes of x <= 1 on a 3 x 3 grid: the edges on x = 0
    # and x = 1 and the horizontal ones between them are cut, so the left
    # column is split in four; the middle column sees one cut edge per square
    mesh = _grid(3, 3)
    adapted = refine_zones(mesh, [_rectangle(-1.0, 1.0, -1.0, 4.0)])
    fine = adapted.mesh
    assert adapted.counts["split"] == 3 and adapted.counts["conformity"] == 3
    assert Counter(fine.cell_types) == {"QUAD4": 3 * 4 + 3, "TRIA3": 3 * 3}
    assert sum(_area(fine, c) for c in range(fine.n_cells)) == pytest.approx(9.0)
    assert _free_edge_length(fine) == pytest.approx(12.0)
    # a triangle with two cut edges is split in four, and cuts its third edge
    tri = Mesh(
        coords=np.array([(0, 0, 0), (1, 0, 0), (0, 1, 0), (1, 1, 0)], dtype=float),
        node_names=["A", "B", "C", "D"],
        cell_names=["T1", "T2"],
        cell_types=["TRIA3", "TRIA3"],
        cell_nodes=[(0, 1, 2), (1, 3, 2)],
        dim=2,
    )
    # the zone holds A, B, C: T1's three edges; T2 keeps one cut edge (B, C)
    adapted = refine_zones(tri, [Zone("DISQUE", {"X_CENTRE": 0.0, "Y_CENTRE": 0.0, "RAYON": 1.0})])
    assert adapted.counts["split"] == 1 and adapted.counts["conformity"] == 1
    assert Counter(adapted.mesh.cell_types) == {"TRIA3": 4 + 2}
    assert _free_edge_length(adapted.mesh) == pytest.approx(4.0)


def test_quadratic_children_share_their_middle_nodes():
    mesh = _grid(2, 1, quadratic=True)
    adapted = refine_zones(mesh, [_rectangle(0.9, 1.1, -0.1, 1.1)])
    fine = adapted.mesh
    assert Counter(fine.cell_types) == {"TRIA6": 6}
    # the cut edge's middle is a vertex now; its halves and the four new
    # edges to the opposite vertices get a middle node each
    assert fine.n_nodes == mesh.n_nodes + 2 + 4
    for c in range(fine.n_cells):
        nodes = fine.cell_nodes[c]
        for k in range(3):
            a, b, m = nodes[k], nodes[(k + 1) % 3], nodes[3 + k]
            np.testing.assert_allclose(fine.coords[m], 0.5 * (fine.coords[a] + fine.coords[b]))
    users = Counter(n for c in range(fine.n_cells) for n in fine.cell_nodes[c][3:])
    # the six outer edges, then the halves and the new edges, inside
    assert sorted(users.values()) == [1] * 6 + [2] * 6


def test_a_curved_quadrangle_is_split_about_the_mean_of_its_vertices():
    # HOMARD's centre of a QUAD8 is the mean of its vertices, not the
    # isoparametric centre (0.6, 0.5 here); its new edges are straight
    mesh = _grid(1, 1, quadratic=True)
    mesh.coords[5] = (1.2, 0.5, 0.0)  # the right edge bulges out
    fine = refine_uniformly(mesh)
    centre = [n for n in range(mesh.n_nodes, fine.n_nodes) if fine.node_names[n] == "N9"]
    np.testing.assert_allclose(fine.coords[centre[0]], (0.5, 0.5, 0.0))
    assert fine.node_groups == {}


def test_zone_shapes_as_homard_tests_nodes():
    coords = np.array([(0, 0, 0), (1, 0, 0), (2, 0, 0), (0, 0, 3)], dtype=float)
    disc = Zone("DISQUE_PERCE", {"X_CENTRE": 0, "Y_CENTRE": 0, "RAYON_INT": 1, "RAYON_EXT": 2})
    assert disc.contains(coords, 0.0).tolist() == [False, True, True, False]  # bounds included
    box = Zone("BOITE", dict(X_MINI=-1, X_MAXI=1, Y_MINI=-1, Y_MAXI=1, Z_MINI=1, Z_MAXI=4))
    assert box.contains(coords, None).tolist() == [False, False, False, True]
    assert not box.contains(coords, 0.0).any()  # a plane mesh in z = 0
    assert box.contains(coords, 2.0).tolist() == [True, True, False, True]  # in z = 2
    sphere = Zone("SPHERE", dict(X_CENTRE=0, Y_CENTRE=0, Z_CENTRE=2, RAYON=2.0))
    assert sphere.contains(coords, None).tolist() == [True, False, False, True]
    assert sphere.contains(coords, 0.0).tolist() == [True, False, False, True]
    pipe = dict(X_AXE=0, Y_AXE=0, Z_AXE=2, X_BASE=0, Y_BASE=0, Z_BASE=0, HAUTEUR=2.0)
    cylinder = Zone("CYLINDRE", pipe | {"RAYON": 1.0})
    assert cylinder.contains(coords, None).tolist() == [True, True, False, False]
    tube = Zone("TUYAU", pipe | {"RAYON_INT": 0.5, "RAYON_EXT": 2.0})
    assert tube.contains(coords, None).tolist() == [False, True, True, False]
    with pytest.raises(RefinementError, match="plane mesh"):
        cylinder.contains(coords, 0.0)
    # a mesh in 3D space with a constant z is plane; a constant x is refused
    mesh = _grid(1, 1)
    mesh.dim = 3
    mesh.coords[:, 2] = 5.0
    assert plane_height(mesh) == 5.0
    mesh.coords[:, [0, 2]] = mesh.coords[:, [2, 0]]
    with pytest.raises(RefinementError, match="X is constant"):
        plane_height(mesh)


def test_refusals_instead_of_a_wrong_mesh():
    mesh = _grid(2, 1)
    once = refine_zones(mesh, [_rectangle(0.9, 1.1, -0.1, 1.1)]).mesh
    with pytest.raises(RefinementError, match="already adapted by zones"):
        refine_zones(once, [_rectangle(0.9, 1.1, -0.1, 1.1)])
    with pytest.raises(RefinementError, match="adapted by zones"):
        refine_uniformly(once)
    hexa = Mesh(
        coords=np.zeros((8, 3)),
        node_names=[f"N{k}" for k in range(8)],
        cell_names=["H"],
        cell_types=["HEXA8"],
        cell_nodes=[tuple(range(8))],
    )
    with pytest.raises(RefinementError, match="HEXA8"):
        refine_zones(hexa, [_rectangle(0, 1, 0, 1)])
    # NIVE_MAX: a uniformly refined mesh at that level is left as it is
    fine = refine_uniformly(mesh)
    kept = refine_zones(fine, [_rectangle(0.9, 1.1, -0.1, 1.1)], max_level=1)
    assert kept.counts["cut_edges"] == 0 and kept.mesh.n_cells == fine.n_cells
    deeper = refine_zones(fine, [_rectangle(0.9, 1.1, -0.1, 1.1)], max_level=2)
    assert deeper.counts["cut_edges"] == 2
    # an edge of no face has no level: HOMARD cuts it whatever NIVE_MAX
    lone = Mesh(
        coords=np.array([(0, 0, 0), (1, 0, 0)], dtype=float),
        node_names=["A", "B"],
        cell_names=["S"],
        cell_types=["SEG2"],
        cell_nodes=[(0, 1)],
        dim=2,
        uniform_level=3,
    )
    split = refine_zones(lone, [_rectangle(-1, 2, -1, 1)], max_level=1)
    assert Counter(split.mesh.cell_types) == {"SEG2": 2}


@pytest.mark.skipif(not DECK_MESH.exists(), reason="the shared corpus is absent")
def test_zzzz402d_mesh_about_the_disc_has_code_asters_counts():
    from asterlite.io.med_mesh import read_med_mesh

    mesh = read_med_mesh(DECK_MESH)
    zone = Zone("DISQUE", {"X_CENTRE": 80.0, "Y_CENTRE": 220.0, "RAYON": 60.0})
    adapted = refine_zones(mesh, [zone])
    # code_aster's MA_MASSE in zzzz402d (POST_NEWMARK VERI_MASSE: 1.2 x RAYON 50)
    assert (adapted.mesh.n_nodes, adapted.mesh.n_cells) == (8038, 3703)
    # each child turns as its parent (this mesh's cells turn clockwise)
    fine, total = adapted.mesh, 0.0
    for child, parent in enumerate(adapted.parent):
        if fine.cell_types[child] != "SEG3":
            area, parent_area = _area(fine, child), _area(mesh, int(parent))
            assert area * parent_area > 0.0
            total += area
    before = sum(_area(mesh, c) for c in range(mesh.n_cells) if mesh.cell_types[c] != "SEG3")
    assert total == pytest.approx(before, rel=1e-12)


def test_post_newmark_veri_masse_takes_the_mass_on_the_refined_mesh():
    from asterlite.concepts.assembly import DofNumbering
    from asterlite.concepts.transient import DynaTrans
    from asterlite.fem.assemble import build_numbering_dofs
    from tests.test_fem_plane import RHO, plane_model
    from tests.test_fem_support import CO, FakeSession, run

    # 2 x 2 unit squares and a disc about (-3, -3) of radius 4.8 reaching the
    # node (0, 0) only: the zone is the first square. The refinement disc
    # (radius 5.76) holds its four vertices: it splits in four, and its child
    # at (1, 1), all of whose nodes lie beyond 4.8, leaves the zone
    mesh = _grid(2, 2)
    model, materials = plane_model(mesh, "D_PLAN")
    numbering = DofNumbering(mesh=mesh, dofs=build_numbering_dofs(model.node_components()))
    times = np.linspace(0.0, 1.0, 5)
    depl = np.zeros((times.size, numbering.n_dofs))
    for k, (node, comp) in enumerate(numbering.dofs):
        if comp == "DX":
            depl[:, k] = 1.0e-7 * times * mesh.coords[node, 0]
    result = DynaTrans(numbering=numbering, times=times, order=np.arange(1, 6),
                       fields={"DEPL": depl}, model=model, materials=materials)  # fmt: skip
    session = FakeSession()
    common = dict(RESULTAT=result, KY=0.01, RAYON=4.8, CENTRE_X=-3.0, CENTRE_Y=-3.0,
                  GROUP_MA_CALC="ALL")  # fmt: skip
    plain = run(session, "POST_NEWMARK", **common).EXTR_TABLE().values()
    checked = run(session, "POST_NEWMARK", **common, VERI_MASSE="OUI", RESI_RELA=0.05,
                  ITER_MAXI=1, MAILLAGE_RESU={"MAILLAGE_MASSE": CO("MA_MASSE")})  # fmt: skip
    fine = session.bound["MA_MASSE"]
    expected = refine_zones(mesh, [Zone("DISQUE", dict(X_CENTRE=-3, Y_CENTRE=-3, RAYON=5.76))])
    assert (fine.n_nodes, fine.n_cells) == (expected.mesh.n_nodes, expected.mesh.n_cells)
    assert expected.counts == {"zone_edges": 4, "cut_edges": 4, "split": 1, "conformity": 2}
    near = np.sum((fine.coords[:, :2] - (-3.0, -3.0)) ** 2, axis=1) <= 4.8**2
    zone = [c for c in range(fine.n_cells) if near[list(fine.cell_nodes[c])].any()]
    assert sorted(fine.cell_groups["GLISSE"].tolist()) == zone
    mass = RHO * sum(_area(fine, c) for c in zone)
    coarse = RHO * 1.0
    assert mass == pytest.approx(0.75 * RHO)
    values = checked.EXTR_TABLE().values()
    np.testing.assert_allclose(
        np.array(values["ACCE_MOY"]) * mass, np.array(plain["ACCE_MOY"]) * coarse, rtol=1e-12
    )
    assert any("VERI_MASSE: refinement 1" in line for line in session.lines)


def test_macr_adap_mail_zone_through_its_catalogue():
    from asterlite.errors import UnsupportedError
    from asterlite.lang.values import CO, FactorDict
    from tests.test_fem_support import FakeSession, validated_run

    mesh = _grid(2, 1)
    session = FakeSession()
    # Z_CENTRE goes to HOMARD with the rest, which reads a disc's X, Y, RAYON
    zone = FactorDict(TYPE="DISQUE", X_CENTRE=1.0, Y_CENTRE=0.5, RAYON=0.6, Z_CENTRE=3.0)
    validated_run(session, "MACR_ADAP_MAIL", MAILLAGE_N=mesh, MAILLAGE_NP1=CO("FINE"),
                  ADAPTATION="RAFF_DERA_ZONE", ZONE=zone)  # fmt: skip
    fine = session.bound["FINE"]
    assert Counter(fine.cell_types) == {"TRIA3": 6} and fine.zone_adapted
    assert any("zone refinement: 6 -> 7 nodes, 2 -> 6 cells" in line for line in session.lines)
    with pytest.raises(Exception, match="RAYON"):
        validated_run(session, "MACR_ADAP_MAIL", MAILLAGE_N=mesh, MAILLAGE_NP1=CO("BAD"),
                      ADAPTATION="RAFF_DERA_ZONE", ZONE=FactorDict(TYPE="DISQUE", X_CENTRE=1.0,
                                                             Y_CENTRE=0.5))  # fmt: skip
    with pytest.raises(UnsupportedError, match="already adapted"):
        validated_run(session, "MACR_ADAP_MAIL", MAILLAGE_N=fine, MAILLAGE_NP1=CO("AGAIN"),
                      ADAPTATION="RAFF_DERA_ZONE", ZONE=zone)  # fmt: skip


def test_coarsening_zones_are_unsupported_not_invalid(tmp_path):
    from asterlite.runtime.check_deck import check_deck

    path = tmp_path / "d.comm"
    path.write_text(
        "DEBUT()\nMA = LIRE_MAILLAGE(FORMAT='MED')\n"
        "MACR_ADAP_MAIL(MAILLAGE_N=MA, MAILLAGE_NP1=CO('MB'), ADAPTATION='RAFF_DERA_ZONE',"
        " ZONE=_F(TYPE='DISQUE', X_CENTRE=0.0, Y_CENTRE=0.0, RAYON=1.0,"
        " USAGE='DERAFFINEMENT'))\nFIN()\n"
    )
    check = check_deck(path)  # (its unit 20 has no file: an invalid finding too)
    found = [(f.kind, f.keyword) for f in check.findings if f.keyword.startswith("MACR")]
    assert found == [("unsupported", "MACR_ADAP_MAIL/ZONE[1]/USAGE")]
