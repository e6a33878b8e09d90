"""DYNA_VIBRA/IMPRESSION/UNITE_DIS_VISC and UNITE_DIS_ECRO_TRAC: the history
of each DIS_VISC / DIS_ECRO_TRAC relation written to a logical unit.

code_aster (mdidisvisc, mdidisisot, called once the time loop is over)
writes, for every relation of that kind in the order of the
nonlinearities, a block read from the result's archived internal
variables: four comment lines (``#``, a dashed rule, ``#RESULTAT name``,
``#DIS_VISC    rank node_1 node_2``), a line of column names (``1X,A18``
each), then one row per archived instant (``1X,1PE18.10E3`` each). The
file is appended to when it already exists, so two runs writing the same
unit leave two blocks that LIRE_FONCTION reads with INDIC_PARA=[1, .] and
[2, .]. With ``reuse=``, the whole history of the result is written.

Nothing here runs per time step: the values are the internal variables
the compiled time loop archived (``ShockHistory.fields['VINTn']``).
"""

from __future__ import annotations

import math
import shutil
from dataclasses import dataclass

import numpy as np

from asterlite.dynamics.laws import dis_ecro_trac as ECRO
from asterlite.dynamics.laws import dis_visc as VISC

FIELD_WIDTH = 18
NAME_WIDTH = 8  # code_aster's node and result names are 8 characters


@dataclass(frozen=True)
class HistoryLayout:
    """Columns of one relation's history: their names and the internal
    variable (0-based, in the archived layout) each one prints."""

    relation: str
    columns: tuple[str, ...]  # after INST
    vint: tuple[int, ...]


LAYOUTS = {
    "DIS_VISC": HistoryLayout(
        "DIS_VISC",
        ("FORCE", "DEPLVISC", "DEPL", "PUISS"),
        (VISC.V_FORCE, VISC.V_EPS_VISC, VISC.V_EPS, VISC.V_DISSIP),
    ),
    # force and displacement paired per direction, then the dissipated energy
    "DIS_ECRO_TRAC": HistoryLayout(
        "DIS_ECRO_TRAC",
        ("FX", "UX", "FY", "UY", "FZ", "UZ", "PUISS"),
        (
            ECRO.V_FORCE,
            ECRO.V_DEPL,
            ECRO.V_FORCE + 1,
            ECRO.V_DEPL + 1,
            ECRO.V_FORCE + 2,
            ECRO.V_DEPL + 2,
            ECRO.V_DISSIP,
        ),
    ),
}

# IMPRESSION keyword -> relation it prints
UNIT_KEYWORDS = {"UNITE_DIS_VISC": "DIS_VISC", "UNITE_DIS_ECRO_TRAC": "DIS_ECRO_TRAC"}


def fortran_e(value: float, digits: int = 10, exponent_digits: int = 3, letter: str = "E") -> str:
    """``value`` as Fortran's 1PEw.dEe (one digit before the point), unpadded."""
    if not math.isfinite(value):
        return "NaN" if math.isnan(value) else ("Infinity" if value > 0 else "-Infinity")
    mantissa, _, exponent = f"{value:.{digits}E}".partition("E")
    power = int(exponent)
    sign = "-" if power < 0 else "+"
    return f"{mantissa}{letter}{sign}{abs(power):0{exponent_digits}d}"


def history_rows(times: np.ndarray, columns: list[np.ndarray]) -> list[str]:
    """One line per archived instant: INST then the columns (1X,1PE18.10E3)."""
    table = np.column_stack([np.asarray(times, dtype=float)] + [np.asarray(c) for c in columns])
    return ["".join(" " + fortran_e(float(x)).rjust(FIELD_WIDTH) for x in row) for row in table]


def block_header(result_name: str, relation: str, rank: int, node_1, node_2, columns) -> list[str]:
    names = ("INST",) + tuple(columns)
    return [
        "#",
        "#" + "-" * 50,
        "#RESULTAT " + fixed_name(result_name),
        f"#{relation} {rank:5d} {fixed_name(node_1)} {fixed_name(node_2)}",
        "".join(" " + name.rjust(FIELD_WIDTH) for name in names),
    ]


def fixed_name(name) -> str:
    """A code_aster K8 name: cut or blank-padded to 8 characters."""
    return str(name or "")[:NAME_WIDTH].ljust(NAME_WIDTH)


def history_lines(result, relation: str, result_name: str) -> list[str]:
    """Every block of ``relation`` in a TranGene, in the order of the
    nonlinearities (the rank counts all of them, as code_aster does)."""
    layout = LAYOUTS[relation]
    lines = []
    for rank, history in enumerate(result.shocks, start=1):
        if history.relation != relation:
            continue
        columns = [history.fields[f"VINT{i + 1}"] for i in layout.vint]
        lines += block_header(
            result_name, relation, rank, history.node_1, history.node_2, layout.columns
        )
        lines += history_rows(result.times, columns)
    return lines


def count_relations(result, relation: str) -> int:
    return sum(1 for history in result.shocks if history.relation == relation)


def append_to_unit(session, unit: int, lines: list[str]):
    """Append ``lines`` to logical ``unit`` the way code_aster opens it: the
    file already written in this run (or the input file the run maps to
    that unit, copied first) is continued, otherwise a new one is made."""
    first_write = unit not in session.output_units
    path = session.output_path(unit)
    if first_write and unit in session.run.units and not path.exists():
        shutil.copyfile(session.run.units[unit], path)
    with open(path, "a", encoding="utf-8") as stream:
        stream.write("\n".join(lines) + "\n")
    return path


def write_histories(session, result, result_name: str, requests: dict[str, int]) -> list[str]:
    """Write the histories asked for (keyword -> unit) in code_aster's order
    (DIS_VISC, then DIS_ECRO_TRAC); returns one log line per request."""
    notes = []
    for keyword, relation in UNIT_KEYWORDS.items():
        unit = requests.get(keyword)
        if unit is None:
            continue
        count = count_relations(result, relation)
        if count == 0:  # code_aster opens nothing when the run has no such relation
            notes.append(f"IMPRESSION/{keyword}={unit}: no {relation} relation, nothing written")
            continue
        lines = history_lines(result, relation, result_name)
        path = append_to_unit(session, int(unit), lines)
        notes.append(
            f"IMPRESSION/{keyword}: history of {count} {relation} relation(s), "
            f"{len(result.times)} archived instants, appended to unit {unit} ({path.name})"
        )
    return notes


__all__ = ["LAYOUTS", "UNIT_KEYWORDS", "fortran_e", "history_lines", "write_histories"]
