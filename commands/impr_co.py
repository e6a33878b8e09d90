"""IMPR_CO: print a summary of concepts to the message log (code_aster prints
its internal JEVEUX objects; asterlite describes the concept's content)."""

from __future__ import annotations

import dataclasses

import numpy as np

from asterlite.concepts.base import Concept
from asterlite.fem.selection import as_tuple


def _describe_value(value) -> str:
    if isinstance(value, np.ndarray):
        if value.size <= 6:
            return np.array2string(value, precision=6, separator=", ")
        return f"array{value.shape} min={value.min():.6g} max={value.max():.6g}"
    if isinstance(value, Concept):
        return f"<{value.aster_type} {value.name or '?'}>"
    if isinstance(value, (list, tuple, dict)):
        return f"{type(value).__name__} of {len(value)}"
    if hasattr(value, "shape") and hasattr(value, "nnz"):
        return f"sparse{value.shape} nnz={value.nnz}"
    text = repr(value)
    return text if len(text) <= 60 else text[:57] + "..."


def describe(concept) -> list[str]:
    """Lines describing a concept: its type then its fields."""
    lines = [f"concept {concept.name or '?'} of type {concept.aster_type}"]
    printed = getattr(concept, "printed_fields", None)
    if printed is not None:
        for name, value in printed().items():
            lines.append(f"  {name}: {_describe_value(value)}")
    elif dataclasses.is_dataclass(concept):
        for f in dataclasses.fields(concept):
            lines.append(f"  {f.name}: {_describe_value(getattr(concept, f.name))}")
    return lines


def run(ctx, kw):
    concepts = []
    for occ in kw.factor("CONCEPT"):
        concepts.extend(as_tuple(occ["NOM"]))
    if kw.get("CHAINE"):
        prefix = str(kw["CHAINE"])[:8].strip()
        found = [
            v
            for name, v in ctx.session.namespace.items()
            if isinstance(v, Concept) and name.startswith(prefix)
        ]
        if not found:
            ctx.log(f"IMPR_CO: no concept matches CHAINE={kw['CHAINE']!r}")
        concepts.extend(found)
    if kw.get("TOUT") == "OUI":
        concepts.extend(v for v in ctx.session.namespace.values() if isinstance(v, Concept))
    for concept in concepts:
        for line in describe(concept):
            ctx.log(line)
    return None
