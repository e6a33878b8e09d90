"""Harmonic response: complex amplitudes of a linear structure driven at
given frequencies (code_aster's DYNA_VIBRA TYPE_CALCUL='HARM', ``comdlh``).

For each frequency f (ω = 2πf) the amplitude u solves

    (K + iω C - ω² M) u = F(f),   F(f) = Σ_k c_k(f) F_k,

K possibly complex (hysteretic damping: K (1 + iη)). Velocity and
acceleration are iω u and -ω² u. This room never reads a keyword: the
command (``commands/dyna_vibra_harm.py``) builds a :class:`HarmonicLoad`
list and the matrices, then calls :func:`modal.solve` (generalized basis,
dense, all frequencies in batches) or :func:`physical.solve` (assembled
sparse matrices under kinematic relations, one factorisation per
frequency).
"""

from asterlite.harmonic.fields import derived_fields
from asterlite.harmonic.loads import HarmonicLoad, load_matrix

__all__ = ["HarmonicLoad", "derived_fields", "load_matrix"]
