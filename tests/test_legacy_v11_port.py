"""``asterlite port`` of code_aster 10-11 decks writes code_aster 17 decks
(asterlite.legacy.port_v11, macros_v11), node names in old tables, and the
code_aster 11 corpus ported and run to the same check values."""

from __future__ import annotations

import math
from pathlib import Path

import pytest

from asterlite.legacy.nodes import node_number_resolver
from asterlite.legacy.port import port_file, port_text
from asterlite.legacy.version import (
    CURRENT,
    NODE_NAMES_IN_TABLES,
    deck_version,
    pragma_version,
)
from asterlite.runtime.runner import run_deck
from tests.conftest import ROOT, corpus_rows

# one pytest-xdist worker runs every test that reads a corpus folder's run
# (tests.conftest.corpus_rows): each folder is run once a session, not once a worker
pytestmark = pytest.mark.xdist_group("shared-corpus")

CORPUS_V11 = ROOT.parent / "shared" / "aster-corpus-v11"


def _ported(text: str, **kwargs) -> str:
    result = port_text(text, "deck.comm", version=11, **kwargs)
    assert not result.skipped, result.skipped
    return result.text


# ------------------------------------------------------------- value forms


def test_reference_values_become_vale_calc_and_vale_refe():
    text = _ported(
        "DEBUT()\nTEST_TABLE(TABLE=T, NOM_PARA='X', VALE=2.5, PRECISION=(1.E-2, 1.E-3))\nFIN()\n"
    )
    assert "VALE_CALC=2.5" in text and "VALE_REFE=2.5" in text
    assert "PRECISION=0.01" in text and "TOLE_MACHINE=0.01" in text  # the first of the pair
    assert 'REFERENCE="NON_DEFINI"' in text and "VALE=" not in text.replace("VALE_", "")
    assert deck_version(text) == CURRENT


def test_formule_is_given_the_deck_variables_it_reads():
    text = _ported(
        "DEBUT()\nOMEGA = 3.0\nF = FORMULE(NOM_PARA='INST', VALE='sin(OMEGA*INST)')\nFIN()\n"
    )
    assert "OMEGA=OMEGA" in text


def test_macro_proj_base_is_proj_base_with_the_old_defaults():
    text = _ported(
        "DEBUT()\nMACRO_PROJ_BASE(BASE=MODES, MATR_ASSE_GENE=_F(MATRICE=CO('MG'), "
        "MATR_ASSE=M), VECT_ASSE_GENE=_F(VECTEUR=CO('VG'), VECT_ASSE=V))\nFIN()\n"
    )
    assert "PROJ_BASE(" in text and "MACRO_PROJ_BASE" not in text
    assert 'STOCKAGE="DIAG"' in text and 'TYPE_VECT="FORC"' in text


def test_macro_matr_asse_is_assemblage_without_its_solver():
    text = _ported(
        "DEBUT()\nMACRO_MATR_ASSE(MODELE=MO, NUME_DDL=CO('NU'), SOLVEUR=_F(METHODE='LDLT'), "
        "MATR_ASSE=_F(MATRICE=CO('K'), OPTION='RIGI_MECA'))\nFIN()\n"
    )
    assert "ASSEMBLAGE(" in text and "SOLVEUR" not in text


def test_macro_matr_asse_new_numbering_needs_a_stiffness():
    """code_aster 11 built a new numbering from the stiffness occurrence."""
    result = port_text(
        "DEBUT()\nMACRO_MATR_ASSE(MODELE=MO, NUME_DDL=CO('NU'), "
        "MATR_ASSE=_F(MATRICE=CO('M'), OPTION='MASS_MECA'))\nFIN()\n",
        "deck.comm",
        version=11,
    )
    assert any("needs a stiffness matrix" in line for line in result.skipped)


def test_gene_nume_ordre_on_a_transient_becomes_the_order_number():
    text = _ported(
        "DEBUT()\nTR = DYNA_TRAN_MODAL(MATR_MASS=M, MATR_RIGI=K, INCREMENT=_F(INST_FIN=1., "
        "PAS=0.1))\nTEST_RESU(GENE=_F(RESU_GENE=TR, NOM_CHAM='VITE', NUME_ORDRE=456, "
        "NUME_CMP_GENE=3, VALE=1.0))\nTEST_RESU(GENE=_F(RESU_GENE=V, NUME_CMP_GENE=3, "
        "VALE=1.0))\nFIN()\n"
    )
    assert "NUME_ORDRE=455" in text


# ------------------------------------------------------- nodes in tables


def test_node_names_in_tables_up_to_code_aster_15():
    assert set(range(10, 16)) <= set(NODE_NAMES_IN_TABLES)
    assert CURRENT not in NODE_NAMES_IN_TABLES


def test_table_filters_on_node_names_become_numbers(tmp_path):
    mesh = tmp_path / "m.mail"
    mesh.write_text("COOR_3D\n NA 0. 0. 0.\n NB 1. 0. 0.\nFINSF\nSEG2\n S1 NA NB\nFINSF\nFIN\n")
    number = node_number_resolver([mesh])
    assert number("NB") == 2 and number("NZ") is None
    deck = (
        "DEBUT()\nFLT = (_F(NOM_PARA='NOEUD', VALE_K='NB'),)\n"
        "TEST_TABLE(TABLE=T, NOM_PARA='F', FILTRE=FLT, VALE_CALC=1.0)\n"
        "TEST_TABLE(TABLE=T, NOM_PARA='F', FILTRE=_F(NOM_PARA='NOEUD', VALE_K='NZ'), "
        "VALE_CALC=1.0)\nFIN()\n"
    )
    result = port_text(deck, "deck.comm", version=15, node_number=number)
    assert 'VALE_K="2"' in result.text  # kept in a variable, found all the same
    assert "VALE_K='NZ'" in result.text  # not a node of the mesh: left as written
    assert any("node names in tables" in note.old for note in result.notes)
    today = port_text(deck, "deck.comm", version=CURRENT, node_number=number)
    assert "VALE_K='NB'" in today.text  # a code_aster 17 deck already filters on numbers


