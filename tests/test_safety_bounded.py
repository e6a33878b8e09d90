"""A study someone sent you is bounded in every dimension (issue 26, part C):
inputs that are not regular files are refused before they are read, sizes
are checked before anything is allocated or decompressed, numpy never holds
arrays of Python objects, the memory limit holds while deck code runs and a
SIGXCPU ends the run with its status. Each case ends quickly with a located
error, the process alive."""

from __future__ import annotations

import json
import os
import signal
import subprocess
import sys
import threading
import time
from pathlib import Path

import pytest

from asterlite.runtime.runner import run_deck

SAMPLE_MESH = Path(__file__).resolve().parents[1] / "samples" / "friction_oscillator"


def run_text(tmp_path: Path, body: str, **options):
    deck = tmp_path / "d.comm"
    deck.write_text("DEBUT()\n" + body + "FIN()\n")
    start = time.monotonic()
    report = run_deck(deck, tmp_path / "out", **options)
    return report, time.monotonic() - start, deck


# ------------------------------------------------------------ input files


@pytest.fixture
def fifo(tmp_path):
    """A FIFO, and a rescuer that opens its other end after 20 s so that code
    that (wrongly) waits on it fails the test instead of hanging."""
    path = tmp_path / "pipe.mail"
    os.mkfifo(path)
    done = threading.Event()

    def rescue():
        if done.wait(20):
            return
        while not done.is_set():
            try:
                os.close(os.open(path, os.O_WRONLY | os.O_NONBLOCK))
            except OSError:
                time.sleep(0.05)

    threading.Thread(target=rescue, daemon=True).start()
    yield path
    done.set()


def _readers():
    from asterlite.io.aster_mesh import read_aster_mesh
    from asterlite.io.export import read_export
    from asterlite.io.ideas_mesh import read_ideas_mesh
    from asterlite.io.input_files import read_bounded_text, read_deck_text
    from asterlite.io.med_mesh import read_med_mesh
    from asterlite.io.med_result import read_nodal_field

    return {
        "ASTER mesh": read_aster_mesh,
        "I-DEAS mesh": read_ideas_mesh,
        "MED mesh": read_med_mesh,
        "MED result (LIRE_RESU)": lambda path: read_nodal_field(path, "DEPL"),
        "function file (LIRE_FONCTION)": lambda path: read_bounded_text(path, "function file", 30),
        "deck, INCLUDE_MATERIAU, helper module": read_deck_text,
        "export": read_export,
    }


@pytest.mark.parametrize("reader", sorted(_readers()))
def test_every_reader_refuses_a_fifo_without_waiting(fifo, reader):
    start = time.monotonic()
    with pytest.raises(Exception, match="FIFO") as caught:
        _readers()[reader](fifo)
    assert time.monotonic() - start < 10
    assert str(fifo) in str(caught.value) or fifo.name in str(caught.value)


def test_a_device_is_refused_before_it_is_opened(tmp_path):
    from asterlite.io.aster_mesh import AsterMeshError, read_aster_mesh

    link = tmp_path / "null.mail"
    link.symlink_to("/dev/null")  # reads as empty text: refused all the same
    with pytest.raises(AsterMeshError, match="character device"):
        read_aster_mesh(link)


def test_a_fifo_swapped_in_after_the_check_is_refused_on_its_descriptor(fifo, monkeypatch):
    """The stat before opening saw a regular file; the descriptor's fstat
    catches the FIFO, and opening it with O_NONBLOCK did not wait."""
    from asterlite.io import input_files

    monkeypatch.setattr(input_files, "check_regular_file", lambda path, what: 0)
    start = time.monotonic()
    with pytest.raises(input_files.NotARegularFileError, match="FIFO"):
        input_files.read_bounded_text(fifo, "mesh", 40)
    assert time.monotonic() - start < 10


def test_an_export_naming_a_fifo_is_refused_at_its_line(tmp_path, fifo):
    (tmp_path / "d.comm").write_text(
        "DEBUT()\nMA = LIRE_MAILLAGE(FORMAT='ASTER', UNITE=20)\nFIN()\n"
    )
    export = tmp_path / "d.export"
    export.write_text(f"P time_limit 30\nF comm d.comm D 1\nF mail {fifo.name} D 20\n")
    start = time.monotonic()
    report = run_deck(export, tmp_path / "out")
    assert report.status == "ERROR" and report.exit_code == 2, report.message
    assert f"{export}:3" in report.message and "FIFO" in report.message
    assert time.monotonic() - start < 10


