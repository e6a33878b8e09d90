"""RECU_FONCTION: a time history extracted from a result or a table.

Sources: a physical transient (RESULTAT + NOM_CHAM + node + NOM_CMP), a
generalized transient (RESU_GENE + NOM_CHAM + NUME_CMP_GENE, or + node +
NOM_CMP recombined on the basis), the local quantities of a shock
(RESU_GENE + GROUP_NO_CHOC / NOEUD_CHOC / INTITULE + PARA_Y), or two columns
of a table (TABLE + PARA_X + PARA_Y). INTERP_NUME='LIN' interpolates the
result between archived instants.

From a field (CHAM_GD + node or cell + NOM_CMP) the function is a constant,
as code_aster builds it: the field's value, NOM_PARA 'TOUTPARA', NOM_RESU
the component, extended as a constant on both sides.
"""

from __future__ import annotations

import numpy as np

from asterlite.concepts.function import ComplexFunction, Function
from asterlite.concepts.harmonic import DynaHarmo, HarmGene
from asterlite.concepts.modes import GeneralizedModes
from asterlite.concepts.table import Table
from asterlite.concepts.transient import DynaTrans, TranGene
from asterlite.errors import missing_name
from asterlite.legacy.v15 import relation_title
from asterlite.legacy.v15_names import GENERATED_NAME
from asterlite.post.harmonic import selection_from_keywords
from asterlite.post.restitution import (
    added_motions,
    as_tuple,
    computed_fields,
    element_value_history,
    field_component_value,
    recombine,
    select_instants,
    single_node,
    support_motion,
    values_of,
)


def run(ctx, kw):
    if isinstance(kw.peek("RESULTAT"), DynaHarmo) or isinstance(kw.peek("RESU_GENE"), HarmGene):
        return from_harmonic(ctx, kw)
    if kw.get("TABLE") is not None:
        x, y = from_table(ctx, kw)
        para, resu = kw["PARA_X"], kw["PARA_Y"]
        if kw["TABLE"].types.get(resu) == "C":
            # a complex column (VALE_C) makes a fonction_c, as the catalogue types it
            return ComplexFunction(
                x,
                np.asarray(y, dtype=complex),
                NOM_PARA=kw.get("NOM_PARA") or para,
                NOM_RESU=kw.get("NOM_RESU") or resu,
                INTERPOL=kw.get("INTERPOL", ("LIN", "LIN")),
                PROL_GAUCHE=kw.get("PROL_GAUCHE", "EXCLU"),
                PROL_DROITE=kw.get("PROL_DROITE", "EXCLU"),
            )
    elif kw.get("RESU_GENE") is not None:
        modal = isinstance(kw.peek("RESU_GENE"), GeneralizedModes)  # rfmge1: against FREQ
        para, resu, (x, y) = "FREQ" if modal else "INST", None, from_generalized(ctx, kw)
        resu = kw.peek("NOM_PARA_RESU") if modal else None
    elif kw.get("RESULTAT") is not None:
        # a physical result's function is named after its component (focrr0),
        # a generalized one's after its field (rfrgen)
        para, resu, (x, y) = "INST", kw.peek("NOM_CMP"), from_physical(ctx, kw)
    elif kw.get("CHAM_GD") is not None:
        return constant_from_field(ctx, kw)
    elif kw.get("INTE_SPEC") is not None:
        from asterlite.post.spectral_functions import function_of_interspectrum

        return function_of_interspectrum(ctx, kw)
    else:
        which = next((k for k in ("CHAM_GD", "BASE_ELAS_FLUI", "NAPPE") if k in kw), "source")
        ctx.unsupported(f"RECU_FONCTION from {which}", which, kw)
    if resu is None:
        # code_aster names a generalized ordinate after the field (DEPL)
        resu = kw.get("PARA_Y") or kw.get("NOM_CHAM") or kw.get("NOM_CMP") or "TOUTRESU"
    return Function(
        x,
        y,
        NOM_PARA=kw.get("NOM_PARA") or para,
        NOM_RESU=kw.get("NOM_RESU") or resu,
        INTERPOL=kw.get("INTERPOL", ("LIN", "LIN")),
        PROL_GAUCHE=kw.get("PROL_GAUCHE", "EXCLU"),
        PROL_DROITE=kw.get("PROL_DROITE", "EXCLU"),
    )


