"""Whole-run marginal cost of the tube deck: the extra time of
``asterlite run`` for more steps, archiving and POST_DYNA_MODA_T included.

The deck is samples/tube_supports (20 beam modes, 3 CERCLE supports with
friction, PAS_ARCH=10, POST_DYNA_MODA_T and IMPR_TABLE of every impact)
with its first DYNA_VIBRA run at PAS = 1e-5 s to INST_FIN = T and to
T + extra: the difference of the two runs' times, divided by the
difference of their step counts, is what one more step costs a user.
Each length runs ``--repeats`` times, interleaved, in fresh processes; the
best wall time and the best CPU time (user + system of the child) are
kept. The hand-written loop (tube_floor.py, same step, same archiving
period) runs in this process between them for the ratio.

``--scheme`` runs the same deck with another SCHEMA (fixed step: PAS_MINI
= PAS_MAXI = PAS for the adaptive family, so that both lengths take the
grid's steps).

``--instructions STEPS``: instead of seconds, count the instructions the
processes execute (valgrind's callgrind, the same count whatever the load of
the machine): the deck to INST_FIN = 0.5 s and 0.5 s + STEPS steps, and the
floor for 10^4 and 10^4 + STEPS steps, each in a fresh process under
callgrind after one warm-up run of each (kernels compiled once for the
processor valgrind presents: without AVX-512, the code differs from the
native one, the same way for both). Slow (50-100x): 10^5 steps take
minutes. With NUMBA_CPU_NAME=generic (SSE2 code, valgrind runs it) the
native warm-up runs compile the kernels valgrind then loads from the cache:
no compilation under valgrind.

Run: python benchmarks/tube_marginal.py [--extra-steps 1000000] [--repeats 5]
     [--scheme NEWMARK] [--keep DIR] [--instructions 100000]
"""

from __future__ import annotations

import argparse
import json
import os
import re
import resource
import shutil
import subprocess
import sys
import tempfile
import time
from pathlib import Path

os.environ.setdefault("OPENBLAS_NUM_THREADS", "1")

HERE = Path(__file__).resolve().parent
SAMPLE = HERE.parent / "samples" / "tube_supports"
DT = 1.0e-5
BASE_END = 0.5  # s: the shorter run
INCREMENT = "INCREMENT=_F(INST_INIT=0.0, INST_FIN=4.0, PAS=2.0e-5)"
SCHEMA = 'SCHEMA_TEMPS=_F(SCHEMA="DIFF_CENTRE"),\n    MATR_MASS=MASSGENE,\n    MATR_RIGI=RIGIGENE,\n    AMOR_MODAL=_F(AMOR_REDUIT=0.01),\n    EXCIT=(\n        _F(VECT_ASSE_GENE=FYGENE, FONC_MULT=SINUS),\n        _F(VECT_ASSE_GENE=FZGENE, FONC_MULT=COSINUS),\n    ),\n    INCREMENT=_F(INST_INIT=0.0, INST_FIN=4.0'  # noqa: E501
ADAPTIVE = ("RUNGE_KUTTA_32", "RUNGE_KUTTA_54", "ADAPT_ORDRE1", "ADAPT_ORDRE2", "DEVOGE")


def write_deck(folder: Path, t_end: float, scheme: str) -> Path:
    """The sample deck with its first DYNA_VIBRA run to ``t_end`` at PAS=DT."""
    text = (SAMPLE / "tube_supports.comm").read_text()
    if scheme != "DIFF_CENTRE":
        fixed = f", PAS_MINI={DT!r}, PAS_MAXI={DT!r}" if scheme in ADAPTIVE else ""
        first = text.index(SCHEMA)
        changed = SCHEMA.replace('"DIFF_CENTRE")', f'"{scheme}"{fixed})')
        text = text[:first] + changed + text[first + len(SCHEMA) :]
    assert INCREMENT in text
    text = text.replace(INCREMENT, f"INCREMENT=_F(INST_INIT=0.0, INST_FIN={t_end!r}, PAS={DT!r})")
    name = f"tube_{scheme.lower()}_{t_end:g}"
    (folder / f"{name}.comm").write_text(text)
    export = (SAMPLE / "tube_supports.export").read_text()
    export = export.replace("tube_supports.comm", f"{name}.comm")
    export = export.replace("tube_supports.mail", str(SAMPLE / "tube_supports.mail"))
    (folder / f"{name}.export").write_text(export)
    return folder / f"{name}.export"


COMMAND_LINE = re.compile(r"^  (\S+)\s+line (\d+)\s+(?:-> \S+)?\s+([\d.]+) s$")


