"""Check every verification deck of a code_aster snapshot: the acceptance test
of the language data and of ``asterlite check``'s verdicts.

Usage::

    python3 -m asterlite.tools.astest_check GIT_DIR --version 17 \\
        [--sample 400 --seed 27 | --decks sdnd100a ...] [--jobs 2] \\
        [--markdown docs/language-astest-17.md] [--json FILE] [--work DIR]

``GIT_DIR`` is a (bare) git directory of code_aster (the decks and their
data files are read from ``astest/`` of its HEAD with ``git cat-file``,
nothing is checked out). Each deck (its ``.export`` and the files its ``F``
lines name) is laid out in a folder under ``--work`` (a temporary folder by
default) and checked with :func:`asterlite.runtime.check_deck.check_deck`
read as code_aster ``--version``, one deck at a time in each of ``--jobs``
worker processes.

Decks code_aster itself expects to fail are told apart, and how:

- the export says so: a ``P expected_diag`` line (``<S>_CPU_LIMIT``...);
- every invalid finding of the deck is a call inside a ``try:`` block that
  has an ``except`` clause, or inside ``with ....assertRaises...:``: the
  deck calls the command to check that code_aster refuses it.

Such decks are counted as ``INVALID (expected)``, apart from INVALID.
The table lists each deck with its status, its findings by kind and its
first finding; the summary counts decks per status.
"""

from __future__ import annotations

import argparse
import ast
import json
import os
import random
import selectors
import shutil
import subprocess
import sys
import tempfile
import time
from collections import Counter
from pathlib import Path

from asterlite.runtime.check_deck import check_deck

# ------------------------------------------------------------- the snapshot


class Snapshot:
    """Files of a git directory's HEAD, read through one ``git cat-file --batch``."""

    def __init__(self, git_dir: Path):
        self.git_dir = str(git_dir)
        listing = subprocess.run(
            ["git", "--git-dir", self.git_dir, "ls-tree", "-r", "--name-only", "HEAD", "astest/"],
            capture_output=True,
            text=True,
            check=True,
        ).stdout
        self.files = [line for line in listing.splitlines() if line]
        self.by_name: dict[str, str] = {}
        for path in self.files:
            self.by_name.setdefault(path.rsplit("/", 1)[-1], path)
        self.commit = subprocess.run(
            ["git", "--git-dir", self.git_dir, "rev-parse", "HEAD"],
            capture_output=True,
            text=True,
            check=True,
        ).stdout.strip()
        self._batch = subprocess.Popen(
            ["git", "--git-dir", self.git_dir, "cat-file", "--batch"],
            stdin=subprocess.PIPE,
            stdout=subprocess.PIPE,
        )

    def decks(self) -> list[str]:
        return sorted(
            p[len("astest/") : -len(".export")]
            for p in self.files
            if p.startswith("astest/") and p.endswith(".export") and p.count("/") == 1
        )

    def read(self, path: str) -> bytes | None:
        self._batch.stdin.write(f"HEAD:{path}\n".encode())
        self._batch.stdin.flush()
        header = self._batch.stdout.readline().decode().split()
        if len(header) < 3 or header[1] != "blob":
            return None
        size = int(header[2])
        data = self._batch.stdout.read(size)
        self._batch.stdout.read(1)  # the newline after the content
        return data

    def close(self) -> None:
        self._batch.stdin.close()
        self._batch.wait()


def extract(snapshot: Snapshot, deck: str, folder: Path) -> list[str]:
    """Lay out ``deck``'s export and data files in ``folder``; the files missing."""
    folder.mkdir(parents=True, exist_ok=True)
    export = snapshot.read(f"astest/{deck}.export")
    if export is None:
        return ["export"]
    (folder / f"{deck}.export").write_bytes(export)
    missing = []
    for line in export.decode("utf-8", "replace").replace("\r", "").splitlines():
        fields = line.split()
        if len(fields) < 4 or fields[0] != "F" or "D" not in fields[3]:
            continue
        base = fields[2].rsplit("/", 1)[-1]
        source = f"astest/{fields[2]}"
        data = snapshot.read(source)
        if data is None and base in snapshot.by_name:
            data = snapshot.read(snapshot.by_name[base])
        if data is None:
            missing.append(fields[2])
            continue
        (folder / base).write_bytes(data)
    return missing


