"""DYNA_LINE (TYPE_CALCUL='TRAN'): linear transient response of a model, on its
physical DOFs or on a modal basis built for the excitation.

A macro, as in code_aster: it chains the commands a user would write, each
validated against its own catalogue (so their defaults apply) and run by its
own implementation:

- CALC_MATR_ELEM, NUME_DDL, ASSE_MATRICE: stiffness, mass (and Rayleigh
  damping) of MODELE / CHAM_MATER / CARA_ELEM with the kinematic CHARGE;
- BASE_CALCUL='GENE': the modes of the band (CALC_MODES BANDE on
  BANDE_ANALYSE, or [0, 2 f_c] from the spectrum of the excitation), with
  ENRI_STAT='OUI' the static enrichment (MODE_STATIQUE pseudo-modes of the
  support motions, MACRO_ELAS_MULT responses to the EXCIT loads,
  MODE_STATIQUE attachment modes at the nonlinearities) gathered in a Ritz
  basis (DEFI_BASE_MODALE RITZ, ORTHO against the stiffness), re-diagonalised
  when ORTHO='OUI' (CALC_MODES on the projected matrices, restored on the
  physical DOFs); NUME_DDL_GENE, PROJ_MATR_BASE, PROJ_VECT_BASE project;
- the loads: CALC_VECT_ELEM + ASSE_VECTEUR for CHARGE, CALC_CHAR_SEISME for
  the support motions (MODE_STATIQUE MODE_STAT for TYPE_APPUI='MULTI' or a
  MONO support on GROUP_NO);
- DYNA_VIBRA (step check off, as code_aster), then for GENE REST_GENE_PHYS
  of every field (absolute motion for MULTI supports, absolute acceleration
  for one MONO support).

The result is the physical ``dyna_trans``; BASE_RESU=CO(...) receives the
modal basis and RESU_GENE=CO(...) the ``tran_gene``.
"""

from __future__ import annotations

import importlib
from dataclasses import dataclass, field
from typing import Any

import numpy as np

from asterlite.catalog import load_catalogue, validate
from asterlite.concepts.assembly import MechanicalLoad, NodalField
from asterlite.errors import AsterliteError, missing_name
from asterlite.fem.selection import as_tuple
from asterlite.lang.values import CallSite
from asterlite.modal import frequency_band
from asterlite.modal.renumber import transfer
from asterlite.modal.ritz import stacked_fields
from asterlite.modal.static_modes import StaticModeError, active_components
from asterlite.runtime.context import CommandContext

DOF_NAMES = ("DX", "DY", "DZ", "DRX", "DRY", "DRZ")
TRANSLATIONS = ("DX", "DY", "DZ")
NODE_KEYWORDS = ("NOEUD", "NOEUD_1", "NOEUD_2", "NOEUD_D", "NOEUD_G")
GROUP_KEYWORDS = ("GROUP_NO", "GROUP_NO_1", "GROUP_NO_2", "GROUP_NO_D", "GROUP_NO_G")


# ----------------------------------------------------------------------------- sub-commands


def call(ctx, name: str, **kwargs):
    """Run command ``name`` as the deck would: keywords (None values dropped)
    validated against its catalogue, then its implementation."""
    given = {k: v for k, v in kwargs.items() if v is not None}
    keywords = validate(load_catalogue(name), given, CallSite(location=ctx.location))
    module = importlib.import_module(f"asterlite.commands.{name.lower()}")
    sub = CommandContext(session=ctx.session, command=name, location=ctx.location)
    ctx.log(f"{ctx.command} > {name}")
    try:
        return module.run(sub, keywords)
    except AsterliteError as error:
        error.path = f"{ctx.command} > {error.path or name}"
        raise


# ----------------------------------------------------------------------------- structure


@dataclass
class Structure:
    """The assembled model: matrices on one numbering, and what built them."""

    model: Any
    loads: list
    characteristics: Any
    materials: Any
    numbering: Any
    stiffness: Any
    mass: Any
    damping: Any = None
    cache: dict = field(default_factory=dict)

    @property
    def element_keywords(self) -> dict:
        return {"CARA_ELEM": self.characteristics, "CHAM_MATER": self.materials}


