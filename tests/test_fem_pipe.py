"""Straight pipe elements TUYAU_3M / TUYAU_6M: rigid modes on a tilted line,
a cantilever's deflections and section forces against beam theory, the
ovalisation modes of a ring against the closed form, the first bending
frequency converging with the mesh, and the frames of the pipe lines."""

from __future__ import annotations

import numpy as np
import pytest
import scipy.linalg as sl

from asterlite.concepts.assembly import (
    DofNumbering,
    ElementCharacteristics,
    Material,
    MaterialField,
    Model,
)
from asterlite.concepts.mesh import Mesh
from asterlite.fem import pipe
from asterlite.fem.assemble import assemble_blocks, build_numbering_dofs
from asterlite.fem.elements import element_blocks
from asterlite.fem.pipe_elements import pipe_element_fields, pipe_frames

E, NU, RHO = 1.658e11, 0.3, 1.3404106e4
R, EP = 9.25e-2, 6.12e-3
KINDS = (("TUYAU_3M", 3), ("TUYAU_3M", 4), ("TUYAU_6M", 3))


def line_mesh(n_cells, n_nodes, length=10.0, direction=(1.0, 0.0, 0.0), bend=None):
    """A straight line of pipe cells (ends first in each cell), node 0 at the
    origin; ``bend`` moves the middle node of the first cell sideways."""
    axis = np.asarray(direction, float) / np.linalg.norm(direction)
    ends = [i * length / n_cells for i in range(n_cells + 1)]
    coords = [e * axis for e in ends]
    cells = []
    for i in range(n_cells):
        inner = []
        for k in range(1, n_nodes - 1):
            s = ends[i] + k * (ends[i + 1] - ends[i]) / (n_nodes - 1)
            inner.append(len(coords))
            coords.append(s * axis)
        cells.append((i, i + 1, *inner))
    coords = np.array(coords)
    if bend is not None:
        coords[cells[0][2]] += bend
    kind = f"SEG{n_nodes}"
    return Mesh(
        coords=coords,
        node_names=[f"N{k + 1}" for k in range(len(coords))],
        cell_names=[f"M{k + 1}" for k in range(n_cells)],
        cell_types=[kind] * n_cells,
        cell_nodes=cells,
    )


def pipe_model(mesh, modelisation, generators=(), nsec=16, ncou=3):
    cells = range(len(mesh.cell_names))
    model = Model(mesh=mesh, cell_modelisation=dict.fromkeys(cells, modelisation))
    section = {"SECTION": "CERCLE", "R": R, "EP": EP, "TUYAU_NSEC": nsec, "TUYAU_NCOU": ncou}
    characteristics = ElementCharacteristics(
        model=model,
        sections={c: dict(section) for c in cells},
        pipe_frames=pipe_frames(mesh, list(cells), generators),
    )
    material = Material(behaviours={"ELAS": {"E": E, "NU": NU, "RHO": RHO}})
    field = MaterialField(mesh=mesh, cell_material=dict.fromkeys(cells, material))
    return model, characteristics, field


def assembled(mesh, modelisation, matrix, **options):
    model, characteristics, field = pipe_model(mesh, modelisation, **options)
    numbering = DofNumbering(mesh=mesh, dofs=build_numbering_dofs(model.node_components()))
    blocks = element_blocks(model, characteristics, matrix, materials=field)
    return numbering, assemble_blocks(blocks, numbering).toarray(), (model, characteristics, field)


def section_area_inertia():
    ri = R - EP
    return np.pi * (R**2 - ri**2), np.pi / 4.0 * (R**4 - ri**4)


@pytest.mark.parametrize("modelisation,n_nodes", KINDS)
def test_rigid_motions_of_a_tilted_line_store_no_energy(modelisation, n_nodes):
    mesh = line_mesh(3, n_nodes, length=2.0, direction=(0.3, -0.5, 0.8))
    numbering, k, _ = assembled(mesh, modelisation, "K")
    x = mesh.coords[numbering.dof_nodes]
    comps = np.asarray(numbering.dof_components)
    for rigid in range(6):
        u = np.zeros(len(comps))
        if rigid < 3:
            u[comps == ("DX", "DY", "DZ")[rigid]] = 1.0
        else:
            omega = np.eye(3)[rigid - 3]
            velocity = np.cross(omega, x)
            for d, name in enumerate(("DX", "DY", "DZ")):
                u[comps == name] = velocity[comps == name, d]
            u[comps == ("DRX", "DRY", "DRZ")[rigid - 3]] = 1.0
        assert np.abs(k @ u).max() < 1e-6 * np.abs(k).max()


