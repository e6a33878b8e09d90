"""What a study's text files may do to a run, and what the run says about
them: non-finite numbers refused by name in every reader, error messages
that never quote a file the deck could not legitimately read, deck text in
any of the encodings old decks use, and CA.TestCase's verdicts on NaN."""

from __future__ import annotations

import re
from pathlib import Path

import pytest

from asterlite.runtime.runner import run_deck


def write(folder: Path, name: str, text: str) -> Path:
    path = folder / name
    path.write_text(text)
    return path


# ------------------------------------------------------------ CA.TestCase


def test_testcase_assertions_on_non_finite_numbers_are_nook(tmp_path):
    """code_aster's TestCase is unittest's: assertTrue(nan) passes there
    (bool(nan) is True) and assertAlmostEqual(inf, inf) too (first == second).
    A check that a non-finite number passes is reported NOOK, naming it."""
    deck = write(
        tmp_path,
        "d.comm",
        "from code_aster import CA\nDEBUT()\nt = CA.TestCase()\n"
        "t.assertTrue(float('nan'))\n"
        "x = float('inf')\nt.assertAlmostEqual(x, x)\nt.assertEqual(x, x)\n"
        "t.assertFalse(-x)\nt.assertTrue([1.0, float('nan')])\n"
        "t.assertTrue(1.5)\nt.assertAlmostEqual(1.0, 1.0 + 1e-9)\nt.assertFalse(0.0)\nFIN()\n",
    )
    report = run_deck(deck, tmp_path / "out")
    verdicts = [test.ok for test in report.tests]
    assert verdicts == [False, False, False, False, False, True, True, True]
    assert report.status == "NOOK" and report.exit_code == 1
    log = (tmp_path / "out" / "message.log").read_text()
    assert "NOOK TestCase.assertTrue #1: nan is not a finite number (code_aster's" in log
    assert "NOOK TestCase.assertAlmostEqual #2: inf is not a finite number" in log
    assert "NOOK TestCase.assertFalse #4: -inf is not a finite number\n" in log


def test_testcase_keeps_unittests_verdicts_on_finite_values(tmp_path):
    deck = write(
        tmp_path,
        "d.comm",
        "from code_aster import CA\nDEBUT()\nt = CA.TestCase()\n"
        "t.assertAlmostEqual(1.0, 1.001, places=2)\nt.assertAlmostEqual(1.0, 1.2, delta=0.1)\n"
        "t.assertEqual([1.0, 2.0], [1.0, 2.0])\nt.assertTrue([])\nFIN()\n",
    )
    report = run_deck(deck, tmp_path / "out")
    assert [test.ok for test in report.tests] == [True, False, True, False]


# ------------------------------------------- files the deck may not quote

SECRET = "hunter2-SECRET"
# private files a study might name: none reads as what it is taken for
PRIVATE_TEXTS = {
    "passwd": f"root:x:0:0:{SECRET}:/root:/bin/bash\n",
    "credentials": f"[default]\naws_secret_access_key = {SECRET}\n",
    "netrc": f"machine example.org login me password {SECRET}\n",
    "ideas-like": f"    -1\n{SECRET}\n    -1\n",
}


def private_file(folder: Path, name: str) -> Path:
    path = folder / "private" / name
    path.parent.mkdir(parents=True, exist_ok=True)
    path.write_text(PRIVATE_TEXTS[name])
    path.chmod(0o600)
    return path


def study(folder: Path, deck: str, lines: list[str]) -> Path:
    folder.mkdir(parents=True, exist_ok=True)
    write(folder, "deck.comm", deck)
    return write(folder, "deck.export", "\n".join(["F comm deck.comm D 1", *lines]) + "\n")


def assert_not_quoted(report, *where: str) -> None:
    assert report.exit_code == 2, report.message
    assert "hunter2" not in report.message.lower(), report.message  # ASTER upper-cases
    for fragment in where:
        assert fragment in report.message, report.message


