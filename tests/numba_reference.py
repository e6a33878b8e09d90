"""numba's results as the C++ loops' reference, kept as fingerprints.

The tests of tests/test_native_*.py compare each C++ loop with numba's to the
last bit. Running numba's side means compiling its loops (about ten
CPU-minutes), so its results are kept instead: :func:`reference` stands for
what numba computes for a call by its fingerprint (:func:`fingerprint`: a
digest of each array, canonical so that two arrays ``assert_array_equal``
calls equal have the same one; the file keeps one digest of the whole), and
:func:`assert_same` compares the C++ result with it.

Where they come from (``ASTERLITE_NUMBA_REFERENCE``):

- unset or ``stored``: ``tests/native_fingerprints.json``, recorded from
  the sources of :data:`SOURCES` as they are; a missing entry, or a file
  recorded from other sources, computes numba's result here instead (as
  ``live``), except in CI (``CI=true``) where the test fails at once, and
  ``test_the_stored_fingerprints_are_current`` fails, naming the command
  that records them again. A file recorded on another platform
  (:func:`platform_signature`: the C library and the CPU features numpy's
  and the C library's math functions choose their code by, so results may
  differ in their last bits) is not used: numba's side is computed here,
  CI included (slower, not wrong);
- ``live``: numba's result, computed now (nothing read or written);
- ``record``: computed now and written to the file at the end of the
  session (``python tests/numba_reference.py``: the native tests in one
  process, then the file).
"""

from __future__ import annotations

import hashlib
import importlib.metadata
import json
import math
import os
import platform
import subprocess
import sys
from pathlib import Path

import numpy as np
import pytest

ROOT = Path(__file__).resolve().parent.parent
STORE = Path(__file__).with_name("native_fingerprints.json")
MODE_VARIABLE = "ASTERLITE_NUMBA_REFERENCE"
MODES = ("stored", "live", "record")

#: what numba's results depend on: its kernels and the Python that sets up
#: their arrays (asterlite.dynamics but the C++ loops, the harmonic LDLᵀ,
#: the formula programs) and the tests' problems
SOURCES = (
    "asterlite/dynamics",
    "asterlite/harmonic",
    "asterlite/lang/formula.py",
    "asterlite/lang/numeric.py",
    "asterlite/concepts/function.py",
    "tests/native_runs.py",
    "tests/numba_reference.py",
    "tests/test_dynamics_specialised.py",
    "tests/validated.py",
    "tests/test_native_*.py",
)
EXCLUDED = ("asterlite/dynamics/native",)


def sources_digest() -> str:
    """A digest of the names and bytes of every Python file of :data:`SOURCES`,
    and of numba's and numpy's versions."""
    numba = importlib.metadata.version("numba")  # without importing it
    digest = hashlib.sha256(f"numba {numba} numpy {np.__version__}".encode())
    files = set()
    for entry in SOURCES:
        path = ROOT / entry
        if path.is_dir():
            files.update(path.rglob("*.py"))
        else:
            files.update(ROOT.glob(entry))
    for path in sorted(files):
        name = path.relative_to(ROOT).as_posix()
        if name.startswith(EXCLUDED):
            continue
        digest.update(name.encode() + b"\0" + path.read_bytes() + b"\0")
    return digest.hexdigest()[:16]


def _array_digest(array: np.ndarray) -> str:
    array = np.asarray(array)
    if array.dtype.kind in "fc":
        # canonical: every NaN alike, -0.0 as 0.0 (assert_array_equal's equality)
        array = np.where(np.isnan(array), np.nan, array) + np.zeros((), array.dtype)
    array = np.ascontiguousarray(array)
    digest = hashlib.sha256(f"{array.dtype.str} {array.shape}".encode())
    digest.update(array.tobytes())
    return digest.hexdigest()[:16]


def fingerprint(value):
    """A JSON value standing for ``value``: arrays by digest, floats by their
    exact text, containers item by item."""
    if isinstance(value, np.ndarray):
        return "array " + _array_digest(value)
    if isinstance(value, (bool, np.bool_)):
        return bool(value)
    if isinstance(value, (int, np.integer)):
        return int(value)
    if isinstance(value, (float, np.floating)):
        value = float(value)
        return "nan" if math.isnan(value) else repr(value + 0.0)
    if isinstance(value, (complex, np.complexfloating)):
        return [fingerprint(value.real), fingerprint(value.imag)]
    if value is None or isinstance(value, str):
        return value
    if isinstance(value, type):
        return f"type {value.__module__}.{value.__qualname__}"
    if isinstance(value, dict):
        return {str(key): fingerprint(item) for key, item in value.items()}
    if isinstance(value, (list, tuple)):
        return [fingerprint(item) for item in value]
    raise TypeError(f"no fingerprint for a {type(value).__name__}")


def mode() -> str:
    chosen = os.environ.get(MODE_VARIABLE, "stored").strip().lower() or "stored"
    if chosen not in MODES:
        raise ValueError(f"{MODE_VARIABLE}={chosen!r}: expected one of {', '.join(MODES)}")
    return chosen


_stored: dict | None = None
_recorded: dict[str, object] = {}


