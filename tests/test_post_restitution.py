import numpy as np
import pytest
from asterlite.commands import recu_fonction, recu_gene, rest_gene_phys, test_resu

from asterlite.concepts.lists import ListReal
from asterlite.errors import CommandError, UnsupportedError

from .test_post_support import context, kw, small_transient


def test_rest_gene_phys_interpolates_between_archived_states():
    result = small_transient()
    out = rest_gene_phys.run(
        context(), kw(RESU_GENE=result, NOM_CHAM=("DEPL",), INST=(0.25, 0.5), INTERPOL="LIN")
    )
    # NO2 DX = 2 q1 + 0.5 q2 with q linear-in-time interpolated between samples
    q2_at_025 = 0.5 * (0.2**2 + 0.3**2)
    assert out.fields["DEPL"][0, 2] == pytest.approx(2 * 0.25 + 0.5 * q2_at_025)
    assert out.fields["DEPL"][1, 2] == pytest.approx(2 * 0.5 + 0.5 * 0.25)
    assert out.order.tolist() == [1, 2]


def test_rest_gene_phys_without_interpolation_needs_archived_instants():
    result = small_transient()
    with pytest.raises(CommandError, match="no archived instant"):
        rest_gene_phys.run(context(), kw(RESU_GENE=result, NOM_CHAM=("DEPL",), INST=(0.25,)))
    out = rest_gene_phys.run(
        context(), kw(RESU_GENE=result, NOM_CHAM=("VITE",), INST=(0.3,), GROUP_NO=("NO2",))
    )
    assert out.numbering.dofs == [(1, "DX"), (1, "DY")]
    assert out.fields["VITE"][0].tolist() == pytest.approx([2 + 0.5 * 0.6, -0.6])


def test_rest_gene_phys_tout_ordre_keeps_orders_and_all_fields():
    result = small_transient()
    out = rest_gene_phys.run(context(), kw(RESU_GENE=result, TOUT_CHAM="OUI", NOM_CMP=("DY",)))
    assert set(out.fields) == {"DEPL", "VITE", "ACCE"}
    assert out.order.tolist() == list(range(11))
    assert out.fields["ACCE"].shape == (11, 2)


def test_rest_gene_phys_element_fields_need_calc_champ_on_the_modes():
    with pytest.raises(CommandError, match="SIPO_ELNO.*CALC_CHAMP"):
        rest_gene_phys.run(context(), kw(RESU_GENE=small_transient(), NOM_CHAM=("SIPO_ELNO",)))
    with pytest.raises(UnsupportedError, match="FORC_NODA"):
        rest_gene_phys.run(context(), kw(RESU_GENE=small_transient(), NOM_CHAM=("FORC_NODA",)))


def test_recu_fonction_from_physical_generalized_and_shock():
    result = small_transient()
    phys = rest_gene_phys.run(context(), kw(RESU_GENE=result, NOM_CHAM=("DEPL",)))
    f = recu_fonction.run(
        context(), kw(RESULTAT=phys, NOM_CHAM="DEPL", GROUP_NO="NO1", NOM_CMP="DY")
    )
    # NOM_RESU is the component on a physical result (code_aster's focrr0:
    # sdls113a reads INFO_FONCTION MAX of such a function on the column DX) ...
    assert f.NOM_PARA == "INST" and f.NOM_RESU == "DY"
    assert np.allclose(f.ordinates, result.times**2)
    gene = recu_fonction.run(context(), kw(RESU_GENE=result, NOM_CHAM="VITE", NUME_CMP_GENE=2))
    assert np.allclose(gene.ordinates, 2 * result.times)
    # ... and the field on a generalized one (rfrgen: sdnd120a's column DEPL)
    assert gene.NOM_RESU == "VITE"
    node = recu_fonction.run(
        context(),
        kw(
            RESU_GENE=result,
            NOM_CHAM="DEPL",
            GROUP_NO="NO2",
            NOM_CMP="DX",
            LIST_INST=ListReal([0.05]),
            INTERP_NUME="LIN",
        ),
    )
    assert node.ordinates[0] == pytest.approx(2 * 0.05 + 0.5 * 0.5 * 0.01)
    fn = recu_fonction.run(
        context(), kw(RESU_GENE=result, GROUP_NO_CHOC="NO2", PARA_X="INST", PARA_Y="FN")
    )
    assert np.allclose(fn.ordinates, np.sin(np.pi * result.times))
    with pytest.raises(CommandError, match="no quantity"):
        recu_fonction.run(context(), kw(RESU_GENE=result, INTITULE="CHOC1", PARA_Y="VT9"))


