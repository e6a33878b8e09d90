"""REST_GENE_PHYS: physical fields of a generalized transient (tran_gene).

u(t) = Φ q(t) on the chosen DOFs, at the archived states (TOUT_ORDRE,
NUME_ORDRE) or at chosen instants (INST, LIST_INST), interpolated linearly
when INTERPOL='LIN'. The restituted states are numbered in sequence, as
code_aster's tran75 does: interpolated instants (INTERPOL='LIN') 1..n;
archived states, whether chosen by order or by instant, 0 for the initial
state when it is restituted, then 1, 2... (so with PAS_ARCH=10 the 10th
archived state is order 10, not step 100). An interpolated instant outside
the archive keeps the field of the previous one, as tran75 leaves it.

MULT_APPUI='OUI' adds the support motion Σ ψ_k s_k(t) when the tran_gene
carries it in ``info["mult_appui"]`` (a list of dicts with ``"shape"``: a
static mode on the basis DOFs, and ``"DEPL"``/``"VITE"``/``"ACCE"``:
functions of time). ACCE_MONO_APPUI adds γ(t)·DIRECTION to translations.
"""

from __future__ import annotations

import numpy as np

from asterlite.concepts.assembly import DofNumbering
from asterlite.concepts.harmonic import DynaHarmo, HarmGene
from asterlite.concepts.modes import GeneralizedModes
from asterlite.concepts.transient import DynaTrans, TranGene
from asterlite.post.harmonic import selection_from_keywords as frequency_selection
from asterlite.post.restitution import (
    FIELDS,
    InstantSelection,
    added_motions,
    as_tuple,
    dof_rows,
    node_indices,
    recombine,
    recombine_element_field,
    selection_from_keywords,
    support_motion,
    values_of,
)

TRANSLATIONS = ("DX", "DY", "DZ")


def run(ctx, kw):
    result = kw.get("RESU_GENE")
    if isinstance(result, GeneralizedModes):
        return restored_modes(ctx, kw, result)
    if isinstance(result, HarmGene):
        basis = result.basis
        if isinstance(basis, GeneralizedModes) or not hasattr(basis, "shapes"):
            # harm75 needs the restored modes of a coupled generalized model
            if kw.get("MODE_MECA") is None:
                ctx.error(
                    "the harmonic result's basis is not a mode_meca: give MODE_MECA (modes "
                    "restored by REST_SOUS_STRUC) or restore with REST_SOUS_STRUC",
                    "MODE_MECA",
                    kw,
                )
            basis = kw["MODE_MECA"]
        else:
            kw.mark_used("MODE_MECA")  # harm75 restores on the result's own basis
        return restore_harmonic(ctx, kw, result, basis)
    if not isinstance(result, TranGene):
        ctx.unsupported(
            f"REST_GENE_PHYS of a {getattr(result, 'aster_type', type(result).__name__)}",
            "RESU_GENE",
            kw,
        )
    basis = kw.get("MODE_MECA") or result.basis
    if isinstance(basis, GeneralizedModes):  # a transient of a coupled generalized model
        ctx.error(
            "the transient's basis is a mode_gene: give MODE_MECA (modes restored by"
            " REST_SOUS_STRUC) or restore with REST_SOUS_STRUC",
            "MODE_MECA",
            kw,
        )
    return restore_transient(ctx, kw, result, basis)


