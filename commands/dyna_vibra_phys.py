"""DYNA_VIBRA, TYPE_CALCUL='TRAN', BASE_CALCUL='PHYS' (code_aster's DYNA_LINE_TRAN):
the transient on the assembled physical matrices. commands/dyna_vibra.py
dispatches here; the keyword readers both paths share stay there."""

from __future__ import annotations

import numpy as np
from asterlite.commands.dyna_vibra_keywords import first_value, list_values
from asterlite.commands.dyna_vibra_loads import support_shape
from asterlite.commands.dyna_vibra_time import archived_index, refuse_too_many_steps
from asterlite.commands.dyna_vibra_words import TRANSIENT

from asterlite.concepts.table import TableNotComputed
from asterlite.concepts.transient import DynaTrans
from asterlite.dynamics.physical.archive import Archive, archive_on_disk, archived_steps
from asterlite.dynamics.physical.imposed import ConstantInTime, ScaledInTime
from asterlite.dynamics.physical.modal_damping import build_modal_damping, damping_ratios
from asterlite.errors import NumericalError, worded
from asterlite.fem.loads import load_history, load_terms
from asterlite.fem.selection import as_tuple
from asterlite.io.disk_rows import DiskRows
from asterlite.modal.renumber import transfer

PHYSICAL_SCHEMES = ("NEWMARK", "WILSON", "DIFF_CENTRE", "ADAPT_ORDRE2")


