"""The Python methods decks call on results (code_aster's object API).

Concepts keep thin methods listed in their ``deck_methods`` and delegate
here: reading and writing the generalized coordinates of a ``tran_gene``
(``getDisplacementValues(idx)``...), the nonlinearity summary
(``INFO_NONL()``), and nodal fields of a physical result or a modal basis
(``getField("DEPL", nume_ordre).getValues()``).

Indices follow code_aster: a ``tran_gene``'s *time index* is the 0-based
position in its archive (``getIndexes()`` lists the NUME_ORDRE of each
position); ``getField`` takes a NUME_ORDRE.
"""

from __future__ import annotations

import sys
from collections.abc import Callable
from dataclasses import dataclass
from typing import ClassVar

import numpy as np

from asterlite.concepts.assembly import NodalField
from asterlite.concepts.mesh import Mesh
from asterlite.errors import CommandError, UnsupportedError
from asterlite.fem.lagrange_layout import (
    dualised_relations,
    full_vector,
    lagrange_coefficient,
    lagrange_layout,
)
from asterlite.harmonic.fields import derived_fields
from asterlite.post.cell_fields import result_cell_field

# Where INFO_NONL and other printing methods write: the session's message log
# once the session registers it (``set_sink``), standard output until then.
_sink: list[Callable[[str], None]] = []


def set_sink(sink: Callable[[str], None] | None) -> None:
    """Send what deck methods print to ``sink(line)`` (None: standard output)."""
    _sink.clear()
    if sink is not None:
        _sink.append(sink)


def emit(line: str) -> None:
    if _sink:
        _sink[0](line)
    else:
        sys.stdout.write(line + "\n")


# ----------------------------------------------------------------- tran_gene


def archive_position(n_archived: int, idx) -> int:
    """A 0-based time index checked against the archive length."""
    position = int(idx)
    if not 0 <= position < n_archived:
        raise CommandError(f"time index {position} is outside the archive (0..{n_archived - 1})")
    return position


def generalized_values(states: np.ndarray, idx=None) -> list[float]:
    """All states flattened instant after instant, or the state at one index."""
    states = np.asarray(states, dtype=float)
    if idx is None:
        return states.ravel().tolist()
    return states[archive_position(states.shape[0], idx)].tolist()


def set_generalized_values(states: np.ndarray, idx, values) -> None:
    """Overwrite the state at one time index (one value per mode)."""
    position = archive_position(states.shape[0], idx)
    values = np.asarray(values, dtype=float).ravel()
    if values.size != states.shape[1]:
        raise CommandError(f"{values.size} values given for {states.shape[1]} modes")
    states[position] = values


# code_aster's summary table of INFO_NONL
_RULE = "-" * 104
_HEADER = (
    " |  IND  |       TYPE        |    NO1    |    NO2    |   SST1    |"
    "    SST2   |           TITLE          |"
)


def nonlinearity_rows(shocks) -> list[list[str]]:
    """[type, title, node 1, node 2, substructure 1, substructure 2] per nonlinearity."""
    return [[s.relation, s.name, s.node_1, s.node_2 or "", "", ""] for s in shocks]


def info_nonl_lines(shocks) -> list[str]:
    """The lines INFO_NONL prints."""
    if not shocks:
        return ["Linear calculation, no nonlinearities used or can be printed."]
    lines = [_RULE, " " * 15 + "Information regarding the considered non linearities", _RULE]
    lines += [_HEADER, _RULE]
    for i, (kind, title, no1, no2, sst1, sst2) in enumerate(nonlinearity_rows(shocks), 1):
        cells = [c.strip() or "-" for c in (no1, no2, sst1, sst2)]
        lines.append(
            f" | {i:^5} | {kind:^17} | {cells[0]:^9} | {cells[1]:^9}"
            f" | {cells[2]:^9} | {cells[3]:^9} | {title:^25}"
        )
    lines.append(_RULE)
    return lines


def info_nonl(shocks):
    """Print the nonlinearity summary; return its rows (None when linear)."""
    for line in info_nonl_lines(shocks):
        emit(line)
    return nonlinearity_rows(shocks) or None


# -------------------------------------------------------------- nodal fields


