"""Parameter studies: run one deck for every combination of deck-level
variables, in parallel on Dask, and gather one table of results.

Each variant is an ordinary :func:`run_deck` with ``overrides`` (the deck's
``NAME = ...`` statements bind the swept value instead), run as one Dask task
in its own output subfolder ``DIR/<NAME>=<v>_<NAME2>=<v2>/``. ``run_deck``
turns every failure into an ERROR report, so one bad variant never stops the
others; a worker that dies is reported as an ERROR row too.

With ``--scheduler`` the tasks go to an existing cluster: its workers need
asterlite installed and must see the deck and the output folder at the same
paths (a shared filesystem).

Dask and pyarrow come with the ``sweep`` extra (``pip install
'asterlite[sweep]'``); without them :func:`dask_client` stops with a
:class:`~asterlite.extras.MissingExtraError` saying so, before any variant runs.
"""

from __future__ import annotations

import csv
import itertools
import logging
import re
from collections.abc import Callable, Iterator
from contextlib import contextmanager
from dataclasses import dataclass
from pathlib import Path

from asterlite.extras import require
from asterlite.isolation import protect_spawned_workers
from asterlite.runtime.runner import run_deck
from asterlite.runtime.verdicts import CALC, REFE, variant_note, verdict_text, verdicts

PURPOSE = "asterlite sweep"
STATUSES_THAT_RAN = ("PASS", "NOOK", "DONE")
# VALE_REFE / VALE_CALC: each kind of comparison counted apart ("4/4"): a variant
# is expected to fail the deck's VALE_CALC values, which are the deck's own
# results (asterlite.runtime.verdicts); note says so in words
FIXED_COLUMNS = (
    "status", "seconds", "checks_ok", "checks_total", "VALE_REFE", "VALE_CALC", "message", "note"
)  # fmt: skip
TABLE_NAME = "sweep"  # DIR/sweep.csv, DIR/sweep.parquet


class SweepError(ValueError):
    """A sweep that cannot start: a malformed --set, or a name the deck never assigns."""


@dataclass(frozen=True)
class Setting:
    """One ``--set NAME=v1,v2,...``: a deck-level variable and its values."""

    name: str
    values: tuple


# ----------------------------------------------------------------- settings


def parse_value(text: str) -> int | float | str:
    """A Python number when the text is one (``3``, ``0.15``, ``1.E+04``),
    else the text itself (without surrounding quotes)."""
    text = text.strip()
    for convert in (int, float):
        try:
            return convert(text)
        except ValueError:
            pass
    if len(text) >= 2 and text[0] == text[-1] and text[0] in "'\"":
        return text[1:-1]
    return text


def parse_setting(text: str) -> Setting:
    """``NAME=v1,v2,...`` -> Setting (raises SweepError on bad syntax)."""
    name, equals, values = text.partition("=")
    name = name.strip()
    if not equals or not name.isidentifier():
        raise SweepError(f"--set {text!r}: expected NAME=value1,value2,...")
    parsed = tuple(parse_value(v) for v in values.split(",") if v.strip())
    if not parsed:
        raise SweepError(f"--set {name}: no values given")
    return Setting(name, parsed)


def variants(settings: list[Setting]) -> list[dict[str, object]]:
    """Every combination of the settings' values, first setting slowest."""
    names = [s.name for s in settings]
    duplicated = sorted({n for n in names if names.count(n) > 1})
    if duplicated:
        raise SweepError(f"--set given twice for {', '.join(duplicated)}")
    combos = itertools.product(*(s.values for s in settings))
    return [dict(zip(names, combo, strict=True)) for combo in combos]


def variant_folder(variant: dict[str, object]) -> str:
    """``MU=0.15_U0=0.003``: a folder name safe on any filesystem."""
    parts = (f"{name}={_value_text(value)}" for name, value in variant.items())
    return re.sub(r"[^\w.+=-]", "-", "_".join(parts)) or "default"


def _value_text(value) -> str:
    return repr(value) if isinstance(value, float) else str(value)


def unique_folders(all_variants: list[dict]) -> list[str]:
    """One folder per variant, suffixed when sanitizing made two names equal."""
    folders, seen = [], set()
    for variant in all_variants:
        folder = base = variant_folder(variant)
        counter = 2
        while folder in seen:
            folder, counter = f"{base}_{counter}", counter + 1
        seen.add(folder)
        folders.append(folder)
    return folders


# ------------------------------------------------------------ one variant


def run_variant(deck: str, output_dir: str, variant: dict[str, object]) -> dict:
    """Run one variant (a Dask task: plain arguments in, a plain row out)."""

    report = run_deck(Path(deck), Path(output_dir), overrides=variant)
    return report_row(variant, report)