# ----------------------------------------------------------------- expected


def expected_diag(export: Path) -> str | None:
    """The ``P expected_diag`` of an export, if any."""
    for line in export.read_text(errors="replace").splitlines():
        fields = line.split()
        if len(fields) >= 3 and fields[0] == "P" and fields[1] == "expected_diag":
            return fields[2]
    return None


def guarded_lines(path: Path) -> set[int]:
    """Lines of ``try:`` bodies that have an ``except`` clause, and of
    ``with ...assertRaises...:`` bodies (parsed by Python's ast, never run)."""
    try:
        tree = ast.parse(path.read_text(errors="replace"))
    except (SyntaxError, ValueError, RecursionError, MemoryError):
        return set()
    lines: set[int] = set()
    for node in ast.walk(tree):
        if isinstance(node, ast.Try) and node.handlers:
            for statement in node.body:
                lines.update(
                    range(statement.lineno, (statement.end_lineno or statement.lineno) + 1)
                )
        elif isinstance(node, ast.With):
            if any("assertRaises" in ast.unparse(item.context_expr) for item in node.items):
                for statement in node.body:
                    end = statement.end_lineno or statement.lineno
                    lines.update(range(statement.lineno, end + 1))
    return lines


def all_invalid_expected(result: dict) -> bool:
    """Every invalid finding is a call the deck guards with try/assertRaises."""
    invalid = [f for f in result["findings"] if f["kind"] == "invalid"]
    if not invalid:
        return False
    guarded: dict[str, set[int]] = {}
    for finding in invalid:
        file = finding.get("file")
        if not file or finding.get("line") is None:
            return False
        if file not in guarded:
            guarded[file] = guarded_lines(Path(file))
        if finding["line"] not in guarded[file]:
            return False
    return True


# ------------------------------------------------------------------- checks


def _check_one(task: tuple) -> dict:
    deck, export, version, time_limit = task

    start = time.perf_counter()
    try:
        result = check_deck(Path(export), aster_version=version, time_limit=time_limit).as_json()
    except Exception as error:  # never lose the whole table for one deck
        result = {"status": "ERROR", "message": f"{type(error).__name__}: {error}", "findings": []}
    result["deck"] = deck
    result["seconds"] = round(time.perf_counter() - start, 3)
    diag = expected_diag(Path(export))
    if diag:
        result["expected"] = f"export: P expected_diag {diag}"
    elif result["status"] == "INVALID" and all_invalid_expected(result):
        result["expected"] = "every invalid call is guarded by try/except or assertRaises"
    if result["status"] == "INVALID" and result.get("expected"):
        result["status"] = "INVALID (expected)"
    return result


