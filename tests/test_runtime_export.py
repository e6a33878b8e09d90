"""The .export reader and the bare-deck run description."""

from __future__ import annotations

from pathlib import Path

import pytest

from asterlite.io.export import ExportError, describe_run, read_export


def write(path: Path, text: str) -> Path:
    path.write_text(text)
    return path


def test_export_maps_units_and_decks(tmp_path):
    write(tmp_path / "a.comm", "DEBUT()\nFIN()\n")
    write(tmp_path / "a.com1", "POURSUITE()\nFIN()\n")
    write(tmp_path / "a.mail", "")
    write(tmp_path / "helper.py", "def f():\n    return 1\n")
    export = write(
        tmp_path / "a.export",
        "P time_limit 60\nF comm a.comm D 1\nF comm a.com1 D 1\nF mail a.mail D 20\n"
        "F nom helper.py D 0\nR resu out.resu R 8\n",
    )
    run = read_export(export)
    assert [p.name for p in run.deck_files] == ["a.comm", "a.com1"]
    assert run.units[20].name == "a.mail"
    assert run.helper_modules["helper"].name == "helper.py"
    assert run.parameters["time_limit"] == "60"


def test_export_missing_file_is_located(tmp_path):
    export = write(tmp_path / "b.export", "F comm b.comm D 1\n")
    with pytest.raises(ExportError) as info:
        read_export(export)
    assert "b.comm" in str(info.value) and "b.export:1" in str(info.value)


def test_export_without_deck(tmp_path):
    write(tmp_path / "c.mail", "")
    export = write(tmp_path / "c.export", "F mail c.mail D 20\n")
    with pytest.raises(ExportError, match="names no deck"):
        read_export(export)


def test_bare_deck_finds_sibling_mesh(tmp_path):
    deck = write(tmp_path / "d.comm", "DEBUT()\n")
    write(tmp_path / "d.mail", "")
    run = describe_run(deck)
    assert run.deck_files == [deck.resolve()]
    assert run.units[20].name == "d.mail"


def test_missing_deck(tmp_path):
    with pytest.raises(ExportError, match="no such file"):
        describe_run(tmp_path / "nothing.comm")


def test_a_lines_carry_code_asters_arguments(tmp_path):
    # astest's exports: code_aster's command-line settings (base size, echo, checks)
    write(tmp_path / "a.comm", "DEBUT()\nFIN()\n")
    export = write(
        tmp_path / "a.export",
        "A args --max_print=5000 --max_check=5000\nF comm a.comm D 1\n",
    )
    run = read_export(export)
    assert run.arguments == {"args": "--max_print=5000 --max_check=5000"}
    write(export, "F comm a.comm D 1\nA\n")
    with pytest.raises(ExportError, match="expected 'A <name> <value>'"):
        read_export(export)
    write(export, "F comm a.comm D 1\nQ x y\n")
    with pytest.raises(ExportError, match="expected F, R, P or A"):
        read_export(export)
