"""Convergence studies: what accuracy each scheme and step buys, at what cost.

``asterlite converge DECK`` reruns a deck's ``DYNA_VIBRA`` transients (TRAN,
GENE) over a ladder of settings per scheme — steps for the fixed-step
schemes, tolerances for the error-controlled ones, points per period for
ADAPT_ORDRE1/2 — and compares each run's quantities of interest with a
reference: by default the value of every ``TEST_*`` check of the deck (by
label) and, per shock, the peak normal force and the wear power (time mean
of FN·|VT|, code_aster's PUIS_USURE). Each run is an ordinary in-process
:func:`run_deck` whose ``DYNA_VIBRA`` keywords are replaced before
validation (:class:`asterlite.runtime.session.KeywordOverride`).

The reference is a separate, finer run (``against="finest"``: by default
the first scheme at half its finest step, a tenth of its finest tolerance,
twice its finest points per period) or, for the checks, the deck's own
``VALE_REFE`` when every check has one (``against="reference"``; the shock
quantities, which have none, still use the finest run).

A setting the engine refuses or that diverges (a ``NumericalError``: step
above the stability limit, non-finite solution) becomes a row with status
``unstable`` and the engine's message; the study goes on.
"""

from __future__ import annotations

import csv
import math
import os
import re
import tempfile
from collections.abc import Callable
from contextlib import contextmanager
from dataclasses import dataclass, field
from pathlib import Path

from asterlite.extras import MissingExtraError, require
from asterlite.runtime.runner import run_deck
from asterlite.runtime.session import KeywordOverride
from asterlite.watchdog import address_space_cap

# the knob that buys accuracy, per scheme as named on the command line
FIXED_STEP = ("DIFF_CENTRE", "NEWMARK", "DEVOGE", "TRBDF2")
TOLERANCE = ("RUNGE_KUTTA_32", "RUNGE_KUTTA_54", "DEVOGE_ADAPT")
POINTS = ("ADAPT_ORDRE1", "ADAPT_ORDRE2")
SCHEMES = FIXED_STEP + TOLERANCE + POINTS
KNOBS = {**dict.fromkeys(FIXED_STEP, "PAS"), **dict.fromkeys(TOLERANCE, "TOLERANCE")}
KNOBS.update(dict.fromkeys(POINTS, "NB_POIN_PERIODE"))

DEFAULT_SCHEMES = ("DIFF_CENTRE", "DEVOGE", "RUNGE_KUTTA_54")
DEFAULT_FACTORS = (2.0, 1.0, 0.5, 0.25, 0.125)  # times the deck's own PAS
DEFAULT_TOLERANCES = (1e-3, 1e-4, 1e-5, 1e-6, 1e-7)
DEFAULT_POINTS = (25, 50, 100, 200, 400)
SHOCK_QUANTITIES = ("max_FN", "wear_power")
# adaptive rungs may be stopped (an "unstable" row) when their step falls
# below this fraction of the deck's PAS (0: code_aster's default PAS_MINI).
# Off by default: sound runs also take isolated tiny steps at contact events.
MIN_STEP_RATIO = 0.0
MEMORY_FRACTION = 0.7  # of the physical memory: the address-space cap of `asterlite converge`
RAN = ("PASS", "NOOK", "DONE")  # run statuses whose values count
# a scheme's ladder converges when its finest run's error is below this fraction
# of its coarsest run's (halving the step four times divides a first-order
# error by 16); errors this small count as converged whatever their trend
CONVERGING_RATIO = 0.5
NEGLIGIBLE_ERROR = 1.0e-9
UNSTABLE, ERROR, OK = "unstable", "error", "ok"


PLOT_PURPOSE = "converge.png (error against cost)"


class ConvergeError(ValueError):
    """A study that cannot start or has no reference to compare with."""


# ------------------------------------------------------------------ settings


@dataclass(frozen=True)
class Setting:
    """One rung: a scheme and the value of its knob. ``relative``: the value
    is a factor of each transient's own PAS (the default step ladder)."""

    scheme: str
    value: float
    relative: bool = False

    @property
    def knob(self) -> str:
        return KNOBS[self.scheme]

    def label(self, base_step: float | None = None) -> str:
        if self.relative and base_step:
            return f"{self.value * base_step:.4g}"
        if self.relative:
            return f"x{self.value:g}"
        return f"{self.value:.4g}" if self.knob != "NB_POIN_PERIODE" else f"{int(self.value)}"


