"""Run (or check) a deck from its path and report what happened.

The run owns its output folder (:mod:`asterlite.runtime.outdir`): locked,
cleared of an earlier result, ``message.log`` and ``summary.json`` written
as it goes; result files are staged and appear under their names only when
the run completes, else they stay under ``incomplete/`` so nothing partial
looks finished. A complete run also copies the files the export's ``R``
lines ask for. The whole run is bounded in time, memory and output
(:func:`run_limits`); SIGINT and SIGTERM end it cleanly.

Statuses: PASS (every TEST_* check OK), NOOK (some check not OK), DONE
(the deck ran to its end without any check), ERROR, UNSUPPORTED,
INTERRUPTED; under ``check``: CHECKED, or ERROR/UNSUPPORTED listing every
error of the deck. Exit status 1 means NOOK only: every failure is 2.
"""

from __future__ import annotations

import os
import signal
import threading
import time
import traceback
from contextlib import contextmanager
from dataclasses import dataclass, field
from pathlib import Path

from asterlite import watchdog
from asterlite.errors import AsterliteError, UnsupportedError
from asterlite.io.export import NOT_PRODUCED, describe_run, limit_refusal
from asterlite.post.check_record import TestRecord
from asterlite.report.fields import summary_fields, summary_lines
from asterlite.runtime import stops
from asterlite.runtime.outdir import (
    OutputFolder,
    OutputFolderError,
    OutputLimitError,
)
from asterlite.runtime.previous_results import DEFAULT_KEEP
from asterlite.runtime.verdicts import check_comparisons, plain_value
from asterlite.runtime.write_boundary import replace_outside

EXIT_OK, EXIT_NOOK, EXIT_ERROR = 0, 1, 2
# statuses of a run that went to its end (its results and checks count)
COMPLETE = ("PASS", "NOOK", "DONE")


@dataclass
class RunReport:
    deck: str
    status: str  # PASS, NOOK, DONE, ERROR, UNSUPPORTED, INTERRUPTED (CHECKED under check)
    message: str = ""
    errors: list[str] = field(default_factory=list)  # every error ``check`` found
    tests: list[TestRecord] = field(default_factory=list)
    seconds: float = 0.0
    timings: list = field(default_factory=list)
    overrides: dict = field(default_factory=dict)  # deck-level variables set by value
    overrides_used: list[str] = field(default_factory=list)  # those the deck assigned
    unknown_overrides: list[str] = field(default_factory=list)  # those it never assigned
    table_values: dict = field(default_factory=dict)  # "TABLE.PARA" of one-row tables
    # one dict per tran_gene result made by the run (scheme, step, steps, seconds...)
    transients: list[dict] = field(default_factory=list)
    # one dict per shock of those results: max FN, wear power (mean FN·|VT|)...
    shocks: list[dict] = field(default_factory=list)
    keyword_edits: list[dict] = field(default_factory=list)  # keyword overrides applied
    # summary.json fields of asterlite.report.fields (verdicts, supports, ...)
    extras: dict = field(default_factory=dict)
    # the deck's names and concepts after a computed run (asterlite.api reads them)
    namespace: dict = field(default_factory=dict, repr=False, compare=False)
    traceback: str = ""  # of an internal error: written to message.log, not shown

    @property
    def checks_total(self) -> int:
        return len(self.tests)

    @property
    def checks_ok(self) -> int:
        return sum(1 for t in self.tests if t.ok)

    @property
    def strict_ok(self) -> int:
        return sum(1 for t in self.tests if t.ok and t.strict)

    @property
    def exit_code(self) -> int:
        if self.status in ("PASS", "DONE", "CHECKED"):
            return EXIT_OK
        if self.status == "NOOK":
            return EXIT_NOOK
        return EXIT_ERROR

    def as_dict(self) -> dict:
        return {
            "deck": self.deck,
            "status": self.status,
            "checks_ok": self.checks_ok,
            "checks_total": self.checks_total,
            "strict_ok": self.strict_ok,
            "seconds": round(self.seconds, 3),
            "message": self.message,
            "errors": self.errors,
            "overrides": {k: plain_value(v) for k, v in self.overrides.items()},
            "overrides_used": self.overrides_used,
            "transients": self.transients,
            "shocks": self.shocks,
            **self.extras,
            "tests": [
                {
                    "command": t.command,
                    "label": t.label,
                    "value": plain_value(t.value),
                    "expected": plain_value(t.expected),
                    "reference": t.reference,
                    "error": plain_value(t.error),
                    "tolerance": plain_value(t.tolerance),
                    "ok": bool(t.ok),
                    "strict": bool(t.strict),
                    **check_comparisons(t),
                }
                for t in self.tests
            ],
            "commands": [
                {
                    "command": c.command,
                    "line": c.location.line if c.location else None,
                    "result": c.result,
                    "seconds": round(c.seconds, 4),
                }
                for c in self.timings
            ],
        }


