"""DEFI_BASE_MODALE: Ritz bases (RITZ, with ORTHO) and ORTHO_BASE.

RITZ concatenates dynamic modes (MODE_MECA, capped by NMAX_MODE, or a previous
BASE_MODALE) and interface / static vectors (MODE_INTF: mode_meca or
mult_elas) on the reference numbering (NUME_REF, else the first basis's);
with INTERF_DYNA the basis remembers those interfaces (for MACR_ELEM_DYNA).
ORTHO='OUI' orthonormalises the family with respect to MATRICE and drops the
dependent vectors; ORTHO_BASE does the same on an existing basis but keeps
dependent vectors as zero columns. Per-mode parameters (FREQ, MASS_GENE,
RIGI_GENE, NUME_MODE...) are copied from the sources by position, as
code_aster does; ``generalized_mass``/``generalized_stiffness`` are
recomputed from the vectors when the matrices are known."""

from __future__ import annotations

import numpy as np

from asterlite.concepts.modes import ModeResult, MultElasResult
from asterlite.concepts.substructure import ReductionBasis
from asterlite.fem.selection import as_tuple
from asterlite.modal.renumber import lost_rows, transfer
from asterlite.modal.ritz import orthonormalise


def _source_parameters(basis, count: int, static: bool) -> dict[str, np.ndarray]:
    """Per-mode parameters of the first ``count`` vectors of a source."""
    if isinstance(basis, MultElasResult):
        labels = basis.case_names[:count] or [""] * count
        return {
            "FREQ": np.zeros(count),
            "NUME_MODE": np.arange(1, count + 1),
            "MASS_GENE": np.zeros(count),
            "RIGI_GENE": np.zeros(count),
            "NOEUD_CMP": np.array(labels, dtype=object),
            "TYPE_DEFO": np.array(["DEPL_IMPO"] * count, dtype=object),
            "TYPE_MODE": np.array(["MODE_STA"] * count, dtype=object),
        }
    p = basis.parameters
    labels = list(basis.mode_labels[:count]) if basis.mode_labels else [""] * count
    kind = "MODE_STA" if static or basis.kind == "static" else "MODE_DYN"
    out = {
        "FREQ": np.asarray(basis.frequencies, dtype=float)[:count],
        "NUME_MODE": np.asarray(basis.mode_numbers)[:count],
        "MASS_GENE": np.asarray(p.get("MASS_GENE", basis.generalized_mass), dtype=float)[:count],
        "RIGI_GENE": np.asarray(p.get("RIGI_GENE", basis.generalized_stiffness), dtype=float)[
            :count
        ],
        "NOEUD_CMP": np.array(labels, dtype=object),
        "TYPE_DEFO": np.asarray(
            p.get("TYPE_DEFO", np.array([""] * basis.n_modes, dtype=object)), dtype=object
        )[:count],
        "TYPE_MODE": np.asarray(
            p.get("TYPE_MODE", np.array([kind] * basis.n_modes, dtype=object)), dtype=object
        )[:count],
    }
    return out


def _capped(ctx, occ, count: int, value, keyword="NMAX_MODE") -> int:
    if value is None:
        return count
    if int(value) < 0:
        ctx.error("NMAX_MODE must be positive", keyword, occ)
    return min(int(value), count)


def _pieces(ctx, kw):
    """[(basis, number of vectors, static?)] in code_aster's order."""
    dynamic, static = [], []
    for occ in kw.factor("RITZ"):
        if occ.get("MODE_MECA") is not None:
            bases = as_tuple(occ["MODE_MECA"])
            caps = as_tuple(occ.get("NMAX_MODE"))
            if caps and len(caps) != len(bases) and len(caps) != 1:
                ctx.error(
                    f"NMAX_MODE has {len(caps)} values for {len(bases)} MODE_MECA",
                    "NMAX_MODE",
                    occ,
                )
            for k, basis in enumerate(bases):
                cap = caps[k] if len(caps) == len(bases) else (caps[0] if caps else None)
                dynamic.append((basis, _capped(ctx, occ, basis.n_modes, cap), False))
        elif occ.get("BASE_MODALE") is not None:
            basis = occ["BASE_MODALE"]
            dynamic.append((basis, basis.n_modes, False))
        elif occ.get("MODE_INTF") is not None:
            basis = occ["MODE_INTF"]
            count = basis.n_cases if isinstance(basis, MultElasResult) else basis.n_modes
            cap = as_tuple(occ.get("NMAX_MODE"))
            static.append((basis, _capped(ctx, occ, count, cap[0] if cap else None), True))
    if not dynamic and not static:
        ctx.error("RITZ needs MODE_MECA, BASE_MODALE or MODE_INTF", "RITZ", kw)
    return dynamic + static


