"""The system OpenBLAS's core, named from the CPU while MUMPS loads."""

from __future__ import annotations

import os
import subprocess
import sys

import pytest

from asterlite.fem import sparse_direct, system_openblas

SKYLAKE_X = frozenset("fpu sse2 avx avx2 fma avx512f avx512dq avx512cd avx512bw avx512vl".split())


def test_the_core_follows_the_instruction_sets():
    assert system_openblas.core_for(SKYLAKE_X) == "SkylakeX"
    # AVX-512 foundation alone is not SkylakeX's kernels' set
    assert system_openblas.core_for(frozenset({"avx2", "fma", "avx512f"})) == "Haswell"
    assert system_openblas.core_for(frozenset({"avx2"})) is None
    assert system_openblas.core_for(frozenset()) is None


def test_flags_are_read_from_the_first_cpu(tmp_path):
    info = tmp_path / "cpuinfo"
    info.write_text(
        "processor\t: 0\nmodel\t\t: 207\nflags\t\t: fpu avx2 fma\n\n"
        "processor\t: 1\nflags\t\t: fpu avx512f\n"
    )
    assert system_openblas.cpu_flags(str(info)) == {"fpu", "avx2", "fma"}
    assert system_openblas.cpu_flags(str(tmp_path / "missing")) == frozenset()


def test_the_variable_is_set_for_the_block_only(monkeypatch):
    monkeypatch.delenv(system_openblas.VARIABLE, raising=False)
    monkeypatch.setattr(system_openblas, "cpu_flags", lambda: SKYLAKE_X)
    with system_openblas.named_core() as core:
        assert core == "SkylakeX"
        assert os.environ[system_openblas.VARIABLE] == "SkylakeX"
    assert system_openblas.VARIABLE not in os.environ


def test_a_users_choice_stands(monkeypatch):
    monkeypatch.setenv(system_openblas.VARIABLE, "Prescott")
    monkeypatch.setattr(system_openblas, "cpu_flags", lambda: SKYLAKE_X)
    with system_openblas.named_core() as core:
        assert core is None
        assert os.environ[system_openblas.VARIABLE] == "Prescott"
    assert os.environ[system_openblas.VARIABLE] == "Prescott"


_LOADED_CORE = """
import ctypes, os
from asterlite.fem import sparse_direct
sparse_direct.load_mumps()
path = next(line.split()[-1] for line in open("/proc/self/maps") if "libopenblas" in line)
lib = ctypes.CDLL(path)
lib.openblas_get_corename.restype = ctypes.c_char_p
print(lib.openblas_get_corename().decode(), os.environ.get("OPENBLAS_CORETYPE"))
"""


@pytest.mark.skipif(not sparse_direct.mumps_available(), reason="python-mumps is not installed")
def test_mumps_runs_on_the_kernels_the_cpu_can_run():
    expected = system_openblas.core_for(system_openblas.cpu_flags())
    if expected is None:
        pytest.skip("this CPU has no AVX2: OpenBLAS's own choice stands")
    if not any("libopenblas" in line for line in _system_libraries()):
        pytest.skip("MUMPS does not link the system OpenBLAS here")
    env = {k: v for k, v in os.environ.items() if k != system_openblas.VARIABLE}
    out = subprocess.run(
        [sys.executable, "-c", _LOADED_CORE], env=env, capture_output=True, text=True, check=True
    ).stdout.split()
    # the library's kernels are the CPU's, and nothing is left for child processes
    assert out == [expected, "None"]


def _system_libraries() -> list[str]:
    """The shared libraries MUMPS's extension loads (ldd), empty if unknown."""
    mumps = sparse_direct.load_mumps()
    extension = mumps.mumps._mumps.__file__
    try:
        listing = subprocess.run(["ldd", extension], capture_output=True, text=True, timeout=30)
    except (OSError, subprocess.SubprocessError):
        return []
    return listing.stdout.splitlines()
