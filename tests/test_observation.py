"""OBSERVATION: a rigid displacement projected onto sensors and turned into
their frame, a strain gauge's mean strain on a uniform strain field, the
interpolation of a field lacking values (code_aster's cnsprj) and the
keywords refused by name."""

from __future__ import annotations

import numpy as np
import pytest

from asterlite.concepts.assembly import NodalComponentField
from asterlite.concepts.harmonic import DynaHarmo
from asterlite.concepts.mesh import Mesh
from asterlite.concepts.transient import DynaTrans
from asterlite.errors import CommandError
from asterlite.post import observation as obs
from asterlite.post.field_projection import Placement
from tests.solid_meshes import box_mesh
from tests.test_fem_support import FakeSession, chain_mesh, run, validated_run

STRAINS = ("EPXX", "EPYY", "EPZZ", "EPXY", "EPXZ", "EPYZ")
TRANSLATION = np.array([1.0e-3, -2.0e-3, 0.5e-3])
SPIN = np.array([0.2e-3, -0.1e-3, 0.3e-3])  # small rotation vector
DIRECTION = np.array([2.0, 1.0, 0.5]) / np.linalg.norm([2.0, 1.0, 0.5])
SENSORS = np.outer([0.3, 1.25, 1.7], DIRECTION)  # between the nodes of the line
INSIDE_BOX = np.array([[0.3, 0.4, 0.55], [0.75, 0.2, 0.9], [0.5, 0.5, 0.5]])


def _solid(session):
    mesh = box_mesh("HEXA8", n=(2, 2, 2), size=(1.0, 1.0, 1.0))
    mesh.cell_groups["GAUGE"] = np.array([0])
    model = run(session, "AFFE_MODELE", MAILLAGE=mesh,
                AFFE={"TOUT": "OUI", "PHENOMENE": "MECANIQUE", "MODELISATION": "3D"})  # fmt: skip
    return mesh, model, run(session, "NUME_DDL", MODELE=model)


def _line(session):
    """Springs along a tilted line of length 2, its nodes every 0.5."""
    mesh = chain_mesh(5, 2.0)
    mesh.coords = np.outer(mesh.coords[:, 0], DIRECTION)
    springs = {"TOUT": "OUI", "PHENOMENE": "MECANIQUE", "MODELISATION": "DIS_T"}
    model = run(session, "AFFE_MODELE", MAILLAGE=mesh, AFFE=springs)
    return mesh, model, run(session, "NUME_DDL", MODELE=model)


def _sensors(session, points=SENSORS):
    mesh = Mesh(
        coords=np.asarray(points, dtype=float).copy(),
        node_names=["C1", "C2", "C3"],
        cell_names=["P1", "P2", "P3"],
        cell_types=["POI1"] * 3,
        cell_nodes=[(0,), (1,), (2,)],
        node_groups={"C1": np.array([0]), "C2": np.array([1]), "ALL": np.arange(3)},
        cell_groups={"ALL": np.arange(3)},
    )
    return run(session, "AFFE_MODELE", MAILLAGE=mesh,
               AFFE={"TOUT": "OUI", "PHENOMENE": "MECANIQUE", "MODELISATION": "DIS_T"})  # fmt: skip


def _rigid(points):
    return TRANSLATION + np.cross(SPIN, points)


def _displacements(mesh, numbering):
    """Two instants of a rigid motion (the second twice the first)."""
    depl = np.zeros((2, numbering.n_dofs))
    motion = _rigid(mesh.coords)
    for j, (node, component) in enumerate(numbering.dofs):
        depl[:, j] = motion[node, "XYZ".index(component[1])] * np.array([1.0, 2.0])
    return depl


@pytest.mark.parametrize("source", ["line", "box"])
def test_rigid_displacement_projected_and_turned_into_the_sensor_frame(source):
    session = FakeSession()
    if source == "line":
        (mesh, model, numbering), points = _line(session), SENSORS
    else:  # the sensors inside HEXA8 cells, trilinear: a rigid motion exactly
        (mesh, model, numbering), points = _solid(session), INSIDE_BOX
    sensors = _sensors(session, points)
    result = DynaTrans(
        numbering, np.array([0.0, 1.0]), np.array([1, 2]), {"DEPL": _displacements(mesh, numbering)}
    )
    out = validated_run(
        session,
        "OBSERVATION",
        RESULTAT=result,
        MODELE_1=model,
        MODELE_2=sensors,
        NOM_CHAM="DEPL",
        TOUT_ORDRE="OUI",
        MODI_REPERE={"GROUP_NO": "ALL", "REPERE": "UTILISATEUR", "ANGL_NAUT": (30.0, 0.0, 0.0)},
        FILTRE=(
            {"GROUP_NO": "C1", "NOM_CHAM": "DEPL", "DDL_ACTIF": ("DX", "DY")},
            {"GROUP_NO": "C2", "NOM_CHAM": "DEPL", "DDL_ACTIF": ("DX", "DY")},
        ),
    )
    assert isinstance(out, DynaTrans)
    assert sorted(out.numbering.dofs) == [(0, "DX"), (0, "DY"), (1, "DX"), (1, "DY")]
    c, s = np.cos(np.radians(30.0)), np.sin(np.radians(30.0))
    for node in (0, 1):
        u = _rigid(points[node])  # a linear field: interpolated exactly
        expected = {"DX": c * u[0] + s * u[1], "DY": -s * u[0] + c * u[1]}
        for component, value in expected.items():
            column = out.numbering.index[(node, component)]
            np.testing.assert_allclose(
                out.fields["DEPL"][:, column], [value, 2 * value], rtol=1e-12
            )


