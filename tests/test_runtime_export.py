"""The .export reader and the bare-deck run description."""

from __future__ import annotations

import os
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


def test_ncpus_is_the_runs_threads(tmp_path):
    write(tmp_path / "t.comm", "DEBUT()\nFIN()\n")
    two = write(tmp_path / "t.export", "P ncpus 2\nF comm t.comm D 1\n")
    assert read_export(two).threads == 2
    none = write(tmp_path / "u.export", "F comm t.comm D 1\n")
    assert read_export(none).threads == 1  # code_aster's run_aster without P ncpus
    assert describe_run(tmp_path / "t.comm").threads == 1


@pytest.mark.parametrize("value", ["0", "two", "1.5", "", "-1", "5000"])
def test_bad_ncpus_is_refused_where_it_is(tmp_path, value):
    write(tmp_path / "t.comm", "DEBUT()\nFIN()\n")
    export = write(tmp_path / "t.export", f"F comm t.comm D 1\nP ncpus {value}\n")
    with pytest.raises(ExportError, match="P ncpus must be a whole number") as info:
        read_export(export)
    assert "t.export:2" in str(info.value)


def test_a_run_sets_code_asters_thread_variable_before_numpy_loads(tmp_path):
    """`asterlite run` runs on the export's P ncpus threads (OMP_NUM_THREADS,
    which OpenBLAS reads when it loads), whatever the caller's environment."""
    import os
    import subprocess
    import sys

    write(tmp_path / "t.comm", "DEBUT()\nFIN()\n")
    write(tmp_path / "t.export", "P ncpus 3\nF comm t.comm D 1\n")
    probe = (
        "import os, sys\n"
        "from asterlite.cli import main\n"
        f"status = main(['run', {str(tmp_path / 't.export')!r}, '-o', "
        f"{str(tmp_path / 'out')!r}, '-q'])\n"
        "print(status, os.environ.get('OMP_NUM_THREADS'), 'numpy' in sys.modules)\n"
    )
    env = dict(os.environ, OMP_NUM_THREADS="7")
    done = subprocess.run(
        [sys.executable, "-c", probe], capture_output=True, text=True, env=env, timeout=120
    )
    assert done.stdout.split() == ["0", "3", "True"], done.stderr


def test_the_api_leaves_the_callers_threads(monkeypatch):
    import numpy  # noqa: F401  (a caller of the API has its libraries loaded)

    from asterlite.runtime import threads

    monkeypatch.setenv(threads.VARIABLE, "5")
    assert not threads.use_threads(2)  # numpy is loaded in this process
    assert os.environ[threads.VARIABLE] == "5"
    assert not threads.use_threads(None)
