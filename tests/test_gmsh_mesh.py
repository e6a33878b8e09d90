"""gmsh meshes read as code_aster's PRE_GMSH converts them."""

from __future__ import annotations

import numpy as np
import pytest

from asterlite.io.gmsh_mesh import GmshMeshError, read_gmsh_mesh

V1 = """$NOD
5
1 0 0 0
2 1 0 0
3 1 1 0
4 0 1 0
9 5 5 5
$ENDNOD
$ELM
3
1 1 7 7 2 1 2
2 3 12 12 4 1 2 3 4
3 2 12 12 3 1 3 4
$ENDELM
"""

V2 = """$MeshFormat
2.2 0 8
$EndMeshFormat
$PhysicalNames
2
1 5 "edge_long_name"
2 6 "surf"
$EndPhysicalNames
$Nodes
4
1 0 0 0
2 1 0 0
3 1 1 0
4 0 1 0
$EndNodes
$Elements
3
10 1 2 5 1 1 2
11 3 2 6 1 1 2 3 4
12 1 2 6 1 3 4
$EndElements
"""


def test_format_1_groups_by_physical_number_and_drops_unused_nodes(tmp_path):
    path = tmp_path / "m.msh"
    path.write_text(V1)
    mesh = read_gmsh_mesh(path)
    assert mesh.node_names == ["N1", "N2", "N3", "N4"]  # N9 is used by no cell
    assert mesh.cell_names == ["M1", "M2", "M3"]
    assert mesh.cell_types == ["SEG2", "QUAD4", "TRIA3"]
    np.testing.assert_array_equal(mesh.cell_groups["GM12"], [1, 2])
    np.testing.assert_array_equal(mesh.cell_groups["GM7"], [0])
    assert mesh.coords.shape == (4, 3)


def test_format_2_named_groups_keep_cells_of_their_dimension(tmp_path):
    path = tmp_path / "m.msh"
    path.write_text(V2)
    mesh = read_gmsh_mesh(path)
    # names are cut to 8 characters; the SEG2 tagged 6 is not in the surface group
    assert sorted(mesh.cell_groups) == ["edge_lon", "surf"]
    np.testing.assert_array_equal(mesh.cell_groups["surf"], [1])
    np.testing.assert_array_equal(mesh.cell_groups["edge_lon"], [0])


def test_format_4_is_refused_by_name(tmp_path):
    path = tmp_path / "m.msh"
    path.write_text("$MeshFormat\n4.1 0 8\n$EndMeshFormat\n")
    with pytest.raises(GmshMeshError, match="formats 1 and 2"):
        read_gmsh_mesh(path)


def test_a_group_of_one_point_cell_is_also_a_node_group(tmp_path):
    path = tmp_path / "m.msh"
    path.write_text(V1.replace("3\n1 1 7 7 2 1 2", "4\n4 15 24 24 1 3\n1 1 7 7 2 1 2"))
    mesh = read_gmsh_mesh(path)
    assert mesh.cell_types[0] == "POI1"
    np.testing.assert_array_equal(mesh.node_groups["GM24"], [mesh.node_names.index("N3")])
    assert "GM12" not in mesh.node_groups
