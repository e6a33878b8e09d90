"""`asterlite check`'s two verdicts (issue 27): valid code_aster N, judged by
that version's language data, and what asterlite computes. Every finding has
a kind; a deck is VALID (0), UNSUPPORTED (3) or INVALID (2)."""

from __future__ import annotations

import json
from pathlib import Path

import pytest

from asterlite.cli import main
from asterlite.runtime.check_deck import check_deck


def deck(tmp_path, body: str, name: str = "d.comm"):
    path = tmp_path / name
    path.write_text("DEBUT()\n" + body + "FIN()\n")
    return path


def kinds(check) -> list[tuple[str, str]]:
    return [(f.kind, f.keyword) for f in check.findings]


def test_valid_keyword_asterlite_does_not_compute_is_unsupported(tmp_path):
    path = deck(tmp_path, "MAT = DEFI_MATERIAU(FLUIDE=_F(RHO=1000.0, CELE_R=1400.0))\n")
    check = check_deck(path)
    assert check.status == "UNSUPPORTED" and check.exit_code == 3
    assert kinds(check) == [("unsupported", "DEFI_MATERIAU/FLUIDE")]


def test_valid_command_asterlite_does_not_compute_is_unsupported(tmp_path):
    path = deck(tmp_path, 'INFO_EXEC_ASTER(LISTE_INFO="UNITE_LIBRE")\n')
    check = check_deck(path)
    assert check.status == "UNSUPPORTED"
    assert kinds(check) == [("unsupported", "INFO_EXEC_ASTER")]


def test_misspelt_keyword_is_invalid_with_a_close_match(tmp_path):
    path = deck(tmp_path, "MAT = DEFI_MATERIAU(ELAS=_F(E=2.0e11, NUU=0.3))\n")
    check = check_deck(path)
    assert check.status == "INVALID" and check.exit_code == 2
    first = check.findings[0]
    assert (first.kind, first.keyword) == ("invalid", "DEFI_MATERIAU/ELAS[1]/NUU")
    assert "did you mean NU?" in first.message
    assert (first.line, first.column) == (2, 39)


def test_misspelt_reference_is_the_root_then_what_it_breaks(tmp_path):
    # REFERENCE misspelt next to VALE_REFE: the unknown keyword first, then
    # VALE_REFE, which only the missing REFERENCE allows
    path = deck(
        tmp_path,
        'T = CREA_TABLE(LISTE=_F(PARA="A", LISTE_R=(1.0, 2.0)))\n'
        'TEST_TABLE(TABLE=T, NOM_PARA="A", REFERENC="ANALYTIQUE", VALE_REFE=1.0,'
        " VALE_CALC=1.0, TYPE_TEST='MAX')\n",
    )
    check = check_deck(path)
    assert check.status == "INVALID"
    assert kinds(check) == [("invalid", "TEST_TABLE/REFERENC"), ("invalid", "TEST_TABLE/VALE_REFE")]
    assert "did you mean REFERENCE?" in check.findings[0].message
    assert "only with" in check.findings[1].message and "REFERENCE" in check.findings[1].message


def test_choices_are_checked_in_a_table_filter(tmp_path):
    path = deck(
        tmp_path,
        'T = CREA_TABLE(LISTE=(_F(PARA="A", LISTE_R=(1.0, 2.0)),\n'
        '                      _F(PARA="B", LISTE_R=(3.0, 4.0))))\n'
        'TEST_TABLE(TABLE=T, NOM_PARA="B", VALE_CALC=3.0,\n'
        '           FILTRE=_F(NOM_PARA="A", VALE=1.0, CRITERE="ABSOLUZ"))\n',
    )
    check = check_deck(path)
    assert check.status == "INVALID"
    (finding,) = check.findings
    assert finding.keyword == "TEST_TABLE/FILTRE[1]/CRITERE"
    assert (
        "'ABSOLUZ' is not one of" in finding.message and "did you mean 'ABSOLU'" in finding.message
    )