def structure(ctx, kw) -> Structure:
    charges = as_tuple(kw.get("CHARGE"))
    kinematic = [c for c in charges if not isinstance(c, MechanicalLoad)]
    if kinematic:
        ctx.unsupported("DYNA_LINE with AFFE_CHAR_CINE loads", "CHARGE", kw)
    loads = list(charges)
    common = {
        "MODELE": kw["MODELE"],
        "CHARGE": tuple(loads) or None,
        "CARA_ELEM": kw.get("CARA_ELEM"),
        "CHAM_MATER": kw.get("CHAM_MATER"),
    }
    rigi = call(ctx, "CALC_MATR_ELEM", OPTION="RIGI_MECA", **common)
    mass = call(ctx, "CALC_MATR_ELEM", OPTION="MASS_MECA", **common)
    numbering = call(ctx, "NUME_DDL", MATR_RIGI=rigi)
    built = Structure(
        model=kw["MODELE"],
        loads=loads,
        characteristics=kw.get("CARA_ELEM"),
        materials=kw.get("CHAM_MATER"),
        numbering=numbering,
        stiffness=call(ctx, "ASSE_MATRICE", MATR_ELEM=rigi, NUME_DDL=numbering),
        mass=call(ctx, "ASSE_MATRICE", MATR_ELEM=mass, NUME_DDL=numbering),
    )
    damping = damping_keywords(kw)
    if damping.get("TYPE_AMOR") == "RAYLEIGH":
        # as code_aster's macro: the element matrices go along with a material
        # field only; without one the damping is the discrete elements' (CARA_ELEM)
        elements = {"RIGI_MECA": rigi, "MASS_MECA": mass} if kw.get("CHAM_MATER") else {}
        amor = call(ctx, "CALC_MATR_ELEM", OPTION="AMOR_MECA", **elements, **common)
        built.damping = call(ctx, "ASSE_MATRICE", MATR_ELEM=amor, NUME_DDL=numbering)
    return built


def damping_keywords(kw) -> dict:
    occurrences = kw.factor("AMORTISSEMENT")
    return dict(occurrences[0]) if occurrences else {}


def load_vector(ctx, st: Structure, loads) -> NodalField:
    """The assembled nodal load of mechanical loads (CALC_VECT_ELEM + ASSE_VECTEUR)."""
    elementary = call(
        ctx, "CALC_VECT_ELEM", OPTION="CHAR_MECA", CHARGE=tuple(loads), **st.element_keywords
    )
    return call(ctx, "ASSE_VECTEUR", VECT_ELEM=elementary, NUME_DDL=st.numbering)


# ----------------------------------------------------------------------------- excitations


def excitations(kw, kind: str | None) -> list:
    """EXCIT occurrences of one TYPE_APPUI (None: the CHARGE loads)."""
    return [occ for occ in kw.factor("EXCIT") if occ.get("TYPE_APPUI") == kind]


def components_of(direction) -> list[str]:
    return [DOF_NAMES[i] for i, value in enumerate(as_tuple(direction)) if value != 0.0]


def support_static_modes(ctx, kw, st: Structure, kind: str):
    """MODE_STATIQUE MODE_STAT for the supports of TYPE_APPUI ``kind`` that name
    their nodes (unit displacements along the components of DIRECTION)."""
    key = f"static_{kind}"
    if key in st.cache:
        return st.cache[key]
    occurrences = []
    for occ in excitations(kw, kind):
        if occ.get("GROUP_NO") is None:
            continue
        components = components_of(occ["DIRECTION"])
        if not components:
            ctx.error(f"DIRECTION of a TYPE_APPUI='{kind}' support is zero", "DIRECTION", occ)
        occurrences.append({"GROUP_NO": occ["GROUP_NO"], "AVEC_CMP": tuple(components)})
    modes = None
    if occurrences:
        modes = call(
            ctx, "MODE_STATIQUE", MATR_RIGI=st.stiffness, MATR_MASS=st.mass, MODE_STAT=occurrences
        )
    st.cache[key] = modes
    return modes


