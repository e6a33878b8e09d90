"""LIRE_MAILLAGE(FORMAT='IDEAS'): I-DEAS universal files mapped to code_aster's
mesh as its converter (PRE_IDEAS) maps them: names, cell types and node order,
type-sorted cells, group naming rules, colour groups, refusals."""

from __future__ import annotations

import sys
from pathlib import Path

import numpy as np
import pytest

from asterlite.errors import CommandError, UnsupportedError
from asterlite.io.ideas_mesh import (
    IdeasMeshError,
    IdeasMeshUnsupported,
    group_name,
    parse_ideas_mesh,
)
from asterlite.io.ideas_result import fortran_float
from tests.test_fem_support import FakeSession, run

WIDER = Path(__file__).resolve().parent.parent.parent / "shared" / "aster-corpus-wider"

pytest.importorskip("pyuff")

SEP = "    -1"


def i10(*values: int) -> str:
    return "".join(f"{v:10d}" for v in values)


def node_2411(label: int, xyz, cs: int = 1, color: int = 11) -> list[str]:
    return [i10(label, cs, 1, color), "".join(f"{v:25.16E}" for v in xyz)]


def block(number: int, lines: list[str]) -> list[str]:
    return [SEP, f"{number:6d}", *lines, SEP]


def element_2412(label, descriptor, nodes, color=7) -> list[str]:
    rows = [i10(label, descriptor, 1, 1, color, len(nodes))]
    if descriptor in (11, 21, 22, 23, 24):
        rows.append(i10(0, 1, 1))
    rows += [i10(*nodes[k : k + 8]) for k in range(0, len(nodes), 8)]
    return rows


def group_2467(number, name, entities) -> list[str]:
    rows = [i10(number, 0, 0, 0, 0, 0, 0, len(entities)), name]
    for k in range(0, len(entities), 2):
        rows.append("".join(i10(code, tag, 0, 0) for code, tag in entities[k : k + 2]))
    return rows


# 20 nodes on a unit cube's edges (HEXA20), labels 101..120, plus a 6-node triangle
CUBE = [(x, y, z) for z in (0.0, 0.5, 1.0) for y in (0.0, 0.5, 1.0) for x in (0.0, 0.5, 1.0)]


def universal_file() -> str:
    nodes = []
    for k, xyz in enumerate(CUBE):
        nodes += node_2411(101 + k, xyz, color=3 if k < 10 else 4)
    lines = block(151, ["title", "", "", "", "", "", ""]) + block(2411, nodes)
    hexa20 = list(range(101, 121))
    tria6 = [101, 102, 103, 106, 109, 105]
    elements = (
        element_2412(7, 116, hexa20, color=5)
        + element_2412(3, 21, [101, 102], color=5)
        + element_2412(5, 92, tria6, color=6)
        + element_2412(1, 21, [102, 103], color=6)
    )
    lines += block(2412, elements)
    groups = (
        group_2467(1, "FACE", [(7, 101), (7, 102), (8, 5)])
        + group_2467(2, "PERMANENT GROUP5", [(7, 103), (8, 7)])
        + group_2467(3, "LONGGROUPNAME", [(8, 3)])
        + group_2467(4, "2BAD", [(7, 101)])
        + group_2467(5, "COUL_9", [(7, 104), (8, 1)])
        + group_2467(6, "AB-CD", [(7, 105)])
    )
    lines += block(2477, groups)
    lines += block(775, ["beam properties the converter skips"])
    return "\n".join(lines) + "\n"


