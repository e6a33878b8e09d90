"""Access to harmonic results (``dyna_harmo``, ``harm_gene``) for the
post-processing commands: which stored frequencies a command's keywords
select.

A harmonic result stores one state per frequency, in the order computed
(not necessarily increasing); FREQ / LIST_FREQ pick the stored frequency
within PRECISION (CRITERE, relative by default; absolute at 0 Hz),
NUME_ORDRE / LIST_ORDRE pick by order number, and nothing picks every state.
"""

from __future__ import annotations

import numpy as np

from asterlite.errors import CommandError
from asterlite.post.restitution import InstantSelection, as_tuple, values_of


def frequency_indices(frequencies, wanted, precision: float = 1e-6, criterion: str = "RELATIF"):
    """Index of the stored frequency nearest each wanted one; CommandError
    naming the first one without a match within the precision."""
    stored = np.asarray(frequencies, dtype=float)
    out = []
    for f in np.atleast_1d(np.asarray(wanted, dtype=float)):
        gap = np.abs(stored - f)
        k = int(np.argmin(gap))
        tolerance = precision * abs(f) if criterion == "RELATIF" and f != 0 else precision
        if gap[k] > tolerance:
            raise CommandError(
                f"no stored frequency at {f:g} Hz (PRECISION={precision:g}, "
                f"CRITERE={criterion}); stored: {stored.min():g} to {stored.max():g} Hz"
            )
        out.append(k)
    return np.asarray(out, dtype=int)


def select_frequencies(
    frequencies, order, *, nume_ordre=None, freq=None, precision=1e-6, criterion="RELATIF"
) -> InstantSelection:
    """The states chosen (no interpolation): ``times`` of the selection are
    the stored frequencies, ``order`` their NUME_ORDRE."""
    frequencies = np.asarray(frequencies, dtype=float)
    order = np.asarray(order)
    if nume_ordre is not None and len(nume_ordre):
        lookup = {int(o): i for i, o in enumerate(order)}
        absent = [int(n) for n in nume_ordre if int(n) not in lookup]
        if absent:
            raise CommandError(f"NUME_ORDRE {absent[0]} is not stored (orders 1..{order.size})")
        idx = np.array([lookup[int(n)] for n in nume_ordre], dtype=int)
    elif freq is not None:
        idx = frequency_indices(frequencies, freq, precision, criterion)
    else:
        idx = np.arange(frequencies.size)
    return InstantSelection(idx, np.zeros(idx.size), frequencies[idx].copy(), order[idx].copy())


def selection_from_keywords(ctx, kw, frequencies, order) -> InstantSelection:
    """FREQ / LIST_FREQ / NUME_ORDRE / LIST_ORDRE / TOUT_ORDRE of a command
    reading a harmonic result."""
    kw.mark_used("TOUT_ORDRE")  # every stored state: the default selection
    freq = None
    if kw.get("LIST_FREQ") is not None:
        freq = values_of(kw["LIST_FREQ"])
    elif kw.get("FREQ") is not None:
        freq = values_of(kw["FREQ"])
    nume = kw.get("NUME_ORDRE")
    if kw.get("LIST_ORDRE") is not None:
        nume = kw["LIST_ORDRE"].values
    try:
        return select_frequencies(
            frequencies,
            order,
            nume_ordre=as_tuple(nume) if nume is not None else None,
            freq=freq,
            precision=float(as_tuple(kw.get("PRECISION") or 1e-6)[0]),
            criterion=str(as_tuple(kw.get("CRITERE") or "RELATIF")[0]),
        )
    except CommandError as error:
        key = "NUME_ORDRE" if nume is not None else "FREQ"
        ctx.error(error.message, key, kw)