def report_row(variant: dict[str, object], report) -> dict:
    """The table row of a finished run: variables, verdict, each TEST_* value,
    then the cells of the deck's one-row tables as ``TABLE.PARA``."""
    row = dict(variant)
    row.update(
        status=report.status,
        seconds=round(report.seconds, 3),
        checks_ok=report.checks_ok,
        checks_total=report.checks_total,
        message=report.message,
    )
    row.update(verdict_cells(report))
    for label, value in check_values(report.tests).items():
        row[label] = value
    for name, value in report.table_values.items():
        row.setdefault(name, _cell(value))  # a check label of the same name wins
    return row


def verdict_cells(report) -> dict[str, object]:
    """The VALE_REFE and VALE_CALC columns ("3/4", "-" when none) and the note."""

    counts = verdicts(report.tests)
    extras = getattr(report, "extras", None) or {}
    note = extras.get("note")
    if note is None:
        note = variant_note(report.tests, getattr(report, "overrides", {}) or {}, {})
    return {REFE: verdict_text(counts, REFE), CALC: verdict_text(counts, CALC), "note": note}


def check_values(tests) -> dict[str, object]:
    """``{label: value}`` of each TEST_* record; repeated labels get ``#2``, ``#3``."""
    values: dict[str, object] = {}
    for test in tests:
        label, counter = test.label, 2
        while label in values:
            label, counter = f"{test.label} #{counter}", counter + 1
        values[label] = _cell(test.value)
    return values


def _cell(value):
    """A CSV/Parquet-friendly scalar: numbers stay numbers, the rest is text."""
    if hasattr(value, "item") and getattr(value, "ndim", 0) == 0:
        value = value.item()
    if isinstance(value, bool):
        return int(value)
    if isinstance(value, (int, float, str)) or value is None:
        return value
    return str(value)


def failed_row(variant: dict[str, object], message: str) -> dict:
    """The row of a variant whose task never returned (its worker died...)."""
    row = dict(variant)
    row.update(status="ERROR", seconds=None, checks_ok=0, checks_total=0, message=message)
    return row


# ------------------------------------------------------------- the sweep


def unknown_names(deck: Path, settings: list[Setting]) -> list[str]:
    """Names of ``settings`` the deck never assigns, found by a quick check run
    (no computation) before any worker starts."""

    first_values = {s.name: s.values[0] for s in settings}
    report = run_deck(deck, check_only=True, overrides=first_values)
    return report.unknown_overrides


def require_extras():
    """The ``distributed`` module, once Dask and pyarrow are known to import
    (else a MissingExtraError naming ``asterlite[sweep]``)."""
    require("pyarrow.parquet", PURPOSE)
    return require("distributed", PURPOSE)


@contextmanager
def dask_client(scheduler: str | None = None, workers: int = 2) -> Iterator:
    """A client of an existing scheduler, or of a LocalCluster of processes
    (one thread each: a deck run is single-threaded numerics) closed on exit.
    Checks first that the sweep extra is installed (the tables need pyarrow)."""

    distributed = require_extras()
    Client, LocalCluster = distributed.Client, distributed.LocalCluster
    if scheduler:
        with Client(scheduler) as client:
            yield client
        return
    protect_spawned_workers()  # the workers' `python -c` would import from the current folder
    with (
        LocalCluster(
            n_workers=workers,
            threads_per_worker=1,
            processes=True,
            dashboard_address=None,
            silence_logs=logging.ERROR,
        ) as cluster,
        Client(cluster) as client,
    ):
        yield client


def run_sweep(
    deck: Path,
    settings: list[Setting],
    output_dir: Path,
    client,
    *,
    progress: Callable[[dict], None] | None = None,
) -> list[dict]:
    """Run every variant on ``client``; rows in variant order."""
    as_completed = require("distributed", PURPOSE).as_completed
    all_variants = variants(settings)
    deck = Path(deck).resolve()
    output_dir = Path(output_dir).resolve()
    output_dir.mkdir(parents=True, exist_ok=True)
    futures = {}
    for index, (variant, folder) in enumerate(
        zip(all_variants, unique_folders(all_variants), strict=True)
    ):
        future = client.submit(
            run_variant, str(deck), str(output_dir / folder), variant, pure=False
        )
        futures[future] = index
    rows: list[dict | None] = [None] * len(all_variants)
    for future in as_completed(futures):
        index = futures[future]
        try:
            row = future.result()
        except Exception as error:  # the worker died or could not run the task
            row = failed_row(all_variants[index], f"task failed: {error!r}")
        rows[index] = row
        if progress is not None:
            progress(row)
    return rows


def sweep_exit_code(rows: list[dict]) -> int:
    """0 when every variant ran (PASS or NOOK), 2 when any errored."""
    return 0 if all(row["status"] in STATUSES_THAT_RAN for row in rows) else 2


# ----------------------------------------------------------------- tables


def table_columns(rows: list[dict], variables: list[str]) -> list[str]:
    """Variables first, then the fixed columns, then check labels and table
    cells as first seen."""
    columns = list(variables) + list(FIXED_COLUMNS)
    for row in rows:
        columns += [key for key in row if key not in columns]
    return columns


