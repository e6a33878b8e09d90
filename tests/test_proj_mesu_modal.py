"""PROJ_MESU_MODAL: generalized coordinates identified from measurements.

Synthetic measurements are made from the modes themselves (interpolated on
a coarser measurement mesh whose nodes fall inside the calculation cells),
with known generalized coordinates that the identification must recover."""

from __future__ import annotations

import numpy as np
import pytest

from asterlite.concepts.assembly import DofNumbering, Model
from asterlite.concepts.harmonic import DynaHarmo, HarmGene
from asterlite.concepts.modes import GeneralizedModes, ModeResult
from asterlite.concepts.transient import DynaTrans, TranGene
from asterlite.errors import CommandError, UnsupportedError
from asterlite.modal import measured_projection as mp
from tests.test_fem_support import FakeSession, validated_run
from tests.test_proj_champ_lire_resu import line

CALC_X = np.linspace(0.0, 1.0, 11)
SENSOR_X = np.array([0.05, 0.2, 0.35, 0.5, 0.75, 0.95])  # inside the SEG2 cells
N_MODES = 3


def _model(mesh) -> Model:
    return Model(mesh=mesh, cell_modelisation={c: "POU_D_E" for c in range(mesh.n_cells)})


def _shape(x, k, component):
    """Mode k: linear in x (collocation on SEG2 is then exact), a different
    slope per mode and component."""
    return (k + 1.0) * x + (0.3 if component == "DY" else -0.2) * k * (1.0 - x)


def _basis(mesh) -> ModeResult:
    dofs = [(n, c) for n in range(mesh.n_nodes) for c in ("DX", "DY", "DZ")]
    x = mesh.coords[:, 0]
    shapes = np.zeros((len(dofs), N_MODES))
    for i, (n, c) in enumerate(dofs):
        if c != "DZ":
            shapes[i] = [_shape(x[n], k, c) for k in range(N_MODES)]
    # piecewise-linear shapes are seen exactly only if linear overall: add a
    # kink at x = 0.6, a node of the calculation mesh, for the last mode
    kink = np.array([max(0.0, x[n] - 0.6) for n, _ in dofs])
    shapes[:, -1] += 4.0 * kink * np.array([c != "DZ" for _, c in dofs])
    return ModeResult(
        numbering=DofNumbering(mesh=mesh, dofs=dofs),
        shapes=shapes,
        frequencies=np.array([1.0, 2.0, 3.0]),
        generalized_mass=np.ones(N_MODES),
        generalized_stiffness=np.ones(N_MODES),
    )


def _seen(basis, sensor_mesh) -> tuple[list, np.ndarray]:
    """The measurement DOFs (DX, DY, DRZ at each sensor) and the basis there."""
    dofs = [(n, c) for n in range(sensor_mesh.n_nodes) for c in ("DX", "DY", "DRZ")]
    calc = basis.numbering.mesh.coords[:, 0]
    out = np.zeros((len(dofs), N_MODES))
    for i, (n, c) in enumerate(dofs):
        if c == "DRZ":
            continue
        column = [basis.shapes[basis.numbering.index[(m, c)]] for m in range(len(calc))]
        out[i] = [
            np.interp(sensor_mesh.coords[n, 0], calc, np.array(column)[:, k])
            for k in range(N_MODES)
        ]
    return dofs, out


@pytest.fixture
def setup():
    calc_mesh, sensor_mesh = line(CALC_X), line(SENSOR_X)
    basis = _basis(calc_mesh)
    dofs, seen = _seen(basis, sensor_mesh)
    return calc_mesh, sensor_mesh, basis, DofNumbering(mesh=sensor_mesh, dofs=dofs), seen


def _call(calc_mesh, sensor_mesh, basis, measured, **extra):
    return validated_run(
        FakeSession(),
        "PROJ_MESU_MODAL",
        MODELE_CALCUL={"MODELE": _model(calc_mesh), "BASE": basis},
        MODELE_MESURE={"MODELE": _model(sensor_mesh), "MESURE": measured, **extra.pop("mesu", {})},
        **extra,
    )


