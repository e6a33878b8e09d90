"""numpy's tools a run never uses stay unloaded until something reads them."""

from __future__ import annotations

import re
import subprocess
import sys
from pathlib import Path

ROOT = Path(__file__).resolve().parent.parent
SAMPLE = ROOT / "samples" / "friction_oscillator"

_DEFERRED_THEN_USED = """
import sys
from asterlite.runtime.deferred_modules import defer_numpy_tools
print(defer_numpy_tools())
import numpy, scipy.linalg, scipy.sparse.linalg
print(sorted(m for m in sys.modules if m.startswith(("numpy.f2py.", "numpy.testing."))))
# read, they are whole modules
numpy.testing.assert_allclose(numpy.ones(2), [1.0, 1.0])
print(callable(numpy.f2py.run_main), "numpy.f2py.crackfortran" in sys.modules)
"""


def _python(code: str, *args: str) -> subprocess.CompletedProcess:
    return subprocess.run(
        [sys.executable, *args, "-c", code], capture_output=True, text=True, cwd=ROOT, check=True
    )


def test_scipy_loads_without_numpy_tools_which_load_when_read():
    lines = _python(_DEFERRED_THEN_USED).stdout.splitlines()
    assert lines == ["['numpy.f2py', 'numpy.testing']", "[]", "True True"]


def test_nothing_is_deferred_once_scipy_is_loaded():
    code = (
        "import scipy.linalg\nfrom asterlite.runtime.deferred_modules import defer_numpy_tools\n"
        "print(defer_numpy_tools())"
    )
    assert _python(code).stdout.strip() == "[]"


def test_a_run_never_loads_numpy_tools(tmp_path):
    done = subprocess.run(
        [sys.executable, "-X", "importtime", "-m", "asterlite", "run", str(SAMPLE)]
        + ["-o", str(tmp_path / "out"), "-q"],
        capture_output=True,
        text=True,
        cwd=ROOT,
    )
    assert done.returncode == 0, done.stderr[-2000:]
    loaded = {m[1] for m in re.finditer(r"^import time:.*\|\s*(\S+)$", done.stderr, re.M)}
    assert "scipy.linalg" in loaded  # the run does load scipy
    assert not {m for m in loaded if m.startswith(("numpy.f2py", "numpy.testing"))}
