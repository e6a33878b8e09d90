"""One ``TEST_*`` verdict, as the checks of :mod:`asterlite.post.checks`
make it and the run records, prints and summarises it.

Kept apart from the checks so that the run can hold records without
loading numpy (``asterlite check`` starts without it).
"""

from __future__ import annotations

from dataclasses import dataclass
from typing import Any

from asterlite.errors import Location


@dataclass
class TestRecord:
    """One ``TEST_*`` check: what was compared and whether it held.

    ``ok`` is the verdict asterlite uses (reference checks at the deck's
    PRECISION, VALE_CALC checks within 1e-3 relative unless the deck sets
    a tighter/looser criterion); ``strict`` says whether it also holds at
    code_aster's own tolerance (TOLE_MACHINE, 1e-6 by default).
    """

    command: str  # TEST_RESU, TEST_TABLE, TEST_FONCTION
    label: str  # what was tested, e.g. "RESU[1] DYNATRA1 DEPL NO1 DY ordre 1"
    value: Any
    expected: Any
    reference: str  # "ANALYTIQUE", "SOURCE_EXTERNE", "NON_REGRESSION", "AUTRE_ASTER", ...
    error: float
    tolerance: float
    criterion: str  # RELATIF / ABSOLU
    ok: bool
    strict: bool = True
    location: Location | None = None
    # the VALE_CALC comparison when a reference check is shown in ``expected``
    calc_comparison: Any = None

    @property
    def verdict(self) -> str:
        return "OK" if self.ok else "NOOK"