def run_deck(
    deck: Path,
    output_dir: Path | None = None,
    *,
    check_only: bool = False,
    echo: bool = False,
    overrides: dict | None = None,
    keyword_overrides: list | None = None,
    save_results: bool = False,
    time_limit: float | None = None,
    memory_limit: float | None = None,
    output_limit: float | None = None,
    aster_version: int | None = None,
    report_page: bool = False,
    result_paths: bool = False,
    keep_previous: int | None = None,
) -> RunReport:
    """Run or check the deck at ``deck`` (an .export or a .comm).

    ``overrides`` maps deck-level variable names to the values bound instead
    of the deck's own (see :class:`asterlite.lang.Evaluator`); a name the deck
    never assigns makes the run an ERROR naming it. ``keyword_overrides``
    (:class:`asterlite.runtime.session.KeywordOverride`) replace keyword
    values in command calls before validation (e.g. DYNA_VIBRA's scheme).
    ``time_limit`` (seconds) and ``memory_limit`` (MB) replace the export's
    ``P`` lines, ``output_limit`` (MB) the cap on what the run writes; None
    means the default, 0 no limit (see :func:`run_limits`, docs/safety.md).
    The output folder is taken as :mod:`asterlite.runtime.outdir` describes;
    one that cannot be taken makes an ERROR report with nothing written.
    The export's ``R`` lines are kept in the output folder, or at their own
    paths with ``result_paths`` (``asterlite run --allow-result-paths``).
    An earlier result in the folder is moved into ``previous-<time>/``; the
    ``keep_previous`` most recent of those stay (None: 3, 0: none), see
    :mod:`asterlite.runtime.previous_results`.

    A stop signal ends the run INTERRUPTED; one that comes once the result
    is written is raised after it (RunInterrupted, with ``report`` set).
    """
    start = time.perf_counter()
    refusal = limits_refusal(
        time_limit=time_limit, memory_limit=memory_limit, output_limit=output_limit
    )
    if keep_previous is not None and (
        isinstance(keep_previous, bool) or not isinstance(keep_previous, int) or keep_previous < 0
    ):
        refusal = f"keep_previous={keep_previous!r}: earlier results kept must be a count >= 0"
    if refusal:
        return RunReport(deck.stem, "ERROR", refusal)
    output_bytes = output_cap_bytes(output_limit)
    # held while the folder is taken: an earlier result is moved aside and the
    # RUNNING summary written before a signal stops the run
    with stops.stop_on_signals(held=True) as stop:
        folder = None
        if output_dir is not None and not check_only:
            try:
                cap = log_cap_bytes(output_bytes)
                folder = OutputFolder(
                    output_dir,
                    log_cap=cap,
                    deck=deck.stem,
                    protected=input_identities(deck),
                    keep_previous=DEFAULT_KEEP if keep_previous is None else keep_previous,
                ).open()
            except OutputFolderError as error:
                report = RunReport(deck.stem, "ERROR", str(error))
        if output_dir is None or check_only or folder is not None:
            report = _run_in_folder(
                deck,
                folder,
                stop,
                check_only=check_only,
                echo=echo,
                overrides=overrides,
                keyword_overrides=keyword_overrides,
                limits=(time_limit, memory_limit, output_bytes),
                aster_version=aster_version,
                placing=(save_results, report_page, result_paths),
                started=start,
            )
        else:
            report.seconds = time.perf_counter() - start
        late = stop.take_pending()
    if late is not None:  # the run's result is written: the caller stops now
        interrupt = stops.RunInterrupted(late)
        interrupt.report = report
        raise interrupt
    return report