@pytest.mark.parametrize("modelisation,n_nodes", KINDS)
def test_cantilever_deflections_and_section_forces(modelisation, n_nodes):
    length, force = 10.0, 3.0e3
    mesh = line_mesh(8, n_nodes, length=length)
    # generating line -Z at the clamp: the local frame is the global one
    generators = [(0, np.array([0.0, 0.0, -1.0]), 1e-4, "RELATIF")]
    numbering, k, (model, characteristics, field) = assembled(
        mesh, modelisation, "K", generators=generators
    )
    comps = np.asarray(numbering.dof_components)
    clamped = (numbering.dof_nodes == 0) & np.isin(comps, ("DX", "DY", "DZ", "DRX", "DRY", "DRZ"))
    free = np.nonzero(~clamped)[0]
    area, inertia = section_area_inertia()
    tip = {c: numbering.dof_indices([8], c)[0] for c in ("DX", "DY")}
    for component, exact in (
        ("DX", force * length / (E * area)),
        ("DY", force * length**3 / (3.0 * E * inertia)),
    ):
        f = np.zeros(len(comps))
        f[tip[component]] = force
        u = np.zeros(len(comps))
        u[free] = np.linalg.solve(k[np.ix_(free, free)], f[free])
        # axial: exact; bending: Euler-Bernoulli plus shear and ovalisation (< 0.2 %)
        tolerance = 1e-9 if component == "DX" else 2e-3
        assert u[tip[component]] == pytest.approx(exact, rel=tolerance)
        efge = pipe_element_fields(
            model, characteristics, field, numbering, np.arange(8), u[None], ["EFGE_ELNO"]
        )["EFGE_ELNO"].values[0]
        if component == "DX":
            assert np.allclose(efge[:, :2, 0], force, rtol=1e-6)
        else:
            # shear force along the pipe; bending moment P (L - x) at the clamp
            assert np.allclose(efge[:, :2, 1], force, rtol=2e-2)
            assert efge[0, 0, 5] == pytest.approx(force * length, rel=2e-2)


@pytest.mark.parametrize("modelisation,modes", (("TUYAU_3M", 3), ("TUYAU_6M", 6)))
def test_ring_ovalisation_frequencies(modelisation, modes):
    """A uniform inextensional ovalisation w = cos(m phi), v = -sin(m phi)/m:
    the Rayleigh quotient is a thin ring's frequency,
    w^2 = E t^2 m^2 (m^2 - 1)^2 / (12 rho (1 - nu^2) a^4 (m^2 + 1))."""
    mesh = line_mesh(1, 3, length=0.5)
    numbering, k, _ = assembled(mesh, modelisation, "K")
    _, m, _ = assembled(mesh, modelisation, "M")
    comps = np.asarray(numbering.dof_components)
    a = R - EP / 2.0
    for mode in range(2, modes + 1):
        for phase in "IO":
            q = np.zeros(len(comps))
            q[comps == f"W{phase}{mode}"] = 1.0
            q[comps == f"V{phase}{mode}"] = (-1.0 if phase == "I" else 1.0) / mode
            omega2 = (q @ k @ q) / (q @ m @ q)
            exact = E * EP**2 * mode**2 * (mode**2 - 1) ** 2
            exact /= 12.0 * RHO * (1.0 - NU**2) * a**4 * (mode**2 + 1)
            assert omega2 == pytest.approx(exact, rel=1e-9)


def test_first_bending_frequency_converges_to_the_beam_one():
    length = 10.0
    area, inertia = section_area_inertia()
    euler = 1.8751040687**2 / (2 * np.pi) * np.sqrt(E * inertia / (RHO * area * length**4))
    frequencies = []
    for n_cells in (2, 4, 8, 16):
        mesh = line_mesh(n_cells, 3, length=length)
        numbering, k, _ = assembled(mesh, "TUYAU_3M", "K")
        _, m, _ = assembled(mesh, "TUYAU_3M", "M")
        comps = np.asarray(numbering.dof_components)
        clamped = (numbering.dof_nodes == 0) & np.isin(
            comps, ("DX", "DY", "DZ", "DRX", "DRY", "DRZ")
        )
        free = np.nonzero(~clamped)[0]
        w = sl.eigh(
            k[np.ix_(free, free)], m[np.ix_(free, free)], eigvals_only=True, subset_by_index=[0, 0]
        )
        frequencies.append(np.sqrt(w[0]) / (2 * np.pi))
    errors = np.abs(np.array(frequencies[:-1]) / frequencies[-1] - 1.0)
    assert errors[0] > 4 * errors[1] > 16 * errors[2]
    # shear and rotary inertia lower it by about 0.1 % at L/R = 108
    assert frequencies[-1] == pytest.approx(euler, rel=2e-3)


