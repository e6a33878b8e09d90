"""AFFE_CARA_ELEM: discrete element matrices (DISCRET, DISCRET_2D), beam and
bar sections (POUTRE, BARRE), plate thicknesses (COQUE) and orientations;
other keywords are kept for the rooms that compute them."""

from __future__ import annotations

import numpy as np
from asterlite.commands.affe_cara_elem_parasol import rigi_parasol

from asterlite.concepts.assembly import DiscreteAssignment, ElementCharacteristics
from asterlite.fem.beam import BeamError, seg2_angles
from asterlite.fem.discrete import DiscreteError, expected_count, parse_cara
from asterlite.fem.dofs import DISCRETE_MODELISATIONS
from asterlite.fem.fibres import section_integrals
from asterlite.fem.frames import angles_from_x_and_y
from asterlite.fem.pipe import PipeError
from asterlite.fem.pipe_elements import PIPE_MODELISATIONS, pipe_frames
from asterlite.fem.sections import (
    SectionError,
    cara_dict,
    section_properties,
    uniform_varying_section,
)
from asterlite.fem.selection import as_scalar, as_tuple, node_group_members, select_cells

_BEAMS = ("POU_D_E", "POU_D_T", "POU_D_TG", "POU_D_EM", "POU_D_TGM")
_MULTIFIBRE_BEAMS = ("POU_D_EM", "POU_D_TGM")
_BARS = ("BARRE", "2D_BARRE")

_OTHER_KEYWORDS = (
    "POUTRE",
    "BARRE",
    "COQUE",
    "CABLE",
    "MASSIF",
    "GRILLE",
    "MEMBRANE",
    "MASS_REP",
    "MASS_AJOU",
    "GENE_TUYAU",
    "POUTRE_FLUI",
)


def _discrete(ctx, model, result, occ, dim: int, keyword: str, verif: bool) -> None:
    mesh = model.mesh
    cells = select_cells(ctx, occ, mesh)
    # cells of the group without an element of the model take nothing (the
    # characteristic is only read by elements), unless VERIF='MAILLE' asks
    # every cell to carry one; none with one is an error
    bare = [c for c in cells if model.cell_modelisation.get(int(c)) is None]
    if bare and (verif or len(bare) == len(cells)):
        name = mesh.cell_names[bare[0]]
        ctx.error(f"cell {name} carries no element of the model", "GROUP_MA", occ)
    if bare:
        ctx.log(f"{keyword}: {len(bare)} cells without an element of the model are left out")
        cells = np.array([c for c in cells if model.cell_modelisation.get(int(c)) is not None])
    caras = as_tuple(occ.get("CARA"))
    values = np.atleast_1d(np.asarray(as_tuple(occ.get("VALE")), dtype=float))
    symmetric = as_scalar(occ.get("SYME", "OUI")) == "OUI"
    repere = as_scalar(occ.get("REPERE")) or "GLOBAL"
    hysteretic = float(occ.get("AMOR_HYST") or 0.0)
    start = 0
    for cara in caras:
        try:
            matrix, kind, _, support = parse_cara(cara)
            count = expected_count(cara, dim, symmetric)
        except DiscreteError as exc:
            ctx.error(str(exc), "CARA", occ)
        chunk = values[start : start + count]
        if chunk.size != count:
            ctx.error(
                f"{cara} expects {count} values in {keyword}, VALE gives {values.size - start}",
                "VALE",
                occ,
            )
        start += count
        wanted = ("2D_" if dim == 2 else "") + ("DIS_TR" if kind == "TR" else "DIS_T")
        for cell in cells:
            modelisation = model.cell_modelisation.get(int(cell))
            name = mesh.cell_names[cell]
            if modelisation not in DISCRETE_MODELISATIONS:
                ctx.error(f"cell {name} is a {modelisation} element, not a discrete", "CARA", occ)
            # a point mass (M_T_D_N, M_T_D_L: one value) means the same to 2D and 3D
            # elements, and code_aster gives it under either keyword (vafcar)
            same_meaning = cara in ("M_T_D_N", "M_T_D_L") and modelisation.endswith("DIS_T")
            if modelisation != wanted and not same_meaning:
                ctx.error(
                    f"{cara} needs {wanted} elements but cell {name} is {modelisation}",
                    "CARA",
                    occ,
                )
            cell_type = mesh.cell_types[cell]
            if (support == "N") != (cell_type == "POI1"):
                ctx.error(f"{cara} cannot be given to the {cell_type} cell {name}", "CARA", occ)
            result.discrete.setdefault(int(cell), {})[matrix] = DiscreteAssignment(
                matrix=matrix,
                cara=cara,
                values=chunk.copy(),
                repere=repere,
                symmetric=symmetric,
                hysteretic=hysteretic,
            )
    if start != values.size:
        ctx.error(f"VALE has {values.size} values, CARA uses {start}", "VALE", occ)


