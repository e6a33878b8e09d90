"""What the compiled loop records and reports besides the state: the step
history of each archived instant (PTEM), step rejections, pauses for
progress reports, the step budget of adaptive runs and the archive past
its memory limit."""

import io
import math
import re

import numpy as np
import pytest

from asterlite import progress
from asterlite.dynamics import integrate as I
from asterlite.errors import NumericalError
from tests.test_dynamics_vibra import friction_shock, kws, one_mode, run_vibra, vector

OMEGA = 2.0 * math.pi


def adaptive_oscillator(scheme="RUNGE_KUTTA_32", pas=0.2, **schema):
    gnum, m, kk = one_mode(OMEGA**2, coords=(0.0, 0.0, 0.0), shape=(1.0, 0.0, 0.0))
    return run_vibra(
        m,
        kk,
        scheme,
        pas,
        2.0,
        etat={"VITE": vector(gnum, OMEGA, "VITE")},
        schema={"TOLERANCE": 1.0e-6, **schema},
    )


def test_every_archived_instant_records_the_step_that_led_to_it():
    result = adaptive_oscillator()
    steps, rejected = result.step_sizes, result.rejections
    assert steps.shape == rejected.shape == result.times.shape
    # adaptive runs archive every step: the steps add up to the instants,
    # except before INST_FIN, where the step shortened to land on it may
    # itself be cut by the error control (the cut step is not archived)
    np.testing.assert_allclose(np.diff(result.times)[:-1], steps[1:-1], rtol=1e-12, atol=1e-15)
    assert steps[-1] <= np.diff(result.times)[-1] * (1 + 1e-12)
    assert steps[1:].min() == pytest.approx(result.info["min_step"])
    assert steps[1:].max() == pytest.approx(result.info["max_step"])
    # PAS=0.2 is far too large for the tolerance: rejections at the start,
    # counted cumulatively and ending at the run's total
    assert np.all(np.diff(rejected) >= 0)
    assert rejected[-1] == result.info["rejected_steps"] > 0


def test_fixed_step_history_is_the_step_and_the_shortened_ones():
    gnum, m, kk = one_mode(OMEGA**2)
    result = run_vibra(
        m,
        kk,
        "DIFF_CENTRE",
        1.0e-3,
        0.1,
        ARCHIVAGE=[kws("DYNA_VIBRA/ARCHIVAGE", INST=(0.0505,))],
    )
    assert set(np.round(result.step_sizes / 1.0e-3, 9)) <= {0.5, 1.0}
    shortened = result.step_sizes[np.isclose(result.times, 0.0505)]
    assert shortened == pytest.approx([5.0e-4])  # the step cut to land on INST
    assert np.all(result.rejections == 0)


def test_recu_fonction_ptem_gives_the_step_history():
    from asterlite.commands import recu_fonction

    from tests.test_dynamics_vibra import ctx

    result = adaptive_oscillator()
    produced = recu_fonction.run(
        ctx("RECU_FONCTION"), kws("RECU_FONCTION", RESU_GENE=result, NOM_CHAM="PTEM")
    )
    np.testing.assert_array_equal(produced.abscissas, result.times)
    np.testing.assert_array_equal(produced.ordinates, result.step_sizes)


def test_pausing_the_loop_often_changes_nothing(monkeypatch):
    """The loop pauses after every chunk of steps (progress, budget): the
    results are bit-identical whatever the chunk."""
    reference = adaptive_oscillator("RUNGE_KUTTA_54", 0.01)
    monkeypatch.setattr(I.StepBudget, "FIRST_CHUNK", 7)
    monkeypatch.setattr(I.StepBudget, "resize_chunk", lambda self, seconds: None)
    paused = adaptive_oscillator("RUNGE_KUTTA_54", 0.01)
    np.testing.assert_array_equal(paused.depl, reference.depl)
    np.testing.assert_array_equal(paused.step_sizes, reference.step_sizes)
    assert paused.info["steps"] == reference.info["steps"] > 7