def _run_in_folder(deck, folder, stop, *, started, placing, **session_options) -> RunReport:
    """The run itself, once its folder is taken: signals stop it from here
    until its final files are written."""
    try:
        stop.release()  # a signal held while the folder was taken stops the run now
        # a report page draws the transients: the session keeps them
        report, session = _run_session(deck, folder, keep_results=placing[1], **session_options)
    except stops.RunInterrupted as interrupt:  # between the session and the report
        report, session = _interrupted(deck.stem, interrupt, None), None
    stop.hold()  # a signal from here on waits until the folder is written
    report.seconds = time.perf_counter() - started
    if folder is not None:
        _finish_output(folder, report, session, *placing)
    return report


def input_identities(deck: Path) -> frozenset:
    """(device, inode) of the deck, its export and the files its F lines name:
    never moved aside, never replaced by an R line."""
    paths = [deck]
    try:
        description = describe_run(deck)
    except (AsterliteError, OSError, ValueError):
        description = None
    if description is not None:
        paths += run_inputs(description)
    identities = set()
    for path in paths:
        for follow in (False, True):
            try:
                info = os.stat(path, follow_symlinks=follow)
            except (OSError, ValueError):
                continue
            identities.add((info.st_dev, info.st_ino))
    return frozenset(identities)


def run_inputs(description) -> list[Path]:
    """Every file a run description reads."""
    paths = list(description.deck_files) + list(description.units.values())
    paths += list(description.helper_modules.values())
    if description.source is not None:
        paths.append(description.source)
    return paths


def _run_session(
    deck: Path,
    folder,
    *,
    check_only,
    echo,
    overrides,
    keyword_overrides,
    limits,
    aster_version=None,
    keep_results=False,
):
    """Run the deck's session; (report, session) whatever happens in it.
    ``keep_results``: the session keeps its transients for a report page."""
    from asterlite.runtime.language_check import python_refusal
    from asterlite.runtime.session import Session, UnknownOverrideError

    time_limit, memory_limit, output_bytes = limits
    name = deck.stem
    session = None
    try:
        description = describe_run(deck)
        name = description.name
        extra = {"messages": folder.log} if folder is not None else {}
        session = Session(
            description,
            output_dir=folder.staging if folder is not None else None,
            check_only=check_only,
            echo=echo,
            overrides=dict(overrides or {}),
            keyword_overrides=list(keyword_overrides or []),
            aster_version=aster_version,  # None: detected from the decks' text
            **extra,
        )
        session.summaries.keep_results = keep_results
        if folder is not None:
            session.output_guard = folder.check_name
            session.command_hook = folder.record_command
            folder.log.on_line = output_watch(folder, output_bytes)
        seconds, megabytes = run_limits(description, time_limit, memory_limit, check_only)
        with watchdog.limits(seconds, megabytes, not check_only), file_size_cap(output_bytes):
            session.run_all()
    except stops.RunInterrupted as interrupt:
        report = _interrupted(name, interrupt, session)
    except UnknownOverrideError as error:
        report = RunReport(name, "ERROR", str(error), unknown_overrides=session.unused_overrides())
    except UnsupportedError as error:
        report = RunReport(name, "UNSUPPORTED", str(error))
    except AsterliteError as error:
        refusal = python_refusal(error, getattr(error.location, "file", None) or str(deck))
        if refusal is not None:
            report = RunReport(name, "UNSUPPORTED", str(refusal))
        else:
            report = RunReport(name, "ERROR", str(error))
    except RecursionError as error:
        report = RunReport(name, "ERROR", f"{_where(error)}deck error: nested too deeply")
    except MemoryError as error:  # outside any command (the session locates those)
        report = RunReport(name, "ERROR", f"{_where(error)}memory limit exceeded: {_memory_text()}")
    except OSError as error:
        report = _os_error_report(name, error, output_bytes)
    except Exception as error:  # an asterlite bug: report it, never crash the caller
        report = internal_error_report(name, error)
    else:
        if check_only:
            report = check_report(name, session.check_errors)
        elif not session.tests:  # ran to its end, but nothing was checked
            report = RunReport(name, "DONE")
        elif all(t.ok for t in session.tests):
            report = RunReport(name, "PASS")
        else:
            report = RunReport(name, "NOOK")
    _fill_report(report, session, overrides, check_only)
    return report, session


def _fill_report(report: RunReport, session, overrides, check_only: bool) -> None:
    report.overrides = dict(overrides or {})
    if session is None:
        return
    report.tests = list(session.tests)
    report.timings = list(session.timings)
    report.overrides_used = sorted(session.overrides_used)
    if not check_only:  # results exist only when computed (and check stays light)
        try:
            report.table_values = one_row_table_values(session.namespace)
            report.transients, report.shocks = session.summaries.results()
        except (MemoryError, RecursionError, ValueError, TypeError) as error:
            report.status = "ERROR"
            report.message = f"cannot summarise the results: {type(error).__name__}: {error}"
        report.namespace = session.namespace
    report.keyword_edits = list(session.keyword_edits)
    report.extras = summary_fields(report, session)