def _orientation(ctx, model, result, occ, generators: list) -> None:
    mesh = model.mesh
    cara = as_scalar(occ.get("CARA"))
    vale = np.atleast_1d(np.asarray(as_tuple(occ.get("VALE")), dtype=float))
    if cara == "GENE_TUYAU":
        nodes = node_group_members(ctx, occ, mesh)
        if len(nodes) != 1:
            ctx.error("GENE_TUYAU needs a GROUP_NO of one node", "GROUP_NO", occ)
        precision = float(occ.get("PRECISION", 1.0e-4))
        generators.append((int(nodes[0]), vale[:3], precision, occ.get("CRITERE", "RELATIF")))
        return
    cells = select_cells(ctx, occ, mesh)
    for cell in cells:
        cell = int(cell)
        conn = mesh.cell_nodes[cell]
        axis = mesh.coords[conn[-1]] - mesh.coords[conn[0]] if len(conn) > 1 else None
        if cara == "ANGL_NAUT":
            angles = np.zeros(3)
            angles[: vale.size] = np.radians(vale[:3])
        elif cara in ("ANGL_VRIL", "VECT_Y", "VECT_Z"):
            if axis is None or not np.any(axis):
                ctx.error(f"{cara} needs segment cells of non-zero length", "CARA", occ)
            try:
                angles = seg2_angles(mesh.coords[conn[0]], mesh.coords[conn[-1]], cara, vale)[0]
            except BeamError as exc:
                ctx.error(str(exc), "VALE", occ)
        elif cara == "VECT_X_Y":
            angles = angles_from_x_and_y(vale[:3], vale[3:6])
        else:
            ctx.unsupported(f"ORIENTATION CARA={cara!r}", "CARA", occ)
        result.orientation[cell] = np.asarray(angles, dtype=float)


def _check_cells(ctx, model, cells, accepted, keyword, occ) -> None:
    mesh = model.mesh
    for cell in cells:
        modelisation = model.cell_modelisation.get(int(cell))
        if modelisation not in accepted:
            what = "no element" if modelisation is None else f"a {modelisation} element"
            ctx.error(
                f"{keyword} is given to cell {mesh.cell_names[cell]}, which carries {what}",
                "GROUP_MA",
                occ,
            )


def _poutre(ctx, model, result, occ) -> None:
    section = occ["SECTION"]
    if section == "COUDE":
        ctx.unsupported("POUTRE SECTION='COUDE' (elbow elements)", "SECTION", occ)
    vari = occ.get("VARI_SECT", "CONSTANT")
    if occ.get("TABLE_CARA") is not None:
        ctx.unsupported("POUTRE TABLE_CARA (sections from a table)", "TABLE_CARA", occ)
    if occ.get("FCX") is not None:
        ctx.unsupported("POUTRE FCX (wind load function)", "FCX", occ)
    try:
        cara = cara_dict(occ["CARA"], occ["VALE"])
        if vari != "CONSTANT":
            # equal start and end values: the constant section, exactly
            cara = uniform_varying_section(section, vari, cara)
            if cara is None:
                what = f"POUTRE VARI_SECT={vari!r} with different start and end (tapered beams)"
                ctx.unsupported(what, "VARI_SECT", occ)
        props = section_properties(section, cara)
    except SectionError as exc:
        ctx.error(str(exc), "CARA", occ)
    cells = select_cells(ctx, occ, model.mesh)
    _check_cells(ctx, model, cells, _BEAMS + PIPE_MODELISATIONS, "POUTRE", occ)
    pipes = [c for c in cells if model.cell_modelisation.get(int(c)) in PIPE_MODELISATIONS]
    if pipes:
        props = _pipe_section(ctx, occ, section, vari, props)
    for cell in cells:
        # a later occurrence completes or overrides the section of a cell
        result.sections[int(cell)] = dict(props)


