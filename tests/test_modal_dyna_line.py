"""DYNA_LINE (TRAN) on spring-mass chains, the frequency-band helpers, PROJ_BASE
with an existing NUME_DDL_GENE, mode_gene restitution and CREA_CHAMP EXTR of
element fields."""

from __future__ import annotations

import importlib
from types import SimpleNamespace

import numpy as np
import pytest

from asterlite.catalog import load_catalogue, validate
from asterlite.concepts.assembly import ElementField
from asterlite.concepts.modes import FieldOnElements
from asterlite.lang.values import CO, Unknown
from asterlite.modal import frequency_band
from asterlite.modal.static_modes import active_components
from asterlite.runtime.context import CommandContext
from tests.test_fem_support import FakeSession, chain_matrices, chain_mesh, run

K, M, N = 1.0e4, 2.0, 5


def validated_run(session, command, **kwargs):
    """Validate against the real catalogue (defaults filled), then run."""
    keywords = validate(load_catalogue(command), kwargs)
    module = importlib.import_module(f"asterlite.commands.{command.lower()}")
    return module.run(CommandContext(session=session, command=command), keywords)


@pytest.fixture
def clamped_chain():
    """N1 clamped in DX, DY/DZ blocked everywhere; a unit force on N5 DX."""
    session, model, k, m = chain_matrices(
        N,
        (K, K, K),
        M,
        ddl_impo=[{"GROUP_NO": "FIRST", "DX": 0.0}, {"TOUT": "OUI", "DY": 0.0, "DZ": 0.0}],
    )
    cara = k.characteristics
    blocked = run(
        session,
        "AFFE_CHAR_MECA",
        MODELE=model,
        DDL_IMPO=[{"GROUP_NO": "FIRST", "DX": 0.0}, {"TOUT": "OUI", "DY": 0.0, "DZ": 0.0}],
    )
    force = run(session, "AFFE_CHAR_MECA", MODELE=model, FORCE_NODALE={"NOEUD": "N5", "FX": 1.0})
    ramp = validated_run(
        session, "DEFI_FONCTION", NOM_PARA="INST", VALE=(0.0, 0.0, 0.01, 1.0, 1.0, 1.0)
    )
    return SimpleNamespace(
        session=session, model=model, k=k, m=m, cara=cara, blocked=blocked, force=force, ramp=ramp
    )


def _line(chain, base, **extra):
    return validated_run(
        chain.session,
        "DYNA_LINE",
        TYPE_CALCUL="TRAN",
        BASE_CALCUL=base,
        MODELE=chain.model,
        CARA_ELEM=chain.cara,
        CHARGE=chain.blocked,
        SCHEMA_TEMPS={"SCHEMA": "NEWMARK"},
        EXCIT={"CHARGE": chain.force, "FONC_MULT": chain.ramp},
        INCREMENT={"INST_INIT": 0.0, "INST_FIN": 0.05, "PAS": 1.0e-4},
        **extra,
    )


def test_frequency_band_helpers():
    assert frequency_band.band((9.3,)) == (0.0, 9.3)
    assert frequency_band.band((1.0, 20.0)) == (1.0, 20.0)
    assert frequency_band.band((), cutoff=5.0) == (0.0, 10.0)
    assert frequency_band.default_step(20.0) == pytest.approx(0.01)
    freqs = np.arange(8.0)
    spectrum = np.array([3.0, 1.0, 0.0, 0.0, 0.0, 0.0, 0.0, 1.0])
    # of the energy 3² + 1² = 10 of the non-negative half, 9 lies at f = 0
    assert frequency_band.cutoff_from_spectrum(freqs, spectrum, 90) == 0.0
    assert frequency_band.cutoff_from_spectrum(freqs, spectrum, 95) == 1.0


