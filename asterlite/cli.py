"""Command-line interface: ``asterlite run | status | check | corpus | sweep | plot |
report | converge | sensitivity | port | warmup``.

Exit status: 0 when every TEST_* check is OK, or the deck ran to its end
without any check (DONE), or ``check`` finds no error; 1 when a check is
NOOK; 2 on any error, unsupported command, interruption or internal error
(one line here, the traceback in the run's message.log).
"""

from __future__ import annotations

import argparse
import atexit
import gc
import json
import os
import shlex
import sys
from pathlib import Path

from asterlite import __version__, progress
from asterlite.errors import AsterliteError
from asterlite.extras import MissingExtraError
from asterlite.io.export import limit_refusal
from asterlite.runtime import deferred_modules, threads


def _start_engine(deck: Path) -> None:
    """Before numpy loads: the export's threads, then numpy's unused tools
    deferred (runtime.deferred_modules)."""
    threads.use_threads(threads.export_threads(deck))
    deferred_modules.defer_numpy_tools()


def _run(args) -> int:
    from asterlite.runtime import console, stops

    # a signal from here on waits until the run has taken its output folder
    # (an earlier result moved aside, RUNNING written), then stops it there
    stops.hold_signals()
    from asterlite.runtime.runner import format_summary, run_deck

    if args.no_progress:
        progress.enable(False)
    deck = Path(args.deck)
    if deck.is_dir():  # a deck folder: the one .export (or .comm) in it
        from asterlite.api import DeckNotFound, deck_in_folder

        try:
            deck = deck_in_folder(deck)
        except DeckNotFound as error:
            print(error, file=sys.stderr)
            return 2
    _start_engine(deck)
    output = Path(args.output) if args.output else Path("asterlite-out") / deck.stem
    if (args.mpi or args.mpi_python) is not None and _select_mpi(args, output) is not None:
        return 2
    try:
        report = run_deck(
            deck,
            output,
            echo=not args.quiet,
            save_results=args.save_results or args.report,  # the report draws the histories
            report_page=args.report,
            time_limit=args.time_limit,
            memory_limit=args.memory_limit,
            output_limit=args.output_limit,
            aster_version=args.aster_version,
            result_paths=args.allow_result_paths,
            keep_previous=args.keep_previous,
        )
    except stops.RunInterrupted as interrupt:  # came once the result was written
        if interrupt.report is None:
            raise
        report = interrupt.report
    # the verdict is in message.log and summary.json: a closed pipe or
    # terminal silences what follows, never changes the exit status
    if not args.quiet:
        console.say(format_summary(report))
        console.say(f"output folder: {output}")
    elif report.status not in ("PASS", "DONE"):
        console.say(f"{report.deck}: {report.status} {report.message}", sys.stderr)
    if args.report:
        _say_report(output)
    return report.exit_code


def _select_mpi(args, output: Path) -> str | None:
    """Select the PETSc/SLEPc modal solver across MPI ranks for this run
    (asterlite.modal.slepc_mpi), or say on stderr why it cannot run."""
    from asterlite.modal import slepc_mpi

    if args.mpi is None:
        print("asterlite run: --mpi-python needs --mpi LAUNCHER", file=sys.stderr)
        return "--mpi-python without --mpi"
    python = args.mpi_python or slepc_mpi.DEFAULT_PYTHON
    problem = slepc_mpi.unavailable(shlex.split(args.mpi), python)
    if problem is not None:
        print(f"asterlite run: {problem}", file=sys.stderr)
        return problem
    os.environ[slepc_mpi.LAUNCHER_VARIABLE] = args.mpi
    os.environ[slepc_mpi.PYTHON_VARIABLE] = python
    os.environ[slepc_mpi.FOLDER_VARIABLE] = str(output.resolve())
    return None


def _status(args) -> int:
    from asterlite.runtime.console import say
    from asterlite.runtime.folder_status import folder_status

    found = folder_status(Path(args.folder))
    for line in found.lines:
        say(line)
    return found.exit_code


