"""asterlite warmup and the compile notices (issue 16, goal 1): every loop
a run can take is one of the kernels the warmup compiles, compiling says so
on standard error, and a run after the warmup compiles nothing."""

from __future__ import annotations

import io
import subprocess
import sys

import numpy as np
import pytest
from numba import njit

from asterlite import progress
from asterlite.dynamics import warmup
from asterlite.dynamics.integrate import loop_kernel
from asterlite.dynamics.schemes import SCHEMES


@pytest.fixture
def notices(monkeypatch):
    stream = io.StringIO()
    monkeypatch.setattr(progress, "notice_stream", stream)
    return stream


def test_a_compile_inside_a_kernel_block_is_announced_once(notices):
    @njit(cache=False)
    def doubled(x):
        return 2.0 * x

    with progress.kernel("TEST", 7.0) as notice:
        assert doubled(1.5) == 3.0
        assert doubled(2.5) == 5.0  # same signature: nothing more to compile
    lines = notices.getvalue().splitlines()
    assert lines[0] == "asterlite: compiling the TEST kernel, once per install: ~7 s"
    assert lines[1].startswith("asterlite: compiled the TEST kernel in ")
    assert len(lines) == 2 and notice.seconds > 0.0
    with progress.kernel("TEST", 7.0) as again:  # compiled now: silent
        doubled(4.0)
    assert len(notices.getvalue().splitlines()) == 2 and again.seconds == 0.0


def test_a_compile_outside_any_block_names_the_function(notices):
    progress.listen_to_compiles()

    @njit(cache=False)
    def tripled(x):
        return 3.0 * x

    tripled(1.0)
    text = notices.getvalue()
    assert "compiling tests.test_warmup." in text and "tripled, once per install" in text
    assert "compiled tests.test_warmup." in text


@pytest.mark.parametrize("scheme", sorted(SCHEMES))
def test_every_loop_a_run_can_take_is_warmed_up(scheme):
    diagonal, full = warmup.tiny_system(True), warmup.tiny_system(False)
    shocks = warmup.tiny_shocks(diagonal)
    rotation = warmup.tiny_rotation(diagonal, 0.01, 1.0e-4)
    names = {
        loop_kernel(scheme, diagonal, shocks),
        loop_kernel(scheme, full, shocks),
        loop_kernel(scheme, diagonal, shocks, specialised=False),
        loop_kernel(scheme, diagonal, shocks, rotation=rotation),
        loop_kernel(scheme, diagonal, shocks, implicit=True),
        loop_kernel(scheme, diagonal, shocks, legacy_adapt=True),  # code_aster 10-12
    }
    assert names <= set(warmup.LOOPS)


def test_warmed_up_kernels_serve_a_deck_without_compiling():
    """A DYNA_VIBRA run (through the command, with its own model) after the
    warmup of its kernel compiles nothing: the warmup's tiny problem has the
    same argument types as the deck's."""
    from tests.test_dynamics_vibra import obstacle, one_mode, run_vibra, vector

    for name in (warmup.SHARED, "NEWMARK"):
        warmup.warm_one(name)
    gnum, m, kk = one_mode(1.0, coords=(0.0, 0.0, 0.0), shape=(0.0, 1.0, 0.0))
    stop = dict(RELATION="DIS_CHOC", NOEUD_1="NO1", OBSTACLE=obstacle("PLAN_Y"),
                ORIG_OBST=(0.0, 0.0, 0.0), NORM_OBST=(1.0, 0.0, 0.0), JEU=0.01,
                RIGI_NOR=1.0e6)  # fmt: skip
    before = progress.compiled_seconds()
    result = run_vibra(m, kk, "NEWMARK", 1.0e-3, 0.05, etat={"VITE": vector(gnum, 1.0, "VITE")},
                       comportement=[stop])  # fmt: skip
    assert progress.compiled_seconds() == before
    assert result.info["compile_seconds"] == 0.0
    assert np.all(np.isfinite(result.depl))


def test_warmup_is_a_command():
    out = subprocess.run(
        [sys.executable, "-m", "asterlite", "warmup", "--help"],
        capture_output=True,
        text=True,
        check=True,
    )
    assert "--jobs" in out.stdout


def test_kernel_argument_types_do_not_depend_on_the_model():
    """One mode or several, matrices in any memory order: the bundles have
    the same numba types (a read-only or Fortran-ordered array would be
    another compilation at a deck's first run)."""
    from numba import typeof

    from asterlite.dynamics.model import LinearSystem, local_bundle

    one = LinearSystem(np.eye(1), np.array([[4.0]]), np.array([[0.1]]))
    two = warmup.tiny_system(True)
    fortran = LinearSystem(
        np.asfortranarray(two.mass), np.asfortranarray(two.stiffness), two.damping.T
    )
    for system in (one, fortran):
        assert typeof(system.bundle()) == typeof(two.bundle())
        shocks, reference = warmup.tiny_shocks(two), warmup.tiny_shocks(two)
        assert typeof(local_bundle(system, shocks)) == typeof(local_bundle(two, reference))
    assert all(array.flags.writeable for array in one.kernel_matrices())


def test_a_kernel_that_fails_is_reported_not_raised():
    warmed = warmup.warm_one("NO_SUCH_SCHEME")
    assert warmed.error is not None and "KeyError" in warmed.error