def command_seconds(out: Path) -> dict[str, float]:
    """Wall seconds of each command of a run (message.log's closing table),
    plus the first transient's integration seconds."""
    seconds = {}
    for line in (out / "message.log").read_text().splitlines():
        match = COMMAND_LINE.match(line)
        if match:
            seconds[f"{match[1]} line {match[2]}"] = float(match[3])
    summary = json.loads((out / "summary.json").read_text())
    seconds["  of which integration"] = summary["transients"][0]["integration_seconds"]
    return seconds


def run_deck(export: Path, out: Path) -> tuple[float, float, int]:
    """(wall seconds, child CPU seconds, steps of the first transient)."""
    before = resource.getrusage(resource.RUSAGE_CHILDREN)
    started = time.perf_counter()
    subprocess.run(
        [sys.executable, "-m", "asterlite", "run", str(export), "-o", str(out)],
        check=True,
        stdout=subprocess.DEVNULL,
        stderr=subprocess.DEVNULL,
    )
    wall = time.perf_counter() - started
    after = resource.getrusage(resource.RUSAGE_CHILDREN)
    cpu = (after.ru_utime - before.ru_utime) + (after.ru_stime - before.ru_stime)
    summary = json.loads((out / "summary.json").read_text())
    if summary["status"] != "PASS":
        raise SystemExit(f"{export.name}: {summary['status']} {summary.get('message', '')}")
    return wall, cpu, int(summary["transients"][0]["steps"])


def floor_seconds(steps: int, scheme: str = "DIFF_CENTRE") -> tuple[float, float]:
    """(wall, CPU) seconds of the hand-written loop of ``scheme`` for ``steps``
    steps (warm, best of 3 each): tube_floor.py, scheme_floors.py."""
    sys.path.insert(0, str(HERE))
    import scheme_floors
    import tube_floor
    import tube_model as T

    problem = floor_seconds.problem = getattr(floor_seconds, "problem", None) or T.tube_problem()
    if scheme != "DIFF_CENTRE":
        wall, cpu = scheme_floors.floor_seconds(scheme, problem, steps, DT)
        return wall, cpu
    tube_floor.run_floor(problem, 100, DT, 10)
    best = [float("inf"), float("inf")]
    for _ in range(3):
        started, cpu = time.perf_counter(), time.process_time()
        tube_floor.run_floor(problem, steps, DT, 10)
        best[0] = min(best[0], time.perf_counter() - started)
        best[1] = min(best[1], time.process_time() - cpu)
    return best[0], best[1]


FLOOR_SCRIPT = """
import sys
sys.path.insert(0, {here!r})
import tube_model as T
problem = T.tube_problem()
if {scheme!r} == "DIFF_CENTRE":
    import tube_floor
    tube_floor.run_floor(problem, {steps}, {dt!r}, 10)
else:
    import scheme_floors
    scheme_floors.run_floor({scheme!r}, problem, {steps}, {dt!r})
"""
FLOOR_BASE = 10_000  # steps of the floor's shorter count
TOTALS = re.compile(r"^(?:totals|summary):\s+(\d+)", re.MULTILINE)


def instructions(command: list[str], out_file: Path) -> int:
    """Instructions executed by ``command`` (all its threads), callgrind's count."""
    env = dict(os.environ, PYTHONHASHSEED="0")
    subprocess.run(
        ["valgrind", "--tool=callgrind", f"--callgrind-out-file={out_file}", *command],
        check=True,
        stdout=subprocess.DEVNULL,
        stderr=subprocess.DEVNULL,
        env=env,
    )
    return int(TOTALS.findall(out_file.read_text())[-1])


