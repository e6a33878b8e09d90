"""The runtime: dispatch, statuses, exit codes, output staging, CA.TestCase."""

from __future__ import annotations

import json

from asterlite.cli import main
from asterlite.runtime.runner import run_deck

FUNCTION_DECK = """
DEBUT(CODE="OUI")
F = DEFI_FONCTION(NOM_PARA="INST", VALE=(0.0, 0.0, 1.0, 2.0))
TEST_FONCTION(VALEUR=_F(FONCTION=F, VALE_PARA=0.5, VALE_CALC=1.0, VALE_REFE=1.0,
                        REFERENCE="ANALYTIQUE"))
IMPR_FONCTION(FORMAT="TABLEAU", UNITE=8, COURBE=_F(FONCTION=F))
FIN()
"""


def deck(tmp_path, text, name="d.comm"):
    path = tmp_path / name
    path.write_text(text)
    return path


def test_passing_deck_writes_outputs(tmp_path):
    out = tmp_path / "out"
    report = run_deck(deck(tmp_path, FUNCTION_DECK), out)
    assert report.status == "PASS", report.message
    assert report.checks_total == 1 and report.checks_ok == 1
    assert (out / "fort.8").exists()
    assert not (out / ".running").exists() and not (out / "incomplete").exists()
    summary = json.loads((out / "summary.json").read_text())
    assert summary["status"] == "PASS"
    assert [c["command"] for c in summary["commands"]] == [
        "DEFI_FONCTION",
        "TEST_FONCTION",
        "IMPR_FONCTION",
    ]
    assert "TEST_FONCTION" in (out / "message.log").read_text()


def test_nook_deck_exits_1(tmp_path):
    text = FUNCTION_DECK.replace("VALE_CALC=1.0, VALE_REFE=1.0", "VALE_CALC=1.5, VALE_REFE=1.5")
    report = run_deck(deck(tmp_path, text), tmp_path / "out")
    assert report.status == "NOOK"
    assert report.exit_code == 1
    assert main(["run", str(tmp_path / "d.comm"), "-o", str(tmp_path / "o2"), "-q"]) == 1


def test_error_keeps_partial_files_apart(tmp_path):
    text = FUNCTION_DECK.replace("FIN()", "X = 1 / 0\nFIN()")
    out = tmp_path / "out"
    report = run_deck(deck(tmp_path, text), out)
    assert report.status == "ERROR"
    assert report.exit_code == 2
    assert "d.comm:7" in report.message and "division by zero" in report.message
    assert not (out / "fort.8").exists()  # not presented as a finished result
    assert (out / "incomplete" / "fort.8").exists()
    assert json.loads((out / "summary.json").read_text())["status"] == "ERROR"


def test_unsupported_command_names_itself_and_line(tmp_path):
    text = "DEBUT()\nT = POST_RCCM(TYPE_RESU_MECA='B3600', OPTION='MOMENT_EQUIVALENT')\nFIN()\n"
    report = run_deck(deck(tmp_path, text), tmp_path / "out")
    assert report.exit_code == 2
    assert report.status in ("UNSUPPORTED", "ERROR")
    assert "POST_RCCM" in report.message and "d.comm:2" in report.message


def test_statements_after_fin_are_not_run(tmp_path):
    text = "DEBUT()\nFIN()\nX = 1 / 0\n"
    assert run_deck(deck(tmp_path, text), tmp_path / "out").status == "DONE"


def test_testcase_assertions_are_checks(tmp_path):
    text = (
        "from code_aster import CA\nDEBUT()\nt = CA.TestCase()\n"
        "t.assertTrue(1 + 1 == 2)\nt.assertAlmostEqual(0.1 + 0.2, 0.3)\n"
        "t.assertTrue(False)\nFIN()\n"
    )
    report = run_deck(deck(tmp_path, text), tmp_path / "out")
    assert report.checks_total == 3 and report.checks_ok == 2
    assert report.status == "NOOK"


def test_check_mode_computes_nothing(tmp_path):
    out = tmp_path / "out"
    report = run_deck(deck(tmp_path, FUNCTION_DECK), out, check_only=True)
    assert report.status == "CHECKED" and report.tests == []
    assert not out.exists()


def test_check_cli_json(tmp_path, capsys):
    path = deck(tmp_path, FUNCTION_DECK.replace("NOM_PARA=", "NOM_PAR="))
    assert main(["check", str(path), "--format", "json"]) == 2
    result = json.loads(capsys.readouterr().out)
    assert result["decks"][0]["status"] == "INVALID"  # not code_aster 17 (asterlite check)
    first = result["decks"][0]["findings"][0]
    assert first["kind"] == "invalid" and "did you mean NOM_PARA" in first["message"]


def test_check_imports_no_numerical_stack(tmp_path):
    """`asterlite check` stays light: numpy, scipy and numba load on first use only."""
    import subprocess
    import sys

    path = deck(tmp_path, FUNCTION_DECK)
    code = (
        f"import sys; from asterlite.cli import main; main(['check', {str(path)!r}]); "
        "print(sorted(m for m in ('numpy', 'scipy', 'numba') if m in sys.modules))"
    )
    out = subprocess.run([sys.executable, "-c", code], capture_output=True, text=True, check=True)
    assert out.stdout.strip().splitlines()[-1] == "[]"


def test_impr_fonction_draws_an_image_with_an_image_pilote(tmp_path):
    text = FUNCTION_DECK.replace(
        'IMPR_FONCTION(FORMAT="TABLEAU", UNITE=8,',
        'IMPR_FONCTION(FORMAT="XMGRACE", PILOTE="PNG", UNITE=29,',
    )
    assert "PILOTE" in text
    out = tmp_path / "out"
    assert run_deck(deck(tmp_path, text), out).status == "PASS"
    assert (out / "fort.29").read_bytes()[:8] == b"\x89PNG\r\n\x1a\n"


def test_detruire_nom_unbinds_the_concept(tmp_path):
    # code_aster 13+ spells DETRUIRE(NOM=...); the name is gone afterwards
    text = (
        "DEBUT()\nF = DEFI_CONSTANTE(VALE=1.0)\nG = F\nDETRUIRE(NOM=(F,))\n"
        "try:\n    x = G\nexcept NameError:\n    x = 'destroyed'\nprint('after', x)\nFIN()\n"
    )
    out = tmp_path / "out"
    report = run_deck(deck(tmp_path, text), out)
    assert report.status in ("DONE", "PASS"), report.message
    assert "after destroyed" in (out / "message.log").read_text()
