"""Round-off sensitivity: does a check's value survive a change in the last bits?

Impact dynamics can be chaotic: two runs whose arithmetic differs by one
rounding (another compiler, another BLAS, code_aster against asterlite) then
follow trajectories that part after a few impacts, and a statistic such as an
RMS normal force lands anywhere in a band. A ``VALE_CALC`` inside that band
was one draw from it; comparing another machine's draw with it at 1e-3 or
1e-6 is chance, not a measure of accuracy.

``asterlite sensitivity DECK`` reruns the deck with each transient's step
``PAS`` moved by a few units in the last place (1, -1, 2, -2... ulps: a
relative change of about 1e-16, far below any modelling or discretisation
error) and reports, per check, how far its value moves against the check's
own tolerance:

- ``stable``: every perturbed value within 1 % of the tolerance of the
  unperturbed one: the check measures the model;
- ``marginal``: the spread is a noticeable part of the tolerance;
- ``sensitive``: the spread exceeds the tolerance: whether the check passes
  depends on the last bits of the arithmetic, on any machine.

The shock statistics of the run's summary (each shock's peak normal force
and wear power) are judged the same way against 1e-3, a value that no
check tests can still be a draw of a chaotic response (stick-slip whirl);
one that stays below 1e-12 is reported ``zero`` (round-off of a quantity
that vanishes in exact arithmetic).

A reference check that also gives ``VALE_CALC`` is judged against both
comparisons (the worse verdict): its value may stay well inside a loose
``PRECISION`` while moving by more than the 1e-3 of the VALE_CALC comparison,
which then decides OK or NOOK by chance. A transient whose ``PAS_MINI`` and
``PAS_MAXI`` equal ``PAS`` (a fixed step of an adaptive scheme) has them moved
with it.

Each run is an ordinary in-process run with the ``DYNA_VIBRA`` keyword
replaced before validation (:class:`asterlite.runtime.session.KeywordOverride`),
as ``asterlite converge`` does.
"""

from __future__ import annotations

import json
import math
from collections.abc import Callable
from dataclasses import asdict, dataclass, field
from pathlib import Path

from asterlite.runtime.converge import RAN, ConvergeError, memory_cap, run_in_scratch
from asterlite.runtime.session import KeywordOverride

DEFAULT_RUNS = 8
# spread / tolerance below this: the check is insensitive to round-off
STABLE_FRACTION = 0.01
STABLE, MARGINAL, SENSITIVE = "stable", "marginal", "sensitive"


