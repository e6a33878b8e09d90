"""DYNA_VIBRA, TYPE_CALCUL='HARM' (code_aster's comdlh): the harmonic response
at a list of frequencies, on a generalized basis (``harm_gene``) or on the
assembled physical matrices (``dyna_harmo``). commands/dyna_vibra.py
dispatches here.

This module reads the keywords into matrices, :class:`HarmonicLoad`
excitations and a frequency list; the solves live in ``asterlite.harmonic``
(``modal.solve``: all frequencies in batches; ``physical.solve``: one
sparse factorisation per frequency).

- Frequencies: FREQ or LIST_FREQ, in the order given (NUME_ORDRE 1..n).
- Fields: NOM_CHAM, or DEPL, VITE and ACCE (TOUT_CHAM='OUI' or nothing
  given): VITE = iω u, ACCE = -ω² u.
- Matrices: (K + iωC - ω²M) u = F; K may be complex (RIGI_MECA_HYST,
  RIGI_GENE_C: hysteretic damping); C is MATR_AMOR, or on a generalized
  basis AMOR_MODAL's diagonal 2 ξ_i sqrt(|k_ii m_ii|) (dl_CreateDampMatrix:
  missing ratios repeat the last one, extra ones are ignored).
- EXCIT: VECT_ASSE / CHARGE (physical) or VECT_ASSE_GENE times
  COEF_MULT[_C] or FONC_MULT[_C](f), times e^{i PHAS_DEG π/180} and ω^PUIS_PULS.
  A CHARGE's imposed values (AFFE_CHAR_CINE[_F], DDL_IMPO), constant or
  functions of FREQ evaluated at each frequency, are scaled likewise and
  lifted into the right-hand side.
- RESULTAT with reuse=: the new frequencies stored after the result's own,
  NUME_ORDRE going on from its last one (comdlh, resu60); without reuse= it is
  not read.
- EXCIT_RESU: COEF_MULT_C times the DEPL field of a previous harmonic result
  at the same frequency (relative precision 1e-6, dyexre).
"""

from __future__ import annotations

import numpy as np

from asterlite.concepts.assembly import ComplexAssembledMatrix, MechanicalLoad
from asterlite.concepts.harmonic import HARMONIC_FIELDS, DynaHarmo, HarmGene
from asterlite.errors import CommandError, NumericalError
from asterlite.fem.lagrange_layout import constrained_rows, lagrange_coefficient
from asterlite.fem.loads import load_terms
from asterlite.harmonic import HarmonicLoad, derived_fields
from asterlite.harmonic import modal as modal_solver
from asterlite.harmonic.fields import TWO_PI
from asterlite.harmonic.loads import SweepLoads
from asterlite.harmonic.modal import SingularSystem


def run_harmonic(ctx, kw):
    previous = continued_result(ctx, kw)
    frequencies = frequency_list(ctx, kw)
    names = field_names(kw)
    if kw.get("BASE_CALCUL") == "GENE":
        result = generalized(ctx, kw, frequencies, names)
    else:
        result = physical(ctx, kw, frequencies, names)
    if previous is None:
        return result
    return append_frequencies(ctx, kw, previous, result)


# ----------------------------------------------------------------------------- continuation


def continued_result(ctx, kw):
    """The result a reuse= call continues (RESULTAT, which must be it), or None.

    code_aster (comdlh) reads RESULTAT only for a reentrant call: its
    frequencies are then added after those already stored; without reuse=
    the call makes a new result and RESULTAT is not read."""
    given = kw.get("RESULTAT")
    if ctx.reuse is None:
        if given is not None:
            kw.mark_used("RESULTAT")  # code_aster does not read it without reuse=
            ctx.log("RESULTAT without reuse=: a new result (RESULTAT is read only to continue it)")
        return None
    if given is None:
        ctx.error("reuse= continues a harmonic result: give it as RESULTAT", "RESULTAT", kw)
    if given is not ctx.reuse:
        ctx.error("RESULTAT must be the result given as reuse=", "RESULTAT", kw)
    wanted = HarmGene if kw.get("BASE_CALCUL") == "GENE" else DynaHarmo
    if not isinstance(given, wanted):
        ctx.error(
            f"RESULTAT is a {given.aster_type}; BASE_CALCUL={kw.get('BASE_CALCUL')!r} "
            f"continues a {wanted.aster_types[0]}",
            "RESULTAT",
            kw,
        )
    return given


