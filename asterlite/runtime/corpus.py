"""Run every deck folder of a corpus, each in its own process, and tabulate.

Each deck runs as ``python -I ... asterlite run`` in a subprocess (isolated
from the current folder: :mod:`asterlite.isolation`) so a crash,
a runaway computation or a leak in one deck cannot affect the others, and
a per-deck timeout applies.
"""

from __future__ import annotations

import json
import subprocess
import tempfile
import time
from concurrent.futures import ThreadPoolExecutor
from pathlib import Path

from asterlite.isolation import python_command


def find_decks(root: Path) -> list[Path]:
    """One run file per deck folder: ``<folder>/<folder>.export``, else any export."""
    decks = []
    for folder in sorted(p for p in root.iterdir() if p.is_dir()):
        preferred = folder / f"{folder.name}.export"
        exports = [preferred] if preferred.exists() else sorted(folder.glob("*.export"))
        if exports:
            decks.append(exports[0])
    return decks


def run_one(export: Path, timeout: float) -> dict:
    start = time.perf_counter()
    with tempfile.TemporaryDirectory(prefix="asterlite-corpus-") as tmp:
        out = Path(tmp) / export.stem
        # isolated: nothing in the current folder or the deck's is imported
        command = python_command("asterlite", "run", str(export), "-o", str(out), "--quiet")
        try:
            completed = subprocess.run(command, capture_output=True, text=True, timeout=timeout)
        except subprocess.TimeoutExpired:
            return _row(export, "ERROR", f"timeout after {timeout:.0f} s", start)
        summary = out / "summary.json"
        if not summary.exists():
            tail = (completed.stderr or completed.stdout).strip().splitlines()[-3:]
            return _row(export, "ERROR", "no summary written: " + " | ".join(tail), start)
        data = json.loads(summary.read_text())
        if data.get("status") == "RUNNING":  # the process ended without finishing the run
            detail = f"killed (exit status {completed.returncode}) before the run finished"
            return _row(export, "ERROR", detail, start)
    return {
        "deck": export.parent.name,
        "status": data["status"],
        "checks_ok": data["checks_ok"],
        "checks_total": data["checks_total"],
        "strict_ok": data["strict_ok"],
        "seconds": round(time.perf_counter() - start, 2),
        "message": _first_line(data.get("message", "")),
        # each TEST_* value as the run computed it (JSON keeps a float's every bit)
        "tests": [
            [test["command"], test["label"], test["value"]] for test in data.get("tests", [])
        ],
    }


def _first_line(message: str) -> str:
    lines = [line for line in message.splitlines() if line.strip()]
    return lines[0] if lines else ""


def _row(export: Path, status: str, message: str, start: float) -> dict:
    return {
        "deck": export.parent.name,
        "status": status,
        "checks_ok": 0,
        "checks_total": 0,
        "strict_ok": 0,
        "seconds": round(time.perf_counter() - start, 2),
        "message": message,
        "tests": [],
    }


def run_corpus(root: Path, *, only=None, jobs: int = 2, timeout: float = 900.0, progress=None):
    decks = find_decks(root)
    if only:
        wanted = set(only)
        decks = [d for d in decks if d.parent.name in wanted]
    with ThreadPoolExecutor(max_workers=max(1, jobs)) as pool:
        futures = [pool.submit(run_one, deck, timeout) for deck in decks]
        rows = []
        for future in futures:
            row = future.result()
            rows.append(row)
            if progress is not None:
                progress(row, len(rows), len(decks))
    return rows


def format_table(rows: list[dict]) -> str:
    header = f"{'deck':<10} {'status':<12} {'checks':>9} {'strict':>6} {'seconds':>8}  message"
    lines = [header, "-" * len(header)]
    for row in rows:
        checks = f"{row['checks_ok']}/{row['checks_total']}"
        lines.append(
            f"{row['deck']:<10} {row['status']:<12} {checks:>9} {row['strict_ok']:>6} "
            f"{row['seconds']:>8.2f}  {row['message'][:110]}"
        )
    counts = {}
    for row in rows:
        counts[row["status"]] = counts.get(row["status"], 0) + 1
    lines.append("")
    lines.append("  ".join(f"{k}: {v}" for k, v in sorted(counts.items())) + f"  (of {len(rows)})")
    return "\n".join(lines)