@pytest.mark.parametrize("name", ["passwd", "credentials", "netrc"])
@pytest.mark.parametrize("check_only", [False, True], ids=["run", "check"])
def test_a_private_file_named_as_the_deck_is_never_quoted(tmp_path, name, check_only):
    secret = private_file(tmp_path, name)
    export = write(tmp_path, "s.export", f"F comm {secret} D 1\n")
    report = run_deck(export, None if check_only else tmp_path / "out", check_only=check_only)
    assert_not_quoted(report, f"{secret}:1:", "does not read as a code_aster deck")
    if not check_only:
        assert "hunter2" not in (tmp_path / "out" / "message.log").read_text().lower()


@pytest.mark.parametrize("name", ["passwd", "credentials", "netrc", "ideas-like"])
@pytest.mark.parametrize("fmt", ["ASTER", "IDEAS"])
def test_a_mesh_symlinked_to_a_private_file_is_never_quoted(tmp_path, name, fmt):
    secret = private_file(tmp_path, name)
    deck = f"DEBUT()\nMA = LIRE_MAILLAGE(FORMAT='{fmt}', UNITE=20)\nFIN()\n"
    export = study(tmp_path / "study", deck, ["F mail mesh.mail D 20"])
    (tmp_path / "study" / "mesh.mail").symlink_to(secret)
    report = run_deck(export, tmp_path / "out")
    assert_not_quoted(report, "deck.comm:2:", "LIRE_MAILLAGE/UNITE")


def test_an_export_symlinked_to_a_private_file_is_never_quoted(tmp_path):
    secret = private_file(tmp_path, "netrc")
    (tmp_path / "s.export").symlink_to(secret)
    report = run_deck(tmp_path / "s.export", tmp_path / "out")
    assert_not_quoted(report, "s.export:1:", "not an export file")


def test_a_real_deck_error_still_shows_its_line(tmp_path):
    deck = write(tmp_path, "d.comm", "DEBUT()\nx = undefined_name + 1\nFIN()\n")
    report = run_deck(deck, tmp_path / "out")
    assert "name 'undefined_name' is not defined" in report.message
    assert "x = undefined_name + 1" in report.message


def test_a_real_mesh_error_still_quotes_the_token(tmp_path):
    from asterlite.io.aster_mesh import AsterMeshError, parse_aster_mesh

    with pytest.raises(AsterMeshError) as caught:
        parse_aster_mesh("COOR_2D\nN1 0.0 0.0\nN2 1.O 0.0\nFINSF\nFIN\n", "m.mail")
    assert str(caught.value) == "m.mail:3: expected a number, found '1.O'"


# ------------------------------------------------ non-finite spellings

WINDOWS_AND_OTHER_SPELLINGS = [
    "1.#QNAN",
    "-1.#IND",
    "1.#INF",
    "NaN%",
    "1.#SNAN",
    "1.#QNAN0",
    "-1.#IND00",
    "inf",
    "-Infinity",
    "nan(ind)",
    "-nan(snan)",
    "NaNQ",
    "#DIV/0!",
    "#N/A",
    "*********",
    "1.0D+999",
]

LIRE_DECK = (
    "DEBUT()\nF = LIRE_FONCTION(UNITE=21, NOM_PARA='INST', INDIC_PARA=(1, 1), "
    "INDIC_RESU=(1, 2))\nFIN()\n"
)


@pytest.mark.parametrize("bad", WINDOWS_AND_OTHER_SPELLINGS)
def test_lire_fonction_refuses_every_non_finite_spelling_by_name(tmp_path, bad):
    """Before: a spelling float() does not read ended the block there, the
    rest of the file was dropped and the deck passed with a shorter function."""
    data = f"0.0 1.0\n1.0 2.0\n2.0 {bad}\n3.0 4.0\n4.0 5.0\n"
    export = study(tmp_path / "s", LIRE_DECK, ["F libr data.txt D 21"])
    write(tmp_path / "s", "data.txt", data)
    report = run_deck(export, tmp_path / "out")
    assert report.exit_code == 2, report.message
    assert "LIRE_FONCTION/UNITE" in report.message and "data.txt" in report.message
    assert f"block 1, line 3, column 2: {bad!r} is" in report.message
    assert "not a finite number" in report.message