def test_every_error_of_one_occurrence_in_one_pass(tmp_path):
    # an unknown keyword and the rule it then breaks, in the same occurrence
    path = deck(tmp_path, "MAT = DEFI_MATERIAU(ELAS=_F(E=2.0e11, NUU=0.3, RHOO=7800.0))\n")
    check = check_deck(path)
    assert [f.keyword for f in check.findings] == [
        "DEFI_MATERIAU/ELAS[1]/NUU",
        "DEFI_MATERIAU/ELAS[1]/RHOO",
        "DEFI_MATERIAU/ELAS[1]",
    ]
    assert "(ENSEMBLE)" in check.findings[2].message


def test_a_command_of_another_version_says_which_has_it(tmp_path):
    path = deck(tmp_path, "X = DEFI_CONT(ZONE=_F(GROUP_MA_MAIT='A', GROUP_MA_ESCL='B'))\n")
    check = check_deck(path)  # DEFI_CONT is imported from its module in code_aster 17
    assert check.status == "INVALID"
    assert "DEFI_CONT" in check.findings[0].message


def test_the_version_decides_validity(tmp_path):
    # DEFI_PRES_EC8 is a command of code_aster 17, not of code_aster 15
    body = (
        "P = DEFI_PRES_EC8(Z_FOND=0.0, RAYON=1.0, HAUT_EAU=2.0, RHO_EAU=1000.0, ACCE_SP_H=1.0,"
        " ACCE_FLEX_H_N=1.0, ACCE_FLEX_V=1.0, ACCE_SP_V=1.0, ACCE_CONV_H=1.0)\n"
    )
    path = deck(tmp_path, body)
    check = check_deck(path, aster_version=17)
    assert (check.version, check.language, check.status) == (17, 17, "UNSUPPORTED")
    check = check_deck(path, aster_version=15)
    assert (check.version, check.language, check.status) == (15, 15, "INVALID")
    assert check.findings[0].message == (
        "DEFI_PRES_EC8 is not a command of code_aster 15 (code_aster 17 has it)"
    )


def test_python_asterlite_does_not_take_is_unsupported_not_invalid(tmp_path):
    path = deck(tmp_path, "import mpi4py\n")
    check = check_deck(path)
    assert check.status == "UNSUPPORTED"
    assert check.findings[0].kind == "unsupported-python"


def test_an_undefined_name_is_invalid(tmp_path):
    path = deck(tmp_path, "L = DEFI_LIST_REEL(VALE=(1.0, X))\n")
    check = check_deck(path)
    assert check.status == "INVALID"
    assert "name 'X' is not defined" in check.findings[0].message


def test_cli_statuses_exit_codes_and_json(tmp_path, capsys):
    valid = deck(tmp_path, "L = DEFI_LIST_REEL(VALE=(1.0, 2.0))\n", "valid.comm")
    unsupported = deck(tmp_path, 'INFO_EXEC_ASTER(LISTE_INFO="UNITE_LIBRE")\n', "u.comm")
    invalid = deck(tmp_path, "L = DEFI_LIST_REEL(VALEUR=(1.0, 2.0))\n", "i.comm")
    assert main(["check", str(valid)]) == 0
    assert "VALID (code_aster 17)" in capsys.readouterr().out
    assert main(["check", str(unsupported), "--format", "json"]) == 3
    (result,) = json.loads(capsys.readouterr().out)["decks"]
    assert result["status"] == "UNSUPPORTED" and result["counts"]["unsupported"] == 1
    # several decks: the worst status's code
    assert main(["check", str(valid), str(unsupported), str(invalid)]) == 2
    out = capsys.readouterr().out
    assert "i.comm: INVALID" in out and "did you mean VALE?" in out
    assert main(["check", str(valid), "--aster-version", "15"]) == 0
    assert "VALID (code_aster 15)" in capsys.readouterr().out


