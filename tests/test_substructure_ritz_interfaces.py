"""DEFI_BASE_MODALE RITZ with INTERF_DYNA: the Ritz basis of fixed-interface
modes and MODE_STATIQUE's constraint modes remembers its interfaces
(code_aster's ritz99), so MACR_ELEM_DYNA joins it to the other half of a
beam; it spans what the CLASSIQUE Craig-Bampton basis spans, so the coupled
frequencies are the same."""

from __future__ import annotations

import numpy as np

from tests.test_substructure_beam import (
    LENGTH,
    N_HALF,
    beam_mesh,
    frequencies,
    run_case,
    substructured_deck,
)


def ritz_deck(nmax: int) -> str:
    deck = substructured_deck(nmax, clamped=False)
    for side, node in (("L", "B"), ("R", "A")):
        classical = (
            f"BA_{side} = DEFI_BASE_MODALE(CLASSIQUE=_F(INTERF_DYNA=IN_{side}, "
            f"MODE_MECA=MO_{side}, NMAX_MODE={nmax}))"
        )
        assert classical in deck
        deck = deck.replace(
            classical,
            f'MS_{side} = MODE_STATIQUE(MATR_RIGI=KA_{side}, MODE_STAT=_F(GROUP_NO="{node}",'
            f' AVEC_CMP=("DY", "DRZ")))\n'
            f"BA_{side} = DEFI_BASE_MODALE(RITZ=(_F(MODE_MECA=MO_{side}, NMAX_MODE={nmax}),"
            f" _F(MODE_INTF=MS_{side}, NMAX_MODE=2)), INTERF_DYNA=IN_{side},"
            f" NUME_REF=NU_{side})",
        )
    return deck


def test_ritz_basis_with_interfaces_couples_like_the_classical_one(tmp_path):
    mesh = beam_mesh(N_HALF, LENGTH / 2)
    classical = run_case(tmp_path / "classical", "cut", substructured_deck(3, False), mesh)
    ritz = run_case(tmp_path / "ritz", "cut", ritz_deck(3), mesh)
    expected, found = frequencies(classical, "RESGEN"), frequencies(ritz, "RESGEN")
    elastic = slice(2, 5)  # the first two are rigid-body modes (about 0)
    np.testing.assert_allclose(found[elastic], expected[elastic], rtol=1e-9)
    assert type(ritz.concepts.raw["BA_L"]).__name__ == "ReductionBasis"
