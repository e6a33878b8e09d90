"""IMPR_CO: print the internal objects of concepts (a developer aid)."""

from asterlite.catalogues.common import ANY_CONCEPT

from asterlite.catalog import BLOC, FACT, PROC, SIMP, UN_PARMI, equal_to

IMPR_CO = PROC(
    nom="IMPR_CO",
    fr="Print the content of concepts",
    regles=(UN_PARMI("CONCEPT", "CHAINE", "TOUT"),),
    UNITE=SIMP(statut="f", typ="I", defaut=8),
    NIVEAU=SIMP(statut="f", typ="I", defaut=2, into=(-1, 0, 1, 2)),
    ATTRIBUT=SIMP(statut="f", typ="TXM", defaut="NON", into=("NON", "OUI")),
    CONTENU=SIMP(statut="f", typ="TXM", defaut="OUI", into=("NON", "OUI")),
    BASE=SIMP(statut="f", typ="TXM", defaut="G", into=(" ", "G", "V", "L")),
    CONCEPT=FACT(statut="f", max="**", NOM=SIMP(statut="o", typ=ANY_CONCEPT, max="**")),
    CHAINE=SIMP(statut="f", typ="TXM"),
    POSITION=SIMP(statut="f", typ="I", defaut=1),
    TOUT=SIMP(statut="f", typ="TXM", into=("OUI",)),
    b_permut=BLOC(
        condition=equal_to("NIVEAU", -1),
        PERMUTATION=SIMP(statut="f", typ="TXM", defaut="OUI", into=("NON", "OUI")),
    ),
)
