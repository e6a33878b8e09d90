"""Seismic loads, static modes, Ritz bases, MACRO_ELAS_MULT, fields and
generalized / critical-load eigenproblems on spring-mass chains."""

from __future__ import annotations

import numpy as np
import pytest

from tests.test_fem_support import CO, chain_matrices, run

K, M = 1.0e4, 2.0
N = 6


@pytest.fixture
def two_supports():
    """Chain N1..N6 along x, N1 and N6 blocked in DX, DY/DZ blocked everywhere."""
    return chain_matrices(
        N,
        (K, K, K),
        M,
        ddl_impo=[{"GROUP_NO": "ENDS", "DX": 0.0}, {"TOUT": "OUI", "DY": 0.0, "DZ": 0.0}],
    )


def _dx(numbering):
    return numbering.dof_indices(range(N), "DX")


def test_constrained_modes_are_linear_between_two_supports(two_supports):
    session, model, k, m = two_supports
    modes = run(session, "MODE_STATIQUE", MATR_RIGI=k, MODE_STAT={"TOUT": "OUI", "AVEC_CMP": "DX"})
    assert modes.mode_labels == ["N1 DX", "N6 DX"]
    assert list(modes.parameters["TYPE_DEFO"]) == ["DEPL_IMPO"] * 2
    x = np.linspace(0.0, 1.0, N)
    dx = _dx(modes.numbering)
    np.testing.assert_allclose(modes.shapes[dx, 0], 1.0 - x, atol=1e-12)
    np.testing.assert_allclose(modes.shapes[dx, 1], x, atol=1e-12)
    # TOUT_CMP on N1 gives the three blocked components, in numbering order
    all_cmp = run(
        session, "MODE_STATIQUE", MATR_RIGI=k, MODE_STAT={"NOEUD": "N1", "TOUT_CMP": "OUI"}
    )
    assert all_cmp.mode_labels == ["N1 DX", "N1 DY", "N1 DZ"]
    sans = run(session, "MODE_STATIQUE", MATR_RIGI=k, MODE_STAT={"NOEUD": "N1", "SANS_CMP": "DX"})
    assert sans.mode_labels == ["N1 DY", "N1 DZ"]


def test_pseudo_mode_of_a_blocked_dof(two_supports):
    session, model, k, m = two_supports
    pseudo = run(
        session,
        "MODE_STATIQUE",
        MATR_RIGI=k,
        MATR_MASS=m,
        PSEUDO_MODE={"NOEUD": "N1", "AVEC_CMP": "DX"},
    )
    psi = run(session, "MODE_STATIQUE", MATR_RIGI=k, MODE_STAT={"NOEUD": "N1", "AVEC_CMP": "DX"})
    # K u = M ψ with the supports held: check the equilibrium on the free DOFs
    residual = k.matrix @ pseudo.shapes[:, 0] - m.matrix @ psi.shapes[:, 0]
    free = _dx(k.numbering)[1:-1]
    np.testing.assert_allclose(residual[free], 0.0, atol=1e-12)
    assert pseudo.parameters["TYPE_DEFO"][0] == "ACCE_IMPO"


def test_mono_support_load_is_minus_m_delta(two_supports):
    session, model, k, m = two_supports
    load = run(
        session, "CALC_CHAR_SEISME", MATR_MASS=m, DIRECTION=(2.0, 0.0, 0.0), MONO_APPUI="OUI"
    )
    delta = np.array([1.0 if c == "DX" else 0.0 for c in m.numbering.dof_components])
    np.testing.assert_allclose(load.values, -(m.matrix @ delta))
    # an oblique direction is normalised
    oblique = run(
        session, "CALC_CHAR_SEISME", MATR_MASS=m, DIRECTION=(1.0, 1.0, 0.0), MONO_APPUI="OUI"
    )
    dy = np.array([1.0 if c == "DY" else 0.0 for c in m.numbering.dof_components])
    np.testing.assert_allclose(oblique.values, -(m.matrix @ (delta + dy)) / np.sqrt(2.0))