def run_checks(tasks: list, jobs: int, progress=None, wall_limit: float = 600.0) -> list[dict]:
    """Check the decks in ``jobs`` worker processes (each ``python3 -m
    asterlite.tools.astest_check --worker``, one deck at a time).
    A worker that dies (a backstop signal of the check's limits kills the
    process) or takes longer than ``wall_limit`` seconds on a deck gives
    that deck an ERROR and is replaced."""
    pending = list(reversed(tasks))
    results: list[dict] = []
    workers: list[_Worker] = []
    selector = selectors.DefaultSelector()

    def start_worker() -> None:
        worker = _Worker()
        workers.append(worker)
        selector.register(worker.process.stdout, selectors.EVENT_READ, worker)

    def give(worker) -> None:
        if pending:
            worker.send(pending.pop())

    def done(result) -> None:
        results.append(result)
        if progress:
            progress(result, len(results), len(tasks))

    for _ in range(max(1, min(jobs, len(tasks)))):
        start_worker()
    for worker in list(workers):
        give(worker)
    while any(w.task is not None for w in workers):
        for key, _ in selector.select(timeout=5.0):
            worker = key.data
            line = worker.process.stdout.readline()
            if not line:  # the worker died with its deck
                selector.unregister(worker.process.stdout)
                done(worker.failed("the check's process died (killed by a signal)"))
                worker.stop()
                workers.remove(worker)
                start_worker()
                give(workers[-1])
                continue
            result = json.loads(line)
            worker.task = None
            done(result)
            give(worker)
        now = time.monotonic()
        for worker in list(workers):
            if worker.task is not None and now - worker.started > wall_limit:
                selector.unregister(worker.process.stdout)
                done(worker.failed(f"no verdict within {wall_limit:.0f} s (wall clock)"))
                worker.stop()
                workers.remove(worker)
                start_worker()
                give(workers[-1])
    for worker in workers:
        worker.stop()
    selector.close()
    return sorted(results, key=lambda r: r["deck"])


class _Worker:
    def __init__(self):
        self.process = subprocess.Popen(
            [sys.executable, "-m", "asterlite.tools.astest_check", "--worker"],
            stdin=subprocess.PIPE,
            stdout=subprocess.PIPE,
            text=True,
        )
        self.task = None
        self.started = 0.0

    def send(self, task) -> None:
        self.task = task
        self.started = time.monotonic()
        self.process.stdin.write(json.dumps(task) + "\n")
        self.process.stdin.flush()

    def failed(self, why: str) -> dict:
        deck = self.task[0]
        self.task = None
        return {"deck": deck, "status": "ERROR", "message": why, "findings": [], "seconds": 0.0}

    def stop(self) -> None:
        try:
            self.process.stdin.close()
        except OSError:
            pass
        try:
            self.process.wait(timeout=5)
        except subprocess.TimeoutExpired:
            self.process.kill()
            self.process.wait()


def worker_loop() -> int:
    """``--worker``: a task per line on stdin, a result per line on stdout."""
    for line in sys.stdin:
        result = _check_one(tuple(json.loads(line)))
        sys.stdout.write(json.dumps(result) + "\n")
        sys.stdout.flush()
    return 0


# -------------------------------------------------------------------- table

STATUSES = ("VALID", "UNSUPPORTED", "INVALID", "INVALID (expected)", "ERROR")
KINDS = ("invalid", "unsupported", "unsupported-python")


def first_finding(result: dict, kind: str | None = None) -> str:
    for finding in result.get("findings", []):
        if kind is None or finding["kind"] == kind:
            text = f"{finding['keyword']}: " if finding.get("keyword") else ""
            return _cell(text + finding["message"])
    return _cell(result.get("message", ""))


def _cell(text: str, limit: int = 140) -> str:
    text = " ".join(text.split()).replace("|", "\\|")
    return text if len(text) <= limit else text[: limit - 3] + "..."


def markdown(results: list[dict], version: int, commit: str, seconds: float, jobs: int) -> str:
    counts = Counter(r["status"] for r in results)
    lines = [
        f"# `asterlite check` on code_aster {version}'s verification decks",
        "",
        f"Snapshot commit `{commit}`, {len(results)} decks, checked as code_aster {version} "
        f"in {seconds:.0f} s with {jobs} worker process(es) "
        f"(`python3 -m asterlite.tools.astest_check`).",
        "",
        "| status | decks |",
        "|---|---|",
    ]
    lines += [f"| {status} | {counts.get(status, 0)} |" for status in STATUSES]
    kinds = Counter()
    for result in results:
        for finding in result.get("findings", []):
            kinds[finding["kind"]] += 1
    lines += ["", "Findings by kind: " + ", ".join(f"{k} {kinds.get(k, 0)}" for k in KINDS), ""]
    lines += [
        "| deck | status | invalid | unsupported | unsupported-python | first finding |",
        "|---|---|---|---|---|---|",
    ]
    for result in results:
        found = Counter(f["kind"] for f in result.get("findings", []))
        kind = "invalid" if found.get("invalid") else None
        first = first_finding(result, kind)
        if result.get("expected"):
            first = _cell(f"[{result['expected']}] {first}")
        lines.append(
            f"| {result['deck']} | {result['status']} | {found.get('invalid', 0)} | "
            f"{found.get('unsupported', 0)} | {found.get('unsupported-python', 0)} | {first} |"
        )
    return "\n".join(lines) + "\n"


