"""LIRE_MAILLAGE VERI_MAIL (code_aster's chckma): alarms for orphan nodes,
doubled and flat cells, errors for a repeated first node and for quadratic
cells that disagree on an edge's middle node or a face's centre."""

from __future__ import annotations

import time

import numpy as np
import pytest

from asterlite.concepts.mesh import Mesh
from asterlite.fem.mesh_check import check_mesh
from tests.solid_meshes import box_mesh


@pytest.mark.parametrize("kind", ["HEXA8", "HEXA20", "HEXA27", "TETRA10", "PENTA15", "PYRAM13"])
def test_a_sound_box_gives_nothing(kind):
    found = check_mesh(box_mesh(kind, n=(2, 2, 2), jitter=0.2, seed=1))
    assert found.alarms == [] and found.errors == []


def _plate():
    coords = np.array(
        [[0, 0, 0], [1, 0, 0], [1, 1, 0], [0, 1, 0], [2, 0, 0], [2, 1e-5, 0], [5, 5, 5.0]]
    )
    return Mesh(
        coords=coords,
        node_names=[f"N{i + 1}" for i in range(7)],
        cell_names=["Q1", "Q2", "T1", "S1"],
        cell_types=["QUAD4", "QUAD4", "TRIA3", "SEG2"],
        cell_nodes=[(0, 1, 2, 3), (1, 2, 3, 0), (1, 4, 5), (0, 1)],
    )


def test_alarms_orphan_doubled_flat():
    found = check_mesh(_plate(), aplat=1e-3)
    assert found.errors == []
    text = "\n".join(found.alarms)
    assert "1 nodes belong to no cell: N7" in text
    assert "1 QUAD4 cells have the nodes of another cell: Q2" in text
    assert "1 TRIA3 cells are flat" in text and "T1" in text
    assert not any("flat" in a for a in check_mesh(_plate(), aplat=1e-6).alarms)


def test_a_repeated_first_node_is_an_error():
    mesh = _plate()
    mesh.cell_nodes[2] = (1, 4, 1)
    assert any("first node twice: T1" in e for e in check_mesh(mesh).errors)


def test_quadratic_cells_disagreeing_on_an_edge_middle():
    mesh = box_mesh("HEXA20", n=(2, 1, 1))
    # give the second cell its own copy of a middle node shared with the first
    first, second = (set(mesh.cell_nodes[c][8:]) for c in (0, 1))
    shared = sorted(first & second)[0]
    mesh.coords = np.vstack([mesh.coords, mesh.coords[shared]])
    mesh.node_names.append("COPY")
    nodes = list(mesh.cell_nodes[1])
    nodes[nodes.index(shared)] = len(mesh.coords) - 1
    mesh.cell_nodes[1] = tuple(nodes)
    found = check_mesh(mesh)
    assert any("edges of quadratic cells have different middle nodes" in e for e in found.errors)


def test_hexa27_cells_disagreeing_on_a_face_centre():
    mesh = box_mesh("HEXA27", n=(2, 1, 1))
    first, second = (set(mesh.cell_nodes[c][20:26]) for c in (0, 1))
    (shared,) = first & second
    mesh.coords = np.vstack([mesh.coords, mesh.coords[shared]])
    mesh.node_names.append("COPY")
    nodes = list(mesh.cell_nodes[1])
    nodes[nodes.index(shared)] = len(mesh.coords) - 1
    mesh.cell_nodes[1] = tuple(nodes)
    assert any("centre nodes" in e for e in check_mesh(mesh).errors)


def test_the_check_of_a_big_mesh_is_quick():
    mesh = box_mesh("HEXA8", n=(30, 30, 30))
    start = time.process_time()
    assert check_mesh(mesh).errors == []
    assert time.process_time() - start < 2.0
