"""The MED writer's one-array connectivity (med_writer._level_mesh) gives
medcoupling the mesh that inserting the cells one by one gives: same types,
same node order (MED's for volumes), same cells in the same order."""

from __future__ import annotations

import numpy as np
import pytest

from asterlite.concepts.mesh import Mesh
from asterlite.io import med_writer

mc = pytest.importorskip("medcoupling")


def mixed_volume_mesh() -> Mesh:
    """Two hexahedra, a tetrahedron, two segments and a point, types interleaved."""
    coords = np.array(
        [[x, y, z] for z in (0.0, 1.0, 2.0) for y in (0.0, 1.0) for x in (0.0, 1.0)], dtype=float
    )
    hexa_low = (0, 1, 3, 2, 4, 5, 7, 6)
    hexa_high = (4, 5, 7, 6, 8, 9, 11, 10)
    return Mesh(
        coords=coords,
        node_names=[f"N{i + 1}" for i in range(len(coords))],
        cell_names=["H1", "S1", "T1", "P1", "H2", "S2"],
        cell_types=["HEXA8", "SEG2", "TETRA4", "POI1", "HEXA8", "SEG2"],
        cell_nodes=[hexa_low, (0, 1), (0, 1, 2, 4), (11,), hexa_high, (10, 11)],
        node_groups={},
        cell_groups={},
    )


def inserted_one_by_one(mesh: Mesh, cells, dim: int, coords):
    """The level mesh as the writer built it before (one insertNextCell per cell)."""
    umesh = mc.MEDCouplingUMesh("M", dim)
    umesh.setCoords(coords)
    umesh.allocateCells(len(cells))
    for cell in cells:
        _, med_type, order = med_writer._ASTER_TO_MED[mesh.cell_types[cell]]
        conn = list(mesh.cell_nodes[cell])
        if order is not None:
            med_conn = [0] * len(conn)
            for aster_pos, med_pos in enumerate(order):
                med_conn[med_pos] = conn[aster_pos]
            conn = med_conn
        umesh.insertNextCell(getattr(mc, med_type), [int(n) for n in conn])
    umesh.finishInsertingCells()
    return umesh


def test_level_meshes_match_cell_by_cell_insertion():
    mesh = mixed_volume_mesh()
    coords = med_writer._coords_array(mc, mesh)
    mesh_dim, levels = med_writer._level_layout(mesh)
    assert sorted(levels) == [-3, -2, 0]  # points, segments, volumes
    for level, cells in levels.items():
        dim = mesh_dim + level
        built = med_writer._level_mesh(mc, "M", coords, mesh, cells, dim)
        expected = inserted_one_by_one(mesh, cells, dim, coords)
        assert built.getNodalConnectivity().getValues() == (
            expected.getNodalConnectivity().getValues()
        )
        assert built.getNodalConnectivityIndex().getValues() == (
            expected.getNodalConnectivityIndex().getValues()
        )
        assert built.getAllGeoTypes() == expected.getAllGeoTypes()
        assert built.isEqual(expected, 0.0)


def test_written_file_reads_back_the_volume_cells_in_med_order(tmp_path):
    mesh = mixed_volume_mesh()
    path = med_writer.write_med(tmp_path / "m.med", mesh, "MAIL")
    volume = mc.MEDFileUMesh.New(str(path), "MAIL").getMeshAtLevel(0)
    connectivity = volume.getNodalConnectivity().getValues()
    # TETRA4 (MED 304) sorts before HEXA8 (308); nodes in MED's order
    assert connectivity[:5] == [mc.NORM_TETRA4, 0, 2, 1, 4]
    assert connectivity[5:14] == [mc.NORM_HEXA8, 0, 2, 3, 1, 4, 6, 7, 5]
