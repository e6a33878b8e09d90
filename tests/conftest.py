"""Shared test fixtures: where the corpus is, and a helper to skip without it."""

from __future__ import annotations

import functools
import os
import sys
from pathlib import Path

import pytest

# A deck run in this process (run_deck) uses this process's BLAS threads: one,
# as `asterlite run` gives a deck without P ncpus (asterlite.runtime.threads),
# so that its values and a subprocess run's agree to the last bit (forma02d's
# differ by 1e-8 between one and two OpenBLAS threads). Set before numpy loads.
if "numpy" not in sys.modules:
    os.environ["OMP_NUM_THREADS"] = "1"

ROOT = Path(__file__).resolve().parent.parent
CORPUS = ROOT.parent / "shared" / "aster-corpus"
SAMPLES = ROOT / "samples"


def corpus_decks() -> list[str]:
    if not CORPUS.is_dir():
        return []
    return sorted(p.name for p in CORPUS.iterdir() if p.is_dir())


@pytest.fixture
def corpus_dir() -> Path:
    if not CORPUS.is_dir():
        pytest.skip("../shared/aster-corpus is not available")
    return CORPUS


@functools.cache
def corpus_rows(name: str) -> tuple[dict, ...]:
    """Every deck of ../shared/<name> run once per test session (the slow
    corpus tests of one folder share it), or skip when the folder is absent."""
    from asterlite.runtime.corpus import run_corpus

    folder = ROOT.parent / "shared" / name
    if not folder.is_dir():
        pytest.skip(f"../shared/{name} is not available")
    return tuple(run_corpus(folder, jobs=2, timeout=900))


@pytest.fixture()
def needs_mumps():
    """Skip without python-mumps (the large extra), except in CI (CI=true),
    where .ci/run installs it."""
    import os

    from asterlite.fem import sparse_direct

    if sparse_direct.mumps_available():
        return
    if os.environ.get("CI", "").lower() == "true":
        pytest.fail("CI: python-mumps is missing (.ci/run installs the large extra)")
    pytest.skip("python-mumps is not installed (the large extra)")


@pytest.fixture()
def needs_native():
    """Skip without the compiled time loops (no C++ compiler at install),
    except in CI (CI=true), where .ci/run installs g++."""
    import os

    from asterlite.dynamics import native

    if native._loops is not None:
        return
    if os.environ.get("CI", "").lower() == "true":
        pytest.fail("CI: the compiled loops are not built (asterlite/dynamics/native)")
    pytest.skip("the compiled loops are not built (no C++ compiler at install)")


def pytest_sessionfinish(session):
    """``ASTERLITE_NUMBA_REFERENCE=record``: numba's fingerprints to their file."""
    from tests import numba_reference

    numba_reference.write_recorded()


def pytest_collection_finish(session):
    """Under ``--dist loadgroup`` every test of an ``xdist_group`` must carry
    its group in its id, which is how pytest-xdist sends a group to one
    worker: otherwise each worker runs the corpus folders (``corpus_rows``)
    again, for minutes."""
    if not getattr(session.config.option, "loadgroup", False):
        return
    ungrouped = [
        item.nodeid
        for item in session.items
        if item.get_closest_marker("xdist_group") is not None and "@" not in item.nodeid
    ]
    if ungrouped:
        raise pytest.UsageError(
            f"pytest-xdist's loadgroup left {len(ungrouped)} grouped tests ungrouped "
            f"(e.g. {ungrouped[0]}): this pytest and pytest-xdist do not work together"
        )
