"""MODI_REPERE REPERE='COQUE', 'COQUE_INTR_UTIL', 'COQUE_UTIL_INTR' of DKT
plate fields (code_aster's te0442): on a tilted, distorted mesh, the forces
and stresses computed in the CARA_ELEM frame ANGL_REP = (0, 0) and turned to
(30, 10) equal those computed with CARA_ELEM ANGL_REP = (30, 10), complex
values included; the intrinsic frame is reached from either user frame; a
rotation by a right angle swaps the axes (closed form); angvx's angles;
the frames of triangles and quadrangles in one field. FORCE_ARETE on the
plates' edges (te0034: F L / 2 per node)."""

from __future__ import annotations

import copy

import numpy as np
import pytest

from asterlite.concepts.assembly import DofNumbering
from asterlite.concepts.harmonic import DynaHarmo
from asterlite.errors import CommandError
from asterlite.fem.assemble import build_numbering_dofs
from asterlite.fem.plate_fields import plate_element_fields
from asterlite.fem.shell_frames import GENERALISED, TENSOR, angles_from_vector, rotate_in_plane
from tests.test_fem_plane import grid_mesh
from tests.test_fem_plate import KINDS, ROTATION, plate_model, tilted
from tests.test_fem_support import FakeSession, run

OPTIONS = ["EFGE_ELNO", "SIGM_ELNO"]
TURNED = (30.0, 10.0)


def _result(kind, angles):
    """A dyna_harmo of random complex states of a tilted DKT mesh, its forces
    and stresses computed in the CARA_ELEM frame ``angles``."""
    mesh = tilted(grid_mesh(kind, (2, 3), (1.0, 1.3), jitter=0.25, seed=5), ROTATION)
    model, characteristics, materials = plate_model(mesh)
    for shell in characteristics.shells.values():
        shell["ANGL_REP"] = angles
    numbering = DofNumbering(mesh=mesh, dofs=build_numbering_dofs(model.node_components()))
    rng = np.random.default_rng(3)
    depl = rng.normal(size=(1, numbering.n_dofs)) + 1j * rng.normal(size=(1, numbering.n_dofs))
    cells = np.arange(mesh.n_cells)
    fields = plate_element_fields(
        model, characteristics, materials, numbering, cells, depl * 1e-3, OPTIONS
    )
    return DynaHarmo(
        numbering=numbering,
        frequencies=np.array([5.0]),
        order=np.array([1]),
        fields={"DEPL": depl},
        model=model,
        characteristics=characteristics,
        element_fields=fields,
    )


def _turned(result, repere, **affe):
    return run(
        FakeSession(),
        "MODI_REPERE",
        RESULTAT=result,
        REPERE=repere,
        MODI_CHAM=[
            {"TYPE_CHAM": "COQUE_GENE", "NOM_CHAM": "EFGE_ELNO"},
            {"TYPE_CHAM": "TENS_3D", "NOM_CHAM": "SIGM_ELNO"},
        ],
        AFFE={"TOUT": "OUI", **affe},
    )


def _close(a, b):
    finite = np.isfinite(a)
    assert np.array_equal(finite, np.isfinite(b))
    scale = np.abs(b[finite]).max()
    assert np.abs(a[finite] - b[finite]).max() < 1e-12 * scale


@pytest.mark.parametrize("kind", KINDS)
def test_coque_turns_the_fields_to_the_frame_affe_gives(kind):
    plain, reference = _result(kind, (0.0, 0.0)), _result(kind, TURNED)
    for affe in ({"ANGL_REP": TURNED}, {"VECTEUR": _direction(TURNED)}):
        out = _turned(plain, "COQUE", **affe)
        for name in OPTIONS:
            _close(out.element_fields[name].values, reference.element_fields[name].values)
    # the input is unchanged; the cells AFFE does not name go to (0, 0)
    assert plain.element_fields["EFGE_ELNO"] is not out.element_fields["EFGE_ELNO"]
    back = _turned(reference, "COQUE", ANGL_REP=(0.0, 0.0))
    for name in OPTIONS:
        _close(back.element_fields[name].values, plain.element_fields[name].values)