def from_harmonic(ctx, kw) -> ComplexFunction:
    """A complex function of the frequency (``fonction_c``, NOM_PARA 'FREQ')
    from a dyna_harmo (NOM_CHAM at a node component) or a harm_gene (a
    generalized component NUME_CMP_GENE, or a node component recombined on
    the modal basis)."""

    generalized = kw.get("RESU_GENE") is not None
    result = kw["RESU_GENE"] if generalized else kw["RESULTAT"]
    field = kw.get("NOM_CHAM") or "DEPL"  # rfhge2: DEPL when a harm_gene is read without it
    selection = selection_from_keywords(ctx, kw, result.frequencies, result.order)
    if not generalized and field not in result.fields and field in computed_fields(result):
        # a component of an element field CALC_CHAMP computed (complex values)
        values = selection.apply(element_value_history(ctx, kw, result, field))
        return _complex_function(kw, selection, values, kw.get("NOM_CMP") or field)
    if field not in result.fields:
        known = ", ".join([*result.fields, *computed_fields(result)])
        ctx.error(f"result has no field {field!r} (it has {known})", "NOM_CHAM", kw)
    states = selection.apply(result.fields[field])
    if generalized and kw.get("NUME_CMP_GENE") is not None:
        mode = int(kw["NUME_CMP_GENE"])
        if not 1 <= mode <= states.shape[1]:
            ctx.error(f"NUME_CMP_GENE={mode}: {states.shape[1]} generalized DOFs", None, kw)
        values = states[:, mode - 1]
    elif generalized:
        basis = result.basis
        if not hasattr(basis, "shape_at"):
            ctx.unsupported(
                "RECU_FONCTION at a node of a harm_gene whose basis is not a mode_meca",
                "GROUP_NO" if kw.get("GROUP_NO") is not None else "NOEUD",
                kw,
            )
        node = single_node(ctx, kw, basis.numbering.mesh)
        shape = basis.shape_at(node, kw.get("NOM_CMP"))
        values = states @ shape
    else:
        numbering = result.numbering
        node = single_node(ctx, kw, numbering.mesh)
        component = kw.get("NOM_CMP")
        try:
            row = numbering.dof_index(node, component)
        except KeyError:
            name = numbering.mesh.node_names[node]
            ctx.error(f"no DOF {component} on node {name}", "NOM_CMP", kw)
        values = states[:, row]
    # named after the component on a physical result (focrr0), the field on a harm_gene
    return _complex_function(
        kw, selection, values, field if generalized else kw.get("NOM_CMP") or field
    )


def _complex_function(kw, selection, values, name: str) -> ComplexFunction:
    return ComplexFunction(
        np.asarray(selection.times, dtype=float),
        np.asarray(values, dtype=complex),
        NOM_PARA=kw.get("NOM_PARA") or "FREQ",
        NOM_RESU=kw.get("NOM_RESU") or name,
        INTERPOL=kw.get("INTERPOL", ("LIN", "LIN")),
        PROL_GAUCHE=kw.get("PROL_GAUCHE", "EXCLU"),
        PROL_DROITE=kw.get("PROL_DROITE", "EXCLU"),
    )


def constant_from_field(ctx, kw) -> Function:
    """CHAM_GD: the constant function of one field value (code_aster's focste)."""

    value = field_component_value(ctx, kw, kw["CHAM_GD"])
    component = str(kw["NOM_CMP"])
    return Function(
        [1.0],
        [value],
        NOM_PARA=kw.get("NOM_PARA") or "TOUTPARA",
        NOM_RESU=kw.get("NOM_RESU") or component,
        INTERPOL=kw.get("INTERPOL", ("LIN", "LIN")),
        PROL_GAUCHE=kw.get("PROL_GAUCHE", "CONSTANT"),
        PROL_DROITE=kw.get("PROL_DROITE", "CONSTANT"),
    )


def instants(ctx, kw, times, order):
    """The instant selection of RECU_FONCTION (INTERP_NUME, not INTERPOL)."""
    kw.mark_used("TOUT_INST", "TOUT_ORDRE")  # every instant: the default selection
    inst = None
    if kw.get("LIST_INST") is not None:
        inst = values_of(kw["LIST_INST"])
    elif kw.get("INST") is not None:
        inst = values_of(kw["INST"])
    elif kw.get("LIST_PARA") is not None:
        inst = values_of(kw["LIST_PARA"])
    nume = kw.get("NUME_ORDRE")
    if kw.get("LIST_ORDRE") is not None:
        nume = kw["LIST_ORDRE"].values
    try:
        return select_instants(
            times,
            order,
            nume_ordre=as_tuple(nume) if nume is not None else None,
            inst=inst,
            interpolate=kw.get("INTERP_NUME", "NON") == "LIN",
            precision=float(kw.get("PRECISION", 1e-6)),
            criterion=kw.get("CRITERE", "RELATIF"),
        )
    except Exception as exc:  # CommandError: locate it on the call
        ctx.error(getattr(exc, "message", str(exc)), "LIST_INST", kw)


