"""What a run's checks say, told apart: reference checks and non-regression.

A ``TEST_*`` check may compare a value with two things (code_aster's
vocabulary): ``VALE_REFE``, an independent reference (an analytic formula,
another code, an experiment: ``REFERENCE='ANALYTIQUE'``...), and
``VALE_CALC``, the value code_aster (or asterlite, for the samples)
computed for the deck as written: a non-regression check. A variant of a
deck (``asterlite sweep --set MU=0.2``, ``asterlite.run(deck, MU=0.2)``)
computes something else on purpose: it is expected to fail the deck's
``VALE_CALC`` values, which belong to the deck's own settings, while its
``VALE_REFE`` checks still say whether the physics holds (when the deck
computes its references from those settings, as the samples do).

:func:`verdicts` counts both kinds, :func:`variant_note` says in words why
a variant is NOOK, naming the deck's own values of what was changed
(``summary.json`` gets both through :mod:`asterlite.report.fields`).
"""

from __future__ import annotations

import re
from pathlib import Path

from asterlite.io.input_files import read_text_or_none
from asterlite.post.check_record import TestRecord

REFE, CALC = "VALE_REFE", "VALE_CALC"


def verdicts(tests) -> dict[str, dict[str, int]]:
    """``{"VALE_REFE": {"ok": n, "total": m}, "VALE_CALC": {...}}`` over the
    comparisons the checks made (a check may make both)."""
    counts = {REFE: {"ok": 0, "total": 0}, CALC: {"ok": 0, "total": 0}}
    for test in tests:
        for kind, comparison in check_comparisons(test)["comparisons"].items():
            counts[kind]["total"] += 1
            counts[kind]["ok"] += int(bool(comparison["ok"]))
    return counts


def verdict_text(counts: dict[str, dict[str, int]], kind: str) -> str:
    """``"4/4"``, or ``"-"`` when no check made that comparison."""
    count = counts.get(kind) or {"ok": 0, "total": 0}
    return f"{count['ok']}/{count['total']}" if count["total"] else "-"


def deck_assignments(deck_files, names) -> dict[str, dict]:
    """Where the deck assigns each of ``names`` at its top level:
    ``{"MU": {"text": "MU = 0.15", "file": "x.comm", "line": 17}}`` (the first
    assignment; a name assigned only inside a block is not found)."""
    found: dict[str, dict] = {}
    wanted = set(names)
    for path in deck_files or ():
        # the run's own reader: regular files only (a FIFO would block), the
        # deck's encoding (UTF-8, declared, Windows-1252), never a byte replaced
        text = read_text_or_none(Path(path))
        if text is None:
            continue
        for number, line in enumerate(text.splitlines(), 1):
            match = re.match(r"([A-Za-z_]\w*)\s*=(?!=)\s*(.*?)\s*(#.*)?$", line)
            if match and match.group(1) in wanted and match.group(1) not in found:
                name, value = match.group(1), match.group(2)
                found[name] = {
                    "text": f"{name} = {value}",
                    "file": Path(path).name,
                    "line": number,
                }
    return found


def variant_note(tests, overrides: dict, assignments: dict) -> str:
    """Why a run with deck variables replaced is NOOK, when its VALE_CALC
    checks fail: they hold the deck's own results, not the variant's."""
    if not overrides:
        return ""
    counts = verdicts(tests)
    calc, refe = counts[CALC], counts[REFE]
    if calc["ok"] == calc["total"]:
        return ""
    changed = ", ".join(f"{name}={value!r}" for name, value in overrides.items())
    own = (
        ", ".join(f"{a['text']} ({a['file']}:{a['line']})" for a in assignments.values())
        or "the deck's own values"
    )
    text = (
        f"run with {changed} instead of {own}: the deck's VALE_CALC values are its results "
        f"for its own settings (non-regression), so a variant is expected to fail them "
        f"({verdict_text(counts, CALC)} hold)"
    )
    if refe["total"] == 0:
        return text + "; the deck has no VALE_REFE check to judge the variant's physics"
    if refe["ok"] == refe["total"]:
        return text + f"; every VALE_REFE (independent reference) check holds ({refe['ok']})"
    return text + (
        f"; {refe['total'] - refe['ok']} of {refe['total']} VALE_REFE checks fail: the "
        "variant's result departs from the deck's references (or is outside the range "
        "where they apply)"
    )


def check_comparisons(test: TestRecord) -> dict:
    """Each value a check compared with, VALE_REFE (with its reference kind)
    and VALE_CALC, with error, tolerance and verdict; ``failed`` names the
    comparisons that did not hold (``expected`` alone shows only one)."""
    shown = {
        "expected": plain_value(test.expected),
        "error": plain_value(test.error),
        "tolerance": plain_value(test.tolerance),
    }
    calc = test.calc_comparison
    comparisons = {}
    if test.expected is not None and test.reference != "NON_REGRESSION":
        holds = bool(test.error <= test.tolerance)  # the reference check shown in ``expected``
        comparisons["VALE_REFE"] = {**shown, "reference": test.reference, "ok": holds}
    if calc is not None:
        comparisons["VALE_CALC"] = {
            "expected": plain_value(calc.expected),
            "error": plain_value(calc.error),
            "tolerance": plain_value(calc.tolerance),
            "ok": bool(calc.holds),
        }
    failed = [kind for kind, comparison in comparisons.items() if not comparison["ok"]]
    return {"comparisons": comparisons, "failed": failed}


def plain_value(value):
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