def seismic_vector(ctx, kw, st: Structure, occ) -> NodalField:
    """CALC_CHAR_SEISME of one support motion."""
    direction = as_tuple(occ["DIRECTION"])
    if occ["TYPE_APPUI"] == "MONO" and occ.get("GROUP_NO") is None:
        return call(
            ctx, "CALC_CHAR_SEISME", MATR_MASS=st.mass, MONO_APPUI="OUI", DIRECTION=direction
        )
    return call(
        ctx,
        "CALC_CHAR_SEISME",
        MATR_MASS=st.mass,
        MODE_STAT=support_static_modes(ctx, kw, st, occ["TYPE_APPUI"]),
        GROUP_NO=occ["GROUP_NO"],
        DIRECTION=direction,
    )


def loading(ctx, kw, st: Structure, to_basis) -> list[dict]:
    """DYNA_VIBRA's EXCIT occurrences: the global loads' own forces, each CHARGE
    times its function, then the support motions; ``to_basis`` turns an
    assembled vector into the keyword DYNA_VIBRA reads (VECT_ASSE or
    VECT_ASSE_GENE)."""
    out = []
    if st.loads:
        blocked = load_vector(ctx, st, st.loads)
        if np.any(blocked.values != 0.0):
            out.append({"COEF_MULT": 1.0, **to_basis(blocked)})
    for occ in excitations(kw, None):
        vector = load_vector(ctx, st, (occ["CHARGE"],))
        out.append({"FONC_MULT": occ["FONC_MULT"], **to_basis(vector)})
    for occ in excitations(kw, "MULTI"):
        entry = {"MULT_APPUI": "OUI", **to_basis(seismic_vector(ctx, kw, st, occ))}
        entry.update(_present(occ, "ACCE", "VITE", "DEPL", "FONC_MULT", "GROUP_NO", "DIRECTION"))
        out.append(entry)
    for occ in excitations(kw, "MONO"):
        entry = to_basis(seismic_vector(ctx, kw, st, occ))
        entry.update(_present(occ, "ACCE", "VITE", "DEPL", "FONC_MULT"))
        out.append(entry)
    return out


def _present(occ, *names) -> dict:
    return {name: occ[name] for name in names if occ.get(name) is not None}


# ----------------------------------------------------------------------------- frequencies


def cutoff_frequency(ctx, kw) -> float:
    """f_c: BANDE_ANALYSE's upper bound, else the spectral cutoff of the
    excitation functions (PCENT_COUP percent of the energy)."""
    if kw.get("BANDE_ANALYSE"):
        return float(as_tuple(kw["BANDE_ANALYSE"])[-1])
    functions = [occ.get("FONC_MULT") or occ.get("ACCE") for occ in kw.factor("EXCIT")]
    functions = [f for f in functions if f is not None]
    if not functions:
        ctx.error("give BANDE_ANALYSE: no EXCIT function to compute a cutoff frequency")
    cutoffs = []
    for function in functions:
        if not hasattr(function, "abscissas"):
            ctx.error(
                "the cutoff frequency needs tabulated functions (not a FORMULE): "
                "give BANDE_ANALYSE or use CALC_FONC_INTERP",
                "EXCIT",
                kw,
            )
        spectrum = call(ctx, "CALC_FONCTION", FFT={"FONCTION": function})
        cutoffs.append(
            frequency_band.cutoff_from_spectrum(
                spectrum.abscissas, spectrum.ordinates, kw.get("PCENT_COUP", 90)
            )
        )
    return max(cutoffs)


def time_increment(ctx, kw) -> dict:
    occ = dict(kw.factor("INCREMENT")[0])
    if occ.get("PAS") is None:
        occ["PAS"] = frequency_band.default_step(cutoff_frequency(ctx, kw))
    occ["VERI_PAS"] = "NON"
    return occ


