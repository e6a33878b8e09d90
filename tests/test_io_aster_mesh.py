"""The ASTER mesh reader: a section keyword's options may go on over the
lines after it (meshes written by code_aster's IDEAS interface: NUMIN= and
NUMAX= under COOR_3D, AUTEUR= and DATE= below)."""

from __future__ import annotations

import numpy as np
import pytest

from asterlite.io.aster_mesh import AsterMeshError, parse_aster_mesh

MESH = """TITRE    NOM=INDEFINI
         AUTEUR=INTERFACE_IDEAS                 DATE=07/02/2005
FINSF
%
COOR_3D    NOM=INDEFINI    NBOBJ=2      NBLIGE=5        NBLIGT=9
           NUMIN=1                        NUMAX=2
           AUTEUR=INTERF_ST/TF            DATE=07/02/2005
%FORMAT=(1*NOM_DE_NOEUD,3*COORD)
  N1        4.0E-01 -1.0E+00  1.75E-01
  N2        5.0E-01 -1.0E+00  1.75E-01
FINSF
SEG2       NOM=INDEFINI    NBOBJ=1
           AUTEUR=INTERF_ST/TF            DATE=07/02/2005
  M1  N1  N2
FINSF
GROUP_NO
           NOM = ENDS
  N1 N2
FINSF
FIN
"""


def test_options_going_on_over_several_lines():
    mesh = parse_aster_mesh(MESH, "m.mail")
    assert mesh.node_names == ["N1", "N2"]
    np.testing.assert_allclose(mesh.coords[1], [0.5, -1.0, 0.175])
    assert mesh.cell_names == ["M1"] and mesh.cell_types == ["SEG2"]
    assert sorted(mesh.node_groups["ENDS"].tolist()) == [0, 1]


def test_a_name_among_the_coordinates_is_still_refused():
    with pytest.raises(AsterMeshError, match="expected a number"):
        parse_aster_mesh(MESH.replace("  N2        5.0E-01", "  N2        N1"), "m.mail")


SECTIONS = """COOR_2D
 A 0.0 0.0   B 1.0D+00 0.0
FINSF
COOR_3D
 C 2.5 -1.0 3.0
 D 1E-3 2.0
   7.0
FINSF
SEG2
 S1 A B S2 B C
FINSF
TRIA3
 T1 A C
 D
FINSF
FIN
"""


def test_sections_are_read_whole_and_fortran_exponents_one_by_one():
    """Sections are read column by column (entries wrapping over lines),
    a COOR section with a Fortran exponent number by number; the values are
    float()'s either way, and the garbage collector is left as it was."""
    import gc

    mesh = parse_aster_mesh(SECTIONS)
    assert gc.isenabled()
    assert mesh.node_names == ["A", "B", "C", "D"]
    expected = [[0.0, 0.0, 0.0], [1.0, 0.0, 0.0], [2.5, -1.0, 3.0], [1e-3, 2.0, 7.0]]
    assert mesh.coords.flags.c_contiguous and np.array_equal(mesh.coords, expected)
    assert mesh.cell_names == ["S1", "S2", "T1"]
    assert mesh.cell_types == ["SEG2", "SEG2", "TRIA3"]
    assert mesh.cell_nodes == [(0, 1), (1, 2), (0, 2, 3)]
    assert all(type(k) is int for k in mesh.cell_nodes[2])


@pytest.mark.parametrize(
    "change, message",
    [
        (("C 2.5", "A 2.5"), "m.mail:5: node A defined twice"),
        (("D 1E-3", "D nan"), "m.mail:6: node D: 'nan' is"),
        (("T1 A C", "S2 A C"), "m.mail:13: cell S2 defined twice"),
        (("\n D\n", "\n Z\n"), "m.mail:13: cell T1 uses unknown node Z"),
    ],
)
def test_a_wrong_entry_of_a_section_is_named_with_its_line(change, message):
    with pytest.raises(AsterMeshError, match=message):
        parse_aster_mesh(SECTIONS.replace(*change), "m.mail")
