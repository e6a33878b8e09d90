"""What a study's text files may do to a run, and what the run says about
them: non-finite numbers refused by name in every reader, error messages
that never quote a file the deck could not legitimately read, deck text in
any of the encodings old decks use, and CA.TestCase's verdicts on NaN."""

from __future__ import annotations

import codecs
import os
import re
import subprocess
import sys
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


# ------------------------------------------------------------- deck encodings

ACCENTED_DECK = 'DEBUT()\nt = "déplacement à l’origine"\nprint(t)\nFIN()\n'


def encoded_deck(folder: Path, data: bytes) -> Path:
    folder.mkdir(parents=True, exist_ok=True)
    path = folder / "d.comm"
    path.write_bytes(data)
    return path


def test_a_deck_with_a_utf8_byte_order_mark_runs(tmp_path):
    """Editors on Windows start UTF-8 files with a BOM: refused at 1:1 before."""
    deck = encoded_deck(tmp_path, codecs.BOM_UTF8 + ACCENTED_DECK.encode("utf-8"))
    report = run_deck(deck, tmp_path / "out")
    assert report.status == "DONE", report.message
    log = (tmp_path / "out" / "message.log").read_text(encoding="utf-8")
    assert "déplacement à l’origine" in log and "read as" not in log
    assert run_deck(deck, check_only=True).status == "CHECKED"


@pytest.mark.parametrize(
    "encoding, named",
    [("latin-1", "Latin-1 (ISO-8859-1)"), ("cp1252", "Windows-1252")],
)
def test_an_old_french_deck_keeps_its_accents_and_says_how_it_was_read(tmp_path, encoding, named):
    """Latin-1 letters in deck strings used to become U+FFFD without a word."""
    text = ACCENTED_DECK if encoding == "cp1252" else ACCENTED_DECK.replace("’", "'")
    deck = encoded_deck(tmp_path, text.encode(encoding))
    report = run_deck(deck, tmp_path / "out")
    assert report.status == "DONE", report.message
    log = (tmp_path / "out" / "message.log").read_text(encoding="utf-8")
    assert text.splitlines()[1][5:-1] in log and "\ufffd" not in log
    assert f"# deck d.comm read as {named}, not UTF-8" in log


def test_a_coding_declaration_is_honoured(tmp_path):
    text = "# -*- coding: iso-8859-15 -*-\nDEBUT()\nprint('prix: 5 €')\nFIN()\n"
    deck = encoded_deck(tmp_path, text.encode("iso-8859-15"))
    run_deck(deck, tmp_path / "out")
    log = (tmp_path / "out" / "message.log").read_text(encoding="utf-8")
    assert "prix: 5 €" in log and "read as iso8859-15, not UTF-8" in log


def test_bytes_contradicting_a_byte_order_mark_are_refused_at_their_line(tmp_path):
    deck = encoded_deck(tmp_path, codecs.BOM_UTF8 + "DEBUT()\nt = 'é'\n".encode("latin-1"))
    report = run_deck(deck, tmp_path / "out")
    assert report.exit_code == 2
    assert "line 2: byte" in report.message and "byte order mark" in report.message


def test_decoding_rules():
    from asterlite.io.text_encoding import TextEncodingError, decode_text

    assert decode_text("é".encode()) == ("é", "UTF-8")
    assert decode_text(codecs.BOM_UTF8 + b"x") == ("x", "UTF-8 (with a byte order mark)")
    assert decode_text("é".encode("latin-1")) == ("é", "Latin-1 (ISO-8859-1)")
    assert decode_text("’é".encode("cp1252")) == ("’é", "Windows-1252")
    assert decode_text(b"\x81\xe9") == ("\x81é", "Latin-1 (ISO-8859-1)")  # not Windows-1252
    declared = b"#!x\n# coding: latin-1\n\xe9"
    assert decode_text(declared) == (declared.decode("latin-1"), "iso8859-1")
    # a declaration on line 2 counts only after a comment line 1, as in Python
    assert decode_text(b"x = 1\n# coding: latin-1\n\xe9")[1] == "Latin-1 (ISO-8859-1)"
    for declared in (b"# coding: rot13\n", b"# coding: no-such-codec\n"):
        with pytest.raises(TextEncodingError):
            decode_text(declared)


def test_port_writes_utf8_and_says_so(tmp_path):
    text = "# -*- coding: iso-8859-1 -*-\nDEBUT()\nt = 'élément'\nFIN()\n"
    deck = encoded_deck(tmp_path, text.encode("latin-1"))
    command = [sys.executable, "-m", "asterlite", "port", str(deck)]
    environment = dict(os.environ, PYTHONIOENCODING="ascii", LC_ALL="C")
    done = subprocess.run(command, capture_output=True, env=environment, check=False)
    assert done.returncode == 0, done.stderr
    assert done.stdout.decode("utf-8") == text.replace("iso-8859-1", "utf-8")
    assert b"encoding: read as iso8859-1, written as UTF-8" in done.stderr
    written = tmp_path / "p.comm"
    subprocess.run([*command, "-o", str(written)], env=environment, check=True, capture_output=True)
    assert written.read_bytes() == done.stdout