# ----------------------------------------------------------------------------- modal basis


def dynamic_modes(ctx, kw, st: Structure):
    bande = as_tuple(kw.get("BANDE_ANALYSE"))
    cutoff = None if bande else cutoff_frequency(ctx, kw)
    return call(
        ctx,
        "CALC_MODES",
        OPTION="BANDE",
        MATR_RIGI=st.stiffness,
        MATR_MASS=st.mass,
        CALC_FREQ={"FREQ": frequency_band.band(bande, cutoff)},
        VERI_MODE={"STOP_ERREUR": "NON"},
        STOP_BANDE_VIDE="NON",
    )


def pseudo_modes(ctx, kw, st: Structure, kind: str):
    """Pseudo-modes (unit acceleration along each support's DIRECTION)."""
    occurrences = [
        {"DIRECTION": tuple(as_tuple(occ["DIRECTION"])[:3]), "NOM_DIR": "AxePseudo_Mode"}
        for occ in excitations(kw, kind)
    ]
    if not occurrences:
        return None
    return call(
        ctx, "MODE_STATIQUE", MATR_RIGI=st.stiffness, MATR_MASS=st.mass, PSEUDO_MODE=occurrences
    )


def elastic_modes(ctx, kw, st: Structure):
    """Static responses to each EXCIT load (MACRO_ELAS_MULT on the numbering)."""
    cases = [
        {"CHAR_MECA": (occ["CHARGE"],), "OPTION": "SANS", "NOM_CAS": f"CAS_{k}"}
        for k, occ in enumerate(excitations(kw, None))
    ]
    if not cases:
        return None
    return call(
        ctx,
        "MACRO_ELAS_MULT",
        MODELE=st.model,
        NUME_DDL=st.numbering,
        CHAR_MECA_GLOBAL=tuple(st.loads) or None,
        CAS_CHARGE=cases,
        **st.element_keywords,
    )


def nonlinear_modes(ctx, kw, st: Structure):
    """Attachment modes (unit forces) at the nodes of the COMPORTEMENT
    occurrences, on NOM_CMP or on the translations that move."""
    occurrences = []
    mesh = st.numbering.mesh
    for occ in kw.factor("COMPORTEMENT"):
        for keys, selector in ((NODE_KEYWORDS, "NOEUD"), (GROUP_KEYWORDS, "GROUP_NO")):
            names = [name for key in keys for name in as_tuple(occ.get(key))]
            if not names:
                continue
            components = as_tuple(occ.get("NOM_CMP"))
            if not components:
                nodes = _node_indices(ctx, mesh, selector, names, occ)
                try:
                    components = active_components(
                        st.stiffness.matrix, st.numbering, nodes, TRANSLATIONS
                    )
                except StaticModeError as exc:
                    ctx.error(str(exc), "COMPORTEMENT", kw)
            if components:
                occurrences.append({selector: tuple(names), "AVEC_CMP": tuple(components)})
    if not occurrences:
        return None
    return call(
        ctx, "MODE_STATIQUE", MATR_RIGI=st.stiffness, MATR_MASS=st.mass, FORCE_NODALE=occurrences
    )


def _node_indices(ctx, mesh, selector, names, occ) -> list[int]:
    nodes = []
    for name in names:
        if selector == "GROUP_NO":
            if name not in mesh.node_groups:
                ctx.error(missing_name("node group", name, mesh.node_groups), "GROUP_NO", occ)
            nodes.extend(int(n) for n in mesh.node_groups[name])
        else:
            index = mesh.find_node(name)
            if index is None:
                ctx.error(f"no node {name!r} in the mesh", "NOEUD", occ)
            nodes.append(index)
    return nodes


def interface_modes(ctx, kw, st: Structure) -> list:
    """The static families of ENRI_STAT, in code_aster's order."""
    if kw.get("ENRI_STAT", "OUI") != "OUI":
        return []
    families = [
        pseudo_modes(ctx, kw, st, "MULTI"),
        pseudo_modes(ctx, kw, st, "MONO"),
        elastic_modes(ctx, kw, st),
        nonlinear_modes(ctx, kw, st),
    ]
    return [f for f in families if f is not None]