def test_recu_fonction_skips_the_orders_calc_champ_left_out():
    """code_aster reads an element field at the selected orders that hold it
    (rsutn2): orders CALC_CHAMP did not compute (NaN here) are left out."""
    from asterlite.concepts.assembly import ElementField

    phys = rest_gene_phys.run(context(), kw(RESU_GENE=small_transient(), NOM_CHAM=("DEPL",)))
    values = np.arange(11.0)[:, None, None, None] * np.ones((1, 1, 2, 1))
    values[:3] = np.nan  # CALC_CHAMP on the last 8 orders only
    phys.element_fields = {"SIEF_ELGA": ElementField("SIEF_ELGA", np.array([0]), ("N",), values)}
    f = recu_fonction.run(
        context(),
        kw(RESULTAT=phys, NOM_CHAM="SIEF_ELGA", NOM_CMP="N", GROUP_MA="BAR", POINT=2),
    )
    np.testing.assert_allclose(f.abscissas, phys.times[3:])
    np.testing.assert_allclose(f.ordinates, np.arange(3.0, 11.0))


def test_recu_gene_one_instant():
    vector = recu_gene.run(context(), kw(RESU_GENE=small_transient(), NOM_CHAM="DEPL", INST=0.5))
    assert vector.values.tolist() == pytest.approx([0.5, 0.25])


def test_test_resu_records_reference_and_calc_checks():
    result = small_transient()
    phys = rest_gene_phys.run(context(), kw(RESU_GENE=result, NOM_CHAM=("DEPL",)))
    phys.name = "DYN"
    ctx = context("TEST_RESU")
    occ = dict(RESULTAT=phys, NOM_CHAM="DEPL", GROUP_NO="NO2", NOM_CMP="DY", NUME_ORDRE=5)
    test_resu.run(
        ctx,
        kw(
            RESU=[
                {**occ, "VALE_REFE": -0.25, "VALE_CALC": -0.25, "REFERENCE": "ANALYTIQUE"},
                {**occ, "VALE_CALC": -0.2501},
                {**occ, "VALE_CALC": -0.26},
                {
                    **occ,
                    "INST": 0.5,
                    "NUME_ORDRE": None,
                    "TYPE_TEST": "SOMM",
                    "NOM_CMP": None,
                    "GROUP_NO": None,
                    "VALE_CALC": 0.5 + 0.25 + 1.125 - 0.25,
                },
            ],
            GENE=[{"RESU_GENE": result, "NUME_CMP_GENE": 1, "INST": 1.0, "VALE_CALC": 1.0}],
        ),
    )
    verdicts = [(r.ok, r.strict) for r in ctx.session.tests]
    assert verdicts == [(True, True), (True, False), (False, False), (True, True), (True, True)]
    assert "RESU[1] DYN DEPL NO2 DY ordre 5" in ctx.session.tests[0].label
    assert ctx.session.messages[2].startswith("NOOK")


def test_every_archived_state_is_selected_without_a_copy():
    from asterlite.post.restitution import select_instants

    times, order = np.linspace(0.0, 1.0, 50), np.arange(50)
    states = np.random.default_rng(1).normal(size=(50, 3))
    whole = select_instants(times, order)
    picked = whole.apply(states)
    assert np.shares_memory(picked, states) and not picked.flags.writeable
    assert np.shares_memory(whole.times, times) and not whole.times.flags.writeable
    np.testing.assert_array_equal(picked, states)
    some = select_instants(times, order, nume_ordre=[3, 7])
    chosen = some.apply(states)
    assert not np.shares_memory(chosen, states) and chosen.flags.writeable
    np.testing.assert_array_equal(chosen, states[[3, 7]])


def test_functions_of_one_transient_share_its_instants():
    result = small_transient()
    ctx = context()
    first = recu_fonction.run(ctx, kw(RESU_GENE=result, NOM_CHAM="DEPL", NUME_CMP_GENE=1))
    second = recu_fonction.run(ctx, kw(RESU_GENE=result, NOM_CHAM="VITE", NUME_CMP_GENE=1))
    assert np.shares_memory(first.abscissas, second.abscissas)
    values = first.getValues()
    assert type(values) is list and len(values) == 2 * first.abscissas.size
    assert values == first.abscissas.tolist() + first.ordinates.tolist()
