"""The step and depth budget one Evaluator shares between interpreted and
compiled deck code.

Every loop iteration, comprehension item and deck function call is one
step. ``steps`` counts them; compiled code increments it inline and calls
:meth:`StepBudget.check` only when it reaches ``next_check``, which is the
next multiple of 256 (when the wall-clock deadline is looked at) or the
step past the limit, whichever comes first: the same checks, at the same
steps, as a check at every step.
"""

from __future__ import annotations

from time import monotonic

from asterlite.lang import limits as guards
from asterlite.lang.limits import Limits

DEADLINE_PERIOD = 256  # steps between two looks at the clock


class StepBudget:
    __slots__ = ("steps", "next_check", "depth", "max_steps", "max_depth", "seconds", "deadline")

    def __init__(self, limits: Limits):
        self.steps = 0
        self.depth = 0  # nested deck function calls
        self.max_steps = limits.max_loop_iterations
        self.max_depth = limits.max_call_depth
        self.seconds = limits.max_seconds
        self.deadline = None if self.seconds is None else monotonic() + self.seconds
        self.next_check = self._next_check()

    def step(self) -> None:
        self.steps += 1
        if self.steps >= self.next_check:
            self.check()

    def check(self) -> None:
        """Called when ``steps`` reaches ``next_check``."""
        steps = self.steps
        if steps > self.max_steps:
            raise guards.exceeded("loop iterations and calls", self.max_steps)
        if self.deadline is not None and steps % DEADLINE_PERIOD == 0:
            if monotonic() > self.deadline:
                raise guards.exceeded("seconds of deck evaluation", self.seconds)
        self.next_check = self._next_check()

    def _next_check(self) -> int:
        following = self.steps - self.steps % DEADLINE_PERIOD + DEADLINE_PERIOD
        return min(following, self.max_steps + 1)

    def too_deep(self) -> None:
        raise guards.exceeded("depth of nested function calls", self.max_depth)