def engine_scheme(scheme: str) -> str:
    """The SCHEMA value: DEVOGE_ADAPT is DEVOGE with an adaptive step."""
    return "DEVOGE" if scheme == "DEVOGE_ADAPT" else scheme


def parse_schemes(text: str | None) -> tuple[str, ...]:
    if not text:
        return DEFAULT_SCHEMES
    schemes = tuple(s.strip().upper() for s in text.split(",") if s.strip())
    unknown = [s for s in schemes if s not in SCHEMES]
    if unknown:
        raise ConvergeError(f"unknown scheme {', '.join(unknown)} (known: {', '.join(SCHEMES)})")
    return schemes


def parse_values(text: str | None) -> tuple[float, ...] | None:
    if not text:
        return None
    try:
        values = tuple(float(v) for v in text.split(",") if v.strip())
    except ValueError:
        raise ConvergeError(f"{text!r}: expected numbers separated by commas") from None
    if not values or any(v <= 0 for v in values):
        raise ConvergeError(f"{text!r}: expected positive numbers")
    return values


def ladder(schemes, steps=None, tolerances=None, points=None) -> list[Setting]:
    """Every rung, scheme by scheme, coarsest first."""
    settings = []
    for scheme in schemes:
        knob = KNOBS[scheme]
        if knob == "PAS":
            rungs = (
                [Setting(scheme, s) for s in sorted(steps, reverse=True)]
                if steps
                else [Setting(scheme, f, relative=True) for f in DEFAULT_FACTORS]
            )
        elif knob == "TOLERANCE":
            rungs = [Setting(scheme, t) for t in sorted(tolerances or DEFAULT_TOLERANCES)[::-1]]
        else:
            rungs = [Setting(scheme, p) for p in sorted(points or DEFAULT_POINTS)]
        settings += rungs
    return settings


def parse_reference(text: str | None, settings: list[Setting]) -> Setting:
    """``SCHEME:VALUE``, or finer than the finest rung of the first scheme."""
    if text:
        scheme, _, value = text.partition(":")
        scheme = scheme.strip().upper()
        parse_schemes(scheme)
        if not value:
            raise ConvergeError(f"--reference {text!r}: expected SCHEME:VALUE")
        return Setting(scheme, parse_values(value)[0])
    first = [s for s in settings if s.scheme == settings[0].scheme]
    if first[0].knob == "PAS":
        finest = min(first, key=lambda s: s.value)
        return Setting(finest.scheme, finest.value / 2.0, finest.relative)
    if first[0].knob == "TOLERANCE":
        return Setting(first[0].scheme, min(s.value for s in first) / 10.0)
    return Setting(first[0].scheme, 2.0 * max(s.value for s in first))


def parse_keyword(text: str) -> tuple[str, object]:
    """``PATH=VALUE`` (``SCHEMA_TEMPS/PAS_MAXI=1e-4``): a number when it is one."""
    path, equals, value = text.partition("=")
    if not equals or not path.strip():
        raise ConvergeError(f"--keyword {text!r}: expected FACT/NAME=VALUE")
    value = value.strip()
    for convert in (int, float):
        try:
            return path.strip(), convert(value)
        except ValueError:
            pass
    return path.strip(), None if value.upper() == "NONE" else value.strip("'\"")


def scheme_keywords(
    setting: Setting, transient: dict, min_step_ratio: float = MIN_STEP_RATIO
) -> dict:
    """DYNA_VIBRA keyword values of one rung for one transient of the deck;
    adaptive rungs get ``PAS_MINI = min_step_ratio * PAS`` (0: the default)."""
    keywords = {"SCHEMA_TEMPS/SCHEMA": engine_scheme(setting.scheme)}
    base_step = transient["step"]
    if setting.knob == "PAS":
        step = setting.value * base_step if setting.relative else setting.value
        keywords["INCREMENT/PAS"] = step
        if setting.scheme == "DEVOGE":  # fixed step: PAS_MINI = PAS_MAXI = PAS
            keywords["SCHEMA_TEMPS/PAS_MINI"] = step
            keywords["SCHEMA_TEMPS/PAS_MAXI"] = step
        else:
            keywords["SCHEMA_TEMPS/PAS_MINI"] = None
            keywords["SCHEMA_TEMPS/PAS_MAXI"] = None
        return keywords
    keywords["INCREMENT/PAS"] = base_step  # the initial step
    keywords["SCHEMA_TEMPS/PAS_MINI"] = min_step_ratio * base_step if min_step_ratio else None
    keywords["SCHEMA_TEMPS/PAS_MAXI"] = None
    if setting.knob == "TOLERANCE":
        keywords["SCHEMA_TEMPS/TOLERANCE"] = setting.value
    else:
        keywords["SCHEMA_TEMPS/NB_POIN_PERIODE"] = int(round(setting.value))
    return keywords


