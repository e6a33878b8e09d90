"""CREA_RESU OPERATION='AFFE' for the result types of modal recombination
studies: MULT_ELAS (one field per NOM_CAS, enriching RESULTAT / reuse),
DYNA_TRANS (DEPL/VITE/ACCE fields at instants) and MODE_MECA (DEPL fields
by NUME_MODE)."""

from __future__ import annotations

import numpy as np
from asterlite.commands.crea_resu_conv import conv_char, conv_resu, kucv

from asterlite.concepts.assembly import NodalField
from asterlite.concepts.modes import ModeResult, MultElasResult
from asterlite.concepts.transient import DynaTrans
from asterlite.fem.selection import as_tuple
from asterlite.modal.renumber import transfer


def _nodal(ctx, occ) -> NodalField:
    field = occ["CHAM_GD"]
    if not isinstance(field, NodalField):
        ctx.unsupported("CREA_RESU from a non-nodal field", "CHAM_GD", occ)
    return field


def _mult_elas(ctx, kw):
    base = kw.get("RESULTAT") or (ctx.reuse if isinstance(ctx.reuse, MultElasResult) else None)
    numbering = base.numbering if base is not None else None
    columns = [] if base is None else list(np.asarray(base.fields).T)
    names = [] if base is None else list(base.case_names)
    context = _base_context(base)
    for occ in kw.factor("AFFE"):
        if occ["NOM_CHAM"] != "DEPL":
            ctx.unsupported(f"MULT_ELAS field {occ['NOM_CHAM']}", "NOM_CHAM", occ)
        field = _nodal(ctx, occ)
        if numbering is None:
            numbering = field.numbering
        elif field.numbering.mesh is not numbering.mesh:
            ctx.error("the fields are on different meshes", "CHAM_GD", occ)
        values = transfer(field.values, field.numbering, numbering)
        _post_context(ctx, occ, numbering, context)
        name = str(occ.get("NOM_CAS") or f"CAS_{len(names) + 1}")
        if name in names:
            columns[names.index(name)] = values
        else:
            columns.append(values)
            names.append(name)
    return MultElasResult(
        numbering=numbering, fields=np.column_stack(columns), case_names=names, **context
    )


def _base_context(base) -> dict:
    keys = ("model", "materials", "characteristics")
    context = {k: getattr(base, k, None) for k in keys}
    return context | {"charges": list(getattr(base, "charges", []))}


def _post_context(ctx, occ, numbering, context: dict) -> None:
    """MODELE, CHAM_MATER, CARA_ELEM, CHARGE of an AFFE occurrence: kept on
    the result for its post-processing (CALC_CHAMP), as code_aster does."""
    model = occ.get("MODELE")
    if model is not None:
        if model.mesh is not numbering.mesh:
            ctx.error("MODELE is built on another mesh than the field", "MODELE", occ)
        context["model"] = model
    for keyword, key in (("CHAM_MATER", "materials"), ("CARA_ELEM", "characteristics")):
        if occ.get(keyword) is not None:
            context[key] = occ[keyword]
    for load in as_tuple(occ.get("CHARGE")):
        if all(load is not known for known in context["charges"]):
            context["charges"].append(load)


def _instants(ctx, occ) -> np.ndarray:
    if occ.get("LIST_INST") is not None:
        values = np.asarray(occ["LIST_INST"].values, dtype=float)
        start = int(occ.get("NUME_INIT") or 1) - 1
        stop = int(occ.get("NUME_FIN") or len(values))
        return values[start:stop]
    return np.asarray(as_tuple(occ["INST"]), dtype=float)