def test_unfiltered_projection_keeps_every_dof_of_the_sensor_model():
    session = FakeSession()
    mesh, model, numbering = _line(session)
    result = DynaTrans(
        numbering, np.array([0.0, 1.0]), np.array([1, 2]), {"DEPL": _displacements(mesh, numbering)}
    )
    out = validated_run(session, "OBSERVATION", RESULTAT=result, MODELE_1=model,
                        MODELE_2=_sensors(session), NOM_CHAM="DEPL", INST=1.0)  # fmt: skip
    assert out.numbering.n_dofs == 9 and out.times.tolist() == [1.0]
    for node in range(3):
        for k, component in enumerate(("DX", "DY", "DZ")):
            value = out.fields["DEPL"][0, out.numbering.index[(node, component)]]
            assert value == pytest.approx(2 * _rigid(SENSORS[node])[k], rel=1e-12)


def _uniform_strain():
    return np.array([3.0e-4, -1.0e-4, -0.5e-4, 0.8e-4, 0.2e-4, -0.3e-4])


def _strain_result(mesh, numbering, ramp=0.0):
    """A harmonic result whose EPSI_NOEU is uniform, plus ``ramp`` x (x - 0.25)
    on EPXX (zero mean over the gauge cell [0, 0.5]^3)."""
    values = np.tile(_uniform_strain(), (mesh.n_nodes, 1)).astype(complex)
    values[:, 0] += ramp * (mesh.coords[:, 0] - 0.25)
    result = DynaHarmo(numbering, np.array([10.0]), np.array([1]), {})
    result.node_fields = {
        "EPSI_NOEU": NodalComponentField(
            "EPSI_NOEU", np.arange(mesh.n_nodes), STRAINS, (1.0 + 2.0j) * values[None]
        )
    }
    return result


def test_gauge_mean_strain_of_a_uniform_field_turned_by_the_gauge_direction():
    session = FakeSession()
    mesh, model, numbering = _solid(session)
    result = _strain_result(mesh, numbering, ramp=1.0e-4)
    out = validated_run(
        session,
        "OBSERVATION",
        RESULTAT=result,
        MODELE_1=model,
        MODELE_2=model,
        PROJECTION="NON",
        NOM_CHAM="EPSI_NOEU",
        FREQ=10.0,
        EPSI_MOYENNE={"GROUP_MA": "GAUGE", "SEUIL_VARI": 0.1},
        MODI_REPERE={
            "GROUP_MA": "GAUGE",
            "TYPE_CHAM": "TENS_3D",
            "REPERE": "DIR_JAUGE",
            "VECT_X": (0.0, 1.0, 0.0),
            "VECT_Y": (-1.0, 0.0, 0.0),
        },
        FILTRE={"GROUP_MA": "GAUGE", "NOM_CHAM": "EPSI_NOEU", "DDL_ACTIF": ("EPXX", "EPYY")},
    )
    field = out.node_fields["EPSI_NOEU"]
    gauge_nodes = sorted(mesh.nodes_of_cells([0]).tolist())
    assert sorted(field.nodes.tolist()) == gauge_nodes and field.components == ("EPXX", "EPYY")
    exx, eyy = _uniform_strain()[:2]
    # gauge x along global y: the gauge reads eyy along itself, exx across
    np.testing.assert_allclose(field.values[0, :, 0], (1 + 2j) * eyy, rtol=1e-12)
    np.testing.assert_allclose(field.values[0, :, 1], (1 + 2j) * exx, rtol=1e-12)
    # the ramp spreads EPXX by 0.25e-4 around 3e-4: within SEUIL_VARI=0.1, no warning
    assert not any("<A>" in line for line in session.lines)