def arc_mesh(n_cells, radius=1.0, angle=np.pi / 2.0, n_nodes=3):
    """A quarter torus' centre line in the XY plane, then a straight leg."""
    ends = np.linspace(0.0, angle, n_cells + 1)
    point = lambda a: radius * np.array([np.sin(a), 1.0 - np.cos(a), 0.0])  # noqa: E731
    coords = [point(a) for a in ends]
    cells = []
    for i in range(n_cells):
        inner = []
        for k in range(1, n_nodes - 1):
            inner.append(len(coords))
            coords.append(point(ends[i] + k * (ends[i + 1] - ends[i]) / (n_nodes - 1)))
        cells.append((i, i + 1, *inner))
    last, start = coords[n_cells], len(coords)
    coords.append(last + np.array([0.0, 1.0, 0.0]))
    for k in range(1, n_nodes - 1):
        coords.append(last + np.array([0.0, k / (n_nodes - 1), 0.0]))
    cells.append((n_cells, start, *range(start + 1, start + n_nodes - 1)))
    return Mesh(
        coords=np.array(coords),
        node_names=[f"N{k + 1}" for k in range(len(coords))],
        cell_names=[f"M{k + 1}" for k in range(len(cells))],
        cell_types=[f"SEG{n_nodes}"] * len(cells),
        cell_nodes=cells,
    )


@pytest.mark.parametrize("modelisation,n_nodes", KINDS)
def test_rigid_motions_of_an_elbow_store_no_energy(modelisation, n_nodes):
    mesh = arc_mesh(4, n_nodes=n_nodes)
    generators = [(0, np.array([0.0, 0.3, 1.0]), 1e-4, "RELATIF")]
    numbering, k, (_, characteristics, _) = assembled(
        mesh, modelisation, "K", generators=generators
    )
    elbows = [c for c in characteristics.pipe_frames.values() if isinstance(c.geometry, pipe.Elbow)]
    assert len(elbows) == 4
    assert elbows[0].geometry.radius == pytest.approx(1.0)
    assert elbows[0].geometry.angle == pytest.approx(np.pi / 8.0)
    x = mesh.coords[numbering.dof_nodes]
    comps = np.asarray(numbering.dof_components)
    for rigid in range(6):
        u = np.zeros(len(comps))
        if rigid < 3:
            u[comps == ("DX", "DY", "DZ")[rigid]] = 1.0
        else:
            velocity = np.cross(np.eye(3)[rigid - 3], x)
            for d, name in enumerate(("DX", "DY", "DZ")):
                u[comps == name] = velocity[comps == name, d]
            u[comps == ("DRX", "DRY", "DRZ")[rigid - 3]] = 1.0
        # the arc's interpolation holds a rigid rotation only to O(theta^n)
        tolerance = 1e-9 if rigid < 3 else 1e-5
        assert np.abs(k @ u).max() < tolerance * np.abs(k).max()


def test_frames_follow_the_generating_line_and_refuse_bad_arcs():
    mesh = line_mesh(3, 3, length=3.0)
    cells = [0, 1, 2]
    frames = pipe_frames(mesh, cells, [(0, np.array([0.0, 0.0, -1.0]), 1e-4, "RELATIF")])
    # z opposite the generating line, y = x ^ generating line
    for cell in frames.values():
        assert np.allclose(cell.frames, np.eye(3))
    # given at the last node: the same line walked backwards
    frames = pipe_frames(mesh, cells, [(3, np.array([0.0, 1.0, 1.0]), 1e-4, "RELATIF")])
    expected = np.array([[1, 0, 0], [0, -1, 1], [0, -1, -1]]) / np.array([[1], [2**0.5], [2**0.5]])
    for cell in frames.values():
        assert np.allclose(cell.frames, expected)
    # a SEG4 whose inner nodes are not on one arc
    bent = line_mesh(3, 4, length=3.0, bend=(0.0, 0.05, 0.0))
    with pytest.raises(pipe.PipeError, match="not an arc"):
        pipe_frames(bent, cells)
    with pytest.raises(pipe.PipeError, match="not an end"):
        pipe_frames(mesh, cells, [(4, np.array([0.0, 0.0, 1.0]), 1e-4, "RELATIF")])