def write_csv(rows: list[dict], columns: list[str], path: Path) -> Path:
    with path.open("w", newline="", encoding="utf-8") as stream:
        writer = csv.DictWriter(stream, fieldnames=columns, restval="")
        writer.writeheader()
        writer.writerows(rows)
    return path


def write_parquet(rows: list[dict], columns: list[str], path: Path) -> Path:
    pa = require("pyarrow", PURPOSE)
    pq = require("pyarrow.parquet", PURPOSE)
    arrays = {name: _arrow_column([row.get(name) for row in rows]) for name in columns}
    pq.write_table(pa.table(arrays), path)
    return path


def _arrow_column(values: list):
    """Numbers as float64 (int64 when all are ints); a column mixing numbers and
    text (a swept value of the wrong type) becomes text."""
    import pyarrow as pa

    present = [v for v in values if v is not None]
    if present and all(isinstance(v, int) for v in present):
        return pa.array(values, type=pa.int64())
    if all(isinstance(v, (int, float)) for v in present):
        return pa.array([None if v is None else float(v) for v in values], type=pa.float64())
    return pa.array([None if v is None else str(v) for v in values], type=pa.string())


def write_tables(rows: list[dict], variables: list[str], output_dir: Path) -> list[Path]:
    columns = table_columns(rows, variables)
    return [
        write_csv(rows, columns, output_dir / f"{TABLE_NAME}.csv"),
        write_parquet(rows, columns, output_dir / f"{TABLE_NAME}.parquet"),
    ]


def format_sweep_table(rows: list[dict], variables: list[str]) -> str:
    """A text table: one line per variant; checks as c1, c2... with a legend."""
    labels = [c for c in table_columns(rows, variables) if c not in (*variables, *FIXED_COLUMNS)]
    names = [f"c{i}" for i in range(1, len(labels) + 1)]
    header = [*variables, "status", "seconds", "checks", "VALE_REFE", "VALE_CALC", *names]
    lines = []
    for row in rows:
        cells = [_value_text(row.get(v)) for v in variables]
        seconds = row.get("seconds")
        cells += [
            row["status"],
            "-" if seconds is None else f"{seconds:.2f}",
            f"{row['checks_ok']}/{row['checks_total']}",
            row.get("VALE_REFE") or "-",
            row.get("VALE_CALC") or "-",
        ]
        cells += [_short(row.get(label)) for label in labels]
        lines.append(cells)
    widths = [max(len(str(c)) for c in column) for column in zip(header, *lines, strict=True)]
    text = [_join(header, widths), _join(["-" * w for w in widths], widths)]
    text += [_join(cells, widths) for cells in lines]
    if labels:
        text.append("")
        text += [f"  {name}: {label}" for name, label in zip(names, labels, strict=True)]
    text += variant_footnote(rows)
    failures = [row for row in rows if row["status"] not in STATUSES_THAT_RAN]
    if failures:
        text.append("")
        for row in failures:
            where = ", ".join(f"{v}={_value_text(row.get(v))}" for v in variables)
            text.append(f"  {where}: {row['status']}: {_first_line(row['message'])}")
    return "\n".join(text)


def variant_footnote(rows: list[dict]) -> list[str]:
    """Why NOOK variants are NOOK when their VALE_CALC checks fail: those are
    the deck's own results (one line, with the deck's values when known)."""
    calc_only = [
        row
        for row in rows
        if row["status"] == "NOOK" and row.get("note") and _all_hold(row.get("VALE_REFE"))
    ]
    failing_calc = [row for row in rows if row["status"] == "NOOK" and row.get("note")]
    if not failing_calc:
        return []
    lines = [
        "",
        "  VALE_CALC values are the deck's own results for its own settings (non-regression):",
        "  a variant is expected to fail them; VALE_REFE checks are independent references.",
    ]
    if calc_only:
        lines.append(
            f"  {len(calc_only)} of the {len(failing_calc)} NOOK variants fail only VALE_CALC"
            " checks: every VALE_REFE check holds."
        )
    return lines


def _all_hold(cell) -> bool:
    if not isinstance(cell, str) or "/" not in cell:
        return False
    ok, total = cell.split("/")
    return ok == total


def _short(value) -> str:
    if value is None:
        return "-"
    return f"{value:.6g}" if isinstance(value, float) else str(value)


def _join(cells, widths) -> str:
    return "  ".join(str(c).ljust(w) for c, w in zip(cells, widths, strict=True)).rstrip()


def _first_line(message: str) -> str:
    return next((line for line in message.splitlines() if line.strip()), "")


__all__ = [
    "Setting",
    "SweepError",
    "dask_client",
    "format_sweep_table",
    "parse_setting",
    "parse_value",
    "require_extras",
    "run_sweep",
    "run_variant",
    "sweep_exit_code",
    "unknown_names",
    "variants",
    "write_tables",
]