def run_physical(ctx, kw):
    """TYPE_CALCUL='TRAN', BASE_CALCUL='PHYS' (code_aster's DYNA_LINE_TRAN):
    linear, on the assembled matrices; a ``DynaTrans`` on the numbering's DOFs."""
    from asterlite.dynamics.physical import adapt_ordre2, diff_centre, newmark, wilson
    from asterlite.dynamics.physical.system import build_system

    # SCHEMA_TEMPS is a defaulted factor keyword: always one occurrence, defaults filled
    schema_kw = kw.factor("SCHEMA_TEMPS")[0]
    scheme = schema_kw["SCHEMA"]
    if scheme not in PHYSICAL_SCHEMES:
        ctx.unsupported(
            f"SCHEMA={scheme!r} on a physical basis (code_aster's PHYS transient offers "
            f"{', '.join(PHYSICAL_SCHEMES)})",
            "SCHEMA",
            schema_kw,
        )
    mass_matrix, stiffness_matrix = kw["MATR_MASS"], kw["MATR_RIGI"]
    numbering = stiffness_matrix.numbering
    damping = kw["MATR_AMOR"].matrix if kw.get("MATR_AMOR") is not None else None
    loads = physical_loads(ctx, kw, numbering, stiffness_matrix)
    imposed = physical_imposed_motion(ctx, kw, numbering, scheme)
    system = build_system(
        numbering, mass_matrix.matrix, stiffness_matrix.matrix, damping, loads, imposed
    )
    modal = physical_modal_damping(ctx, kw, numbering, stiffness_matrix, system, scheme)

    reused = ctx.reuse if isinstance(getattr(ctx, "reuse", None), DynaTrans) else None
    q, v, a, t_state, order_offset = physical_initial_state(ctx, kw, system)
    times, dt = physical_instants(ctx, kw, t_state)
    if a is None:
        a = (
            system.initial_acceleration(times[0], q, v)
            if initial_acceleration_computed(kw)
            else np.zeros(system.n_free)
        )
    archiving = (kw.factor("ARCHIVAGE") or [{}])[0]
    mask = None if scheme == "ADAPT_ORDRE2" else physical_archive_mask(kw, times)
    capacity = 64 if mask is None else int(np.count_nonzero(mask))
    # past its share of the memory limit the archive lives on disk
    disk = (
        ctx.session.output_dir
        if mask is not None and archive_on_disk(capacity, system.n_free, system.n_dofs)
        else False
    )
    archive = Archive(system.n_free, capacity, disk)
    excluded = as_tuple(archiving.get("CHAM_EXCLU"))
    if excluded:
        # code_aster stores excluded fields at the last instant only; asterlite keeps
        # them at every instant, so every value code_aster can give is the same
        ctx.log(f"CHAM_EXCLU {', '.join(excluded)}: kept at every archived instant")
    last_velocity = None
    energy = None
    if kw.factor("ENERGIE"):
        from asterlite.dynamics.physical.energy import EnergyBalance

        if scheme not in ("NEWMARK", "DIFF_CENTRE"):
            ctx.unsupported(f"ENERGIE with SCHEMA={scheme!r} (NEWMARK, DIFF_CENTRE)", "ENERGIE", kw)
        if modal is not None:
            ctx.unsupported("ENERGIE with AMOR_MODAL on a physical basis", "ENERGIE", kw)
        energy = EnergyBalance(system, times[0])
        previous = getattr(reused, "tables", {}).get("PARA_CALC") if reused is not None else None
        if previous is not None and t_state is not None:
            energy.resume(previous, t_state)
    started = __import__("time").perf_counter()
    try:
        if scheme == "ADAPT_ORDRE2":
            inverse = checked_diagonal_mass(ctx, system, scheme)
            if system.elimination.multi_rows is not None and system.elimination.multi_rows.size:
                ctx.error("ADAPT_ORDRE2 on a physical basis does not accept LIAISON_DDL relations")
            options = {
                "vite_min": first_value(schema_kw["VITE_MIN"]),
                "coef_mult_pas": schema_kw["COEF_MULT_PAS"],
                "coef_divi_pas": schema_kw["COEF_DIVI_PAS"],
                "dt_min": schema_kw.get("PAS_MINI")
                if schema_kw.get("PAS_MINI") is not None
                else dt * schema_kw["PAS_LIMI_RELA"],
                "nb_poin_periode": int(schema_kw["NB_POIN_PERIODE"]),
                "nmax_iter_pas": int(schema_kw["NMAX_ITER_PAS"]),
                "pas_arch": int(archiving.get("PAS_ARCH") or 1),
            }
            neighbours = adapt_ordre2.same_component_neighbours(numbering, system.elimination.free)
            stats = adapt_ordre2.integrate(
                system,
                times[0],
                times[-1],
                dt,
                q,
                v,
                a,
                archive,
                inverse,
                options,
                neighbours,
                lambda text: ctx.log(worded(text, TRANSIENT)),
            )
        else:
            if scheme == "NEWMARK":
                newmark.integrate(
                    system,
                    times,
                    q,
                    v,
                    a,
                    mask,
                    archive,
                    beta=schema_kw["BETA"],
                    gamma=schema_kw["GAMMA"],
                    monitor=energy,
                    modal=modal,
                )
            elif scheme == "WILSON":
                wilson.integrate(
                    system,
                    times,
                    q,
                    v,
                    a,
                    mask,
                    archive,
                    theta=schema_kw["THETA"],
                    modal=modal,
                )
            else:
                inverse = checked_diagonal_mass(ctx, system, scheme)
                limit = diff_centre.stability_limit(system, inverse)
                if np.max(np.diff(times)) > limit * (1.0 + 1.0e-12):
                    raise NumericalError(
                        f"DIFF_CENTRE: the step {np.max(np.diff(times)):.6g} exceeds "
                        f"{limit:.6g} (1/20 of the shortest period sqrt(m_ii/k_ii) 2π)",
                        ctx.location,
                        f"{ctx.command}/INCREMENT",
                    )
                half_velocity = diff_centre.integrate(
                    system, times, q, v, a, mask, archive, inverse, monitor=energy
                )
                if "VITE" in excluded and half_velocity is not None:
                    # code_aster's dldiff archives the fields excluded along the run at
                    # the last instant, VITE being then the half-step velocity v_{N-1/2}
                    last_velocity = half_velocity
            stats = {"steps": times.size - 1}
    except FloatingPointError as error:  # worded with the deck's keywords
        path = worded(getattr(error, "path", ""), TRANSIENT, whole_path=True)
        path = f"{ctx.command}/{path}" if path else ctx.command
        message = worded(str(error), TRANSIENT)
        raise NumericalError(f"{scheme}: {message}", ctx.location, path) from None
    except NumericalError as error:
        error = error.worded(TRANSIENT)
        raise NumericalError(error.message, ctx.location, ctx.command) from None
    elapsed = __import__("time").perf_counter() - started
    out_t = archive.times[: archive.count].copy()
    ctx.log(
        f"DYNA_VIBRA PHYS {scheme}: {stats['steps']} steps, {out_t.size} archived, "
        f"{system.n_free} free DOFs of {system.n_dofs}, {elapsed:.3f} s"
    )
    fields = {}
    # one quantity at a time, its reduced states let go of once expanded: the
    # archive and the fields are never both whole in memory
    for k, (name, expand) in enumerate(
        (("DEPL", system.expand), ("VITE", system.expand_rate), ("ACCE", system.expand_rate))
    ):
        states = archive.take(k)
        if name == "VITE" and last_velocity is not None and out_t.size and out_t[-1] == times[-1]:
            states[-1] = last_velocity
        fields[name] = expand(
            states, DiskRows(system.n_dofs, disk or None) if archive.on_disk else None
        )
        del states
    if archive.on_disk:
        ctx.log(f"archive of {out_t.size} states kept on disk (over its share of the memory limit)")
    del archive
    if system.imposed is not None:
        # the archived instants are step instants: their motion is the scheme's
        steps = np.clip(np.searchsorted(times, out_t), 0, times.size - 1)
        for name, values in zip(
            ("DEPL", "VITE", "ACCE"), system.imposed_fields(steps), strict=True
        ):
            fields[name] = fields[name] + values
    supports = physical_supports(ctx, kw, numbering)
    if supports:
        # code_aster (dlnew0): the fields are the relative motion; the absolute
        # ones add Σ ψ_k (d_k, v_k, a_k)(t) (support static modes times motions)
        for name in ("DEPL", "VITE", "ACCE"):
            absolute = fields[name].copy()
            for support in supports:
                values = np.asarray(support[name].evaluate(out_t), dtype=float)
                absolute += np.outer(values, support["shape"])
            fields[f"{name}_ABSOLU"] = absolute
    order = order_offset + np.arange(out_t.size, dtype=np.int64)
    if reused is not None and t_state is not None:
        keep = reused.times < out_t[0] - 1.0e-12 * max(1.0, abs(out_t[0]))
        start = int(reused.order[keep][-1]) + 1 if np.any(keep) else 0
        order = start + np.arange(out_t.size, dtype=np.int64)
        out_t = np.concatenate([reused.times[keep], out_t])
        order = np.concatenate([reused.order[keep], order])
        fields = {
            name: np.concatenate([reused.fields[name][keep], values])
            for name, values in fields.items()
            if name in reused.fields
        }
    produced = DynaTrans(
        numbering=numbering,
        times=out_t,
        order=order,
        fields=fields,
        model=kw.get("MODELE") or numbering.model,
        materials=kw.get("CHAM_MATER") or stiffness_matrix.materials,
        characteristics=kw.get("CARA_ELEM") or stiffness_matrix.characteristics,
        mass_matrix=mass_matrix,
        loads=result_loads(kw),
    )
    if energy is not None:
        produced.tables["PARA_CALC"] = energy.table()
    if kw.factor("OBSERVATION"):
        for occ in kw.factor("OBSERVATION"):
            dict(occ.items())  # the occurrences define the deferred table's content
        path, location = kw.where("OBSERVATION")
        produced.tables["OBSERVATION"] = TableNotComputed(
            "the OBSERVATION table of DYNA_VIBRA (values at every PAS_OBSE step, between "
            "archived instants) is not computed by asterlite",
            location,
            path,
        )
    return produced


