"""code_aster's numbering with Lagrange multipliers, as the object API shows
it (asterlite.fem.lagrange_layout): the dualised matrix toNumpy() gives
solves the constrained problem (a clamped cantilever's tip deflection under
a tip force, L³/3EI), its multipliers hold half the reaction over β, the
mode shapes' multiplier values make the dualised eigenproblem hold, and the
placement is code_aster's (λ1 before the node's DOFs, λ2 after)."""

from __future__ import annotations

import numpy as np
import pytest

from asterlite.fem.lagrange_layout import lagrange_coefficient, lagrange_layout
from asterlite.post.deck_api import mode_field
from tests.test_fem_structures import E, R, beam_model, line_mesh
from tests.test_fem_support import FakeSession, run

N_EL, LENGTH = 4, 2.0
COMPONENTS = ("DX", "DY", "DZ", "DRX", "DRY", "DRZ")


def _clamped_beam():
    session = FakeSession()
    model, field, cara = beam_model(session, line_mesh(N_EL, LENGTH))
    clamp = run(session, "AFFE_CHAR_MECA", MODELE=model,
                DDL_IMPO={"GROUP_NO": "A", "LIAISON": "ENCASTRE"})  # fmt: skip
    options = {"MODELE": model, "CHAM_MATER": field, "CARA_ELEM": cara, "CHARGE": clamp}
    rigi = run(session, "CALC_MATR_ELEM", OPTION="RIGI_MECA", **options)
    mass = run(session, "CALC_MATR_ELEM", OPTION="MASS_MECA", **options)
    numbering = run(session, "NUME_DDL", MATR_RIGI=rigi)
    k = run(session, "ASSE_MATRICE", MATR_ELEM=rigi, NUME_DDL=numbering)
    m = run(session, "ASSE_MATRICE", MATR_ELEM=mass, NUME_DDL=numbering)
    return session, k, m


def test_placement_and_labels_are_code_aster_ones():
    _, k, _ = _clamped_beam()
    numbering = k.numbering
    n = numbering.n_dofs
    assert numbering.getNumberOfDOFs() == n + 2 * 6
    # node A (first): six λ1, its six DOFs, six λ2; then the other nodes
    assert numbering.getLagrangeDOFs() == list(range(6)) + list(range(12, 18))
    assert numbering.getPhysicalDOFs() == list(range(6, 12)) + list(range(18, n + 12))
    for k_comp, comp in enumerate(COMPONENTS):
        assert numbering.getNodeAndComponentFromDOF(k_comp) == (0, f"LAGR:{comp}")
        assert numbering.getNodeAndComponentFromDOF(12 + k_comp) == (0, f"LAGR:{comp}")
        assert numbering.getComponentFromDOF(6 + k_comp) == comp
    # without a DOF: every DOF's label, and the two families of multipliers
    labels = numbering.getNodeAndComponentFromDOF()
    assert len(labels) == n + 12 and labels[3] == (0, "LAGR:DRX") and labels[9] == (0, "DRX")
    assert numbering.getDictOfLagrangeDOFs() == {1: list(range(6)), 2: list(range(12, 18))}


def test_dualised_stiffness_solves_the_clamped_cantilever():
    _, k, m = _clamped_beam()
    numbering = k.numbering
    full = k.toNumpy()
    layout = lagrange_layout(numbering)
    beta = lagrange_coefficient(k.matrix)
    physical = layout.physical
    np.testing.assert_array_equal(full[np.ix_(physical, physical)], k.matrix.toarray())
    one, two = layout.first[0], layout.second[0]
    assert full[one, one] == full[two, two] == -beta and full[one, two] == beta
    # the mass carries no load terms: zero multiplier rows and columns
    mass = m.toNumpy()
    assert not mass[layout.lagrange].any() and not mass[:, layout.lagrange].any()
    force = np.zeros(layout.size)
    force[physical[numbering.index[(N_EL, "DY")]]] = 1.0
    solution = np.linalg.solve(full, force)
    inertia = np.pi * R**4 / 4.0
    tip = solution[physical[numbering.index[(N_EL, "DY")]]]
    assert tip == pytest.approx(LENGTH**3 / (3.0 * E * inertia), rel=1e-10)
    # λ1 = λ2 = r / (2 β), r = (f - K u) at the clamp: the unit force (DY) ...
    reaction = -(k.matrix @ solution[physical])
    dy, drz = COMPONENTS.index("DY"), COMPONENTS.index("DRZ")
    for comp, magnitude in ((dy, 1.0), (drz, LENGTH)):
        lam1, lam2 = solution[layout.first[comp]], solution[layout.second[comp]]
        assert lam1 == pytest.approx(lam2, rel=1e-10)
        assert 2.0 * beta * lam1 == pytest.approx(reaction[comp], rel=1e-8)
        assert abs(reaction[comp]) == pytest.approx(magnitude, rel=1e-8)  # ... and the moment L


