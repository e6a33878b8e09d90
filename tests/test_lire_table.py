"""LIRE_TABLE: the TABLEAU, LIBRE and ASTER layouts as code_aster 17 reads
them (asterlite.io.table_reader), and the command through a deck."""

from __future__ import annotations

from pathlib import Path

import pytest

from asterlite.io.table_reader import TableFileError, read_table
from asterlite.runtime.runner import run_deck

# sdls140c.52's layout: a comment, the names, rows of reals
TABLEAU = """#MERGE avec labels=['EPSI']
EPSI         GG1
 1.00000E-06  1.00000E+00

 3.00000E-06  0.5
"""


def test_tableau_comment_is_the_title_and_reals_are_read():
    table = read_table(TABLEAU, "TABLEAU")
    assert table.columns == ["EPSI", "GG1"]
    assert table.types == ["R", "R"]
    assert table.rows == [{"EPSI": 1e-6, "GG1": 1.0}, {"EPSI": 3e-6, "GG1": 0.5}]
    assert table.title == "#MERGE avec labels=['EPSI']"


def test_libre_reads_a_comment_as_a_line_of_fields():
    # 3 fields then 2: in LIBRE the comment is a block of its own
    with pytest.raises(TableFileError, match="mixes text and numbers|no value"):
        read_table(TABLEAU, "LIBRE")
    assert read_table(TABLEAU, "LIBRE", number=2).columns == ["EPSI", "GG1"]
    with pytest.raises(TableFileError, match="table 3 asked for, the file holds 2"):
        read_table(TABLEAU, "LIBRE", number=3)


def test_blocks_integers_mixed_types_empty_cells_and_text():
    text = "A B C\n1 2 x\n3 4.5 -\n\nN K\n7 long_text_of_twenty\n"
    first = read_table(text, "TABLEAU")
    assert first.columns == ["A", "B", "C"] and first.types == ["I", "R", "K24"]
    assert first.rows == [{"A": 1, "B": 2.0, "C": "x"}, {"A": 3, "B": 4.5}]
    second = read_table(text, "TABLEAU", number=2)
    assert second.types == ["I", "K24"] and second.rows == [{"N": 7, "K": "long_text_of_twenty"}]
    # in LIBRE, '-' is text, not an empty cell
    with pytest.raises(TableFileError, match="column 'C' mixes"):
        read_table("A C\n1 x\n2 -\n3 4\n", "LIBRE")


def test_separator_decimal_comma_and_unique_names():
    text = "X;Y;Y\n1,5;2;3\n"
    with pytest.raises(TableFileError, match="'Y' repeats"):
        read_table(text, "LIBRE", separator=";")
    table = read_table(text, "LIBRE", separator=";", unique=True)
    assert table.columns == ["Y".replace("Y", "X"), "Y", "Y_1"]
    assert table.rows == [{"X": 1.5, "Y": 2, "Y_1": 3}]
    # a tab is not a space: with the default separator the line is one field
    assert read_table("A\tB\n1\t2\n", "LIBRE").columns == ["A\tB".replace(" ", "_")]


def test_aster_layout_types_widths_and_table_number():
    text = (
        "#DEBUT_TABLE\n#TITRE first\nA B\nI R\n1 2.0\n#FIN_TABLE\n"
        "#DEBUT_TABLE\n#TITRE second\nNOM V E\nK8 R R\nab       3.0 -\nlonger12 -4,5 -\n"
        "#FIN_TABLE\n"
    )
    table = read_table(text, "ASTER", number=2)
    assert table.title == "second"
    # the column E has a type but no value: left out, as CREA_TABLE does
    assert table.columns == ["NOM", "V"] and table.types == ["K8", "R"]
    assert table.rows == [{"NOM": "ab", "V": 3.0}, {"NOM": "longer12", "V": -4.5}]
    first = read_table(text, "ASTER")
    assert first.rows == [{"A": 1, "B": 2.0}] and first.types == ["I", "R"]
    with pytest.raises(TableFileError, match="table 3 asked for, the file holds 2"):
        read_table(text, "ASTER", number=3)


def test_aster_layout_refuses_cells_against_their_types():
    with pytest.raises(TableFileError, match="row 1: '1.5 2' does not match"):
        read_table("#DEBUT_TABLE\nA B\nI R\n1.5 2\n#FIN_TABLE\n", "ASTER")
    with pytest.raises(TableFileError, match="'1.0D\\+00' is not read"):
        read_table("#DEBUT_TABLE\nA\nR\n1.0D+00\n#FIN_TABLE\n", "ASTER")
    with pytest.raises(TableFileError, match="unknown type 'C'"):
        read_table("#DEBUT_TABLE\nA\nC\n1\n#FIN_TABLE\n", "ASTER")


