"""Command-line interface: ``asterlite run | check | corpus``.

Exit status: 0 when every TEST_* check is OK (or a check finds no error),
1 when a check is NOOK, 2 on any error or unsupported command.
"""

from __future__ import annotations

import argparse
import json
import sys
from pathlib import Path


def _run(args) -> int:
    from asterlite.runtime.runner import format_summary, run_deck

    deck = Path(args.deck)
    output = Path(args.output) if args.output else Path("asterlite-out") / deck.stem
    report = run_deck(deck, output, echo=not args.quiet)
    if not args.quiet:
        print(format_summary(report))
        print(f"output folder: {output}")
    elif report.status not in ("PASS",):
        print(f"{report.deck}: {report.status} {report.message}", file=sys.stderr)
    return report.exit_code


def _check(args) -> int:
    from asterlite.runtime.runner import run_deck

    worst = 0
    results = []
    for deck in args.decks:
        report = run_deck(Path(deck), check_only=True)
        results.append(
            {
                "deck": deck,
                "status": "OK" if report.exit_code == 0 else "ERROR",
                "message": report.message,
            }
        )
        worst = max(worst, report.exit_code)
        if args.format == "text":
            print(f"{deck}: OK" if report.exit_code == 0 else f"{deck}: {report.message}")
    if args.format == "json":
        print(json.dumps({"decks": results}, indent=1))
    return worst


def _corpus(args) -> int:
    from asterlite.runtime.corpus import format_table, run_corpus

    def progress(row):
        if not args.quiet:
            print(f"  {row['deck']:<10} {row['status']:<12} {row['seconds']:7.2f} s", flush=True)

    only = args.only.split(",") if args.only else None
    rows = run_corpus(
        Path(args.directory), only=only, jobs=args.jobs, timeout=args.timeout, progress=progress
    )
    print(format_table(rows))
    if args.json:
        Path(args.json).write_text(json.dumps({"decks": rows}, indent=1) + "\n")
    return 0 if all(r["status"] == "PASS" for r in rows) else 1


def build_parser() -> argparse.ArgumentParser:
    parser = argparse.ArgumentParser(
        prog="asterlite",
        description="Run Code_Aster command files: modal transient dynamics with shocks.",
    )
    commands = parser.add_subparsers(dest="command", required=True)

    run = commands.add_parser("run", help="run a deck (.comm or .export)")
    run.add_argument("deck")
    run.add_argument("-o", "--output", help="output folder (default asterlite-out/<deck>)")
    run.add_argument("-q", "--quiet", action="store_true", help="print only problems")
    run.set_defaults(handler=_run)

    check = commands.add_parser("check", help="validate decks without computing")
    check.add_argument("decks", nargs="+")
    check.add_argument("--format", choices=("text", "json"), default="text")
    check.set_defaults(handler=_check)

    corpus = commands.add_parser("corpus", help="run every deck folder under a directory")
    corpus.add_argument("directory")
    corpus.add_argument("--json", help="write the table as JSON to this file")
    corpus.add_argument("--only", help="comma-separated deck names")
    corpus.add_argument("--jobs", type=int, default=2)
    corpus.add_argument("--timeout", type=float, default=900.0, help="seconds per deck")
    corpus.add_argument("-q", "--quiet", action="store_true")
    corpus.set_defaults(handler=_corpus)
    return parser


def main(argv: list[str] | None = None) -> int:
    args = build_parser().parse_args(argv)
    try:
        return args.handler(args)
    except KeyboardInterrupt:
        print("interrupted", file=sys.stderr)
        return 2
