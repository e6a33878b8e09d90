"""Pieces the harmonic and modal decks of aster-corpus-dyna use around their
results: IMPR_GENE of a harm_gene (complex generalized fields by frequency),
TEST_RESU by NUME_MODE on a mode result, MODE_STATIQUE TOUT_CMP."""

from __future__ import annotations

import numpy as np
from asterlite.commands import impr_gene

from asterlite.concepts.harmonic import HarmGene
from tests.test_fem_support import FakeSession, chain_matrices, run
from tests.test_post_support import context, kw


def test_impr_gene_of_a_harm_gene(tmp_path):
    depl = np.array([[1.0 + 2.0j, -0.5j], [3.0, 4.0 - 1.0j]])
    result = HarmGene(
        basis=None,
        numbering=None,
        frequencies=np.array([10.0, 20.0]),
        order=np.array([1, 2]),
        fields={"DEPL": depl},
    )
    result.name = "HARM"
    impr_gene.run(
        context("IMPR_GENE", tmp_path),
        kw(UNITE=8, GENE=[{"RESU_GENE": result, "FREQ": (20.0,), "NUME_CMP_GENE": (2,)}]),
    )
    text = (tmp_path / "fort.8").read_text()
    assert "RESULTAT GENERALISE HARM (harm_gene)" in text
    assert "NUMERO D'ORDRE:        2 FREQUENCE: 2.00000E+01" in text
    assert "FREQUENCE: 1.00000E+01" not in text
    assert "       2    4.00000E+00 -1.00000E+00" in text
    assert "       1 " not in text.split("NUME_CMP")[-1]


def test_test_resu_by_mode_number_and_mode_stat_tout_cmp():
    session, model, k, m = chain_matrices(
        4, (1.0e4,) * 3, 2.0, ddl_impo=[{"GROUP_NO": "FIRST", "DX": 0.0, "DY": 0.0, "DZ": 0.0}]
    )
    stat = run(session, "MODE_STATIQUE", MATR_RIGI=k, MODE_STAT={"NOEUD": "N1", "TOUT_CMP": "OUI"})
    assert stat.mode_labels == ["N1 DX", "N1 DY", "N1 DZ"]
    modes = run(session, "CALC_MODES", MATR_RIGI=k, MATR_MASS=m, CALC_FREQ={"NMAX_FREQ": 3})
    modes.parameters["NUME_MODE"] = np.array([7, 8, 9])
    session = _Recording()
    run(
        session,
        "TEST_RESU",
        RESU={
            "RESULTAT": modes,
            "NUME_MODE": 8,
            "PARA": "FREQ",
            "VALE_CALC": float(modes.frequencies[1]),
        },
    )
    (record,) = session.tests
    assert record.ok and "mode 8" in record.label
    assert record.value == modes.frequencies[1]


class _Recording(FakeSession):
    def __init__(self):
        super().__init__()
        self.tests = []

    def record_test(self, record) -> None:
        self.tests.append(record)