def _say_report(output: Path) -> None:
    """Where ``asterlite run --report`` put the page (incomplete/ for a run
    that did not complete)."""
    from asterlite.report import REPORT_NAME

    found = sorted(output.glob(f"incomplete*/{REPORT_NAME}"), key=lambda p: p.stat().st_mtime)
    page = output / REPORT_NAME
    if page.is_file() and (not found or page.stat().st_mtime >= found[-1].stat().st_mtime):
        print(f"report: {page}")
    elif found:
        print(f"report: {found[-1]}")
    else:
        print("report: not written (see message.log)", file=sys.stderr)


def _report(args) -> int:
    from asterlite.report import ReportError, write_report

    try:
        page = write_report(Path(args.folder), Path(args.output) if args.output else None)
    except ReportError as error:
        print(f"error: {error}", file=sys.stderr)
        return 2
    print(f"report: {page}")
    return 0


def _check(args) -> int:
    """Each deck VALID (0), UNSUPPORTED (3), INVALID (2) or ERROR (4), with
    every finding (asterlite.runtime.check_deck); the worst status's code."""
    from asterlite.runtime.check_deck import check_deck, format_text, worst_exit_code

    checks = []
    for deck in args.decks:
        check = check_deck(Path(deck), aster_version=args.aster_version)
        checks.append(check)
        if args.format == "text":
            print(format_text(check))
    if args.format == "json":
        print(json.dumps({"decks": [c.as_json() for c in checks]}, indent=1))
    return worst_exit_code(checks)


def _corpus(args) -> int:
    from asterlite.runtime.corpus import format_table, run_corpus

    if args.no_progress or args.quiet:
        progress.enable(False)
    bar = None

    def report(row, done, total):
        nonlocal bar
        if bar is None:  # a bar over the decks (terminal only), lines above it
            bar = progress.count_bar("corpus", total)
        if not args.quiet:
            line = f"  {row['deck']:<10} {row['status']:<12} {row['seconds']:7.2f} s"
            if isinstance(bar, progress.NoBar):
                print(line, flush=True)
            else:
                bar.write(line)
        bar.update(done, f"{row['deck']} {row['status']}")

    only = args.only.split(",") if args.only else None
    try:
        rows = run_corpus(
            Path(args.directory), only=only, jobs=args.jobs, timeout=args.timeout, progress=report
        )
    finally:
        if bar is not None:
            bar.close()
    print(format_table(rows))
    if args.json:
        Path(args.json).write_text(json.dumps({"decks": rows}, indent=1) + "\n")
    return 0 if all(r["status"] in ("PASS", "DONE") for r in rows) else 1


def _sweep(args) -> int:
    from asterlite.runtime import sweep

    deck = Path(args.deck)
    if not deck.is_file():
        print(f"error: {deck}: no such deck", file=sys.stderr)
        return 2
    _start_engine(deck)
    try:
        settings = [sweep.parse_setting(text) for text in args.set]
        sweep.variants(settings)  # rejects a name set twice before anything runs
        unknown = sweep.unknown_names(deck, settings)
    except sweep.SweepError as error:
        print(f"error: {error}", file=sys.stderr)
        return 2
    if unknown:
        print(f"error: --set {', '.join(unknown)}: the deck never assigns it", file=sys.stderr)
        return 2
    output = Path(args.output) if args.output else Path("asterlite-out") / f"{deck.stem}-sweep"
    variables = [s.name for s in settings]

    def progress(row):
        if not args.quiet:
            where = " ".join(f"{name}={row[name]!r}" for name in variables)
            print(f"  {where}: {row['status']}", flush=True)

    with sweep.dask_client(args.scheduler, args.workers) as client:
        rows = sweep.run_sweep(deck, settings, output, client, progress=progress)
    paths = sweep.write_tables(rows, variables, output)
    print(sweep.format_sweep_table(rows, variables))
    print("table: " + ", ".join(str(p) for p in paths))
    return sweep.sweep_exit_code(rows)


def _plot(args) -> int:
    from asterlite.post import plots

    try:
        path = plots.plot_from_store(
            Path(args.result),
            result=args.name,
            node=args.node,
            component=args.cmp,
            shock=args.shock,
            quantity=args.quantity,
            field=args.field,
            output=Path(args.output) if args.output else None,
        )
    except (AsterliteError, ValueError, KeyError, OSError) as error:
        print(f"error: {error}", file=sys.stderr)
        return 2
    print(f"plot: {path}")
    return 0


