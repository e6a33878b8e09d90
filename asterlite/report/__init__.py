"""The run report: one self-contained HTML page to look at.

``asterlite run --report`` writes ``report.html`` (and ``curves.json``, the
data of its curves) with the run's files; ``asterlite report OUTDIR`` writes
it later from what a run left (summary.json, message.log, results.h5 when
the run saved it, curves.json). :mod:`asterlite.report.page` lays it out,
:mod:`asterlite.report.svg` draws its figures, :mod:`asterlite.report.data`
gathers what it shows, :mod:`asterlite.report.fields` adds to summary.json
what it needs (and what a reader needs).

Importing this package stays light: the runner imports it at every run.
"""

from __future__ import annotations

import io
from pathlib import Path

from asterlite.runtime.outdir import list_in_summary
from asterlite.runtime.write_boundary import replace_outside

REPORT_NAME = "report.html"


class ReportError(Exception):
    """A report that cannot be written (no run there, a file in the way)."""


def write_run_page(folder, report, session) -> None:
    """``asterlite run --report``: report.html and curves.json into the run's
    staging folder (published with the run's files, or kept under
    incomplete/ with them). Never fails the run: a failure is logged."""
    from asterlite.report import data as D
    from asterlite.report.page import render

    try:
        data = D.from_run(report, session, folder.path)
        staging = Path(folder.staging)
        folder.check_name(REPORT_NAME)
        folder.check_name(D.CURVES_NAME)
        if data.curves:
            (staging / D.CURVES_NAME).write_text(D.curves_json(data.curves), encoding="utf-8")
        (staging / REPORT_NAME).write_text(render(data), encoding="utf-8")
        session.log(f"{REPORT_NAME}: the run report (asterlite report {folder.path} rewrites it)")
    except Exception as error:  # noqa: BLE001 - the run's results matter more than its page
        try:
            session.log(f"{REPORT_NAME} not written: {type(error).__name__}: {error}")
        except Exception:  # noqa: BLE001
            pass


def write_report(outdir: Path, output: Path | None = None) -> Path:
    """``asterlite report OUTDIR``: the page of the run in ``outdir``, written
    to ``output`` (default ``OUTDIR/report.html``). A report.html there that
    asterlite did not write is never replaced; one it wrote is, and the
    run's summary.json lists it among the run's files (so that the next run
    into the folder moves it aside with them)."""
    from asterlite.report import data as D
    from asterlite.report.page import GENERATOR, render

    outdir = Path(outdir)
    if (outdir / ".asterlite.lock").exists():
        raise ReportError(f"{outdir}: a run is writing there; report when it has ended")
    try:
        data = D.from_folder(outdir)
    except (FileNotFoundError, ValueError) as error:
        raise ReportError(str(error)) from None
    target = Path(output) if output is not None else outdir / REPORT_NAME
    if target.is_symlink() or (target.exists() and not _ours(target, GENERATOR)):
        raise ReportError(f"{target}: a file asterlite did not write is there; give -o FILE")
    page = io.BytesIO(render(data).encode("utf-8"))
    try:  # written aside (never through a symlink), then renamed over the target
        replace_outside(page, target)
    except OSError as error:
        raise ReportError(f"{target}: {error.strerror or error}") from None
    if output is None:  # listed in the run's (verified) summary: the next run moves it aside
        list_in_summary(outdir, REPORT_NAME)
    return target


def _ours(path: Path, generator: str) -> bool:
    try:
        with open(path, encoding="utf-8", errors="replace") as stream:
            head = stream.read(2000)
    except OSError:
        return False
    return f'content="{generator}"' in head


__all__ = ["REPORT_NAME", "ReportError", "write_report", "write_run_page"]
