"""CALC_FONCTION: operations on functions (combination, integration, spectra, FFT...).

Exactly one operation per call; the type of the result depends on it
(see :func:`calc_fonction_type`).
"""

from asterlite.catalogues.common_post import (
    INTERPOLATION,
    PARA_FONCTION,
    PROLONGEMENT,
    TABLE,
    concept_is,
    is_type,
)

from asterlite.catalog import BLOC, FACT, MACRO, SIMP, UN_PARMI, equal_to, exists

OPERATIONS = (
    "DERIVE", "INTEGRE", "SPEC_OSCI", "DSP", "FFT", "CORR_ACCE", "COMB", "COMB_C", "MULT", "ASSE",
    "INVERSE", "ABS", "ENVELOPPE", "COMPOSE", "EXTRACTION", "PUISSANCE", "PROL_SPEC_OSCI",
    "INTEGRE_FREQ", "DERIVE_FREQ", "LISS_ENVELOP", "FRACTILE", "REGR_POLYNOMIALE", "MOYENNE",
    "COHERENCE", "INTERPOL_FFT",
)  # fmt: skip


def _first_function(kw, operation):
    occurrences = kw.get(operation) or []
    first = occurrences[0] if occurrences else {}
    value = first.get("FONCTION")
    if isinstance(value, (list, tuple)):
        value = value[0] if value else None
    return value


def _same_as_input(kw, operation) -> str:
    """nappe_sdaster when the (first) function is a nappe, fonction_sdaster otherwise."""
    if concept_is(_first_function(kw, operation), "nappe_sdaster"):
        return "nappe_sdaster"
    if concept_is(_first_function(kw, operation), "fonction_c"):
        return "fonction_c"
    return "fonction_sdaster"


def calc_fonction_type(kw) -> str:
    """The result type of the operation given."""
    if kw.get("COMB_C") is not None:
        if concept_is(_first_function(kw, "COMB_C"), "nappe_sdaster"):
            return "nappe_sdaster"
        return "fonction_c"
    for operation in ("COMB", "ENVELOPPE", "FRACTILE", "MOYENNE", "MULT", "PUISSANCE"):
        if kw.get(operation) is not None:
            return _same_as_input(kw, operation)
    if kw.get("SPEC_OSCI") is not None:
        occurrence = kw["SPEC_OSCI"][0]
        if occurrence.get("TYPE_RESU") == "NAPPE":
            return "nappe_sdaster"
        damping = occurrence.get("AMOR_REDUIT")
        return "fonction_sdaster" if damping is not None and len(damping) == 1 else "nappe_sdaster"
    if kw.get("FFT") is not None:
        is_complex = concept_is(_first_function(kw, "FFT"), "fonction_c")
        return "fonction_sdaster" if is_complex else "fonction_c"
    if kw.get("LISS_ENVELOP") is not None:
        return "nappe_sdaster"
    return "fonction_sdaster"