def test_names_types_and_code_aster_node_order():
    mesh = parse_ideas_mesh(universal_file(), "cube.unv")
    assert mesh.node_names[:3] == ["N101", "N102", "N103"] and mesh.n_nodes == 27
    assert mesh.dim == 3
    # cells by converter type order (SEG2, TRIA6, HEXA20), file order within a type
    assert mesh.cell_names == ["M3", "M1", "M5", "M7"]
    assert mesh.cell_types == ["SEG2", "SEG2", "TRIA6", "HEXA20"]
    names = mesh.node_names
    tria = [names[i] for i in mesh.cell_nodes[2]]
    # I-DEAS lists corner, middle, corner...: code_aster wants the corners first
    assert tria == ["N101", "N103", "N109", "N102", "N106", "N105"]
    hexa = [names[i] for i in mesh.cell_nodes[3]]
    listed = [f"N{k}" for k in range(101, 121)]
    order = (1, 9, 2, 10, 3, 11, 4, 12, 13, 14, 15, 16, 5, 17, 6, 18, 7, 19, 8, 20)
    assert all(hexa[pos - 1] == listed[k] for k, pos in enumerate(order))
    assert np.allclose(mesh.coords[names.index("N105")], CUBE[4])


def test_group_naming_rules():
    mesh = parse_ideas_mesh(universal_file(), "cube.unv")
    names = mesh.node_names
    assert [names[i] for i in mesh.node_groups["FACE"]] == ["N101", "N102"]
    assert [mesh.cell_names[i] for i in mesh.cell_groups["FACE"]] == ["M5"]
    # PERMANENT groups are numbered, long names cut to 8, a leading digit drops the group
    assert "GRNO2" in mesh.node_groups and "GRMA2" in mesh.cell_groups
    assert [mesh.cell_names[i] for i in mesh.cell_groups["LONGGROU"]] == ["M3"]
    assert "2BAD" not in mesh.node_groups
    # COUL_ names keep their nodes but lose their cells; AB-CD stops at the sign
    assert "COUL_9" in mesh.node_groups and "COUL_9" not in mesh.cell_groups
    assert [names[i] for i in mesh.node_groups["AB"]] == ["N105"]
    assert mesh.ideas_skipped == [151, 775]
    assert any("LONGGROUPNAME" in note for note in mesh.ideas_notes)


def test_group_name_function():
    assert group_name("MASSE", 1, "GROUP_NO") == ("MASSE", "")
    assert group_name("PERMANENT_X", 12, "GROUP_MA")[0] == "GRMA12"
    assert group_name("A_1.5", 1, "GROUP_NO")[0] == "A_1"
    assert group_name("_X", 1, "GROUP_NO")[0] is None
    assert group_name("A#B", 1, "GROUP_NO")[0] is None


def test_colour_groups():
    mesh = parse_ideas_mesh(universal_file(), "cube.unv", color_groups=True)
    assert len(mesh.node_groups["COUL_3"]) == 10 and len(mesh.node_groups["COUL_4"]) == 17
    cells = {c: [mesh.cell_names[i] for i in v] for c, v in mesh.cell_groups.items()}
    assert cells["COUL_5"] == ["M7", "M3"] and cells["COUL_6"] == ["M5", "M1"]


def legacy_file() -> str:
    """SuperTab 6 datasets: 781 nodes, 780 elements, 752 groups (4 entities a line)."""
    nodes = []
    for k in range(5):
        nodes += [i10(k + 1, 0, 0, 11), "".join(f"{v:25.16E}" for v in (0.1 * k, 0.0, 0.0))]
    elements = []
    for k in range(4):
        elements += [i10(k + 1, 21, 1, 2, 1, 1, 7, 2), i10(0, 1, 1, 1, 1), i10(k + 1, k + 2)]
    groups = [i10(1, 0, 0, 0, 0, 5), "ENDS", i10(7, 1, 7, 5, 8, 1, 8, 2), i10(8, 3)]
    lines = block(781, nodes) + block(780, elements) + block(752, groups)
    return "\n".join(lines) + "\n"


def test_legacy_supertab_datasets():
    mesh = parse_ideas_mesh(legacy_file(), "old.unv")
    assert mesh.node_names == ["N1", "N2", "N3", "N4", "N5"]
    assert mesh.cell_types == ["SEG2"] * 4 and mesh.cell_nodes[3] == (3, 4)
    assert list(mesh.node_groups["ENDS"]) == [0, 4]
    assert list(mesh.cell_groups["ENDS"]) == [0, 1, 2]
    # the converter's coordinates go through 15 significant digits
    assert mesh.coords[3, 0] == float(f"{0.1 * 3:.14E}")