def restore_transient(ctx, kw, result, basis):
    """The dyna_trans of a tran_gene recombined on ``basis`` (also used by
    REST_SOUS_STRUC with the substructure's or skeleton's restored modes)."""
    if basis.n_modes != result.n_modes:
        ctx.error(
            f"MODE_MECA has {basis.n_modes} modes, the result {result.n_modes}", "MODE_MECA", kw
        )
    fields, element_names = requested_fields(ctx, kw, basis)
    if kw.get("INTERPOL") == "LIN" and chosen_instants(kw) is not None:
        selection = interpolated_instants(ctx, kw, result.times)
    else:
        selection = selection_from_keywords(ctx, kw, result.times, result.order)
    numbering = basis.numbering
    nodes = node_indices(ctx, kw, numbering.mesh)
    rows = dof_rows(numbering, nodes, as_tuple(kw.get("NOM_CMP")))
    if rows.size == 0:
        ctx.error("no DOF matches the requested nodes and components", "GROUP_NO", kw)
    shapes = basis.shapes[rows, :]
    out = {}
    for name in fields:
        generalized = selection.apply(getattr(result, name[:4].lower()))
        out[name] = recombine(shapes, generalized)
    for keyword in ("MULT_APPUI", "CORR_STAT"):
        if kw.get(keyword) == "OUI":
            add_support_motion(ctx, kw, result, rows, selection.times, out, keyword)
    if kw.get("ACCE_MONO_APPUI") is not None:
        uniform_accelerations(ctx, kw)  # checked even when ACCE_ABSOLU is not asked for
        if "ACCE_ABSOLU" in out:
            add_uniform_acceleration(ctx, kw, numbering, rows, selection.times, out)
    if nodes is None and rows.size == numbering.n_dofs:
        sub = numbering
    else:
        sub = DofNumbering(numbering.mesh, [numbering.dofs[i] for i in rows])
    if chosen_instants(kw) is not None and kw.get("INTERPOL") == "LIN":
        order = np.arange(1, len(selection.times) + 1)  # interpolated instants: 1..n
    else:  # archived states, also chosen by instant (tran75 from code_aster 10 to 17)
        order = sequence_numbers(selection.times, result.times)
    restored = DynaTrans(sub, selection.times, order, out)
    if sub is numbering:
        # each field recombined on the whole basis, as code_aster does over all
        # its equations: the multipliers of a field are those of the modes
        # recombined (asterlite.post.deck_api.transient_field)
        added = {"ACCE_ABSOLU"} | {
            name for keyword in ("MULT_APPUI", "CORR_STAT") if kw.get(keyword) == "OUI"
            for name in out
        }  # fmt: skip
        restored.modal_source = (
            basis,
            {name: selection.apply(getattr(result, name[:4].lower())) for name in out
             if name not in added},
        )  # fmt: skip
    if element_names:
        for keyword in ("MULT_APPUI", "CORR_STAT"):
            if kw.get(keyword) == "OUI":
                ctx.unsupported(f"{keyword}='OUI' with element fields", keyword, kw)
        generalized = selection.apply(result.depl)
        # stored as CALC_CHAMP stores element fields on a result
        restored.element_fields = {
            name: recombine_element_field(basis.element_fields[name], generalized)
            for name in element_names
        }
    return restored


def restore_harmonic(ctx, kw, result, basis) -> DynaHarmo:
    """The dyna_harmo of a harm_gene recombined on ``basis`` (code_aster's
    harm75): u = Φ q at the frequencies FREQ / LIST_FREQ / NUME_ORDRE (all
    by default), numbered 1..n; TOUT_CHAM gives DEPL, VITE and ACCE, NOM_CHAM
    (ACCE by default) some of them, which the harm_gene must hold. Also used
    by REST_SOUS_STRUC with the substructure's or skeleton's restored modes."""

    if basis.n_modes != result.n_modes:
        ctx.error(
            f"the basis has {basis.n_modes} modes, the result {result.n_modes}", "MODE_MECA", kw
        )
    if kw.get("INTERPOL", "NON") != "NON":
        ctx.error("a harmonic result is restored without interpolation", "INTERPOL", kw)
    if kw.get("TOUT_CHAM") == "OUI":
        names = FIELDS
    else:
        names = tuple(dict.fromkeys(as_tuple(kw.get("NOM_CHAM") or "ACCE")))
        other = [n for n in names if n not in FIELDS]
        if other:
            ctx.unsupported(f"NOM_CHAM={other[0]!r} of a harm_gene", "NOM_CHAM", kw)
    for name in names:
        if name not in result.fields:
            ctx.error(f"the harm_gene holds no {name} field", "NOM_CHAM", kw)
    for keyword in ("MULT_APPUI", "CORR_STAT", "ACCE_MONO_APPUI"):
        if kw.get(keyword) is not None:
            ctx.unsupported(f"{keyword} with a harm_gene", keyword, kw)
    selection = frequency_selection(ctx, kw, result.frequencies, result.order)
    numbering = basis.numbering
    nodes = node_indices(ctx, kw, numbering.mesh)
    rows = dof_rows(numbering, nodes, as_tuple(kw.get("NOM_CMP")))
    if rows.size == 0:
        ctx.error("no DOF matches the requested nodes and components", "GROUP_NO", kw)
    shapes = np.asarray(basis.shapes)[rows, :]
    fields = {name: selection.apply(result.fields[name]) @ shapes.T for name in names}
    if nodes is None and rows.size == numbering.n_dofs:
        sub = numbering
    else:
        sub = DofNumbering(numbering.mesh, [numbering.dofs[i] for i in rows])
    restored = DynaHarmo(
        numbering=sub,
        frequencies=selection.times,
        order=np.arange(1, selection.times.size + 1),
        fields=fields,
        model=getattr(numbering, "model", None),
        materials=getattr(numbering, "materials", None),
        characteristics=getattr(numbering, "characteristics", None),
    )
    if sub is numbering:
        # recombined over all of code_aster's equations: a field's multipliers
        # are the modes' (asterlite.post.deck_api.harmonic_field)
        restored.modal_source = (
            basis,
            {name: selection.apply(result.fields[name]) for name in names},
        )
    return restored


