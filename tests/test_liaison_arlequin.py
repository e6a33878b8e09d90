"""LIAISON_ELEM OPTION='3D_POU_ARLEQUIN' (asterlite.fem.arlequin): a beam of
square section inside a solid bar of the same section. A rigid motion of the
beam given to the solid satisfies every relation (the beam's mass with unit
density equals the integral of its interpolation over the solid when the
sections agree); the pairing of cells follows code_aster's X rule."""

from __future__ import annotations

from types import SimpleNamespace

import numpy as np
import pytest

from asterlite.fem.arlequin import (
    BeamCell,
    arlequin_relations,
    beam_displacement_matrix,
    beam_unit_mass,
    pair_cells,
)
from asterlite.fem.element_errors import ElementError
from asterlite.fem.frames import rotation_from_angles
from asterlite.fem.solid_reference import REFERENCE_ELEMENTS

H, L = 0.02, 0.06  # side of the square section, length of the bar along X
COMPS = {"DX": 0, "DY": 1, "DZ": 2, "DRX": 3, "DRY": 4, "DRZ": 5}


def _bar(kind: str, nx: int = 3, ny: int = 2, x0: float = 0.0):
    """The bar [x0, x0 + L] x [-H/2, H/2]^2 meshed with HEXA8 or HEXA20 cells,
    the beam axis being the X axis; beam nodes appended after the solid's."""
    reference = REFERENCE_ELEMENTS["HE8" if kind == "HEXA8" else "H20"]
    corners = np.array([[-1, -1, -1], [1, -1, -1], [1, 1, -1], [-1, 1, -1]] * 2, dtype=float)
    corners[4:, 2] = 1.0
    nodes: dict[tuple, int] = {}
    coords, cells = [], []
    dx, dy = L / nx, H / ny
    for i in range(nx):
        for j in range(ny):
            for k in range(ny):
                low = np.array([x0 + i * dx, -H / 2 + j * dy, -H / 2 + k * dy])
                cell = []
                for xi in np.asarray(reference.nodes, dtype=float):
                    x = low + (xi + 1.0) / 2.0 * np.array([dx, dy, dy])
                    key = tuple(np.round(x, 12))
                    if key not in nodes:
                        nodes[key] = len(coords)
                        coords.append(x)
                    cell.append(nodes[key])
                cells.append(cell)
    n_solid = len(coords)
    coords += [np.array([x0, 0.0, 0.0]), np.array([x0 + L, 0.0, 0.0])]
    mesh = SimpleNamespace(
        coords=np.array(coords),
        cell_nodes=cells,
        cell_types=[kind] * len(cells),
    )
    return mesh, n_solid


def _beam(mesh, n_solid, reverse=False, ay=1.2, az=1.2) -> BeamCell:
    first, second = (n_solid + 1, n_solid) if reverse else (n_solid, n_solid + 1)
    start, end = mesh.coords[first], mesh.coords[second]
    angles = (np.pi, 0.0, 0.0) if reverse else (0.0, 0.0, 0.0)
    return BeamCell(
        name="B1",
        nodes=(first, second),
        start=start,
        end=end,
        rotation=rotation_from_angles(angles),
        length=L,
        young=2.0e11,
        poisson=0.3,
        area=H * H,
        iy=H**4 / 12.0,
        iz=H**4 / 12.0,
        ay=ay,
        az=az,
    )


def _residuals(mesh, relations, field, beam_dofs):
    """sum coef * u of each relation, divided by the largest |coef * u| of all."""
    sums, scale = [], 0.0
    for terms, rhs in relations:
        parts = []
        for node, comp, coef in terms:
            values = beam_dofs[node] if node in beam_dofs else field(mesh.coords[node])
            parts.append(coef * values[COMPS[comp]])
        sums.append(sum(parts) - rhs)
        scale = max(scale, max(abs(p) for p in parts))
    return np.array(sums) / scale


def _rigid(translation, rotation):
    def field(x):
        return np.asarray(translation) + np.cross(rotation, x)

    return field