def one_cell_file(descriptor: int, nodes: list[int]) -> str:
    lines = block(2411, node_2411(1, (0, 0, 0))) + block(2412, element_2412(1, descriptor, nodes))
    return "\n".join(lines) + "\n"


def test_refusals_and_errors():
    text = one_cell_file(104, [1] * 8)  # thick-shell brick
    with pytest.raises(IdeasMeshUnsupported, match="HEXACE8"):
        parse_ideas_mesh(text, "shell.unv")
    text = one_cell_file(21, [1, 2])
    with pytest.raises(IdeasMeshError, match="unknown node N2"):
        parse_ideas_mesh(text, "bad.unv")
    with pytest.raises(IdeasMeshError, match="no I-DEAS dataset"):
        parse_ideas_mesh("COOR_3D\nFIN\n", "aster.mail")
    cylindrical = [
        "1",
        "part",
        i10(5, 1, 0),
        "CYL",
        *[" 1.0 0.0 0.0"] * 4,
    ]
    text = "\n".join(block(2420, cylindrical) + block(2411, node_2411(1, (0, 0, 0), cs=5)))
    with pytest.raises(IdeasMeshUnsupported, match="not Cartesian"):
        parse_ideas_mesh(text, "cyl.unv")


def test_lire_maillage_ideas_command(tmp_path):
    path = tmp_path / "cube.unv"
    path.write_text(universal_file())
    session = FakeSession({19: path})
    mesh = run(session, "LIRE_MAILLAGE", FORMAT="IDEAS", UNITE=19, CREA_GROUP_COUL="NON")
    assert mesh.n_cells == 4 and "FACE" in mesh.cell_groups
    assert any("not used for the mesh: 151, 775" in line for line in session.lines)
    shell = tmp_path / "shell.unv"
    shell.write_text(one_cell_file(104, [1] * 8))
    with pytest.raises(UnsupportedError, match="HEXACE8"):
        run(FakeSession({19: shell}), "LIRE_MAILLAGE", FORMAT="IDEAS", UNITE=19)
    empty = tmp_path / "empty.unv"
    empty.write_text("nothing\n")
    with pytest.raises(CommandError, match="no I-DEAS dataset"):
        run(FakeSession({19: empty}), "LIRE_MAILLAGE", FORMAT="IDEAS", UNITE=19)


@pytest.mark.parametrize(
    "deck, nodes, groups",
    [
        ("sdld102a", 3, {"MASSE": ["N2", "N3"], "N1": ["N1"]}),
        ("sdll113a", 6, {"BLOC0": ["N1"], "BLOC1": ["N6"]}),
    ],
)
def test_corpus_universal_files(deck, nodes, groups):
    path = WIDER / deck / f"{deck}.msup"
    if not path.is_file():
        pytest.skip("../shared/aster-corpus-wider is not available")
    mesh = run(FakeSession({19: path}), "LIRE_MAILLAGE", FORMAT="IDEAS", UNITE=19)
    assert mesh.n_nodes == nodes and set(mesh.cell_types) == {"SEG2"}
    for name, members in groups.items():
        assert [mesh.node_names[i] for i in mesh.node_groups[name]] == members
    # the file's 0.9999999999999962E-01 as the converter writes it (1PE21.14)
    assert mesh.coords[1, 0] == float("9.99999999999996E-02")


def test_fortran_reals_without_exponent_letter():
    assert fortran_float(" 1.5D+02") == 150.0 and fortran_float("-2.5E-03") == -0.0025
    assert fortran_float("0.12345-102") == 0.12345e-102
    # code_aster's largest real, written rounded up, is read as the largest real
    assert fortran_float("0.17977+309") == sys.float_info.max