@dataclass(eq=False)
class FieldValues(NodalField):
    """A nodal field taken from a result (``result.getField(...)``).

    ``getValues()`` gives one value per DOF of code_aster's numbering: with
    dualised constraints, the Lagrange multipliers too (their values from
    ``reactions``, the loads' reactions per physical DOF, and ``beta``, the
    stiffness's Lagrange coefficient: asterlite.fem.lagrange_layout), so that
    ``getPhysicalDOFs()`` of the numbering indexes the physical values.
    """

    deck_methods: ClassVar[frozenset[str]] = frozenset(
        {"getName", "getValues", "size", "norm", "getComponents"}
    )

    reactions: np.ndarray | None = None
    beta: float = 1.0

    def getValues(self):  # noqa: N802 - code_aster's names
        values = np.asarray(self.values)
        values = values.astype(complex if np.iscomplexobj(values) else float)
        if dualised_relations(self.numbering):
            values = full_vector(self.numbering, values, self.reactions, self.beta)
        return values.tolist()

    def size(self) -> int:
        return int(lagrange_layout(self.numbering).size)

    def norm(self, normType: str = "NORM_2") -> float:  # noqa: N803
        values = np.asarray(self.values, dtype=float)
        kind = normType.upper()
        if kind == "NORM_1":
            return float(np.abs(values).sum())
        if kind == "NORM_INFINITY":
            return float(np.abs(values).max(initial=0.0))
        return float(np.sqrt(values @ values))

    def getComponents(self):  # noqa: N802
        return sorted(set(self.numbering.dof_components))


def order_position(order, nume_ordre, what: str) -> int:
    """Position of a NUME_ORDRE among a result's orders."""
    matches = np.flatnonzero(np.asarray(order) == int(nume_ordre))
    if matches.size == 0:
        orders = np.asarray(order)
        span = f"{orders[0]}..{orders[-1]}" if orders.size else "none"
        raise CommandError(f"{what}: NUME_ORDRE {nume_ordre} is not stored (orders {span})")
    return int(matches[0])


def instant_position(times, instant, what: str) -> int:
    """Position of the stored instant closest to ``instant`` (relative 1e-6)."""
    times = np.asarray(times, dtype=float)
    position = int(np.argmin(np.abs(times - float(instant)))) if times.size else -1
    if position < 0 or abs(times[position] - instant) > 1e-6 * max(abs(instant), 1e-300):
        raise CommandError(f"{what}: no stored instant at {float(instant):g}")
    return position


def transient_field(result, name: str, value=None, para: str = "NUME_ORDRE") -> FieldValues:
    """``dyna_trans.getField(name, value, para)``: ``value`` is a NUME_ORDRE
    (``para='NUME_ORDRE'``, the last stored one when omitted) or an instant
    (``para='INST'``); an element field CALC_CHAMP stored comes as a
    :class:`~asterlite.post.cell_fields.FieldOnCells`."""
    name = str(name).strip().upper()
    if name not in result.fields and name in (getattr(result, "element_fields", None) or {}):
        return result_cell_field(result, name, _position(result, name, value, para))
    if name not in result.fields:
        raise CommandError(
            f"result {result.name or ''} has no field {name} (it has {', '.join(result.fields)})"
        )
    position = _position(result, name, value, para)
    field = FieldValues(result.numbering, np.array(result.fields[name][position], dtype=float))
    source = getattr(result, "modal_source", None)
    if source is not None and name in source[1] and dualised_relations(result.numbering):
        # a recombination of modes: its multipliers are those of the modes recombined
        basis, generalized = source
        modal = mode_reactions(basis)
        if modal is not None:
            reactions, field.beta = modal
            field.reactions = reactions @ np.asarray(generalized[name][position], dtype=float)
    return field


