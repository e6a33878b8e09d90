"""DYNA_VIBRA TRAN/GENE EXCIT_RESU (code_aster's mdrecf): the DEPL field of
a tran_gene on the same basis is a generalized force history, one load per
generalized coordinate, times COEF_MULT, linear between the archived
instants and undefined outside them."""

import math

import numpy as np
import pytest

from asterlite.concepts.function import Function
from asterlite.concepts.modes import GeneralizedMatrix, GeneralizedNumbering, GeneralizedVector
from asterlite.concepts.transient import TranGene
from asterlite.errors import CommandError
from tests.test_dynamics_vibra import kws, one_mode, run_vibra, vector
from tests.validated import occurrence


def two_modes(k1=400.0, k2=2500.0):
    """A second generalized system on the basis of :func:`one_mode`'s
    numbering is not possible (one shape), so two modes get their own basis."""
    from asterlite.concepts.assembly import DofNumbering
    from asterlite.concepts.mesh import Mesh
    from asterlite.concepts.modes import ModeResult

    mesh = Mesh(
        coords=np.zeros((1, 3)),
        node_names=["NO1"],
        cell_names=[],
        cell_types=[],
        cell_nodes=[],
        node_groups={"NO1": np.array([0])},
    )
    numbering = DofNumbering(mesh=mesh, dofs=[(0, "DX"), (0, "DY"), (0, "DZ")])
    basis = ModeResult(
        numbering=numbering,
        shapes=np.array([[1.0, 0.0], [0.0, 1.0], [0.0, 0.0]]),
        frequencies=np.sqrt([k1, k2]) / (2 * math.pi),
        generalized_mass=np.ones(2),
        generalized_stiffness=np.array([k1, k2]),
    )
    basis.name = "MODES2"
    gnum = GeneralizedNumbering(basis=basis, storage="DIAG")
    m = GeneralizedMatrix(numbering=gnum, matrix=np.eye(2), kind="MASS")
    k = GeneralizedMatrix(numbering=gnum, matrix=np.diag([k1, k2]), kind="RIGI")
    return gnum, m, k


def history(basis, times, values):
    """A tran_gene whose DEPL holds ``values`` (n_instants, n_modes)."""
    values = np.asarray(values, dtype=float)
    return TranGene(
        basis=basis,
        times=np.asarray(times, dtype=float),
        order=np.arange(len(times)),
        depl=values,
        vite=np.zeros_like(values),
        acce=np.zeros_like(values),
    )


def resu(result, **extra):
    # the GENE transient's EXCIT_RESU, validated (COEF_MULT's default filled)
    return [occurrence("EXCIT_RESU", dict(RESULTAT=result, **extra), block="b_excit_tran_mod")]


@pytest.mark.parametrize("scheme", ["NEWMARK", "DIFF_CENTRE", "RUNGE_KUTTA_54", "DEVOGE"])
def test_excit_resu_equals_unit_loads_with_the_tabulated_functions(scheme):
    """The same run with EXCIT VECT_ASSE_GENE e_j + FONC_MULT (instants,
    COEF_MULT DEPL_j): identical generalized response."""
    gnum, m, k = two_modes()
    times = np.linspace(0.0, 0.6, 13)
    values = np.column_stack([np.sin(7.0 * times) * 30.0, np.where(times > 0.2, 50.0, -20.0)])
    force = history(gnum.basis, times, values)
    by_result = run_vibra(m, k, scheme, 2.0e-3, 0.5, EXCIT_RESU=resu(force, COEF_MULT=-1.5))
    loads = []
    for j in range(2):
        unit = np.zeros(2)
        unit[j] = 1.0
        fn = Function(abscissas=times, ordinates=-1.5 * values[:, j])
        loads.append(
            kws(
                "DYNA_VIBRA/EXCIT",
                VECT_ASSE_GENE=GeneralizedVector(numbering=gnum, values=unit, kind="FORC"),
                FONC_MULT=fn,
            )
        )
    by_functions = run_vibra(m, k, scheme, 2.0e-3, 0.5, EXCIT=loads)
    np.testing.assert_array_equal(by_result.times, by_functions.times)
    np.testing.assert_allclose(by_result.depl, by_functions.depl, rtol=0.0, atol=1e-15)
    assert np.max(np.abs(by_result.depl)) > 1e-3  # the loads do move the system