def test_non_finite_reals_are_refused():
    with pytest.raises(TableFileError, match="column 'B', row 2: nan is not finite"):
        read_table("A B\n1 2\n3 nan\n", "TABLEAU")


def test_deck_reads_tables_through_the_export(tmp_path: Path):
    (tmp_path / "t.52").write_text(TABLEAU)
    (tmp_path / "t.53").write_text("#DEBUT_TABLE\nN X\nK16 R\nabc              2.5\n#FIN_TABLE\n")
    (tmp_path / "d.comm").write_text(
        "DEBUT()\n"
        "T = LIRE_TABLE(UNITE=52)\n"
        "U = LIRE_TABLE(UNITE=53, FORMAT='ASTER', TITRE='mine')\n"
        "TEST_TABLE(TABLE=T, NOM_PARA='GG1', VALE_CALC=0.5, REFERENCE='ANALYTIQUE',"
        " VALE_REFE=0.5, FILTRE=_F(NOM_PARA='EPSI', VALE=3.e-6))\n"
        "TEST_TABLE(TABLE=U, NOM_PARA='X', VALE_CALC=2.5,"
        " FILTRE=_F(NOM_PARA='N', VALE_K='abc'))\n"
        "V = LIRE_TABLE(UNITE=53, FORMAT='ASTER', NUME_TABLE=2)\n"
        "FIN()\n"
    )
    (tmp_path / "d.export").write_text("F comm d.comm D 1\nF libr t.52 D 52\nF libr t.53 D 53\n")
    report = run_deck(tmp_path / "d.export", tmp_path / "out")
    assert [test.ok for test in report.tests] == [True, True]
    log = (tmp_path / "out" / "message.log").read_text()
    assert "t.53 (unit 53): table 2 asked for, the file holds 1" in log
    assert report.exit_code == 2


def test_title_line_joins_free_titles_and_keeps_aster_lines_apart():
    text = "# first part\n# second part\nA\n1\n"
    assert read_table(text, "TABLEAU").title_line() == "# first part # second part"
    long_line = " ".join(["word"] * 30)  # 149 characters
    table = read_table(f"{long_line}\nA;B\n1;2\n", "LIBRE", separator=";")
    assert table.title_line() == " ".join(["word"] * 16)  # 79 characters, the next word overflows
    aster = "#DEBUT_TABLE\n#TITRE one\n#TITRE two\nA\nI\n1\n#FIN_TABLE\n"
    assert read_table(aster, "ASTER").title_line() == "one"


def test_deck_table_keeps_interior_empty_rows_and_drops_trailing_ones(tmp_path: Path):
    (tmp_path / "t.52").write_text("A B\n1 -\n- -\n2 3\n- -\n")
    (tmp_path / "d.comm").write_text(
        "DEBUT()\nT = LIRE_TABLE(UNITE=52)\n"
        "TEST_TABLE(TABLE=T, NOM_PARA='A', TYPE_TEST='SOMM', VALE_CALC_I=3)\n"
        "TEST_TABLE(TABLE=T, NOM_PARA='B', VALE_CALC=3.0, FILTRE=_F(NOM_PARA='A', VALE_I=2))\n"
        "FIN()\n"
    )
    (tmp_path / "d.export").write_text("F comm d.comm D 1\nF libr t.52 D 52\n")
    report = run_deck(tmp_path / "d.export", tmp_path / "out")
    assert [test.ok for test in report.tests] == [True, True], report.status
    assert (
        "3 rows, 2 parameters read from unit 52" in (tmp_path / "out" / "message.log").read_text()
    )


def test_extracted_columns_have_code_aster_colonne_methods(tmp_path: Path):
    (tmp_path / "t.31").write_text("ALPHA GAMMA\n1 -\n2 1.5\n3 -3.4\n")
    (tmp_path / "d.comm").write_text(
        "DEBUT()\nT = LIRE_TABLE(UNITE=31)\npy = T.EXTR_TABLE()\n"
        "g = py.GAMMA.values()\nk = py.GAMMA.not_none_values()\nd = py.values()\n"
        "ok = g == [None, 1.5, -3.4] and k == [1.5, -3.4] and d['ALPHA'] == [1, 2, 3]\n"
        "TEST_TABLE(TABLE=T, NOM_PARA='ALPHA', TYPE_TEST='SOMM', VALE_CALC_I=6 if ok else 0)\n"
        "FIN()\n"
    )
    (tmp_path / "d.export").write_text("F comm d.comm D 1\nF libr t.31 D 31\n")
    report = run_deck(tmp_path / "d.export", tmp_path / "out")
    assert [test.ok for test in report.tests] == [True], report.status
