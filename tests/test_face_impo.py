"""AFFE_CHAR_MECA/FACE_IMPO: components on every node of the faces, and DNOR
(DTAN on plane models) with the mean unit normal at each node (code_aster's
canort): exact normals of flat faces, radial normals on a cylinder and an
arc where symmetry makes the mean exact."""

from __future__ import annotations

from types import SimpleNamespace

import numpy as np
import pytest

from asterlite.errors import CommandError
from asterlite.fem.node_normals import node_normals
from tests.solid_meshes import box_mesh, solid_model, with_side_faces
from tests.test_fem_support import FakeSession, run


def _cylinder_strip(angles, radius=2.0, height=1.0):
    """QUAD4 facets between consecutive angles on a cylinder about z, normals outward."""
    coords = []
    for z in (0.0, height):
        coords += [(radius * np.cos(a), radius * np.sin(a), z) for a in angles]
    n = len(angles)
    cells = [(k, k + 1, n + k + 1, n + k) for k in range(n - 1)]
    return SimpleNamespace(
        coords=np.array(coords),
        cell_nodes=cells,
        cell_types=["QUAD4"] * len(cells),
        cell_names=[f"F{k}" for k in range(len(cells))],
        node_names=[f"N{k}" for k in range(len(coords))],
    )


def test_normals_on_a_cylinder_are_radial_where_facets_are_symmetric():
    angles = np.radians([0.0, 30.0, 60.0, 90.0])
    mesh = _cylinder_strip(angles)
    nodes = list(range(len(mesh.coords)))
    alarms = []
    normals = node_normals(mesh, range(len(mesh.cell_nodes)), nodes, 3, log=alarms.append)
    for node in nodes:
        a = angles[node % 4]
        if node % 4 in (1, 2):  # between two facets: the mean is radial
            expected = (np.cos(a), np.sin(a), 0.0)
        else:  # one facet: its own normal, at the facet's mid-angle
            mid = a + np.radians(15.0) if node % 4 == 0 else a - np.radians(15.0)
            expected = (np.cos(mid), np.sin(mid), 0.0)
        assert normals[node] == pytest.approx(expected, abs=1e-14)
    # facets 30 degrees apart: each is 15 degrees from the mean, no alarm (over 10: alarm)
    assert len(alarms) == 4 and "15 degrees" in alarms[0]


def test_normal_at_the_middle_of_an_arc_edge_is_radial():
    """A SEG3 on a circle (2D): at its middle node the parabola's derivative
    is perpendicular to the radius; the normal (dy, -dx)/|.| of an edge going
    counterclockwise points outward."""
    t = np.radians([20.0, 80.0, 50.0])  # SEG3: ends, then middle
    mesh = SimpleNamespace(
        coords=np.column_stack([3.0 * np.cos(t), 3.0 * np.sin(t), np.zeros(3)]),
        cell_nodes=[(0, 1, 2)],
        cell_types=["SEG3"],
        cell_names=["A1"],
        node_names=["P1", "P2", "P3"],
    )
    normals = node_normals(mesh, [0], [2], 2)
    assert normals[0] == pytest.approx([np.cos(t[2]), np.sin(t[2])], abs=1e-14)
    tangents = node_normals(mesh, [0], [2], 2, tangent=True)
    assert tangents[0] == pytest.approx([-np.sin(t[2]), np.cos(t[2])], abs=1e-14)


def _box_with_face():
    mesh = with_side_faces(box_mesh("HEXA8", n=(2, 2, 2)), {"XMAX": (0, 1.0)})
    model, _ = solid_model(mesh)
    return mesh, model


def test_dnor_on_a_flat_face_is_one_relation_per_node():
    mesh, model = _box_with_face()
    load = run(
        FakeSession(), "AFFE_CHAR_MECA", MODELE=model, FACE_IMPO={"GROUP_MA": "XMAX", "DNOR": 0.002}
    )
    face_nodes = set(mesh.node_groups["XMAX"].tolist())
    assert len(load.relations) == len(face_nodes) == 9
    signs = set()
    for relation in load.relations:
        ((node, comp, coef),) = relation.terms  # the y and z parts of the normal are 0
        assert node in face_nodes and comp == "DX" and abs(coef) == pytest.approx(1.0)
        assert relation.rhs == 0.002
        signs.add(np.sign(coef))
    assert len(signs) == 1  # one orientation for the whole face


def test_components_and_exclusions():
    mesh, model = _box_with_face()
    corner = int(mesh.node_groups["XMAX"][0])
    mesh.node_groups["CORNER"] = np.array([corner])
    load = run(
        FakeSession(),
        "AFFE_CHAR_MECA",
        MODELE=model,
        FACE_IMPO={"GROUP_MA": "XMAX", "DY": 0.0, "DZ": -1.0, "SANS_GROUP_NO": "CORNER"},
    )
    assert len(load.relations) == 2 * 8
    assert all(r.terms[0][0] != corner for r in load.relations)
    assert {r.rhs for r in load.relations if r.terms[0][1] == "DZ"} == {-1.0}


def test_dtan_on_a_3d_face_is_an_error():
    _, model = _box_with_face()
    with pytest.raises(CommandError, match="DTAN"):
        run(
            FakeSession(),
            "AFFE_CHAR_MECA",
            MODELE=model,
            FACE_IMPO={"GROUP_MA": "XMAX", "DTAN": 0.0},
        )


def test_veri_norm_without_pressure_faces_checks_nothing():
    from asterlite.catalog.keywords import unread_keywords
    from tests.test_fem_support import keywords

    _, model = _box_with_face()
    from asterlite.commands import affe_char_meca

    from asterlite.runtime.context import CommandContext

    kw = keywords("AFFE_CHAR_MECA", {"MODELE": model, "VERI_NORM": "NON",
                                     "FACE_IMPO": {"GROUP_MA": "XMAX", "DX": 0.0}})  # fmt: skip
    kw.given = frozenset(dict.keys(kw))  # iterating kw would count as reads
    affe_char_meca.run(CommandContext(session=FakeSession(), command="AFFE_CHAR_MECA"), kw)
    assert unread_keywords(kw) == []


def test_dnor_on_the_edges_of_a_plane_model_with_constant_z():
    """A D_PLAN model on a mesh stored with Z = 2: its skin is made of edges,
    whose normal is (dy, -dx)."""
    from asterlite.concepts.assembly import Model
    from tests.test_orie_peau_2d import _square

    mesh = _square(z=2.0)
    model = Model(mesh=mesh, cell_modelisation={c: "D_PLAN" for c in range(mesh.n_cells)})
    assert set(model.node_components()[1]) >= {"DX", "DY"}
    mesh.cell_groups["RIGHT"] = np.array([3])  # the edge x = 1, from (1, 0) to (1, 1)
    load = run(
        FakeSession(), "AFFE_CHAR_MECA", MODELE=model, FACE_IMPO={"GROUP_MA": "RIGHT", "DNOR": 0.5}
    )
    assert sorted((r.terms, r.rhs) for r in load.relations) == [
        ([(1, "DX", 1.0)], 0.5),
        ([(2, "DX", 1.0)], 0.5),
    ]
