"""ONDE_PLANE free fields and their loads on paraxial boundaries: the
incident, reflected and converted waves leave the free surface z = z1
without traction (P, SV, SH in 3D, P and S in 2D, oblique and vertical),
and a vertical P wave pushes a flat base with 2 rho c_p v."""

from __future__ import annotations

import numpy as np
import pytest

from asterlite.concepts.assembly import Material, MaterialField, Model
from asterlite.concepts.mesh import Mesh
from asterlite.fem.elements import ElementError
from asterlite.fem.plane_wave import PlaneWave, free_field, plane_wave_history, wave_set

E, NU, RHO = 3.0e10, 0.25, 2450.0
LAM = E * NU / ((1 + NU) * (1 - 2 * NU))
MU = E / (2 * (1 + NU))
CP, CS = np.sqrt((LAM + 2 * MU) / RHO), np.sqrt(MU / RHO)


def signal(t):
    return np.sin(40.0 * t) * np.exp(-(((t - 0.2) / 0.05) ** 2))


def _surface_traction(kind, dim, angle):
    if dim == 3:
        direction = np.array(
            [np.sin(angle) * np.cos(0.5), np.sin(angle) * np.sin(0.5), np.cos(angle)]
        )
        source, surface = np.array([0.0, 0.0, -200.0]), np.array([0.0, 0.0, 0.0])
    else:
        direction = np.array([np.sin(angle), np.cos(angle), 0.0])
        source, surface = np.array([0.0, -200.0]), np.array([0.0, 0.0])
    wave = PlaneWave(kind, direction, signal, source=source, reflection=surface)
    waves = wave_set(wave, dim, NU, CP, CS)
    points = np.random.default_rng(0).uniform(-50.0, 50.0, (8, dim))
    points[:, -1] = 0.0
    times = np.linspace(0.0, 0.6, 300)
    velocity, _, grad = free_field(waves, points, times, signal)
    strain = 0.5 * (grad + np.swapaxes(grad, -1, -2))
    trace = np.trace(strain, axis1=-2, axis2=-1)
    stress = 2 * MU * strain + LAM * trace[..., None, None] * np.eye(dim)
    return np.abs(stress[..., :, -1]).max() / (RHO * CP), np.abs(velocity).max(), len(waves)


@pytest.mark.parametrize(("dim", "kind"), [(3, "P"), (3, "SV"), (3, "SH"), (2, "P"), (2, "S")])
@pytest.mark.parametrize("angle", [0.0, 0.3])
def test_free_surface_is_traction_free(dim, kind, angle):
    traction, velocity, count = _surface_traction(kind, dim, angle)
    assert traction < 1e-12
    assert velocity > 1.0  # the surface moves (about twice the incident wave)
    converted = angle > 0.0 and kind != "SH"
    assert count == (3 if converted else 2)


def test_vertical_p_wave_load_on_a_flat_base():
    """Without reflection, a unit face at z = -100 with outward normal -z
    takes 2 rho c_p v(t - (z - z0)/c_p) per unit area: the dashpot's force on
    the free field plus its stress vector (code_aster's te0498 vector, which
    DYNA_VIBRA subtracts)."""
    coords = np.array([[0, 0, -100], [0, 1, -100], [1, 1, -100], [1, 0, -100]], dtype=float)
    mesh = Mesh(
        coords=coords,
        node_names=[f"N{i + 1}" for i in range(4)],
        cell_names=["F1"],
        cell_types=["QUAD4"],
        cell_nodes=[(0, 1, 2, 3)],
    )
    model = Model(mesh=mesh, cell_modelisation={0: "3D_ABSO"})
    field = MaterialField(
        mesh=mesh, cell_material={0: Material(behaviours={"ELAS": {"E": E, "NU": NU, "RHO": RHO}})}
    )
    wave = PlaneWave("P", np.array([0.0, 0.0, 1.0]), signal, source=np.array([0.0, 0.0, -200.0]))
    times = np.linspace(0.0, 0.6, 61)
    nodes, comps, values = plane_wave_history(model, field, [0], wave, times)
    total = values[:, [c == "DZ" for c in comps]].sum(axis=1)
    expected = 2.0 * RHO * CP * signal(times - 100.0 / CP) * ((times - 100.0 / CP) >= 0)
    assert np.allclose(total, expected, atol=1e-9 * RHO * CP)
    assert np.allclose(values[:, [c != "DZ" for c in comps]], 0.0, atol=1e-6)
    with pytest.raises(ElementError, match="TYPE_ONDE"):
        plane_wave_history(
            model, field, [0], PlaneWave("S", wave.direction, signal, wave.source), times
        )


def test_cells_of_one_material_share_one_free_field_evaluation(monkeypatch):
    """Two faces of one material without LONG_CARA (NaN) are one group: the
    free field is evaluated once for both (NaN never equals NaN, so a key
    holding it made a group of every cell), with the forces of each alone."""
    from asterlite.fem import plane_wave

    coords = np.array(
        [[0, 0, -100], [0, 1, -100], [1, 1, -100], [1, 0, -100], [2, 1, -100], [2, 0, -100]],
        dtype=float,
    )
    mesh = Mesh(
        coords=coords,
        node_names=[f"N{i + 1}" for i in range(6)],
        cell_names=["F1", "F2"],
        cell_types=["QUAD4", "QUAD4"],
        cell_nodes=[(0, 1, 2, 3), (3, 2, 4, 5)],
    )
    steel = Material(behaviours={"ELAS": {"E": E, "NU": NU, "RHO": RHO}})
    model = Model(mesh=mesh, cell_modelisation={0: "3D_ABSO", 1: "3D_ABSO"})
    field = MaterialField(mesh=mesh, cell_material={0: steel, 1: steel})
    wave = PlaneWave("P", np.array([0.3, 0.0, 1.0]), signal, source=np.array([0.0, 0.0, -200.0]))
    times = np.linspace(0.0, 0.6, 31)
    calls = []
    original = plane_wave.free_field
    monkeypatch.setattr(
        plane_wave, "free_field", lambda *a, **k: calls.append(1) or original(*a, **k)
    )
    nodes, comps, values = plane_wave_history(model, field, [0, 1], wave, times)
    assert len(calls) == 1
    for cell in (0, 1):
        alone = plane_wave_history(model, field, [cell], wave, times)[2]
        columns = slice(0, 12) if cell == 0 else slice(12, 24)
        np.testing.assert_allclose(values[:, columns], alone, rtol=1e-13, atol=1e-9)