def _pipe_section(ctx, occ, section, vari, props) -> dict:
    """A pipe's section: a tube (CERCLE with R and EP) and its integration
    (TUYAU_NSEC sectors, TUYAU_NCOU layers, MODI_METRIQUE)."""
    if section != "CERCLE" or "EP" not in as_tuple(occ.get("CARA")):
        ctx.error("pipe elements need SECTION='CERCLE' with R and EP", "SECTION", occ)
    if vari != "CONSTANT":
        ctx.unsupported(f"POUTRE VARI_SECT={vari!r} on pipe elements", "VARI_SECT", occ)
    return {
        **props,
        "TUYAU_NSEC": int(occ.get("TUYAU_NSEC", 16)),
        "TUYAU_NCOU": int(occ.get("TUYAU_NCOU", 3)),
        "MODI_METRIQUE": 1.0 if occ.get("MODI_METRIQUE", "NON") == "OUI" else 0.0,
    }


def _barre(ctx, model, result, occ) -> None:
    section = occ["SECTION"]
    if occ.get("TABLE_CARA") is not None:
        ctx.unsupported("BARRE TABLE_CARA (sections from a table)", "TABLE_CARA", occ)
    try:
        cara = cara_dict(occ["CARA"], occ["VALE"])
        if section == "GENERALE":
            props = {"A": float(cara["A"]), "SECTION": "GENERALE"}
            if not props["A"] > 0.0:
                raise SectionError(f"BARRE: A must be > 0, got {props['A']}")
        else:
            full = section_properties(section, cara)
            props = {k: full[k] for k in full if k in ("A", "SECTION", "R", "EP", "HY", "HZ")}
    except (SectionError, KeyError) as exc:
        ctx.error(str(exc), "CARA", occ)
    cells = select_cells(ctx, occ, model.mesh)
    _check_cells(ctx, model, cells, _BARS, "BARRE", occ)
    for cell in cells:
        result.sections[int(cell)] = dict(props)


def _coque(ctx, model, result, occ) -> None:
    """Plate characteristics of DKT cells: thickness, the DRZ stiffness
    coefficient, rotary inertia, offset, and the output frame of its forces
    (ANGL_REP, degrees; VECTEUR is kept so that the fields refuse it), the
    layer count of its stress sub-points (COQUE_NCOU). The shear coefficient
    of thick plates (A_CIS) changes no matrix of a thin isotropic plate."""
    if occ.get("EPAIS_FO") is not None:
        ctx.unsupported("COQUE EPAIS_FO (thickness given by a function)", "EPAIS_FO", occ)
    if occ.get("EXCENTREMENT_FO") is not None:
        ctx.unsupported(
            "COQUE EXCENTREMENT_FO (offset given by a function)", "EXCENTREMENT_FO", occ
        )
    offset_given = occ.get("EXCENTREMENT") is not None
    offset = float(occ.get("EXCENTREMENT") or 0.0)
    if occ.get("MODI_METRIQUE", "NON") == "OUI":
        ctx.unsupported("COQUE MODI_METRIQUE='OUI' (COQUE_3D)", "MODI_METRIQUE", occ)
    thickness = float(occ["EPAIS"])
    if not thickness > 0.0:
        ctx.error(f"EPAIS must be > 0, got {thickness}", "EPAIS", occ)
    for no_effect in ("A_CIS",):
        occ.get(no_effect)
    angles = tuple(float(a) for a in (occ.get("ANGL_REP") or (0.0, 0.0)))
    values = {
        "EPAIS": thickness,
        "COEF_RIGI_DRZ": float(occ.get("COEF_RIGI_DRZ", 1.0e-5)),
        # EXCENTREMENT implies INER_ROTA='OUI' (code_aster's rule)
        "INER_ROTA": 1.0 if occ.get("INER_ROTA") == "OUI" or offset_given else 0.0,
        "EXCENTREMENT": offset,
        "ANGL_REP": angles,
        # layers of the stress sub-points (SIEF_ELGA, SIGM_ELNO)
        "COQUE_NCOU": int(occ.get("COQUE_NCOU", 1)),
        "VECTEUR": occ.get("VECTEUR"),
    }
    if values["COEF_RIGI_DRZ"] < 0.0:
        ctx.unsupported("COQUE COEF_RIGI_DRZ < 0 (drilling rotations)", "COEF_RIGI_DRZ", occ)
    for cell in select_cells(ctx, occ, model.mesh):
        result.shells[int(cell)] = dict(values)