def _converge(args) -> int:
    from asterlite.runtime import converge

    deck = Path(args.deck)
    if not deck.is_file():
        print(f"error: {deck}: no such deck", file=sys.stderr)
        return 2
    _start_engine(deck)
    try:
        schemes = converge.parse_schemes(args.schemes)
        extra = dict(converge.parse_keyword(text) for text in args.keyword or ())

        def progress(outcome):
            if not args.quiet:
                setting = outcome.setting
                print(
                    f"  {setting.scheme:<15} {setting.knob}={outcome.text}: {outcome.status}"
                    f" {outcome.message[:100]}".rstrip(),
                    flush=True,
                )

        with converge.memory_cap(args.memory_fraction):
            study = _run_converge(converge, args, deck, schemes, extra, progress)
    except converge.ConvergeError as error:
        print(f"error: {error}", file=sys.stderr)
        return 2
    output = Path(args.output) if args.output else Path("asterlite-out") / f"{deck.stem}-converge"
    paths = converge.write_outputs(study, output)
    print(converge.format_table(study))
    print("written: " + ", ".join(str(p) for p in paths))
    return 0 if args.target is None or converge.cheapest(study) is not None else 1


def _run_converge(converge, args, deck, schemes, extra, progress):
    return converge.run_study(
        deck,
        schemes=schemes,
        steps=converge.parse_values(args.steps),
        tolerances=converge.parse_values(args.tolerances),
        points=converge.parse_values(args.points),
        against=args.against,
        reference=args.reference,
        target=args.target,
        pattern=args.quantities,
        extra=extra,
        repeat=args.repeat,
        min_step_ratio=args.min_step_ratio,
        progress=progress,
    )


def _sensitivity(args) -> int:
    from asterlite.runtime import converge, sensitivity

    deck = Path(args.deck)
    if not deck.is_file():
        print(f"error: {deck}: no such deck", file=sys.stderr)
        return 2
    _start_engine(deck)

    def progress(ulps, report):
        if not args.quiet:
            print(
                f"  PAS {ulps:+d} ulp: {report.status} "
                f"{report.checks_ok}/{report.checks_total} checks OK",
                flush=True,
            )

    try:
        with converge.memory_cap(args.memory_fraction):
            study = sensitivity.run_sensitivity(deck, runs=args.runs, progress=progress)
    except converge.ConvergeError as error:
        print(f"error: {error}", file=sys.stderr)
        return 2
    default_output = Path("asterlite-out") / f"{deck.stem}-sensitivity"
    output = Path(args.output) if args.output else default_output
    print(sensitivity.format_table(study))
    print(f"written: {sensitivity.write_json(study, output)}")
    return 0


def _port(args) -> int:
    from asterlite.legacy.port import describe_changes, port_file

    deck = Path(args.deck)
    try:
        result = port_file(deck, aster_version=args.aster_version)
    except (AsterliteError, OSError) as error:
        print(f"{deck}: {error}", file=sys.stderr)
        return 2
    changes = describe_changes(result)
    if args.output:
        Path(args.output).write_text(result.text, encoding="utf-8")
        print("\n".join(changes) if changes else f"{deck}: nothing to port")
        print(f"ported deck: {args.output}")
    else:  # UTF-8 whatever the terminal's locale, as with -o
        _write_utf8(result.text)
        for line in changes:
            print(line, file=sys.stderr)
    return 2 if result.skipped else 0


def _write_utf8(text: str) -> None:
    sys.stdout.flush()
    binary = getattr(sys.stdout, "buffer", None)
    if binary is None:  # a text stream in this process (a test's): no bytes to choose
        sys.stdout.write(text)
        return
    binary.write(text.encode("utf-8"))
    binary.flush()


def _warmup(args) -> int:
    from asterlite.dynamics import warmup
    from asterlite.isolation import protect_spawned_workers

    # the worker pool's `python -c` would import from the current folder (set
    # here, not in asterlite.dynamics, whose sources name the kernel cache)
    protect_spawned_workers()
    if args.numba:  # the workers inherit it: every loop is numba's
        from asterlite.dynamics import native

        os.environ[native.SWITCH] = "0"
    return warmup.main(jobs=args.jobs, verbose=args.verbose)