def _rigid_beam_dofs(mesh, beam, translation, rotation):
    return {
        n: np.concatenate([_rigid(translation, rotation)(mesh.coords[n]), rotation])
        for n in beam.nodes
    }


@pytest.mark.parametrize("kind", ["HEXA8", "HEXA20"])
@pytest.mark.parametrize("reverse", [False, True])
def test_rigid_translations_reach_the_solid(kind, reverse):
    mesh, n_solid = _bar(kind)
    beam = _beam(mesh, n_solid, reverse)
    relations = arlequin_relations(mesh, range(len(mesh.cell_nodes)), [beam])
    assert len(relations) == 12
    for translation in np.eye(3) * 1.0e-3:
        dofs = _rigid_beam_dofs(mesh, beam, translation, np.zeros(3))
        residuals = _residuals(mesh, relations, _rigid(translation, np.zeros(3)), dofs)
        assert np.abs(residuals).max() < 1.0e-12


def _rotation_residuals(shear):
    mesh, n_solid = _bar("HEXA20")
    beam = _beam(mesh, n_solid, ay=shear, az=shear)
    relations = arlequin_relations(mesh, range(len(mesh.cell_nodes)), [beam])
    out = []
    for rotation in np.eye(3) * 1.0e-3:
        dofs = _rigid_beam_dofs(mesh, beam, np.zeros(3), rotation)
        out.append(np.abs(_residuals(mesh, relations, _rigid(np.zeros(3), rotation), dofs)).max())
    return out


def test_rigid_rotations_reach_the_solid():
    """HEXA20's 27 points integrate the cubic interpolation times a linear
    field exactly; with shear coefficients 1 the bending and torsion DOFs of
    the beam follow the solid's rotation exactly."""
    assert max(_rotation_residuals(1.0)) < 1.0e-12


def test_shear_coefficients_other_than_one_bend_differently():
    """code_aster's interpolation divides by AY, AZ where the beam's mass
    multiplies: torsion stays exact, bending rotations leave 0.45 % (AY = 1.2)."""
    torsion, about_y, about_z = _rotation_residuals(1.2)
    assert torsion < 1.0e-12
    assert about_y == pytest.approx(4.48e-3, rel=1e-2)
    assert about_z == pytest.approx(4.48e-3, rel=1e-2)


def test_a_bending_motion_of_the_solid_is_not_a_beam_rotation():
    """The relations can fail: a shear field u_y = x^2 of the solid given with a
    beam at rest leaves residuals."""
    mesh, n_solid = _bar("HEXA20")
    beam = _beam(mesh, n_solid)
    relations = arlequin_relations(mesh, range(len(mesh.cell_nodes)), [beam])
    dofs = {n: np.zeros(6) for n in beam.nodes}
    residuals = _residuals(mesh, relations, lambda x: np.array([0.0, x[0] ** 2, 0.0]), dofs)
    assert np.abs(residuals).max() > 0.5


def test_interpolation_reproduces_the_nodes():
    """B at the beam's nodes gives the nodes' translations (on the axis) when
    the two shear ratios agree; code_aster's formula multiplies the DY
    shapes of one plane by the factor of the other, so they must."""
    mesh, n_solid = _bar("HEXA8")
    beam = _beam(mesh, n_solid, ay=1.5, az=1.5)
    dofs = np.arange(1.0, 13.0)
    assert beam_displacement_matrix(beam.start, beam) @ dofs == pytest.approx(dofs[:3])
    assert beam_displacement_matrix(beam.end, beam) @ dofs == pytest.approx(dofs[6:9])


def test_unit_mass_is_the_beam_volume():
    mesh, n_solid = _bar("HEXA8")
    mass = beam_unit_mass(_beam(mesh, n_solid))
    translation = np.tile([1.0, 0.0, 0.0, 0.0, 0.0, 0.0], 2)
    assert translation @ mass @ translation == pytest.approx(H * H * L, rel=1e-14)