def test_commands_orient_pipes_and_block_their_fourier_dofs():
    from asterlite.errors import CommandError
    from tests.test_fem_support import FakeSession, run

    mesh = line_mesh(2, 3, length=2.0)
    mesh.node_groups.update({"A": np.array([0]), "B": np.array([2])})
    mesh.cell_groups["ALL"] = np.arange(2)
    session = FakeSession()
    model = run(
        session,
        "AFFE_MODELE",
        MAILLAGE=mesh,
        AFFE={"TOUT": "OUI", "PHENOMENE": "MECANIQUE", "MODELISATION": "TUYAU_6M"},
    )
    cara = run(
        session,
        "AFFE_CARA_ELEM",
        MODELE=model,
        POUTRE={"GROUP_MA": "ALL", "SECTION": "CERCLE", "CARA": ("R", "EP"), "VALE": (R, EP)},
        ORIENTATION={"GROUP_NO": "B", "CARA": "GENE_TUYAU", "VALE": (0.0, 0.0, -1.0)},
    )
    assert cara.sections[0]["TUYAU_NSEC"] == 16 and cara.sections[0]["TUYAU_NCOU"] == 3
    assert np.allclose(cara.pipe_frames[0].frames, np.eye(3))
    load = run(
        session,
        "AFFE_CHAR_MECA",
        MODELE=model,
        DDL_IMPO=[
            {"GROUP_NO": "A", "BLOCAGE": ("DEPLACEMENT", "TUYAU_FOURIER")},
            {"GROUP_NO": "B", "WO6": 0.5},
        ],
    )
    fixed = {(t[0][0], t[0][1]): r.rhs for r in load.relations for t in [r.terms]}
    assert len(fixed) == 3 + 33 + 1
    assert fixed[(0, "WO1")] == 0.0 and fixed[(0, "UI6")] == 0.0 and (0, "DRX") not in fixed
    assert fixed[(2, "WO6")] == 0.5
    with pytest.raises(CommandError, match="no WO6 DOF"):
        model3 = run(
            session,
            "AFFE_MODELE",
            MAILLAGE=mesh,
            AFFE={"TOUT": "OUI", "PHENOMENE": "MECANIQUE", "MODELISATION": "TUYAU_3M"},
        )
        run(session, "AFFE_CHAR_MECA", MODELE=model3, DDL_IMPO={"GROUP_NO": "B", "WO6": 0.0})


def test_mass_and_centre_of_a_straight_pipe_and_an_elbow():
    """MASS_INER of pipes: rho A L, the centre of a straight pipe at its
    middle, an elbow's on the bisector at Rc sin(a)/a (1 + (Re^2 + Ri^2) /
    (4 Rc^2)) from the bend centre (a torus' centroid, a = theta / 2)."""
    from asterlite.fem.mass_properties import mass_properties

    area, _ = section_area_inertia()
    mesh = line_mesh(4, 3, length=2.0, direction=(0.0, 1.0, 1.0))
    values = mass_properties(*pipe_model(mesh, "TUYAU_3M"))
    assert values["MASSE"] == pytest.approx(RHO * area * 2.0, rel=1e-12)
    middle = 2.0 / np.sqrt(2.0) / 2.0
    assert [values[f"CDG_{c}"] for c in "XYZ"] == pytest.approx([0.0, middle, middle])
    for n_nodes in (3, 4):
        mesh = arc_mesh(1, radius=1.0, angle=np.pi / 2.0, n_nodes=n_nodes)
        generators = [(0, np.array([0.0, 0.0, 1.0]), 1e-4, "RELATIF")]
        model, characteristics, field = pipe_model(mesh, "TUYAU_3M", generators)
        values = mass_properties(model, characteristics, field, cells=[0])
        assert values["MASSE"] == pytest.approx(RHO * area * np.pi / 2.0, rel=1e-12)
        half = np.pi / 4.0
        distance = np.sin(half) / half * (1.0 + (R**2 + (R - EP) ** 2) / 4.0)
        # bend centre (0, 1, 0), bisector towards (sin 45, -cos 45)
        expected = [distance * np.sin(half), 1.0 - distance * np.cos(half), 0.0]
        assert [values[f"CDG_{c}"] for c in "XYZ"] == pytest.approx(expected, rel=1e-12)