def physical_modal_damping(ctx, kw, numbering, stiffness_matrix, system, scheme):
    """AMOR_MODAL of a physical transient (code_aster's nmmoam): a
    ``ModalDamping`` applied explicitly by NEWMARK and WILSON (dlnew0);
    DIFF_CENTRE and ADAPT_ORDRE2 do not read the keyword in code_aster."""

    occs = kw.factor("AMOR_MODAL")
    if not occs:
        return None
    occ = occs[0]
    if scheme not in ("NEWMARK", "WILSON"):
        ctx.log(
            f"warning: AMOR_MODAL is ignored with SCHEMA={scheme!r} on a physical basis "
            "(as code_aster, whose modal damping force is applied by NEWMARK and WILSON only)"
        )
        return None
    modes = occ.get("MODE_MECA")
    if modes is None:
        ctx.error("AMOR_MODAL on a physical basis needs MODE_MECA", "MODE_MECA", occ)
    n_modes = modes.n_modes
    if occ.get("NB_MODE") is not None:
        n_modes = min(n_modes, int(occ["NB_MODE"]))
    values = occ.get("AMOR_REDUIT")
    if values is None and occ.get("LIST_AMOR") is not None:
        values = list_values(occ["LIST_AMOR"])
    if values is None or np.size(values) == 0:
        ctx.error("AMOR_MODAL needs AMOR_REDUIT or LIST_AMOR", "AMOR_REDUIT", occ)
    ratios, too_many = damping_ratios(values, n_modes)
    if too_many:
        ctx.log(
            f"warning: AMOR_MODAL gives more damping ratios than the {n_modes} modes used; "
            "the extra values are ignored"
        )
    # b_i = K φ_i with the stiffness of the modes (REF_RIGI_PREM), on their numbering
    mode_stiffness = modes.stiffness if modes.stiffness is not None else stiffness_matrix
    shapes = np.asarray(modes.shapes[:, :n_modes], dtype=float)
    shapes = transfer(shapes, modes.numbering, mode_stiffness.numbering)
    stiffness_shapes = transfer(mode_stiffness.matrix @ shapes, mode_stiffness.numbering, numbering)
    masses = modes.parameters.get("MASS_GENE", modes.generalized_mass)
    masses = np.asarray(masses, dtype=float)[:n_modes]
    frequencies = np.asarray(modes.frequencies, dtype=float)[:n_modes]
    supports = [
        (support["shape"], support["VITE"]) for support in physical_supports(ctx, kw, numbering)
    ]
    try:
        modal = build_modal_damping(
            system.elimination, stiffness_shapes, frequencies, masses, ratios, supports
        )
    except ValueError as error:
        ctx.error(f"AMOR_MODAL: {error}", "MODE_MECA", occ)
    ctx.log(f"AMOR_MODAL: modal damping force on {n_modes} modes, applied explicitly")
    return modal


