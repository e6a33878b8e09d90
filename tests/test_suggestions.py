"""A name that is not there gets the nearest ones that are.

Before: a misspelt command (``CALC_MODE(``) or concept got "name is not
defined" and nothing more; a missing mesh group did not list the mesh's
groups; a missing mesh did not say where it was looked for; and with
several meshes beside a bare ``.comm`` the first in alphabetical order was
read without a word. The suggestions come from one place,
:mod:`asterlite.errors` (``did_you_mean``, ``missing_name``).
"""

from __future__ import annotations

import shutil

import pytest

from asterlite.errors import close_names, did_you_mean, missing_name
from asterlite.runtime.runner import run_deck
from tests.conftest import SAMPLES

SAMPLE = SAMPLES / "friction_oscillator"


def test_did_you_mean():
    names = ["CALC_MODES", "CALC_MATR_ELEM", "MODE_STATIQUE", "MASSEGEN"]
    assert did_you_mean("CALC_MODE", names) == ", did you mean CALC_MODES?"
    assert did_you_mean("calc_modes", names) == ", did you mean CALC_MODES?"
    assert did_you_mean("XYZ", names) == ""
    assert close_names("MASSGEN", names) == ["MASSEGEN"]


def test_missing_name_lists_the_nearest():
    few = ["SUPP1", "SUPP2", "SUPP3", "ENCASTR"]
    text = missing_name("node group", "SUP2", few)
    assert text.startswith("the mesh has no node group 'SUP2', did you mean 'SUPP2'?")
    assert "'ENCASTR'" in text  # few groups: all of them
    many = [f"G{k}" for k in range(40)] + ["SUPP2"]
    text = missing_name("node group", "SUP2", many)
    assert "nearest of its 41 node groups: 'SUPP2'" in text and "'G39'" not in text
    assert "it has no cell groups" in missing_name("cell group", "X", [])


def deck_variant(tmp_path, old: str, new: str, mesh: bool = True):
    text = (SAMPLE / "friction_oscillator.comm").read_text()
    assert old in text
    deck = tmp_path / "deck.comm"
    deck.write_text(text.replace(old, new, 1))
    if mesh:
        shutil.copy(SAMPLE / "friction_oscillator.mail", tmp_path / "deck.mail")
    return deck


@pytest.mark.parametrize(
    ("old", "new", "expected"),
    [
        ("MODES = CALC_MODES(", "MODES = CALC_MODE(", "did you mean CALC_MODES?"),
        ("MATR_MASS=MASSEGEN", "MATR_MASS=MASSGEN", "did you mean MASSEGEN?"),
        ('GROUP_NO_1="N1"', 'GROUP_NO_1="N11"', "did you mean 'N1'? (its node groups: 'N1')"),
        ('GROUP_NO="N1", NOM_CMP="DX"', 'GROUP_NO="N1", NOM_CMP="DXX"', "did you mean 'DX'?"),
    ],
)
def test_misspelt_names_at_run_time(tmp_path, old, new, expected):
    deck = deck_variant(tmp_path, old, new)
    report = run_deck(deck, tmp_path / "out")
    assert report.status == "ERROR"
    assert expected in report.message, report.message


def test_misspelt_global_in_a_deck_function(tmp_path):
    """Deck functions are compiled (lang/compiled_runtime.py): same hint."""
    function = "def w0():\n    return sqrt(K / M + 0 * PENETRATON)\n\nW0 = w0()"
    deck = deck_variant(tmp_path, "W0 = sqrt(K / M)", function)
    report = run_deck(deck, tmp_path / "out")
    expected = "name 'PENETRATON' is not defined, did you mean PENETRATION?"
    assert expected in report.message, report.message


def test_missing_mesh_says_where_it_looked(tmp_path):
    deck = deck_variant(tmp_path, "DEBUT(", "DEBUT(", mesh=False)
    report = run_deck(deck, tmp_path / "out")
    assert report.status == "ERROR"
    for place in ("deck.mail", "deck.mmed", "deck.med", "*.mail", "*.med", str(tmp_path)):
        assert place in report.message, report.message


def test_several_sibling_meshes_are_an_error_naming_them(tmp_path):
    deck = deck_variant(tmp_path, "DEBUT(", "DEBUT(", mesh=False)
    for name in ("b.mail", "a.mail"):
        shutil.copy(SAMPLE / "friction_oscillator.mail", tmp_path / name)
    report = run_deck(deck, tmp_path / "out")
    assert report.status == "ERROR"
    assert "2 meshes beside the deck deck.comm (a.mail, b.mail)" in report.message
    (tmp_path / "b.mail").unlink()  # one mesh left: it is the deck's
    assert run_deck(deck, tmp_path / "out2").status == "PASS"


def test_unmapped_unit_of_an_export_names_the_export(tmp_path):
    deck_variant(
        tmp_path, 'LIRE_MAILLAGE(FORMAT="ASTER")', 'LIRE_MAILLAGE(FORMAT="ASTER", UNITE=21)'
    )
    export = tmp_path / "deck.export"
    export.write_text("F comm deck.comm D 1\nF mail deck.mail D 20\n")
    report = run_deck(export, tmp_path / "out")
    assert f"the export {export} maps units 20" in report.message, report.message