def _where(error: BaseException) -> str:
    """``file:line: `` of the deck statement an exception came from, if known."""
    location = getattr(error, "deck_location", None)
    return f"{location}: " if location is not None else ""


def _interrupted(name: str, interrupt, session) -> RunReport:
    where = where_the_run_was(session)
    message = (
        f"interrupted by {interrupt.signal_name}{' ' + where if where else ''}: "
        "the run's results are incomplete"
    )
    return RunReport(name, "INTERRUPTED", message)


def where_the_run_was(session) -> str:
    """``during IMPR_TABLE (d.comm:3)``, ``after ...`` (in deck code), or ''."""
    current = session.current_command if session is not None else None
    if current is None:
        return ""
    command, location, running = current
    where = f" ({Path(location.file).name}:{location.line})" if location is not None else ""
    return f"{'during' if running else 'after'} {command}{where}"


# errno values that mean the disk (or the run's cap on a file) is full
_FULL = {28: "no space left on the device", 122: "disk quota exceeded", 27: "file too large"}


def _os_error_report(name: str, error: OSError, output_bytes: int | None) -> RunReport:
    """A file the run could not read or write: a located error, not a bug."""
    where = _where(error)
    if error.errno == 27 and output_bytes:  # EFBIG: the run's RLIMIT_FSIZE
        text = f"output limit exceeded: a file reached the run's cap of {output_bytes / 1e6:g} MB"
        return RunReport(name, "ERROR", where + text)
    reason = _FULL.get(error.errno, error.strerror or type(error).__name__)
    target = f" ({error.filename})" if error.filename else ""
    return RunReport(name, "ERROR", f"{where}cannot read or write a file{target}: {reason}")


def internal_error_report(name: str, error: BaseException) -> RunReport:
    """An asterlite bug: one located line to show, the traceback for message.log."""
    first = (str(error).strip().splitlines() or [""])[0][:300]
    text = f"{type(error).__name__}: {first}" if first else type(error).__name__
    report = RunReport(name, "ERROR", f"{_where(error)}internal error, please report: {text}")
    report.traceback = "".join(traceback.format_exception(error))
    return report


def check_report(name: str, errors: list) -> RunReport:
    """CHECKED, or every error the check found (UNSUPPORTED when all are)."""
    if not errors:
        return RunReport(name, "CHECKED")
    unsupported = all(isinstance(error, UnsupportedError) for error in errors)
    texts = [str(error) for error in errors]
    head = f"{len(errors)} errors:\n" if len(errors) > 1 else ""
    report = RunReport(name, "UNSUPPORTED" if unsupported else "ERROR", head + "\n".join(texts))
    report.errors = texts
    return report


# limits of a run whose export has no P line for them (docs/safety.md)
DEFAULT_TIME_LIMIT = 3600.0  # CPU seconds of a run
DEFAULT_CHECK_TIME_LIMIT = 60.0  # CPU seconds of ``asterlite check``
DEFAULT_MEMORY_FRACTION = 0.5  # of the machine's memory, for a run or a check
DEFAULT_OUTPUT_LIMIT = 2048.0  # MB: message.log and every file the deck writes
# bytes of message.log at most: code_aster's .mess of a long study takes a
# few MB; a print flood stops here with a located error, not at 256 MB
MESSAGE_LOG_CAP = 32 * 1_000_000


def run_limits(
    description, time_limit, memory_limit, check_only: bool = False
) -> tuple[float | None, float | None]:
    """(seconds, MB) the run may take: the options, else the export's P lines,
    else the defaults; 0 means no limit. code_aster's FACMTPS environment
    variable scales the time as it does there."""
    seconds = description.time_limit if time_limit is None else time_limit
    megabytes = description.memory_limit if memory_limit is None else memory_limit
    if seconds is None:
        seconds = DEFAULT_CHECK_TIME_LIMIT if check_only else DEFAULT_TIME_LIMIT
    if megabytes is None:
        megabytes = default_memory_limit()
    elif megabytes and not check_only:  # a study's own limit measures its data only
        watchdog.preload_engine()
    if seconds:
        try:
            seconds *= float(os.environ.get("FACMTPS", "1"))
        except ValueError:
            pass
    return (seconds or None), (megabytes or None)