def _med_bomb(path: Path, values: int = 300_000_000) -> Path:
    """A MED mesh of a few kB whose coordinates declare ``values`` doubles:
    a chunked, compressed dataset never written (HDF5 returns its fill value)."""
    h5py = pytest.importorskip("h5py")
    step = "ENS_MAA/bomb/-0000000000000000001-0000000000000000001"
    with h5py.File(path, "w") as handle:
        coordinates = handle.create_dataset(
            f"{step}/NOE/COO", shape=(values,), dtype="f8", chunks=(100_000,), compression="gzip"
        )
        coordinates.attrs["NBR"] = values // 3
        handle.create_dataset(f"{step}/MAI/PO1/NOD", data=[1]).attrs["NBR"] = 1
    return path


def test_a_med_file_declaring_gigabytes_is_refused_before_decompressing(tmp_path):
    from asterlite import watchdog
    from asterlite.io.med_mesh import MedMeshError, read_med_mesh
    from asterlite.io.med_result import MedResultError, read_nodal_field

    bomb = _med_bomb(tmp_path / "bomb.med")
    assert bomb.stat().st_size < 100_000
    start = time.monotonic()
    with watchdog.limits(None, 256, compiles=False):
        with pytest.raises(MedMeshError, match="2400 MB of data once decompressed"):
            read_med_mesh(bomb)
        with pytest.raises(MedResultError, match="once decompressed"):
            read_nodal_field(bomb, "DEPL")
    assert time.monotonic() - start < 30


def test_the_med_child_caps_its_own_memory(tmp_path):
    """The child sets its RLIMIT_AS to its size once its libraries are
    loaded plus twice the run's memory limit (handed down by the parent)."""
    script = (
        "import resource\n"
        "from asterlite.io import med_mesh\n"
        "from asterlite import watchdog\n"
        "med_mesh._cap_own_memory()\n"
        "print(resource.getrlimit(resource.RLIMIT_AS)[0], watchdog.address_space_size())\n"
    )
    environment = dict(os.environ, ASTERLITE_MED_MEMORY_MB="100")
    child = subprocess.run(
        [sys.executable, "-c", script], env=environment, capture_output=True, text=True, timeout=120
    )
    assert child.returncode == 0, child.stderr
    cap, size = (int(word) for word in child.stdout.split())
    assert size < cap <= size + 2 * 100 * 2**20 + 2**20


# ------------------------------------------------------ the deck evaluator


SIZE_CASES = {
    # list += extends with any iterable: read within the element limit
    "list += range": ("L = []\nfor i in range(30):\n    L += range(5000000)\n", "sequence length"),
    "list += range, compiled": (
        "def f():\n    L = []\n    for i in range(30):\n        L += range(5000000)\n"
        "    return L\nx = f()\n",
        "sequence length",
    ),
    # the widths and precisions of all the fields add up
    "format widths": ('s = "{:9999999}" * 150\nt = s.format(*range(150))\n', "string length"),
    "% widths": ('s = "%9999999d" * 150\nt = s % tuple(range(150))\n', "string length"),
    "format precisions": ('t = "{:.9999999f}{:.9999999f}".format(1.0, 2.0)\n', "string length"),
    # numpy's like-functions allocate the shape= asked; long strings count in bytes
    "ones_like shape=": ("x = np.ones_like([1.0], shape=(10**5, 10**5))\n", "numpy.ones_like size"),
    "full_like shape=": (
        "x = np.full_like([1.0], 2.0, shape=(10**5, 10**5))\n",
        "numpy.full_like size",
    ),
    "U100 items": ("x = np.zeros(10**6, dtype='U100')\n", "16-byte items"),
    # hexadecimal, octal, binary literals and int(text, base)
    "hex literal": ("x = 0x" + "f" * 2_000_000 + "\n", "integer size in digits"),
    "octal literal": ("x = 0o" + "7" * 20_000 + "\n", "integer size in digits"),
    "binary literal": ("x = 0b" + "1" * 40_000 + "\n", "integer size in digits"),
    "int(text, 16)": ('x = int("f" * 2000000, 16)\n', "integer size in digits"),
    "int(text, base=2)": ('x = int("1" * 200000, base=2)\n', "integer size in digits"),
}


@pytest.mark.parametrize("case", sorted(SIZE_CASES))
def test_sizes_are_checked_before_allocation(tmp_path, case):
    body, expected = SIZE_CASES[case]
    report, seconds, deck = run_text(tmp_path, "import numpy as np\n" + body)
    assert report.status == "ERROR" and report.exit_code == 2, report.message
    assert expected in report.message and f"{deck}:" in report.message
    assert seconds < 30