def count_instructions(folder: Path, scheme: str, extra: int) -> None:
    """Marginal instructions per step of the whole run and of the floor."""
    decks = [write_deck(folder, t, scheme) for t in (BASE_END, BASE_END + extra * DT)]
    python = [sys.executable]
    run = [*python, "-m", "asterlite", "run"]
    run_deck(decks[0], folder / "warmup")  # natively: the outputs are checked here
    # NUMBA_CPU_NAME set (generic): the native runs compiled the kernels valgrind loads
    warm = 0 if os.environ.get("NUMBA_CPU_NAME") else 1
    floor_script = FLOOR_SCRIPT.format(here=str(HERE), scheme=scheme, steps=100, dt=DT)
    subprocess.run([sys.executable, "-c", floor_script], check=True)
    counts, steps = [0] * (1 - warm), [0] * (1 - warm)
    for k, deck in enumerate([decks[0]] * warm + decks, start=1 - warm):
        out = folder / f"instr{k}"
        # --memory-limit 0: no CPU-time timer (every 10 ms of CPU with a memory limit), whose
        # Python handler would add instructions in proportion to valgrind's CPU time
        command = [*run, str(deck), "-o", str(out), "--memory-limit", "0"]
        counts.append(instructions(command, folder / f"cg{k}.out"))
        steps.append(int(json.loads((out / "summary.json").read_text())["transients"][0]["steps"]))
    floor = [0] * (1 - warm)
    lengths = (FLOOR_BASE, FLOOR_BASE, FLOOR_BASE + extra)[1 - warm :]  # the first: warm-up
    for k, n in enumerate(lengths, start=1 - warm):
        script = FLOOR_SCRIPT.format(here=str(HERE), scheme=scheme, steps=n, dt=DT)
        floor.append(instructions([*python, "-c", script], folder / f"floor{k}.out"))
    whole = (counts[2] - counts[1]) / (steps[2] - steps[1])
    own = (floor[2] - floor[1]) / extra
    print(f"tube deck, {scheme}, PAS={DT:g}, PAS_ARCH=10, instructions (callgrind)")
    print(f"  runs: {steps[1]} and {steps[2]} steps: {counts[1]:,} and {counts[2]:,}")
    print(f"  floor: {FLOOR_BASE} and {FLOOR_BASE + extra} steps: {floor[1]:,} and {floor[2]:,}")
    print(f"  marginal: {whole:,.0f} instructions/step, floor {own:,.0f}: ratio {whole / own:.2f}x")


def main() -> None:
    parser = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    parser.add_argument("--extra-steps", type=int, default=1_000_000)
    parser.add_argument("--repeats", type=int, default=5)
    parser.add_argument("--scheme", default="DIFF_CENTRE")
    parser.add_argument("--keep", help="folder for the decks and outputs (default: temporary)")
    parser.add_argument("--no-floor", action="store_true")
    parser.add_argument(
        "--instructions", type=int, metavar="STEPS", help="count instructions (callgrind)"
    )
    args = parser.parse_args()
    folder = Path(args.keep or tempfile.mkdtemp(prefix="tube_marginal_"))
    folder.mkdir(parents=True, exist_ok=True)
    if args.instructions:
        count_instructions(folder, args.scheme, args.instructions)
        if not args.keep:
            shutil.rmtree(folder, ignore_errors=True)
        return
    long_end = BASE_END + args.extra_steps * DT
    decks = [write_deck(folder, t, args.scheme) for t in (BASE_END, long_end)]
    run_deck(decks[0], folder / "warmup")  # compiled kernels loaded once
    best = [[float("inf")] * 2 for _ in decks]
    steps = [0, 0]
    floor = [float("inf"), float("inf")]
    commands = [{}, {}]  # best seconds of each command in each length
    for _ in range(args.repeats):
        for k, deck in enumerate(decks):
            wall, cpu, steps[k] = run_deck(deck, folder / f"out{k}")
            best[k] = [min(best[k][0], wall), min(best[k][1], cpu)]
            for name, value in command_seconds(folder / f"out{k}").items():
                commands[k][name] = min(commands[k].get(name, float("inf")), value)
        if not args.no_floor:
            floor = [
                min(a, b)
                for a, b in zip(floor, floor_seconds(args.extra_steps, args.scheme), strict=True)
            ]
    extra = steps[1] - steps[0]
    print(f"tube deck, {args.scheme}, PAS={DT:g}, PAS_ARCH=10, POST_DYNA_MODA_T + IMPR_TABLE")
    for k, label in enumerate(("short", "long")):
        print(f"  {label}: {steps[k]} steps, wall {best[k][0]:.3f} s, cpu {best[k][1]:.3f} s")
    for j, what in enumerate(("wall", "cpu")):
        seconds = best[1][j] - best[0][j]
        rate = extra / seconds if seconds > 0 else float("inf")
        line = (
            f"  marginal ({what}): {1e9 * seconds / extra:.0f} ns/step, {rate:,.0f} steps/s, "
            f"{1e3 * seconds * 1e5 / extra:.1f} ms per 1e5 steps"
        )
        if not args.no_floor:
            line += (
                f"; floor ({args.scheme}, same minutes) {1e9 * floor[j] / extra:.0f} ns/step, "
                f"{extra / floor[j]:,.0f} steps/s: ratio {seconds / floor[j]:.2f}x"
            )
        print(line)
    print("  extra wall seconds per command (best of each), per 1e5 steps:")
    for name, value in commands[1].items():
        extra_ms = 1e3 * (value - commands[0].get(name, 0.0)) * 1e5 / extra
        if abs(extra_ms) >= 0.05:
            print(f"    {name:32s} {extra_ms:7.2f} ms")
    if not args.keep:
        shutil.rmtree(folder, ignore_errors=True)


if __name__ == "__main__":
    main()