def default_memory_limit() -> float | None:
    """MB: a fraction of the machine's memory (None where it is unknown)."""
    try:
        total = os.sysconf("SC_PAGE_SIZE") * os.sysconf("SC_PHYS_PAGES")
    except (ValueError, OSError, AttributeError):
        return None
    return round(DEFAULT_MEMORY_FRACTION * total / watchdog.MEGABYTE)


def limits_refusal(**limits) -> str:
    """Why the limits given to :func:`run_deck` cannot be used ('' if they can)."""
    for name, value in limits.items():
        if value is not None:
            refusal = limit_refusal(name, value)
            if refusal:
                return f"{refusal}, got {value!r}"
    return ""


def output_cap_bytes(output_limit: float | None) -> int | None:
    """Bytes the run may write (None: no cap): ``output_limit`` MB, or the default."""
    megabytes = DEFAULT_OUTPUT_LIMIT if output_limit is None else output_limit
    return int(megabytes * 1_000_000) if megabytes else None


def log_cap_bytes(output_bytes: int | None) -> int:
    return MESSAGE_LOG_CAP if output_bytes is None else min(output_bytes, MESSAGE_LOG_CAP)


def output_watch(folder, output_bytes: int | None):
    """A check of the bytes written so far, run as message lines come (every
    command logs its start and end), at most every half second."""
    if output_bytes is None:
        return None
    last = [0.0]

    def check() -> None:
        now = time.monotonic()
        if now - last[0] < 0.5:
            return
        last[0] = now
        written = folder.staged_bytes() + folder.log.written
        if written > output_bytes:
            raise OutputLimitError(
                f"the run wrote {written / 1e6:.1f} MB, beyond its cap of "
                f"{output_bytes / 1e6:g} MB (asterlite run --output-limit to change it)"
            )

    return check


@contextmanager
def file_size_cap(output_bytes: int | None):
    """RLIMIT_FSIZE at the output cap while the deck runs: a single file
    growing past it fails with EFBIG (SIGXFSZ ignored) instead of filling the
    disk between two checks. Main thread only (signal dispositions)."""
    if output_bytes is None or threading.current_thread() is not threading.main_thread():
        yield
        return
    try:
        import resource

        previous = resource.getrlimit(resource.RLIMIT_FSIZE)
        cap = (
            output_bytes
            if previous[1] == resource.RLIM_INFINITY
            else min(output_bytes, previous[1])
        )
        if previous[0] != resource.RLIM_INFINITY:
            cap = min(cap, previous[0])
        handler = signal.signal(signal.SIGXFSZ, signal.SIG_IGN)
        resource.setrlimit(resource.RLIMIT_FSIZE, (cap, previous[1]))
    except (ImportError, ValueError, OSError, AttributeError):
        yield
        return
    try:
        yield
    finally:
        resource.setrlimit(resource.RLIMIT_FSIZE, previous)
        signal.signal(signal.SIGXFSZ, handler)


def _memory_text() -> str:
    limit = watchdog.memory_limit_mb()
    return f"the run's limit is {limit:g} MB" if limit else "the machine is out of memory"


def one_row_table_values(namespace: dict) -> dict:
    """``{"TABLE.PARA": value}`` for the deck's tables of a single row: the
    scalar results (wear power, peak force...) a parameter study compares."""
    from asterlite.concepts.table import Table

    values = {}
    for name, value in namespace.items():
        if isinstance(value, Table) and len(value) == 1:
            for para, cell in value.row(0).items():
                values[f"{name}.{para}"] = plain_value(cell)
    return values


def _finish_output(
    folder,
    report: RunReport,
    session,
    save_results: bool = False,
    report_page: bool = False,
    result_paths: bool = False,
) -> None:
    """Publish a complete run's files (else keep them under incomplete/),
    copy the R-line results, end message.log and write the final summary."""
    try:
        _place_files(folder, report, session, save_results, report_page, result_paths)
    except OSError as error:  # a full disk while finishing: say so, keep going
        failed = _os_error_report(report.deck, error, None)
        report.status, report.message = "ERROR", failed.message
    lines = [""]
    if report.traceback:
        lines += ["internal error, traceback:", *report.traceback.rstrip("\n").split("\n"), ""]
    lines.append(format_summary(report))
    try:
        folder.log.final("\n".join(lines))
    except OutputLimitError:
        pass  # the disk is full: summary.json may still fit
    try:
        folder.write_summary(report.as_dict())
    except (OSError, ValueError, TypeError) as error:
        _summary_not_written(folder, report, error)
    finally:
        folder.release()