def harmonic_field(result, name: str, value=None, para: str = "NUME_ORDRE") -> FieldValues:
    """``dyna_harmo.getField(name, value, para)``: the complex nodal field at
    a NUME_ORDRE (the last one when omitted) or a frequency (``para='FREQ'``,
    relative 1e-6). Element fields of a harmonic result are not given."""
    name = str(name).strip().upper()
    if name not in result.fields:
        if name in (getattr(result, "element_fields", None) or {}):
            raise UnsupportedError(f"getField of the element field {name} of a dyna_harmo")
        raise CommandError(
            f"result {result.name or ''} has no field {name} (it has {', '.join(result.fields)})"
        )
    if value is None:
        position = len(result.order) - 1
    elif str(para).upper() == "FREQ":
        position = instant_position(result.frequencies, value, f"field {name} (FREQ)")
    elif str(para).upper() == "NUME_ORDRE":
        position = order_position(result.order, value, f"field {name}")
    else:
        raise CommandError(f"getField of a dyna_harmo: para must be NUME_ORDRE or FREQ, got {para}")
    field = FieldValues(result.numbering, np.array(result.fields[name][position], dtype=complex))
    known = getattr(result, "reactions", None)
    if known is not None and dualised_relations(result.numbering):
        # VITE and ACCE scale the whole solution, multipliers included (comdlh)
        rows, reactions = known
        frequency = np.asarray(result.frequencies, dtype=float)[position : position + 1]
        scaled = derived_fields(reactions[position : position + 1], frequency, (name,))[name]
        field.reactions = np.zeros(result.numbering.n_dofs, dtype=complex)
        field.reactions[rows] = scaled[0]
        field.beta = result.lagrange_beta
    source = getattr(result, "modal_source", None)
    if known is None and source is not None and name in source[1]:
        if dualised_relations(result.numbering):
            # a recombination of modes over all equations (harm75): the modes' multipliers
            basis, generalized = source
            modal = mode_reactions(basis)
            if modal is not None:
                reactions, field.beta = modal
                field.reactions = reactions @ np.asarray(generalized[name][position])
    return field


def field_indexes(result, name: str) -> list[int]:
    """``result.getIndexesForFieldName(name)``: the NUME_ORDRE at which the
    result stores the field (an element field CALC_CHAMP computed at some
    orders only is stored at those)."""
    name = str(name).strip().upper()
    order = result.getIndexes()
    # a modal basis holds its shapes as DEPL
    nodal = getattr(result, "fields", None) or {"DEPL": None}
    if name in nodal:
        return [int(o) for o in order]
    field = (getattr(result, "element_fields", None) or {}).get(name)
    if field is None:
        return []
    values = np.asarray(field.values)
    stored = ~np.all(np.isnan(values.reshape(values.shape[0], -1)), axis=1)
    return [int(o) for o, kept in zip(order, stored, strict=True) if kept]


def _position(result, name: str, value, para: str) -> int:
    if value is None:
        return len(result.order) - 1
    if str(para).upper() == "INST":
        return instant_position(result.times, value, f"field {name}")
    return order_position(result.order, value, f"field {name}")


def mode_field(basis, name: str, nume_ordre=1, para: str = "NUME_ORDRE") -> FieldValues:
    """``mode_meca.getField("DEPL", nume_ordre)``: the mode shape (NUME_ORDRE
    counts the modes from 1, as code_aster stores them)."""
    name = str(name).strip().upper()
    if name != "DEPL":
        raise CommandError(f"a modal basis holds DEPL fields here, not {name}")
    orders = basis.mode_numbers if str(para).upper() == "NUME_MODE" else None
    orders = np.arange(1, basis.n_modes + 1) if orders is None else orders
    position = order_position(orders, nume_ordre, "mode")
    shape = np.array(basis.shapes[:, position], dtype=float)
    field = FieldValues(basis.numbering, shape)
    if dualised_relations(basis.numbering):
        modal = mode_reactions(basis)
        if modal is not None:
            reactions, field.beta = modal
            field.reactions = reactions[:, position]
    return field


def mode_reactions(basis):
    """(the constraints' reactions (ω² M - K) φ of every mode, one column
    each; the stiffness's Lagrange coefficient) of a real dynamic modal
    basis, or None where they are not known (static or complex modes,
    matrices not kept)."""
    stiffness, mass = getattr(basis, "stiffness", None), getattr(basis, "mass", None)
    dynamic = getattr(basis, "kind", "dynamic") == "dynamic" and not np.iscomplexobj(basis.shapes)
    if not dynamic or stiffness is None or mass is None:
        return None
    cached = _MODE_REACTIONS.get("last")
    if cached is None or cached[0] is not basis:  # a deck reads fields mode after mode
        shapes = np.asarray(basis.shapes, dtype=float)
        omega2 = (2.0 * np.pi * np.asarray(basis.frequencies, dtype=float)) ** 2
        reactions = (mass.matrix @ shapes) * omega2 - stiffness.matrix @ shapes
        # the last basis only (bounded memory), held so that it stays that object
        cached = (basis, (reactions, lagrange_coefficient(stiffness.matrix)))
        _MODE_REACTIONS["last"] = cached
    return cached[1]


_MODE_REACTIONS: dict = {}