def modal_basis(ctx, kw, st: Structure):
    """The dynamic modes of the band, enriched and orthogonalised as asked."""
    modes = dynamic_modes(ctx, kw, st)
    families = interface_modes(ctx, kw, st)
    ritz = [{"MODE_MECA": modes}]
    extra = {}
    if families:
        static = families[0] if len(families) == 1 else stacked_fields(families, st.numbering)
        ritz.append({"MODE_INTF": static})
        extra = {"ORTHO": "OUI", "MATRICE": st.stiffness}
    basis = call(ctx, "DEFI_BASE_MODALE", RITZ=ritz, NUME_REF=st.numbering, **extra)
    if families and kw.get("ORTHO", "NON") == "OUI":
        basis = diagonalised(ctx, kw, st, basis)
    return basis


def diagonalised(ctx, kw, st: Structure, ritz):
    """The Ritz basis made (K, M)-orthogonal: modes of the projected pencil
    (all of them, or those below FREQ_COUP_STAT), restored on the physical DOFs."""
    numbering = call(ctx, "NUME_DDL_GENE", BASE=ritz, STOCKAGE="PLEIN")
    mass = call(ctx, "PROJ_MATR_BASE", BASE=ritz, NUME_DDL_GENE=numbering, MATR_ASSE=st.mass)
    stiffness = call(
        ctx, "PROJ_MATR_BASE", BASE=ritz, NUME_DDL_GENE=numbering, MATR_ASSE=st.stiffness
    )
    if kw.get("FREQ_COUP_STAT") is not None:
        low = frequency_band.band(as_tuple(kw.get("BANDE_ANALYSE")), cutoff_frequency(ctx, kw))[0]
        window = {"OPTION": "BANDE", "CALC_FREQ": {"FREQ": (low, kw["FREQ_COUP_STAT"])}}
    else:
        window = {"OPTION": "TOUT", "SOLVEUR_MODAL": {"METHODE": "QZ"}}
    modes = call(
        ctx,
        "CALC_MODES",
        MATR_RIGI=stiffness,
        MATR_MASS=mass,
        VERI_MODE={"STOP_ERREUR": "NON"},
        STOP_BANDE_VIDE="NON",
        **window,
    )
    restored = modes.physical()
    restored.mass, restored.stiffness = st.mass, st.stiffness
    return restored


def storage(kw) -> str:
    """PLEIN for a static enrichment kept non-orthogonal, else DIAG."""
    enriched = kw.get("ENRI_STAT", "OUI") == "OUI"
    return "PLEIN" if enriched and kw.get("ORTHO", "NON") != "OUI" else "DIAG"


# ----------------------------------------------------------------------------- runs


def common_keywords(ctx, kw) -> dict:
    """DYNA_VIBRA keywords shared by both bases."""
    out = {
        "TYPE_CALCUL": "TRAN",
        "INCREMENT": time_increment(ctx, kw),
        "SCHEMA_TEMPS": [dict(o) for o in kw.factor("SCHEMA_TEMPS")] or None,
        "ARCHIVAGE": [dict(o) for o in kw.factor("ARCHIVAGE")] or None,
    }
    return out


def physical(ctx, kw, st: Structure):
    """BASE_CALCUL='PHYS': DYNA_VIBRA on the assembled matrices."""

    def to_basis(vector):
        return {"VECT_ASSE": vector}

    excit = loading(ctx, kw, st, to_basis)
    multi = support_static_modes(ctx, kw, st, "MULTI")
    return call(
        ctx,
        "DYNA_VIBRA",
        BASE_CALCUL="PHYS",
        MODELE=st.model,
        MATR_MASS=st.mass,
        MATR_RIGI=st.stiffness,
        MATR_AMOR=st.damping,
        MODE_STAT=multi,
        ETAT_INIT=initial_state(kw, lambda f, name: on_numbering(f, st.numbering)),
        EXCIT=excit or None,
        **common_keywords(ctx, kw),
    )