def requested_fields(ctx, kw, basis) -> tuple[tuple[str, ...], tuple[str, ...]]:
    """(nodal fields, element fields) to restore. Element fields (SIPO_ELNO,
    EFGE_ELNO...) recombine those CALC_CHAMP computed on the modal basis.
    TOUT_CHAM gives DEPL, VITE, ACCE, and ACCE_ABSOLU with ACCE_MONO_APPUI."""
    if kw.get("TOUT_CHAM") == "OUI" or kw.get("NOM_CHAM") is None:
        with_entrainment = kw.get("ACCE_MONO_APPUI") is not None
        return (*FIELDS, "ACCE_ABSOLU") if with_entrainment else FIELDS, ()
    names = tuple(dict.fromkeys(as_tuple(kw["NOM_CHAM"])))
    nodal = (*FIELDS, "ACCE_ABSOLU")
    computed = getattr(basis, "element_fields", None) or {}
    elements = tuple(n for n in names if n not in nodal and n in computed)
    other = [n for n in names if n not in nodal and n not in computed]
    if other:
        if other[0].endswith(("_ELNO", "_ELGA")):
            ctx.error(
                f"NOM_CHAM={other[0]!r}: the modal basis {basis.name or ''} has no such field "
                "(compute it first with CALC_CHAMP on the modes)",
                "NOM_CHAM",
                kw,
            )
        ctx.unsupported(f"NOM_CHAM={other[0]!r} (DEPL, VITE, ACCE, element fields)", "NOM_CHAM", kw)
    return tuple(n for n in names if n in nodal), elements


def add_support_motion(ctx, kw, result, rows, times, out, keyword="MULT_APPUI") -> None:
    supports = added_motions(ctx, kw, result, keyword)
    for name in out:
        out[name] = out[name] + support_motion(supports, rows, times, name)


def uniform_accelerations(ctx, kw):
    """ACCE_MONO_APPUI functions and their unit DIRECTION triples (code_aster's
    tran75 checks and normalises them whatever fields are restored)."""
    functions = as_tuple(kw["ACCE_MONO_APPUI"])
    directions = np.asarray(as_tuple(kw.get("DIRECTION")) or (0.0,) * 3, dtype=float)
    if directions.size < 3 * len(functions):
        ctx.error(
            f"{len(functions)} ACCE_MONO_APPUI functions need {3 * len(functions)} DIRECTION "
            f"values, got {directions.size}",
            "DIRECTION",
            kw,
        )
    directions = directions[: 3 * len(functions)].reshape(-1, 3)
    norms = np.linalg.norm(directions, axis=1)
    if np.any(norms < np.finfo(float).eps):
        ctx.error("a DIRECTION of ACCE_MONO_APPUI is the zero vector", "DIRECTION", kw)
    return functions, directions / norms[:, None]


def add_uniform_acceleration(ctx, kw, numbering, rows, times, out) -> None:
    """ACCE_ABSOLU: the relative acceleration plus Σ γ_k(t) DIRECTION_k on
    the translations (one direction per ACCE_MONO_APPUI function)."""
    functions, directions = uniform_accelerations(ctx, kw)
    components = [numbering.dofs[i][1] for i in rows]
    for function, direction in zip(functions, directions, strict=True):
        weights = np.array(
            [direction[TRANSLATIONS.index(c)] if c in TRANSLATIONS else 0.0 for c in components]
        )
        out["ACCE_ABSOLU"] = out["ACCE_ABSOLU"] + np.outer(function.evaluate(times), weights)