def from_physical(ctx, kw):
    result = kw["RESULTAT"]
    if not isinstance(result, DynaTrans):
        ctx.unsupported(f"RECU_FONCTION from a {result.aster_type}", "RESULTAT", kw)
    field = kw.get("NOM_CHAM")
    selection = instants(ctx, kw, result.times, result.order)
    computed = computed_fields(result)
    if field not in result.fields and field in computed:
        history = selection.apply(element_value_history(ctx, kw, result, field))
        if np.any(selection.weight):
            return selection.times, history
        # code_aster reads a field at the selected orders that hold it (rsutn2):
        # those CALC_CHAMP left out are skipped
        held = orders_holding(result, field)[selection.lower]
        return selection.times[held], history[held]
    if field not in result.fields:
        known = ", ".join([*result.fields, *computed])
        ctx.error(f"result has no field {field!r} (it has {known})", "NOM_CHAM", kw)
    node = single_node(ctx, kw, result.numbering.mesh)
    component = kw.get("NOM_CMP")
    try:
        row = result.numbering.dof_index(node, component)
    except KeyError:
        present = [c for n, c in result.numbering.dofs if n == node]
        where = f"node {node_name(result, node)}"
        ctx.error(missing_name("DOF", component, present, where), "NOM_CMP", kw)
    return selection.times, selection.apply(result.fields[field][:, row])


def orders_holding(result, name: str) -> np.ndarray:
    """Mask of the orders at which an element or smoothed nodal field of
    ``result`` is computed (CALC_CHAMP leaves the others NaN)."""
    field = (getattr(result, "node_fields", None) or {}).get(name)
    if field is None:
        field = result.element_fields[name]
    values = np.asarray(field.values).reshape(field.values.shape[0], -1)
    return ~np.all(np.isnan(values), axis=1)


def node_name(result, node: int) -> str:
    return result.numbering.mesh.node_names[node]


def from_generalized(ctx, kw):
    result = kw["RESU_GENE"]
    if isinstance(result, GeneralizedModes):
        return from_generalized_modes(ctx, kw, result)
    if not isinstance(result, TranGene):
        ctx.unsupported(f"RECU_FONCTION from a {result.aster_type}", "RESU_GENE", kw)
    if any(kw.get(k) is not None for k in ("GROUP_NO_CHOC", "NOEUD_CHOC", "INTITULE")):
        return from_shock(ctx, kw, result)
    field = kw.get("NOM_CHAM", "DEPL")
    if field == "PTEM":  # the time step that led to each archived instant
        if result.step_sizes is None:
            ctx.error("this tran_gene holds no step history (PTEM)", "NOM_CHAM", kw)
        selection = instants(ctx, kw, result.times, result.order)
        return selection.times, selection.apply(result.step_sizes)
    if field not in ("DEPL", "VITE", "ACCE"):
        ctx.unsupported(f"NOM_CHAM={field!r} from a tran_gene", "NOM_CHAM", kw)
    if kw.get("ACCE_MONO_APPUI") is not None and field != "ACCE":
        ctx.error("ACCE_MONO_APPUI goes with NOM_CHAM='ACCE'", "ACCE_MONO_APPUI", kw)
    selection = instants(ctx, kw, result.times, result.order)
    states = selection.apply(getattr(result, field.lower()))
    if kw.get("NUME_CMP_GENE") is not None:
        mode = int(kw["NUME_CMP_GENE"])
        if not 1 <= mode <= result.n_modes:
            ctx.error(f"NUME_CMP_GENE={mode}: the basis has {result.n_modes} modes", None, kw)
        return selection.times, states[:, mode - 1]
    node = single_node(ctx, kw, result.basis.numbering.mesh)
    shape = result.basis.shape_at(node, kw.get("NOM_CMP"))
    values = recombine(shape[None, :], states)[:, 0]
    for keyword in ("MULT_APPUI", "CORR_STAT"):
        if kw.get(keyword) == "OUI":
            values = values + added_part(ctx, kw, result, node, field, selection.times, keyword)
    if kw.get("ACCE_MONO_APPUI") is not None:
        # the drive acceleration, whatever the component (as code_aster adds it)
        values = values + kw["ACCE_MONO_APPUI"].evaluate(selection.times)
    return selection.times, values