def overrides_for(
    setting: Setting,
    transients: list[dict],
    extra: dict | None = None,
    span: int | None = None,
    min_step_ratio: float = MIN_STEP_RATIO,
) -> list[KeywordOverride]:
    """One override per transient call of the deck; ``span``: stop each
    transient after that many (initial) steps (a warm-up run)."""
    overrides = []
    for transient in transients:
        keywords = scheme_keywords(setting, transient, min_step_ratio)
        keywords.update(extra or {})
        if span is not None and transient["t_start"] is not None:
            keywords["INCREMENT/INST_FIN"] = transient["t_start"] + span * keywords["INCREMENT/PAS"]
        overrides.append(KeywordOverride(transient["command"], keywords, call=transient["call"]))
    return overrides


# ------------------------------------------------------------------ one run


@dataclass
class Outcome:
    """One run of the study."""

    setting: Setting
    status: str  # ok, unstable, error
    message: str = ""
    seconds: float = 0.0  # integration wall time, summed over the transients
    steps: int = 0
    rejected: int = 0
    step: float = math.nan  # PAS of the first transient (mean step for adaptive runs)
    mean_step: float = math.nan  # simulated time / steps, all transients
    min_step: float = math.nan
    max_step: float = math.nan
    checks: str = ""
    values: dict[str, float] = field(default_factory=dict)
    errors: dict[str, float] = field(default_factory=dict)
    max_error: float = math.nan
    worst: str = ""
    order: float = math.nan
    orders: dict[str, float] = field(default_factory=dict)
    is_reference: bool = False
    text: str = ""  # the setting as shown: the step in seconds for the default ladder


def quantities(report, pattern: str | None = None) -> dict[str, float]:
    """The run's quantities of interest: each TEST_* value by label, then each
    shock's peak normal force and wear power (``RESULT:SHOCK:max_FN``)."""
    found: dict[str, float] = {}
    for test in report.tests:
        value = _real(test.value)
        if value is not None:
            found[_unique(found, test.label)] = value
    for shock in report.shocks:
        for name in SHOCK_QUANTITIES:
            found[_unique(found, f"{shock['result']}:{shock['shock']}:{name}")] = shock[name]
    if pattern:
        regex = re.compile(pattern)
        found = {k: v for k, v in found.items() if regex.search(k)}
    return found


def reference_values(report, pattern: str | None = None) -> dict[str, float]:
    """The deck's VALE_REFE of every check (ConvergeError if one has none)."""
    found: dict[str, float] = {}
    for test in report.tests:
        expected = _real(test.expected)
        if test.reference == "NON_REGRESSION" or expected is None:
            raise ConvergeError(
                f"--against reference: check {test.label!r} has no reference value "
                "(only VALE_CALC): use --against finest"
            )
        found[_unique(found, test.label)] = expected
    if pattern:
        regex = re.compile(pattern)
        found = {k: v for k, v in found.items() if regex.search(k)}
    return found


def _unique(found: dict, label: str) -> str:
    if label not in found:
        return label
    number = 2
    while f"{label} #{number}" in found:
        number += 1
    return f"{label} #{number}"


def _real(value) -> float | None:
    if isinstance(value, bool) or value is None:
        return None
    try:
        number = float(value)
    except (TypeError, ValueError):
        return None
    return number if math.isfinite(number) else None