def _on_reference(ctx, kw, basis, count, reference):
    shapes = np.asarray(basis.shapes, dtype=float)[:, :count]
    if basis.numbering.mesh is not reference.mesh:
        ctx.error("the bases and NUME_REF are on different meshes", "NUME_REF", kw)
    lost = lost_rows(shapes, basis.numbering, reference)
    if lost.size:
        ctx.log(
            f"warning: {lost.size} non-zero DOF(s) of {basis.name or 'a basis'} are not in"
            f" the reference numbering (first: {basis.numbering.label(int(lost[0]))})"
        )
    return transfer(shapes, basis.numbering, reference)


def _matrices(pieces):
    for basis, _, _ in pieces:
        if isinstance(basis, ModeResult) and basis.mass is not None:
            return basis.mass, basis.stiffness
    return None, None


def _result(shapes, numbering, params, mass, stiffness, labels, kind, norm=""):
    n = shapes.shape[1]
    gm = np.asarray(params["MASS_GENE"], dtype=float).copy()
    gk = np.asarray(params["RIGI_GENE"], dtype=float).copy()
    if mass is not None and mass.numbering.dofs == numbering.dofs:
        gm = np.einsum("ij,ij->j", shapes, mass.matrix @ shapes)
    if stiffness is not None and stiffness.numbering.dofs == numbering.dofs:
        gk = np.einsum("ij,ij->j", shapes, stiffness.matrix @ shapes)
    return ModeResult(
        numbering=numbering,
        shapes=shapes,
        frequencies=np.asarray(params["FREQ"], dtype=float).copy(),
        generalized_mass=gm,
        generalized_stiffness=gk,
        mass=mass,
        stiffness=stiffness,
        kind=kind,
        parameters=params,
        norm=norm,
        mode_labels=[str(x) for x in labels][:n],
    )


def _take(params: dict, count: int) -> dict:
    return {k: np.asarray(v)[:count] for k, v in params.items()}


def _ortho(ctx, shapes, params, matrix_concept, numbering, drop_zero):
    """Orthonormalise on the matrix's numbering; parameters follow by position."""
    target = matrix_concept.numbering
    if target.dofs != numbering.dofs:
        ctx.log("the basis is copied onto the numbering of MATRICE")
        shapes = transfer(shapes, numbering, target)
    q, kept = orthonormalise(shapes, matrix_concept.matrix, drop_zero=drop_zero)
    ctx.log(f"orthonormalisation: {q.shape[1]} of {shapes.shape[1]} vectors kept")
    return q, _take(params, q.shape[1]), target


def run(ctx, kw):
    if kw.factor("DIAG_MASS"):
        ctx.unsupported("DEFI_BASE_MODALE DIAG_MASS", "DIAG_MASS", kw)
    if kw.factor("CLASSIQUE"):
        return _classical(ctx, kw, kw.factor("CLASSIQUE")[0])
    if kw.factor("ORTHO_BASE"):
        return _ortho_base(ctx, kw)
    pieces = _pieces(ctx, kw)
    reference = kw.get("NUME_REF") or pieces[0][0].numbering
    blocks, params = [], []
    for basis, count, static in pieces:
        blocks.append(_on_reference(ctx, kw, basis, count, reference))
        params.append(_source_parameters(basis, count, static))
    shapes = np.hstack(blocks)
    merged = {k: np.concatenate([p[k] for p in params]) for k in params[0]}
    mass, stiffness = _matrices(pieces)
    numbering = reference
    if kw.get("ORTHO", "NON") == "OUI":
        shapes, merged, numbering = _ortho(ctx, shapes, merged, kw["MATRICE"], numbering, True)
    if shapes.shape[1] == 0:
        ctx.error("the Ritz basis is empty", "RITZ", kw)
    n_static = int(np.sum(merged["TYPE_MODE"] == "MODE_STA"))
    kind = "static" if n_static == shapes.shape[1] else "dynamic"
    ctx.log(f"Ritz basis: {shapes.shape[1]} vectors ({n_static} static)")
    basis = _result(shapes, numbering, merged, mass, stiffness, merged["NOEUD_CMP"], kind)
    return _with_interfaces(ctx, kw, basis)