def test_multi_support_load_uses_the_static_modes(two_supports):
    session, model, k, m = two_supports
    modes = run(session, "MODE_STATIQUE", MATR_RIGI=k, MODE_STAT={"TOUT": "OUI", "AVEC_CMP": "DX"})
    one = run(
        session,
        "CALC_CHAR_SEISME",
        MATR_MASS=m,
        DIRECTION=(1.0, 0.0, 0.0),
        MODE_STAT=modes,
        GROUP_NO="FIRST",
    )
    expected = -(m.matrix @ modes.shapes[:, 0])
    dx = _dx(m.numbering)
    expected[dx[[0, -1]]] = 0.0  # zeroed on the blocked DOFs
    np.testing.assert_allclose(one.values, expected)
    both = run(
        session,
        "CALC_CHAR_SEISME",
        MATR_MASS=m,
        DIRECTION=(1.0, 0.0, 0.0),
        MODE_STAT=modes,
        GROUP_NO="ENDS",
    )
    # both supports moving together: the rigid translation, i.e. the mono-support load
    mono = run(
        session, "CALC_CHAR_SEISME", MATR_MASS=m, DIRECTION=(1.0, 0.0, 0.0), MONO_APPUI="OUI"
    )
    mono_free = mono.values.copy()
    mono_free[dx[[0, -1]]] = 0.0
    np.testing.assert_allclose(both.values, mono_free, atol=1e-12)


def test_multi_support_without_the_static_mode_is_an_error(two_supports):
    from asterlite.errors import CommandError

    session, model, k, m = two_supports
    modes = run(session, "MODE_STATIQUE", MATR_RIGI=k, MODE_STAT={"NOEUD": "N1", "AVEC_CMP": "DX"})
    with pytest.raises(CommandError, match="N6 DX"):
        run(
            session,
            "CALC_CHAR_SEISME",
            MATR_MASS=m,
            DIRECTION=(1.0, 0, 0),
            MODE_STAT=modes,
            GROUP_NO="ENDS",
        )


def test_effective_masses_sum_to_the_free_mass():
    session, model, k, m = chain_matrices(
        N,
        (K, K, K),
        M,
        ddl_impo=[{"GROUP_NO": "FIRST", "DX": 0.0}, {"TOUT": "OUI", "DY": 0.0, "DZ": 0.0}],
    )
    modes = run(session, "CALC_MODES", MATR_RIGI=k, MATR_MASS=m, OPTION="TOUT")
    assert modes.n_modes == N - 1
    np.testing.assert_allclose(np.sum(modes.parameters["MASS_EFFE_DX"]), M * (N - 1), rtol=1e-10)
    np.testing.assert_allclose(np.sum(modes.parameters["MASS_EFFE_DY"]), 0.0, atol=1e-12)
    # invariant under renormalisation; participation factor scales as 1/factor
    before = modes.parameters["FACT_PARTICI_DX"].copy()
    normed = run(session, "NORM_MODE", MODE=modes, NORME="MASS_GENE")
    np.testing.assert_allclose(np.sum(normed.parameters["MASS_EFFE_DX"]), M * (N - 1), rtol=1e-10)
    factor = 1.0 / np.sqrt(modes.generalized_mass)
    np.testing.assert_allclose(normed.parameters["FACT_PARTICI_DX"], before / factor)


def test_ritz_basis_is_mass_orthonormal_and_keeps_the_span(two_supports):
    session, model, k, m = two_supports
    modes = run(session, "CALC_MODES", MATR_RIGI=k, MATR_MASS=m, CALC_FREQ={"NMAX_FREQ": 2})
    pseudo = run(session, "MODE_STATIQUE", MATR_RIGI=k, MATR_MASS=m, PSEUDO_MODE={"AXE": "X"})
    plain = run(session, "DEFI_BASE_MODALE", RITZ=[{"MODE_MECA": modes}, {"MODE_INTF": pseudo}])
    assert plain.n_modes == 3
    np.testing.assert_allclose(plain.shapes, np.hstack([modes.shapes, pseudo.shapes]))
    ritz = run(
        session,
        "DEFI_BASE_MODALE",
        RITZ=[{"MODE_MECA": modes}, {"MODE_INTF": pseudo}],
        ORTHO="OUI",
        MATRICE=m,
    )
    q = ritz.shapes
    np.testing.assert_allclose(q.T @ (m.matrix @ q), np.eye(3), atol=1e-10)
    # same span: the original vectors are reproduced from the new ones
    original = plain.shapes
    coords = q.T @ (m.matrix @ original)
    np.testing.assert_allclose(q @ coords, original, atol=1e-10)
    # first vector is the first mode, mass-normalised (Gram-Schmidt order)
    phi = modes.shapes[:, 0] / np.sqrt(modes.generalized_mass[0])
    np.testing.assert_allclose(q[:, 0], phi, atol=1e-12)
    # parameters follow by position, as code_aster copies them
    np.testing.assert_allclose(ritz.frequencies[:2], modes.frequencies)