def test_mode_values_satisfy_the_dualised_eigenproblem():
    session, k, m = _clamped_beam()
    modes = run(session, "CALC_MODES", MATR_RIGI=k, MATR_MASS=m, CALC_FREQ={"NMAX_FREQ": 2})
    k_full, m_full = k.toNumpy(), m.toNumpy()
    for order in (1, 2):
        values = np.array(mode_field(modes, "DEPL", order).getValues())
        omega2 = (2.0 * np.pi * modes.frequencies[order - 1]) ** 2
        residual = k_full @ values - omega2 * (m_full @ values)
        assert np.linalg.norm(residual) <= 1e-7 * np.linalg.norm(k_full @ values)
        physical = k.numbering.getPhysicalDOFs()
        np.testing.assert_array_equal(values[physical], modes.shapes[:, order - 1])


def test_restituted_fields_carry_the_recombined_modes_multipliers():
    """REST_GENE_PHYS recombines the modes over all of code_aster's
    equations: a field's multipliers are those of the modes recombined."""
    from asterlite.concepts.transient import DynaTrans
    from asterlite.post.deck_api import transient_field

    session, k, m = _clamped_beam()
    modes = run(session, "CALC_MODES", MATR_RIGI=k, MATR_MASS=m, CALC_FREQ={"NMAX_FREQ": 2})
    q = np.array([[0.3, -1.2]])
    result = DynaTrans(k.numbering, np.array([0.0]), np.array([1]), {"DEPL": q @ modes.shapes.T})
    result.modal_source = (modes, {"DEPL": q})
    values = np.array(transient_field(result, "DEPL", 1).getValues())
    expected = sum(
        q[0, j] * np.array(mode_field(modes, "DEPL", j + 1).getValues()) for j in range(2)
    )
    np.testing.assert_allclose(values, expected, rtol=1e-12, atol=1e-12)
    # without a modal source the multipliers are not known: refused by name
    result.modal_source = None
    with pytest.raises(Exception, match="Lagrange multipliers"):
        transient_field(result, "DEPL", 1).getValues()


def test_harmonic_fields_carry_the_dualised_solution_multipliers():
    """DYNA_VIBRA HARM on the physical basis: getValues() is the solution of
    code_aster's dualised system (K - ω² M) x = F at each frequency,
    multipliers included (λ = r / 2β, r = F - (K - ω² M) u at the clamp);
    VITE scales all of it by iω, as comdlh does. Near f = 0 the clamp holds
    the tip force: r = -(K u) there is minus the support's reaction, r_DY = 1
    and r_DRZ = L (closed form)."""
    session, k, m = _clamped_beam()
    model = k.model
    force = run(session, "AFFE_CHAR_MECA", MODELE=model,
                FORCE_NODALE={"GROUP_NO": "B", "FY": 1.0})  # fmt: skip
    elementary = run(session, "CALC_VECT_ELEM", CHARGE=force, OPTION="CHAR_MECA")
    vector = run(session, "ASSE_VECTEUR", VECT_ELEM=elementary, NUME_DDL=k.numbering)
    frequencies = (1.0e-3, 37.0, 420.0)
    excitation = {"VECT_ASSE": vector, "COEF_MULT": 1.0, "PHAS_DEG": 0.0, "PUIS_PULS": 0}
    result = run(session, "DYNA_VIBRA", TYPE_CALCUL="HARM", BASE_CALCUL="PHYS",
                 MATR_RIGI=k, MATR_MASS=m, FREQ=frequencies, EXCIT=excitation)  # fmt: skip
    k_full, m_full = k.toNumpy(), m.toNumpy()
    layout = lagrange_layout(k.numbering)
    rhs = np.zeros(layout.size)
    rhs[layout.physical[k.numbering.index[(N_EL, "DY")]]] = 1.0
    beta = lagrange_coefficient(k.matrix)
    for order, frequency in enumerate(frequencies, start=1):
        omega = 2.0 * np.pi * frequency
        expected = np.linalg.solve(k_full - omega**2 * m_full, rhs)
        depl = np.array(result.getField("DEPL", order).getValues())
        np.testing.assert_allclose(depl, expected, rtol=1e-9, atol=1e-12 * np.abs(expected).max())
        vite = np.array(result.getField("VITE", order).getValues())
        np.testing.assert_allclose(vite, 1j * omega * depl, rtol=1e-12)
    static = np.array(result.getField("DEPL", 1).getValues()).real
    dy, drz = COMPONENTS.index("DY"), COMPONENTS.index("DRZ")
    assert 2.0 * beta * static[layout.first[dy]] == pytest.approx(1.0, rel=1e-6)
    assert 2.0 * beta * static[layout.second[drz]] == pytest.approx(LENGTH, rel=1e-6)