def physical_imposed_motion(ctx, kw, numbering, scheme):
    """(rhs over the numbering's relations, multiplier in time) of the
    imposed motions of the EXCIT loads: their relations times FONC_MULT, and
    the relations AFFE_CHAR_MECA_F gives as functions of INST times FONC_MULT
    or COEF_MULT (see ``asterlite.dynamics.physical.imposed``)."""

    position = {id(relation): r for r, relation in enumerate(numbering.relations)}
    imposed = []
    for occ in kw.factor("EXCIT"):
        load, function = occ.get("CHARGE"), occ.get("FONC_MULT")
        if load is None or occ.get("MULT_APPUI") == "OUI":
            continue
        constant = np.zeros(len(numbering.relations))
        in_time = {}
        for relation in getattr(load, "relations", ()):
            row = position.get(id(relation))
            if row is None:
                continue
            value = getattr(relation, "rhs_in_time", None)
            if value is None:
                constant[row] = relation.rhs
            else:
                in_time.setdefault(value.key, (value, []))[1].append(row)
        columns = []
        if function is not None and np.any(constant):
            columns.append((constant, function))
        elif float(occ.get("COEF_MULT", 1.0)) != 1.0 and np.any(constant):
            # code_aster scales the imposed values by COEF_MULT too
            columns.append((constant, ConstantInTime(float(occ["COEF_MULT"]))))
        scale = function if function is not None else float(occ.get("COEF_MULT", 1.0))
        for value, rows in in_time.values():
            rhs = np.zeros(len(numbering.relations))
            rhs[rows] = 1.0  # DDL_IMPO: the relation u = g(t), coefficient 1
            columns.append((rhs, ScaledInTime(scale, value)))
        if not columns:
            continue
        where = "FONC_MULT" if function is not None else "CHARGE"
        if scheme != "NEWMARK":
            ctx.unsupported(
                "an imposed motion (DDL_IMPO times FONC_MULT, or AFFE_CHAR_MECA_F DDL_IMPO "
                f"of INST) with SCHEMA={scheme!r} on a physical basis (NEWMARK only)",
                where,
                occ,
            )
        for name in ("ENERGIE", "AMOR_MODAL"):
            if kw.factor(name):
                ctx.unsupported(
                    f"{name} with an imposed motion (DDL_IMPO times FONC_MULT, or "
                    "AFFE_CHAR_MECA_F DDL_IMPO of INST) on a physical basis",
                    name,
                    kw,
                )
        imposed.extend(columns)
    return imposed