def append_frequencies(ctx, kw, previous, new):
    """``previous`` with the frequencies of ``new`` stored after its own
    (NUME_ORDRE continuing from its last one), as comdlh / resu60 do."""
    if new.numbering is not previous.numbering:
        ctx.error("the matrices are not on the numbering of RESULTAT", "RESULTAT", kw)
    if set(new.fields) != set(previous.fields):
        # resu60 stops the same way (ALGORITH17_25) on a generalized basis
        ctx.error(
            f"RESULTAT holds {', '.join(previous.fields)}; this call computes "
            f"{', '.join(new.fields)}: give the same NOM_CHAM",
            "NOM_CHAM",
            kw,
        )
    if isinstance(previous, DynaHarmo) and previous.element_fields:
        ctx.unsupported(
            "continuing a dyna_harmo that holds CALC_CHAMP fields "
            f"({', '.join(previous.element_fields)})",
            "RESULTAT",
            kw,
        )
    last = int(previous.order[-1]) if np.size(previous.order) else 0
    orders = last + 1 + (np.asarray(new.order) - int(new.order[0]))
    previous.fields = {
        name: np.concatenate([previous.fields[name], new.fields[name]]) for name in previous.fields
    }
    previous.frequencies = np.concatenate([previous.frequencies, new.frequencies])
    previous.order = np.concatenate([np.asarray(previous.order), orders])
    if isinstance(previous, DynaHarmo):
        previous.reactions = _joined_reactions(previous.reactions, new.reactions)
    ctx.log(
        f"RESULTAT continued: {np.size(new.frequencies)} frequencies added after "
        f"NUME_ORDRE {last} ({np.size(previous.frequencies)} stored)"
    )
    return previous


def _joined_reactions(old, new):
    if old is None or new is None or not np.array_equal(old[0], new[0]):
        return None  # unknown for part of the frequencies: none known
    return (old[0], np.concatenate([old[1], new[1]]))


# ----------------------------------------------------------------------------- common readers


def frequency_list(ctx, kw) -> np.ndarray:
    if kw.get("LIST_FREQ") is not None:
        values = np.asarray(kw["LIST_FREQ"].values, dtype=float)
    else:
        values = np.atleast_1d(np.asarray(kw["FREQ"], dtype=float))
    if values.size == 0:
        ctx.error("no frequency to compute", "FREQ", kw)
    return values


def field_names(kw) -> tuple[str, ...]:
    """NOM_CHAM in the deck's order, else DEPL, VITE, ACCE (comdlh's default,
    which TOUT_CHAM='OUI' asks for explicitly)."""
    kw.mark_used("TOUT_CHAM")  # its only value, 'OUI', is the default set of fields
    names = kw.get("NOM_CHAM")
    if not names:
        return HARMONIC_FIELDS
    names = (names,) if isinstance(names, str) else tuple(names)
    return tuple(dict.fromkeys(names))


def multiplier(ctx, occ):
    """(g, label) of an EXCIT occurrence: a number or a function of FREQ."""
    for key in ("COEF_MULT", "COEF_MULT_C"):
        if occ.get(key) is not None:
            return occ[key], key
    for key in ("FONC_MULT", "FONC_MULT_C"):
        function = occ.get(key)
        if function is None:
            continue
        parameters = getattr(function, "NOM_PARA", None)
        if hasattr(function, "VALE") and not isinstance(parameters, str):
            # a formula: code_aster evaluates it at FREQ=f (fointe with 'FREQ')
            if tuple(parameters) != ("FREQ",):
                ctx.error(
                    f"{key}: the formula {function.name or ''} must depend on FREQ only "
                    f"(it takes {', '.join(parameters)})",
                    key,
                    occ,
                )
        return function, key
    return 1.0, "COEF_MULT"