def test_gravity_on_pipes_is_the_weight_on_the_translations():
    """PESANTEUR on pipes (te0583): the nodes' DX, DY, DZ share rho g V, no
    moment; on a straight cell the shares are rho g A L (1/6, 1/6, 2/3)."""
    from asterlite.fem.loads import gravity_terms

    area, _ = section_area_inertia()
    for mesh, length in ((line_mesh(1, 3, length=2.0), 2.0), (arc_mesh(2), np.pi / 2.0 + 1.0)):
        generators = [(0, np.array([0.0, 0.0, 1.0]), 1e-4, "RELATIF")]
        model, characteristics, field = pipe_model(mesh, "TUYAU_3M", generators)
        terms = gravity_terms(model, characteristics, 9.81, (0.0, 0.0, -1.0), materials=field)
        assert {c for _, c, _ in terms} == {"DX", "DY", "DZ"}
        total = sum(v for _, c, v in terms if c == "DZ")
        assert total == pytest.approx(-9.81 * RHO * area * length, rel=1e-12)
    model, characteristics, field = pipe_model(line_mesh(1, 3, length=2.0), "TUYAU_3M")
    terms = gravity_terms(model, characteristics, 9.81, (0.0, 0.0, -1.0), materials=field)
    shares = {n: v for n, c, v in terms if c == "DZ"}
    weight = -9.81 * RHO * area * 2.0
    assert [shares[n] for n in (0, 1, 2)] == pytest.approx([weight / 6, weight / 6, 2 * weight / 3])


def test_internal_pressure_swells_a_straight_pipe_as_a_thin_tube():
    """FORCE_TUYAU on a straight pipe, free to stretch: hoop stress
    p Ri / t, so WO = p Ri a / (E t) (a the mean radius) and the length
    shrinks by nu p Ri / (E t) L."""
    from asterlite.fem.pipe_elements import pipe_pressure_terms

    length, pressure = 2.0, 1.0e6
    mesh = line_mesh(4, 3, length=length)
    numbering, k, (model, characteristics, _) = assembled(mesh, "TUYAU_3M", "K")
    f = np.zeros(numbering.n_dofs)
    for node, component, value in pipe_pressure_terms(
        model, characteristics, np.arange(4), pressure
    ):
        f[numbering.dof_indices([node], component)[0]] += value
    inner, mean = R - EP, R - EP / 2.0
    assert f.sum() == pytest.approx(pressure * 2.0 * np.pi * inner * length, rel=1e-12)
    comps = np.asarray(numbering.dof_components)
    # the first node holds the rigid motions, the swelling is free
    fixed = (numbering.dof_nodes == 0) & np.isin(comps, ("DX", "DY", "DZ", "DRX", "DRY", "DRZ"))
    free = np.nonzero(~fixed)[0]
    u = np.zeros(numbering.n_dofs)
    u[free] = np.linalg.solve(k[np.ix_(free, free)], f[free])
    hoop = pressure * inner / EP / E
    assert u[comps == "WO"] == pytest.approx(hoop * mean, rel=1e-9)
    tip = numbering.dof_indices([4], "DX")[0]
    assert u[tip] == pytest.approx(-NU * hoop * length, rel=1e-9)


def test_internal_pressure_on_an_elbow_has_the_resultant_of_its_missing_caps():
    """The pressure on a 90-degree elbow's wall balances the caps it lacks:
    its resultant is p Ai (t1 - t2), t1 and t2 the end tangents."""
    from asterlite.fem.pipe_elements import pipe_pressure_terms

    mesh = arc_mesh(8)
    generators = [(0, np.array([0.0, 0.0, 1.0]), 1e-4, "RELATIF")]
    model, characteristics, _ = pipe_model(mesh, "TUYAU_3M", generators)
    terms = pipe_pressure_terms(model, characteristics, np.arange(8), 1.0)
    resultant = np.zeros(3)
    for _, component, value in terms:
        if component in ("DX", "DY", "DZ"):
            resultant["XYZ".index(component[1])] += value
    expected = np.pi * (R - EP) ** 2 * np.array([1.0, -1.0, 0.0])
    assert resultant == pytest.approx(expected, rel=1e-6, abs=1e-12)