def test_active_components_skip_absent_and_blocked(clamped_chain):
    k = clamped_chain.k
    last, first = [N - 1], [0]
    assert active_components(k.matrix, k.numbering, last, ("DX", "DY", "DZ")) == ["DX"]
    assert active_components(k.matrix, k.numbering, first, ("DX", "DY", "DZ")) == []
    assert active_components(k.matrix, k.numbering, last, ("DRX",)) == []


def test_modal_line_with_every_mode_matches_the_physical_one(clamped_chain):
    physical = _line(clamped_chain, "PHYS")
    modal = _line(
        clamped_chain,
        "GENE",
        BANDE_ANALYSE=1.0e4,
        ENRI_STAT="NON",
        BASE_RESU=CO("BASE"),
        RESU_GENE=CO("GENE"),
    )
    bound = clamped_chain.session.bound
    assert bound["BASE"].n_modes == N - 1
    assert bound["GENE"].aster_type == "tran_gene"
    assert modal.aster_type == "dyna_trans"
    np.testing.assert_allclose(modal.times, physical.times)
    rows = modal.numbering.dof_indices(range(N), "DX")
    scale = np.abs(physical.fields["DEPL"]).max()
    np.testing.assert_allclose(
        modal.fields["DEPL"][:, rows], physical.fields["DEPL"][:, rows], atol=1e-6 * scale
    )


def test_rayleigh_damping_without_a_material_field_is_the_discrete_elements(clamped_chain):
    """Without CHAM_MATER, code_aster's macro asks CALC_MATR_ELEM for the
    damping of CARA_ELEM alone (its RIGI_MECA/MASS_MECA go with a material
    field only): here the springs carry none, so the response is undamped."""
    damped = _line(clamped_chain, "PHYS", AMORTISSEMENT={"TYPE_AMOR": "RAYLEIGH"})
    undamped = _line(clamped_chain, "PHYS")
    np.testing.assert_array_equal(damped.fields["DEPL"], undamped.fields["DEPL"])


def test_static_enrichment_spans_the_static_response(clamped_chain):
    chain = clamped_chain
    for ortho in ("NON", "OUI"):
        name = f"BASE_{ortho}"
        _line(chain, "GENE", BANDE_ANALYSE=5.0, ENRI_STAT="OUI", ORTHO=ortho, BASE_RESU=CO(name))
        basis = chain.session.bound[name]
        assert basis.n_modes == 2  # the first mode (about 3.5 Hz) and the static response
        numbering = chain.k.numbering
        load = np.zeros(numbering.n_dofs)
        load[numbering.dof_index("N5", "DX")] = 1.0
        static = np.linalg.lstsq(chain.k.matrix.toarray(), load, rcond=None)[0]
        free = numbering.dof_indices(range(1, N), "DX")
        target = np.zeros_like(static)
        target[free] = np.linalg.solve(chain.k.matrix.toarray()[np.ix_(free, free)], load[free])
        coef = np.linalg.lstsq(basis.shapes, target, rcond=None)[0]
        np.testing.assert_allclose(basis.shapes @ coef, target, atol=1e-10 * np.abs(target).max())
        if ortho == "OUI":  # re-diagonalised: (K, M)-orthogonal vectors
            gm = basis.shapes.T @ (chain.m.matrix @ basis.shapes)
            assert abs(gm[0, 1]) < 1e-10 * abs(gm[0, 0])


def test_proj_base_uses_an_existing_generalized_numbering(clamped_chain):
    chain = clamped_chain
    modes = run(
        chain.session,
        "CALC_MODES",
        MATR_RIGI=chain.k,
        MATR_MASS=chain.m,
        OPTION="PLUS_PETITE",
        CALC_FREQ={"NMAX_FREQ": 2},
    )
    numbering = run(chain.session, "NUME_DDL_GENE", BASE=modes, STOCKAGE="PLEIN")
    run(
        chain.session,
        "PROJ_BASE",
        BASE=modes,
        STOCKAGE="DIAG",
        NUME_DDL_GENE=numbering,
        MATR_ASSE_GENE={"MATRICE": CO("MGEN"), "MATR_ASSE": chain.m},
    )
    projected = chain.session.bound["MGEN"]
    assert projected.numbering is numbering  # PLEIN storage of the given numbering
    assert projected.matrix.shape == (2, 2)