def harmonic_load(ctx, occ, vector, label) -> HarmonicLoad:
    value, _ = multiplier(ctx, occ)
    return HarmonicLoad(
        vector=vector,
        multiplier=value,
        phase_deg=float(occ["PHAS_DEG"]),
        power=int(occ["PUIS_PULS"]),
        label=label,
    )


def result_excitations(ctx, kw, frequencies, numbering, size) -> np.ndarray | None:
    """EXCIT_RESU: Σ COEF_MULT_C · DEPL(f) of previous results (n_freq, size)."""
    occs = kw.factor("EXCIT_RESU")
    if not occs:
        return None
    out = np.zeros((frequencies.size, size), dtype=complex)
    for occ in occs:
        previous = occ["RESULTAT"]
        if getattr(previous, "numbering", None) is not numbering and (
            getattr(previous.numbering, "dofs", None) != getattr(numbering, "dofs", ())
        ):
            ctx.error("the result is not on the numbering of the matrices", "RESULTAT", occ)
        depl = previous.fields.get("DEPL")
        if depl is None:
            ctx.error("the result holds no DEPL field", "RESULTAT", occ)
        stored = np.asarray(previous.frequencies, dtype=float)
        for k, f in enumerate(frequencies):
            tolerance = 1e-6 * abs(f) if abs(f) > 1e-12 else 1e-12
            hits = np.flatnonzero(np.abs(stored - f) <= tolerance)
            if hits.size == 0:
                ctx.error(f"the result has no field at {f:g} Hz", "RESULTAT", occ)
            out[k] += complex(occ["COEF_MULT_C"]) * depl[hits[0]]
    return out


def numerical_error(ctx, error: SingularSystem):
    raise NumericalError(str(error), ctx.location, f"{ctx.command}/FREQ") from None


# ----------------------------------------------------------------------------- generalized


def generalized(ctx, kw, frequencies, names):
    mass_matrix, stiffness_matrix = kw["MATR_MASS"], kw["MATR_RIGI"]
    numbering = mass_matrix.numbering
    for key in ("MATR_RIGI", "MATR_AMOR"):
        matrix = kw.get(key)
        if matrix is not None and matrix.numbering is not numbering:
            ctx.error(f"{key} is not on the generalized numbering of MATR_MASS", key, kw)
    mass = np.asarray(mass_matrix.matrix, dtype=float)
    stiffness = np.asarray(stiffness_matrix.matrix)
    stiffness = stiffness.astype(complex if np.iscomplexobj(stiffness) else float)
    n = mass.shape[0]
    if stiffness.shape != (n, n):
        ctx.error("MATR_MASS and MATR_RIGI do not have the same size", "MATR_RIGI", kw)
    damping = None
    if kw.get("MATR_AMOR") is not None:
        damping = np.asarray(kw["MATR_AMOR"].matrix, dtype=float)
    modal = modal_damping(ctx, kw, mass, stiffness)
    if modal is not None:
        damping = modal  # comdlh: AMOR_MODAL builds the damping matrix it uses
    loads = []
    for i, occ in enumerate(kw.factor("EXCIT"), start=1):
        vector = occ["VECT_ASSE_GENE"]
        if vector.numbering is not numbering and np.size(vector.values) != n:
            ctx.error(
                f"VECT_ASSE_GENE has {np.size(vector.values)} values for {n} generalized DOFs",
                "VECT_ASSE_GENE",
                occ,
            )
        loads.append(harmonic_load(ctx, occ, np.asarray(vector.values), f"EXCIT[{i}]"))
    extra = result_excitations(ctx, kw, frequencies, numbering, n)
    try:
        rhs = SweepLoads.of(loads, frequencies, n, extra)
    except ValueError as error:
        ctx.error(str(error), "EXCIT", kw)
    constraints = None
    if np.size(getattr(numbering, "constraints", ())):  # a coupled generalized model
        from asterlite.substructure.coupling import null_space_basis

        constraints = null_space_basis(np.asarray(numbering.constraints, dtype=float), n)
    try:
        depl, info = modal_solver.solve(mass, stiffness, damping, frequencies, rhs, constraints)
    except SingularSystem as error:
        numerical_error(ctx, error)
    extra_note = f", {info.redone} solved again directly" if info.redone else ""
    ctx.log(
        f"DYNA_VIBRA HARM GENE: {frequencies.size} frequencies "
        f"[{frequencies.min():g}, {frequencies.max():g}] Hz, {n} generalized DOFs"
        + (f" ({constraints.shape[1]} independent)" if constraints is not None else "")
        + f", {info.method} solve{extra_note}"
    )
    return HarmGene(
        basis=getattr(mass_matrix, "basis", None),
        numbering=numbering,
        frequencies=frequencies,
        order=np.arange(1, frequencies.size + 1),
        fields=derived_fields(depl, frequencies, names),
        info={"method": info.method},
    )