def result_loads(kw) -> tuple:
    """The list of loads code_aster keeps with the result: the EXCIT
    occurrences that give a CHARGE, with their FONC_MULT (or COEF_MULT);
    a VECT_ASSE is no load of the result."""
    return tuple(
        (occ["CHARGE"], occ.get("FONC_MULT") or float(occ.get("COEF_MULT", 1.0)))
        for occ in kw.factor("EXCIT")
        if occ.get("CHARGE") is not None
    )


def physical_loads(ctx, kw, numbering, stiffness_matrix):
    from asterlite.dynamics.physical.system import Load
    from asterlite.fem.assemble import assemble_terms

    loads = []
    for occ in kw.factor("EXCIT"):
        if occ.get("ACCE") is not None and occ.get("VECT_ASSE") is None:
            ctx.unsupported("EXCIT ACCE with a CHARGE on a physical basis", "ACCE", occ)
        if occ.get("VECT_ASSE") is not None:
            vector = np.asarray(occ["VECT_ASSE"].values, dtype=float)
            if vector.size != numbering.n_dofs:
                ctx.error("VECT_ASSE is not on the numbering of the matrices", "VECT_ASSE", occ)
        history = None
        if occ.get("VECT_ASSE") is None:
            load = occ["CHARGE"]
            materials = stiffness_matrix.materials
            try:
                terms = load_terms(
                    load, stiffness_matrix.characteristics, materials, history_apart=True
                )
                vector = assemble_terms(terms, numbering)
            except KeyError as exc:
                ctx.error(f"load on DOFs the numbering does not have: {exc}", "CHARGE", occ)
            history = load_history(load, materials)
        mult = occ.get("FONC_MULT")
        if occ.get("ACCE") is not None:
            mult = occ["ACCE"]  # relative motion: the vector is -M ψ (CALC_CHAR_SEISME)
        elif mult is None:
            mult = float(occ.get("COEF_MULT", 1.0))
        loads.append(Load(vector, mult, _numbered_history(ctx, history, numbering, occ)))
    for occ in kw.factor("EXCIT_RESU"):
        loads.append(_result_load(ctx, occ, numbering))
    return loads


