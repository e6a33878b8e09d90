"""What a study's text files may do to a run, and what the run says about
them: non-finite numbers refused by name in every reader, error messages
that never quote a file the deck could not legitimately read, deck text in
any of the encodings old decks use, and CA.TestCase's verdicts on NaN."""

from __future__ import annotations

from pathlib import Path

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