@pytest.mark.parametrize("version", [15, 17])
def test_a_typical_deck_checks_valid_again_and_again(tmp_path, version):
    # (its speed is a benchmark's, not a timed test's: docs/performance.md)
    body = (
        "L = DEFI_LIST_REEL(DEBUT=0.0, INTERVALLE=_F(JUSQU_A=1.0, PAS=0.01))\n"
        "F = DEFI_FONCTION(NOM_PARA='INST', VALE=(0.0, 0.0, 1.0, 1.0))\n"
        "T = CREA_TABLE(LISTE=_F(PARA='A', LISTE_R=(1.0, 2.0)))\n"
        "TEST_TABLE(TABLE=T, NOM_PARA='A', VALE_CALC=2.0, TYPE_TEST='MAX')\n"
    )
    path = deck(tmp_path, body)
    for _ in range(2):  # the second with the modules and catalogue already loaded
        check = check_deck(path, aster_version=version)
        assert check.status == "VALID", check.findings


def test_asterlites_own_verdict_is_kept_apart(tmp_path):
    # run_deck(check_only=True) (asterlite.check, sweep) keeps asterlite's own
    # verdict, what `run` would meet; `asterlite check` tells the two apart
    from asterlite.runtime.runner import run_deck

    path = deck(tmp_path, "MAT = DEFI_MATERIAU(FLUIDE=_F(RHO=1000.0, CELE_R=1400.0))\n")
    report = run_deck(path, check_only=True)
    assert report.status == "ERROR" and "FLUIDE" in report.message
    assert check_deck(path).status == "UNSUPPORTED"


def test_choice_in_a_table_filter_is_checked(tmp_path):
    path = deck(
        tmp_path,
        'T = CREA_TABLE(LISTE=_F(PARA="A", LISTE_R=(1.0, 2.0)))\n'
        'TEST_TABLE(TABLE=T, NOM_PARA="A", VALE_CALC=1.0, TYPE_TEST="MAX",\n'
        '           FILTRE=_F(NOM_PARA="A", VALE=1.0, CRITERE="ABSOLUZ"))\n',
    )
    check = check_deck(path)
    assert kinds(check) == [("invalid", "TEST_TABLE/FILTRE[1]/CRITERE")]
    assert "did you mean 'ABSOLU'" in check.findings[0].message
    assert check.findings[0].line == 4


def test_component_of_a_displacement_field_is_checked(tmp_path):
    body = (
        "TRAN = DYNA_VIBRA(TYPE_CALCUL='TRAN', BASE_CALCUL='GENE', MATR_MASS=M, MATR_RIGI=K,"
        " INCREMENT=_F(INST_FIN=1.0, PAS=0.1), SCHEMA_TEMPS=_F(SCHEMA='NEWMARK'))\n"
        "F = RECU_FONCTION(RESU_GENE=TRAN, NOM_CHAM='DEPL', GROUP_NO='N1',\n"
        "                  NOM_CMP='{}')\n"
    )
    for component, expected in (("DQ", [("invalid", "RECU_FONCTION/NOM_CMP")]), ("DX", [])):
        path = deck(tmp_path, body.format(component), name=f"{component}.comm")
        found = [
            (f.kind, f.keyword)
            for f in check_deck(path).findings
            if f.keyword.startswith("RECU_FONCTION")
        ]
        assert found == expected, component


def test_uncomputed_list_given_to_a_keyword_with_min_is_not_counted(tmp_path):
    # ACIER's items come from a command asterlite does not compute: the list
    # itself is unknown, never a one-item list ("at least 2 values, got 1")
    path = deck(
        tmp_path,
        "ACIER = [None] * 2\n"
        "ACIER[0] = DEFI_MATERIAU(ELAS=_F(E=1.0, NU=0.3), PRAGER=_F(C=1.0))\n"
        "T = TEST_COMPOR(OPTION='MECA', COMPORTEMENT=_F(RELATION='VMIS_ECMI_LINE'),"
        " LIST_MATER=ACIER, YOUNG=1.0, POISSON=0.3, VARI_TEST=('V1',))\n",
    )
    check = check_deck(path)
    assert not [f for f in check.findings if f.kind == "invalid"], [
        f.text() for f in check.findings
    ]


