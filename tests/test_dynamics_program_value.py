"""formula.program_value (the FORMULE evaluator of the specialised
DIFF_CENTRE loop, top of the stack in a local variable) gives run_program's
value to the last bit, for every kind of code."""

from __future__ import annotations

import numpy as np
import pytest

from asterlite.concepts.function import Formula
from asterlite.dynamics.formula import (
    STACK_DEPTH,
    formula_program,
    program_tables,
    program_value,
    run_program,
)

TEXTS = [
    ("sin(W * INST)", {"W": 190.52274033}),
    ("F0*cos(W*INST + PHI) - 3.0", {"F0": 5.0, "W": 190.5, "PHI": 0.25}),
    ("Fa*sin(2*pi*f*(INST))", {"Fa": 3.0, "f": 7.0}),
    ("-INST**2 + 3*INST - 1/(INST+1)", {}),
    ("1.0 / (INST - 0.5) + (INST - 0.5) / 0.0 * 0.0", {}),
    ("(INST > 0.3) * 2.0 + (1 if INST < 0.5 else -1)", {}),
    ("max(INST, 0.2, 0.1) + abs(INST - 0.5) + sqrt(INST) + exp(-INST) + log(1 + INST)", {}),
    ("INST % 0.3 + atan2(INST, 1) + sign(INST - 0.5) + int(3.7 * INST) + INST // 0.07", {}),
    ("INST >= 0.2 and INST <= 0.7 or not INST", {}),
    ("(2.0 if INST < 0.3 else (INST if INST < 0.6 else -INST)) * tanh(INST) ** 1.5", {}),
]


@pytest.mark.parametrize("text, extra", TEXTS)
def test_program_value_is_run_program_to_the_last_bit(text, extra):
    program = formula_program(Formula(VALE=text, NOM_PARA="INST", extra=extra))
    assert program is not None
    codes, constants = program_tables([None, program])  # row 1: rows are honoured
    stack = np.zeros(STACK_DEPTH)
    times = np.concatenate([np.linspace(-1.0, 2.0, 301), [0.0, -0.0, 0.5, 0.3]])
    for t in times:
        expected = run_program(codes, constants, 1, t, stack)
        got = program_value(codes, constants, 1, t, stack)
        assert np.array_equal(np.float64(got), np.float64(expected), equal_nan=True), (t, got)
        assert np.signbit(got) == np.signbit(expected)
