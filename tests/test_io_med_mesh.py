"""MED mesh reader: synthetic meshes written with medcoupling, and every MED
mesh of the corpus against the groups its deck uses."""

from __future__ import annotations

import re
from pathlib import Path

import numpy as np
import pytest

from asterlite.io.med_mesh import MedMeshError, med_mesh_names, read_med_mesh

mc = pytest.importorskip("medcoupling")

CORPUS = Path(__file__).resolve().parents[2] / "shared" / "aster-corpus"


# -- synthetic meshes ------------------------------------------------------------------


def _umesh(name, dim, coords, cells):
    """A medcoupling mesh of one dimension; cells = [(NORM type, nodes), ...]."""
    m = mc.MEDCouplingUMesh(name, dim)
    m.allocateCells(len(cells))
    for kind, nodes in cells:
        m.insertNextCell(kind, [int(n) for n in nodes])
    m.finishInsertingCells()
    m.setCoords(coords)
    return m


def _group(name, ids):
    arr = mc.DataArrayInt(list(ids))
    arr.setName(name)
    return arr


def _names(names):
    """A MED name field: 16-character blank-padded names."""
    return mc.DataArrayAsciiChar([n.ljust(16) for n in names])


def write_mixed_mesh(path: Path, names: bool) -> None:
    """Two triangles and a quad with edges and a point cell: levels 0 (faces),
    -1 (SEG2), -2 (POI1), which code_aster numbers from the points up."""
    xy = [0, 0, 1, 0, 2, 0, 0, 1, 1, 1, 2, 1]
    coords = mc.DataArrayDouble(xy, 6, 2)
    coords.setInfoOnComponents(["X", "Y"])
    faces = _umesh(
        "mixed",
        2,
        coords,
        [(mc.NORM_TRI3, (0, 1, 4)), (mc.NORM_TRI3, (0, 4, 3)), (mc.NORM_QUAD4, (1, 2, 5, 4))],
    )
    edges = _umesh("mixed", 1, coords, [(mc.NORM_SEG2, (0, 1)), (mc.NORM_SEG2, (1, 2))])
    points = _umesh("mixed", 0, coords, [(mc.NORM_POINT1, (5,))])
    med = mc.MEDFileUMesh()
    med.setName("mixed")
    med.setDescription("synthetic")
    med.setMeshAtLevel(0, faces)
    med.setMeshAtLevel(-1, edges)
    med.setMeshAtLevel(-2, points)
    med.setGroupsAtLevel(0, [_group("SURF", [0, 1, 2]), _group("TRIS", [0, 1])])
    med.setGroupsAtLevel(-1, [_group("BOTTOM", [0, 1])])
    med.setGroupsAtLevel(-2, [_group("CORNER", [0])])
    med.setGroupsAtLevel(1, [_group("CORNER", [5]), _group("LEFT", [3, 0])])
    if names:
        med.setNameFieldAtLevel(1, _names([f"P{i}" for i in range(6)]))
        med.setNameFieldAtLevel(0, _names(["T1", "T2", "Q1"]))
        med.setNameFieldAtLevel(-1, _names(["E1", "E2"]))
        med.setNameFieldAtLevel(-2, _names(["C1"]))
    med.write(str(path), 2)


def test_mixed_levels_ordering_and_groups(tmp_path):
    path = tmp_path / "mixed.med"
    write_mixed_mesh(path, names=False)
    mesh = read_med_mesh(path)
    assert mesh.dim == 2 and mesh.coords.shape == (6, 3)
    assert np.all(mesh.coords[:, 2] == 0) and mesh.coords[4].tolist() == [1, 1, 0]
    # code_aster order: by MED type number, POI1 < SEG2 < TRIA3 < QUAD4
    assert mesh.cell_types == ["POI1", "SEG2", "SEG2", "TRIA3", "TRIA3", "QUAD4"]
    assert mesh.cell_nodes == [(5,), (0, 1), (1, 2), (0, 1, 4), (0, 4, 3), (1, 2, 5, 4)]
    assert mesh.node_names == [f"N{i}" for i in range(1, 7)]
    assert mesh.cell_names == [f"M{i}" for i in range(1, 7)]
    assert mesh.cell_groups["SURF"].tolist() == [3, 4, 5]
    assert mesh.cell_groups["TRIS"].tolist() == [3, 4]
    assert mesh.cell_groups["BOTTOM"].tolist() == [1, 2]
    assert mesh.cell_groups["CORNER"].tolist() == [0]
    assert mesh.node_groups["CORNER"].tolist() == [5]  # same name at both levels
    assert mesh.node_groups["LEFT"].tolist() == [0, 3]
    assert set(mesh.node_groups) == {"CORNER", "LEFT"}
    assert mesh.title == "synthetic"


def test_names_from_the_file(tmp_path):
    path = tmp_path / "named.med"
    write_mixed_mesh(path, names=True)
    mesh = read_med_mesh(path, "mixed")
    assert mesh.node_names == [f"P{i}" for i in range(6)]
    assert mesh.cell_names == ["C1", "E1", "E2", "T1", "T2", "Q1"]
    assert mesh.cell_index["Q1"] == 5 and mesh.node_index["P4"] == 4


