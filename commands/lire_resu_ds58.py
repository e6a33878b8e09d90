"""LIRE_RESU FORMAT='IDEAS_DS58': measured time histories or frequency
responses (universal file datasets 58) into a DYNA_TRANS or a DYNA_HARMO,
as code_aster's lect58 builds them.

Each dataset is one sensor: a node and a direction (±1, ±2, ±3; a negative
direction changes the sign of the values). Displacements, velocities and
accelerations become components D1, D2, D3 (the direction's number) with the
sensor's orientation in D1X..D3Z: the global axis of that number, or the
DIRECTION of a REDEFI_ORIENT occurrence naming the node and that CODE_DIR.
Stresses and strains fill SIXX..SIYZ / EPXX..EPYZ by the direction's number
(REDEFI_ORIENT does not apply to them: code_aster warns and ignores it).
Orders are the abscissas' ranks from 1; INST / FREQ / NUME_ORDRE and their
lists choose among them.
"""

from __future__ import annotations

import numpy as np

from asterlite.concepts.assembly import DofNumbering
from asterlite.concepts.harmonic import DynaHarmo
from asterlite.concepts.transient import DynaTrans
from asterlite.io.ideas_ds58 import ORDINATE_KIND, Ds58ReadError, read_datasets_58
from asterlite.post.restitution import as_tuple

_DIRECTIONAL = ("D1", "D2", "D3", "D1X", "D1Y", "D1Z", "D2X", "D2Y", "D2Z", "D3X", "D3Y", "D3Z")
_TENSOR = {
    "SIEF_NOEU": ("SIXX", "SIYY", "SIZZ", "SIXY", "SIXZ", "SIYZ"),
    "EPSI_NOEU": ("EPXX", "EPYY", "EPZZ", "EPXY", "EPXZ", "EPYZ"),
}


def read(ctx, kw, input_path):
    kind = kw["TYPE_RESU"]
    if kind not in ("DYNA_TRANS", "DYNA_HARMO"):
        ctx.unsupported(f"LIRE_RESU FORMAT='IDEAS_DS58' TYPE_RESU={kind!r}", "TYPE_RESU", kw)
    if kw.get("RESULTAT") is not None:
        ctx.unsupported("LIRE_RESU into an existing result (reuse)", "RESULTAT", kw)
    kw.mark_used("INFO", "TITRE", "CHAM_MATER", "CARA_ELEM")  # recorded by code_aster only
    mesh = kw["MAILLAGE"] if kw.get("MAILLAGE") is not None else kw["MODELE"].mesh
    try:
        functions = read_datasets_58(input_path)
    except (Ds58ReadError, ValueError) as exc:
        ctx.error(f"the file is not a readable universal file: {exc}", "UNITE", kw)
    orientations = _orientations(ctx, kw, mesh)
    per_field: dict[str, dict[tuple[int, str], np.ndarray]] = {}
    abscissas = None
    for name in as_tuple(kw["NOM_CHAM"]):
        chosen = [f for f in functions if f.ordinate_kind == ORDINATE_KIND[name]]
        if not chosen:
            ctx.log(f"LIRE_RESU IDEAS_DS58: no dataset of field {name} in the file")
            continue
        if name in _TENSOR and orientations:
            ctx.log(f"LIRE_RESU IDEAS_DS58: REDEFI_ORIENT does not apply to {name}")
        values: dict[tuple[int, str], np.ndarray] = {}
        for function in chosen:
            if abscissas is None:
                abscissas = function.abscissas
            if function.values.size != abscissas.size:
                ctx.error("the datasets do not have the same number of values", "UNITE", kw)
            if function.is_complex != (kind == "DYNA_HARMO"):
                ctx.error(
                    f"{'complex' if function.is_complex else 'real'} data cannot make a {kind}",
                    "TYPE_RESU",
                    kw,
                )
            node = _node(ctx, kw, mesh, function)
            number = abs(function.direction)
            signed = -function.values if function.direction < 0 else function.values
            if name in _TENSOR:
                if not 1 <= number <= 6:
                    ctx.error(f"direction {function.direction} of a {name} dataset", "UNITE", kw)
                values[(node, _TENSOR[name][number - 1])] = signed
                continue
            if not 1 <= number <= 3:
                ctx.error(f"direction {function.direction} of a {name} dataset", "UNITE", kw)
            axis = np.eye(3)[number - 1]
            direction = orientations.get((node, number), axis)
            values[(node, f"D{number}")] = signed
            for k, suffix in enumerate("XYZ"):
                values[(node, f"D{number}{suffix}")] = np.full(abscissas.size, direction[k])
        per_field[name] = values
    if not per_field:
        ctx.error("no dataset of the file holds the fields of NOM_CHAM", "NOM_CHAM", kw)
    picked = _selection(ctx, kw, abscissas)
    numbering = _numbering(mesh, per_field)
    dtype = complex if kind == "DYNA_HARMO" else float
    fields = {}
    for name, values in per_field.items():
        array = np.zeros((picked.size, numbering.n_dofs), dtype=dtype)
        for dof, series in values.items():
            array[:, numbering.index[dof]] = series[picked]
        fields[name] = array
    ctx.log(
        f"LIRE_RESU IDEAS_DS58: {len(fields)} fields at {picked.size} of "
        f"{abscissas.size} abscissas on {numbering.n_dofs} components"
    )
    order = picked + 1
    if kind == "DYNA_HARMO":
        return DynaHarmo(
            numbering=numbering, frequencies=abscissas[picked], order=order, fields=fields
        )
    return DynaTrans(numbering=numbering, times=abscissas[picked], order=order, fields=fields)


