"""Nodal fields taken from results and combined (CREA_CHAMP EXTR / ASSE / COMB).

A result is read as a stack of nodal fields: ``field_stack(result, name)``
gives (numbering, values (n_fields, n_dofs), access) where ``access`` holds
what selects a field (NUME_ORDRE, INST, NUME_MODE, FREQ, NOM_CAS, NOEUD_CMP).
"""

from __future__ import annotations

import numpy as np

from asterlite.concepts.modes import ModeResult, MultElasResult
from asterlite.errors import UnsupportedError

# element fields code_aster's command stores in its result unasked
# (MECA_STATIQUE: OPTION='SIEF_ELGA' by default), by result class
_STORED_BY_CODE_ASTER = {"evol_elas": ("SIEF_ELGA",)}


class FieldError(ValueError):
    pass


def field_stack(result, name: str):
    if isinstance(result, ModeResult):
        if name != "DEPL":
            raise FieldError(f"a modal basis holds DEPL only, not {name}")
        n = result.n_modes
        access = {
            "NUME_ORDRE": np.arange(1, n + 1),
            "NUME_MODE": result.mode_numbers,
            "FREQ": np.asarray(result.frequencies, dtype=float),
            "NOEUD_CMP": np.asarray(result.mode_labels or [""] * n, dtype=object),
        }
        return result.numbering, np.asarray(result.shapes).T, access
    if isinstance(result, MultElasResult):
        if name != "DEPL":
            raise FieldError(f"a mult_elas result holds DEPL only, not {name}")
        access = {
            "NUME_ORDRE": np.arange(1, result.n_cases + 1),
            "NOM_CAS": np.asarray(result.case_names, dtype=object),
        }
        return result.numbering, np.asarray(result.fields).T, access
    fields = getattr(result, "fields", None)
    numbering = getattr(result, "numbering", None)
    if isinstance(fields, dict) and numbering is not None and hasattr(result, "frequencies"):
        # a dyna_harmo: complex fields, one per frequency
        if name not in fields:
            raise FieldError(f"the result has no field {name} (it has {', '.join(fields)})")
        access = {
            "NUME_ORDRE": np.asarray(result.order),
            "FREQ": np.asarray(result.frequencies, dtype=float),
        }
        return numbering, np.asarray(fields[name]), access
    if isinstance(fields, dict) and numbering is not None:
        if name not in fields:
            raise FieldError(f"the result has no field {name} (it has {', '.join(fields)})")
        values = np.asarray(fields[name], dtype=float)
        access = {
            "NUME_ORDRE": np.asarray(getattr(result, "order", np.arange(1, len(values) + 1))),
            "INST": np.asarray(getattr(result, "times", np.zeros(len(values))), dtype=float),
        }
        return numbering, values, access
    raise FieldError(f"cannot extract nodal fields from a {type(result).__name__}")


def match_real(available: np.ndarray, value: float, precision: float, criterion: str) -> int:
    """Index of the stored parameter equal to ``value`` within the tolerance."""
    available = np.asarray(available, dtype=float)
    if available.size == 0:
        raise FieldError("the result is empty")
    k = int(np.argmin(np.abs(available - value)))
    tol = precision * (abs(value) if criterion == "RELATIF" else 1.0)
    if abs(available[k] - value) > max(tol, 0.0) and available[k] != value:
        raise FieldError(f"no field at {value:g} (nearest {available[k]:g})")
    return k


def interpolate(times: np.ndarray, values: np.ndarray, t: float) -> np.ndarray:
    """Linear interpolation in time of a stack of fields (INTERPOL='LIN')."""
    times = np.asarray(times, dtype=float)
    if t < times[0] or t > times[-1]:
        raise FieldError(f"instant {t:g} outside [{times[0]:g}, {times[-1]:g}]")
    k = int(np.clip(np.searchsorted(times, t) - 1, 0, len(times) - 2))
    w = (t - times[k]) / (times[k + 1] - times[k])
    return (1.0 - w) * values[k] + w * values[k + 1]


