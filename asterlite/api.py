"""asterlite from Python: run a deck, check it, load saved results.

::

    import asterlite

    run = asterlite.run("samples/friction_oscillator", MU=0.15)
    run.status                      # "PASS"
    run.checks[0].value             # each TEST_* check, with what it compared
    run.concepts["RESUGENE"]        # a tran_gene as arrays with named dimensions
    asterlite.check("deck.comm").ok
    asterlite.load("out/results.h5")  # what ``asterlite run --save-results`` saved

A run goes through :func:`asterlite.runtime.runner.run_deck`, exactly as
``asterlite run`` does. Results come as data (:mod:`asterlite.io.frames`):
xarray Datasets and pandas DataFrames when those packages are installed,
numpy arrays in plain dicts otherwise. Importing this module stays light
(numpy and numba load when a deck runs).
"""

from __future__ import annotations

import importlib.resources
import tempfile
from collections.abc import Iterator, Mapping
from dataclasses import dataclass, field
from pathlib import Path
from typing import Any

from asterlite.errors import AsterliteError

# statuses of a run that went to its end without a failed check
SUCCESS = ("PASS", "DONE")


class DeckNotFound(AsterliteError):
    """No deck at the given path, or a folder that does not hold exactly one."""

    kind = "no deck"


def deck_in_folder(folder: Path) -> Path:
    """The deck a folder stands for: its one ``.export``, else its one ``.comm``."""
    folder = Path(folder)
    for pattern in ("*.export", "*.comm"):
        found = sorted(folder.glob(pattern))
        if len(found) == 1:
            return found[0]
        if len(found) > 1:
            names = ", ".join(p.name for p in found)
            raise DeckNotFound(
                f"{folder}: the folder holds {len(found)} {pattern[1:]} files ({names}): "
                "give the one to run"
            )
    raise DeckNotFound(f"{folder}: the folder holds no .export or .comm file")


def find_deck(path: str | Path) -> Path:
    """A deck file, or the one deck of a folder; DeckNotFound otherwise."""
    path = Path(path)
    if path.is_dir():
        return deck_in_folder(path)
    if not path.is_file():
        raise DeckNotFound(f"{path}: no such deck file or folder")
    return path


# ------------------------------------------------------------------ results


@dataclass(frozen=True)
class Check:
    """One TEST_* check: the value, what it was compared with and the verdict.

    ``expected``/``error``/``tolerance`` are those of the reference check
    (VALE_REFE) when there is one, else of VALE_CALC; ``comparisons`` holds
    each (``{"VALE_REFE": {...}, "VALE_CALC": {...}}``) and ``failed`` names
    those that did not hold."""

    command: str
    label: str
    value: Any
    expected: Any
    reference: str
    error: float
    tolerance: float
    ok: bool
    strict: bool
    comparisons: dict = field(default_factory=dict)
    failed: tuple[str, ...] = ()
    line: int | None = None


class Concepts(Mapping):
    """The concepts of a run by deck name, converted to data on first access
    (:func:`asterlite.io.frames.as_python`); ``raw`` keeps asterlite's objects."""

    def __init__(self, raw: dict[str, Any]):
        self.raw = raw
        self._converted: dict[str, Any] = {}

    def __getitem__(self, name: str) -> Any:
        if name not in self._converted:
            from asterlite.io.frames import as_python

            self._converted[name] = as_python(self.raw[name])
        return self._converted[name]

    def __iter__(self) -> Iterator[str]:
        return iter(self.raw)

    def __len__(self) -> int:
        return len(self.raw)

    def __repr__(self) -> str:
        kinds = ", ".join(f"{name}: {concept.aster_type}" for name, concept in self.raw.items())
        return f"Concepts({kinds})"


@dataclass
class RunResult:
    """What :func:`run` returns: the verdict, the checks, the concepts."""

    deck: str
    status: str  # PASS, NOOK, DONE, ERROR, UNSUPPORTED
    message: str
    seconds: float
    checks: list[Check]
    concepts: Concepts
    variables: dict[str, Any]  # the deck's plain values (numbers, strings, lists)
    output: Path | None
    report: Any = field(repr=False)  # the runner's RunReport

    @property
    def ok(self) -> bool:
        """True when the deck ran to its end and every check held."""
        return self.status in SUCCESS

    @property
    def exit_code(self) -> int:
        return self.report.exit_code

    @property
    def summary(self) -> dict:
        """The run as ``summary.json`` has it (JSON-friendly)."""
        return self.report.as_dict()

    @property
    def transients(self) -> list[dict]:
        """Per tran_gene result: scheme, steps, step sizes, integration time."""
        return self.report.transients

    @property
    def shocks(self) -> list[dict]:
        """Per shock: impacts, peak and mean normal force, wear power."""
        return self.report.shocks

    @property
    def verdicts(self) -> dict[str, str]:
        """The two kinds of comparison counted apart: ``{"VALE_REFE": "4/4",
        "VALE_CALC": "0/4"}`` (``"-"`` when no check makes that kind).
        VALE_REFE checks compare with an independent reference; VALE_CALC ones
        with the deck's own computed values (non-regression), which a run with
        other variables (``MU=0.1``) is expected to fail."""
        from asterlite.runtime.verdicts import CALC, REFE, verdict_text, verdicts

        counts = verdicts(self.report.tests)
        return {REFE: verdict_text(counts, REFE), CALC: verdict_text(counts, CALC)}

    @property
    def note(self) -> str:
        """Why a run with deck variables replaced is NOOK when its VALE_CALC
        checks fail (they are the deck's results for its own values, named
        here), else ""."""
        return (getattr(self.report, "extras", None) or {}).get("note", "")

    def __repr__(self) -> str:
        passed = sum(c.ok for c in self.checks)
        names = ", ".join(self.concepts) or "none"
        return (
            f"<RunResult {self.deck}: {self.status}, {passed}/{len(self.checks)} checks OK, "
            f"concepts {names}>"
        )