def test_identified_modes_recover_known_coordinates(setup):
    calc_mesh, sensor_mesh, basis, numbering, seen = setup
    eta = np.array([[1.0, 0.0, 0.5], [-0.2, 2.0, 0.0], [0.3, 0.1, -1.5], [0.0, 0.0, 1.0]])
    measured = ModeResult(
        numbering=numbering,
        shapes=seen @ eta.T,
        frequencies=np.array([1.5, 2.5, 3.5, 4.5]),
        generalized_mass=np.array([2.0, 3.0, 4.0, 5.0]),
        generalized_stiffness=np.ones(4),
    )
    for resolution in ({"METHODE": "LU"}, {"METHODE": "SVD", "EPS": 1e-8}):
        result = _call(
            calc_mesh, sensor_mesh, basis, measured, RESOLUTION=resolution, NOM_PARA="MASS_GENE"
        )
        assert isinstance(result, GeneralizedModes)
        np.testing.assert_allclose(result.vectors.T, eta, atol=1e-12)
        np.testing.assert_allclose(result.frequencies, measured.frequencies)
        np.testing.assert_allclose(result.parameters["MASS_GENE"], [2.0, 3.0, 4.0, 5.0])
        # restored on the calculation mesh: the basis combined
        np.testing.assert_allclose(result.physical().shapes, basis.shapes @ eta.T, atol=1e-12)


def test_transient_measurement_gives_tran_gene_with_differences(setup):
    calc_mesh, sensor_mesh, basis, numbering, seen = setup
    times = np.linspace(0.0, 1.0, 21)
    eta = np.column_stack([np.sin(2 * times), times**2, np.cos(times)])
    measured = DynaTrans(
        numbering=numbering, times=times, order=np.arange(21), fields={"DEPL": eta @ seen.T}
    )
    result = _call(calc_mesh, sensor_mesh, basis, measured)
    assert isinstance(result, TranGene)
    np.testing.assert_allclose(result.depl, eta, atol=1e-12)
    forward = np.diff(eta, axis=0) / np.diff(times)[:, None]
    np.testing.assert_allclose(result.vite[:-1], forward, atol=1e-10)
    np.testing.assert_allclose(result.vite[-1], forward[-1], atol=1e-10)
    assert list(result.order) == list(range(21))

    # measured velocities: displacements integrated from zero
    measured.fields["VITE"] = measured.fields.pop("DEPL")
    result = _call(calc_mesh, sensor_mesh, basis, measured, mesu={"NOM_CHAM": "VITE"})
    np.testing.assert_allclose(result.vite, eta, atol=1e-12)
    np.testing.assert_allclose(result.depl[0], 0.0)
    np.testing.assert_allclose(
        result.depl[-1], (eta[1:] * np.diff(times)[:, None]).sum(axis=0), atol=1e-12
    )


def test_harmonic_measurement_gives_harm_gene(setup):
    calc_mesh, sensor_mesh, basis, numbering, seen = setup
    freqs = np.array([1.0, 2.0, 5.0])
    eta = np.array([[1 + 1j, 0.5, -2j], [0.1, 0.2j, 3.0], [2.0, -1.0, 1j]])
    measured = DynaHarmo(
        numbering=numbering,
        frequencies=freqs,
        order=np.arange(1, 4),
        fields={"DEPL": eta @ seen.T},
    )
    result = _call(calc_mesh, sensor_mesh, basis, measured, RESOLUTION={"METHODE": "SVD"})
    assert isinstance(result, HarmGene)
    np.testing.assert_allclose(result.fields["DEPL"], eta, atol=1e-12)
    iw = 2j * np.pi * freqs[:, None]
    np.testing.assert_allclose(result.fields["ACCE"], iw**2 * eta, atol=1e-9)


def test_refused_forms_are_named(setup):
    calc_mesh, sensor_mesh, basis, numbering, seen = setup
    measured = ModeResult(
        numbering=numbering,
        shapes=seen[:, :1],
        frequencies=np.ones(1),
        generalized_mass=np.ones(1),
        generalized_stiffness=np.ones(1),
    )
    with pytest.raises(UnsupportedError, match="EPSI_NOEU"):
        _call(calc_mesh, sensor_mesh, basis, measured, mesu={"NOM_CHAM": "EPSI_NOEU"})
    with pytest.raises(CommandError, match="no parameter AMOR_REDUIT"):
        _call(calc_mesh, sensor_mesh, basis, measured, NOM_PARA="AMOR_REDUIT")


def test_corr_manu_pairs_a_measurement_node_with_a_calculation_node(setup):
    calc_mesh, sensor_mesh, basis, numbering, seen = setup
    moved = seen.copy()
    for i, (node, component) in enumerate(numbering.dofs):
        if node == 0 and component != "DRZ":  # sensor N1 read at calculation node N4
            moved[i] = basis.shapes[basis.numbering.index[(3, component)]]
    eta = np.array([[0.5, -1.0, 2.0]])
    measured = ModeResult(
        numbering=numbering,
        shapes=moved @ eta.T,
        frequencies=np.ones(1),
        generalized_mass=np.ones(1),
        generalized_stiffness=np.ones(1),
    )
    result = _call(
        calc_mesh,
        sensor_mesh,
        basis,
        measured,
        CORR_MANU={"NOEU_CALCUL": "N4", "NOEU_MESURE": "N1"},
    )
    np.testing.assert_allclose(result.vectors.T, eta, atol=1e-12)
    plain = _call(calc_mesh, sensor_mesh, basis, measured)
    assert np.abs(plain.vectors.T - eta).max() > 1e-3


