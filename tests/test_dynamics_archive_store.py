"""A modal transient's archive past its memory budget: written out to disk
by chunks while the compiled loop runs (asterlite.dynamics.archive_store),
with the numbers of the archive held in memory, bit for bit."""

from __future__ import annotations

import gc
from collections import namedtuple
from contextlib import contextmanager

import numpy as np
import pytest

from asterlite.dynamics import archive_store as AS
from asterlite.dynamics.excitation import tabulate_excitation
from asterlite.dynamics.integrate import integrate
from asterlite.errors import NumericalError
from tests.test_dynamics_specialised import N_MODES, small_shock_problem
from tests.validated import scheme_options

ARRAYS = ("times", "order", "depl", "vite", "acce", "vint", "step_info")


def shock_run(scheme, max_archive_bytes=None, energy=False, tmp_path=None, t_end=0.1, dt=2.0e-5):
    """The small CERCLE problem with friction (many impacts), ``scheme`` at
    step ``dt`` archiving every 3rd step and at two instants."""
    system, shocks, vectors = small_shock_problem()
    loads = [(vectors[0], _Harmonic()), (vectors[1], _Harmonic(0.3))]
    excitation = tabulate_excitation(N_MODES, loads, 0.0, t_end, dt / 2.0)
    options = scheme_options(scheme, max_archive_bytes=max_archive_bytes, archive_folder=tmp_path)
    q0, v0 = np.full(N_MODES, 2.0e-4), np.zeros(N_MODES)
    instants = np.array([0.0123, 0.05001])
    return integrate(
        system, shocks, excitation, scheme, q0, v0, 0.0, t_end, dt, instants, 3, options,
        energy=energy,
    )  # fmt: skip


class _Harmonic:
    """A multiplier known by ``evaluate`` (sampled by windows)."""

    def __init__(self, phase=0.0):
        self.phase = phase

    def evaluate(self, t):
        return 0.5 * np.sin(190.0 * np.asarray(t) + self.phase)


def assert_identical(on_disk, in_memory):
    for name in ARRAYS:
        np.testing.assert_array_equal(getattr(on_disk, name), getattr(in_memory, name), name)
        assert getattr(on_disk, name).dtype == getattr(in_memory, name).dtype
    if in_memory.energy is not None:
        np.testing.assert_array_equal(on_disk.energy, in_memory.energy)
    for key in ("steps", "archived", "rejected_steps", "min_step", "max_step"):
        assert on_disk.info[key] == in_memory.info[key], key


def test_a_fixed_step_archive_past_its_budget_is_written_out_bit_for_bit(tmp_path, monkeypatch):
    """DIFF_CENTRE with the energy balance: the archive of ~1700 instants
    goes to disk from the start, by chunks of 40 kB (many write-outs)."""
    in_memory = shock_run("DIFF_CENTRE", energy=True)
    assert in_memory.info["archive_on_disk"] is False
    row_bytes = 8 * (2 + 3 * N_MODES + in_memory.vint[0].size + 2 + in_memory.energy.shape[1])
    budget = 40_000
    assert in_memory.info["archived"] * row_bytes > 10 * budget
    written = []
    write_out = AS.ArchiveStore.write_out

    def counted(store, buffers, balance, count):
        written.append((len(buffers.times), count))
        write_out(store, buffers, balance, count)

    monkeypatch.setattr(AS.ArchiveStore, "write_out", counted)
    on_disk = shock_run("DIFF_CENTRE", budget, energy=True, tmp_path=tmp_path / "run")
    chunk = budget // row_bytes
    assert len(written) > 10 and all(size == chunk for size, _ in written)  # never grown
    assert sum(count for _, count in written) == on_disk.info["archived"]
    assert on_disk.info["archive_on_disk"] is True
    assert isinstance(on_disk.depl, np.memmap) and isinstance(on_disk.vint, np.memmap)
    fn = on_disk.vint[:, 0, 0]
    assert (fn > 0).any() and (fn == 0).any()  # impacts and flights
    assert_identical(on_disk, in_memory)
    assert (tmp_path / "run").is_dir()  # the files are unnamed: nothing left in the folder
    assert not any((tmp_path / "run").iterdir())


def test_an_adaptive_archive_goes_to_disk_when_it_would_pass_its_budget():
    """RUNGE_KUTTA_32 archives into buffers that double from 4096 rows: past
    the budget they are written out instead, the run goes on unchanged."""
    in_memory = shock_run("RUNGE_KUTTA_32", t_end=0.6)
    assert in_memory.info["archived"] > 4096
    row_bytes = in_memory.depl[0].nbytes * 3 + in_memory.vint[0].nbytes + 32
    on_disk = shock_run("RUNGE_KUTTA_32", 4096 * row_bytes + 1, t_end=0.6)
    assert on_disk.info["archive_on_disk"] is True
    assert_identical(on_disk, in_memory)


def test_an_archive_that_would_not_fit_the_disk_is_refused(monkeypatch):
    usage = namedtuple("usage", "total used free")
    monkeypatch.setattr(AS.shutil, "disk_usage", lambda folder: usage(10**6, 10**6, 10_000))
    with pytest.raises(NumericalError, match="archive disk space.*GB free.*archive less often"):
        shock_run("DIFF_CENTRE", 40_000)