def test_a_strain_straying_over_the_gauge_gives_a_warning_unless_masked():
    for masked, warned in (((), True), (("EPXX",), False)):
        session = FakeSession()
        mesh, model, numbering = _solid(session)
        validated_run(
            session,
            "OBSERVATION",
            RESULTAT=_strain_result(mesh, numbering, ramp=4.0e-4),
            MODELE_1=model,
            MODELE_2=model,
            PROJECTION="NON",
            NOM_CHAM="EPSI_NOEU",
            TOUT_ORDRE="OUI",
            EPSI_MOYENNE={"GROUP_MA": "GAUGE", **({"MASQUE": masked} if masked else {})},
        )
        assert any("<A>" in line and "EPXX" in line for line in session.lines) == warned


def test_projection_of_a_field_lacking_values_follows_cnsprj():
    field = obs.ObservedField(
        np.arange(4),
        ("EPXX",),
        np.array([[[1.0], [3.0], [5.0], [7.0]]]),
        np.array([[True], [True], [False], [True]]),
    )
    weights = {
        10: (np.arange(4), np.array([0.25, 0.25, 0.25, 0.25])),  # some nodes lack it
        11: (np.arange(4), np.array([0.0, 0.0, 1.0, 0.0])),  # only the lacking one weighs
        12: (np.array([0, 1]), np.array([0.5, 0.5])),  # all hold it
    }
    out = obs.project(field, Placement(weights, [], 0.0), np.array([10, 11, 12, 13]))
    np.testing.assert_allclose(out.values[0, :3, 0], [(1 + 3 + 7) / 3, (1 + 3 + 7) / 3, 2.0])
    assert out.defined[:, 0].tolist() == [True, True, True, False]


def test_gauge_axes_from_one_direction():
    # VECT_X alone along z: y is e_x x z = -y (the longest product, first on ties)
    np.testing.assert_allclose(obs.gauge_axes((0, 0, 2.0), None)[0], [0, 0, 1], atol=1e-15)
    axes = obs.gauge_axes(None, (0, 1.0, 0))
    np.testing.assert_allclose(axes[1], [0, 1, 0], atol=1e-15)
    np.testing.assert_allclose(axes @ axes.T, np.eye(3), atol=1e-15)


def test_refusals_by_name():
    session = FakeSession()
    mesh, model, numbering = _solid(session)
    result = _strain_result(mesh, numbering)
    common = dict(RESULTAT=result, MODELE_1=model, MODELE_2=model, PROJECTION="NON",
                  TOUT_ORDRE="OUI", NOM_CHAM="EPSI_NOEU")  # fmt: skip
    with pytest.raises(CommandError, match="normals of every cell of MODELE_1.*not a face"):
        validated_run(session, "OBSERVATION", **common, MODI_REPERE={
            "GROUP_MA": "GAUGE", "TYPE_CHAM": "TENS_3D", "REPERE": "NORMALE", "VECT_X": (1, 0, 0)
        })  # fmt: skip
    with pytest.raises(CommandError, match="DEPL, which NOM_CHAM does not give"):
        validated_run(session, "OBSERVATION", **common,
                      FILTRE={"TOUT": "OUI", "NOM_CHAM": "DEPL", "DDL_ACTIF": ("DX",)})  # fmt: skip
    with pytest.raises(CommandError, match="SIEF_NOEU"):
        validated_run(session, "OBSERVATION", **{**common, "NOM_CHAM": "SIEF_NOEU"})


def test_plane_strains_and_vectors_turned_about_z():
    theta = np.radians(25.0)
    c, s = np.cos(theta), np.sin(theta)
    axes = np.array([[[c, s, 0.0], [-s, c, 0.0], [0.0, 0.0, 1.0]]])
    exx, eyy, ezz, exy = 2.0, -1.0, 0.5, 0.7
    field = obs.ObservedField(
        np.array([4]),
        ("EPXX", "EPYY", "EPZZ", "EPXY", "DX", "DY"),
        np.array([[[exx, eyy, ezz, exy, 3.0, 4.0]]]),
        np.ones((1, 6), dtype=bool),
    )
    assert obs.plane_rotation(axes)
    obs.rotate_tensors(field, np.array([0]), ("EPXX", "EPYY", "EPZZ", "EPXY"), axes)
    obs.rotate_vectors(field, np.array([0]), ("DX", "DY"), axes)
    expected = [
        c * c * exx + s * s * eyy + 2 * c * s * exy,
        s * s * exx + c * c * eyy - 2 * c * s * exy,
        ezz,
        (eyy - exx) * c * s + (c * c - s * s) * exy,
        c * 3.0 + s * 4.0,
        -s * 3.0 + c * 4.0,
    ]
    np.testing.assert_allclose(field.values[0, 0], expected, rtol=1e-14)