def _summary_not_written(folder, report: RunReport, error: Exception) -> None:
    """The final summary could not replace the RUNNING one (a full disk): the
    run is an ERROR saying so, written in the RUNNING summary's place."""
    if isinstance(error, OSError):
        reason = _FULL.get(error.errno, error.strerror or type(error).__name__)
    else:
        reason = f"{type(error).__name__}: {error}"
    ended = f"the run had ended {report.status}" + (
        f" ({report.message})" if report.message else ""
    )
    report.status = "ERROR"
    report.message = f"summary.json could not be written ({reason}); {ended}"
    try:
        folder.write_summary_in_place(report.as_dict())
    except OSError:
        pass  # nothing can be written: the next run finds RUNNING and says KILLED


def _place_files(
    folder,
    report: RunReport,
    session,
    save_results: bool,
    report_page: bool = False,
    result_paths: bool = False,
) -> None:
    complete = report.status in COMPLETE
    if complete and save_results:
        # every tran_gene of the deck, in the store documented in docs/results.md
        from asterlite.io.result_store import save_session_results

        try:
            folder.check_name("results.h5")
            saved = save_session_results(folder.staging / "results.h5", session.namespace)
            session.log(f"results.h5: {', '.join(saved) if saved else 'no tran_gene result'}")
        except AsterliteError as error:
            report.status, report.message = "ERROR", f"results.h5 not saved: {error}"
            complete = False
    if report_page and session is not None:  # asterlite run --report: report.html
        from asterlite.report import write_run_page

        write_run_page(folder, report, session)
    if complete:
        blocked = folder.publish()
        if blocked:
            report.status = "ERROR"
            report.message = (
                f"{', '.join(blocked)}: appeared in the output folder during the run; "
                "the run's files are kept under incomplete/ instead"
            )
            folder.keep_incomplete()
            return
        keep_result_files(folder, session, result_paths)
    else:
        folder.keep_incomplete()


def keep_result_files(folder, session, result_paths: bool = False) -> None:
    """What the deck wrote on each unit an export R line names, kept under
    that line's file name in the output folder; at the line's own path only
    with ``result_paths`` (``--allow-result-paths``: an export alone cannot
    write outside the output folder). Each line's outcome goes to the log."""
    inputs = _input_files(session.run)
    for result in session.run.results:
        note = _keep_result(folder, session, result, result_paths, inputs)
        try:
            session.log(note)
        except OutputLimitError:
            pass


def _keep_result(folder, session, result, result_paths: bool, inputs) -> str:
    head = f"R {result.file_type} {result.path}"
    if result.file_type in NOT_PRODUCED:
        return f"R {result.file_type} {result.path.name}: a code_aster database, not produced"
    if result.unit == 6 or result.file_type == "mess":
        return f"R {result.file_type}: the messages are in message.log"
    written = session.output_units.get(result.unit)
    if written is None or not folder.owns(written.name):
        return f"{head}: the deck wrote nothing on unit {result.unit}"
    source, place = written.name, _place_in_folder(folder.path, result.path)
    if place is None and result_paths:
        refusal = _outside_refusal(result.path, inputs)
        if refusal:
            return f"{head}: not copied ({refusal})"
        try:
            with folder.open_own_file(source) as original:
                replace_outside(original, result.path)
        except OSError as error:
            return f"{head}: not copied ({error.strerror or error})"
        return f"R {result.file_type}: unit {result.unit} copied to {result.path}"
    if place == "":
        return f"{head}: not copied (inside the output folder, only its top level may be named)"
    target = place or result.path.name
    if target == source:
        return f"{head}: unit {result.unit} is in the output folder as {source}"
    try:
        folder.copy_own_file(source, target)
    except OutputFolderError as error:
        return f"{head}: not copied ({error.message})"
    except FileExistsError:
        return f"{head}: not copied (the output folder already holds {target})"
    except OSError as error:
        return f"{head}: not copied ({error.strerror or error})"
    how = "" if place else " (asterlite run --allow-result-paths writes it at the export's path)"
    return f"{head}: unit {result.unit} kept in the output folder as {target}{how}"


