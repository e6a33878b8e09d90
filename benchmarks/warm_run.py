"""Warm whole run (issue 30, goal 5): ``asterlite run`` of a corpus deck
(default sdnd100a) with every kernel already built, against the floor any
such run pays: the interpreter, numpy, scipy.linalg and scipy.sparse.linalg
(modes, constraints; what asterlite.watchdog.preload_engine imports), as
they load by themselves and as a run loads them (numpy's f2py and testing
deferred: asterlite.runtime.deferred_modules). The
deck runs twice: as installed (its DIFF_CENTRE loop compiled C++ when the
extension is built: numba is not imported) and with ``ASTERLITE_NATIVE=0``
(numba's loop, loaded from its cache), next to numba's own floor (its import
and a first cached call, which initialises its lowering registries).

Each figure is the best and the median of ``--repeat`` fresh processes,
wall and CPU (user + system) seconds; the runs warm the caches first.

    python benchmarks/warm_run.py                   # ~30 s
    python benchmarks/warm_run.py sdnd100b --repeat 9
"""

from __future__ import annotations

import argparse
import os
import resource
import statistics
import subprocess
import sys
import tempfile
import time
from pathlib import Path

ROOT = Path(__file__).resolve().parent.parent
CORPUS = ROOT.parent / "shared" / "aster-corpus"

# the floor: what a run needs before any asterlite code, and numba's first
# cached call (a trivial kernel, compiled once into the benchmark's cache)
FLOOR = """
import numpy, scipy.linalg, scipy.sparse.linalg
from numba import njit
@njit(cache=True)
def total(x):
    s = 0.0
    for i in range(x.shape[0]):
        s += x[i]
    return s
total(numpy.ones(3))
"""
COMPILE_BYTECODE = "from asterlite.dynamics.warmup import compile_bytecode; compile_bytecode()"
PIECES = {
    "python": "pass",
    "+ numpy": "import numpy",
    "+ scipy.linalg, scipy.sparse.linalg": "import numpy, scipy.linalg, scipy.sparse.linalg",
    # what a run loads: numpy's unused tools deferred first (runtime.deferred_modules)
    "+ the same, numpy's tools deferred": (
        "from asterlite.runtime.deferred_modules import defer_numpy_tools;"
        " defer_numpy_tools(); import scipy.linalg, scipy.sparse.linalg"
    ),
    "+ numba import": "import numpy, scipy.linalg, scipy.sparse.linalg, numba",
}


def timed(command: list[str], env: dict, cwd: Path) -> tuple[float, float, int]:
    before = resource.getrusage(resource.RUSAGE_CHILDREN)
    started = time.perf_counter()
    done = subprocess.run(command, env=env, cwd=cwd, capture_output=True, text=True)
    wall = time.perf_counter() - started
    after = resource.getrusage(resource.RUSAGE_CHILDREN)
    cpu = (after.ru_utime - before.ru_utime) + (after.ru_stime - before.ru_stime)
    return wall, cpu, done.returncode


def summary(name: str, samples: list[tuple[float, float, int]]) -> str:
    walls, cpus = [s[0] for s in samples], [s[1] for s in samples]
    return (
        f"{name:42s} wall best {min(walls):6.3f} median {statistics.median(walls):6.3f}"
        f"   CPU best {min(cpus):6.3f} median {statistics.median(cpus):6.3f}"
    )


def main() -> int:
    parser = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    parser.add_argument("deck", nargs="?", default="sdnd100a")
    parser.add_argument("--repeat", type=int, default=7)
    args = parser.parse_args()
    export = CORPUS / args.deck / f"{args.deck}.export"
    if not export.is_file():
        print(f"no deck at {export}", file=sys.stderr)
        return 2
    work = Path(tempfile.mkdtemp(prefix="asterlite-warm-"))
    env = dict(os.environ, ASTERLITE_PROGRESS="0")
    floor_env = dict(env, NUMBA_CACHE_DIR=str(work / "floor-cache"))
    floor_script = work / "floor.py"
    floor_script.write_text(FLOOR)
    run = [sys.executable, "-m", "asterlite", "run", str(export), "-o", str(work / "out"), "-q"]
    print(f"python {sys.version.split()[0]}, load average {os.getloadavg()[0]:.1f}")
    # the sources' bytecode, as `asterlite warmup` or a regular pip install writes it (a
    # run under PYTHONDONTWRITEBYTECODE would otherwise parse every changed module again)
    subprocess.run([sys.executable, "-c", COMPILE_BYTECODE], env=env, cwd=ROOT, check=True)
    for command, cmd_env in ((run, env), ([sys.executable, str(floor_script)], floor_env)):
        timed(command, cmd_env, ROOT)  # warm numba's cache and the OS file cache
    numba_env = dict(env, ASTERLITE_NATIVE="0")
    timed(run, numba_env, ROOT)
    with_numba = f"{args.deck}, ASTERLITE_NATIVE=0"
    floor = "numba floor (+ its first cached call)"
    rows = {name: [] for name in (*PIECES, floor, args.deck, with_numba)}
    for _ in range(args.repeat):  # interleaved, so that all see the same load
        for name, code in PIECES.items():
            rows[name].append(timed([sys.executable, "-c", code], env, ROOT))
        rows[floor].append(timed([sys.executable, str(floor_script)], floor_env, ROOT))
        rows[args.deck].append(timed(run, env, ROOT))
        rows[with_numba].append(timed(run, numba_env, ROOT))
    for name, samples in rows.items():
        print(summary(name, samples))
    failed = [s for s in rows[args.deck] if s[2] != 0]
    print(f"{args.deck}: exit {rows[args.deck][0][2]}" + (" (failures!)" if failed else ""))
    print(f"load average at end: {os.getloadavg()[0]:.1f}")
    return 0


if __name__ == "__main__":
    raise SystemExit(main())