def test_filters_stay_names_when_the_ported_deck_stays_old(tmp_path):
    """A deck whose port still reads as an old version keeps reading tables by name."""
    mesh = tmp_path / "m.mail"
    mesh.write_text("COOR_3D\n NA 0. 0. 0.\nFINSF\nPOI1\n P1 NA\nFINSF\nFIN\n")
    deck = (
        "DEBUT()\nX = DYNA_TRAN_MODAL(ARGS)\n"  # positional: not portable, stays old
        "TEST_TABLE(TABLE=T, NOM_PARA='F', FILTRE=_F(NOM_PARA='NOEUD', VALE_K='NA'), "
        "VALE=1.0)\nFIN()\n"
    )
    result = port_text(deck, "deck.comm", version=11, node_number=node_number_resolver([mesh]))
    assert deck_version(result.text) in NODE_NAMES_IN_TABLES
    assert "VALE_K='NA'" in result.text
    assert any("table filters on node names left as written" in s for s in result.skipped)


# ------------------------------------------------- the code_aster 11 corpus


def _decks() -> list[str]:
    """Every deck of the corpus (its runs that do not pass are skipped below)."""
    if not CORPUS_V11.is_dir():
        return []
    return sorted(p.name for p in CORPUS_V11.iterdir() if (p / f"{p.name}.export").is_file())


def _ported_copy(deck: str, tmp_path: Path, corpus: Path = CORPUS_V11):
    """(the export of the ported deck beside the corpus files, port's result for
    its .comm; other command files, .com1..., are ported beside it)."""
    folder = corpus / deck
    result = port_file(folder / f"{deck}.comm")
    tmp_path.mkdir(parents=True, exist_ok=True)
    for path in folder.iterdir():
        target = tmp_path / path.name
        if path.suffix == ".comm":
            target.write_text(result.text)
        elif path.suffix.startswith(".com"):
            target.write_text(port_file(path).text)
        else:
            target.symlink_to(path)
    return tmp_path / f"{deck}.export", result


@pytest.mark.slow
@pytest.mark.corpus
@pytest.mark.parametrize("deck", _decks())
def test_ported_v11_deck_checks_and_runs_to_the_same_values(deck, tmp_path):
    """The code_aster 17 deck `asterlite port` writes for a code_aster 11 deck
    passes `asterlite check`, reads as today's version and, for a deck that
    passes, gives the same TEST_* values (labels may differ: node numbers, order
    numbers). Whether a deck passes is the ratchet's (tests/test_corpus_v15.py);
    a call port leaves as written is one the run refuses too."""
    export, result = _ported_copy(deck, tmp_path / "ported")
    # the deck as written: the folder's run of the session (the ratchet's)
    legacy = {row["deck"]: row for row in corpus_rows("aster-corpus-v11")}[deck]
    if result.skipped:
        assert legacy["status"] in ("UNSUPPORTED", "ERROR"), result.skipped
        pytest.skip(f"{deck}: {result.skipped[0]}")
    ported_text = (tmp_path / "ported" / f"{deck}.comm").read_text()
    stated = pragma_version(ported_text)  # a behaviour only its version line keeps
    assert stated in (None, 11) and deck_version(ported_text) == CURRENT
    assert run_deck(export, check_only=True).status == "CHECKED"
    if legacy["status"] != "PASS":
        why = legacy["message"] or f"{legacy['checks_ok']} checks OK"
        pytest.skip(f"{deck} does not pass as written: {legacy['status']}, {why}")
    ported = run_deck(export, tmp_path / "ported_run")
    assert ported.status == "PASS", ported.message
    old = [(command, value) for command, _label, value in legacy["tests"]]
    new = [(t.command, t.value) for t in ported.tests]
    assert [c for c, _ in old] == [c for c, _ in new]
    for (_, a), (_, b) in zip(old, new, strict=True):
        assert math.isclose(a, b, rel_tol=1.0e-9, abs_tol=1.0e-300), (deck, a, b)


# ------------------------------------------------------- REST_GENE_PHYS


class _Ctx:
    def __init__(self):
        self.messages = []

    def log(self, message):
        self.messages.append(message)

    def unsupported(self, message, keyword, kw):
        raise AssertionError(message)


def test_interpolated_instant_past_the_archive_keeps_the_previous_field():
    """tran75 does not read extrac's return code: 0.2 past an archive ending at
    0.19 gets the field of 0.18 (sdnd110a's LIST_INST)."""
    import numpy as np
    from asterlite.commands.rest_gene_phys import interpolated_instants

    times = np.linspace(0.0, 0.19, 20)
    ctx = _Ctx()
    selection = interpolated_instants(ctx, {"LIST_INST": (0.02, 0.185, 0.2)}, times)
    states = np.arange(20.0)[:, None]
    assert np.allclose(selection.apply(states)[:, 0], [2.0, 18.5, 18.5])
    assert list(selection.order) == [1, 2, 3]
    assert ctx.messages and "outside the archived range" in ctx.messages[0]