def restored_modes(ctx, kw, modes: GeneralizedModes):
    """A mode_gene restored on its projection basis: the modes Φ q_k (DEPL),
    all of them or those chosen by NUME_ORDRE / NUME_MODE (1-based)."""
    every_field = kw.get("TOUT_CHAM") == "OUI"  # a mode_gene has DEPL only
    names = [n for n in as_tuple(kw.get("NOM_CHAM")) if n != "DEPL"]
    if names and not every_field:
        ctx.unsupported(f"NOM_CHAM={names[0]!r} of a mode_gene (DEPL only)", "NOM_CHAM", kw)
    for keyword in ("MULT_APPUI", "CORR_STAT", "ACCE_MONO_APPUI"):
        if kw.get(keyword) is not None:
            ctx.unsupported(f"{keyword} on a mode_gene", keyword, kw)
    restored = modes.physical(chosen_modes(ctx, kw, modes))
    nodes = node_indices(ctx, kw, restored.numbering.mesh)
    rows = dof_rows(restored.numbering, nodes, as_tuple(kw.get("NOM_CMP")))
    if rows.size != restored.numbering.n_dofs:
        numbering = restored.numbering
        restored.numbering = DofNumbering(numbering.mesh, [numbering.dofs[i] for i in rows])
        restored.shapes = restored.shapes[rows, :]
    return restored


def chosen_modes(ctx, kw, modes: GeneralizedModes) -> list[int] | None:
    """0-based indices of the modes NUME_MODE / NUME_ORDRE name (None: all, as
    TOUT_ORDRE asks)."""
    kw.mark_used("TOUT_ORDRE")
    if kw.get("NUME_MODE") is not None:
        key, known = "NUME_MODE", [int(n) for n in modes.mode_numbers]
    elif kw.get("NUME_ORDRE") is not None:
        key, known = "NUME_ORDRE", list(range(1, modes.n_modes + 1))
    else:
        return None
    wanted = [int(w) for w in as_tuple(kw[key])]
    absent = [w for w in wanted if w not in known]
    if absent:
        ctx.error(f"{key} {absent[0]} is not among the {modes.n_modes} modes", key, kw)
    return [known.index(w) for w in wanted]


def sequence_numbers(selected_times, archived_times) -> np.ndarray:
    """NUME_ORDRE of restituted states: in sequence, from 0 when the first
    one is the initial state of the transient, else from 1."""
    count = len(selected_times)
    initial = count > 0 and len(archived_times) > 0 and selected_times[0] == archived_times[0]
    start = 0 if initial else 1
    return np.arange(start, start + count)


def chosen_instants(kw) -> np.ndarray | None:
    if kw.get("INST") is not None:
        return values_of(kw["INST"])
    if kw.get("LIST_INST") is not None:
        return values_of(kw["LIST_INST"])
    return None


def interpolated_instants(ctx, kw, times) -> InstantSelection:
    """INTERPOL='LIN' as code_aster does it (tran75 calling extrac, code_aster 10 to
    17): an instant within PRECISION of the first or last archived one takes that
    state; an instant outside the archive is not extracted and its field keeps the
    state restituted for the previous instant (tran75 does not read extrac's
    return code)."""
    times = np.asarray(times, dtype=float)
    wanted = np.atleast_1d(chosen_instants(kw))
    precision = float(kw.get("PRECISION", 1e-6))
    relative = kw.get("CRITERE", "RELATIF") == "RELATIF"
    lower = np.zeros(wanted.size, dtype=int)
    weight = np.zeros(wanted.size)
    last = times.size - 1
    for i, t in enumerate(wanted):
        if abs(t - times[0]) <= precision * (abs(times[0]) if relative else 1.0):
            lower[i] = 0
        elif abs(t - times[last]) <= precision * (abs(times[last]) if relative else 1.0):
            lower[i] = last
        elif times[0] < t < times[last]:
            lower[i] = int(np.searchsorted(times, t, side="right")) - 1
            weight[i] = (t - times[lower[i]]) / (times[lower[i] + 1] - times[lower[i]])
        elif i == 0:
            ctx.unsupported(
                f"instant {t:g} outside the archived range [{times[0]:g}, {times[last]:g}] "
                "as the first one restituted (code_aster leaves its field as allocated)",
                "INST" if kw.get("INST") is not None else "LIST_INST",
                kw,
            )
        else:
            lower[i], weight[i] = lower[i - 1], weight[i - 1]
            ctx.log(
                f"REST_GENE_PHYS: instant {t:g} is outside the archived range "
                f"[{times[0]:g}, {times[last]:g}]: its field is that of the previous "
                "instant, as code_aster's tran75 leaves it"
            )
    return InstantSelection(lower, weight, wanted.copy(), np.arange(1, wanted.size + 1))