def from_generalized_modes(ctx, kw, modes):
    """A mode_gene, abscissa FREQ, as code_aster's rfmge1 stores it. Its two
    loops write one slot off the function's two halves (abscissas 0..n-1,
    ordinates n..2n-1), and the function keeps what they leave:

    - NOM_PARA_RESU: the abscissas are f_1..f_n, the ordinates written from
      slot n-1 on, so the parameters of modes 2..n and a last 0 (mode 1's
      value is overwritten by f_n);
    - NOM_CHAM + NUME_CMP_GENE: the abscissas written from slot 1 on, so 0,
      f_1..f_(n-1), and f_n in the first ordinate slot, then the components
      of modes 2..n."""
    if kw.get("NUME_ORDRE") is not None:
        wanted = [int(n) for n in as_tuple(kw["NUME_ORDRE"])]
        if any(not 1 <= n <= modes.n_modes for n in wanted):
            ctx.error(f"NUME_ORDRE outside 1..{modes.n_modes}", "NUME_ORDRE", kw)
        picked = np.asarray(wanted, dtype=int) - 1
    else:
        kw.mark_used("TOUT_ORDRE")  # every mode: the default
        picked = np.arange(modes.n_modes)
    frequencies = np.asarray(modes.frequencies, dtype=float)[picked]
    ctx.log("RECU_FONCTION of a mode_gene: values laid out as code_aster's rfmge1 leaves them")
    if kw.get("NOM_PARA_RESU") is not None:
        name = kw["NOM_PARA_RESU"]
        known = {
            "FREQ": modes.frequencies,
            "MASS_GENE": modes.generalized_mass,
            "RIGI_GENE": modes.generalized_stiffness,
            **modes.parameters,
        }
        if name not in known or np.size(known[name]) != modes.n_modes:
            ctx.error(f"the mode_gene has no parameter {name!r}", "NOM_PARA_RESU", kw)
        values = np.asarray(known[name], dtype=float)[picked]
        return frequencies, np.concatenate([values[1:], [0.0]])
    field = kw.get("NOM_CHAM")
    if field != "DEPL":
        ctx.unsupported(f"NOM_CHAM={field!r} of a mode_gene (DEPL only)", "NOM_CHAM", kw)
    if kw.get("NUME_CMP_GENE") is None:
        ctx.unsupported(
            "RECU_FONCTION of a mode_gene at a node component (SQUELETTE / SOUS_STRUC)",
            "NOM_CMP",
            kw,
        )
    component = int(kw["NUME_CMP_GENE"])
    if not 1 <= component <= modes.vectors.shape[0]:
        ctx.error(
            f"NUME_CMP_GENE={component}: {modes.vectors.shape[0]} generalized DOFs",
            "NUME_CMP_GENE",
            kw,
        )
    values = np.asarray(modes.vectors, dtype=float)[component - 1, picked]
    abscissas = np.concatenate([[0.0], frequencies[:-1]])
    return abscissas, np.concatenate([frequencies[-1:], values[1:]])


def added_part(ctx, kw, result, node, field, times, keyword) -> np.ndarray:
    """MULT_APPUI / CORR_STAT='OUI': the support motion or static correction
    added to the relative value."""
    supports = added_motions(ctx, kw, result, keyword)
    try:
        row = result.basis.numbering.dof_index(node, kw.get("NOM_CMP"))
    except KeyError:
        return np.zeros(len(times))
    return support_motion(supports, [row], times, field)[:, 0]


