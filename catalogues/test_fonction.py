"""TEST_FONCTION: check values (or attributes) of functions against references."""

from asterlite.catalogues.common_post import test_reference

from asterlite.catalog import FACT, MACRO, SIMP, UN_PARMI

FUNCTIONS = ("fonction_sdaster", "fonction_c", "nappe_sdaster", "formule")

TEST_FONCTION = MACRO(
    nom="TEST_FONCTION",
    sd_prod=None,
    fr="Check the value or an attribute of a function against a reference",
    VALEUR=FACT(
        statut="f",
        max="**",
        fr="Value of a function (or a nappe) at given parameters",
        regles=(UN_PARMI("VALE_PARA", "INTERVALLE"),),
        FONCTION=SIMP(statut="o", typ=FUNCTIONS),
        NOM_PARA=SIMP(statut="f", typ="TXM", max=2),
        VALE_PARA=SIMP(statut="f", typ="R", max=2),
        INTERVALLE=SIMP(statut="f", typ="R", min=2, max=2),
        **test_reference("FONCTION"),
    ),
    ATTRIBUT=FACT(
        statut="f",
        max="**",
        fr="Attribute of a function or a nappe",
        FONCTION=SIMP(statut="o", typ=FUNCTIONS),
        PARA=SIMP(statut="f", typ="R"),
        CRIT_PARA=SIMP(statut="f", typ="TXM", defaut="RELATIF", into=("RELATIF", "ABSOLU")),
        PREC_PARA=SIMP(statut="f", typ="R", defaut=1.0e-3),
        ATTR=SIMP(
            statut="o",
            typ="TXM",
            into=(
                "NOM_PARA",
                "NOM_RESU",
                "PROL_DROITE",
                "PROL_GAUCHE",
                "INTERPOL",
                "PROL_GAUCHE_FONC",
                "PROL_DROITE_FONC",
                "INTERPOL_FONC",
                "NOM_PARA_FONC",
            ),
        ),
        ATTR_REFE=SIMP(statut="o", typ="TXM"),
        REFERENCE=SIMP(statut="f", typ="TXM", into=("ANALYTIQUE", "SOURCE_EXTERNE", "AUTRE_ASTER")),
    ),
)