CALC_FONCTION = MACRO(
    nom="CALC_FONCTION",
    sd_prod=calc_fonction_type,
    reentrant="n",
    fr="Mathematical operations on functions",
    regles=(UN_PARMI(*OPERATIONS),),
    FFT=FACT(
        statut="f",
        fr="Fourier transform or its inverse",
        FONCTION=SIMP(statut="o", typ=("fonction_sdaster", "fonction_c")),
        METHODE=SIMP(
            statut="f", typ="TXM", defaut="PROL_ZERO", into=("PROL_ZERO", "TRONCATURE", "COMPLET")
        ),
        b_syme=BLOC(
            condition=is_type("FONCTION", "fonction_c"),
            SYME=SIMP(statut="f", typ="TXM", into=("OUI", "NON"), defaut="OUI"),
        ),
    ),
    INTERPOL_FFT=FACT(
        statut="f",
        fr="Resample an accelerogram by zero padding",
        FONCTION=SIMP(statut="o", typ="fonction_sdaster"),
        PAS_INST=SIMP(statut="o", typ="R", fr="Wanted time step"),
        PRECISION=SIMP(statut="f", typ="R", defaut=1e-2),
    ),
    DERIVE=FACT(
        statut="f",
        fr="Derivative of a function",
        METHODE=SIMP(statut="f", typ="TXM", defaut="DIFF_CENTREE", into=("DIFF_CENTREE",)),
        FONCTION=SIMP(statut="o", typ="fonction_sdaster"),
    ),
    INTEGRE=FACT(
        statut="f",
        fr="Integral of a function",
        METHODE=SIMP(statut="f", typ="TXM", defaut="TRAPEZE", into=("SIMPSON", "TRAPEZE")),
        FONCTION=SIMP(statut="o", typ="fonction_sdaster"),
        COEF=SIMP(statut="f", typ="R", defaut=0.0, fr="Integration constant"),
    ),
    LISS_ENVELOP=FACT(
        statut="f",
        fr="Smoothing of an envelope spectrum",
        regles=(UN_PARMI("NAPPE", "FONCTION", "TABLE"),),
        NAPPE=SIMP(statut="f", typ="nappe_sdaster", max="**"),
        TABLE=SIMP(statut="f", typ=TABLE, max="**"),
        FONCTION=SIMP(statut="f", typ="fonction_sdaster"),
        LIST_AMOR=SIMP(statut="f", typ="R", max="**"),
        OPTION=SIMP(statut="o", typ="TXM", into=("CONCEPTION", "VERIFICATION")),
        b_verif=BLOC(
            condition=equal_to("OPTION", "VERIFICATION"),
            ELARG=SIMP(statut="f", typ="R", max="**", val_min=0.0, val_max=1.0),
        ),
        FREQ_MIN=SIMP(statut="f", typ="R"),
        FREQ_MAX=SIMP(statut="f", typ="R"),
        LIST_FREQ=SIMP(statut="f", typ="R", max="**"),
        NB_FREQ_LISS=SIMP(statut="f", typ="I", max=2, val_min=1, defaut=(10,)),
        ZPA=SIMP(statut="f", typ="R"),
    ),
    REGR_POLYNOMIALE=FACT(
        statut="f",
        fr="Polynomial regression of a function",
        FONCTION=SIMP(statut="o", typ="fonction_sdaster"),
        DEGRE=SIMP(statut="o", typ="I"),
    ),
    PROL_SPEC_OSCI=FACT(
        statut="f",
        fr="Extend an oscillator spectrum up to DEPL_MAX",
        FONCTION=SIMP(statut="o", typ="fonction_sdaster"),
        NORME=SIMP(statut="o", typ="R"),
        DEPL_MAX=SIMP(statut="o", typ="R", val_min=0.0),
    ),
    SPEC_OSCI=FACT(
        statut="f",
        fr="Oscillator response spectrum",
        TYPE_RESU=SIMP(statut="f", typ="TXM", defaut="NAPPE", into=("NAPPE", "FONCTION")),
        METHODE=SIMP(statut="f", typ="TXM", defaut="NIGAM", into=("NIGAM", "HARMO", "RICE")),
        FONCTION=SIMP(statut="o", typ="fonction_sdaster"),
        AMOR_REDUIT=SIMP(statut="f", typ="R", max="**"),
        LIST_FREQ=SIMP(statut="f", typ="listr8_sdaster"),
        FREQ=SIMP(statut="f", typ="R", max="**"),
        NORME=SIMP(statut="o", typ="R"),
        b_nigam=BLOC(
            condition=equal_to("METHODE", "NIGAM"),
            NATURE_FONC=SIMP(statut="f", typ="TXM", defaut="ACCE", into=("ACCE",)),
            NATURE=SIMP(statut="f", typ="TXM", defaut="ACCE", into=("DEPL", "VITE", "ACCE")),
        ),
        b_rice=BLOC(
            condition=equal_to("METHODE", "RICE"),
            DUREE=SIMP(statut="o", typ="R", val_min=0.0, fr="Strong-motion duration"),
            NATURE_FONC=SIMP(statut="f", typ="TXM", defaut="DSP", into=("DSP",)),
            NATURE=SIMP(statut="f", typ="TXM", defaut="ACCE", into=("DEPL", "VITE", "ACCE")),
        ),
        b_harmo=BLOC(
            condition=equal_to("METHODE", "HARMO"),
            PSEUDO=SIMP(statut="f", typ="TXM", defaut="OUI", into=("OUI", "NON")),
            NATURE_FONC=SIMP(statut="f", typ="TXM", defaut="ACCE", into=("ACCE",)),
            NATURE=SIMP(statut="f", typ="TXM", defaut="ACCE", into=("DEPL", "VITE", "ACCE")),
        ),
    ),
    DSP=FACT(
        statut="f",
        fr="Power spectral density compatible with a response spectrum",
        regles=(UN_PARMI("FREQ_PAS", "LIST_FREQ"),),
        FONCTION=SIMP(statut="o", typ="fonction_sdaster"),
        AMOR_REDUIT=SIMP(statut="o", typ="R", val_min=0.0, val_max=1.0),
        NORME=SIMP(statut="o", typ="R"),
        LIST_FREQ=SIMP(statut="f", typ="listr8_sdaster"),
        NB_ITER=SIMP(statut="f", typ="I", val_min=0, defaut=10),
        FREQ_FILTRE_ZPA=SIMP(statut="f", typ="R", defaut=0.0, val_min=0.0),
        NB_FREQ_LISS=SIMP(statut="f", typ="I", defaut=0),
        FREQ_PAS=SIMP(statut="f", typ="R"),
        FREQ_COUP=SIMP(statut="o", typ="R"),
        DUREE=SIMP(statut="o", typ="R", val_min=0.0),
        FRACT=SIMP(statut="f", typ="R", defaut=0.5, val_min=0.0, val_max=1.0),
    ),
    ABS=FACT(
        statut="f",
        fr="Absolute value of a function",
        FONCTION=SIMP(statut="o", typ="fonction_sdaster"),
    ),
    COMB=FACT(
        statut="f",
        max="**",
        fr="Real linear combination of functions",
        FONCTION=SIMP(statut="o", typ=("fonction_sdaster", "nappe_sdaster")),
        COEF=SIMP(statut="o", typ="R"),
    ),
    COMB_C=FACT(
        statut="f",
        max="**",
        fr="Complex linear combination of functions",
        regles=(UN_PARMI("COEF_R", "COEF_C"),),
        FONCTION=SIMP(statut="o", typ=("fonction_sdaster", "fonction_c", "nappe_sdaster")),
        COEF_R=SIMP(statut="f", typ="R"),
        COEF_C=SIMP(statut="f", typ="C"),
    ),
    MULT=FACT(
        statut="f",
        max="**",
        fr="Product of functions",
        FONCTION=SIMP(statut="o", typ=("fonction_sdaster", "fonction_c", "nappe_sdaster")),
    ),
    b_comb=BLOC(
        condition=exists("COMB") | exists("COMB_C") | exists("REGR_POLYNOMIALE") | exists("MULT"),
        LIST_PARA=SIMP(statut="f", typ="listr8_sdaster"),
    ),
    COMPOSE=FACT(
        statut="f",
        fr="Composition FONC_RESU(FONC_PARA)",
        FONC_RESU=SIMP(statut="o", typ="fonction_sdaster"),
        FONC_PARA=SIMP(statut="o", typ="fonction_sdaster"),
    ),
    EXTRACTION=FACT(
        statut="f",
        fr="Part of a complex function",
        FONCTION=SIMP(statut="o", typ="fonction_c"),
        PARTIE=SIMP(statut="o", typ="TXM", into=("REEL", "IMAG", "MODULE", "PHASE")),
    ),
    ENVELOPPE=FACT(
        statut="f",
        fr="Envelope of a family of functions",
        FONCTION=SIMP(statut="o", typ=("fonction_sdaster", "nappe_sdaster"), max="**"),
        CRITERE=SIMP(statut="f", typ="TXM", defaut="SUP", into=("SUP", "INF")),
    ),
    FRACTILE=FACT(
        statut="f",
        fr="Fractile of a family of functions",
        FONCTION=SIMP(statut="o", typ=("fonction_sdaster", "nappe_sdaster"), max="**"),
        FRACT=SIMP(statut="f", typ="R", defaut=1.0, val_min=0.0, val_max=1.0),
    ),
    MOYENNE=FACT(
        statut="f",
        fr="Mean of a family of functions",
        FONCTION=SIMP(statut="o", typ=("fonction_sdaster", "nappe_sdaster"), max="**"),
    ),
    COHERENCE=FACT(
        statut="f",
        fr="Coherence function",
        NAPPE_1=SIMP(statut="o", typ="nappe_sdaster"),
        NAPPE_2=SIMP(statut="o", typ="nappe_sdaster"),
        FREQ_COUP=SIMP(statut="f", typ="R"),
        OPTION=SIMP(statut="f", typ="TXM", defaut="TOUT", into=("DUREE_PHASE_FORTE", "TOUT")),
        b_option_f=BLOC(
            condition=equal_to("OPTION", "DUREE_PHASE_FORTE"),
            BORNE_INF=SIMP(statut="f", typ="R", defaut=0.05, val_min=0.0, val_max=0.5),
            BORNE_SUP=SIMP(statut="f", typ="R", defaut=0.95, val_min=0.5, val_max=1.0),
        ),
        NB_FREQ_LISS=SIMP(statut="f", typ="I", defaut=12),
    ),
    ASSE=FACT(
        statut="f",
        fr="Concatenation of two functions",
        FONCTION=SIMP(statut="o", typ="fonction_sdaster", min=2, max=2),
        SURCHARGE=SIMP(statut="f", typ="TXM", defaut="DROITE", into=("DROITE", "GAUCHE")),
    ),
    CORR_ACCE=FACT(
        statut="f",
        fr="Baseline correction of a recorded accelerogram",
        FONCTION=SIMP(statut="o", typ="fonction_sdaster"),
        METHODE=SIMP(statut="o", typ="TXM", into=("FILTRAGE", "POLYNOME")),
        b_corr1=BLOC(
            condition=equal_to("METHODE", "FILTRAGE"),
            FREQ_FILTRE=SIMP(statut="f", typ="R", defaut=0.05, val_min=0.0),
        ),
        b_corr2=BLOC(
            condition=equal_to("METHODE", "POLYNOME"),
            CORR_DEPL=SIMP(statut="f", typ="TXM", defaut="NON", into=("OUI", "NON")),
        ),
    ),
    PUISSANCE=FACT(
        statut="f",
        fr="Function raised to a power",
        FONCTION=SIMP(statut="o", typ=("fonction_sdaster", "nappe_sdaster")),
        EXPOSANT=SIMP(statut="f", typ="I", defaut=1),
    ),
    INVERSE=FACT(
        statut="f",
        fr="Inverse of a function",
        FONCTION=SIMP(statut="o", typ="fonction_sdaster"),
    ),
    INTEGRE_FREQ=FACT(
        statut="f",
        fr="Frequency-domain integration of an accelerogram",
        FONCTION=SIMP(statut="o", typ="fonction_sdaster"),
        NIVEAU=SIMP(statut="f", typ="I", defaut=2, into=(1, 2)),
        FREQ_FILTRE=SIMP(statut="f", typ="R", defaut=0.0, val_min=0.0),
        FREQ_COUP=SIMP(statut="o", typ="R", val_min=0.0),
    ),
    DERIVE_FREQ=FACT(
        statut="f",
        fr="Frequency-domain derivation of an accelerogram",
        FONCTION=SIMP(statut="o", typ="fonction_sdaster"),
        NIVEAU=SIMP(statut="f", typ="I", defaut=2, into=(1, 2)),
        FREQ_COUP=SIMP(statut="f", typ="R", defaut=50.0, val_min=0.0),
    ),
    # attributes of the result, overriding those of the input
    NOM_PARA=SIMP(statut="f", typ="TXM", into=PARA_FONCTION),
    NOM_RESU=SIMP(statut="f", typ="TXM"),
    INTERPOL=SIMP(statut="f", typ="TXM", max=2, into=INTERPOLATION),
    PROL_DROITE=SIMP(statut="f", typ="TXM", into=PROLONGEMENT),
    PROL_GAUCHE=SIMP(statut="f", typ="TXM", into=PROLONGEMENT),
    NOM_PARA_FONC=SIMP(statut="f", typ="TXM", into=PARA_FONCTION),
    INTERPOL_FONC=SIMP(statut="f", typ="TXM", max=2, into=INTERPOLATION),
    PROL_DROITE_FONC=SIMP(statut="f", typ="TXM", into=PROLONGEMENT),
    PROL_GAUCHE_FONC=SIMP(statut="f", typ="TXM", into=PROLONGEMENT),
    INFO=SIMP(statut="f", typ="I", defaut=1, into=(1, 2)),
)