def run_setting(
    deck: Path,
    setting: Setting,
    transients: list[dict],
    *,
    extra: dict | None = None,
    pattern: str | None = None,
    repeat: int = 1,
    min_step_ratio: float = MIN_STEP_RATIO,
) -> Outcome:
    """Run the deck with one rung's keywords (``repeat`` times: the least
    integration time is kept; the values are those of the last run)."""
    overrides = overrides_for(setting, transients, extra, min_step_ratio=min_step_ratio)
    best = None
    for _ in range(max(1, repeat)):
        report = run_in_scratch(deck, overrides)
        if report.status not in RAN:
            break
        seconds = sum(t["integration_seconds"] for t in report.transients)
        best = seconds if best is None else min(best, seconds)
    return outcome_of(setting, report, best, pattern)


@contextmanager
def memory_cap(fraction: float = MEMORY_FRACTION):
    """Cap the process's address space at ``fraction`` of the physical memory
    while the study runs, so that a rung whose adaptive step collapses (and
    archives millions of steps) fails with a MemoryError — an ``error`` row —
    instead of being killed by the system. No-op where unsupported."""

    try:
        total = os.sysconf("SC_PAGE_SIZE") * os.sysconf("SC_PHYS_PAGES")
    except (ValueError, OSError, AttributeError):
        total = None
    cap = int(fraction * total) if total and fraction > 0 else None
    with address_space_cap(cap):
        yield


def run_in_scratch(deck: Path, overrides: list | None = None):
    """run_deck with an output folder (decks that print tables or results
    need one) that is thrown away afterwards."""

    with tempfile.TemporaryDirectory(prefix="asterlite-converge-") as scratch:
        return run_deck(deck, Path(scratch), keyword_overrides=overrides)


def outcome_of(setting: Setting, report, seconds: float | None, pattern: str | None) -> Outcome:
    if report.status not in RAN:
        unstable = "numerical error" in report.message
        return Outcome(setting, UNSTABLE if unstable else ERROR, _one_line(report.message))
    transients = report.transients
    steps = sum(t["steps"] for t in transients)
    span = sum(t["t_end"] - t["t_start"] for t in transients)
    first = transients[0] if transients else {}
    adaptive = setting.knob != "PAS"
    return Outcome(
        setting,
        OK,
        seconds=seconds or 0.0,
        steps=steps,
        rejected=sum(t["rejected_steps"] for t in transients),
        step=(span / steps if adaptive else first.get("step", math.nan)) if steps else math.nan,
        mean_step=span / steps if steps else math.nan,
        min_step=min((t["min_step"] for t in transients), default=math.nan),
        max_step=max((t["max_step"] for t in transients), default=math.nan),
        checks=f"{report.checks_ok}/{report.checks_total}",
        values=quantities(report, pattern),
    )


def _one_line(message: str) -> str:
    """The engine's message without its deck location and the excerpt under it."""
    lines = [line.strip() for line in message.splitlines() if line.strip()]
    return re.sub(r"^.*?:\d+:\d+: ", "", lines[0]) if lines else ""


# ------------------------------------------------------------------ errors


def relative_error(value: float, reference: float) -> float:
    """|value - reference| / |reference| (0 when both vanish, NaN when only
    the reference does: no relative scale)."""
    if reference == 0.0:
        return 0.0 if value == 0.0 else math.nan
    return abs(value - reference) / abs(reference)


def compare(outcome: Outcome, reference: dict[str, float]) -> None:
    """Fill the errors of one run against the reference values."""
    if outcome.status != OK:
        return
    outcome.errors = {
        name: relative_error(outcome.values[name], ref)
        for name, ref in reference.items()
        if name in outcome.values
    }
    finite = {k: v for k, v in outcome.errors.items() if not math.isnan(v)}
    if finite:
        outcome.worst = max(finite, key=finite.get)
        outcome.max_error = finite[outcome.worst]


def observed_order(e_coarse: float, e_fine: float, h_coarse: float, h_fine: float) -> float:
    """log(e_coarse / e_fine) / log(h_coarse / h_fine), NaN when undefined."""
    values = (e_coarse, e_fine, h_coarse, h_fine)
    if any(not (v > 0.0) or math.isinf(v) for v in values) or h_coarse == h_fine:
        return math.nan
    return math.log(e_coarse / e_fine) / math.log(h_coarse / h_fine)