def summary(results: list[dict]) -> str:
    counts = Counter(r["status"] for r in results)
    return ", ".join(f"{s} {counts.get(s, 0)}" for s in STATUSES)


# --------------------------------------------------------------------- main


def main(argv: list[str] | None = None) -> int:
    argv = sys.argv[1:] if argv is None else argv
    if argv == ["--worker"]:
        return worker_loop()
    parser = argparse.ArgumentParser(
        prog="python3 -m asterlite.tools.astest_check",
        description="asterlite check on every astest deck of a code_aster snapshot",
    )
    parser.add_argument("git_dir", help="a (bare) git directory of code_aster")
    parser.add_argument("--version", type=int, required=True, help="code_aster major version")
    parser.add_argument("--decks", nargs="*", help="only these decks")
    parser.add_argument("--sample", type=int, help="a random sample of this many decks")
    parser.add_argument("--seed", type=int, default=27, help="seed of --sample (default 27)")
    parser.add_argument("--jobs", type=int, default=os.cpu_count() or 1)
    parser.add_argument(
        "--deck-time-limit",
        type=float,
        default=60.0,
        help="CPU seconds a deck's check may take (default 60; 0: the export's)",
    )
    parser.add_argument("--work", help="folder for the decks' files (default: temporary)")
    parser.add_argument("--markdown", help="write the table here")
    parser.add_argument("--json", help="write every deck's result here")
    parser.add_argument("--quiet", action="store_true")
    args = parser.parse_args(argv)

    snapshot = Snapshot(Path(args.git_dir))
    decks = args.decks or snapshot.decks()
    if args.sample and not args.decks:
        decks = sorted(random.Random(args.seed).sample(decks, min(args.sample, len(decks))))
    work = Path(args.work) if args.work else Path(tempfile.mkdtemp(prefix="astest-check-"))
    start = time.perf_counter()
    tasks = []
    for deck in decks:
        folder = work / deck
        missing = extract(snapshot, deck, folder)
        if "export" not in missing:
            limit = args.deck_time_limit or None
            tasks.append((deck, str(folder / f"{deck}.export"), args.version, limit))
    snapshot.close()
    extracted = time.perf_counter() - start

    def progress(result, done, total):
        if not args.quiet:
            first = first_finding(result) if result["status"] != "VALID" else ""
            print(f"[{done}/{total}] {result['deck']:<12} {result['status']:<18} {first[:90]}")

    wall = max(300.0, 5 * (args.deck_time_limit or 120.0))
    results = run_checks(tasks, args.jobs, progress, wall_limit=wall)
    seconds = time.perf_counter() - start
    if args.markdown:
        text = markdown(results, args.version, snapshot.commit, seconds, args.jobs)
        Path(args.markdown).write_text(text, encoding="utf-8")
    if args.json:
        Path(args.json).write_text(json.dumps(results, indent=1), encoding="utf-8")
    checked = sum(r.get("seconds", 0) for r in results)
    print(
        f"{len(results)} decks in {seconds:.0f} s (extraction {extracted:.0f} s, "
        f"check {checked / max(len(results), 1):.2f} s per deck): {summary(results)}"
    )
    if not args.work:
        shutil.rmtree(work, ignore_errors=True)
    return 0


if __name__ == "__main__":
    sys.exit(main())