def modal_damping(ctx, kw, mass, stiffness) -> np.ndarray | None:
    """AMOR_MODAL on a generalized basis (dl_CreateDampMatrix): the diagonal
    matrix 2 ξ_i sqrt(|k_ii m_ii|)."""
    occs = kw.factor("AMOR_MODAL")
    if not occs:
        return None
    occ = occs[0]
    ratios = occ.get("AMOR_REDUIT")
    if ratios is None and occ.get("LIST_AMOR") is not None:
        ratios = occ["LIST_AMOR"].values
    if ratios is None:
        return None
    ratios = np.atleast_1d(np.asarray(ratios, dtype=float))
    n = mass.shape[0]
    if ratios.size > n:
        ctx.log(
            f"warning: AMOR_MODAL gives {ratios.size} damping ratios for {n} modes: "
            "the extra ones are ignored"
        )
        ratios = ratios[:n]
    elif ratios.size < n:
        ctx.log(f"AMOR_MODAL: the {n - ratios.size} last modes take the last damping ratio given")
        ratios = np.concatenate([ratios, np.full(n - ratios.size, ratios[-1])])
    critical = 2.0 * np.sqrt(np.abs(np.diagonal(stiffness) * np.diagonal(mass)))
    return np.diag(ratios * critical)


# ----------------------------------------------------------------------------- physical