def fill_orders(outcomes: list[Outcome]) -> None:
    """Observed order of each run against the previous (coarser) run of its
    scheme that ran, from the step (fixed) or mean step (adaptive)."""
    previous: dict[str, Outcome] = {}
    for outcome in outcomes:
        if outcome.status != OK or outcome.is_reference:
            continue
        before = previous.get(outcome.setting.scheme)
        if before is not None:
            h0, h1 = before.step, outcome.step
            outcome.order = observed_order(before.max_error, outcome.max_error, h0, h1)
            outcome.orders = {
                name: observed_order(before.errors.get(name, math.nan), error, h0, h1)
                for name, error in outcome.errors.items()
            }
        previous[outcome.setting.scheme] = outcome


# ------------------------------------------------------------------ study


@dataclass
class Study:
    deck: str
    against: str
    target: float | None
    transients: list[dict]
    outcomes: list[Outcome]
    reference: Outcome | None
    reference_values: dict[str, float]
    quantity_names: list[str]
    notes: list[str] = field(default_factory=list)  # e.g. an output not written

    @property
    def rows(self) -> list[Outcome]:
        return [o for o in self.outcomes if not o.is_reference]


def run_study(
    deck: Path,
    *,
    schemes=DEFAULT_SCHEMES,
    steps=None,
    tolerances=None,
    points=None,
    against: str = "finest",
    reference: str | None = None,
    target: float | None = None,
    pattern: str | None = None,
    extra: dict | None = None,
    repeat: int = 1,
    warmup: bool = True,
    min_step_ratio: float = MIN_STEP_RATIO,
    progress: Callable[[Outcome], None] | None = None,
) -> Study:
    """Run the whole ladder and compare every run with the reference."""
    if against not in ("finest", "reference"):
        raise ConvergeError(f"--against {against!r}: expected finest or reference")
    base = run_in_scratch(deck)
    if base.status not in RAN:
        raise ConvergeError(f"the deck does not run as written: {_one_line(base.message)}")
    transients = [t for t in base.transients if t["steps"] > 0]
    if not transients:
        raise ConvergeError("the deck makes no DYNA_VIBRA TRAN/GENE result (tran_gene)")
    settings = ladder(schemes, steps, tolerances, points)
    ref_setting = parse_reference(reference, settings)
    warmed: set[str] = set()
    outcomes = []
    for setting in [*settings, ref_setting]:
        if warmup and setting.scheme not in warmed:  # numba loads/compiles its kernels
            run_in_scratch(deck, overrides_for(setting, transients, extra, span=20))
            warmed.add(setting.scheme)
        outcome = run_setting(
            deck,
            setting,
            transients,
            extra=extra,
            pattern=pattern,
            repeat=repeat,
            min_step_ratio=min_step_ratio,
        )
        outcome.text = setting.label(transients[0]["step"])
        outcomes.append(outcome)
        if progress is not None and setting is not ref_setting:
            progress(outcome)
    reference_run = outcomes[-1]
    reference_run.is_reference = True
    if reference_run.status != OK:
        raise ConvergeError(
            f"the reference run ({ref_setting.scheme} {ref_setting.label()}) failed: "
            f"{reference_run.message}"
        )
    ref_values = dict(reference_run.values)
    if against == "reference":
        ref_values.update(reference_values(base, pattern))
    for outcome in outcomes:
        compare(outcome, ref_values)
    fill_orders(outcomes)
    return Study(
        deck=str(deck),
        against=against,
        target=target,
        transients=transients,
        outcomes=outcomes,
        reference=reference_run,
        reference_values=ref_values,
        quantity_names=list(ref_values),
    )


def cheapest(study: Study, target: float | None = None) -> Outcome | None:
    """The run of least integration time whose max relative error meets ``target``."""
    target = study.target if target is None else target
    if target is None:
        return None
    meeting = [o for o in study.rows if o.status == OK and o.max_error <= target]
    return min(meeting, key=lambda o: (o.seconds, o.steps), default=None)


# ------------------------------------------------------------------ output


def setting_text(outcome: Outcome, study: Study) -> str:
    return outcome.text or outcome.setting.label(study.transients[0]["step"])


def _num(value: float, spec: str = ".2e") -> str:
    return (
        "-"
        if value is None or (isinstance(value, float) and math.isnan(value))
        else format(value, spec)
    )


TABLE_HEADER = (
    "scheme",
    "knob",
    "setting",
    "status",
    "integ. s",
    "steps",
    "max rel. err",
    "order",
    "worst quantity",
)