def test_volume_connectivity_follows_code_aster(tmp_path):
    coords = mc.DataArrayDouble(
        [0, 0, 0, 1, 0, 0, 1, 1, 0, 0, 1, 0, 0, 0, 1, 1, 0, 1, 1, 1, 1, 0, 1, 1], 8, 3
    )
    hexa = _umesh("cube", 3, coords, [(mc.NORM_HEXA8, range(8))])
    tetra = _umesh("cube", 3, coords, [(mc.NORM_TETRA4, (0, 1, 3, 4))])
    for umesh, expected in ((hexa, (0, 3, 2, 1, 4, 7, 6, 5)), (tetra, (0, 3, 1, 4))):
        med = mc.MEDFileUMesh()
        med.setName("cube")
        med.setMeshAtLevel(0, umesh)
        path = tmp_path / "cube.med"
        med.write(str(path), 2)
        mesh = read_med_mesh(path)
        assert mesh.cell_nodes == [expected] and mesh.dim == 3


def test_errors(tmp_path):
    with pytest.raises(MedMeshError, match="no such MED file"):
        read_med_mesh(tmp_path / "absent.med")
    bad = tmp_path / "bad.med"
    bad.write_text("not hdf5")
    with pytest.raises(MedMeshError, match="not a readable MED file"):
        read_med_mesh(bad)
    path = tmp_path / "mixed.med"
    write_mixed_mesh(path, names=False)
    assert med_mesh_names(path) == ["mixed"]
    with pytest.raises(MedMeshError, match="no mesh named 'other'.*mixed"):
        read_med_mesh(path, "other")


# -- corpus meshes ---------------------------------------------------------------------

# deck -> (nodes, cells, space dimension)
CORPUS_MESHES = {
    "forma02d": (31, 30, 2),
    "sdld04a": (4, 3, 3),
    "sdld105a": (4, 3, 3),
    "sdll03a": (23, 22, 3),
    "sdll06a": (2, 1, 3),
    "sdll06b": (2, 1, 3),
    "sdnl111a": (102, 100, 3),
    "sdnl111f": (102, 100, 3),
    "sdnl133a": (22, 21, 3),
    "sdnl301a": (49, 48, 2),
}

_GROUP_REF = re.compile(
    r"(?<![A-Z_])(GROUP_MA|GROUP_NO)\s*=\s*(\([^)]*\)|\[[^\]]*\]|\"[^\"]*\"|'[^']*')"
)
_CREATED = re.compile(r"NOM(?:_GROUP_MA|_GROUP_NO)?\s*=\s*[\"']([^\"']+)")


def corpus_med(deck: str) -> Path | None:
    folder = CORPUS / deck
    export = folder / f"{deck}.export"
    if not export.is_file():
        return None
    for line in export.read_text().splitlines():
        parts = line.split()
        if len(parts) >= 5 and parts[0] == "F" and parts[1] == "mmed" and parts[4] == "20":
            return folder / parts[2]
    return None


def deck_group_references(deck: str) -> tuple[dict[str, set[str]], set[str]]:
    """Group names used under GROUP_MA / GROUP_NO, and names the deck creates
    itself (DEFI_GROUP, CREA_MAILLAGE)."""
    text = "".join(p.read_text() for p in sorted((CORPUS / deck).glob(f"{deck}.com*")))
    used: dict[str, set[str]] = {"GROUP_MA": set(), "GROUP_NO": set()}
    for keyword, value in _GROUP_REF.findall(text):
        used[keyword].update(re.findall(r"[\"']([^\"']+)[\"']", value))
    return used, set(_CREATED.findall(text))


@pytest.mark.corpus
@pytest.mark.parametrize("deck", sorted(CORPUS_MESHES))
def test_corpus_mesh(deck):
    path = corpus_med(deck)
    if path is None or not path.is_file():
        pytest.skip(f"corpus deck {deck} not available")
    mesh = read_med_mesh(path)
    n_nodes, n_cells, dim = CORPUS_MESHES[deck]
    assert (mesh.n_nodes, mesh.n_cells, mesh.dim) == (n_nodes, n_cells, dim)
    assert set(mesh.cell_types) == {"SEG2"}
    assert len(set(mesh.node_names)) == n_nodes and len(set(mesh.cell_names)) == n_cells
    for nodes in mesh.cell_nodes:
        assert all(0 <= n < n_nodes for n in nodes)
    for groups, size in ((mesh.node_groups, n_nodes), (mesh.cell_groups, n_cells)):
        for members in groups.values():
            assert len(members) and members.min() >= 0 and members.max() < size
    used, created = deck_group_references(deck)
    assert used["GROUP_MA"] or used["GROUP_NO"]
    missing_cells = sorted(used["GROUP_MA"] - set(mesh.cell_groups) - created)
    # GROUP_NO may name a node group built from a cell group (CREA_GROUP_NO)
    known = set(mesh.node_groups) | set(mesh.cell_groups)
    missing_nodes = sorted(used["GROUP_NO"] - known - created)
    assert not missing_cells and not missing_nodes


@pytest.mark.corpus
def test_corpus_names_and_groups_detail():
    path = corpus_med("sdld04a")
    if path is None or not path.is_file():
        pytest.skip("corpus deck sdld04a not available")
    mesh = read_med_mesh(path)
    assert mesh.node_names == ["N01", "N02", "N03", "N04"]
    assert mesh.cell_names == ["ELN1", "ELN2", "ELN3"]
    assert mesh.node_groups["ENCASTRE"].tolist() == [0]
    assert mesh.node_groups["MASSES"].tolist() == [1, 2, 3]
    assert mesh.cell_nodes[0] == (0, 1)
    path = corpus_med("sdll03a")
    mesh = read_med_mesh(path)
    # a group name at both levels gives a node group and a cell group
    assert "BEAM_PT_10" in mesh.node_groups and "BEAM_PT_10" in mesh.cell_groups
    cells = mesh.cell_groups["BEAM_PT_10"]
    assert set(mesh.nodes_of_cells(cells)) <= set(mesh.node_groups["BEAM_PT_10"])