def test_step_force_from_a_result_gives_the_analytic_response():
    """DEPL = F0 on [0, 1] (COEF_MULT default 1): q = F0/k (1 - cos w t)."""
    k, f0 = 100.0, 3.0
    gnum, m, kk = one_mode(k)
    force = history(gnum.basis, [0.0, 1.0], [[f0], [f0]])
    result = run_vibra(m, kk, "NEWMARK", 1.0e-4, 1.0, EXCIT_RESU=resu(force))
    w = math.sqrt(k)
    expected = f0 / k * (1.0 - np.cos(w * result.times))
    np.testing.assert_allclose(result.depl[:, 0], expected, atol=2e-5 * f0 / k)


def test_a_first_run_drives_a_second_one_as_a_force_history():
    """Run 1: free oscillation u0 cos(w1 t) of k1. Run 2, stiffness k2 on
    the same basis, forced by run 1's DEPL times c:
    q'' + w2^2 q = c u0 cos(w1 t) -> q = c u0 (cos w1 t - cos w2 t) / (w2^2 - w1^2)."""
    k1, k2, u0, c = 400.0, 2500.0, 0.01, 5.0e3
    gnum, m, kk1 = one_mode(k1)
    kk2 = GeneralizedMatrix(numbering=gnum, matrix=np.array([[k2]]), kind="RIGI")
    first = run_vibra(m, kk1, "NEWMARK", 2.0e-5, 0.5, etat={"DEPL": vector(gnum, u0)})
    w1, w2 = math.sqrt(k1), math.sqrt(k2)
    assert first.depl[-1, 0] == pytest.approx(u0 * math.cos(w1 * 0.5), abs=1e-5 * u0)
    second = run_vibra(m, kk2, "NEWMARK", 1.0e-4, 0.5, EXCIT_RESU=resu(first, COEF_MULT=c))
    t = second.times
    expected = c * u0 * (np.cos(w1 * t) - np.cos(w2 * t)) / (w2**2 - w1**2)
    amplitude = 2 * c * u0 / (w2**2 - w1**2)
    np.testing.assert_allclose(second.depl[:, 0], expected, atol=2e-4 * amplitude)


def test_several_occurrences_add_up():
    gnum, m, k = two_modes()
    times = [0.0, 0.5]
    a = history(gnum.basis, times, [[10.0, 0.0], [10.0, 0.0]])
    b = history(gnum.basis, times, [[0.0, 20.0], [0.0, 20.0]])
    both = run_vibra(m, k, "NEWMARK", 1.0e-3, 0.3, EXCIT_RESU=resu(a) + resu(b, COEF_MULT=2.0))
    total = history(gnum.basis, times, [[10.0, 40.0], [10.0, 40.0]])
    single = run_vibra(m, k, "NEWMARK", 1.0e-3, 0.3, EXCIT_RESU=resu(total))
    np.testing.assert_allclose(both.depl, single.depl, rtol=1e-13, atol=1e-18)


def test_the_run_may_not_leave_the_instants_of_the_result():
    gnum, m, kk = one_mode(100.0)
    force = history(gnum.basis, [0.0, 0.5], [[1.0], [1.0]])
    with pytest.raises(CommandError, match="EXCLU"):
        run_vibra(m, kk, "NEWMARK", 1.0e-3, 0.8, EXCIT_RESU=resu(force))


def test_the_result_must_be_on_the_basis_of_the_matrices():
    gnum, m, kk = one_mode(100.0)
    other, _, _ = two_modes()
    force = history(other.basis, [0.0, 1.0], [[1.0, 0.0], [1.0, 0.0]])
    with pytest.raises(CommandError, match="same basis"):
        run_vibra(m, kk, "NEWMARK", 1.0e-3, 0.5, EXCIT_RESU=resu(force))