def _orientations(ctx, kw, mesh) -> dict[tuple[int, int], np.ndarray]:
    out = {}
    for occ in kw.factor("REDEFI_ORIENT"):
        direction = np.asarray(occ["DIRECTION"], dtype=float)
        for name in as_tuple(occ["NOEUD"]):
            node = mesh.find_node(str(name))
            if node is None:
                ctx.error(f"no node {name} in the mesh", "NOEUD", occ)
            out[(int(node), int(occ["CODE_DIR"]))] = direction
    return out


def _node(ctx, kw, mesh, function) -> int:
    name = function.node_name if function.node_label == 0 else f"N{function.node_label}"
    node = mesh.find_node(name)
    if node is None:
        ctx.error(f"the file's node {name} is not a node of the mesh", "UNITE", kw)
    return int(node)


def _selection(ctx, kw, abscissas) -> np.ndarray:
    """0-based ranks of the abscissas to store."""
    for key in ("NUME_ORDRE", "LIST_ORDRE"):
        if kw.get(key) is not None:
            wanted = [int(v) for v in np.atleast_1d(getattr(kw[key], "values", kw[key]))]
            kept = [w - 1 for w in wanted if 1 <= w <= abscissas.size]
            return np.asarray(kept, dtype=int)
    for key in ("INST", "LIST_INST", "FREQ", "LIST_FREQ"):
        if kw.get(key) is not None:
            wanted = np.atleast_1d(getattr(kw[key], "values", kw[key])).astype(float)
            relative = kw["CRITERE"] == "RELATIF"
            kept = []
            for value in wanted:
                tolerance = kw["PRECISION"] * (abs(value) if relative else 1.0)
                close = np.nonzero(np.abs(abscissas - value) <= tolerance)[0]
                if close.size == 0:
                    ctx.error(f"no abscissa of the file at {value:g}", key, kw)
                kept.append(int(close[0]))
            return np.asarray(kept, dtype=int)
    kw.mark_used("TOUT_ORDRE")  # every abscissa: what the selection rule leaves
    return np.arange(abscissas.size)


def _numbering(mesh, per_field) -> DofNumbering:
    order = {c: k for k, c in enumerate(_DIRECTIONAL + _TENSOR["SIEF_NOEU"] + _TENSOR["EPSI_NOEU"])}
    dofs = set()
    for values in per_field.values():
        dofs.update(values)
    return DofNumbering(mesh=mesh, dofs=sorted(dofs, key=lambda d: (d[0], order[d[1]])))
