"""The run's threads: the export's ``P ncpus``, as code_aster uses it.

code_aster's ``run_aster`` starts a run with ``OMP_NUM_THREADS`` set to the
export's ``ncpus`` (1 when the export gives none): OpenMP code and OpenBLAS,
which reads ``OMP_NUM_THREADS`` unless ``OPENBLAS_NUM_THREADS`` is set, then
use that many threads. ``asterlite run`` (and the commands that run decks in
their own process: sweep, converge, sensitivity) does the same for its
process and what it starts, before numpy loads: a library sizes its thread
pool when it loads. Small dense products and eigen problems (a block
Lanczos method's, a modal basis's) run much slower on two BLAS threads than
on one, and slower still when the threads wait for a busy core.

The Python API runs decks in the caller's process, whose libraries are
loaded already: it leaves the caller's threads as they are.
"""

from __future__ import annotations

import os
import sys
from pathlib import Path

from asterlite.errors import AsterliteError
from asterlite.io.export import describe_run

#: the variable code_aster sets from ``P ncpus``
VARIABLE = "OMP_NUM_THREADS"


def export_threads(deck: Path) -> int | None:
    """The threads the run of ``deck`` (an .export or a bare deck) asks for;
    None when its description cannot be read (the run says why)."""
    try:
        return describe_run(deck).threads
    except (AsterliteError, OSError, ValueError):
        return None


def use_threads(count: int | None) -> bool:
    """Run this process (and the processes it starts) on ``count`` threads;
    False, with nothing changed, when ``count`` is None or once numpy is
    loaded (its thread pools are sized already)."""
    if count is None or "numpy" in sys.modules:
        return False
    os.environ[VARIABLE] = str(count)
    return True