@dataclass
class CheckResult:
    """What :func:`check` returns."""

    deck: str
    status: str  # CHECKED, ERROR, UNSUPPORTED
    message: str
    errors: list[str]

    @property
    def ok(self) -> bool:
        return self.status == "CHECKED"


# ------------------------------------------------------------------ entry points


def run(deck_or_export: str | Path, output: str | Path | None = None, **overrides) -> RunResult:
    """Run a deck (``.comm``, ``.export``, or a folder holding one).

    ``output``: the run's folder (message.log, summary.json, files the deck
    writes); None runs in a temporary folder removed afterwards. Keyword
    arguments replace deck-level variables (``MU=0.2`` binds 0.2 where the
    deck assigns ``MU = ...``), as ``asterlite sweep --set`` does; a name the
    deck never assigns raises ValueError. A deck that fails is no exception:
    ``status`` says ERROR or UNSUPPORTED and ``message`` why."""
    from asterlite.runtime.runner import run_deck

    deck = find_deck(deck_or_export)
    if output is None:
        with tempfile.TemporaryDirectory(prefix="asterlite-run-") as scratch:
            report = run_deck(deck, Path(scratch), overrides=overrides)
    else:
        report = run_deck(deck, Path(output), overrides=overrides)
    if report.unknown_overrides:
        raise ValueError(report.message)
    return _run_result(report, None if output is None else Path(output))


def check(deck: str | Path) -> CheckResult:
    """Validate a deck against the keyword catalogues without computing
    (``asterlite check``): CHECKED, or the errors with file, line and keyword."""
    from asterlite.runtime.runner import run_deck

    report = run_deck(find_deck(deck), check_only=True)
    errors = list(getattr(report, "errors", None) or ([report.message] if report.message else []))
    return CheckResult(report.deck, report.status, report.message, errors)


def sample(name: str) -> Path:
    """The folder of a sample shipped with asterlite (``friction_oscillator``,
    ``tube_supports``): ``asterlite.run(asterlite.sample("friction_oscillator"))``
    runs it from any working directory."""

    root = Path(str(importlib.resources.files("asterlite.samples")))
    folder = root / name
    if not folder.is_dir():
        known = sorted(p.name for p in root.iterdir() if p.is_dir() and not p.name.startswith("_"))
        raise DeckNotFound(f"no sample {name!r} (samples: {', '.join(known)})")
    return folder


def load(path: str | Path, name: str | None = None, *, raw: bool = False):
    """The tran_gene results of an HDF5 store (``asterlite run --save-results``)
    as ``{name: data}`` (each as in :attr:`RunResult.concepts`), or the one
    called ``name``; ``raw=True`` gives asterlite's TranGene objects (with
    their tables, modal basis and mesh)."""
    from asterlite.io.frames import as_python
    from asterlite.io.result_store import load_tran_gene, stored_names

    path = Path(path)
    if not path.is_file():
        raise FileNotFoundError(f"{path}: no such results file")
    names = [name] if name is not None else stored_names(path)
    loaded = {n: load_tran_gene(path, n) for n in names}
    converted = loaded if raw else {n: as_python(t) for n, t in loaded.items()}
    return converted[name] if name is not None else converted


# ------------------------------------------------------------------ helpers


def _check_of(record, entry: dict) -> Check:
    """A Check from a TestRecord and its summary.json entry."""
    location = getattr(record, "location", None)
    return Check(
        command=entry["command"],
        label=entry["label"],
        value=record.value,
        expected=record.expected,
        reference=entry["reference"],
        error=entry["error"],
        tolerance=entry["tolerance"],
        ok=entry["ok"],
        strict=entry["strict"],
        comparisons=entry.get("comparisons", {}),
        failed=tuple(entry.get("failed", ())),
        line=location.line if location is not None else None,
    )


def _is_plain(value) -> bool:
    if isinstance(value, bool | int | float | complex | str):
        return True
    if isinstance(value, list | tuple):
        return all(_is_plain(v) for v in value)
    return type(value).__name__ == "ndarray"


def _run_result(report, output: Path | None) -> RunResult:
    from asterlite.concepts.base import Concept

    namespace = getattr(report, "namespace", None) or {}
    concepts = {n: v for n, v in namespace.items() if isinstance(v, Concept)}
    variables = {
        n: v
        for n, v in namespace.items()
        if not n.startswith("_") and _is_plain(v) and n not in _BUILTIN_NAMES
    }
    entries = report.as_dict()["tests"]
    checks = [_check_of(r, e) for r, e in zip(report.tests, entries, strict=True)]
    return RunResult(
        deck=report.deck,
        status=report.status,
        message=report.message,
        seconds=report.seconds,
        checks=checks,
        concepts=Concepts(concepts),
        variables=variables,
        output=output,
        report=report,
    )


def _builtin_names() -> frozenset[str]:
    """Names every deck starts with (pi, e, ...): not the deck's variables."""
    from asterlite.lang import base_namespace

    return frozenset(base_namespace(print_hook=lambda text: None))


class _LazyNames:
    """``_BUILTIN_NAMES``, computed on first use (keeps the import light)."""

    names: frozenset[str] | None = None

    def __contains__(self, name: str) -> bool:
        if self.names is None:
            self.names = _builtin_names()
        return name in self.names


_BUILTIN_NAMES = _LazyNames()

__all__ = [
    "Check",
    "CheckResult",
    "Concepts",
    "DeckNotFound",
    "RunResult",
    "check",
    "deck_in_folder",
    "find_deck",
    "load",
    "run",
    "sample",
]