def ulp_offsets(runs: int) -> list[int]:
    """1, -1, 2, -2, ...: ``runs`` signed numbers of ulps."""
    return [(k // 2 + 1) * (1 if k % 2 == 0 else -1) for k in range(runs)]


def moved_by_ulps(value: float, ulps: int) -> float:
    """``value`` moved ``ulps`` representable doubles up (or down)."""
    target = math.inf if ulps > 0 else -math.inf
    for _ in range(abs(ulps)):
        value = math.nextafter(value, target)
    return value


def perturbed_overrides(transients: list[dict], ulps: int) -> list[KeywordOverride]:
    """One override per transient of the deck: its step moved by ``ulps``,
    and its PAS_MINI / PAS_MAXI with it when the deck sets them equal to PAS
    (a fixed step of an adaptive scheme, which PAS_MAXI < PAS would refuse)."""
    overrides = []
    for t in transients:
        moved = moved_by_ulps(t["step"], ulps)
        keywords = {"INCREMENT/PAS": moved}
        for key in ("pas_mini", "pas_maxi"):
            if t.get(key) is not None and t[key] == t["step"]:
                keywords[f"SCHEMA_TEMPS/{key.upper()}"] = moved
        overrides.append(KeywordOverride(t["command"], keywords, call=t["call"]))
    return overrides


@dataclass
class CheckSpread:
    """One check over the perturbed runs."""

    label: str
    value: float  # unperturbed
    tolerance: float
    criterion: str  # RELATIF or ABSOLU: how the tolerance reads
    values: list[float] = field(default_factory=list)  # one per perturbed run
    passes: list[bool] = field(default_factory=list)
    verdict_unperturbed: bool = False
    # a reference check's VALE_CALC comparison (asterlite's OK tolerance, 1e-3
    # relative by default, and the scale its error is divided by), or None
    calc_tolerance: float | None = None
    calc_scale: float = 1.0

    def _departure(self) -> float:
        return max(abs(v - self.value) for v in self.values) if self.values else math.nan

    @property
    def spread(self) -> float:
        """Largest departure from the unperturbed value, measured as the
        tolerance is (relative to the value for RELATIF)."""
        departure = self._departure()
        if self.criterion == "RELATIF" and math.isfinite(departure):
            scale = abs(self.value)
            return departure / scale if scale > 0 else (0.0 if departure == 0 else math.inf)
        return departure

    @property
    def calc_spread(self) -> float | None:
        """The departure measured as the VALE_CALC comparison is, or None."""
        if self.calc_tolerance is None:
            return None
        return self._departure() / self.calc_scale if self.calc_scale > 0 else math.inf

    @staticmethod
    def _classify(spread: float, tolerance: float) -> str:
        if not math.isfinite(spread) or tolerance <= 0:
            return SENSITIVE if spread and spread > 0 else STABLE
        if spread <= STABLE_FRACTION * tolerance:
            return STABLE
        return SENSITIVE if spread > tolerance else MARGINAL

    @property
    def classification(self) -> str:
        """The worse of the verdicts against the check's own tolerance and,
        for a reference check that also gives VALE_CALC, against the
        VALE_CALC comparison (whose spread can decide OK / NOOK alone)."""
        own = self._classify(self.spread, self.tolerance)
        calc = self.calc_spread
        if calc is None:
            return own
        other = self._classify(calc, self.calc_tolerance)
        order = (STABLE, MARGINAL, SENSITIVE)
        return max(own, other, key=order.index)


# shock statistics: the relative spread is judged against asterlite's VALE_CALC
# tolerance; a value below ZERO_FLOOR (N or W) is zero in exact arithmetic
SHOCK_QUANTITIES = ("max_FN", "wear_power")
SHOCK_TOLERANCE = 1.0e-3
ZERO_FLOOR = 1.0e-12
ZERO = "zero"


@dataclass
class ShockSpread:
    """A shock statistic of the run's summary (``RunReport.shocks``) over the
    perturbed runs: a quantity no check tests may still be a draw."""

    label: str  # result/shock:quantity
    value: float
    values: list[float] = field(default_factory=list)

    @property
    def spread(self) -> float:
        if not self.values:
            return math.nan
        departure = max(abs(v - self.value) for v in self.values)
        scale = max(abs(self.value), *(abs(v) for v in self.values))
        return departure / scale if scale > 0 else 0.0

    @property
    def classification(self) -> str:
        """``zero`` when every value is below ZERO_FLOOR (round-off of a
        quantity that vanishes in exact arithmetic: a planar orbit's wear),
        else as a check of relative tolerance SHOCK_TOLERANCE."""
        if max([abs(self.value), *(abs(v) for v in self.values)]) < ZERO_FLOOR:
            return ZERO
        return CheckSpread._classify(self.spread, SHOCK_TOLERANCE)


@dataclass
class Sensitivity:
    deck: str
    offsets: list[int]
    checks: list[CheckSpread]
    failed_runs: list[str] = field(default_factory=list)
    shocks: list[ShockSpread] = field(default_factory=list)

    def sensitive(self) -> list[CheckSpread]:
        return [c for c in self.checks if c.classification == SENSITIVE]

    def sensitive_shocks(self) -> list[ShockSpread]:
        return [c for c in self.shocks if c.classification == SENSITIVE]


def _shock_values(report) -> dict[str, float]:
    out = {}
    for shock in report.shocks:
        for quantity in SHOCK_QUANTITIES:
            value = shock.get(quantity)
            if isinstance(value, int | float) and math.isfinite(value):
                out[f"{shock.get('result')}/{shock.get('shock')}:{quantity}"] = float(value)
    return out


def _numeric_checks(report) -> list:
    checks = []
    for test in report.tests:
        if isinstance(test.value, bool):
            continue
        try:
            value = float(test.value)
        except (TypeError, ValueError):
            continue  # text and complex checks have no spread to measure
        if math.isfinite(value) and test.expected is not None:
            checks.append((test, value))
    return checks


def _check_spread(test, value: float) -> CheckSpread:
    spread = CheckSpread(test.label, value, test.tolerance, test.criterion)
    spread.verdict_unperturbed = test.ok
    calc = getattr(test, "calc_comparison", None)
    if calc is not None and test.reference != "NON_REGRESSION":
        spread.calc_tolerance = float(calc.tolerance)
        spread.calc_scale = float(getattr(calc, "scale", 1.0))
    return spread


def no_checks_text(report) -> str:
    """Why there is nothing to measure, and what to do."""
    why = (
        "the deck has no TEST_* check"
        if not report.tests
        else f"none of the deck's {len(report.tests)} TEST_* checks has a finite real value"
    )
    return (
        f"{why}: sensitivity measures how far each check's value moves when the step "
        "moves by a few ulps, so it needs checks on the quantities that matter "
        "(TEST_RESU on RESU_GENE or REST_GENE_PHYS values, TEST_TABLE on POST_DYNA_MODA_T "
        "statistics, TEST_FONCTION on RECU_FONCTION histories, with VALE_CALC set to this "
        "run's value); to compare the transients' histories across steps and schemes "
        "without checks, use asterlite converge"
    )


def run_sensitivity(
    deck: Path,
    runs: int = DEFAULT_RUNS,
    progress: Callable[[int, object], None] | None = None,
) -> Sensitivity:
    """Run the deck once as written, then ``runs`` times with perturbed steps."""
    if runs < 1:
        raise ConvergeError(f"--runs {runs}: at least one perturbed run is needed")
    base = run_in_scratch(deck)
    if base.status not in RAN:
        raise ConvergeError(f"the deck does not run as written: {base.message}")
    transients = [t for t in base.transients if t["steps"] > 0]
    if not transients:
        raise ConvergeError("the deck makes no DYNA_VIBRA TRAN/GENE result (tran_gene)")
    spreads = [_check_spread(t, v) for t, v in _numeric_checks(base)]
    shock_spreads = {k: ShockSpread(k, v) for k, v in _shock_values(base).items()}
    if not spreads:
        raise ConvergeError(no_checks_text(base))
    offsets = ulp_offsets(runs)
    failed = []
    for ulps in offsets:
        report = run_in_scratch(deck, perturbed_overrides(transients, ulps))
        if progress is not None:
            progress(ulps, report)
        if report.status not in RAN:
            failed.append(f"{ulps:+d} ulp: {report.status} {report.message}")
            continue
        for key, value in _shock_values(report).items():
            if key in shock_spreads:
                shock_spreads[key].values.append(value)
        found = _numeric_checks(report)
        if len(found) != len(spreads):
            failed.append(f"{ulps:+d} ulp: {len(found)} checks instead of {len(spreads)}")
            continue
        for spread, (test, value) in zip(spreads, found, strict=True):
            spread.values.append(value)
            spread.passes.append(bool(test.ok))
    return Sensitivity(str(deck), offsets, spreads, failed, list(shock_spreads.values()))


def format_table(study: Sensitivity) -> str:
    lines = [
        f"round-off sensitivity of {study.deck}: step PAS moved by "
        + ", ".join(f"{u:+d}" for u in study.offsets)
        + " ulp",
    ]
    if study.checks:
        lines.append(
            f"{'check':<60} {'value':>14} {'spread':>9} {'tolerance':>9} {'pass':>6}  verdict"
        )
    for check in study.checks:
        passed = sum(check.passes) + int(check.verdict_unperturbed)
        lines.append(
            f"{check.label[:60]:<60} {check.value:>14.8g} {check.spread:>9.2e} "
            f"{check.tolerance:>9.2e} {passed:>3}/{len(check.passes) + 1:<2}  "
            f"{check.classification}"
        )
        if check.calc_spread is not None:
            lines.append(
                f"{'  its VALE_CALC comparison':<60} {'':>14} {check.calc_spread:>9.2e} "
                f"{check.calc_tolerance:>9.2e}"
            )
    if study.shocks:
        lines.append(f"{'shock statistic':<60} {'value':>14} {'spread':>9} {'tolerance':>9}")
        for shock in study.shocks:
            lines.append(
                f"{shock.label[:60]:<60} {shock.value:>14.8g} {shock.spread:>9.2e} "
                f"{SHOCK_TOLERANCE:>9.2e}         {shock.classification}"
            )
    for failure in study.failed_runs:
        lines.append(f"run failed: {failure}")
    chaotic = study.sensitive_shocks()
    if chaotic:
        lines.append(
            f"{len(chaotic)} shock statistic(s) move by more than 1e-3 under a last-bit change: "
            "the response is chaotic there, judge it by its spread (or run an ensemble), "
            "not by one run's value"
        )
    if any(c.classification == ZERO for c in study.shocks):
        lines.append(
            "'zero': round-off of a quantity that vanishes in exact arithmetic (e.g. the wear "
            "of a planar orbit); whether another code's round-off grows there depends on the "
            "stability of that motion, not on the step"
        )
    sensitive = study.sensitive()
    if sensitive:
        lines.append(
            f"{len(sensitive)} check(s) move by more than their tolerance under a last-bit "
            "change: their verdict is not reproducible on any machine"
        )
    return "\n".join(lines)


def write_json(study: Sensitivity, directory: Path) -> Path:
    directory.mkdir(parents=True, exist_ok=True)
    path = directory / "sensitivity.json"
    rows = []
    for check in study.checks:
        row = asdict(check)
        row["spread"] = check.spread
        row["calc_spread"] = check.calc_spread
        row["classification"] = check.classification
        rows.append(row)
    payload = {"deck": study.deck, "offsets_ulp": study.offsets, "checks": rows}
    payload["failed_runs"] = study.failed_runs
    payload["shocks"] = [
        {**asdict(c), "spread": c.spread, "classification": c.classification} for c in study.shocks
    ]
    path.write_text(json.dumps(payload, indent=1))
    return path


__all__ = [
    "memory_cap",
    "run_sensitivity",
    "format_table",
    "write_json",
    "Sensitivity",
    "ShockSpread",
]