def test_keyword_of_several_undetermined_blocks_takes_any_definition(tmp_path):
    # the result is not computed: CALC_CHAMP's blocks on its type are all
    # undetermined, and VARI_ELNO is valid in the non-linear one only
    path = deck(
        tmp_path,
        "U = STAT_NON_LINE(MODELE=MO, CHAM_MATER=CM, EXCIT=_F(CHARGE=CH),"
        " INCREMENT=_F(LIST_INST=L))\n"
        "U = CALC_CHAMP(reuse=U, RESULTAT=U, VARI_INTERNE='VARI_ELNO')\n",
    )
    check = check_deck(path)
    assert not [f for f in check.findings if f.keyword.startswith("CALC_CHAMP")], [
        f.text() for f in check.findings
    ]


def test_run_refuses_the_component_check_reports(tmp_path):
    # run stops at the call with check's finding, before computing it
    # (RECU_FONCTION would otherwise give an all-zero function for 'DQ')
    from asterlite.runtime.runner import run_deck

    sample = Path(__file__).parents[1] / "samples" / "friction_oscillator"
    text = (sample / "friction_oscillator.comm").read_text()
    text = text[: text.index("DEPLPHYS = ")]
    text += (
        "F = RECU_FONCTION(RESULTAT=MODES, NOM_CHAM='DEPL', GROUP_NO='N1',\n"
        "                  NOM_CMP='DQ', TOUT_ORDRE='OUI')\nFIN()\n"
    )
    (tmp_path / "m.comm").write_text(text)
    (tmp_path / "m.mail").write_text((sample / "friction_oscillator.mail").read_text())
    (tmp_path / "m.export").write_text("F comm m.comm D 1\nF mail m.mail D 20\n")
    report = run_deck(tmp_path / "m.export", tmp_path / "out")
    assert report.exit_code == 2
    assert "'DQ' is not a component of DEPL" in report.message
    line = text.count("\n", 0, text.index("NOM_CMP='DQ'")) + 1
    assert f"m.comm:{line}" in report.message, report.message


def test_a_file_associated_without_a_unit_gets_a_free_one(tmp_path):
    # code_aster's ulnume: the highest free unit of 99..70, returned by DEFI_FICHIER
    from asterlite.runtime.runner import run_deck

    path = deck(
        tmp_path,
        "T = CREA_TABLE(LISTE=_F(PARA='X', LISTE_R=(1.0, 2.0)))\n"
        "U = DEFI_FICHIER(ACTION='ASSOCIER', FICHIER='t.txt')\n"
        "V = DEFI_FICHIER(ACTION='ASSOCIER', FICHIER='v.txt')\n"
        "IMPR_TABLE(UNITE=U, TABLE=T)\n"
        "DEFI_FICHIER(ACTION='LIBERER', UNITE=U)\n"
        "W = CREA_TABLE(LISTE=_F(PARA='U', LISTE_I=(U, V)))\n"
        "TEST_TABLE(TABLE=W, NOM_PARA='U', TYPE_TEST='SOMM', VALE_CALC_I=197,\n"
        "           REFERENCE='ANALYTIQUE', VALE_REFE_I=197)\n",
    )
    assert kinds(check_deck(path)) == []
    report = run_deck(path, tmp_path / "out")
    assert report.status == "PASS", report.message
    assert "X" in (tmp_path / "out" / "t.txt").read_text()