@pytest.mark.parametrize(
    "body",
    [
        "x = np.array([10**30] * 10)\n",
        "x = np.sum([10**30] * 1000)\n",
        "x = np.array([1.0, None])\n",
        "x = np.full(3, None)\n",
        "x = np.full(3, 10**30)\n",
        "x = np.zeros(3, dtype='O')\n",
        "x = np.ones(3).astype('O')\n",
        "x = np.ones(3) + [10**30, 1, 1]\n",
        "def f(a):\n    return np.array(a)\nx = f([1, 'a', None])\n",
    ],
)
def test_numpy_arrays_of_objects_are_refused(tmp_path, body):
    """numpy loops over Python objects in C, where no CPU timer can stop it."""
    report, _, deck = run_text(tmp_path, "import numpy as np\n" + body)
    assert report.status == "ERROR" and report.exit_code == 2, report.message
    assert "numpy arrays of Python objects" in report.message and f"{deck}:" in report.message


@pytest.mark.parametrize(
    "body",
    [
        'print("{0[0].session.output_dir}".format([DEBUT]))\n',
        'print("{0[x].session}".format({"x": DEBUT}))\n',
        'print("{a[0][0].session}".format(a=[[DEBUT]]))\n',
        'print("{0[0].upper}".format(["text"]))\n',
    ],
)
def test_every_accessor_of_a_format_field_is_checked(tmp_path, body):
    report, _, deck = run_text(tmp_path, body)
    assert report.status == "ERROR" and "format fields may" in report.message, report.message
    assert f"{deck}:2" in report.message
    log = (tmp_path / "out" / "message.log").read_text()
    assert str(tmp_path / "out") not in log


def test_plain_format_fields_still_work(tmp_path):
    body = 'x = "{0.real}|{1[1]:>3}|{k[a]}|{0:.2f}".format(1.5, [1, 2], k={"a": 3})\nprint(x)\n'
    body += 'print("%5.1f|%s" % (2.5, "z"))\n'
    report, _, _ = run_text(tmp_path, body)
    assert report.status == "DONE", report.message
    log = (tmp_path / "out" / "message.log").read_text()
    assert "1.5|  2|3|1.50" in log and "  2.5|z" in log


# ------------------------------------------------------ the run's limits


def _cli(deck: Path, out: Path, *options: str) -> subprocess.Popen:
    command = [sys.executable, "-m", "asterlite", "run", str(deck), "-o", str(out), "-q"]
    pipes = {"stdout": subprocess.PIPE, "stderr": subprocess.PIPE, "text": True}
    return subprocess.Popen(command + list(options), **pipes)


def test_the_memory_limit_holds_while_deck_code_runs(tmp_path):
    """A deck loop used to grow to the address-space cap (four times the
    limit) and end as 'MemoryError'; resident memory is now sampled."""
    deck = tmp_path / "d.comm"
    deck.write_text(
        'DEBUT()\nL = []\nwhile True:\n    L.append("x" * 1000000 + str(len(L)))\nFIN()\n'
    )
    child = _cli(deck, tmp_path / "out", "--memory-limit", "100")
    _, stderr = child.communicate(timeout=120)
    assert child.returncode == 2, stderr
    summary = json.loads((tmp_path / "out" / "summary.json").read_text())
    message = summary.get("message", "") + stderr
    assert "memory limit exceeded" in message and f"{deck}:4" in message
    held = int(message.split("the run holds ")[1].split(" MB")[0])
    assert held < 2 * 100


def test_sigxcpu_ends_the_run_with_its_status(tmp_path):
    """The soft RLIMIT_CPU's SIGXCPU used to kill the process (summary.json
    left RUNNING); it now stops the run where Python resumes."""
    deck = tmp_path / "d.comm"
    deck.write_text("DEBUT()\nx = 0\nwhile True:\n    x = x + 1\nFIN()\n")
    out = tmp_path / "out"
    child = _cli(deck, out, "--time-limit", "600")
    deadline = time.monotonic() + 60
    while not (out / "summary.json").exists() and time.monotonic() < deadline:
        time.sleep(0.1)
    time.sleep(1.0)
    child.send_signal(signal.SIGXCPU)
    _, stderr = child.communicate(timeout=60)
    assert child.returncode == 2, stderr
    summary = json.loads((out / "summary.json").read_text())
    assert summary["status"] == "ERROR" and "time limit" in summary.get("message", stderr)


def test_compiled_code_that_never_returns_is_ended_soon_after_the_limit(tmp_path):
    """A C loop holding the interpreter (sum() of a long range checks no
    signal) cannot be stopped from Python: SIGVTALRM ends it two grace periods
    past the limit (2 s each for a 1 s limit), not 30 s later as before."""
    script = (
        "from asterlite import watchdog\n"
        "with watchdog.limits(1.0, None, compiles=False):\n"
        "    sum(range(10**13))\n"
    )
    start = time.monotonic()
    child = subprocess.run([sys.executable, "-c", script], capture_output=True, timeout=120)
    assert child.returncode == -signal.SIGVTALRM, child.stderr
    assert time.monotonic() - start < 20