def find_shock(ctx, kw, result):
    """The ShockHistory named by INTITULE, NOEUD_CHOC or GROUP_NO_CHOC."""
    if kw.get("INTITULE") is not None:
        wanted = str(kw["INTITULE"]).strip()
        matches = [s for s in result.shocks if s.name.strip() == wanted]
        key = "INTITULE"
        if not matches:  # one occurrence over several cells: each shock bears its title
            matches = [s for s in result.shocks if occurrence_title(s.name) == wanted]
            if matches and kw.get("NOEUD_CHOC") is not None:
                matches = [first_titled_on_node(ctx, kw, matches[0])]
        if not matches:  # code_aster 15's form of a relation's title
            matches = shocks_titled_as_v15(ctx, kw, result, shock_mesh(ctx, kw, result))
        if matches and kw.get("SOUS_STRUC") is not None:
            _check_titled_node(ctx, kw, result, matches[0])
    else:
        if kw.get("GROUP_NO_CHOC") is not None:
            mesh = shock_mesh(ctx, kw, result)
            key = "GROUP_NO_CHOC"
            group = kw[key]
            if group not in mesh.node_groups:
                ctx.error(missing_name("node group", group, mesh.node_groups), key, kw)
            names = {mesh.node_names[int(i)] for i in mesh.node_groups[group]}
        else:
            key = "NOEUD_CHOC"
            names = {str(kw[key])}
        matches = [s for s in result.shocks if s.node_1 in names] or [
            s for s in result.shocks if s.node_2 in names
        ]
    if not matches:
        known = ", ".join(f"{s.name} ({s.node_1})" for s in result.shocks) or "none"
        ctx.error(f"no localized nonlinearity matches (known: {known})", key, kw)
    return matches[0]


def occurrence_title(name: str) -> str | None:
    """The INTITULE of the DYNA_VIBRA occurrence a shock came from when that
    occurrence made several (asterlite names them TITLE_1, TITLE_2...)."""
    title, _, number = name.strip().rpartition("_")
    return title if title and number.isdigit() else None


def first_titled_on_node(ctx, kw, shock):
    """code_aster gives every shock of a multi-cell occurrence the occurrence's
    INTITULE and, with NOEUD_CHOC, takes the first of them, which must have
    that node as its node 1 or node 2 (focrch)."""
    node = str(kw["NOEUD_CHOC"])
    if node not in (shock.node_1, shock.node_2):
        ctx.error(
            f"node {node!r} is not a node of the first shock titled {kw['INTITULE']!r} "
            f"({shock.node_1}, {shock.node_2})",
            "NOEUD_CHOC",
            kw,
        )
    return shock


def shocks_titled_as_v15(ctx, kw, result, mesh) -> list:
    """The nonlinearities INTITULE names in code_aster 15's form (node name and
    generated function name: asterlite.legacy.v15.relation_title)."""
    title, why = relation_title(
        str(kw["INTITULE"]), mesh.node_index, getattr(ctx.session, "generated_names", None)
    )
    if title is None:
        if why:
            ctx.error(why, "INTITULE", kw)
        return []
    ctx.log(f"note: INTITULE {kw['INTITULE']!r} (code_aster 15) is {title!r} today")
    return [s for s in result.shocks if s.name.strip() == title.strip()]


def shock_quantity(shock, name: str) -> np.ndarray | None:
    """A local quantity by code_aster name; internal variables may be archived
    as VINTk, VARIk or one VARI/VINT array (n_archived, n_vari)."""
    if name in shock.fields:
        return np.asarray(shock.fields[name])
    if name.startswith("VINT") and name[4:].isdigit():
        k = int(name[4:])
        if f"VARI{k}" in shock.fields:
            return np.asarray(shock.fields[f"VARI{k}"])
        for key in ("VINT", "VARI"):
            array = shock.fields.get(key)
            if array is not None and np.ndim(array) == 2 and k <= np.shape(array)[1]:
                return np.asarray(array)[:, k - 1]
    return None


def shock_instants(ctx, kw, result):
    """LIST_PARA: the shock quantities interpolated linearly at those instants
    (code_aster interpolates both parameters in time); otherwise the archived
    instants (or the usual instant keywords)."""
    if kw.get("LIST_PARA") is None:
        return instants(ctx, kw, result.times, result.order)
    try:
        return select_instants(
            result.times, result.order, inst=values_of(kw["LIST_PARA"]), interpolate=True
        )
    except Exception as exc:  # CommandError: locate it on the call
        ctx.error(getattr(exc, "message", str(exc)), "LIST_PARA", kw)


def on_second_node(ctx, kw, shock) -> bool:
    """Whether NOEUD_CHOC / GROUP_NO_CHOC names the shock's second node (its
    local coordinates DXLOC... are then those of node 2)."""
    if kw.get("NOEUD_CHOC") is not None:
        names = {str(kw["NOEUD_CHOC"])}
    elif kw.get("GROUP_NO_CHOC") is not None:
        mesh = shock_mesh(ctx, kw, kw["RESU_GENE"])
        names = {mesh.node_names[int(i)] for i in mesh.node_groups.get(kw["GROUP_NO_CHOC"], ())}
    else:
        return False
    return shock.node_1 not in names and shock.node_2 in names