def test_an_adaptive_run_whose_step_collapses_stops_on_its_step_budget(monkeypatch):
    """Stick-slip under a tight tolerance: the step collapses; the run stops
    with a message naming the time reached and the way out, not after
    filling the memory."""
    monkeypatch.setattr(I.StepBudget, "MIN_STEPS", 500)  # the budget: 2 x 400 steps
    monkeypatch.setattr(I.StepBudget, "STEP_FACTOR", 2)
    monkeypatch.setattr(I.StepBudget, "FIRST_CHUNK", 100)
    gnum, m, kk = one_mode(1.0e4)
    with pytest.raises(NumericalError) as raised:
        run_vibra(
            m,
            kk,
            "RUNGE_KUTTA_54",
            5.0e-4,
            0.2,
            etat={"DEPL": vector(gnum, 0.85e-3)},
            comportement=[friction_shock()],
            schema={"TOLERANCE": 1.0e-12},
        )
    message = str(raised.value)
    assert "step budget exhausted" in message
    assert "PAS_MINI" in message and "DIFF_CENTRE" in message


def test_an_archive_past_its_memory_limit_goes_to_disk(monkeypatch):
    """Past its limit the archive is written out by chunks while the loop
    runs (asterlite.dynamics.archive_store): the same result."""
    gnum, m, kk = one_mode(OMEGA**2)
    held = run_vibra(m, kk, "DIFF_CENTRE", 1.0e-4, 10.0)
    monkeypatch.setattr(I.StepBudget, "ARCHIVE_BYTES", 200_000)
    written = run_vibra(m, kk, "DIFF_CENTRE", 1.0e-4, 10.0)
    assert written.info["archive_on_disk"] and not held.info["archive_on_disk"]
    assert written.depl.nbytes > 200_000
    for name in ("times", "order", "depl", "vite", "acce", "step_sizes"):
        np.testing.assert_array_equal(getattr(written, name), getattr(held, name))


def test_an_adaptive_archive_goes_to_disk_past_the_memory_limit(monkeypatch):
    """Adaptive runs archive into buffers that grow: 4096 instants of 56
    bytes fit the limit, the 8192 of the next growth would not: the 4096
    are written out instead, and the buffers filled again."""
    gnum, m, kk = one_mode(OMEGA**2, coords=(0.0, 0.0, 0.0), shape=(1.0, 0.0, 0.0))
    etat = {"VITE": vector(gnum, OMEGA, "VITE")}
    held = run_vibra(m, kk, "RUNGE_KUTTA_32", 1.0e-3, 40.0, etat=etat)
    monkeypatch.setattr(I.StepBudget, "ARCHIVE_BYTES", 300_000)
    written = run_vibra(m, kk, "RUNGE_KUTTA_32", 1.0e-3, 40.0, etat=etat)
    assert written.info["archive_on_disk"] and len(written.times) > 4096
    for name in ("times", "order", "depl", "vite", "acce", "step_sizes", "rejections"):
        np.testing.assert_array_equal(getattr(written, name), getattr(held, name))


def test_the_time_bar_shows_simulated_time_and_steps_per_second(monkeypatch):
    monkeypatch.setattr(progress, "DELAY", 0.0)
    stream = io.StringIO()
    bar = progress.TimeBar("DYNA_VIBRA TRAN DIFF_CENTRE", 0.0, 2.0, stream=stream)
    bar.update(1.0, 5000)
    bar.close()
    text = stream.getvalue()
    assert "DYNA_VIBRA TRAN DIFF_CENTRE" in text and "50%" in text
    assert re.search(r"1/2 s simulated, [\d,]+ steps/s", text)


def test_no_bar_off_a_terminal(monkeypatch):
    progress.enable(None)
    monkeypatch.delenv("ASTERLITE_PROGRESS", raising=False)
    monkeypatch.setattr("sys.stderr", io.StringIO())  # not a terminal
    assert isinstance(progress.time_bar("x", 0.0, 1.0), progress.NoBar)
    assert isinstance(progress.count_bar("x", 3), progress.NoBar)


def test_bars_follow_the_switch_and_the_environment(monkeypatch):
    class Terminal(io.StringIO):
        def isatty(self):
            return True

    monkeypatch.setattr("sys.stderr", Terminal())
    try:
        assert isinstance(progress.time_bar("x", 0.0, 1.0), progress.TimeBar)
        monkeypatch.setenv("ASTERLITE_PROGRESS", "0")
        assert isinstance(progress.time_bar("x", 0.0, 1.0), progress.NoBar)
        progress.enable(True)
        assert isinstance(progress.count_bar("x", 2), progress.CountBar)
        progress.enable(False)
        assert isinstance(progress.count_bar("x", 2), progress.NoBar)
    finally:
        progress.enable(None)