def test_cells_pair_by_the_x_of_their_centre():
    """Only the solid cells whose mean node X is strictly inside the beam cell's
    X range are tied to it (code_aster's arlchi)."""
    mesh, n_solid = _bar("HEXA8", nx=3, x0=0.0)
    short = _beam(mesh, n_solid)
    short = BeamCell(**{**short.__dict__, "end": short.start + (L / 2, 0.0, 0.0), "length": L / 2})
    pairs = pair_cells(mesh, range(len(mesh.cell_nodes)), [short])
    centres = [np.mean(mesh.coords[mesh.cell_nodes[c], 0]) for c, _ in pairs]
    assert len(pairs) == 4  # the first slice of 2 x 2 cells (centre L/6); L/2 is its end
    assert max(centres) < L / 2


def test_a_beam_cell_with_no_solid_cell_is_refused():
    mesh, n_solid = _bar("HEXA8")
    far = _beam(mesh, n_solid)
    far = BeamCell(**{**far.__dict__, "start": far.start + 10.0, "end": far.end + 10.0})
    with pytest.raises(ElementError, match="enclose the centre of no solid cell"):
        arlequin_relations(mesh, range(len(mesh.cell_nodes)), [far])


def test_solid_cells_of_two_node_counts_are_refused():
    """code_aster gathers the solid nodes with one node count: a load mixing
    HEXA8 and PENTA6 cells is refused (sslv160b gives each its own load)."""
    mesh, n_solid = _bar("HEXA8")
    first = mesh.cell_nodes[0]
    mesh.cell_nodes.append([first[k] for k in (0, 1, 2, 4, 5, 6)])
    mesh.cell_types.append("PENTA6")
    with pytest.raises(ElementError, match="6 and 8 nodes"):
        arlequin_relations(mesh, range(len(mesh.cell_nodes)), [_beam(mesh, n_solid)])


# -- through a deck: a cantilever, solid then beam, coupled over an overlap ------------

E_STEEL, NU_STEEL = 2.0e11, 0.3
FORCE = -100.0


def _cantilever_mesh_text(rename_nodes=False) -> str:
    """A solid bar [0, 0.08] (HEXA20, 4 x 2 x 2 cells, clamped at x = 0) and a
    beam from 0.04 to 0.16 along its axis: cells BC (0.04-0.08, overlapping
    the last two solid slices, group SC) and BL1, BL2 beyond."""
    from dataclasses import replace

    from tests.solid_meshes import aster_mesh_text, box_mesh

    box = box_mesh("HEXA20", n=(4, 2, 2), size=(0.08, H, H))
    coords = box.coords - (0.0, H / 2, H / 2)
    n = len(coords)
    beam_x = (0.04, 0.08, 0.12, 0.16)
    coords = np.vstack([coords, [(x, 0.0, 0.0) for x in beam_x]])
    names = [f"N{i + 1}" for i in range(len(coords))]
    if rename_nodes:
        names = [f"P{i + 1}" for i in range(len(coords))]
    centres = [np.mean(coords[list(c), 0]) for c in box.cell_nodes]
    cells = list(box.cell_nodes) + [(n, n + 1), (n + 1, n + 2), (n + 2, n + 3)]
    mesh = replace(
        box,
        coords=coords,
        node_names=names,
        cell_names=box.cell_names + ["BC", "BL1", "BL2"],
        cell_types=box.cell_types + ["SEG2"] * 3,
        cell_nodes=cells,
        cell_groups={
            "SL": np.array([c for c, x in enumerate(centres) if x < 0.04]),
            "SC": np.array([c for c, x in enumerate(centres) if x > 0.04]),
            "BC": np.array([len(box.cell_nodes)]),
            "BL": np.array([len(box.cell_nodes) + 1, len(box.cell_nodes) + 2]),
        },
        node_groups={
            "ENCAS": np.array([i for i in range(n) if abs(coords[i, 0]) < 1e-12]),
            "TIP": np.array([n + 3]),
        },
    )
    return aster_mesh_text(mesh)