def platform_signature() -> str:
    """The machine, the C library and the CPU features that choose the code
    of numpy's and the C library's math functions (their results may differ
    in the last bits from one choice to the other)."""
    from numpy._core._multiarray_umath import __cpu_features__ as features

    chosen = sorted(name for name in MATH_FEATURES if features.get(name))
    libc = "-".join(platform.libc_ver())
    return f"{platform.machine()} {libc} {' '.join(chosen)}"


#: numpy's dispatch targets of its float64 math (SVML on AVX512_SKX) and
#: glibc's (FMA, AVX2 variants)
MATH_FEATURES = ("FMA3", "AVX2", "AVX512F", "AVX512_SKX")


def _store() -> dict:
    try:
        return json.loads(STORE.read_text())
    except (OSError, ValueError):
        return {}


def same_platform(data: dict | None = None) -> bool:
    """Whether the file (``data``: as read) was recorded on a platform like this one."""
    return (_store() if data is None else data).get("platform") == platform_signature()


def _current_entries(data: dict) -> dict:
    """The entries of the file ``data`` if it was recorded from today's
    sources on a platform like this one, else {}."""
    current = data.get("sources") == sources_digest() and same_platform(data)
    return data.get("entries", {}) if current else {}


def stored() -> dict:
    """The file's fingerprints if they were recorded from today's sources on
    a platform like this one, else {}."""
    global _stored
    if _stored is None:
        _stored = _current_entries(_store())
    return _stored


def reference(request, compute):
    """The fingerprint of numba's result ``compute()`` for this call of the
    test ``request`` names (the calls of one test are told apart by their
    order)."""
    count = getattr(request.node, "_numba_references", 0)
    request.node._numba_references = count + 1
    key = f"{_test_id(request.node)}#{count}"
    chosen = mode()
    if chosen == "record" and os.environ.get("PYTEST_XDIST_WORKER"):
        raise RuntimeError(f"{MODE_VARIABLE}=record runs in one process (-p no:xdist)")
    if chosen == "stored" and key in stored():
        return Stored(stored()[key])
    if chosen == "stored" and os.environ.get("CI", "").lower() == "true" and same_platform():
        # CI does not compile numba's loops: a missing or outdated entry fails at once
        pytest.fail(f"{key}: no fingerprint of numba's result recorded from these sources{HINT}")
    result = fingerprint(compute())
    if chosen == "record":
        _recorded[key] = digest_of(result)
    return result


class Stored:
    """numba's result as the file keeps it: the digest of its fingerprint."""

    def __init__(self, digest: str):
        self.digest = digest

    def __repr__(self) -> str:
        return f"the stored digest {self.digest}"


def digest_of(value_fingerprint) -> str:
    text = json.dumps(value_fingerprint, sort_keys=True, separators=(",", ":"))
    return hashlib.sha256(text.encode()).hexdigest()[:16]


def _test_id(item) -> str:
    """The test's id without the ``@group`` pytest-xdist's loadgroup appends."""
    group = item.get_closest_marker("xdist_group")
    suffix = f"@{group.args[0]}" if group is not None and group.args else None
    nodeid = item.nodeid
    return nodeid[: -len(suffix)] if suffix and nodeid.endswith(suffix) else nodeid


def assert_same(compiled, numba, what: str = "") -> None:
    """The C++ side's value against numba's fingerprint, field by field when
    both are dicts (their names in the message)."""
    mine = fingerprint(compiled)
    if isinstance(numba, Stored):
        assert digest_of(mine) == numba.digest, f"{what}: differs from numba's{HINT}"
    elif isinstance(mine, dict) and isinstance(numba, dict):
        assert set(mine) == set(numba), f"{what}: fields {sorted(mine)} != {sorted(numba)}"
        differ = [name for name in mine if mine[name] != numba[name]]
        assert not differ, f"{what}: differs from numba's in {', '.join(differ)}{HINT}"
    else:
        assert mine == numba, f"{what}: {mine!r} != numba's {numba!r}{HINT}"


HINT = (
    f" (numba's fingerprint; {MODE_VARIABLE}=live compares with numba's result itself,"
    " `python tests/numba_reference.py` records the fingerprints again)"
)


def write_recorded() -> None:
    """At the end of a ``record`` session: the file, the recorded entries
    merged into those of the same sources."""
    if mode() != "record" or not _recorded:
        return
    entries = {**_current_entries(_store()), **_recorded}
    lines = [f"{json.dumps(key)}: {json.dumps(value)}" for key, value in sorted(entries.items())]
    digest, where = json.dumps(sources_digest()), json.dumps(platform_signature())
    head = f'{{"sources": {digest}, "platform": {where}, "entries": {{\n'
    STORE.write_text(head + ",\n".join(lines) + "\n}}\n")


def record() -> int:
    """Record every fingerprint: the native tests in one process (numba's
    loops compile once there), then the file."""
    tests = sorted(str(p.relative_to(ROOT)) for p in ROOT.glob("tests/test_native_*.py"))
    STORE.unlink(missing_ok=True)  # the entries of tests that are gone go too
    environment = {**os.environ, MODE_VARIABLE: "record"}
    command = [sys.executable, "-m", "pytest", "-q", "-p", "no:xdist", *tests]
    return subprocess.run(command, cwd=ROOT, env=environment).returncode


if __name__ == "__main__":
    sys.exit(record())