def on_numbering(field_: NodalField, numbering) -> NodalField:
    if field_.numbering is numbering:
        return field_
    return NodalField(numbering, transfer(field_.values, field_.numbering, numbering))


def initial_state(kw, convert) -> dict | None:
    occurrences = kw.factor("ETAT_INIT")
    if not occurrences:
        return None
    occ = occurrences[0]
    return {
        name: convert(occ[name], name) for name in ("DEPL", "VITE") if occ.get(name) is not None
    } or None


def generalized(ctx, kw, st: Structure):
    """BASE_CALCUL='GENE': modal basis, projections, DYNA_VIBRA, restitution."""
    basis = modal_basis(ctx, kw, st)
    ctx.log(f"DYNA_LINE: modal basis of {basis.n_modes} vectors")
    numbering = call(ctx, "NUME_DDL_GENE", BASE=basis, STOCKAGE=storage(kw))

    def project(matrix):
        if matrix is None:
            return None
        return call(ctx, "PROJ_MATR_BASE", BASE=basis, NUME_DDL_GENE=numbering, MATR_ASSE=matrix)

    def to_basis(vector, kind="FORC"):
        gene = call(
            ctx,
            "PROJ_VECT_BASE",
            BASE=basis,
            NUME_DDL_GENE=numbering,
            VECT_ASSE=vector,
            TYPE_VECT=kind,
        )
        return {"VECT_ASSE_GENE": gene}

    damping = damping_keywords(kw)
    modal = None
    if damping.get("TYPE_AMOR") == "MODAL":
        modal = {"AMOR_REDUIT": tuple(as_tuple(damping["AMOR_REDUIT"]))}
    multi = support_static_modes(ctx, kw, st, "MULTI")
    excit = loading(ctx, kw, st, to_basis)
    transient = call(
        ctx,
        "DYNA_VIBRA",
        BASE_CALCUL="GENE",
        MATR_MASS=project(st.mass),
        MATR_RIGI=project(st.stiffness),
        MATR_AMOR=project(st.damping),
        AMOR_MODAL=modal,
        MODE_STAT=multi,
        ETAT_INIT=initial_state(kw, lambda f, name: to_basis(f, name)["VECT_ASSE_GENE"]),
        COMPORTEMENT=[dict(o) for o in kw.factor("COMPORTEMENT")] or None,
        EXCIT=excit or None,
        **common_keywords(ctx, kw),
    )
    if kw.get("BASE_RESU") is not None:
        ctx.bind(kw["BASE_RESU"], basis)
    if kw.get("RESU_GENE") is not None:
        ctx.bind(kw["RESU_GENE"], transient)
    return restored(ctx, kw, basis, transient, multi)


def restored(ctx, kw, basis, transient, multi):
    """REST_GENE_PHYS of every field: absolute motion with MULTI supports,
    absolute acceleration with a single MONO support."""
    extra = {}
    if multi is not None:
        extra["MULT_APPUI"] = "OUI"
    mono = excitations(kw, "MONO")
    if len(mono) == 1:
        function = mono[0].get("FONC_MULT") or mono[0].get("ACCE")
        extra["DIRECTION"] = tuple(as_tuple(mono[0]["DIRECTION"])[:3])
        extra["ACCE_MONO_APPUI"] = function
    return call(
        ctx, "REST_GENE_PHYS", RESU_GENE=transient, MODE_MECA=basis, TOUT_CHAM="OUI", **extra
    )


def run(ctx, kw):
    if kw["TYPE_CALCUL"] != "TRAN":
        ctx.unsupported("DYNA_LINE TYPE_CALCUL='HARM'", "TYPE_CALCUL", kw)
    st = structure(ctx, kw)
    if kw["BASE_CALCUL"] == "PHYS":
        return physical(ctx, kw, st)
    return generalized(ctx, kw, st)
