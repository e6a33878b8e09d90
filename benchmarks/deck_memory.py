"""Peak memory of corpus decks, as the run's memory limit counts it.

asterlite's limit (``P memory_limit``, asterlite.watchdog) is on the
resident memory the run adds to what the process held when it started
(after the engine's libraries are imported). Each deck runs here in a fresh
process, with the limits lifted, while a thread samples the resident size
every 2 ms and notes the command and the innermost asterlite function the
main thread is in at the highest sample, overall and per command. Prints,
per deck: the start-up resident size, the peak above it (the figure the
limit compares), the process's VmHWM, where the peak was, the run's status
and checks, and each command's highest sample above the start-up size.

Run from the repository root:

    python benchmarks/deck_memory.py                    # sdlv126h/i/j, sdlv127e, sdls01b
    python benchmarks/deck_memory.py sdlv126h --corpus /work/shared/aster-corpus-dyna
"""

from __future__ import annotations

import argparse
import json
import subprocess
import sys
import tempfile
from pathlib import Path

DEFAULT_DECKS = ("sdlv126h", "sdlv126i", "sdlv126j", "sdlv127e", "sdls01b")
DEFAULT_CORPUS = Path(__file__).resolve().parents[1].parent / "shared" / "aster-corpus-dyna"
SAMPLE_SECONDS = 0.002

CHILD = r"""
import json, os, sys, threading, time
from pathlib import Path

PAGE = os.sysconf("SC_PAGE_SIZE")

def resident():
    with open("/proc/self/statm") as statm:
        return int(statm.read().split()[1]) * PAGE

def high_water_mark():
    for line in open("/proc/self/status"):
        if line.startswith("VmHWM:"):
            return int(line.split()[1]) * 1024

from asterlite import watchdog
watchdog.preload_engine()
from asterlite.runtime.runner import run_deck

main_id = threading.get_ident()
peak = {"bytes": 0, "where": ""}
done = threading.Event()

def where():
    frame = sys._current_frames().get(main_id)
    command, inner = "", ""
    while frame is not None:
        name = frame.f_code.co_filename
        if "asterlite" in name and not inner:
            inner = f"{Path(name).stem}.{frame.f_code.co_name}"
        if "/commands/" in name and not command:
            command = Path(name).stem
        frame = frame.f_back
    return f"{command}: {inner}"

by_command = {}

def sample():
    while not done.is_set():
        size = resident()
        here = where()
        command = here.split(":")[0] or "-"
        if size > by_command.get(command, (0, ""))[0]:
            by_command[command] = (size, here)
        if size > peak["bytes"]:
            peak["bytes"], peak["where"] = size, here
        time.sleep(SAMPLE)

SAMPLE = float(sys.argv[3])
start = resident()
thread = threading.Thread(target=sample, daemon=True)
thread.start()
report = run_deck(Path(sys.argv[1]), Path(sys.argv[2]), time_limit=0, memory_limit=0)
done.set()
thread.join()
print(json.dumps({
    "start_mb": start / 2**20,
    "peak_above_start_mb": (peak["bytes"] - start) / 2**20,
    "vmhwm_mb": high_water_mark() / 2**20,
    "peak_at": peak["where"],
    "status": report.status,
    "checks": f"{report.checks_ok}/{report.checks_total}",
    "seconds": round(report.seconds, 1),
    "above_start_by_command_mb": {
        command: [round((size - start) / 2**20), inner.split(": ")[-1]]
        for command, (size, inner) in sorted(by_command.items(), key=lambda kv: -kv[1][0])
    },
}))
"""


def measure(export: Path, output: Path) -> dict:
    done = subprocess.run(
        [sys.executable, "-c", CHILD, str(export), str(output), str(SAMPLE_SECONDS)],
        capture_output=True,
        text=True,
        check=False,
    )
    lines = [line for line in done.stdout.splitlines() if line.startswith("{")]
    if not lines:
        return {"status": "FAILED", "stderr": done.stderr[-2000:]}
    return json.loads(lines[-1])


def main() -> None:
    parser = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    parser.add_argument("decks", nargs="*", default=DEFAULT_DECKS)
    parser.add_argument("--corpus", type=Path, default=DEFAULT_CORPUS)
    args = parser.parse_args()
    with tempfile.TemporaryDirectory(prefix="deck-memory-") as scratch:
        for deck in args.decks:
            export = args.corpus / deck / f"{deck}.export"
            result = measure(export, Path(scratch) / deck)
            print(deck, json.dumps(result), flush=True)


if __name__ == "__main__":
    main()
