"""A deck on an axisymmetric thick cylinder (AXIS, QUAD8 with a SEG3 inner
edge) under internal pressure, with the axial displacement held (plane
strain): PRES_REP on edges, ASSEMBLAGE, FACTORISER/RESOUDRE, CREA_RESU and
CALC_CHAMP SIGM_ELNO against Lame's solution."""

from __future__ import annotations

import numpy as np
import pytest

from tests.solid_meshes import aster_mesh_text
from tests.test_fem_plane import grid_mesh

A, B, HEIGHT, E, NU, P = 1.0, 2.0, 0.5, 2.0e11, 0.3, 1.0e7

DECK = """
DEBUT(CODE="OUI")
mesh = LIRE_MAILLAGE(FORMAT="ASTER", UNITE=20)
model = AFFE_MODELE(MAILLAGE=mesh, AFFE=_F(TOUT="OUI", PHENOMENE="MECANIQUE", MODELISATION="AXIS"))
steel = DEFI_MATERIAU(ELAS=_F(E=YOUNG, NU=POISSON, RHO=7800.0))
chmat = AFFE_MATERIAU(MAILLAGE=mesh, AFFE=_F(TOUT="OUI", MATER=steel))
held = AFFE_CHAR_MECA(MODELE=model, DDL_IMPO=_F(TOUT="OUI", DY=0.0))
inner = AFFE_CHAR_MECA(MODELE=model, PRES_REP=_F(GROUP_MA="INNER", PRES=PRESSURE))
ASSEMBLAGE(
    MODELE=model,
    CHAM_MATER=chmat,
    CHARGE=held,
    NUME_DDL=CO("nume"),
    MATR_ASSE=_F(MATRICE=CO("rigi"), OPTION="RIGI_MECA"),
)
load = ASSE_VECTEUR(NUME_DDL=nume, VECT_ELEM=CALC_VECT_ELEM(OPTION="CHAR_MECA", CHARGE=inner))
rigi = FACTORISER(reuse=rigi, MATR_ASSE=rigi)
u = RESOUDRE(MATR=rigi, CHAM_NO=load)
res = CREA_RESU(
    OPERATION="AFFE",
    TYPE_RESU="MULT_ELAS",
    AFFE=_F(NOM_CHAM="DEPL", CHAM_GD=u, NOM_CAS="P", MODELE=model, CHAM_MATER=chmat),
)
res = CALC_CHAMP(reuse=res, RESULTAT=res, CONTRAINTE="SIGM_ELNO")
TEST_RESU(
    CHAM_NO=_F(CHAM_GD=u, GROUP_NO="BORE", NOM_CMP="DX", REFERENCE="ANALYTIQUE",
               VALE_REFE=U_BORE, VALE_CALC=U_CALC, PRECISION=1e-6),
)
FIN()
"""

EXPORT = """P time_limit 120
F comm ring.comm D 1
F mail ring.mail D 20
"""


def _lame():
    """Plane-strain thick cylinder: radial displacement and hoop stress at r = a."""
    c1 = P * A * A / (B * B - A * A)
    u_bore = (1 + NU) / E * ((1 - 2 * NU) * c1 * A + c1 * B * B / A)
    hoop = P * (A * A + B * B) / (B * B - A * A)
    return u_bore, hoop


def _write(folder, values):
    mesh = grid_mesh("QUAD8", (16, 2), (B - A, HEIGHT), origin=(A, 0.0))
    first_column = [
        c for c, nodes in enumerate(mesh.cell_nodes) if np.isclose(mesh.coords[nodes[0], 0], A)
    ]
    edges = []
    for c in first_column:
        nodes = mesh.cell_nodes[c]
        # corner 4 (top) to corner 1 (bottom): n = (dy/ds, -dx/ds) = -x, so -p n pushes outwards
        edges.append(len(mesh.cell_nodes))
        mesh.cell_nodes.append((nodes[3], nodes[0], nodes[7]))
        mesh.cell_types.append("SEG3")
        mesh.cell_names.append(f"E{len(edges)}")
    bore = [
        n
        for n in range(len(mesh.coords))
        if np.isclose(mesh.coords[n, 0], A) and np.isclose(mesh.coords[n, 1], 0.0)
    ]
    mesh.cell_groups = {"INNER": np.array(edges), "FIRST": np.array(first_column[:1])}
    mesh.node_groups = {"BORE": np.array(bore)}
    folder.mkdir(parents=True, exist_ok=True)
    (folder / "ring.mail").write_text(aster_mesh_text(mesh))
    text = DECK
    for name, value in values.items():
        text = text.replace(name, repr(float(value)))
    (folder / "ring.comm").write_text(text)
    (folder / "ring.export").write_text(EXPORT)
    return folder / "ring.export"


# asterlite's value (non-regression), within the analytic precision above
U_CALC = 9.533330815404416e-05


def test_thick_cylinder_under_internal_pressure(tmp_path):
    """u(a) to 1e-6 of Lame's; the hoop stress SIZZ (AXIS: the theta
    component) at the bore, taken to the node from the Gauss points, to 0.2 %."""
    import asterlite

    u_bore, hoop = _lame()
    values = {"YOUNG": E, "POISSON": NU, "PRESSURE": P, "U_BORE": u_bore, "U_CALC": U_CALC}
    run = asterlite.run(_write(tmp_path, values), output=None)
    assert run.status == "PASS", run.message
    res = run.concepts.raw["res"]
    mesh = res.numbering.mesh
    cell = int(mesh.cell_groups["FIRST"][0])
    node = int(mesh.node_groups["BORE"][0])
    point = list(mesh.cell_nodes[cell]).index(node)
    sigma = res.element_fields["SIGM_ELNO"].at(cell, point, "SIZZ")[0]
    assert sigma == pytest.approx(hoop, rel=2e-3)