@pytest.mark.parametrize("kind", KINDS)
def test_intrinsic_frame_from_either_user_frame(kind):
    plain, reference = _result(kind, (0.0, 0.0)), _result(kind, TURNED)
    a = _turned(plain, "COQUE_UTIL_INTR")
    b = _turned(reference, "COQUE_UTIL_INTR")
    for name in OPTIONS:
        _close(a.element_fields[name].values, b.element_fields[name].values)
    again = _turned(copy.copy(b), "COQUE_INTR_UTIL")
    for name in OPTIONS:
        _close(again.element_fields[name].values, reference.element_fields[name].values)


def test_nom_cham_resu_keeps_the_input_field():
    """COQUE_INTR_UTIL with NOM_CHAM_RESU='EGRU_ELNO' stores the turned
    EFGE_ELNO beside the untouched input; COQUE_UTIL_INTR of that EGRU_ELNO
    turns it back."""
    result = _result("QUAD4", TURNED)
    out = run(FakeSession(), "MODI_REPERE", RESULTAT=result, REPERE="COQUE_INTR_UTIL",
              MODI_CHAM={"TYPE_CHAM": "COQUE_GENE", "NOM_CHAM": "EFGE_ELNO",
                         "NOM_CHAM_RESU": "EGRU_ELNO"},
              AFFE={"TOUT": "OUI"})  # fmt: skip
    efge, egru = out.element_fields["EFGE_ELNO"], out.element_fields["EGRU_ELNO"]
    assert efge.values is result.element_fields["EFGE_ELNO"].values
    assert egru.name == "EGRU_ELNO"
    finite = np.isfinite(efge.values)
    assert (
        np.abs(egru.values[finite] - efge.values[finite]).max()
        > 1e-3 * np.abs(efge.values[finite]).max()
    )
    back = run(FakeSession(), "MODI_REPERE", RESULTAT=out, REPERE="COQUE_UTIL_INTR",
               MODI_CHAM={"TYPE_CHAM": "COQUE_GENE", "NOM_CHAM": "EGRU_ELNO"},
               AFFE={"TOUT": "OUI"})  # fmt: skip
    _close(back.element_fields["EGRU_ELNO"].values, efge.values)


def _direction(angles):
    alpha, beta = np.radians(angles)
    return (np.cos(beta) * np.cos(alpha), np.cos(beta) * np.sin(alpha), -np.sin(beta))


def test_a_right_angle_swaps_the_axes():
    """x' = y, y' = -x: NXX <-> NYY, NXY and QY change sign; SIZZ kept."""
    forces = np.array([[[[1.0, 2.0, 3.0, 4.0, 5.0, 6.0, 7.0, 8.0]]]])
    out = rotate_in_plane(forces, GENERALISED, np.array([0.0]), np.array([1.0]))
    np.testing.assert_allclose(out[0, 0, 0], [2.0, 1.0, -3.0, 5.0, 4.0, -6.0, 8.0, -7.0])
    stresses = np.array([[[[1.0, 2.0, 9.0, 3.0, 7.0, 8.0]]]])
    out = rotate_in_plane(stresses, TENSOR, np.array([0.0]), np.array([1.0]))
    np.testing.assert_allclose(out[0, 0, 0], [2.0, 1.0, 9.0, -3.0, 8.0, -7.0])


def test_angles_of_a_vector_are_angvx_ones():
    assert angles_from_vector((0.0, 2.0, 0.0)) == pytest.approx((90.0, 0.0))
    assert angles_from_vector((1.0, 0.0, -1.0)) == pytest.approx((0.0, 45.0))
    assert angles_from_vector((0.0, 0.0, 0.0)) == (0.0, 0.0)


def test_one_affe_occurrence_naming_cells():
    result = _result("TRIA3", (0.0, 0.0))
    field = {"TYPE_CHAM": "COQUE_GENE", "NOM_CHAM": "EFGE_ELNO"}
    with pytest.raises(CommandError, match="one AFFE occurrence"):
        run(FakeSession(), "MODI_REPERE", RESULTAT=result, REPERE="COQUE", MODI_CHAM=field,
            AFFE=[{"TOUT": "OUI", "ANGL_REP": (0.0, 0.0)}] * 2)  # fmt: skip
    with pytest.raises(CommandError, match="turns EFGE_ELGA"):
        run(FakeSession(), "MODI_REPERE", RESULTAT=result, REPERE="COQUE_INTR_UTIL",
            MODI_CHAM={"TYPE_CHAM": "COQUE_GENE", "NOM_CHAM": "SIGM_ELNO"},
            AFFE={"TOUT": "OUI"})  # fmt: skip


