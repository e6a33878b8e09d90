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