def test_a_compilation_lifts_the_cpu_backstops_and_moves_them():
    """numba's compilation is not the study's time: while it runs neither
    SIGXCPU nor SIGVTALRM may come, and afterwards both move by what it took."""
    import resource

    from asterlite import watchdog

    with watchdog.limits(30.0, None, compiles=False):
        soft_before, hard = resource.getrlimit(resource.RLIMIT_CPU)
        kill_before = signal.getitimer(signal.ITIMER_VIRTUAL)[0]
        watchdog._compile_started()
        assert resource.getrlimit(resource.RLIMIT_CPU)[0] == hard
        assert signal.getitimer(signal.ITIMER_VIRTUAL)[0] == 0.0
        spin = time.process_time() + 0.3
        while time.process_time() < spin:
            pass
        watchdog._compile_ended()
        assert resource.getrlimit(resource.RLIMIT_CPU)[0] >= soft_before + 1
        assert abs(kill_before - signal.getitimer(signal.ITIMER_VIRTUAL)[0]) < 0.1  # paused
    assert signal.getitimer(signal.ITIMER_VIRTUAL)[0] == 0.0  # disarmed after the run


def test_a_denormal_stiffness_gives_its_modes(tmp_path):
    """K = 1e-310 against M = 2: the dense solver's L⁻¹ M L⁻ᵀ overflowed to inf
    (an internal error); the pencil is now solved scaled by powers of two."""
    (tmp_path / "d.mail").write_bytes((SAMPLE_MESH / "friction_oscillator.mail").read_bytes())
    body = (
        "MA = LIRE_MAILLAGE(FORMAT='ASTER')\n"
        "MO = AFFE_MODELE(MAILLAGE=MA, AFFE=_F(TOUT='OUI', PHENOMENE='MECANIQUE', "
        "MODELISATION='DIS_T'))\n"
        "CA = AFFE_CARA_ELEM(MODELE=MO, DISCRET=(_F(GROUP_MA='MASSE', CARA='K_T_D_N', "
        "VALE=(1e-310, 1e-310, 1e-310)), _F(GROUP_MA='MASSE', CARA='M_T_D_N', VALE=2.0)))\n"
        "KE = CALC_MATR_ELEM(MODELE=MO, CARA_ELEM=CA, OPTION='RIGI_MECA')\n"
        "ME = CALC_MATR_ELEM(MODELE=MO, CARA_ELEM=CA, OPTION='MASS_MECA')\n"
        "NU = NUME_DDL(MATR_RIGI=KE)\n"
        "K = ASSE_MATRICE(MATR_ELEM=KE, NUME_DDL=NU)\n"
        "M = ASSE_MATRICE(MATR_ELEM=ME, NUME_DDL=NU)\n"
        "MODES = CALC_MODES(MATR_RIGI=K, MATR_MASS=M, OPTION='PLUS_PETITE', "
        "CALC_FREQ=_F(NMAX_FREQ=3))\n"
    )
    report, _, _ = run_text(tmp_path, body)
    assert report.status == "DONE", report.message
    frequencies = report.namespace["MODES"].frequencies
    exact = (1e-310 / 2.0) ** 0.5 / (2 * 3.141592653589793)
    assert len(frequencies) == 3
    assert all(abs(f - exact) <= 1e-6 * exact for f in frequencies)


def test_message_log_stops_at_32_mb_under_a_print_flood(tmp_path):
    """code_aster's .mess of a long study takes a few MB: message.log stops
    at 32 MB (it was 256) with a line saying so and a located error."""
    body = 's = "x" * 1000000\nfor i in range(40):\n    print(s)\n'
    report, _, deck = run_text(tmp_path, body)
    assert report.status == "ERROR" and report.exit_code == 2, report.message
    assert "message.log would exceed its cap of 32 MB" in report.message
    assert f"{deck}:4" in report.message
    log = tmp_path / "out" / "message.log"
    assert log.stat().st_size < 33_000_000
    assert "message.log stops here" in log.read_text()[-3000:]


def test_a_sigprof_pending_when_the_timer_stops_does_not_restart_it():
    """A SIGPROF that arrives just before the CPU timer is disarmed runs its
    handler afterwards; re-arming the timer there left it running under the
    default disposition, and the next tick killed the process (pytest ended
    with status 155 = 128 + SIGPROF)."""
    import signal

    from asterlite import watchdog

    with watchdog._cpu_timer(100.0):
        pass
    # as inside limits(), whose deadline outlives the timer's own block by a few bytecodes
    watchdog._state.deadline = watchdog._spent() + 100.0
    try:
        watchdog._on_cpu_timer(signal.SIGPROF, None)
        assert signal.getitimer(signal.ITIMER_PROF) == (0.0, 0.0)
    finally:
        signal.setitimer(signal.ITIMER_PROF, 0.0)
        watchdog._state.deadline = None
