"""Run (or check) a deck from its path and report what happened.

Result files are written into a staging folder and moved into the output
folder only when the run completes; a run stopped by an error leaves its
files under ``incomplete/`` so nothing partial looks finished. The output
folder always gets ``message.log`` and ``summary.json``.
"""

from __future__ import annotations

import json
import shutil
import statistics
import time
import traceback
from dataclasses import dataclass, field
from pathlib import Path

from asterlite.errors import AsterliteError, UnsupportedError
from asterlite.runtime.context import TestRecord
from asterlite.runtime.export import describe_run

EXIT_OK, EXIT_NOOK, EXIT_ERROR = 0, 1, 2


@dataclass
class RunReport:
    deck: str
    status: str  # PASS, NOOK, ERROR, UNSUPPORTED (CHECKED under check)
    message: str = ""
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
        if self.status in ("PASS", "CHECKED"):
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
            "overrides": {k: _plain(v) for k, v in self.overrides.items()},
            "overrides_used": self.overrides_used,
            "transients": self.transients,
            "shocks": self.shocks,
            "tests": [
                {
                    "command": t.command,
                    "label": t.label,
                    "value": _plain(t.value),
                    "expected": _plain(t.expected),
                    "reference": t.reference,
                    "error": _plain(t.error),
                    "tolerance": _plain(t.tolerance),
                    "ok": bool(t.ok),
                    "strict": bool(t.strict),
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


def _plain(value):
    """JSON-friendly version of a test value (numpy scalars, complex...)."""
    if isinstance(value, complex):
        return [value.real, value.imag]
    if hasattr(value, "item"):
        try:
            return value.item()
        except (ValueError, AttributeError):
            return str(value)
    if isinstance(value, (int, float, str, bool)) or value is None:
        return value
    return str(value)


def run_deck(
    deck: Path,
    output_dir: Path | None = None,
    *,
    check_only: bool = False,
    echo: bool = False,
    overrides: dict | None = None,
    keyword_overrides: list | None = None,
    save_results: bool = False,
) -> RunReport:
    """Run or check the deck at ``deck`` (an .export or a .comm).

    ``overrides`` maps deck-level variable names to the values bound instead
    of the deck's own (see :class:`asterlite.lang.Evaluator`); a name the deck
    never assigns makes the run an ERROR naming it. ``keyword_overrides``
    (:class:`asterlite.runtime.session.KeywordOverride`) replace keyword
    values in command calls before validation (e.g. DYNA_VIBRA's scheme).
    """
    from asterlite.runtime.session import Session, UnknownOverrideError

    start = time.perf_counter()
    name = deck.stem
    staging = None
    if output_dir is not None and not check_only:
        output_dir.mkdir(parents=True, exist_ok=True)
        staging = output_dir / ".running"
        shutil.rmtree(staging, ignore_errors=True)
        shutil.rmtree(output_dir / "incomplete", ignore_errors=True)
        staging.mkdir()
    session = None
    try:
        description = describe_run(deck)
        name = description.name
        session = Session(
            description,
            output_dir=staging,
            check_only=check_only,
            echo=echo,
            overrides=dict(overrides or {}),
            keyword_overrides=list(keyword_overrides or []),
        )
        session.run_all()
    except UnknownOverrideError as error:
        report = RunReport(name, "ERROR", str(error), unknown_overrides=session.unused_overrides())
    except UnsupportedError as error:
        report = RunReport(name, "UNSUPPORTED", str(error))
    except AsterliteError as error:
        report = RunReport(name, "ERROR", str(error))
    except RecursionError:
        report = RunReport(name, "ERROR", "internal error: recursion too deep")
    except Exception as error:  # an asterlite bug: report it, never crash the caller
        detail = traceback.format_exc(limit=-3)
        report = RunReport(name, "ERROR", f"internal error: {error!r}\n{detail}")
    else:
        if check_only:
            report = RunReport(name, "CHECKED")
        elif all(t.ok for t in session.tests):
            report = RunReport(name, "PASS")
        else:
            report = RunReport(name, "NOOK")
    report.overrides = dict(overrides or {})
    if session is not None:
        report.tests = list(session.tests)
        report.timings = list(session.timings)
        report.overrides_used = sorted(session.overrides_used)
        if not check_only:  # results exist only when computed (and check stays light)
            report.table_values = one_row_table_values(session.namespace)
            report.transients, report.shocks = transient_summaries(session.produced)
        report.keyword_edits = list(session.keyword_edits)
    report.seconds = time.perf_counter() - start
    if output_dir is not None and not check_only:
        _finish_output(output_dir, staging, report, session, save_results)
    return report


def one_row_table_values(namespace: dict) -> dict:
    """``{"TABLE.PARA": value}`` for the deck's tables of a single row: the
    scalar results (wear power, peak force...) a parameter study compares."""
    from asterlite.concepts.table import Table

    values = {}
    for name, value in namespace.items():
        if isinstance(value, Table) and len(value.rows) == 1:
            for para, cell in value.rows[0].items():
                values[f"{name}.{para}"] = _plain(cell)
    return values


def transient_summaries(produced) -> tuple[list[dict], list[dict]]:
    """Per tran_gene result made by the run: its integration figures; and per
    shock of those results: peak normal force and wear power."""
    from asterlite.concepts.transient import TranGene

    transients, shocks, calls = [], [], {}
    for command, name, concept in produced:
        call = calls[command] = calls.get(command, 0) + 1  # the command's n-th call
        if not isinstance(concept, TranGene):
            continue
        info = concept.info
        transients.append(
            {
                "result": name,
                "command": command,
                "call": call,
                "scheme": concept.scheme,
                "step": float(concept.step),
                "t_start": float(concept.times[0]) if len(concept.times) else None,
                "t_end": float(concept.times[-1]) if len(concept.times) else None,
                "steps": int(info.get("steps", 0)),
                "rejected_steps": int(info.get("rejected_steps", 0)),
                "min_step": _plain(info.get("min_step")),
                "max_step": _plain(info.get("max_step")),
                # the steps that led to the archived instants (PTEM): their median
                "median_step": statistics.median(concept.step_sizes[1:].tolist())
                if concept.step_sizes is not None and len(concept.step_sizes) > 1
                else None,
                "integration_seconds": float(info.get("integration_seconds", 0.0)),
            }
        )
        if "energy_residual" in info:  # ENERGIE=_F(): the final balance residual
            transients[-1]["energy_residual"] = _plain(info["energy_residual"])
            transients[-1]["energy_residual_ratio"] = _plain(info["energy_residual_ratio"])
            transients[-1]["energy_residual_flow_ratio"] = _plain(
                info.get("energy_residual_flow_ratio")
            )
        shocks += [shock_summary(name, concept.times, shock) for shock in concept.shocks]
    return transients, shocks


def shock_summary(result: str | None, times, shock) -> dict:
    """Peak and mean normal force, contact fraction and wear power
    (code_aster's PUIS_USURE: time mean of FN·|VT|) of one shock history."""
    import numpy as np

    from asterlite.post.wear import archard_power

    fields = shock.fields
    fn = np.asarray(fields.get("FN", np.zeros(len(times))), dtype=float)
    zeros = np.zeros_like(fn)
    vt1, vt2 = fields.get("VT1", zeros), fields.get("VT2", zeros)
    in_contact = fn != 0.0
    # an impact starts where the archived normal force leaves zero
    impacts = int(in_contact[0]) + int(np.count_nonzero(in_contact[1:] & ~in_contact[:-1]))
    return {
        "result": result,
        "shock": shock.name,
        "impacts": impacts if fn.size else 0,
        "max_FN": float(np.abs(fn).max()) if fn.size else 0.0,
        "mean_FN": float(np.abs(fn).mean()) if fn.size else 0.0,
        "contact_fraction": float(np.mean(fn != 0.0)) if fn.size else 0.0,
        "wear_power": archard_power(times, fn, vt1, vt2),
    }


def _finish_output(
    output_dir: Path, staging: Path, report: RunReport, session, save_results: bool = False
) -> None:
    complete = report.status in ("PASS", "NOOK")
    if complete and save_results:
        # every tran_gene of the deck, in the store documented in docs/results.md
        from asterlite.io.result_store import save_session_results

        saved = save_session_results(staging / "results.h5", session.namespace)
        session.log(f"results.h5: {', '.join(saved) if saved else 'no tran_gene result to save'}")
    if complete:
        for item in staging.iterdir():
            target = output_dir / item.name
            if target.is_dir():
                shutil.rmtree(target)
            item.replace(target)
        staging.rmdir()
    elif any(staging.iterdir()):
        staging.replace(output_dir / "incomplete")
    else:
        staging.rmdir()
    messages = session.messages if session is not None else []
    lines = list(messages) + ["", format_summary(report)]
    (output_dir / "message.log").write_text("\n".join(lines) + "\n", encoding="utf-8")
    (output_dir / "summary.json").write_text(json.dumps(report.as_dict(), indent=1), "utf-8")


def format_test_line(test: TestRecord) -> str:
    flag = "OK  " if test.ok else "NOOK"
    strict = "" if test.strict or not test.ok else " (not strict)"
    text = (
        f"  {flag} {test.command} {test.label}: value={_plain(test.value)!r} "
        f"expected={_plain(test.expected)!r} error={_plain(test.error)!r}"
    )
    calc = test.calc_comparison
    if calc is not None and test.reference != "NON_REGRESSION":
        text += f" | VALE_CALC={_plain(calc.expected)!r} error={_plain(calc.error)!r}"
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
    if report.message:
        lines.append(report.message)
    return "\n".join(lines)