def _count_option(text: str) -> int:
    """A whole number >= 0 (argparse type)."""
    try:
        value = int(text)
    except ValueError:
        value = -1
    if value < 0:
        raise argparse.ArgumentTypeError(f"{text!r} is not a count (a whole number >= 0)")
    return value


def _limit_option(name: str):
    """An argparse type: a finite number >= 0 up to the limit's maximum
    (``--time-limit inf`` or ``nan`` is a usage error, exit status 2)."""

    def parse(text: str) -> float:
        refusal = limit_refusal(name, text)
        if refusal:
            raise argparse.ArgumentTypeError(refusal)
        return float(text)

    return parse


def build_parser() -> argparse.ArgumentParser:
    parser = argparse.ArgumentParser(
        prog="asterlite",
        description="Run Code_Aster command files: modal transient dynamics with shocks.",
    )
    parser.add_argument("--version", action="version", version=f"%(prog)s {__version__}")
    commands = parser.add_subparsers(dest="command", required=True)

    run = commands.add_parser("run", help="run a deck (.comm or .export, or a folder holding one)")
    run.add_argument("deck")
    run.add_argument("-o", "--output", help="output folder (default asterlite-out/<deck>)")
    run.add_argument("-q", "--quiet", action="store_true", help="print only problems")
    run.add_argument(
        "--save-results",
        action="store_true",
        help="save every tran_gene result to OUTDIR/results.h5 (layout: docs/results.md)",
    )
    run.add_argument(
        "--report",
        action="store_true",
        help="write OUTDIR/report.html, a page with the checks, timings, shocks and plots "
        "(saves results.h5 too)",
    )
    run.add_argument(
        "--no-progress", action="store_true", help="no progress bars (off anyway off a terminal)"
    )
    run.add_argument(
        "--time-limit",
        type=_limit_option("time_limit"),
        metavar="SECONDS",
        help="time for the whole run, replacing the export's 'P time_limit' (0: no limit)",
    )
    run.add_argument(
        "--memory-limit",
        type=_limit_option("memory_limit"),
        metavar="MB",
        help="memory the run may allocate, replacing the export's 'P memory_limit' (0: none)",
    )
    run.add_argument(
        "--output-limit",
        type=_limit_option("output_limit"),
        metavar="MB",
        help="what the run may write: message.log and the deck's files (default 2048; 0: none)",
    )
    run.add_argument(
        "--aster-version",
        type=int,
        metavar="N",
        help="read the decks as code_aster N wrote them (default: detected from their text)",
    )
    run.add_argument(
        "--allow-result-paths",
        action="store_true",
        help="write the export's R-line results at their own paths, as code_aster does "
        "(default: into the output folder; never over the deck, its inputs or the run's files)",
    )
    run.add_argument(
        "--mpi",
        metavar="LAUNCHER",
        help="solve CALC_MODES on PETSc/SLEPc across MPI ranks started by LAUNCHER, "
        "e.g. 'mpirun -n 4' or 'srun' (docs/large_models.md)",
    )
    run.add_argument(
        "--mpi-python",
        metavar="PYTHON",
        help="the interpreter of the MPI ranks, with numpy, petsc4py, slepc4py and mpi4py "
        "(default python3)",
    )
    previous = run.add_mutually_exclusive_group()
    previous.add_argument(
        "--keep-previous",
        type=_count_option,
        metavar="N",
        help="earlier results a rerun keeps under OUTDIR/previous-*/, most recent first "
        "(default 3; older ones asterlite made are deleted)",
    )
    previous.add_argument(
        "--no-previous",
        dest="keep_previous",
        action="store_const",
        const=0,
        help="keep no earlier result: a rerun deletes what the earlier run wrote",
    )
    run.set_defaults(handler=_run)

    status = commands.add_parser(
        "status",
        help="the status of the run in an output folder (a killed run's folder is settled)",
    )
    status.add_argument("folder", help="a run's output folder")
    status.set_defaults(handler=_status)

    check = commands.add_parser(
        "check",
        help="validate decks without computing: VALID (0), INVALID (2), UNSUPPORTED (3)",
        description="Validate decks in the language of their code_aster version, and say "
        "what asterlite does not compute. Exit status: 0 VALID, 2 INVALID, 3 UNSUPPORTED, "
        "4 ERROR (the check could not finish); the worst of several decks.",
    )
    check.add_argument("decks", nargs="+")
    check.add_argument("--format", choices=("text", "json"), default="text")
    check.add_argument(
        "--aster-version",
        type=int,
        default=None,
        metavar="N",
        help="read the decks as code_aster N (default: detected from their text)",
    )
    check.set_defaults(handler=_check)

    port = commands.add_parser("port", help="rewrite a legacy deck in current syntax")
    port.add_argument("deck")
    port.add_argument("-o", "--output", help="write the ported deck here (default: stdout)")
    port.add_argument(
        "--aster-version",
        type=int,
        metavar="N",
        help="read the deck as code_aster N wrote it (default: detected from its text)",
    )
    port.set_defaults(handler=_port)

    corpus = commands.add_parser("corpus", help="run every deck folder under a directory")
    corpus.add_argument("directory")
    corpus.add_argument("--json", help="write the table as JSON to this file")
    corpus.add_argument("--only", help="comma-separated deck names")
    corpus.add_argument("--jobs", type=int, default=2)
    corpus.add_argument("--timeout", type=float, default=900.0, help="seconds per deck")
    corpus.add_argument("-q", "--quiet", action="store_true")
    corpus.add_argument("--no-progress", action="store_true", help="no progress bar")
    corpus.set_defaults(handler=_corpus)

    sweep = commands.add_parser(
        "sweep", help="run a deck for every combination of deck-level variables (Dask)"
    )
    sweep.add_argument("deck")
    sweep.add_argument(
        "--set",
        action="append",
        required=True,
        metavar="NAME=V1,V2,...",
        help="values of a deck-level variable (repeat for several variables)",
    )
    sweep.add_argument("--scheduler", help="address of an existing Dask scheduler")
    sweep.add_argument("--workers", type=int, default=2, help="local worker processes")
    sweep.add_argument("-o", "--output", help="output folder (default asterlite-out/<deck>-sweep)")
    sweep.add_argument("-q", "--quiet", action="store_true", help="no progress lines")
    sweep.set_defaults(handler=_sweep)

    conv = commands.add_parser(
        "converge", help="error against cost of the deck's transients over schemes and steps"
    )
    conv.add_argument("deck")
    conv.add_argument(
        "--schemes",
        help="comma-separated: DIFF_CENTRE, NEWMARK, DEVOGE, TRBDF2 (fixed step), "
        "RUNGE_KUTTA_32, RUNGE_KUTTA_54, DEVOGE_ADAPT (tolerance), ADAPT_ORDRE1, ADAPT_ORDRE2 "
        "(points per period); default DIFF_CENTRE,DEVOGE,RUNGE_KUTTA_54",
    )
    conv.add_argument(
        "--steps", help="steps of the fixed-step schemes (default: deck PAS x2, x1, /2, /4, /8)"
    )
    conv.add_argument("--tolerances", help="TOLERANCE ladder (default 1e-3,...,1e-7)")
    conv.add_argument("--points", help="NB_POIN_PERIODE ladder of ADAPT_ORDRE* (default 25..400)")
    conv.add_argument("--target", type=float, help="max relative error to meet")
    conv.add_argument(
        "--against",
        choices=("finest", "reference"),
        default="finest",
        help="compare with a finer run (default) or with the checks' VALE_REFE",
    )
    conv.add_argument(
        "--reference",
        metavar="SCHEME:VALUE",
        help="the reference run (default: first scheme, half its finest step)",
    )
    conv.add_argument("--quantities", metavar="REGEX", help="keep the quantities matching this")
    conv.add_argument(
        "--keyword",
        action="append",
        metavar="FACT/NAME=VALUE",
        help="extra DYNA_VIBRA keyword for every run, e.g. SCHEMA_TEMPS/PAS_MAXI=1e-4",
    )
    conv.add_argument("--repeat", type=int, default=1, help="runs per setting (least time kept)")
    conv.add_argument(
        "--min-step-ratio",
        type=float,
        default=0.0,
        help="stop adaptive runs (unstable) whose step falls below this fraction of PAS",
    )
    conv.add_argument(
        "--memory-fraction",
        type=float,
        default=0.7,
        help="cap the memory at this fraction of RAM: a runaway run is an error row (0: no cap)",
    )
    conv.add_argument("-o", "--output", help="folder (default asterlite-out/<deck>-converge)")
    conv.add_argument("-q", "--quiet", action="store_true", help="no progress lines")
    conv.set_defaults(handler=_converge)

    sens = commands.add_parser(
        "sensitivity",
        help="rerun with the time step moved by a few ulps: which checks survive round-off",
    )
    sens.add_argument("deck")
    sens.add_argument("--runs", type=int, default=8, help="perturbed runs (default 8)")
    sens.add_argument(
        "--memory-fraction", type=float, default=0.7, help="cap the memory (0: no cap)"
    )
    sens.add_argument("-o", "--output", help="folder (default asterlite-out/<deck>-sensitivity)")
    sens.add_argument("-q", "--quiet", action="store_true", help="no progress lines")
    sens.set_defaults(handler=_sensitivity)

    warm = commands.add_parser(
        "warmup",
        help="compile every time-loop kernel now (once per install), so that no run waits for it",
    )
    warm.add_argument(
        "-j", "--jobs", type=int, default=None, help="worker processes (default: one per core)"
    )
    warm.add_argument("-v", "--verbose", action="store_true", help="each kernel's compile time")
    warm.add_argument(
        "--numba",
        action="store_true",
        help="numba's kernels of every loop, also those the compiled C++ loops serve "
        "(ASTERLITE_NATIVE=0 runs, and the tests' reference)",
    )
    warm.set_defaults(handler=_warmup)

    page = commands.add_parser(
        "report", help="write the HTML report of a run from its output folder"
    )
    page.add_argument("folder", help="a run's output folder (holding summary.json)")
    page.add_argument("-o", "--output", help="the page to write (default FOLDER/report.html)")
    page.set_defaults(handler=_report)

    plot = commands.add_parser("plot", help="plot a saved transient result (HDF5)")
    plot.add_argument("result", help="HDF5 result file")
    plot.add_argument("--name", help="result name in the file (default: the only/first one)")
    plot.add_argument("--node", help="node of a time history (with --cmp)")
    plot.add_argument("--cmp", help="component of the node time history, e.g. DX")
    plot.add_argument(
        "--field", default="DEPL", choices=("DEPL", "VITE", "ACCE"), help="node field"
    )
    plot.add_argument("--shock", help="shock name (INTITULE)")
    plot.add_argument(
        "--quantity",
        help="shock quantity: a stored field (FN, FT1, DYLOC, ...), orbit or wear",
    )
    plot.add_argument("-o", "--output", help="image file (.png or .svg)")
    plot.set_defaults(handler=_plot)
    return parser