def physical(ctx, kw, frequencies, names):
    from asterlite.fem.constraints import eliminate
    from asterlite.harmonic import physical as physical_solver

    mass_matrix, stiffness_matrix = kw["MATR_MASS"], kw["MATR_RIGI"]
    for key in ("MATR_MASS", "MATR_RIGI", "MATR_AMOR"):
        matrix = kw.get(key)
        if matrix is not None and matrix.satisfies("matr_asse_pres_c"):
            ctx.unsupported("an acoustic harmonic response (matr_asse_pres_c)", key, kw)
    if kw.factor("AMOR_MODAL"):
        # code_aster stops too (DYNALINE1_95): modal damping needs a generalized basis
        ctx.error("AMOR_MODAL needs generalized matrices (BASE_CALCUL='GENE')", "AMOR_MODAL", kw)
    numbering = stiffness_matrix.numbering
    for key in ("MATR_MASS", "MATR_AMOR"):
        matrix = kw.get(key)
        if matrix is not None and matrix.numbering is not numbering:
            ctx.error(f"{key} is not on the numbering of MATR_RIGI", key, kw)
    damping = kw["MATR_AMOR"].matrix if kw.get("MATR_AMOR") is not None else None
    b_matrix, _ = numbering.constraint_matrix(rhs_in_time=True, rhs_in_frequency=True)
    # the relations' values are not those of the harmonic problem: code_aster's
    # Lagrange right-hand side is zero unless an EXCIT CHARGE imposes values
    elimination = eliminate(b_matrix, np.zeros(b_matrix.shape[0]), numbering.n_dofs)
    sweep = physical_solver.prepare(
        elimination, stiffness_matrix.matrix, mass_matrix.matrix, damping
    )
    loads = physical_loads(ctx, kw, numbering, stiffness_matrix)
    vectors = (
        np.array([load.vector for load in loads]) if loads else np.zeros((0, numbering.n_dofs))
    )
    coefficients = (
        np.column_stack([load.coefficients(frequencies) for load in loads])
        if loads
        else np.zeros((frequencies.size, 0), dtype=complex)
    )
    # the applied loads (the lifting of imposed motion aside) on the DOFs the
    # dualised relations hold: the reactions there give code_aster's multipliers
    rows = constrained_rows(numbering)
    forces = coefficients @ vectors[:, rows] if loads else np.zeros((frequencies.size, rows.size))
    imposed = imposed_motion(ctx, kw, numbering, elimination, frequencies)
    if imposed is not None:
        # u = u_imposed + T q: the imposed part moves to the right-hand side
        lift_vectors, lift_coefficients = lifting_loads(
            *imposed, frequencies, stiffness_matrix, mass_matrix, kw.get("MATR_AMOR")
        )
        vectors = np.vstack([vectors.astype(complex), lift_vectors])
        coefficients = np.hstack([coefficients, lift_coefficients])
    extra = result_excitations(ctx, kw, frequencies, numbering, numbering.n_dofs)
    if extra is not None:  # one load vector per frequency, solved as such
        forces = forces + extra[:, rows]
    try:
        depl, info = physical_solver.solve(
            sweep, frequencies, vectors, coefficients, per_frequency=extra
        )
    except SingularSystem as error:
        numerical_error(ctx, error)
    if imposed is not None:
        depl = depl + imposed[1] @ imposed[0].T
    reactions = physical_solver.constraint_reactions(
        rows, depl, forces, frequencies, stiffness_matrix.matrix, mass_matrix.matrix, damping
    )
    hysteretic = isinstance(stiffness_matrix, ComplexAssembledMatrix)
    ctx.log(
        f"DYNA_VIBRA HARM PHYS: {frequencies.size} frequencies "
        f"[{frequencies.min():g}, {frequencies.max():g}] Hz, {info['n_free']} free DOFs of "
        f"{numbering.n_dofs}{', complex stiffness' if hysteretic else ''}, "
        f"{_solvers(info)}, {info['seconds']:.3f} s"
    )
    return DynaHarmo(
        numbering=numbering,
        frequencies=frequencies,
        order=np.arange(1, frequencies.size + 1),
        fields=derived_fields(depl, frequencies, names),
        model=kw.get("MODELE") or getattr(stiffness_matrix, "model", None),
        materials=kw.get("CHAM_MATER") or getattr(stiffness_matrix, "materials", None),
        characteristics=kw.get("CARA_ELEM") or getattr(stiffness_matrix, "characteristics", None),
        mass_matrix=mass_matrix,
        reactions=(rows, reactions),
        lagrange_beta=lagrange_coefficient(stiffness_matrix.matrix),
    )


def imposed_motion(ctx, kw, numbering, elimination, frequencies):
    """The displacements EXCIT CHARGE imposes (AFFE_CHAR_CINE[_F], or
    DDL_IMPO of a dualised load), each scaled by its occurrence's
    coefficient, as code_aster scales the imposed values (ascavc): (U
    (n_dofs, n_k), C (n_freq, n_k)), the motion being C @ U.T; None when no
    occurrence imposes a value. Constant values make one column; values
    given as a function of FREQ one column per function (and point, for a
    function of X, Y, Z too), its value at each frequency in C."""
    row_of = {id(relation): row for row, relation in enumerate(numbering.relations)}
    particulars, motions = [], []
    for i, occ in enumerate(kw.factor("EXCIT")):
        charge = occ.get("CHARGE")
        if charge is None or not any(
            relation.rhs != 0.0 or relation.rhs_in_frequency is not None
            for relation in charge.relations
        ):
            continue
        constant = np.zeros(len(numbering.relations))
        in_frequency: dict = {}
        for relation in charge.relations:
            row = row_of.get(id(relation))
            if row is None:
                ctx.error(
                    "the values this load imposes are not among the constraints of the "
                    "matrices: assemble them with it (ASSE_MATRICE CHAR_CINE, or the load "
                    "in CALC_MATR_ELEM CHARGE)",
                    "CHARGE",
                    occ,
                )
            value = relation.rhs_in_frequency
            if value is None:
                constant[row] = relation.rhs
            else:
                # u = g(f) with the relation's coefficient: the rhs is coefficient g(f)
                coefficient = relation.terms[0][2]
                in_frequency.setdefault(value.key, (value, []))[1].append((row, coefficient))
        scale = harmonic_load(ctx, occ, None, f"EXCIT[{i + 1}]").coefficients(frequencies)
        if np.any(constant):
            particulars.append(elimination.particular(constant))
            motions.append(scale)
        for value, rows in in_frequency.values():
            rhs = np.zeros(len(numbering.relations))
            for row, coefficient in rows:
                rhs[row] = coefficient
            try:
                values = value.evaluate(frequencies)
            except CommandError as exc:
                ctx.error(str(exc), "CHARGE", occ)
            particulars.append(elimination.particular(rhs))
            motions.append(scale * values)
    if not particulars:
        return None
    return np.column_stack(particulars), np.column_stack(motions)


