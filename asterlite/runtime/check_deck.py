"""``asterlite check``: a deck's status and every finding, without computing.

A deck is checked in the language of its code_aster version (detected from
its text, or given with ``--aster-version``) and against what asterlite
computes (:mod:`asterlite.runtime.language_check`). Its status:

========== ==== =========================================================
status     exit meaning
========== ==== =========================================================
VALID      0    valid code_aster N, and asterlite computes all of it
UNSUPPORTED 3   valid code_aster N, but some of it asterlite does not
                compute (a command, keyword or value; Python its
                evaluator does not take): ``run`` would stop there
INVALID    2    code_aster N would refuse the deck (a located error with
                a close match from that version's vocabulary)
ERROR      4    the check itself could not finish (unreadable files, its
                time or memory limit, an internal error)
========== ==== =========================================================

INVALID keeps ``run``'s exit code for errors (2); UNSUPPORTED gets a code
of its own so that a script can tell a deck to fix from a deck asterlite
cannot run yet (``run`` has 1 for NOOK, which a check never reaches).
Several decks exit with the code of the worst status (ERROR, INVALID,
UNSUPPORTED, VALID in that order).
"""

from __future__ import annotations

import time
from dataclasses import asdict, dataclass, field
from pathlib import Path

from asterlite import watchdog
from asterlite.errors import AsterliteError
from asterlite.io.export import describe_run
from asterlite.runtime import stops
from asterlite.runtime.runner import internal_error_report, run_limits

EXIT_CODES = {"VALID": 0, "INVALID": 2, "UNSUPPORTED": 3, "ERROR": 4}
SEVERITY = ("VALID", "UNSUPPORTED", "INVALID", "ERROR")  # worst last
KINDS = ("invalid", "unsupported", "unsupported-python")


@dataclass
class Finding:
    kind: str  # invalid, unsupported, unsupported-python
    message: str
    file: str | None
    line: int | None
    column: int | None
    keyword: str  # keyword path: COMMAND/FACTOR[n]/KEYWORD ('' for a statement)

    def text(self) -> str:
        where = ""
        if self.file:
            where = f"{self.file}:{self.line}" + (f":{self.column}" if self.column else "") + ": "
        path = f"{self.keyword}: " if self.keyword else ""
        return f"{where}{self.kind}: {path}{self.message}"


@dataclass
class DeckCheck:
    deck: str
    status: str
    version: int | None = None  # the code_aster version the deck is read in
    language: int | None = None  # the language data it was validated with
    findings: list[Finding] = field(default_factory=list)
    message: str = ""  # why the check could not finish (ERROR)
    seconds: float = 0.0

    @property
    def exit_code(self) -> int:
        return EXIT_CODES[self.status]

    def counts(self) -> dict[str, int]:
        counts = dict.fromkeys(KINDS, 0)
        for finding in self.findings:
            counts[finding.kind] = counts.get(finding.kind, 0) + 1
        return counts

    def as_json(self) -> dict:
        data = {
            "deck": self.deck,
            "status": self.status,
            "exit_code": self.exit_code,
            "aster_version": self.version,
            "language_version": self.language,
            "counts": self.counts(),
            "findings": [asdict(f) for f in self.findings],
            "seconds": round(self.seconds, 3),
        }
        if self.message:
            data["message"] = self.message
        return data


def deck_status(findings: list[Finding]) -> str:
    kinds = {f.kind for f in findings}
    if "invalid" in kinds:
        return "INVALID"
    if kinds:
        return "UNSUPPORTED"
    return "VALID"


def worst_exit_code(checks: list[DeckCheck]) -> int:
    if not checks:
        return 0
    worst = max(checks, key=lambda c: SEVERITY.index(c.status))
    return worst.exit_code


def finding_of(error) -> Finding:
    from asterlite.runtime.language_check import finding_kind

    location = getattr(error, "location", None)
    return Finding(
        kind=finding_kind(error),
        message=getattr(error, "message", str(error)),
        file=getattr(location, "file", None),
        line=getattr(location, "line", None),
        column=getattr(location, "column", None) or None,
        keyword=getattr(error, "path", "") or "",
    )


def check_deck(
    deck: Path, aster_version: int | None = None, time_limit: float | None = None
) -> DeckCheck:
    """Check one deck (a .comm, an .export or a deck folder); ``time_limit``
    (CPU seconds) replaces the export's and the default."""
    from asterlite.runtime.session import Session

    start = time.perf_counter()
    deck = Path(deck)
    result = DeckCheck(str(deck), "ERROR")
    session = None
    try:
        if deck.is_dir():
            from asterlite.api import deck_in_folder

            deck = deck_in_folder(deck)
        description = describe_run(deck)
        session = Session(description, check_only=True, aster_version=aster_version)
        seconds, megabytes = run_limits(description, time_limit, None, check_only=True)
        with stops.stop_on_signals(), watchdog.limits(seconds, megabytes, False):
            session.run_all()
    except stops.RunInterrupted as interrupt:
        result.message = f"interrupted by {interrupt.signal_name}"
    except RecursionError:
        result.message = "deck nested too deeply"
    except MemoryError:
        result.message = "memory limit exceeded"
    except OSError as error:
        result.message = f"cannot read a file: {error.strerror or error}"
    except Exception as error:
        if isinstance(error, AsterliteError):
            result.message = str(error)
        else:  # an asterlite bug: said, never a crash of the caller
            result.message = internal_error_report(deck.stem, error).message
    else:
        result.findings = [finding_of(e) for e in session.check.findings]
        result.status = deck_status(result.findings)
    if session is not None:
        from asterlite.runtime.language_check import deck_version, session_language

        lang = session_language(session)
        result.version = deck_version(session)
        result.language = lang.version if lang is not None else None
    result.seconds = time.perf_counter() - start
    return result


def format_text(check: DeckCheck) -> str:
    """``deck: STATUS (code_aster N)`` and one line per finding."""
    if check.version is None:
        version = ""
    elif check.language is None:
        version = f" (code_aster {check.version}: no language data, asterlite's catalogues only)"
    elif check.language != check.version:
        version = f" (code_aster {check.version}, read with the language of {check.language})"
    else:
        version = f" (code_aster {check.version})"
    counts = check.counts()
    parts = [f"{n} {kind}" for kind, n in counts.items() if n]
    head = f"{check.deck}: {check.status}{version}" + (f": {', '.join(parts)}" if parts else "")
    lines = [head]
    if check.message:
        lines.append(f"  {check.message}")
    lines += [f"  {finding.text()}" for finding in check.findings]
    return "\n".join(lines)