# A run's start-up makes about 200 000 objects the collector tracks, living as
# long as the process (numpy, scipy, numba's typing registries, catalogues); with Python's
# default thresholds (700, 10, 10) the collector walks them ~360 times in a
# warm run of sdnd100a, and once more at exit: 250 ms of its CPU on the busy
# 2-core machine (load 20, 2026-11-28), 60-80 ms with these thresholds and no
# pass at exit. Young cycles are still collected every 20 000 allocations.
GC_THRESHOLDS = (20_000, 20, 50)


def _lighter_collector() -> None:
    gc.set_threshold(*GC_THRESHOLDS)
    # at exit the process is ending: its memory goes back to the system anyway
    atexit.unregister(gc.disable)
    atexit.register(gc.disable)


def main(argv: list[str] | None = None) -> int:
    _lighter_collector()
    args = build_parser().parse_args(argv)
    try:
        return args.handler(args)
    except KeyboardInterrupt:
        print("interrupted", file=sys.stderr)
        return 2
    except MissingExtraError as error:  # e.g. asterlite sweep without asterlite[sweep]
        print(f"error: {error}", file=sys.stderr)
        return 2
    except MemoryError:  # e.g. printing a huge report: still an error, not NOOK
        print("asterlite: out of memory", file=sys.stderr)
        return 2
    except OSError as error:  # a full disk, a closed terminal...
        print(f"asterlite: {error.strerror or error}", file=sys.stderr)
        return 2
    except Exception as error:  # a bug: one line here, never exit status 1 (NOOK)
        first = (str(error).strip().splitlines() or [""])[0][:200]
        print(
            f"asterlite: internal error, please report: {type(error).__name__}: {first}",
            file=sys.stderr,
        )
        return 2