CANTILEVER = """
MA = LIRE_MAILLAGE(FORMAT="ASTER")
MO = AFFE_MODELE(MAILLAGE=MA, AFFE=(
    _F(GROUP_MA=("SL", "SC"), PHENOMENE="MECANIQUE", MODELISATION="3D"),
    _F(GROUP_MA=("BC", "BL"), PHENOMENE="MECANIQUE", MODELISATION="POU_D_T")))
FULL = DEFI_MATERIAU(ELAS=_F(E=2.0e11, NU=0.3, RHO=7800.0))
HALF = DEFI_MATERIAU(ELAS=_F(E=1.0e11, NU=0.3, RHO=3900.0))
CM = AFFE_MATERIAU(MAILLAGE=MA, AFFE=(
    _F(GROUP_MA=("SL", "BL"), MATER=FULL), _F(GROUP_MA=("SC", "BC"), MATER=HALF)))
CE = AFFE_CARA_ELEM(MODELE=MO, POUTRE=_F(GROUP_MA=("BC", "BL"), SECTION="GENERALE",
    CARA=("A", "IY", "IZ", "AY", "AZ", "JX"), VALE=(4.0e-4, IH, IH, 1.0, 1.0, 2.25e-8)))
CL = AFFE_CHAR_MECA(MODELE=MO, DDL_IMPO=_F(GROUP_NO="ENCAS", DX=0, DY=0, DZ=0))
ARLE = AFFE_CHAR_MECA(MODELE=MO, LIAISON_ELEM=_F(OPTION="3D_POU_ARLEQUIN",
    GROUP_MA_1="SC", GROUP_MA_2="BC", CARA_ELEM=CE, CHAM_MATER=CM))
F = AFFE_CHAR_MECA(MODELE=MO, FORCE_NODALE=_F(GROUP_NO="TIP", FZ=-100.0))
RES = MECA_STATIQUE(MODELE=MO, CHAM_MATER=CM, CARA_ELEM=CE,
    EXCIT=(_F(CHARGE=CL), _F(CHARGE=ARLE), _F(CHARGE=F)))
TEST_RESU(RESU=_F(RESULTAT=RES, NUME_ORDRE=1, NOM_CHAM="DEPL", GROUP_NO="TIP",
    NOM_CMP="DZ", VALE_CALC=VALUE, VALE_REFE=VALUE, REFERENCE="ANALYTIQUE",
    PRECISION=TOLERANCE, TOLE_MACHINE=TOLERANCE))
"""


def _run_cantilever(tmp_path, value, tolerance, rename_nodes=False):
    from asterlite.runtime.runner import run_deck

    (tmp_path / "m.mail").write_text(_cantilever_mesh_text(rename_nodes))
    deck = tmp_path / "d.comm"
    body = CANTILEVER.replace("TOLERANCE", repr(tolerance)).replace("VALUE", repr(value))
    body = body.replace("IH", repr(H**4 / 12.0))
    deck.write_text("DEBUT()\n" + body + "FIN()\n")
    export = tmp_path / "d.export"
    export.write_text(f"F comm {deck} D 1\nF mail {tmp_path / 'm.mail'} D 20\n")
    return run_deck(export, tmp_path / "out")


def test_a_cantilever_through_the_coupling_bends_as_the_beam_theory(tmp_path):
    """The tip of the 0.16 cantilever (solid to 0.08, beam from 0.04, both at
    half stiffness where they overlap) against Timoshenko's cantilever of the
    whole length: the coupling carries the load through the overlap (0.85 %).
    AY = AZ = 1: with code_aster's formula other shear coefficients make the
    short overlap cell stiffer (45 % at 1.2 here, see asterlite.fem.arlequin)."""
    length, inertia, area = 0.16, H**4 / 12.0, H * H
    shear = E_STEEL / (2.0 * (1.0 + NU_STEEL))
    theory = FORCE * length**3 / (3.0 * E_STEEL * inertia) + FORCE * length / (shear * area)
    report = _run_cantilever(tmp_path, theory, 0.015)
    assert report.status == "PASS", report.message


def test_a_mesh_whose_nodes_are_not_named_by_number_is_refused(tmp_path):
    report = _run_cantilever(tmp_path, -1.0, 0.03, rename_nodes=True)
    assert report.status == "UNSUPPORTED", report.message
    assert "'N' + their number" in report.message