def test_an_archive_file_past_the_runs_output_limit_is_refused(monkeypatch):
    """A run's files are capped at its output limit (the runner's
    RLIMIT_FSIZE): an archive whose largest file would pass it is refused
    before the loop starts, not stopped by the system midway."""
    infinity = AS.resource.RLIM_INFINITY
    monkeypatch.setattr(AS.resource, "getrlimit", lambda which: (50_000, infinity))
    with pytest.raises(NumericalError, match="archive file size.*output limit"):
        shock_run("DIFF_CENTRE", 40_000)


def test_the_memory_budget_is_a_share_of_the_runs_headroom(monkeypatch):
    # an eighth of what the run may still add: with 1 GB left, 128 MB; with
    # 200 MB left (results of earlier transients held), 25 MB
    monkeypatch.setattr(AS.watchdog, "memory_headroom", lambda: 1024**3)
    assert AS.memory_budget(None) == 128 * 1024**2
    assert AS.memory_budget(1000) == 1000
    monkeypatch.setattr(AS.watchdog, "memory_headroom", lambda: 200 * 1024**2)
    assert AS.memory_budget(None) == 25 * 1024**2
    monkeypatch.setattr(AS.watchdog, "memory_headroom", lambda: None)
    assert AS.memory_budget(None) == AS.UNLIMITED_RUN_BYTES


@contextmanager
def _cyclic_garbage_left(objects=300_000):
    """Unreachable cycles that only a collection frees, left while the block
    runs (the automatic collector held off)."""

    class Node:
        pass

    collecting = gc.isenabled()
    gc.disable()
    try:
        for index in range(objects):
            node = Node()
            node.itself, node.data = node, [index] * 5
        del node
        yield
    finally:
        if collecting:
            gc.enable()


def test_the_headroom_counts_what_the_run_holds():
    from asterlite import watchdog

    assert watchdog.memory_headroom() is None  # no limit
    # garbage that a check frees is no growth of the study's
    with _cyclic_garbage_left(), watchdog.limits(None, 400.0):
        before = watchdog.memory_headroom()
        held = np.ones(50 * 1024**2 // 8)  # 50 MB touched
        after = watchdog.memory_headroom()
        assert 0 < before <= 400 * watchdog.MEGABYTE
        assert before - after > 40 * watchdog.MEGABYTE
        del held


def test_doubled_buffers_keep_the_rows_and_leave_the_new_half_zero():
    from asterlite.dynamics.integrate import doubled, grow

    rows = np.arange(12.0).reshape(3, 2, 2)
    grown = doubled(rows)
    assert grown.shape == (6, 2, 2) and grown.dtype == rows.dtype
    np.testing.assert_array_equal(grown[:3], rows)
    assert not grown[3:].any()
    buffers = AS.Archive(*(np.ones((4, 1)) for _ in AS.Archive._fields))
    assert all(len(b) == 8 for b in grow(buffers))


def test_the_pages_of_an_archive_on_disk_are_given_back_and_its_values_kept(monkeypatch):
    from asterlite.io import disk_rows

    rows = disk_rows.DiskRows(3)
    rows.append(np.arange(300.0).reshape(100, 3))
    mapped = rows.array()
    mapped[0, 0] = -1.0  # a value written into the copy-on-write map
    advised = []

    class Region:  # records what release_pages asks of a live map
        def __init__(self, size):
            self.size = size

        def __len__(self):
            return self.size

        def madvise(self, option):
            advised.append(option)

    region = Region(4096)
    assert disk_rows.release_pages() >= mapped.nbytes  # the real map, paged out
    assert mapped[0, 0] == -1.0 and mapped[99, 2] == 299.0  # nothing lost
    monkeypatch.setattr(disk_rows, "_MAPS", [region])
    assert disk_rows.release_pages() == 4096 and advised == [disk_rows.MADV_PAGEOUT]


def test_a_map_no_array_uses_is_no_longer_released():
    from asterlite.io import disk_rows

    rows = disk_rows.DiskRows(2)
    rows.append(np.ones((10, 2)))
    column = rows.array()[:, 1]  # a view keeps the map
    gc.collect()
    held = len(disk_rows._MAPS)
    assert held >= 1
    del column
    gc.collect()
    assert len(disk_rows._MAPS) == held - 1


def test_each_command_gives_the_pages_of_archives_on_disk_back(tmp_path, monkeypatch):
    from asterlite.io import disk_rows
    from asterlite.runtime.runner import run_deck

    calls = []
    monkeypatch.setattr(disk_rows, "release_pages", lambda: calls.append(1) or 0)
    deck = tmp_path / "d.comm"
    deck.write_text(
        "DEBUT()\nL = DEFI_LIST_REEL(VALE=(0.0, 1.0))\nM = DEFI_LIST_REEL(VALE=2.0)\nFIN()\n"
    )
    run_deck(deck, tmp_path / "out")
    assert len(calls) == 2  # asterlite.runtime.result_paging.after_command