def _check_titled_node(ctx, kw, result, shock) -> None:
    """With INTITULE, code_aster only checks NOEUD_CHOC and SOUS_STRUC against
    the relation it names (focrch's alarms): the substructure must exist, and
    the node be the relation's and the substructure's."""
    mesh = shock_mesh(ctx, kw, result)
    node = kw.get("NOEUD_CHOC")
    if node is None:
        return
    node = str(node)
    if node not in (shock.node_1, shock.node_2) or node not in mesh.node_index:
        ctx.log(
            f"alarm: NOEUD_CHOC {node} of SOUS_STRUC {kw['SOUS_STRUC']} is not a node of "
            f"the nonlinearity {shock.name.strip()}"
        )


def shock_mesh(ctx, kw, result):
    """The mesh that names a nonlinearity's nodes: the basis's, or on a model
    of substructures (a mode_gene basis) that of the substructure SOUS_STRUC."""
    numbering = result.basis.numbering
    mesh = getattr(numbering, "mesh", None)
    if mesh is not None:
        return mesh
    name = kw.get("SOUS_STRUC")
    if name is None:
        ctx.error("the basis is a model of substructures: name the node's SOUS_STRUC", None, kw)
    for sub in numbering.model.substructures:
        if sub.name == name:
            return sub.macro.mesh
    known = ", ".join(sub.name for sub in numbering.model.substructures)
    ctx.error(f"no substructure {name!r} in the generalized model ({known})", "SOUS_STRUC", kw)


def from_shock(ctx, kw, result):
    shock = find_shock(ctx, kw, result)
    para_x, para_y = kw.get("PARA_X", "INST"), kw.get("PARA_Y")
    selection = shock_instants(ctx, kw, result)
    second = on_second_node(ctx, kw, shock)

    def quantity(name, key):
        if name == "INST":
            return selection.times
        if second and name in ("DXLOC", "DYLOC", "DZLOC"):
            name = f"{name}_2"
        values = shock_quantity(shock, name)
        if values is None:
            known = ", ".join(sorted(shock.fields)) or "none"
            ctx.error(f"shock {shock.name} has no quantity {name!r} (it has {known})", key, kw)
        return selection.apply(values)

    return quantity(para_x, "PARA_X"), quantity(para_y, "PARA_Y")


def from_table(ctx, kw):
    table: Table = kw["TABLE"]
    for occ in kw.factor("FILTRE"):
        table = filter_table(ctx, table, occ)
    for key in ("PARA_X", "PARA_Y"):
        if kw[key] not in table.types:
            ctx.error(f"table has no parameter {kw[key]!r}", key, kw)
    xs, ys = table.column(kw["PARA_X"]), table.column(kw["PARA_Y"])
    kept = [i for i, x in enumerate(xs) if x is not None]
    return (
        np.array([xs[i] for i in kept], dtype=float),
        np.array([np.nan if ys[i] is None else ys[i] for i in kept]),
    )


def filter_table(ctx, table: Table, occ) -> Table:
    """One FILTRE occurrence applied to a table (shared by the TABLE commands)."""
    name = occ["NOM_PARA"]
    if name not in table.types:
        ctx.error(
            f"table has no parameter {name!r} (it has {', '.join(table.columns)})", "NOM_PARA", occ
        )
    value = None
    for key in ("VALE", "VALE_I", "VALE_K", "VALE_C"):
        if occ.get(key) is not None:
            value = occ[key]
            break
    if occ.get("VALE_K") is not None and value not in table.column(name):
        value = generated_name_as_today(ctx, value, occ)
    return table.filtered(
        name,
        occ.get("CRIT_COMP", "EQ"),
        value,
        float(occ.get("PRECISION", 1e-3)),
        occ.get("CRITERE", "RELATIF"),
    )


def generated_name_as_today(ctx, value, occ):
    """A code_aster 15 object name quoted in a FILTRE ('00000027'), as the deck
    name of the concept it stands for, which asterlite's tables hold (when the
    session followed code_aster 15's names that far; else the value as given)."""
    names = getattr(ctx.session, "generated_names", None)
    if not isinstance(value, str) or names is None or not GENERATED_NAME.match(value.strip()):
        return value
    concept, why = names.lookup(value.strip())
    name = getattr(concept, "name", None)
    if not name:
        ctx.error(f"{value!r} is a name code_aster 15 generates: {why or 'not a concept'}",
                  "VALE_K", occ)  # fmt: skip
    ctx.log(f"note: {value!r} (code_aster 15's name of {name}) filtered as {name!r}")
    return name
