"""Untrusted input files: a damaged MED file never crashes the run (it is
validated with h5py and read in a child process), oversized text inputs are
refused before they are read."""

from __future__ import annotations

import random
import shutil
from pathlib import Path

import pytest

from asterlite.io import med_mesh as med_reader
from asterlite.io.aster_mesh import AsterMeshError, read_aster_mesh
from asterlite.io.med_mesh import MedMeshError, read_med_mesh
from asterlite.runtime.runner import run_deck
from tests.conftest import CORPUS

MED = CORPUS / "forma02d" / "forma02d.mmed"
needs_corpus = pytest.mark.skipif(not MED.exists(), reason="corpus absent")


@needs_corpus
def test_a_sound_med_file_reads_as_before():
    mesh = read_med_mesh(MED)
    assert mesh.n_nodes == 31 and mesh.n_cells == 30


@needs_corpus
def test_mutated_med_files_give_errors_never_crashes(tmp_path):
    rng = random.Random(17)
    data = MED.read_bytes()
    outcomes = set()
    for number in range(12):
        damaged = bytearray(data)
        for _ in range(rng.randint(1, 8)):
            damaged[rng.randrange(len(damaged))] = rng.randrange(256)
        path = tmp_path / f"m{number}.med"
        path.write_bytes(bytes(damaged))
        try:
            read_med_mesh(path)
            outcomes.add("read")
        except MedMeshError as error:
            assert str(path) in str(error)
            outcomes.add("error")
    assert "error" in outcomes


def test_a_crash_of_the_reader_becomes_a_located_error(tmp_path, monkeypatch):
    """Whatever kills the child (here a SIGSEGV on purpose), the run gets an error."""
    path = tmp_path / "x.med"
    path.write_bytes(b"not hdf5")
    script = tmp_path / "crash.py"
    script.write_text("import os, signal\nos.kill(os.getpid(), signal.SIGSEGV)\n")
    monkeypatch.setattr(med_reader.sys, "executable", str(_python_running(script)))
    # a reading server that dies at once is started again, then given up for
    # one new Python per file, which dies too
    med_reader._ReadingServer.stop()
    try:
        with pytest.raises(MedMeshError, match="crashed reading this file \\(SIGSEGV\\)"):
            read_med_mesh(path)
    finally:
        med_reader._ReadingServer.stop()


def test_the_reading_server_reports_its_child_killed_or_late():
    """What the server answers for a forked child (the reader) that a signal
    ends, and for one still running at its deadline (killed)."""
    import os
    import signal
    import time

    crashed = os.fork()
    if crashed == 0:
        os.kill(os.getpid(), signal.SIGSEGV)
        os._exit(0)
    assert med_reader._wait_child(crashed, 30.0) == {"status": -signal.SIGSEGV}
    late = os.fork()
    if late == 0:
        time.sleep(60)
        os._exit(0)
    start = time.monotonic()
    assert med_reader._wait_child(late, 0.2) == {"timeout": True}
    assert time.monotonic() - start < 10


def _python_running(script: Path) -> Path:
    """An executable that runs ``script`` whatever its arguments."""
    import sys

    launcher = script.with_suffix(".sh")
    launcher.write_text(f"#!/bin/sh\nexec {sys.executable} {script}\n")
    launcher.chmod(0o755)
    return launcher


@needs_corpus
def test_a_damaged_med_mesh_is_a_located_deck_error(tmp_path):
    damaged = bytearray(MED.read_bytes())
    damaged[: len(damaged) // 2] = bytes(len(damaged) // 2)
    (tmp_path / "m.mmed").write_bytes(bytes(damaged))
    deck = tmp_path / "d.comm"
    deck.write_text("DEBUT()\nMA = LIRE_MAILLAGE(FORMAT='MED', UNITE=20)\nFIN()\n")
    export = tmp_path / "d.export"
    export.write_text("F comm d.comm D 1\nF mmed m.mmed D 20\n")
    report = run_deck(export, tmp_path / "out")
    assert report.status == "ERROR" and report.exit_code == 2
    assert f"{deck}:2" in report.message and "m.mmed" in report.message


def test_a_mesh_too_large_for_the_memory_limit_is_refused_before_reading(tmp_path, monkeypatch):
    from asterlite import watchdog

    path = tmp_path / "big.mail"
    lines = [f"N{i} {i}.0 0.0 0.0" for i in range(60000)]
    path.write_text("COOR_3D\n" + "\n".join(lines) + "\nFINSF\nFIN\n")
    monkeypatch.setattr(watchdog, "memory_limit_mb", lambda: 10)
    with pytest.raises(AsterMeshError, match="beyond the run's memory limit of 10 MB"):
        read_aster_mesh(path)


def test_copying_a_corpus_med_keeps_reading(tmp_path):
    if not MED.exists():
        pytest.skip("corpus absent")
    copy = tmp_path / "copy.med"
    shutil.copyfile(MED, copy)
    assert read_med_mesh(copy).n_nodes == 31