def _square_with_edges():
    """Two DKT triangles of a tilted unit square, its edge x = 1 as SEG2
    cells (two segments: lengths 0.4 and 0.6), a bar elsewhere."""
    from asterlite.concepts.mesh import Mesh

    coords = np.array(
        [[0.0, 0.0, 0.0], [1.0, 0.0, 0.0], [1.0, 1.0, 0.0], [0.0, 1.0, 0.0], [1.0, 0.4, 0.0]]
    )
    coords = coords @ ROTATION.T
    return Mesh(
        coords=coords,
        node_names=["N1", "N2", "N3", "N4", "N5"],
        cell_names=["T1", "T2", "E1", "E2"],
        cell_types=["TRIA3", "TRIA3", "SEG2", "SEG2"],
        cell_nodes=[(0, 1, 3), (1, 2, 3), (1, 4), (4, 2)],
        node_groups={},
        cell_groups={"PLAQUE": np.array([0, 1]), "BORD": np.array([2, 3])},
        dim=3,
    )


def test_force_arete_on_plate_edges_is_half_the_edge_per_node():
    """FORCE_ARETE (te0034): F L / 2 at each node of each SEG2 edge, moments
    too; the resultant is F times the edge's length."""
    from asterlite.concepts.assembly import Model

    mesh = _square_with_edges()
    model = Model(mesh=mesh, cell_modelisation=dict.fromkeys(range(4), "DKT"))
    load = run(FakeSession(), "AFFE_CHAR_MECA", MODELE=model,
               FORCE_ARETE={"GROUP_MA": "BORD", "FX": 3.0, "FZ": -2.0, "MY": 5.0})  # fmt: skip
    got = {}
    for node, comp, value in load.nodal_forces:
        got[(node, comp)] = got.get((node, comp), 0.0) + value
    assert got[(1, "DX")] == pytest.approx(3.0 * 0.2)
    assert got[(4, "DX")] == pytest.approx(3.0 * 0.5)
    assert got[(2, "DZ")] == pytest.approx(-2.0 * 0.3)
    assert got[(4, "DRY")] == pytest.approx(5.0 * 0.5)
    assert sum(v for (_, c), v in got.items() if c == "DX") == pytest.approx(3.0)
    assert {c for _, c in got} == {"DX", "DZ", "DRY"}


def test_frame_axes_of_triangles_and_quadrangles_together():
    """A mesh of both kinds (zzzz333a's): each cell's axes from its own
    intrinsic frame; in the XY plane ANGL_REP (alpha, 0) makes the angle
    alpha with global X, so (c, s) = (cos, sin)(alpha - the cell's x angle)."""
    from asterlite.concepts.mesh import Mesh
    from asterlite.fem.shell_frames import frame_axes

    coords = np.array(
        [[0, 0, 0], [1, 0, 0], [1, 1, 0], [0, 1, 0], [2, 1, 0]], dtype=float
    )  # a square 1-2-3-4 and a triangle 2-5-3
    mesh = Mesh(coords=coords, node_names=[f"N{i}" for i in range(5)], cell_names=["Q", "T"],
                cell_types=["QUAD4", "TRIA3"], cell_nodes=[(0, 1, 2, 3), (1, 4, 2)],
                node_groups={}, cell_groups={}, dim=3)  # fmt: skip
    c, s = frame_axes(mesh, np.array([0, 1]), [(30.0, 0.0), (30.0, 0.0)])
    triangle_x = np.degrees(np.arctan2(1.0, 1.0))  # its first side, 2 -> 5
    np.testing.assert_allclose(c, np.cos(np.radians([30.0, 30.0 - triangle_x])), atol=1e-14)
    np.testing.assert_allclose(s, np.sin(np.radians([30.0, 30.0 - triangle_x])), atol=1e-14)