# ------------------------------------------------ tran_gene nonlinearities
# code_aster 15's Python access to a tran_gene's localized nonlinearities
# (LIST_ARCH, VARI_INTERNE, FORCE_NORMALE, FORCE_AXIALE, FORCE_RELATION):
# nonlinearities are numbered from 1 in COMPORTEMENT order, and each archives
# a fixed number of internal variables (VINT1..) per instant.

# code_aster's integer code of each relation in the result's nonlinearity
# types (sd_nl .TYPE) and its number of internal variables (NBVARINT_*)
NONLINEARITY_CODES = {
    "DIS_CHOC": 1,
    "FLAMBAGE": 2,
    "ANTI_SISM": 3,
    "DIS_VISC": 4,
    "DIS_ECRO_TRAC": 5,
    "ROTOR_FISS": 6,
    "COUPLAGE_EDYOS": 7,
    "RELA_EFFO_DEPL": 8,
    "RELA_EFFO_VITE": 9,
}
INTERNAL_VARIABLE_COUNTS = {
    "DIS_CHOC": 20,
    "FLAMBAGE": 12,
    "ANTI_SISM": 8,
    "DIS_VISC": 11,
    "DIS_ECRO_TRAC": 20,
    "ROTOR_FISS": 3,
    "RELA_EFFO_DEPL": 3,
    "RELA_EFFO_VITE": 3,
    "CHOC_ELAS_TRAC": 8,
}

# What VARI_INTERNE prints for each column (short labels, code_aster's order)
_VINT_LABELS = {
    "DIS_CHOC": (
        "F_NORMAL F_TANGE1 F_TANGE2 DXLOC_N1 DYLOC_N1 DZLOC_N1 DXLOC_N2 DYLOC_N2 DZLOC_N2 "
        "V_NORMAL V_TANGE1 V_TANGE2 IND_ADHE VINT_FR1 VINT_FR2 VINT_FR3 VINT_FR4 VINT_FR5 "
        "VINT_FR6 VINT_FR7"
    ),
    "FLAMBAGE": (
        "F_NORMAL DXLOC_N1 DYLOC_N1 DZLOC_N1 DXLOC_N2 DYLOC_N2 DZLOC_N2 V_NORMAL ENFO_PLA "
        "RIGI_P_F ENFO_MAX AMOR_P_F"
    ),
    "ANTI_SISM": "F_AXIAL DXLOC_N1 DYLOC_N1 DZLOC_N1 DXLOC_N2 DYLOC_N2 DZLOC_N2 V_NORMAL",
    "DIS_VISC": (
        "DXLOC_N1 DYLOC_N1 DZLOC_N1 DXLOC_N2 DYLOC_N2 DZLOC_N2 V_AXIALE F_AXIALE EPS_VISQ "
        "D_AXIALE PUISSANC"
    ),
    "DIS_ECRO_TRAC": (
        "DXLOC_N1 DYLOC_N1 DZLOC_N1 DXLOC_N2 DYLOC_N2 DZLOC_N2 FXLOC FYLOC FZLOC DXLOC DYLOC "
        "DZLOC PUISSANC PCUM DXPLOC DYPLOC DZPLOC FXCINE FYCINE FZCINE"
    ),
    "ROTOR_FISS": "PHI_DEGR F_TANGE1 F_TANGE2",
    "RELA_EFFO_DEPL": "DCMP_N1 FCMP_LOC IND_NONZ",
    "RELA_EFFO_VITE": "VCMP_N1 FCMP_LOC IND_NONZ",
    "CHOC_ELAS_TRAC": "F_AXIAL LONGUEUR DXLOC_N1 DYLOC_N1 DZLOC_N1 DXLOC_N2 DYLOC_N2 DZLOC_N2",
}


def archived_instants(times) -> list[float]:
    """``LIST_ARCH()``: the archived instants as a list."""
    return [float(t) for t in np.asarray(times, dtype=float)]


def nonlinearity_position(shocks, inoli) -> int:
    """The 0-based position of nonlinearity ``inoli`` (1-based; -1: the first)."""
    if not isinstance(inoli, (int, np.integer)) or isinstance(inoli, bool):
        raise CommandError(f"the nonlinearity index must be an integer, got {inoli!r}")
    if inoli == -1:
        emit("Nonlinearity index not specified, by default the first nonlinearity is considered.")
        inoli = 1
    if not shocks:
        raise CommandError("linear calculation: the result has no nonlinearity to read")
    if not 1 <= inoli <= len(shocks):
        raise CommandError(
            f"nonlinearity index {inoli}: it must lie between 1 and {len(shocks)}, "
            "the number of nonlinearities"
        )
    return int(inoli) - 1


