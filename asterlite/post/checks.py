"""The comparison behind TEST_RESU, TEST_TABLE and TEST_FONCTION.

One tested value gives one :class:`TestRecord`. Two checks may apply:

*Reference check* (``VALE_REFE*`` given): error ``|v - ref|``, divided by
``|ref|`` when ``CRITERE='RELATIF'`` and ``ref != 0``; it holds when the error
is at most ``PRECISION`` (default 1e-3, as code_aster).

*Non-regression check* (``VALE_CALC*``, code_aster's own computed value):

- ``strict`` (code_aster's own verdict): relative error at most
  ``TOLE_MACHINE`` (default 1e-6) for ``CRITERE='RELATIF'``; absolute error at
  most ``TOLE_MACHINE`` for ``'ABSOLU'``. When ``ORDRE_GRANDEUR`` is given the
  error is measured relative to it instead (absolute error / ORDRE_GRANDEUR).
- ``ok`` (asterlite's verdict, since a different code cannot reproduce
  code_aster's round-off): the same error measure within 1e-3 (or the deck's
  TOLE_MACHINE if looser). For ``CRITERE='ABSOLU'`` without ORDRE_GRANDEUR the
  tolerance is ``max(1e-3·|VALE_CALC|, TOLE_MACHINE, 1e-6)``: relative for
  large values, absolute near zero. A zero ``VALE_CALC`` under RELATIF is
  compared absolutely with the same floor.

``record.ok`` requires both checks that apply; ``record.strict`` is ``ok``
and the strict non-regression check. Several ``VALE_CALC`` values (code_aster
accepts any of them) keep the closest. Integers and texts compare exactly
(integers also accept the reference PRECISION as an absolute tolerance);
``VALE_ABS='OUI'`` compares the absolute values of the value and of the
references (the modulus of a complex one).
"""

from __future__ import annotations

from dataclasses import dataclass, replace

import numpy as np

from asterlite.post.check_record import TestRecord

LOOSE_TOLERANCE = 1e-3
DEFAULT_TOLE_MACHINE = 1e-6
DEFAULT_PRECISION = 1e-3


@dataclass
class Expectation:
    """What a TEST_* occurrence expects of one value."""

    kind: str  # R, C, I, K
    calc: tuple = ()
    refe: tuple = ()
    precision: float = DEFAULT_PRECISION
    criterion: str = "RELATIF"  # of the VALE_CALC check
    reference: str = "NON_REGRESSION"
    ordre_grandeur: float | None = None
    tole_machine: float | None = None
    absolute_value: bool = False
    refe_criterion: str = "RELATIF"  # of the VALE_REFE check


def _tuple(value) -> tuple:
    if value is None:
        return ()
    return tuple(value) if isinstance(value, tuple | list) else (value,)


def expectation_from(kw) -> Expectation:
    """Read the VALE_* / PRECISION / CRITERE / ... keywords of an occurrence."""
    kind, calc, refe = "R", (), ()
    for candidate, suffix in (("R", ""), ("C", "_C"), ("I", "_I"), ("K", "_K")):
        calc = _tuple(kw.get("VALE_CALC" + suffix))
        refe = _tuple(kw.get("VALE_REFE" + suffix))
        if calc or refe:
            kind = candidate
            break
    precision = kw.get("PRECISION")
    # CRITERE / TOLE_MACHINE may hold two values: the VALE_CALC one, then the VALE_REFE one
    criteria = tuple(str(c) for c in _tuple(kw.get("CRITERE")) if c) or ("RELATIF",)
    tolerances = tuple(t for t in _tuple(kw.get("TOLE_MACHINE")) if t is not None)
    return Expectation(
        kind=kind,
        calc=calc,
        refe=refe,
        precision=DEFAULT_PRECISION if precision is None else float(precision),
        criterion=criteria[0],
        refe_criterion=criteria[-1],
        reference=kw.get("REFERENCE") or ("NON_REGRESSION" if not refe else "NON_DEFINI"),
        ordre_grandeur=kw.get("ORDRE_GRANDEUR"),
        tole_machine=tolerances[0] if tolerances else None,
        absolute_value=kw.get("VALE_ABS") == "OUI",
    )


@dataclass
class Comparison:
    expected: object
    error: float
    tolerance: float
    holds: bool
    scale: float = 1.0  # error = |value - expected| / scale (|expected| when relative)


def _numeric_error(value, expected, criterion: str, scale: float | None) -> float:
    diff = float(abs(value - expected))
    if scale is not None:
        return diff / scale if scale else diff
    if criterion == "RELATIF" and expected != 0:
        return diff / abs(expected)
    return diff


def compare_reference(value, exp: Expectation) -> Comparison | None:
    if not exp.refe:
        return None
    if exp.kind == "K":
        best = next((r for r in exp.refe if str(r).strip() == str(value).strip()), exp.refe[0])
        return Comparison(best, 0.0 if best == value else 1.0, 0.0, str(best).strip() == value)
    errors = [_numeric_error(value, r, exp.refe_criterion, None) for r in exp.refe]
    i = int(np.argmin(errors))
    return Comparison(exp.refe[i], errors[i], exp.precision, errors[i] <= exp.precision)