def extreme_over(values: np.ndarray, kind: str, what: str, params: np.ndarray) -> np.ndarray:
    """Per-DOF extreme over the stack (TYPE_MAXI / TYPE_RESU of CREA_CHAMP EXTR)."""
    if kind == "MAXI":
        idx = np.argmax(values, axis=0)
    elif kind == "MINI":
        idx = np.argmin(values, axis=0)
    elif kind == "MAXI_ABS":
        idx = np.argmax(np.abs(values), axis=0)
    elif kind == "MINI_ABS":
        idx = np.argmin(np.abs(values), axis=0)
    else:
        raise FieldError(f"TYPE_MAXI={kind!r} on a nodal field")
    picked = values[idx, np.arange(values.shape[1])]
    if what == "VALE":
        return picked
    if what == "VALE_ABS":
        return np.abs(picked)
    return np.asarray(params, dtype=float)[idx]


def element_field_stack(result, name: str):
    """(ElementField, access) of an ELNO/ELGA field CALC_CHAMP stored on a
    result (``result.element_fields[name]``, values (n_orders, n_cells,
    n_points, n_components)); ``access`` as :func:`field_stack`'s."""
    fields = getattr(result, "element_fields", None) or {}
    kind = (getattr(result, "aster_types", None) or ("",))[0]
    if name not in fields and name in _STORED_BY_CODE_ASTER.get(kind, ()):
        raise UnsupportedError(
            f"{name} of an {kind} result: code_aster stores it there by "
            "default; asterlite computes it only through CALC_CHAMP"
        )
    if name not in fields:
        known = ", ".join(fields) or "none"
        raise FieldError(
            f"the result has no element field {name} (computed: {known}; use CALC_CHAMP first)"
        )
    field = fields[name]
    if field.sub_points > 1:
        raise UnsupportedError(f"{name} on sub-points (multifibre beams) as a field")
    count = field.values.shape[0]
    order = getattr(result, "order", None)
    times = getattr(result, "times", None)
    access = {"NUME_ORDRE": np.asarray(order if order is not None else np.arange(1, count + 1))}
    if times is not None:
        access["INST"] = np.asarray(times, dtype=float)
    if isinstance(result, ModeResult):
        access["NUME_MODE"] = result.mode_numbers
        access["FREQ"] = np.asarray(result.frequencies, dtype=float)
    return field, access


def element_extreme(values: np.ndarray, kind: str, what: str, params) -> np.ndarray:
    """:func:`extreme_over` applied entry by entry to a stack of element
    fields (n_orders, n_cells, n_points, n_components)."""
    values = np.asarray(values, dtype=float)
    flat = values.reshape(values.shape[0], -1)
    return extreme_over(flat, kind, what, params).reshape(values.shape[1:])


TRANSLATIONS = ("DX", "DY", "DZ")
NORM_TRAN_COMPONENTS = ("DX", "DY", "DZ", "DRX", "DRY", "DRZ")


def norm_tran_extreme(numbering, values: np.ndarray, what: str, params) -> np.ndarray:
    """CREA_CHAMP EXTR TYPE_MAXI='NORM_TRAN' over a stack of nodal fields
    (n_fields, n_dofs): at each node, the field where the translation norm
    sqrt(DX² + DY² + DZ²) is largest (the first such field on ties; missing
    translations count as 0). TYPE_RESU 'VALE' gives that field's DX..DRZ,
    'INST' / 'NUME_ORDRE' puts ``params`` of that field in DX..DRZ; other
    components keep the first field's values, as in code_aster. Nodes
    without translations keep the first field's values."""
    values = np.asarray(values, dtype=float)
    if values.ndim != 2 or values.shape[0] == 0:
        raise FieldError("NORM_TRAN needs at least one stored nodal field")
    out = values[0].copy()
    by_node: dict[int, dict[str, int]] = {}
    for row, (node, comp) in enumerate(numbering.dofs):
        if comp in NORM_TRAN_COMPONENTS:
            by_node.setdefault(int(node), {})[comp] = row
    params = np.asarray(params, dtype=float)
    for rows in by_node.values():
        translation = [rows[c] for c in TRANSLATIONS if c in rows]
        if not translation:
            continue
        norms = np.sqrt(np.sum(values[:, translation] ** 2, axis=1))
        best = int(np.argmax(norms))  # first index of the maximum
        picked = list(rows.values())
        if what == "VALE":
            out[picked] = values[best, picked]
        else:
            out[picked] = params[best]
    return out