def test_a_unit_the_decks_own_python_may_have_written_is_not_judged(tmp_path):
    # open() is refused (UNSUPPORTED); what it wrote (fort.86) check cannot know
    read = "F = LIRE_FONCTION(UNITE=86, NOM_PARA='INST', INDIC_PARA=(1, 1), INDIC_RESU=(1, 2))\n"
    writes = "def write(unit):\n    open('fort.%d' % unit, 'w').write('0 1')\n\nwrite(86)\n"
    invalid = [f.keyword for f in check_deck(deck(tmp_path, read, "r.comm")).findings]
    assert invalid == ["LIRE_FONCTION"]
    found = kinds(check_deck(deck(tmp_path, writes + read, "w.comm")))
    assert found == [("unsupported", "")], found


@pytest.mark.parametrize(
    ("version", "call", "expected"),
    [
        (17, "FIN(exit=True)", []),
        (17, "FIN(atexit=True)", []),
        (15, "FIN(exit=True)", []),
        (15, "FIN(atexit=True)", [("invalid", "FIN/atexit")]),  # 15's wrapper takes exit only
        (11, "FIN(exit=True)", [("invalid", "FIN/exit")]),
    ],
)
def test_arguments_fin_takes_before_its_syntax_is_checked(tmp_path, version, call, expected):
    from asterlite.runtime.runner import run_deck

    path = tmp_path / "f.comm"
    path.write_text(f"DEBUT()\n{call}\nraise RuntimeError('after FIN')\n")
    assert kinds(check_deck(path, aster_version=version)) == expected
    if version == 17:  # asterlite's FIN ends the deck: what follows is never run
        assert run_deck(path, tmp_path / "out").status == "DONE"


def test_a_list_filled_by_a_statement_check_could_not_finish_is_unknown(tmp_path):
    # the loop stops at eval (not provided): MODELS[i] was maybe assigned, so
    # MODELS is unknown, not the [None] it was made as
    path = deck(
        tmp_path,
        "MODELS = [None] * 2\n"
        "for i in range(2):\n"
        "    x = eval('1.0')\n"
        "    MODELS[i] = i\n"
        "T = CREA_TABLE(LISTE=_F(PARA='X', LISTE_R=MODELS[0]))\n",
    )
    assert ("invalid", "CREA_TABLE/LISTE[1]/LISTE_R") not in kinds(check_deck(path))
    assert [kind for kind, _ in kinds(check_deck(path))] == ["unsupported-python"]


@pytest.mark.parametrize(("version", "expected"), [(15, []), (17, [("invalid", "IMPR_TABLE/TRI")])])
def test_a_factor_keyword_without_max_takes_one_occurrence_from_16_on(tmp_path, version, expected):
    # code_aster 15's SyntaxChecker: no max means any number; 17's: one
    path = deck(
        tmp_path,
        "T = CREA_TABLE(LISTE=(_F(PARA='A', LISTE_R=(1.0, 2.0)),\n"
        "                      _F(PARA='B', LISTE_R=(3.0, 4.0))))\n"
        "IMPR_TABLE(TABLE=T, TRI=(_F(NOM_PARA='A'), _F(NOM_PARA='B')))\n",
    )
    found = [k for k in kinds(check_deck(path, aster_version=version)) if k[0] == "invalid"]
    assert found == expected


@pytest.mark.parametrize(
    "flow",
    [
        "if x == 0:\n    V = 1.0\nelif x == 1:\n    V = 2.0\n",
        "while x < 3:\n    V = 1.0\n    x = x + 1\n",
    ],
)
def test_names_bound_under_a_condition_check_cannot_compute_are_unknown(tmp_path, flow):
    # x is not computed (eval is not provided): either branch may run, so V may
    # be bound; check runs neither and judges nothing that uses V
    path = deck(
        tmp_path,
        "x = eval('1')\nV = None\n"
        + flow
        + "T = CREA_TABLE(LISTE=_F(PARA='X', LISTE_R=V))\nraise ValueError('not reached?')\n",
    )
    assert [kind for kind, _ in kinds(check_deck(path))] == ["unsupported-python"] * 2
