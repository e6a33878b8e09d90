"""DEFI_MODELE_GENE: the coupled model of dynamic substructuring."""

from asterlite.catalog import EXCLUS, FACT, OPER, SIMP


def interface_links():
    """LIAISON: which interfaces of which substructures are glued together
    (DEFI_MODELE_GENE and ASSE_ELEM_SSD read it alike)."""
    return FACT(
        statut="o",
        max="**",
        regles=(EXCLUS("GROUP_MA_MAIT_1", "GROUP_MA_MAIT_2"),),
        SOUS_STRUC_1=SIMP(statut="o", typ="TXM"),
        INTERFACE_1=SIMP(statut="o", typ="TXM"),
        SOUS_STRUC_2=SIMP(statut="o", typ="TXM"),
        INTERFACE_2=SIMP(statut="o", typ="TXM"),
        GROUP_MA_MAIT_1=SIMP(statut="f", typ="grma", max="**"),
        GROUP_MA_MAIT_2=SIMP(statut="f", typ="grma", max="**"),
        OPTION=SIMP(statut="f", typ="TXM", defaut="CLASSIQUE", into=("REDUIT", "CLASSIQUE")),
    )


DEFI_MODELE_GENE = OPER(
    nom="DEFI_MODELE_GENE",
    sd_prod="modele_gene",
    reentrant="n",
    fr="Build the global structure from its substructures (dynamic substructuring)",
    SOUS_STRUC=FACT(
        statut="o",
        max="**",
        NOM=SIMP(statut="o", typ="TXM"),
        MACR_ELEM_DYNA=SIMP(statut="o", typ="macr_elem_dyna"),
        ANGL_NAUT=SIMP(statut="o", typ="R", max=3),
        TRANS=SIMP(statut="o", typ="R", max=3),
    ),
    LIAISON=interface_links(),
    VERIF=FACT(
        statut="f",
        max="**",
        STOP_ERREUR=SIMP(statut="f", typ="TXM", defaut="OUI", into=("OUI", "NON")),
        PRECISION=SIMP(statut="f", typ="R", defaut=1.0e-3),
        CRITERE=SIMP(statut="f", typ="TXM", defaut="RELATIF", into=("RELATIF", "ABSOLU")),
    ),
    INFO=SIMP(statut="f", typ="I", defaut=1, into=(1, 2)),
)