def test_dependent_vectors_are_dropped(two_supports):
    session, model, k, m = two_supports
    modes = run(session, "CALC_MODES", MATR_RIGI=k, MATR_MASS=m, CALC_FREQ={"NMAX_FREQ": 2})
    ritz = run(
        session,
        "DEFI_BASE_MODALE",
        RITZ=[{"MODE_MECA": modes}, {"MODE_INTF": modes}],
        ORTHO="OUI",
        MATRICE=k,
    )
    assert ritz.n_modes == 2
    np.testing.assert_allclose(ritz.shapes.T @ (k.matrix @ ritz.shapes), np.eye(2), atol=1e-10)
    kept = run(session, "DEFI_BASE_MODALE", ORTHO_BASE={"BASE": ritz, "MATRICE": m})
    np.testing.assert_allclose(kept.shapes.T @ (m.matrix @ kept.shapes), np.eye(2), atol=1e-10)


def test_macro_elas_mult_matches_a_direct_solve():
    session, model, k, m = chain_matrices(
        N,
        (K, K, K),
        M,
        ddl_impo=[{"GROUP_NO": "FIRST", "DX": 0.0}, {"TOUT": "OUI", "DY": 0.0, "DZ": 0.0}],
    )
    blocked = run(
        session,
        "AFFE_CHAR_MECA",
        MODELE=model,
        DDL_IMPO=[{"GROUP_NO": "FIRST", "DX": 0.0}, {"TOUT": "OUI", "DY": 0.0, "DZ": 0.0}],
    )
    tip = run(session, "AFFE_CHAR_MECA", MODELE=model, FORCE_NODALE={"NOEUD": "N6", "FX": 3.0})
    result = run(
        session,
        "MACRO_ELAS_MULT",
        MODELE=model,
        CARA_ELEM=_cara(session),
        CHAR_MECA_GLOBAL=blocked,
        NUME_DDL=CO("NUM2"),
        CAS_CHARGE=[{"NOM_CAS": "TIP", "CHAR_MECA": tip}],
    )
    assert result.case_names == ["TIP"]
    numbering = session.bound["NUM2"]
    dx = numbering.dof_indices(range(N), "DX")
    np.testing.assert_allclose(result.fields[dx, 0], 3.0 * np.arange(N) / K, rtol=1e-12)
    # the same by CREA_CHAMP EXTR, by NOM_CAS
    field = run(
        session,
        "CREA_CHAMP",
        OPERATION="EXTR",
        TYPE_CHAM="NOEU_DEPL_R",
        RESULTAT=result,
        NOM_CHAM="DEPL",
        NOM_CAS="TIP",
    )
    np.testing.assert_allclose(field.values, result.fields[:, 0])


def _cara(session):
    # the last AFFE_CARA_ELEM built by chain_matrices is what its matrices used
    return session.last_cara


@pytest.fixture(autouse=True)
def _remember_cara(monkeypatch):
    """Keep the characteristics chain_matrices builds, for MACRO_ELAS_MULT."""
    import asterlite.commands.affe_cara_elem as module

    original = module.run

    def wrapped(ctx, kw):
        result = original(ctx, kw)
        ctx.session.last_cara = result
        return result

    monkeypatch.setattr(module, "run", wrapped)


def test_fields_assembled_combined_and_put_in_a_result(two_supports):
    session, model, k, m = two_supports
    modes = run(session, "MODE_STATIQUE", MATR_RIGI=k, MODE_STAT={"TOUT": "OUI", "AVEC_CMP": "DX"})
    first = run(
        session,
        "CREA_CHAMP",
        OPERATION="EXTR",
        TYPE_CHAM="NOEU_DEPL_R",
        RESULTAT=modes,
        NOM_CHAM="DEPL",
        NUME_ORDRE=1,
    )
    second = run(
        session,
        "CREA_CHAMP",
        OPERATION="EXTR",
        TYPE_CHAM="NOEU_DEPL_R",
        RESULTAT=modes,
        NOM_CHAM="DEPL",
        NOEUD_CMP=("N6", "DX"),
    )
    total = run(
        session,
        "CREA_CHAMP",
        OPERATION="COMB",
        TYPE_CHAM="NOEU_DEPL_R",
        COMB=[{"CHAM_GD": first, "COEF_R": 1.0}, {"CHAM_GD": second, "COEF_R": 1.0}],
    )
    dx = _dx(k.numbering)
    np.testing.assert_allclose(total.values[dx], 1.0)
    mesh = k.numbering.mesh
    summed = run(
        session,
        "CREA_CHAMP",
        OPERATION="ASSE",
        TYPE_CHAM="NOEU_DEPL_R",
        MAILLAGE=mesh,
        ASSE=[
            {"TOUT": "OUI", "CHAM_GD": first},
            {"TOUT": "OUI", "CHAM_GD": second, "CUMUL": "OUI", "COEF_R": 2.0},
        ],
    )
    x = np.linspace(0.0, 1.0, N)
    np.testing.assert_allclose(summed.values[summed.numbering.dof_indices(range(N), "DX")], 1.0 + x)
    result = run(
        session,
        "CREA_RESU",
        OPERATION="AFFE",
        TYPE_RESU="MULT_ELAS",
        AFFE=[
            {"NOM_CHAM": "DEPL", "CHAM_GD": first, "NOM_CAS": "A"},
            {"NOM_CHAM": "DEPL", "CHAM_GD": second, "NOM_CAS": "B"},
        ],
    )
    assert result.case_names == ["A", "B"] and result.n_cases == 2
    basis = run(session, "DEFI_BASE_MODALE", RITZ=[{"MODE_INTF": result}], NUME_REF=k.numbering)
    np.testing.assert_allclose(basis.shapes, modes.shapes)