def table_rows(study: Study) -> list[tuple[str, ...]]:
    rows = []
    for o in study.rows + ([study.reference] if study.reference else []):
        rows.append(
            (
                o.setting.scheme + (" (reference)" if o.is_reference else ""),
                o.setting.knob,
                setting_text(o, study),
                o.status,
                _num(o.seconds, ".4f") if o.status == OK else "-",
                str(o.steps) if o.status == OK else "-",
                _num(o.max_error),
                _num(o.order, ".2f"),
                "-" if o.is_reference else (o.worst if o.status == OK else o.message[:140]),
            )
        )
    return rows


def format_table(study: Study) -> str:
    """The study as a text table (one row per run), then the verdict."""
    rows = [TABLE_HEADER, *table_rows(study)]
    widths = [max(len(r[i]) for r in rows) for i in range(len(TABLE_HEADER) - 1)]
    lines = []
    for number, row in enumerate(rows):
        cells = [c.ljust(w) for c, w in zip(row[:-1], widths, strict=True)] + [row[-1]]
        lines.append("  ".join(cells).rstrip())
        if number == 0:
            lines.append("  ".join("-" * w for w in widths) + "  " + "-" * 14)
    against = "the deck's VALE_REFE" if study.against == "reference" else "the reference run"
    lines.append(f"errors: max over {len(study.quantity_names)} quantities, relative to {against}")
    lines.append(verdict(study))
    lines += convergence_notes(study) + study.notes
    return "\n".join(lines)


def verdict(study: Study) -> str:
    if study.target is None:
        return "no --target given"
    best = cheapest(study)
    if best is None:
        return f"no setting meets the target {study.target:g}"
    return (
        f"cheapest setting meeting {study.target:g}: {best.setting.scheme} "
        f"{best.setting.knob}={setting_text(best, study)} "
        f"({best.seconds:.4f} s integrating, {best.steps} steps, error {best.max_error:.2e})"
    )


def convergence_notes(study: Study) -> list[str]:
    """One line per scheme whose ladder does not converge: its error at the
    finest setting is not clearly below its error at the coarsest, so the
    observed orders mean nothing (chaotic impacts give O(1) errors whose
    "orders" change sign)."""
    notes = []
    for scheme in dict.fromkeys(o.setting.scheme for o in study.rows):
        runs = [
            o
            for o in study.rows
            if o.setting.scheme == scheme and o.status == OK and not math.isnan(o.max_error)
        ]
        if len(runs) < 2:
            continue
        first, last = runs[0], runs[-1]
        if last.max_error <= max(CONVERGING_RATIO * first.max_error, NEGLIGIBLE_ERROR):
            continue
        orders = [o.order for o in runs[1:] if not math.isnan(o.order)]
        spread = f", observed orders {min(orders):.2f} to {max(orders):.2f}" if orders else ""
        knob = first.setting.knob
        notes.append(
            f"{scheme}: the ladder does not converge: the max relative error goes from "
            f"{first.max_error:.2e} ({knob}={setting_text(first, study)}) to {last.max_error:.2e} "
            f"({knob}={setting_text(last, study)}){spread}; these quantities do not settle as "
            f"the {knob} is refined, so their errors and orders are no accuracy estimate "
            f"(chaotic impacts: compare statistics of long runs, or choose quantities with "
            f"--quantities)"
        )
    return notes


def markdown_table(study: Study) -> str:
    """The same table in Markdown (for docs)."""
    rows = table_rows(study)
    head = "| " + " | ".join(TABLE_HEADER) + " |"
    rule = "|" + "|".join("---" for _ in TABLE_HEADER) + "|"
    body = ["| " + " | ".join(c.replace("|", "\\|") for c in row) + " |" for row in rows]
    return "\n".join([head, rule, *body])


CSV_COLUMNS = (
    "scheme",
    "knob",
    "setting",
    "status",
    "integration_seconds",
    "steps",
    "rejected_steps",
    "step",
    "mean_step",
    "min_step",
    "max_step",
    "checks_ok",
    "max_rel_error",
    "order",
    "worst_quantity",
    "meets_target",
    "reference_run",
    "message",
)