def test_nautical_angles_of_an_orthonormal_frame_give_back_its_axes():
    rng = np.random.default_rng(5)
    for _ in range(5):
        frame, _ = np.linalg.qr(rng.normal(size=(3, 3)))
        frame = frame.T * np.sign(np.linalg.det(frame))  # rows: a right-handed frame
        # y's length does not count, nor does x's for the x axis itself
        np.testing.assert_allclose(
            obs.nautical_rotation(frame[0], 2.0 * frame[1]), frame, atol=1e-12
        )
        np.testing.assert_allclose(obs.nautical_rotation(3.0 * frame[0], frame[1])[0], frame[0])
    # with a normal along z and VECT_X along x the frame is the global one
    np.testing.assert_allclose(obs.normal_axes((0, 0, 2.0), vect_x=(1, 0, 0)), np.eye(3))


def _tilted_plate(session, tilt):
    """2 x 2 QUAD4 on the plane through the origin of normal (0, -sin t, cos t)."""
    u, v = np.meshgrid([0.0, 0.5, 1.0], [0.0, 0.5, 1.0], indexing="ij")
    along = np.array([0.0, np.cos(tilt), np.sin(tilt)])
    coords = np.outer(u.ravel(), [1.0, 0.0, 0.0]) + np.outer(v.ravel(), along)
    quads = [(3 * i + j, 3 * (i + 1) + j, 3 * (i + 1) + j + 1, 3 * i + j + 1)
             for i in range(2) for j in range(2)]  # fmt: skip
    mesh = Mesh(coords, [f"N{k}" for k in range(9)], [f"Q{k}" for k in range(4)],
                ["QUAD4"] * 4, quads)  # fmt: skip
    model = run(session, "AFFE_MODELE", MAILLAGE=mesh,
                AFFE={"TOUT": "OUI", "PHENOMENE": "MECANIQUE", "MODELISATION": "DKT"})  # fmt: skip
    return mesh, model, run(session, "NUME_DDL", MODELE=model)


def test_displacement_in_the_frame_of_the_skin_normal():
    session = FakeSession()
    tilt = np.radians(35.0)
    mesh, model, numbering = _tilted_plate(session, tilt)
    depl = np.zeros((1, numbering.n_dofs))
    for j, (_, component) in enumerate(numbering.dofs):
        depl[0, j] = {"DX": 0.3, "DY": 0.0, "DZ": 1.0}.get(component, 0.0)
    result = DynaTrans(numbering, np.array([0.0]), np.array([1]), {"DEPL": depl})
    points = [mesh.coords[4], 0.5 * (mesh.coords[0] + mesh.coords[4]), mesh.coords[8]]
    out = validated_run(
        session,
        "OBSERVATION",
        RESULTAT=result,
        MODELE_1=model,
        MODELE_2=_sensors(session, points),
        NOM_CHAM="DEPL",
        TOUT_ORDRE="OUI",
        MODI_REPERE={"GROUP_NO": ("C1", "C2"), "REPERE": "NORMALE", "VECT_X": (1.0, 0.0, 0.0)},
    )
    # x along VECT_X, y = normal ^ x in the plate, z the normal
    local = {"DX": 0.3, "DY": np.sin(tilt), "DZ": np.cos(tilt)}
    for node in (0, 1):
        for component, value in local.items():
            got = out.fields["DEPL"][0, out.numbering.index[(node, component)]]
            assert got == pytest.approx(value, abs=1e-13)
    # the third sensor is not turned
    assert out.fields["DEPL"][0, out.numbering.index[(2, "DZ")]] == pytest.approx(1.0)


def test_a_sensor_beyond_distance_max_holds_zero_displacement():
    session = FakeSession()
    mesh, model, numbering = _line(session)
    result = DynaTrans(
        numbering, np.array([0.0, 1.0]), np.array([1, 2]), {"DEPL": _displacements(mesh, numbering)}
    )
    far = np.vstack([SENSORS[:2], [[5.0, 5.0, 5.0]]])
    out = validated_run(session, "OBSERVATION", RESULTAT=result, MODELE_1=model,
                        MODELE_2=_sensors(session, far), NOM_CHAM="DEPL", NUME_ORDRE=2,
                        DISTANCE_MAX=0.1)  # fmt: skip
    assert out.numbering.n_dofs == 9
    assert out.fields["DEPL"][0, out.numbering.index[(2, "DX")]] == 0.0
    assert out.fields["DEPL"][0, out.numbering.index[(0, "DX")]] == pytest.approx(
        2 * _rigid(SENSORS[0])[0], rel=1e-12
    )