def _multifibre(ctx, model, result, occ, geometry) -> None:
    """Fibre groups of POU_D_EM cells, checked as code_aster does against the
    cell's POUTRE section: |A - Σ A_f| / A <= PREC_AIRE and the same for IY
    (Σ z² A_f) and IZ (Σ y² A_f) with PREC_INERTIE."""
    mesh = model.mesh
    names = as_tuple(occ["GROUP_FIBRE"])
    missing = [n for n in names if n not in geometry.groups]
    if missing:
        ctx.error(f"GEOM_FIBRE has no fibre group {missing[0]!r}", "GROUP_FIBRE", occ)
    integrals = sum(
        section_integrals(g.y, g.z, g.area) for g in (geometry.groups[n] for n in names)
    )
    cells = select_cells(ctx, occ, mesh)
    _check_cells(ctx, model, cells, _MULTIFIBRE_BEAMS, "MULTIFIBRE", occ)
    checks = (
        ("A", integrals[0], "PREC_AIRE", 0.01),
        ("IY", integrals[4], "PREC_INERTIE", 0.1),
        ("IZ", integrals[3], "PREC_INERTIE", 0.1),
    )
    for cell in cells:
        section = result.sections.get(int(cell))
        name = mesh.cell_names[cell]
        if section is None:
            ctx.error(
                f"multifibre cell {name} has no POUTRE section (its A, IY, IZ are checked "
                "against the fibres and its JX gives the torsion)",
                "GROUP_MA",
                occ,
            )
        for cara, fibres, keyword, default in checks:
            given = float(section[cara])
            if not given > 0.0:
                ctx.error(f"the POUTRE section of cell {name} has {cara} <= 0", "GROUP_MA", occ)
            precision = float(occ.get(keyword, default))
            error = abs(given - fibres) / given
            if error > precision:
                ctx.error(
                    f"cell {name}: {cara} of the POUTRE section is {given:.6g}, the fibres "
                    f"give {fibres:.6g}, relative difference {error:.3g} > {keyword}={precision:g}",
                    keyword,
                    occ,
                )
        result.fibre_groups[int(cell)] = tuple(names)


def _verify_cells(ctx, model, kw) -> None:
    """VERIF='MAILLE': code_aster checks that every cell of an occurrence
    carries an element of the keyword's family (the checks of DISCRET,
    DISCRET_2D, POUTRE and BARRE asterlite always makes; ORIENTATION: beams and
    discretes), and stops when one does not."""
    if "MAILLE" not in as_tuple(kw.get("VERIF")):
        return
    for occ in kw.factor("ORIENTATION"):
        if occ.get("CARA") == "GENE_TUYAU":
            continue  # a node of a pipe line, checked with the pipe frames
        cells = select_cells(ctx, occ, model.mesh)
        _check_cells(ctx, model, cells, _BEAMS + DISCRETE_MODELISATIONS, "ORIENTATION", occ)
    others = [k for k in _OTHER_KEYWORDS if k not in ("POUTRE", "BARRE") and kw.get(k)]
    if others:
        ctx.unsupported(
            f"VERIF='MAILLE' with {', '.join(others)} (cells of those element families)",
            "VERIF",
            kw,
        )