def write_csv(study: Study, path: Path) -> Path:
    """One row per run: the table's columns, then the value, relative error
    and observed order of each quantity."""
    best = cheapest(study)
    names = study.quantity_names
    columns = list(CSV_COLUMNS)
    for name in names:
        columns += [f"value[{name}]", f"error[{name}]", f"order[{name}]"]
    path.parent.mkdir(parents=True, exist_ok=True)
    with path.open("w", newline="", encoding="utf-8") as handle:
        writer = csv.writer(handle)
        writer.writerow(columns)
        for o in study.outcomes:
            meets = study.target is not None and o.status == OK and o.max_error <= study.target
            row = [
                o.setting.scheme,
                o.setting.knob,
                setting_text(o, study),
                o.status,
                _cell(o.seconds),
                o.steps,
                o.rejected,
                _cell(o.step),
                _cell(o.mean_step),
                _cell(o.min_step),
                _cell(o.max_step),
                o.checks,
                _cell(o.max_error),
                _cell(o.order),
                o.worst,
                "best" if o is best else ("yes" if meets else "no"),
                "yes" if o.is_reference else "no",
                o.message,
            ]
            for name in names:
                row += [
                    _cell(o.values.get(name)),
                    _cell(o.errors.get(name)),
                    _cell(o.orders.get(name)),
                ]
            writer.writerow(row)
    return path


def _cell(value) -> str:
    if value is None or (isinstance(value, float) and math.isnan(value)):
        return ""
    return repr(float(value)) if isinstance(value, float) else str(value)


def plot(study: Study, path: Path) -> Path:
    """Error against integration time and against steps (log–log), one curve
    per scheme; the target as a horizontal line."""

    FigureCanvasAgg = require("matplotlib.backends.backend_agg", PLOT_PURPOSE).FigureCanvasAgg
    Figure = require("matplotlib.figure", PLOT_PURPOSE).Figure
    figure = Figure(figsize=(10, 4.2))
    FigureCanvasAgg(figure)
    axes_time, axes_steps = figure.subplots(1, 2)
    schemes = list(dict.fromkeys(o.setting.scheme for o in study.rows))
    for scheme in schemes:
        runs = [
            o
            for o in study.rows
            if o.setting.scheme == scheme
            and o.status == OK
            and o.max_error > 0
            and not math.isnan(o.max_error)
        ]
        if not runs:
            continue
        errors = [o.max_error for o in runs]
        axes_time.loglog([max(o.seconds, 1e-6) for o in runs], errors, "o-", label=scheme)
        axes_steps.loglog([o.steps for o in runs], errors, "o-", label=scheme)
    for axes, xlabel in ((axes_time, "integration wall time (s)"), (axes_steps, "steps taken")):
        if study.target is not None:
            axes.axhline(study.target, color="grey", linestyle="--", linewidth=1, label="target")
        axes.set_xlabel(xlabel)
        axes.set_ylabel("max relative error")
        axes.grid(True, which="both", alpha=0.3)
    axes_time.legend(fontsize=8)
    figure.suptitle(f"{Path(study.deck).stem}: error against cost", fontsize=10)
    figure.tight_layout()
    path.parent.mkdir(parents=True, exist_ok=True)
    figure.savefig(path, dpi=110)
    return path


def write_outputs(study: Study, directory: Path) -> list[Path]:
    """``converge.csv``, ``converge.png``, ``converge.txt`` (the printed table)
    and ``converge.md`` (the same in Markdown) in ``directory``. Without
    matplotlib (the plot extra) the picture is skipped and a note in
    ``study.notes`` (printed with the table) says how to get it."""

    directory.mkdir(parents=True, exist_ok=True)
    csv_path = write_csv(study, directory / "converge.csv")
    try:
        picture = [plot(study, directory / "converge.png")]
    except MissingExtraError as error:
        picture = []
        study.notes.append(f"note: converge.png not drawn: {error.message}")
    text = directory / "converge.txt"
    text.write_text(format_table(study) + "\n", encoding="utf-8")
    markdown = directory / "converge.md"
    conclusions = [verdict(study), *convergence_notes(study)]
    markdown.write_text(
        markdown_table(study) + "\n\n" + "\n\n".join(conclusions) + "\n", encoding="utf-8"
    )
    return [csv_path, *picture, text, markdown]


__all__ = [
    "ConvergeError",
    "Outcome",
    "Setting",
    "Study",
    "cheapest",
    "convergence_notes",
    "format_table",
    "ladder",
    "markdown_table",
    "run_study",
    "write_outputs",
]
