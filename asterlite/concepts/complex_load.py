"""A mechanical load with complex values (``AFFE_CHAR_MECA_C``).

It is a MechanicalLoad holding the real parts (relations, nodal forces and
distributed loads as AFFE_CHAR_MECA builds them), plus ``imaginary``, the
same load built from the imaginary parts. Loads are linear in their values,
so the complex nodal terms are ``real + 1j * imaginary`` term by term; only a
computation on complex values (a harmonic response) may use them.
"""

from __future__ import annotations

from dataclasses import dataclass

from asterlite.concepts.assembly import MechanicalLoad


@dataclass(eq=False)
class ComplexMechanicalLoad(MechanicalLoad):
    """``AFFE_CHAR_MECA_C`` result: the real parts, and the imaginary ones."""

    imaginary: MechanicalLoad | None = None