def compare_calc(value, exp: Expectation) -> tuple[Comparison, bool] | None:
    """(asterlite's comparison, strict verdict) against VALE_CALC*."""
    if not exp.calc:
        return None
    if exp.kind == "K":
        holds = any(str(c).strip() == str(value).strip() for c in exp.calc)
        return Comparison(exp.calc[0], 0.0 if holds else 1.0, 0.0, holds), holds
    machine = DEFAULT_TOLE_MACHINE if exp.tole_machine is None else float(exp.tole_machine)
    best = None
    for calc in exp.calc:
        scale = 1.0
        if exp.kind == "I":
            error = float(abs(value - calc))
            loose = strict_tol = 0.0
        elif exp.ordre_grandeur:
            error = _numeric_error(value, calc, exp.criterion, float(exp.ordre_grandeur))
            loose, strict_tol = max(LOOSE_TOLERANCE, machine), machine
            scale = abs(float(exp.ordre_grandeur)) or 1.0
        elif exp.criterion == "RELATIF" and calc != 0:
            error = _numeric_error(value, calc, "RELATIF", None)
            loose, strict_tol = max(LOOSE_TOLERANCE, machine), machine
            scale = float(abs(calc))  # complex VALE_CALC_C too
        else:
            error = float(abs(value - calc))
            loose = max(LOOSE_TOLERANCE * abs(calc), machine, DEFAULT_TOLE_MACHINE)
            strict_tol = machine
        candidate = (error > loose, error, Comparison(calc, error, loose, error <= loose, scale))
        strict = error <= strict_tol
        if best is None or candidate[:2] < best[0][:2]:
            best = (candidate, strict)
    (_, _, comparison), strict = best
    return comparison, strict


def make_record(command: str, label: str, value, exp: Expectation, location=None) -> TestRecord:
    """Compare ``value`` with an expectation and build the record."""
    if exp.absolute_value and exp.kind != "K":
        # code_aster's tresu_print takes the modulus of the value and of every
        # reference alike (a complex VALE_REFE_C is compared by its modulus)
        value = abs(value)
        exp = replace(
            exp, calc=tuple(abs(c) for c in exp.calc), refe=tuple(abs(r) for r in exp.refe)
        )
    if exp.kind == "I":
        value = int(value)
    ref = compare_reference(value, exp)
    calc = compare_calc(value, exp)
    ok = (ref is None or ref.holds) and (calc is None or calc[0].holds)
    strict = ok and (calc is None or calc[1])
    shown = ref if ref is not None else (calc[0] if calc is not None else None)
    if shown is None:
        return TestRecord(
            command, label, value, None, exp.reference, 0.0, 0.0, exp.criterion, False, False,
            location,
        )  # fmt: skip
    record = TestRecord(
        command=command,
        label=label,
        value=value,
        expected=shown.expected,
        reference=exp.reference if ref is not None else "NON_REGRESSION",
        error=float(shown.error),
        tolerance=float(shown.tolerance),
        criterion=exp.refe_criterion if ref is not None else exp.criterion,
        ok=bool(ok),
        strict=bool(strict),
        location=location,
        calc_comparison=calc[0] if calc is not None else None,
    )
    return record


def _fmt(value) -> str:
    if isinstance(value, float | np.floating):
        return f"{value:.12g}"
    if isinstance(value, complex | np.complexfloating):
        return f"({value.real:.12g}{value.imag:+.12g}j)"
    return repr(value) if isinstance(value, str) else str(value)


def describe(record: TestRecord) -> str:
    """One log line: verdict, label, value, reference and error."""
    percent = record.criterion == "RELATIF"

    def err(e):
        return f"{100 * e:.3g}%" if percent else f"{e:.3g}"

    parts = [f"{record.verdict:4s} {record.command} {record.label}: value {_fmt(record.value)}"]
    if record.expected is not None:
        parts.append(
            f"{record.reference} {_fmt(record.expected)} error {err(record.error)}"
            f" (tolerance {err(record.tolerance)})"
        )
    calc = getattr(record, "calc_comparison", None)
    if calc is not None and record.reference != "NON_REGRESSION":
        parts.append(f"VALE_CALC {_fmt(calc.expected)} error {err(calc.error)}")
    if record.ok and not record.strict:
        parts.append("(outside code_aster's TOLE_MACHINE)")
    if record.expected is None:
        parts.append("nothing to compare with (no VALE_CALC / VALE_REFE)")
    return ", ".join(parts)


def record_check(ctx, label: str, value, kw) -> TestRecord:
    """Compare, record in the session and log: the common end of TEST_*."""
    location = getattr(kw, "location", None) or ctx.location
    record = make_record(ctx.command, label, value, expectation_from(kw), location)
    ctx.session.record_test(record)
    ctx.session.log(describe(record))
    return record


def reduce_values(values: np.ndarray, type_test: str | None) -> float:
    """TYPE_TEST reduction of several values (SOMM, SOMM_ABS, MAX, MIN)."""
    values = np.asarray(values)
    match type_test:
        case "SOMM":
            return values.sum()
        case "SOMM_ABS":
            return np.abs(values).sum()
        case "MAX":
            return values.max()
        case "MIN":
            return values.min()
    raise ValueError(type_test)