def test_mode_gene_restored_on_its_basis_or_another(clamped_chain):
    chain = clamped_chain
    modes = run(
        chain.session,
        "CALC_MODES",
        MATR_RIGI=chain.k,
        MATR_MASS=chain.m,
        OPTION="PLUS_PETITE",
        CALC_FREQ={"NMAX_FREQ": 3},
    )
    numbering = run(chain.session, "NUME_DDL_GENE", BASE=modes, STOCKAGE="PLEIN")
    kg = run(
        chain.session, "PROJ_MATR_BASE", BASE=modes, NUME_DDL_GENE=numbering, MATR_ASSE=chain.k
    )
    mg = run(
        chain.session, "PROJ_MATR_BASE", BASE=modes, NUME_DDL_GENE=numbering, MATR_ASSE=chain.m
    )
    gene = run(chain.session, "CALC_MODES", MATR_RIGI=kg, MATR_MASS=mg, OPTION="TOUT")
    restored = gene.physical()
    np.testing.assert_allclose(restored.frequencies, modes.frequencies, rtol=1e-10)
    # same shapes up to scale
    for j in range(3):
        a, b = restored.shapes[:, j], modes.shapes[:, j]
        assert abs(a @ b) == pytest.approx(np.linalg.norm(a) * np.linalg.norm(b), rel=1e-10)
    doubled = modes.select([0, 1, 2])
    doubled.shapes = 2.0 * doubled.shapes
    np.testing.assert_allclose(gene.physical(basis=doubled).shapes, 2.0 * restored.shapes)


def test_crea_champ_extracts_element_fields():
    mesh = chain_mesh(3)
    numbering = SimpleNamespace(mesh=mesh)
    values = np.zeros((3, 2, 2, 1))
    values[:, 0, 0, 0] = [0.0, -5.0, 2.0]  # S1 at N1
    values[:, 1, 1, 0] = [1.0, 3.0, -4.0]  # S2 at N3
    result = SimpleNamespace(
        numbering=numbering,
        times=np.array([0.0, 0.5, 1.0]),
        order=np.array([0, 1, 2]),
        element_fields={"SIPO_ELNO": ElementField("SIPO_ELNO", np.array([0, 1]), ("SN",), values)},
    )
    module = importlib.import_module("asterlite.commands.crea_champ")
    session = FakeSession()

    def extr(**kw):
        keywords = validate(
            load_catalogue("CREA_CHAMP"),
            {
                "TYPE_CHAM": "ELNO_SIEF_R",
                "OPERATION": "EXTR",
                "NOM_CHAM": "SIPO_ELNO",
                "RESULTAT": Unknown,  # validated as any type, replaced by the stand-in
                **kw,
            },
        )
        keywords["RESULTAT"] = result
        return module.run(CommandContext(session=session, command="CREA_CHAMP"), keywords)

    field = extr(TYPE_MAXI="MAXI_ABS", TYPE_RESU="VALE")
    assert isinstance(field, FieldOnElements)
    assert field.node_value(0, 0, "SN") == -5.0
    assert field.node_value(1, 2, "SN") == -4.0
    assert extr(TYPE_MAXI="MAXI_ABS", TYPE_RESU="INST").node_value(1, 2, "SN") == 1.0
    assert extr(TYPE_MAXI="MAXI", TYPE_RESU="VALE").node_value(0, 0, "SN") == 2.0
    assert extr(TYPE_MAXI="MINI_ABS", TYPE_RESU="VALE_ABS").node_value(1, 2, "SN") == 1.0
    assert extr(INST=0.5).node_value(1, 2, "SN") == 3.0
    with pytest.raises(KeyError):
        field.node_value(0, 2, "SN")  # N3 is not a node of S1


def extr(**kw):
    return extr(**kw)