def test_lire_fonction_text_lines_still_separate_blocks():
    from asterlite.commands.lire_fonction import numeric_blocks

    text = "Time Info\n0 1\n1 2\nValues: inf means none\n5 6\n"
    assert [len(block) for block in numeric_blocks(text)] == [2, 1]


def test_lire_fonction_cuts_lines_where_code_aster_does():
    """code_aster reads ``for line in open(...)``: a form feed inside a line
    is a blank for split(), not a line break (str.splitlines cut there)."""
    from asterlite.commands.lire_fonction import numeric_blocks

    (block,) = numeric_blocks("0.0 1.0\x0c2.0 3.0\r\n4.0 5.0 6.0 7.0\r")
    assert [list(row) for row in block] == [[0.0, 1.0, 2.0, 3.0], [4.0, 5.0, 6.0, 7.0]]


@pytest.mark.parametrize("bad", ["1.#QNAN", "-1.#IND", "Infinity", "1.D+999"])
def test_aster_mesh_coordinates_refuse_every_non_finite_spelling(bad):
    from asterlite.io.aster_mesh import AsterMeshError, parse_aster_mesh

    text = f"COOR_3D\nN1 0.0 0.0 0.0\nN2 1.0 {bad} 0.0\nFINSF\nFIN\n"
    with pytest.raises(AsterMeshError) as caught:
        parse_aster_mesh(text, "m.mail")
    assert f"m.mail:3: node N2: {bad!r} is" in str(caught.value)


@pytest.mark.parametrize("bad", ["1.#QNAN", "-1.#IND", "nan", "1.0D+999"])
def test_ideas_node_coordinates_refuse_every_non_finite_spelling(bad):
    from asterlite.io.ideas_mesh import IdeasMeshError, parse_ideas_mesh

    coordinates = f"{'0.0D+00':>25}{bad:>25}{'0.0D+00':>25}"
    lines = ["    -1", "  2411", f"{1:10d}{1:10d}{1:10d}{11:10d}", coordinates, "    -1"]
    with pytest.raises(IdeasMeshError) as caught:
        parse_ideas_mesh("\n".join(lines) + "\n", "m.unv")
    assert f"m.unv:4: dataset 2411: {bad!r} is" in str(caught.value)


@pytest.mark.parametrize("bad", ["1.#QNAN", "nan", "-1.#IND"])
def test_lire_inte_spec_refuses_non_finite_values_at_their_line(bad):
    from asterlite.commands.lire_inte_spec import parse_aster_interspectrum

    text = "DIM = 1\nFONCTION_C\nI = 1\nJ = 1\nVALEUR =\n 0.0 1.0 0.0\n 5.0 {} 0.0\nFINSF\n"
    with pytest.raises(ValueError, match=rf"line 7: term \(1, 1\): '{re.escape(bad)}' is"):
        parse_aster_interspectrum(text.format(bad), "REEL_IMAG")


@pytest.mark.parametrize("value", ["inf", "1.#INF", "nan", "Infinity"])
@pytest.mark.parametrize("name", ["time_limit", "memory_limit"])
def test_export_limits_refuse_non_finite_values_by_name(tmp_path, name, value):
    """``P time_limit inf`` used to be accepted: an unlimited run."""
    export = study(tmp_path, "DEBUT()\nFIN()\n", [f"P {name} {value}"])
    report = run_deck(export, tmp_path / "out")
    assert report.exit_code == 2
    assert f"P {name}: {value!r} is" in report.message and "not a finite number" in report.message