def test_restituted_harmonic_fields_carry_the_recombined_modes_multipliers():
    """REST_GENE_PHYS of a harm_gene (harm_75) recombines the modes over all
    of code_aster's equations: each field's multipliers are those of the modes
    times its own complex generalized coordinates."""
    from asterlite.concepts.harmonic import DynaHarmo
    from asterlite.post.deck_api import harmonic_field

    session, k, m = _clamped_beam()
    modes = run(session, "CALC_MODES", MATR_RIGI=k, MATR_MASS=m, CALC_FREQ={"NMAX_FREQ": 2})
    q = {"DEPL": np.array([[0.3 - 0.1j, -1.2 + 2.0j]]), "ACCE": np.array([[4.0j, 0.5]])}
    fields = {name: values @ modes.shapes.T for name, values in q.items()}
    result = DynaHarmo(k.numbering, np.array([3.0]), np.array([1]), fields)
    result.modal_source = (modes, q)
    for name, values in q.items():
        got = np.array(harmonic_field(result, name, 1).getValues())
        expected = sum(
            values[0, j] * np.array(mode_field(modes, "DEPL", j + 1).getValues()) for j in range(2)
        )
        np.testing.assert_allclose(got, expected, rtol=1e-12, atol=1e-12)
    result.modal_source = None
    with pytest.raises(Exception, match="Lagrange multipliers"):
        harmonic_field(result, "DEPL", 1).getValues()


def test_harmonic_multipliers_with_an_imposed_motion():
    """EXCIT CHARGE imposing DY = g at the clamp (DDL_IMPO): getValues() is
    the solution of the dualised system whose multiplier rows hold β g."""
    session = FakeSession()
    model, field, cara = beam_model(session, line_mesh(N_EL, LENGTH))
    imposed = {c: 0.0 for c in COMPONENTS} | {"DY": 0.01}
    clamp = run(session, "AFFE_CHAR_MECA", MODELE=model,
                DDL_IMPO={"GROUP_NO": "A", **imposed})  # fmt: skip
    options = {"MODELE": model, "CHAM_MATER": field, "CARA_ELEM": cara, "CHARGE": clamp}
    rigi = run(session, "CALC_MATR_ELEM", OPTION="RIGI_MECA", **options)
    mass = run(session, "CALC_MATR_ELEM", OPTION="MASS_MECA", **options)
    numbering = run(session, "NUME_DDL", MATR_RIGI=rigi)
    k = run(session, "ASSE_MATRICE", MATR_ELEM=rigi, NUME_DDL=numbering)
    m = run(session, "ASSE_MATRICE", MATR_ELEM=mass, NUME_DDL=numbering)
    excitation = {"CHARGE": clamp, "COEF_MULT": 1.0, "PHAS_DEG": 0.0, "PUIS_PULS": 0}
    result = run(session, "DYNA_VIBRA", TYPE_CALCUL="HARM", BASE_CALCUL="PHYS",
                 MATR_RIGI=k, MATR_MASS=m, FREQ=(55.0,), EXCIT=excitation)  # fmt: skip
    layout = lagrange_layout(numbering)
    beta = lagrange_coefficient(k.matrix)
    rhs = np.zeros(layout.size)
    dy = COMPONENTS.index("DY")
    rhs[[layout.first[dy], layout.second[dy]]] = beta * 0.01
    omega = 2.0 * np.pi * 55.0
    expected = np.linalg.solve(k.toNumpy() - omega**2 * m.toNumpy(), rhs)
    got = np.array(result.getField("DEPL", 1).getValues())
    assert got[layout.physical[numbering.index[(0, "DY")]]] == pytest.approx(0.01)
    np.testing.assert_allclose(got, expected, rtol=1e-9, atol=1e-12 * np.abs(expected).max())