def _dyna_trans(ctx, kw):
    base = kw.get("RESULTAT") or (ctx.reuse if isinstance(ctx.reuse, DynaTrans) else None)
    numbering = base.numbering if base is not None else None
    times = [] if base is None else list(np.asarray(base.times, dtype=float))
    store: dict[str, dict[float, np.ndarray]] = {}
    if base is not None:
        for name, stack in base.fields.items():
            store[name] = {t: np.asarray(row) for t, row in zip(times, stack, strict=True)}
    for occ in kw.factor("AFFE"):
        field = _nodal(ctx, occ)
        if numbering is None:
            numbering = field.numbering
        values = transfer(field.values, field.numbering, numbering)
        for t in _instants(ctx, occ):
            t = float(t)
            if t not in times:
                times.append(t)
            store.setdefault(occ["NOM_CHAM"], {})[t] = values
    times = sorted(times)
    fields = {
        name: np.array([by_time.get(t, np.zeros(numbering.n_dofs)) for t in times])
        for name, by_time in store.items()
    }
    return DynaTrans(
        numbering=numbering,
        times=np.array(times),
        order=np.arange(1, len(times) + 1),
        fields=fields,
    )


def _mode_meca(ctx, kw):
    """MODE_MECA: one DEPL field per AFFE occurrence, numbered NUME_MODE, at
    FREQ (0 when not given); MATR_RIGI / MATR_MASS, kept with the modes,
    give their generalized stiffnesses and masses."""

    if kw.get("RESULTAT") is not None:
        ctx.unsupported("CREA_RESU MODE_MECA enriching a result", "RESULTAT", kw)
    numbering, shapes, numbers, frequencies = None, [], [], []
    for occ in kw.factor("AFFE"):
        if occ["NOM_CHAM"] != "DEPL":
            ctx.unsupported(f"MODE_MECA field {occ['NOM_CHAM']}", "NOM_CHAM", occ)
        if occ.get("AXE") is not None:
            ctx.unsupported("AXE (modes of a Fourier model)", "AXE", occ)
        field = _nodal(ctx, occ)
        if np.iscomplexobj(field.values):
            ctx.error(
                "a MODE_MECA holds real fields (MODE_MECA_C for complex ones)", "CHAM_GD", occ
            )
        if numbering is None:
            numbering = field.numbering
        elif field.numbering.mesh is not numbering.mesh:
            ctx.error("the fields are on different meshes", "CHAM_GD", occ)
        shapes.append(transfer(field.values, field.numbering, numbering))
        numbers.append(int(occ["NUME_MODE"]))
        frequencies.append(float(occ.get("FREQ") or 0.0))
    shapes = np.column_stack(shapes)
    stiffness, mass = kw.get("MATR_RIGI"), kw.get("MATR_MASS")

    def generalized(matrix):
        if matrix is None or matrix.numbering is not numbering:
            return np.zeros(shapes.shape[1])
        return np.einsum("im,im->m", shapes, matrix.matrix @ shapes)

    return ModeResult(
        numbering=numbering,
        shapes=shapes,
        frequencies=np.asarray(frequencies),
        generalized_mass=generalized(mass),
        generalized_stiffness=generalized(stiffness),
        mass=mass,
        stiffness=stiffness,
        parameters={"NUME_MODE": np.asarray(numbers, dtype=int)},
    )


def run(ctx, kw):
    if kw["OPERATION"] == "CONV_RESU":
        return conv_resu(ctx, kw)
    if kw["OPERATION"] == "CONV_CHAR":
        return conv_char(ctx, kw)
    if kw["OPERATION"] == "KUCV":
        return kucv(ctx, kw.factor("KUCV")[0], kw["TYPE_RESU"])
    if kw["OPERATION"] != "AFFE":
        ctx.unsupported(f"CREA_RESU OPERATION={kw['OPERATION']!r}", "OPERATION", kw)
    type_resu = kw["TYPE_RESU"]
    if type_resu == "MULT_ELAS":
        return _mult_elas(ctx, kw)
    if type_resu == "DYNA_TRANS":
        return _dyna_trans(ctx, kw)
    if type_resu == "MODE_MECA":
        return _mode_meca(ctx, kw)
    ctx.unsupported(f"CREA_RESU TYPE_RESU={type_resu!r}", "TYPE_RESU", kw)