def _with_interfaces(ctx, kw, basis):
    """RITZ with INTERF_DYNA: the basis remembers the interfaces (code_aster
    records them with it, ritz99), so that MACR_ELEM_DYNA can join it to
    other substructures; they must be on the basis's numbering."""
    interfaces = kw.get("INTERF_DYNA")
    if interfaces is None:
        return basis
    if interfaces.numbering.dofs != basis.numbering.dofs:
        ctx.error(
            "INTERF_DYNA is not on the numbering of the basis (give NUME_REF)", "INTERF_DYNA", kw
        )
    fields = {f: getattr(basis, f) for f in basis.__dataclass_fields__}
    return ReductionBasis(**fields, interfaces=interfaces)


def _ortho_base(ctx, kw):
    occ = kw.factor("ORTHO_BASE")[0]
    basis = occ["BASE"]
    static = isinstance(basis, MultElasResult)
    count = basis.n_cases if static else basis.n_modes
    params = _source_parameters(basis, count, static)
    shapes, params, numbering = _ortho(
        ctx, np.asarray(basis.shapes, dtype=float), params, occ["MATRICE"], basis.numbering, False
    )
    mass = None if static else basis.mass
    stiffness = None if static else basis.stiffness
    kind = "static" if static else basis.kind
    return _result(shapes, numbering, params, mass, stiffness, params["NOEUD_CMP"], kind)


def _classical(ctx, occ_kw, occ):
    """CLASSIQUE: the modes (NMAX_MODE of each MODE_MECA) then the static
    modes of the interfaces (asterlite.substructure.interfaces)."""
    bases = as_tuple(occ["MODE_MECA"])
    caps = as_tuple(occ.get("NMAX_MODE"))
    return classical_basis(ctx, occ, occ["INTERF_DYNA"], bases, caps)


def classical_basis(ctx, occ, interfaces, bases, caps):
    """The classical basis of ``interfaces`` from the modes ``bases`` (the
    first ``caps[k]`` of each); also CREA_ELEM_SSD's."""
    from asterlite.substructure.interfaces import InterfaceError, static_modes

    numbering = interfaces.numbering
    blocks, params = [], []
    for k, basis in enumerate(bases):
        cap = caps[k] if k < len(caps) else (caps[-1] if caps else None)
        count = _capped(ctx, occ, basis.n_modes, cap)
        if basis.numbering.dofs != numbering.dofs:
            ctx.error("MODE_MECA and INTERF_DYNA use different numberings", "MODE_MECA", occ)
        blocks.append(np.asarray(basis.shapes, dtype=float)[:, :count])
        params.append(_source_parameters(basis, count, False))
    stiffness, mass = bases[0].stiffness, bases[0].mass
    if stiffness is None:
        ctx.error("the stiffness matrix of MODE_MECA is not known", "MODE_MECA", occ)
    labels, defo = [], []
    for interface in interfaces.interfaces:
        try:
            shapes, owners = static_modes(
                interface.kind,
                interface.dofs,
                numbering,
                stiffness.matrix,
                None if mass is None else mass.matrix,
                interfaces.frequency,
            )
        except InterfaceError as exc:
            ctx.error(f"interface {interface.name}: {exc}", "INTERF_DYNA", occ)
        blocks.append(shapes)
        left = interface.dofs.size - owners.size
        if left:
            state = "blocked" if interface.kind == "MNEAL" else "not blocked"
            ctx.log(f"interface {interface.name}: {left} DOF(s) {state}, no static mode")
        labels.extend(numbering.label(int(d)) for d in owners)
        kind = "FORC_IMPO" if interface.kind == "MNEAL" else "DEPL_IMPO"
        defo.extend([kind] * shapes.shape[1])
    merged = {k: np.concatenate([p[k] for p in params]) for k in params[0]}
    n_static = len(labels)
    static = {
        "FREQ": np.zeros(n_static),
        "NUME_MODE": np.arange(1, n_static + 1) + len(merged["FREQ"]),
        "MASS_GENE": np.zeros(n_static),
        "RIGI_GENE": np.zeros(n_static),
        "NOEUD_CMP": np.array(labels, dtype=object),
        "TYPE_DEFO": np.array(defo, dtype=object),
        "TYPE_MODE": np.array(["MODE_STA"] * n_static, dtype=object),
    }
    merged = {k: np.concatenate([merged[k], static[k]]) for k in merged}
    shapes = np.hstack(blocks)
    ctx.log(f"classical basis: {shapes.shape[1]} vectors ({n_static} static)")
    plain = _result(shapes, numbering, merged, mass, stiffness, merged["NOEUD_CMP"], "dynamic")
    fields = {f: getattr(plain, f) for f in plain.__dataclass_fields__}
    return ReductionBasis(**fields, interfaces=interfaces)