def _result_load(ctx, occ, numbering):
    """EXCIT_RESU: the DEPL field of a dyna_trans as forces, times COEF_MULT,
    read as code_aster's dlnew0 reads it: the stored field at an instant the
    result holds (1e-9 relative, 1e-12 absolute at 0), else linear between the
    fields of orders i and i+1 that bracket the instant; before the instant
    of order 1, the field of order 1; after the last, the last field (orders
    0, 1, 2... as a physical transient archives them, or 1, 2...)."""
    from asterlite.dynamics.physical.system import Load, LoadHistory

    result = occ["RESULTAT"]
    depl = result.fields.get("DEPL")
    if depl is None:
        ctx.error("the result holds no DEPL field", "RESULTAT", occ)
    if list(result.numbering.dofs) != list(numbering.dofs):
        ctx.error("the result is not on the numbering of the matrices", "RESULTAT", occ)
    stored = np.asarray(result.times, dtype=float)
    position = {int(o): k for k, o in enumerate(result.order)}
    count = len(stored)
    by_order = [position.get(i) for i in range(1, count + 1)]
    values = np.asarray(depl, dtype=float)

    def field_at(t: float) -> np.ndarray:
        tolerance = 1e-9 * abs(t) if abs(t) > 1e-12 else 1e-12
        hits = np.flatnonzero(np.abs(stored - t) <= tolerance)
        if hits.size:
            return values[hits[0]]
        for i in range(1, count):
            left, right = by_order[i - 1], by_order[i]
            if right is None and i == count - 1:
                # orders 0..n-1: code_aster's last order i+1 is the last field
                right = count - 1
            if left is None or right is None:
                ctx.error(
                    f"the result's orders are not 0, 1, 2...: order {i if left is None else i + 1} "
                    "is missing where code_aster interpolates",
                    "RESULTAT",
                    occ,
                )
            if i == 1 and t < stored[left]:
                return values[left]
            if stored[left] <= t < stored[right]:
                alpha = (t - stored[left]) / (stored[right] - stored[left])
                return (1.0 - alpha) * values[left] + alpha * values[right]
            if i == count - 1 and t >= stored[right]:
                return values[right]
        ctx.error(f"the result has no field near INST={t:g}", "RESULTAT", occ)

    def history(times) -> np.ndarray:
        return np.array([field_at(float(t)) for t in np.atleast_1d(times)])

    rows = np.arange(numbering.n_dofs)
    return Load(np.zeros(numbering.n_dofs), float(occ["COEF_MULT"]), LoadHistory(rows, history))


def _numbered_history(ctx, history, numbering, occ):
    """A load history ``times -> (nodes, components, values)`` as a
    :class:`LoadHistory` on the numbering's DOFs (their rows found once)."""
    from asterlite.dynamics.physical.system import LoadHistory

    if history is None:
        return None
    nodes, components, _ = history(np.zeros(1))
    return LoadHistory(
        history_rows(ctx, numbering, nodes, components, occ), lambda times: history(times)[2]
    )


def history_rows(ctx, numbering, nodes, components, occ) -> np.ndarray:
    """The numbering's rows of a load history's (node, component) terms; an
    error at the occurrence's CHARGE for a term the numbering lacks."""
    rows = numbering.dof_indices(nodes, components)
    if np.any(rows < 0):
        k = int(np.flatnonzero(rows < 0)[0])
        ctx.error(
            f"load on DOFs the numbering does not have: {components[k]} of node "
            f"{numbering.mesh.node_names[nodes[k]]}",
            "CHARGE",
            occ,
        )
    return rows


def physical_supports(ctx, kw, numbering) -> list[dict]:
    """MULT_APPUI='OUI' supports of a physical transient: ψ_k (the static
    modes of MODE_STAT at the support nodes along DIRECTION) on the
    numbering, with the support's DEPL / VITE / ACCE functions."""

    supports = []
    for occ in kw.factor("EXCIT"):
        if occ.get("MULT_APPUI") != "OUI":
            continue
        for name in ("DEPL", "VITE", "ACCE"):
            if occ.get(name) is None:
                ctx.error(f"EXCIT MULT_APPUI='OUI' needs {name}", name, occ)
        shape = transfer(support_shape(ctx, kw, occ), kw["MODE_STAT"].numbering, numbering)
        motions = {name: occ[name] for name in ("DEPL", "VITE", "ACCE")}
        supports.append({"shape": shape, **motions})
    return supports


def initial_acceleration_computed(kw) -> bool:
    """code_aster (dltali / dltini) solves for the initial acceleration only
    when ETAT_INIT gives DEPL or VITE; from rest (no ETAT_INIT) the first
    step starts with a zero acceleration, whatever the load at t0."""
    occs = kw.factor("ETAT_INIT")
    if not occs:
        return False
    occ = occs[0]
    return occ.get("RESULTAT") is not None or any(
        occ.get(name) is not None for name in ("DEPL", "VITE")
    )