def test_general_pencil_gives_minus_omega2(two_supports):
    session, model, k, m = two_supports
    dyn = run(session, "CALC_MODES", MATR_RIGI=k, MATR_MASS=m, OPTION="TOUT")
    crit = run(session, "CALC_MODES", TYPE_RESU="GENERAL", OPTION="TOUT", MATR_A=k, MATR_B=m)
    assert crit.aster_type == "mode_flamb"
    np.testing.assert_allclose(
        np.sort(crit.parameters["CHAR_CRIT"]), np.sort(-dyn.omega2), rtol=1e-10
    )


def test_ajuste_returns_every_mode_between_the_bounds(two_supports):
    session, model, k, m = two_supports
    dyn = run(session, "CALC_MODES", MATR_RIGI=k, MATR_MASS=m, OPTION="TOUT")
    f = dyn.frequencies
    lo, hi = 0.5 * (f[0] + f[1]), 0.5 * (f[2] + f[3])
    band = run(
        session,
        "CALC_MODES",
        MATR_RIGI=k,
        MATR_MASS=m,
        OPTION="AJUSTE",
        CALC_FREQ={"FREQ": (lo, hi)},
    )
    np.testing.assert_allclose(band.frequencies, f[1:3], rtol=1e-10)
    near = run(
        session,
        "CALC_MODES",
        MATR_RIGI=k,
        MATR_MASS=m,
        OPTION="PROCHE",
        CALC_FREQ={"FREQ": (f[2] * 1.01,)},
    )
    np.testing.assert_allclose(near.frequencies, f[2:3], rtol=1e-10)


def test_modes_of_projected_matrices_restore_the_physical_modes(two_supports):
    session, model, k, m = two_supports
    dyn = run(session, "CALC_MODES", MATR_RIGI=k, MATR_MASS=m, OPTION="TOUT")
    static = run(session, "MODE_STATIQUE", MATR_RIGI=k, MATR_MASS=m, PSEUDO_MODE={"AXE": "X"})
    ritz = run(
        session,
        "DEFI_BASE_MODALE",
        RITZ=[{"MODE_MECA": dyn, "NMAX_MODE": 2}, {"MODE_INTF": static}],
    )
    gene = run(session, "NUME_DDL_GENE", BASE=ritz)
    kg = run(session, "PROJ_MATR_BASE", BASE=ritz, NUME_DDL_GENE=gene, MATR_ASSE=k)
    mg = run(session, "PROJ_MATR_BASE", BASE=ritz, NUME_DDL_GENE=gene, MATR_ASSE=m)
    modes = run(session, "CALC_MODES", MATR_RIGI=kg, MATR_MASS=mg, OPTION="TOUT")
    assert modes.aster_type == "mode_gene" and modes.n_modes == 3
    # Rayleigh-Ritz: the two retained modes are exact, the third is an upper bound
    np.testing.assert_allclose(modes.frequencies[:2], dyn.frequencies[:2], rtol=1e-9)
    assert modes.frequencies[2] >= dyn.frequencies[2] * (1 - 1e-9)
    physical = modes.physical()
    residual = (
        k.matrix @ physical.shapes[:, :2] - (m.matrix @ physical.shapes[:, :2]) * dyn.omega2[:2]
    )
    free = _dx(k.numbering)[1:-1]  # blocked rows carry the reactions
    assert np.abs(residual[free]).max() < 1e-6 * np.abs(k.matrix @ physical.shapes[:, :2]).max()


def test_combined_static_shape_is_the_support_motion(two_supports):
    from asterlite.modal.seismic import combined_static_shape

    session, model, k, m = two_supports
    modes = run(session, "MODE_STATIQUE", MATR_RIGI=k, MODE_STAT={"TOUT": "OUI", "AVEC_CMP": "DX"})
    shape = combined_static_shape(modes, ["N1", "N6"], (3.0, 0.0, 0.0))
    np.testing.assert_allclose(shape[_dx(k.numbering)], 1.0)