# -- the solver alone -----------------------------------------------------------------


def _random(rows, cols, seed=3):
    return np.random.default_rng(seed).normal(size=(rows, cols))


def test_least_squares_lu_and_svd_agree_with_lstsq():
    h, y = _random(8, 3), _random(4, 8, seed=5)
    expected = np.linalg.lstsq(h, y.T, rcond=None)[0].T
    for method in ("LU", "SVD"):
        got = mp.identify(h, y, mp.Resolution(method=method))
        np.testing.assert_allclose(got, expected, atol=1e-12)


def test_fewer_sensors_than_modes_minimum_norm():
    h, eta = _random(2, 4), _random(3, 4, seed=7)
    y = eta @ h.T
    got = mp.identify(h, y, mp.Resolution(method="SVD"))
    np.testing.assert_allclose(got, (np.linalg.pinv(h) @ y.T).T, atol=1e-12)
    np.testing.assert_allclose(got @ h.T, y, atol=1e-12)  # the data are matched
    with pytest.raises(mp.MeasuredProjectionError):  # singular normal equations
        mp.identify(h, y, mp.Resolution(method="LU", regul="NORM_MIN", weights=np.zeros(4)))


def test_regularisation_norm_min_and_tikhonov_relative():
    h, y = _random(6, 3), _random(3, 6, seed=11)
    alpha = np.array([0.5, 1.0, 2.0])
    got = mp.identify(h, y, mp.Resolution(regul="NORM_MIN", weights=alpha))
    expected = np.linalg.solve(h.T @ h + np.diag(alpha), h.T @ y.T).T
    np.testing.assert_allclose(got, expected, atol=1e-12)
    got = mp.identify(h, y, mp.Resolution(regul="TIK_RELA", weights=alpha))
    previous = np.linalg.solve(h.T @ h + np.diag(alpha), h.T @ y[0])
    np.testing.assert_allclose(got[0], previous, atol=1e-12)
    second = np.linalg.solve(h.T @ h + np.diag(alpha), h.T @ y[1] + alpha * previous)
    np.testing.assert_allclose(got[1], second, atol=1e-12)
    with pytest.raises(mp.MeasuredProjectionError, match="negative"):
        mp.identify(h, y, mp.Resolution(regul="NORM_MIN", weights=-alpha))


def test_svd_threshold_drops_small_singular_values():
    matrix = np.diag([4.0, 1.0, 1e-9])
    rhs = np.array([4.0, 2.0, 1.0])
    np.testing.assert_allclose(mp.svd_solve(matrix, rhs, 1e-6), [1.0, 2.0, 0.0])
    np.testing.assert_allclose(mp.svd_solve(matrix, rhs, 0.0), [1.0, 2.0, 1e9])


def test_identified_results_restore_on_the_calculation_model(setup):
    """REST_GENE_PHYS of the harm_gene and of the mode_gene: the basis
    combined with the identified coordinates."""
    calc_mesh, sensor_mesh, basis, numbering, seen = setup
    freqs = np.array([1.0, 2.0])
    eta = np.array([[1 + 1j, 0.5, -2j], [0.1, 0.2j, 3.0]])
    harmonic = DynaHarmo(
        numbering=numbering, frequencies=freqs, order=np.arange(1, 3), fields={"DEPL": eta @ seen.T}
    )
    restored = validated_run(
        FakeSession(),
        "REST_GENE_PHYS",
        RESU_GENE=_call(calc_mesh, sensor_mesh, basis, harmonic),
        TOUT_CHAM="OUI",
        TOUT_ORDRE="OUI",
    )
    np.testing.assert_allclose(restored.fields["DEPL"], eta @ basis.shapes.T, atol=1e-12)
    modes = ModeResult(
        numbering=numbering,
        shapes=seen @ eta.real.T,
        frequencies=freqs,
        generalized_mass=np.ones(2),
        generalized_stiffness=np.ones(2),
    )
    restored = validated_run(
        FakeSession(),
        "REST_GENE_PHYS",
        RESU_GENE=_call(calc_mesh, sensor_mesh, basis, modes),
        TOUT_ORDRE="OUI",
        NOM_CHAM="DEPL",
    )
    np.testing.assert_allclose(restored.shapes, basis.shapes @ eta.real.T, atol=1e-12)
    np.testing.assert_allclose(restored.frequencies, freqs)