def _pipe_frames(ctx, model, result, generators, kw) -> None:
    """Frames of every pipe cell of the model, from the pipe lines and
    ORIENTATION GENE_TUYAU (code_aster's aceatu)."""
    pipes = [c for c, m in model.cell_modelisation.items() if m in PIPE_MODELISATIONS]
    if generators and not pipes:
        # code_aster reads GENE_TUYAU only to orient pipe elements
        ctx.log("warning: ORIENTATION GENE_TUYAU on a model without pipe elements: no effect")
    if not pipes:
        return
    try:
        result.pipe_frames = pipe_frames(model.mesh, sorted(pipes), generators)
    except PipeError as exc:
        if "elbow" in str(exc):
            ctx.unsupported(str(exc), "ORIENTATION" if generators else "POUTRE", kw)
        ctx.error(str(exc), "ORIENTATION" if generators else "POUTRE", kw)


def _massif(ctx, model, result, occ) -> None:
    """MASSIF ANGL_REP: the material frame (L, T, N) of solid cells, the global
    axes turned by nautical angles in degrees (missing ones 0), read by the
    orthotropic materials (ELAS_ORTH) of 3D and plane elements."""
    for keyword in ("ANGL_EULER", "ORIG_AXE", "CHAM_ORIE"):
        if occ.get(keyword) is not None:
            ctx.unsupported(f"MASSIF {keyword} (material frame)", keyword, occ)
    angles = np.zeros(3)
    given = np.atleast_1d(np.asarray(occ["ANGL_REP"], dtype=float))
    angles[: given.size] = np.radians(given)
    for cell in select_cells(ctx, occ, model.mesh, all_cells=list(model.cell_modelisation)):
        result.material_angles[int(cell)] = angles


def run(ctx, kw):
    model = kw["MODELE"]
    result = ElementCharacteristics(model=model)
    _verify_cells(ctx, model, kw)
    # orientations first: DISCRET ... REPERE='LOCAL' uses them whatever the order
    generators: list = []
    for occ in kw.factor("ORIENTATION"):
        _orientation(ctx, model, result, occ, generators)
    verif = "MAILLE" in as_tuple(kw.get("VERIF"))
    for occ in kw.factor("DISCRET"):
        _discrete(ctx, model, result, occ, 3, "DISCRET", verif)
    for occ in kw.factor("DISCRET_2D"):
        _discrete(ctx, model, result, occ, 2, "DISCRET_2D", verif)
    for occ in kw.factor("RIGI_PARASOL"):
        rigi_parasol(ctx, model, result, occ)
    for occ in kw.factor("POUTRE"):
        _poutre(ctx, model, result, occ)
    for occ in kw.factor("BARRE"):
        _barre(ctx, model, result, occ)
    for occ in kw.factor("COQUE"):
        _coque(ctx, model, result, occ)
    for occ in kw.factor("MASSIF"):
        _massif(ctx, model, result, occ)
    if kw.get("GEOM_FIBRE") is not None:
        result.geom_fibre = kw["GEOM_FIBRE"]
    for occ in kw.factor("MULTIFIBRE"):
        _multifibre(ctx, model, result, occ, result.geom_fibre)
    without = [
        c
        for c, m in model.cell_modelisation.items()
        if m in _MULTIFIBRE_BEAMS and c not in result.fibre_groups
    ]
    if kw.factor("MULTIFIBRE") and without:
        names = ", ".join(model.mesh.cell_names[c] for c in without[:5])
        ctx.error(f"multifibre beam cells {names} have no fibres (MULTIFIBRE)", "MULTIFIBRE", kw)
    _pipe_frames(ctx, model, result, generators, kw)
    for keyword in _OTHER_KEYWORDS:
        if kw.get(keyword):
            result.extra[keyword] = kw.factor(keyword)
    struct = _BEAMS + _BARS
    missing = [
        c for c, m in model.cell_modelisation.items() if m in struct and c not in result.sections
    ]
    if missing:
        names = ", ".join(model.mesh.cell_names[c] for c in missing[:5])
        ctx.log(f"warning: {len(missing)} beam/bar cells have no section ({names}...)")
    ctx.log(
        f"characteristics: discrete on {len(result.discrete)} cells, "
        f"sections on {len(result.sections)} cells"
    )
    return result