def physical_initial_state(ctx, kw, system):
    """(q, v, a or None, t of the state or None, first NUME_ORDRE)."""
    n = system.n_free
    q, v, a = np.zeros(n), np.zeros(n), None
    occs = kw.factor("ETAT_INIT")
    if not occs:
        return q, v, a, None, 0
    occ = occs[0]
    previous = occ.get("RESULTAT")
    if previous is not None:
        k = archived_index(ctx, occ, previous)
        fields = previous.fields
        q = system.restrict(fields["DEPL"][k])
        v = system.restrict(fields["VITE"][k]) if "VITE" in fields else v
        a = system.restrict(fields["ACCE"][k]) if "ACCE" in fields else None
        return q, v, a, float(previous.times[k]), int(previous.order[k])
    if occ.get("DEPL") is not None:
        q = system.restrict(occ["DEPL"].values)
    if occ.get("VITE") is not None:
        v = system.restrict(occ["VITE"].values)
    if occ.get("ACCE") is not None:
        a = system.restrict(occ["ACCE"].values)
    return q, v, a, None, 0


def physical_instants(ctx, kw, t_state):
    """The step instants (first = the initial state) and the nominal step."""
    occ = kw.factor("INCREMENT")[0]
    if occ.get("LIST_INST") is not None:
        values = list_values(occ["LIST_INST"])
        t_end = float(values[-1])
        if occ.get("NUME_FIN") is not None and occ["NUME_FIN"] < len(values):
            t_end = float(values[occ["NUME_FIN"]])
        if occ.get("INST_FIN") is not None:
            t_end = float(occ["INST_FIN"])
        t0 = float(values[0]) if t_state is None else t_state
        tol = 1.0e-9 * max(1.0, abs(t_end))
        inside = values[(values > t0 + tol) & (values <= t_end + tol)]
        times = np.concatenate([[t0], inside])
        dt = (float(values[-1]) - float(values[0])) / (len(values) - 1)
    else:
        dt = float(occ["PAS"])
        t0 = t_state if t_state is not None else float(occ.get("INST_INIT") or 0.0)
        t_end = float(occ["INST_FIN"])
        refuse_too_many_steps(ctx, occ, t0, t_end, dt)
        n_steps = int(round((t_end - t0) / dt))
        times = t0 + dt * np.arange(n_steps + 1)
        if n_steps >= 1:
            times[-1] = t_end if abs(times[-1] - t_end) < 1.0e-9 * dt else times[-1]
    if times.size < 2 or times[-1] <= times[0]:
        ctx.error(f"INST_FIN ({t_end}) must exceed the initial instant ({t0})", "INST_FIN", occ)
    return times, dt


def physical_archive_mask(kw, times):
    occs = kw.factor("ARCHIVAGE")
    if not occs:
        return archived_steps(times, 1, (), 0.0, True)
    occ = occs[0]
    instants = ()
    if occ.get("LIST_INST") is not None:
        instants = list_values(occ["LIST_INST"])
    elif occ.get("INST") is not None:
        instants = np.atleast_1d(np.asarray(occ["INST"], dtype=float))
    pas_arch = occ.get("PAS_ARCH")
    if pas_arch is None:
        pas_arch = 0 if len(instants) else 1
    if not len(instants):  # no instants: no precision to compare them with
        return archived_steps(times, int(pas_arch), instants, 0.0, True)
    relative = occ["CRITERE"] == "RELATIF"  # filled by the catalogue when instants are given
    return archived_steps(times, int(pas_arch), instants, occ["PRECISION"], relative)


def checked_diagonal_mass(ctx, system, scheme):
    inverse = system.diagonal_mass_inverse()
    if inverse is None:
        ctx.error(
            f"{scheme} on a physical basis needs a diagonal mass matrix "
            "(OPTION='MASS_MECA_DIAG'), as in code_aster",
            "MATR_MASS",
        )
    return inverse
