"""Cold start (issue 16, goal 1): first run against second run of corpus
decks after a fresh install's ``asterlite warmup``.

With a fresh numba cache (a new NUMBA_CACHE_DIR, as a fresh clone has no
``__pycache__``), it times ``asterlite warmup``, then runs each deck twice
with ``asterlite run`` and prints, per deck, the wall and CPU seconds of
both runs, their difference (goal: at most 3 s) and the compile notices
the first run printed (goal: none). ``--no-warmup`` measures the same
without the warmup: what a first run costs when it compiles.

The default decks cover every scheme and the loops shared by all schemes:
DIFF_CENTRE (one mode, many modes, full matrices), NEWMARK, TRBDF2,
DEVOGE, RUNGE_KUTTA_32/54, ADAPT_ORDRE1/2, the relations of laws/ (general
path), VITESSE_VARIABLE and TRAITEMENT_NONL='IMPLICITE'.

    python benchmarks/cold_start.py                 # ~5-15 min on 2 cores
    python benchmarks/cold_start.py --no-warmup sdnd100b sdnl111f
    .venv/bin/python benchmarks/cold_start.py --installed   # after the README's command
"""

from __future__ import annotations

import argparse
import os
import resource
import subprocess
import sys
import tempfile
import time
from pathlib import Path

ROOT = Path(__file__).resolve().parent.parent
CORPUS = ROOT.parent / "shared" / "aster-corpus"
DECKS = (
    "sdnd100a",  # DIFF_CENTRE, one mode
    "forma02d",  # DIFF_CENTRE, beam modes
    "sdld04a",  # DIFF_CENTRE, DEVOGE, NEWMARK, TRAITEMENT_NONL='IMPLICITE'
    "sdnd100b",  # DEVOGE
    "sdld105a",  # NEWMARK
    "sdnl111f",  # TRBDF2
    "sdld22c",  # ADAPT_ORDRE1/2, RUNGE_KUTTA_32/54, DIFF_CENTRE
    "sdnd105a",  # DIS_VISC (general path), ADAPT_ORDRE2, DEVOGE
    "sdll144a",  # NEWMARK with VITESSE_VARIABLE
)


def timed(command: list[str], env: dict) -> tuple[float, float, str, int]:
    """(wall s, CPU s of the child, its standard error, exit code)."""
    before = resource.getrusage(resource.RUSAGE_CHILDREN)
    started = time.perf_counter()
    done = subprocess.run(command, env=env, capture_output=True, text=True, cwd=ROOT)
    wall = time.perf_counter() - started
    after = resource.getrusage(resource.RUSAGE_CHILDREN)
    cpu = (after.ru_utime - before.ru_utime) + (after.ru_stime - before.ru_stime)
    return wall, cpu, done.stderr, done.returncode


def compile_lines(stderr: str) -> list[str]:
    return [line for line in stderr.splitlines() if "asterlite: compiling" in line]


def main() -> int:
    parser = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    parser.add_argument("decks", nargs="*", default=list(DECKS), help="corpus deck names")
    parser.add_argument("--all", action="store_true", help="every deck of the corpus")
    parser.add_argument("--no-warmup", action="store_true", help="skip asterlite warmup")
    parser.add_argument("--jobs", type=int, default=None, help="warmup worker processes")
    parser.add_argument("--cache", help="numba cache folder (default: a fresh temporary one)")
    parser.add_argument(
        "--installed",
        action="store_true",
        help="measure the install as it is (its own cache, already warmed up by the "
        "README's command): no fresh cache, no warmup",
    )
    args = parser.parse_args()
    if not CORPUS.is_dir():
        print(f"no corpus at {CORPUS}", file=sys.stderr)
        return 2
    if args.all:
        args.decks = sorted(p.name for p in CORPUS.iterdir() if (p / f"{p.name}.export").is_file())
    work = Path(tempfile.mkdtemp(prefix="asterlite-cold-"))
    env = dict(os.environ, NUMBA_CACHE_DIR=args.cache or str(work / "numba-cache"))
    if args.installed:  # numba's default: __pycache__ beside the installed sources
        env.pop("NUMBA_CACHE_DIR")
    env["ASTERLITE_PROGRESS"] = "0"
    python = [sys.executable, "-m", "asterlite"]
    cache = env.get("NUMBA_CACHE_DIR", "numba's default (__pycache__)")
    print(f"python {sys.version.split()[0]}, {os.cpu_count()} cores, numba cache {cache}")
    print(f"load average at start: {os.getloadavg()[0]:.1f}")
    if not (args.no_warmup or args.installed):
        warm = python + ["warmup", "-v"] + ([f"--jobs={args.jobs}"] if args.jobs else [])
        wall, cpu, err, code = timed(warm, env)
        print(f"asterlite warmup: {wall:.1f} s wall, {cpu:.1f} s CPU (exit {code})")
        for line in err.splitlines():
            if line.startswith("  ") or "warmup:" in line:
                print("   ", line.strip())
    header = f"{'deck':10s} {'1st wall':>9s} {'2nd wall':>9s} {'extra':>7s} "
    header += f"{'1st CPU':>8s} {'2nd CPU':>8s} {'extra':>7s}  exit  compiles in 1st run"
    print(header)
    worst, compiling = 0.0, 0
    for deck in args.decks:
        export = CORPUS / deck / f"{deck}.export"
        runs = []
        for attempt in (1, 2):
            out = work / f"{deck}-{attempt}"
            runs.append(timed(python + ["run", str(export), "-o", str(out), "--quiet"], env))
        (w1, c1, e1, x1), (w2, c2, _, _) = runs
        compiled = compile_lines(e1)
        worst, compiling = max(worst, w1 - w2), compiling + bool(compiled)
        names = "; ".join(line.split("compiling ", 1)[1].split(",")[0] for line in compiled)
        print(
            f"{deck:10s} {w1:9.2f} {w2:9.2f} {w1 - w2:7.2f} {c1:8.2f} {c2:8.2f} {c1 - c2:7.2f}"
            f"  {x1:4d}  {len(compiled)} {names}"
        )
    print(f"largest first-run excess: {worst:.2f} s wall (goal: <= 3 s)")
    print(f"decks whose first run compiled something: {compiling} of {len(args.decks)}")
    print(f"load average at end: {os.getloadavg()[0]:.1f}")
    return 0


if __name__ == "__main__":
    raise SystemExit(main())
