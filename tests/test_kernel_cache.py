"""numba's cache folder follows every source of asterlite.dynamics: a
kernel compiled from older helpers is never loaded (asterlite/dynamics/__init__.py)."""

from __future__ import annotations

import os
import re
import subprocess
import sys

import pytest

import asterlite.dynamics as D


def test_digest_follows_every_source(tmp_path):
    (tmp_path / "laws").mkdir()
    (tmp_path / "a.py").write_text("x = 1\n")
    (tmp_path / "laws" / "b.py").write_text("y = 2\n")
    first = D.source_digest(tmp_path)
    assert D.source_digest(tmp_path) == first
    (tmp_path / "laws" / "b.py").write_text("y = 3\n")  # a helper in a subfolder
    changed = D.source_digest(tmp_path)
    assert changed != first
    (tmp_path / "c.py").write_text("")  # a new, empty module
    assert D.source_digest(tmp_path) not in (first, changed)
    (tmp_path / "notes.txt").write_text("not a source")
    assert D.source_digest(tmp_path) == D.source_digest(tmp_path)


def test_folder_under_the_users_cache_dir(tmp_path, monkeypatch):
    monkeypatch.setenv("NUMBA_CACHE_DIR", str(tmp_path))
    folder = D.kernel_cache_folder()
    assert folder.parent == tmp_path
    assert re.fullmatch(r"kernels-[0-9a-f]{16}", folder.name)
    monkeypatch.setenv("NUMBA_CACHE_DIR", str(folder))  # a child of a process that set it
    assert D.kernel_cache_folder() == folder


@pytest.mark.parametrize("numba_first", [True, False])
def test_numba_uses_it(tmp_path, numba_first):
    """A fresh process with the user's NUMBA_CACHE_DIR: once asterlite loads
    numba's kernels (jit.load), numba's own config names the digest folder
    below it, whether numba was imported first or not; importing the package
    alone leaves the variable as it was (a run on the C++ loops never imports
    numba, nor reads the sources for their digest)."""
    code = (
        ("import numba\n" if numba_first else "") + "import os, asterlite.dynamics as D\n"
        "from asterlite.dynamics import jit\n"
        "untouched = os.environ['NUMBA_CACHE_DIR'] == os.environ['GIVEN']\n"
        "jit.load()\n"
        "from numba.core import config\n"
        "print(untouched, config.CACHE_DIR == str(D.kernel_cache_folder()))\n"
    )
    env = dict(os.environ, NUMBA_CACHE_DIR=str(tmp_path), GIVEN=str(tmp_path))
    out = subprocess.run([sys.executable, "-c", code], env=env, capture_output=True, text=True)
    assert out.stdout.strip() == "True True", out.stderr


def test_warmup_prunes_only_older_in_tree_folders(tmp_path):
    from asterlite.dynamics.warmup import prune_stale_kernels

    cache = tmp_path / "dynamics" / "__pycache__"
    current = cache / "kernels-0123456789abcdef"
    older = cache / "kernels-fedcba9876543210"
    foreign = cache / "kernels-mine"  # not a digest: not ours
    for folder in (current, older, foreign, tmp_path / "dynamics" / "laws" / "__pycache__"):
        folder.mkdir(parents=True)
    # numba's files from before the digest folders go too (a subpackage's
    # also); bytecode and the current folder's files stay
    old_files = [
        cache / "forces.loads_ready-112.py311.nbi",
        cache / "a.b-3.py311.1.nbc",
        tmp_path / "dynamics" / "laws" / "__pycache__" / "law.force-9.py311.nbi",
    ]
    kept = [cache / "forces.cpython-311.pyc", current / "forces.loads_ready-112.py311.nbi"]
    for path in (*old_files, *kept):
        path.write_bytes(b"")
    assert prune_stale_kernels(current, in_tree=False) == []  # a user's NUMBA_CACHE_DIR
    assert older.exists() and all(path.exists() for path in old_files)
    assert sorted(prune_stale_kernels(current, in_tree=True)) == sorted([older, *old_files])
    assert current.exists() and foreign.exists() and all(path.exists() for path in kept)
    assert not older.exists() and not any(path.exists() for path in old_files)


def test_every_warmed_kernel_has_a_compile_estimate():
    """compile_seconds.json names every kernel the warmup compiles and every
    loop a run can take, so each compile notice says about how long it takes."""
    from asterlite.dynamics import schemes, warmup

    names = set(warmup.KERNELS) | set(schemes.kernels())
    missing = sorted(name for name in names if not (D.compile_estimate(name) or 0.0) > 0.0)
    assert not missing
    assert D.compile_estimate("no such kernel") is None
    estimates = [D.compile_estimate(name) for name in warmup.SCHEME_LOOPS]
    assert estimates == sorted(estimates, reverse=True)  # longest first