def _place_in_folder(folder: Path, target: Path) -> str | None:
    """The name ``target`` has at the top of ``folder``; '' when it is deeper
    inside; None when it is outside (symlinks resolved on both sides)."""
    here = os.path.realpath(folder)
    parent = os.path.realpath(Path(target).parent)
    if parent == here:
        return Path(target).name
    if os.path.commonpath([here, parent]) == here:
        return ""
    return None


def _input_files(description) -> tuple[set[str], set[tuple[int, int]]]:
    """The paths and identities of everything the run reads."""
    paths, identities = set(), set()
    for path in run_inputs(description):
        paths |= {os.path.abspath(path), os.path.realpath(path)}
        try:
            info = os.stat(path)
        except OSError:
            continue
        identities.add((info.st_dev, info.st_ino))
    return paths, identities


def _outside_refusal(target: Path, inputs) -> str:
    """Why an R line may not write ``target`` outside the output folder ('' if it may)."""
    paths, identities = inputs
    if not Path(target).parent.is_dir():
        return "its folder does not exist; asterlite makes no folder outside its output folder"
    if Path(target).is_dir() and not Path(target).is_symlink():
        return "a folder is there"
    named = {os.path.abspath(target), os.path.realpath(target)}
    found = set()
    for follow in (False, True):
        try:
            info = os.stat(target, follow_symlinks=follow)
            found.add((info.st_dev, info.st_ino))
        except OSError:
            pass
    if named & paths or found & identities:
        return "it is a file the run reads: the deck, its export or an F line's file"
    return ""


def format_test_line(test: TestRecord) -> str:
    flag = "OK  " if test.ok else "NOOK"
    strict = "" if test.strict or not test.ok else " (not strict)"
    text = (
        f"  {flag} {test.command} {test.label}: value={plain_value(test.value)!r} "
        f"expected={plain_value(test.expected)!r} error={plain_value(test.error)!r}"
    )
    calc = test.calc_comparison
    if calc is not None and test.reference != "NON_REGRESSION":
        text += f" | VALE_CALC={plain_value(calc.expected)!r} error={plain_value(calc.error)!r}"
    return text + strict


def _steps(run: dict) -> str:
    """The step range of a transient (and the median archived step when it varies)."""
    low, high, median = run["min_step"], run["max_step"], run.get("median_step")
    if low is None or high is None:
        return "?"
    if high <= low * (1.0 + 1.0e-12):
        return f"{low:.4g} s"
    text = f"{low:.4g}..{high:.4g} s"
    return text + (f" (median {median:.4g})" if median is not None else "")


def format_summary(report: RunReport) -> str:
    lines = [f"{report.deck}: {report.status} in {report.seconds:.2f} s"]
    if report.timings:
        lines.append("commands:")
        for timing in report.timings:
            line = timing.location.line if timing.location else "?"
            result = f" -> {timing.result}" if timing.result else ""
            lines.append(
                f"  {timing.command:<18} line {line:<5}{result:<16} {timing.seconds:8.3f} s"
            )
    for run in report.transients:
        lines.append(
            f"transient {run['result']}: {run['scheme']} {run['steps']} steps"
            f" ({run['rejected_steps']} rejected), step {_steps(run)},"
            f" integration {run['integration_seconds']:.3f} s"
            + (f" ({run['loop']} loop)" if run.get("loop") else "")
        )
        if "energy_residual" in run:
            ratio, flow = run["energy_residual_ratio"], run.get("energy_residual_flow_ratio")
            lines.append(
                f"  energy residual {run['energy_residual']:.4g} J"
                + (f", {ratio:.3g} of the largest total energy" if ratio is not None else "")
                + (f", {flow:.3g} of the energy supplied" if flow is not None else "")
            )
    if report.shocks:
        lines.append("shocks (from archived instants):")
        for shock in report.shocks:
            lines.append(
                f"  {shock['result']}/{shock['shock']}: {shock['impacts']} impacts,"
                f" max FN {shock['max_FN']:.4g} N, contact {100 * shock['contact_fraction']:.1f} %,"
                f" wear power {shock['wear_power']:.4g} W"
            )
    if report.tests:
        lines.append(
            f"checks: {report.checks_ok}/{report.checks_total} OK, {report.strict_ok} strict"
        )
        lines += [format_test_line(t) for t in report.tests]
        lines += summary_lines(report)
    if report.message:
        lines.append(report.message)
    return "\n".join(lines)