def lifting_loads(particular, motion, frequencies, stiffness, mass, damping):
    """-(K + i w C - w^2 M) U c(f) as load vectors and their coefficients:
    -K U with c, -C U with i w c, M U with w^2 c."""
    from asterlite.fem import matrix_rows

    omega = TWO_PI * np.asarray(frequencies, dtype=float)[:, None]
    # by blocks of rows: a matrix on disk is never in memory whole
    vectors = [
        -matrix_rows.product(stiffness.matrix, particular).T,
        matrix_rows.product(mass.matrix, particular).T,
    ]
    coefficients = [motion, omega**2 * motion]
    if damping is not None:
        vectors.append(-matrix_rows.product(damping.matrix, particular).T)
        coefficients.append(1j * omega * motion)
    return np.vstack(vectors).astype(complex), np.hstack(coefficients)


def physical_loads(ctx, kw, numbering, stiffness_matrix) -> list[HarmonicLoad]:
    from asterlite.fem.assemble import assemble_terms

    loads = []
    for i, occ in enumerate(kw.factor("EXCIT"), start=1):
        if occ.get("VECT_ASSE") is not None:
            field = occ["VECT_ASSE"]
            vector = np.asarray(field.values)
            if vector.size != numbering.n_dofs or (
                field.numbering is not numbering and field.numbering.dofs != numbering.dofs
            ):
                ctx.error("VECT_ASSE is not on the numbering of the matrices", "VECT_ASSE", occ)
        else:
            load = occ["CHARGE"]
            if not isinstance(load, MechanicalLoad):
                ctx.unsupported(
                    f"EXCIT CHARGE of type {load.aster_type} in a harmonic response",
                    "CHARGE",
                    occ,
                )
            if any(relation.rhs_in_time is not None for relation in load.relations):
                ctx.unsupported(
                    "EXCIT CHARGE imposing displacements given in time (INST) in a "
                    "harmonic response",
                    "CHARGE",
                    occ,
                )
            try:
                terms = load_terms(
                    load,
                    stiffness_matrix.characteristics,
                    stiffness_matrix.materials,
                    complex_values=True,
                )
                vector = assemble_terms(terms, numbering)
            except KeyError as exc:
                ctx.error(f"load on DOFs the numbering does not have: {exc}", "CHARGE", occ)
        loads.append(harmonic_load(ctx, occ, vector, f"EXCIT[{i}]"))
    return loads


def _solvers(info: dict) -> str:
    """How the frequencies were factorised, e.g. "MUMPS 3, out of core 3"."""
    parts = [
        f"{label} {info[key]}"
        for key, label in (("ldl", "LDLT"), ("mumps", "MUMPS"), ("superlu", "SuperLU"))
        if info.get(key)
    ]
    if info.get("out_of_core"):
        parts.append(f"out of core {info['out_of_core']}")
    if info.get("refined"):
        parts.append(f"refined {info['refined']}")
    return ", ".join(parts) or "no frequency"