def internal_variable_count(history) -> int:
    """How many internal variables code_aster archives for this relation."""
    count = INTERNAL_VARIABLE_COUNTS.get(history.relation)
    if count is None:
        raise CommandError(f"{history.relation}: no internal variables are archived")
    missing = [k for k in range(1, count + 1) if f"VINT{k}" not in history.fields]
    if missing:
        raise CommandError(
            f"{history.relation} {history.name}: internal variable VINT{missing[0]} is not stored"
        )
    return count


def internal_variables(history) -> np.ndarray:
    """(n_archived, n_vint): the internal variables of one nonlinearity."""
    count = internal_variable_count(history)
    columns = [np.asarray(history.fields[f"VINT{k}"], dtype=float) for k in range(1, count + 1)]
    return np.column_stack(columns)


def _print_vint_labels(history, inoli: int) -> None:
    labels = _VINT_LABELS[history.relation].split()
    rule = "-" * 104
    emit(rule)
    emit(
        f"Information regarding the saved internal variables for {history.relation} "
        f"non linearity (index={inoli})"
    )
    emit(rule)
    for start in range(0, len(labels), 8):
        chunk = labels[start : start + 8]
        emit(" | ".join(str(start + i + 1).center(10) for i in range(len(chunk))))
        emit(" | ".join(label.center(10) for label in chunk))
        emit(rule)


def vari_interne(shocks, inoli=-1, describe=True) -> np.ndarray:
    """``VARI_INTERNE(inoli)``: internal variables of nonlinearity ``inoli``,
    one row per archived instant."""
    position = nonlinearity_position(shocks, inoli)
    history = shocks[position]
    values = internal_variables(history)
    if describe:
        _print_vint_labels(history, position + 1)
    return values


def _force_column(shocks, inoli, columns: dict[str, int], what: str) -> np.ndarray:
    position = nonlinearity_position(shocks, inoli)
    history = shocks[position]
    if history.relation not in columns:
        info_nonl(shocks)
        kinds = ", ".join(columns)
        raise CommandError(
            f"nonlinearity {position + 1} is a {history.relation}: only {kinds} "
            f"nonlinearities archive {what}"
        )
    return internal_variables(history)[:, columns[history.relation]].copy()


# the internal variable holding each force, as code_aster 15 reads it
NORMAL_FORCE_COLUMNS = {"DIS_CHOC": 0, "FLAMBAGE": 0}
# DIS_ECRO_TRAC: code_aster reads column 8 (its FYLOC), kept as it does
AXIAL_FORCE_COLUMNS = {"ANTI_SISM": 0, "CHOC_ELAS_TRAC": 0, "DIS_VISC": 7, "DIS_ECRO_TRAC": 7}
RELATION_FORCE_COLUMNS = {"RELA_EFFO_DEPL": 1, "RELA_EFFO_VITE": 1}


def normal_force(shocks, inoli=-1) -> np.ndarray:
    """``FORCE_NORMALE(inoli)``: the normal force at the archived instants."""
    return _force_column(shocks, inoli, NORMAL_FORCE_COLUMNS, "a normal force")


def axial_force(shocks, inoli=-1) -> np.ndarray:
    """``FORCE_AXIALE(inoli)``: the axial force at the archived instants."""
    return _force_column(shocks, inoli, AXIAL_FORCE_COLUMNS, "an axial force")


def relation_force(shocks, inoli=-1) -> np.ndarray:
    """``FORCE_RELATION(inoli)``: the force of a RELA_EFFO_DEPL/VITE relation."""
    return _force_column(shocks, inoli, RELATION_FORCE_COLUMNS, "a relation force")


def set_result_mesh(result, mesh) -> None:
    """``result.setMesh(mesh)``: code_aster attaches the mesh to a result that
    has none and refuses another mesh than the one it has; asterlite's
    physical results always know theirs (from their DOF numbering)."""

    if not isinstance(mesh, Mesh):
        raise CommandError(f"setMesh expects a mesh, got {type(mesh).__name__}")
    if result.numbering.mesh is not mesh:
        raise CommandError("setMesh: incompatible meshes (the result is on another mesh)")
