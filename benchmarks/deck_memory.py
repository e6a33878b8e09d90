"""Peak memory of corpus decks, as the run's memory limit counts it.

asterlite's limit (``P memory_limit``, asterlite.watchdog) is on the
resident memory the run adds to what the process held when it started
(after the engine's libraries are imported). Each deck runs here in a fresh
process, with the limits lifted, while a thread samples the resident size
every 2 ms and notes the command and the innermost asterlite function the
main thread is in at the highest sample, overall and per command. Prints,
per deck: the start-up resident size, the peak above it, the same peak less
what loading or compiling kernels kept (``counted_peak_mb``: the figure the
limit compares, before the watchdog's trimming of freed memory), the
process's VmHWM, where the peak was, the run's status and checks, and each
command's highest sample above the start-up size.

With ``--all DIR...`` every deck folder of each corpus folder runs under its
export's own memory limit (so that an archive goes to disk past a quarter of
it, as in a real run; a deck past the limit ends ERROR as it would), one
line per deck is appended to ``--jsonl`` (decks already there are skipped,
so an interrupted walk resumes), and the summary prints the ratio of each
peak to the export's ``memory_limit`` and the decks above half of it.

Run from the repository root:

    python benchmarks/deck_memory.py                    # sdlv126h/i/j, sdlv127e, sdls01b
    python benchmarks/deck_memory.py sdlv126h --corpus /work/shared/aster-corpus-dyna
    python benchmarks/deck_memory.py --all /work/shared/aster-corpus* --jsonl /tmp/mem/all.jsonl
    python benchmarks/deck_memory.py --summary /tmp/mem/all.jsonl
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
    # the watchdog's signal handlers run on top of whatever they interrupt
    frame = sys._current_frames().get(main_id)
    command, inner = "", []
    while frame is not None:
        name = frame.f_code.co_filename
        if "asterlite" in name and "watchdog" not in name and len(inner) < 3:
            inner.append(f"{Path(name).stem}.{frame.f_code.co_name}")
        if "/commands/" in name and not command:
            command = Path(name).stem
        frame = frame.f_back
    return f"{command}: {' < '.join(inner)}"

by_command = {}

kernels_at_start = watchdog._compiling.resident
counted = {"bytes": 0}

def sample():
    while not done.is_set():
        size = resident()
        # what loading or compiling kernels kept is the engine's, not the study's
        kept = watchdog._compiling.resident - kernels_at_start
        counted["bytes"] = max(counted["bytes"], size - kept)
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
limit = None if sys.argv[4] == "export" else 0
report = run_deck(Path(sys.argv[1]), Path(sys.argv[2]), time_limit=0, memory_limit=limit)
done.set()
thread.join()
print(json.dumps({
    "start_mb": start / 2**20,
    "peak_above_start_mb": (peak["bytes"] - start) / 2**20,
    "vmhwm_mb": high_water_mark() / 2**20,
    "counted_peak_mb": (counted["bytes"] - start) / 2**20,
    "kernels_kept_mb": (watchdog._compiling.resident - kernels_at_start) / 2**20,
    "peak_at": peak["where"],
    "status": report.status,
    "message": (report.message or "")[:300] if report.status not in ("PASS", "OK") else "",
    "checks": f"{report.checks_ok}/{report.checks_total}",
    "seconds": round(report.seconds, 1),
    "above_start_by_command_mb": {
        command: [round((size - start) / 2**20), inner.split(": ")[-1]]
        for command, (size, inner) in sorted(by_command.items(), key=lambda kv: -kv[1][0])
    },
}))
"""


def measure(export: Path, output: Path, limit: str = "none", timeout: float | None = None) -> dict:
    """One deck in a fresh process; ``limit``: "export" (its memory limit) or "none"."""
    try:
        done = subprocess.run(
            [sys.executable, "-c", CHILD, str(export), str(output), str(SAMPLE_SECONDS), limit],
            capture_output=True,
            text=True,
            check=False,
            timeout=timeout,
        )
    except subprocess.TimeoutExpired:
        return {"status": "TIMEOUT", "seconds": timeout}
    lines = [line for line in done.stdout.splitlines() if line.startswith("{")]
    if not lines:
        return {"status": "FAILED", "stderr": done.stderr[-2000:]}
    return json.loads(lines[-1])


def export_memory_limit(export: Path) -> float | None:
    """The export's ``P memory_limit`` in MB (None when it gives none)."""
    for line in export.read_text(errors="replace").splitlines():
        words = line.split()
        if len(words) >= 3 and words[0] == "P" and words[1] == "memory_limit":
            return float(words[2])
    return None


