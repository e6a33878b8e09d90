"""Output and post-processing of substructured models (issue 19):
IMPR_MACR_ELEM's universal file, the Fortran number layout it uses, and
the corpus decks of the chain."""

from __future__ import annotations

from pathlib import Path

import numpy as np
import pytest

from asterlite import api
from asterlite.io.ideas_macro import fortran_exponent
from tests.test_substructure_beam import N_HALF, beam_mesh, substructured_deck

CORPUS = Path(__file__).resolve().parents[2] / "shared" / "aster-corpus-wider"


def test_fortran_exponent_layouts():
    assert fortran_exponent(1.0, 13, 5, exp_digits=3) == " 1.00000E+000"
    assert fortran_exponent(0.0, 13, 5, exp_digits=3) == " 0.00000E+000"
    assert fortran_exponent(-0.000123456, 13, 5, exp_digits=3) == "-1.23456E-004"
    assert fortran_exponent(9.9999999, 13, 5, exp_digits=3) == " 1.00000E+001"
    assert fortran_exponent(-123.456, 20, 12, letter="D") == " -1.234560000000D+02"


def datasets(text: str) -> list[tuple[str, list[str]]]:
    """(number, lines) of each universal-file dataset between -1 markers."""
    out, current, inside = [], [], False
    for line in text.splitlines():
        if line.strip() == "-1":
            if inside and current:
                out.append((current[0].split()[0], current[1:]))
            current, inside = [], not inside
            continue
        if inside:
            current.append(line)
    return out


def test_impr_macr_elem_writes_the_basis_and_the_generalized_matrices(tmp_path):
    deck = substructured_deck(3, clamped=True).replace(
        "FIN()", 'IMPR_MACR_ELEM(MACR_ELEM_DYNA=ME_L, FORMAT="IDEAS", UNITE=30)\nFIN()'
    )
    (tmp_path / "cut.comm").write_text(deck)
    (tmp_path / "cut.mail").write_text(beam_mesh(N_HALF, 1.0))
    result = api.run(tmp_path / "cut.comm", tmp_path / "out")
    assert result.status == "DONE", result.message
    macro = result.concepts.raw["ME_L"]
    found = datasets((tmp_path / "out" / "fort.30").read_text())
    names = [lines[1].strip() for number, lines in found if number == "481"]
    assert names[0] == "Junc" and names.count("Phi_a") == 3
    assert names[-5:] == ["Mgen_a", "Kgen_a", "Mbar_a", "Kbar_a", "Lmat_a"]
    junction = next(lines for number, lines in found if number == "757")
    assert junction[1] == "DDL JONCTION"
    assert junction[2].split()[2:] == ["0", "1", "0", "0", "0", "1"]  # DY and DRZ of B
    shapes = [lines for number, lines in found if number == "55"]
    assert len(shapes) == 5  # 3 fixed-interface modes, 2 constraint modes
    matrices = [lines for number, lines in found if number == "252"]
    stiffness = np.array(
        [float(v.replace("D", "E")) for line in matrices[1][2:] for v in line.split()]
    ).reshape(3, 3, order="F")
    np.testing.assert_allclose(stiffness, macro.stiffness[:3, :3], rtol=1e-11, atol=1e-3)
    coupling = np.array(
        [float(v.replace("D", "E")) for line in matrices[4][2:] for v in line.split()]
    )
    np.testing.assert_allclose(coupling, macro.mass[3:, :3].ravel(order="F"), rtol=1e-11)


DECKS = {
    # deck: (checks, needs the I-DEAS reader)
    "sdld102a": (31, True),
    "sdld102b": (12, False),
    "sdld102d": (3, True),
    "sdld102e": (15, True),
    "sdld102f": (3, True),
    "sdnl104b": (10, False),
    "sdll113a": (6, True),
    "sdll113b": (9, True),
}


@pytest.mark.slow
@pytest.mark.parametrize("name", sorted(DECKS))
def test_substructuring_corpus_deck_passes(name, tmp_path):
    folder = CORPUS / name
    if not folder.exists():
        pytest.skip("the wider corpus is not here")
    count, ideas = DECKS[name]
    if ideas:
        pytest.importorskip("pyuff")
    result = api.run(folder / f"{name}.export", tmp_path / "out")
    assert result.status == "PASS", result.message
    assert len(result.checks) == count


def test_a_released_unit_is_written_afresh(tmp_path):
    """DEFI_FICHIER(ACTION='LIBERER') closes the unit: the next write to
    it no longer goes to the file DEFI_FICHIER had associated."""
    writes = (
        'DEFI_FICHIER(UNITE=38, FICHIER="macro.unv")\n'
        "IMPR_MACR_ELEM(MACR_ELEM_DYNA=ME_L, UNITE=38)\n"
        'DEFI_FICHIER(ACTION="LIBERER", UNITE=38)\n'
        "IMPR_MACR_ELEM(MACR_ELEM_DYNA=ME_R, UNITE=38)\nFIN()"
    )
    (tmp_path / "cut.comm").write_text(substructured_deck(2, clamped=True).replace("FIN()", writes))
    (tmp_path / "cut.mail").write_text(beam_mesh(N_HALF, 1.0))
    result = api.run(tmp_path / "cut.comm", tmp_path / "out")
    assert result.status == "DONE", result.message
    first = (tmp_path / "out" / "macro.unv").read_text()
    second = (tmp_path / "out" / "fort.38").read_text()
    assert first.count("   481") == second.count("   481")  # one macro-element in each
