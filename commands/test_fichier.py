"""TEST_FICHIER: non-regression of a text file the run wrote, as code_aster's
test_fichier_ops: the lines matching an EXPR_IGNORE regular expression are
dropped; the reals (with an exponent, then with a decimal point) are counted
and reduced by TYPE_TEST (SOMM by default, SOMM_ABS, MAX, MIN), then the
integers left; the text left is summed by MD5. NB_VALE is checked exactly,
VALE_CALC against the reduction of the reals (CRITERE, TOLE_MACHINE),
NB_VALE_I / VALE_CALC_I against the integers (summed modulo 2147483647) and
VALE_CALC_K against the MD5 sum. code_aster's macro does not test REFERENCE /
VALE_REFE*, nor does this one.

``FICHIER='fort.N'`` is the file of logical unit N; another name is a file
of the run's output folder."""

from __future__ import annotations

import hashlib
import re
from dataclasses import replace

import numpy as np

from asterlite.fem.selection import as_tuple
from asterlite.post.checks import describe, expectation_from, make_record

# code_aster's patterns: reals with an exponent, then with a decimal point, then integers
FLOAT_EXPONENT = re.compile(r"[-+]?[0-9]{1}[0-9\.]+[eED][\-\+]{0,1}[0-9]+")
FLOAT_POINT = re.compile(r"[-+]?[0-9]+?\.[0-9]*")
INTEGER = re.compile(r"[0-9]+")
INT_MODULUS = 2147483647


def scan(text: str):
    """(reals, integers, MD5 of the text left) of the kept text."""
    reals = [s.replace("D", "E").replace("d", "e") for s in FLOAT_EXPONENT.findall(text)]
    text = FLOAT_EXPONENT.sub("", text)
    reals += FLOAT_POINT.findall(text)
    text = FLOAT_POINT.sub("", text)
    integers = [int(s) for s in INTEGER.findall(text)]
    text = INTEGER.sub("", text)
    return [float(r) for r in reals], integers, hashlib.md5(text.encode()).hexdigest()


def kept_text(ctx, kw, path) -> str:
    patterns = []
    for expression in as_tuple(kw.get("EXPR_IGNORE")):
        try:
            patterns.append(re.compile(expression))
        except re.error as exc:
            ctx.error(
                f"EXPR_IGNORE {expression!r} is no regular expression: {exc}", "EXPR_IGNORE", kw
            )
    with open(path, encoding="utf-8", errors="replace") as handle:
        lines = [line for line in handle if not any(p.search(line) for p in patterns)]
    return "".join(lines)


def reduce(values, type_test: str) -> float:
    values = np.asarray(values, dtype=float)
    if values.size == 0:
        return 0.0
    match type_test:
        case "SOMM":
            return float(values.sum())
        case "SOMM_ABS":
            return float(np.abs(values).sum())
        case "MAX":
            return float(values.max())
        case "MIN":
            return float(values.min())
    raise ValueError(type_test)


def _path(ctx, kw):
    name = str(kw["FICHIER"]).strip()
    match = re.fullmatch(r"fort\.(\d+)", name.split("/")[-1])
    path = ctx.session.output_path(int(match.group(1)) if match else name)
    if not path.is_file():
        ctx.error(f"the run wrote no file {name!r}", "FICHIER", kw)
    return path


def _check(ctx, label, value, expectation) -> None:
    record = make_record(ctx.command, label, value, expectation, ctx.location)
    ctx.session.record_test(record)
    ctx.session.log(describe(record))


def run(ctx, kw):
    # code_aster's macro reads neither of them (only VALE_CALC* are tested)
    kw.mark_used("REFERENCE", "VALE_REFE", "VALE_REFE_I", "VALE_REFE_K", "PRECISION")
    if kw.get("VALE_CALC_I") is not None and kw.get("NB_VALE_I") is None:
        ctx.error("VALE_CALC_I needs NB_VALE_I", "NB_VALE_I", kw)
    path = _path(ctx, kw)
    reals, integers, checksum = scan(kept_text(ctx, kw, path))
    type_test = kw.get("TYPE_TEST") or "SOMM"
    name = kw["FICHIER"]
    # the checked quantities: (label, value, expected, kind, tolerance from the deck?)
    checks = [(f"{name} NB_VALE", len(reals), kw["NB_VALE"], "I", False)]
    if kw.get("VALE_CALC") is not None:
        checks.append((f"{name} {type_test}", reduce(reals, type_test), kw["VALE_CALC"], "R", True))
    if kw.get("NB_VALE_I") is not None:
        checks.append((f"{name} NB_VALE_I", len(integers), kw["NB_VALE_I"], "I", False))
    if kw.get("VALE_CALC_I") is not None:
        value = int(reduce(integers, type_test)) % INT_MODULUS
        checks.append((f"{name} {type_test} of integers", value, kw["VALE_CALC_I"], "I", True))
    if kw.get("VALE_CALC_K") is not None:
        same = int(checksum == kw["VALE_CALC_K"])
        checks.append((f"{name} text MD5 {checksum}", same, 1, "I", False))
    base = expectation_from(kw)
    for label, value, expected, kind, deck_tolerance in checks:
        expectation = replace(
            base, kind=kind, calc=(expected,), refe=(), reference="NON_REGRESSION"
        )
        if not deck_tolerance:  # counts and the text are compared exactly
            expectation = replace(expectation, criterion="ABSOLU", tole_machine=0.0)
        _check(ctx, label, value, expectation)
    ctx.log(f"{path.name}: {len(reals)} reals, {len(integers)} integers, text MD5 {checksum}")
    return None