def corpus_exports(folders: list[Path]):
    """(corpus folder name, deck, export) for every deck folder holding DECK.export."""
    for folder in folders:
        for deck_folder in sorted(path for path in folder.iterdir() if path.is_dir()):
            export = deck_folder / f"{deck_folder.name}.export"
            if export.is_file():
                yield folder.name, deck_folder.name, export


def read_results(path: Path) -> list[dict]:
    if not path.is_file():
        return []
    return [json.loads(line) for line in path.read_text().splitlines() if line.startswith("{")]


def summarise(results: list[dict], worst: int = 15) -> dict:
    """Decks above half their export's memory limit, and the worst ratios."""
    measured = [r for r in results if r.get("ratio") is not None]
    ranked = sorted(measured, key=lambda r: -r["ratio"])
    return {
        "decks": len(results),
        "measured": len(measured),
        "not_measured": [
            f"{r['corpus']}/{r['deck']} {r.get('status')}"
            for r in results
            if r.get("peak_above_start_mb") is None
        ],
        "without_limit": [f"{r['corpus']}/{r['deck']}" for r in results if not r["limit_mb"]],
        "above_half": len([r for r in measured if r["ratio"] > 0.5]),
        "above_limit": len([r for r in measured if r["ratio"] > 1.0]),
        "worst": [
            {
                "deck": f"{r['corpus']}/{r['deck']}",
                "peak_mb": round(r["peak_above_start_mb"], 1),
                "limit_mb": r["limit_mb"],
                "ratio": round(r["ratio"], 3),
                "status": r["status"],
                "peak_at": r.get("peak_at", ""),
            }
            for r in ranked[:worst]
        ],
    }


def markdown(results: list[dict]) -> str:
    """A table of every measured deck, highest ratio first."""
    lines = [
        "| deck | limit MB | peak above start-up MB | peak / limit | status | where the peak was |",
        "|---|---|---|---|---|---|",
    ]
    ranked = sorted(results, key=lambda r: -(r.get("ratio") or 0.0))
    for r in ranked:
        peak = r.get("peak_above_start_mb")
        ratio = r.get("ratio")
        corpus = r["corpus"].removeprefix("aster-corpus").lstrip("-") or "main"
        limit = "none" if r["limit_mb"] is None else f"{r['limit_mb']:g}"
        lines.append(
            f"| {corpus}/{r['deck']} | {limit} "
            f"| {'-' if peak is None else f'{peak:.0f}'} "
            f"| {'-' if ratio is None else f'{ratio:.2f}'} "
            f"| {r.get('status')} | {r.get('peak_at', '').replace('|', '/')} |"
        )
    return "\n".join(lines)


def walk(folders: list[Path], jsonl: Path, timeout: float | None) -> None:
    done = {(r["corpus"], r["deck"]) for r in read_results(jsonl)}
    jsonl.parent.mkdir(parents=True, exist_ok=True)
    with tempfile.TemporaryDirectory(prefix="deck-memory-") as scratch:
        for corpus, deck, export in corpus_exports(folders):
            if (corpus, deck) in done:
                continue
            limit = export_memory_limit(export)
            result = measure(export, Path(scratch) / deck, "export", timeout)
            peak = result.get("peak_above_start_mb")
            ratio = None if peak is None or not limit else peak / limit
            result = {"corpus": corpus, "deck": deck, "limit_mb": limit, "ratio": ratio, **result}
            with jsonl.open("a") as out:
                out.write(json.dumps(result) + "\n")
            shown = "-" if ratio is None else f"{ratio:.2f}"
            print(f"{corpus}/{deck} {result['status']} peak/limit {shown}", flush=True)


def main() -> None:
    parser = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    parser.add_argument("decks", nargs="*", default=DEFAULT_DECKS)
    parser.add_argument("--corpus", type=Path, default=DEFAULT_CORPUS)
    parser.add_argument("--all", type=Path, nargs="+", metavar="DIR", help="corpus folders")
    parser.add_argument("--jsonl", type=Path, default=Path("deck_memory.jsonl"))
    parser.add_argument("--timeout", type=float, default=1800.0, help="seconds per deck")
    parser.add_argument("--summary", type=Path, help="only summarise this --jsonl file")
    parser.add_argument("--markdown", action="store_true", help="with --summary: a table")
    args = parser.parse_args()
    if args.summary:
        results = read_results(args.summary)
        print(markdown(results) if args.markdown else json.dumps(summarise(results), indent=1))
        return
    if args.all:
        walk(args.all, args.jsonl, args.timeout)
        print(json.dumps(summarise(read_results(args.jsonl)), indent=1))
        return
    with tempfile.TemporaryDirectory(prefix="deck-memory-") as scratch:
        for deck in args.decks:
            export = args.corpus / deck / f"{deck}.export"
            result = measure(export, Path(scratch) / deck)
            print(deck, json.dumps(result), flush=True)


if __name__ == "__main__":
    main()
