"""MODI_REPERE: fields of a result expressed in another frame."""

from asterlite.catalogues.common import group_ma, group_no, maille, noeud, tout

from asterlite.catalog import BLOC, ENSEMBLE, FACT, OPER, SIMP, UN_PARMI, equal_to, exists

_WHERE = dict(
    TOUT=tout(),
    GROUP_MA=group_ma(),
    GROUP_NO=group_no(),
    MAILLE=maille(),
    NOEUD=noeud(),
)
_WHERE_RULE = UN_PARMI("TOUT", "GROUP_MA", "MAILLE", "GROUP_NO", "NOEUD")


def _sd_prod(kw) -> str:
    if kw.get("RESULTAT") is not None:
        return getattr(kw["RESULTAT"], "aster_type", None) or "resultat_sdaster"
    return getattr(kw.get("CHAM_GD"), "aster_type", None) or "cham_gd_sdaster"


MODI_REPERE = OPER(
    nom="MODI_REPERE",
    sd_prod=_sd_prod,
    reentrant="f",
    fr="Fields of a result in another frame",
    regles=(UN_PARMI("CHAM_GD", "RESULTAT"),),
    CHAM_GD=SIMP(statut="f", typ="cham_gd_sdaster"),
    RESULTAT=SIMP(statut="f", typ="resultat_sdaster"),
    b_resultat=BLOC(
        condition=exists("RESULTAT"),
        TOUT_ORDRE=SIMP(statut="f", typ="TXM", into=("OUI",)),
        NUME_ORDRE=SIMP(statut="f", typ="I", max="**"),
        INST=SIMP(statut="f", typ="R", max="**"),
        FREQ=SIMP(statut="f", typ="R", max="**"),
        CRITERE=SIMP(statut="f", typ="TXM", defaut="RELATIF", into=("RELATIF", "ABSOLU")),
        PRECISION=SIMP(statut="f", typ="R"),
    ),
    MODI_CHAM=FACT(
        statut="f",
        max="**",
        TYPE_CHAM=SIMP(
            statut="o",
            typ="TXM",
            into=("VECT_2D", "VECT_3D", "TENS_2D", "TENS_3D", "COQUE_GENE", "1D_GENE"),
        ),
        NOM_CHAM=SIMP(statut="o", typ="TXM"),
        NOM_CMP=SIMP(statut="f", typ="TXM", max="**"),
        TOUT=tout(),
        GROUP_MA=group_ma(),
        NOM_CHAM_RESU=SIMP(statut="f", typ="TXM"),
    ),
    REPERE=SIMP(
        statut="o",
        typ="TXM",
        into=(
            "UTILISATEUR",
            "CYLINDRIQUE",
            "COQUE",
            "GLOBAL_UTIL",
            "COQUE_INTR_UTIL",
            "COQUE_UTIL_INTR",
            "COQUE_UTIL_CYL",
        ),
    ),  # fmt: skip
    b_cyl=BLOC(
        condition=equal_to("REPERE", ("CYLINDRIQUE", "COQUE_UTIL_CYL")),
        AFFE=FACT(
            statut="o",
            max="**",
            regles=(_WHERE_RULE,),
            ORIGINE=SIMP(statut="f", typ="R", min=2, max=3),
            AXE_Z=SIMP(statut="f", typ="R", min=3, max=3),
            **_WHERE,
        ),
    ),
    b_uti=BLOC(
        condition=equal_to("REPERE", "UTILISATEUR"),
        AFFE=FACT(
            statut="o",
            max="**",
            regles=(UN_PARMI("ANGL_NAUT", "VECT_X"), ENSEMBLE("VECT_X", "VECT_Y"), _WHERE_RULE),
            ANGL_NAUT=SIMP(statut="f", typ="R", max=3),
            VECT_X=SIMP(statut="f", typ="R", min=3, max=3),
            VECT_Y=SIMP(statut="f", typ="R", min=3, max=3),
            **_WHERE,
        ),
    ),
    b_coq=BLOC(
        condition=equal_to("REPERE", "COQUE"),
        AFFE=FACT(
            statut="o",
            max="**",
            regles=(UN_PARMI("ANGL_REP", "VECTEUR"), _WHERE_RULE),
            ANGL_REP=SIMP(statut="f", typ="R", min=2, max=2),
            VECTEUR=SIMP(statut="f", typ="R", min=3, max=3),
            **_WHERE,
        ),
    ),
    b_autre=BLOC(
        condition=equal_to("REPERE", ("GLOBAL_UTIL", "COQUE_INTR_UTIL", "COQUE_UTIL_INTR")),
        AFFE=FACT(statut="o", max="**", regles=(_WHERE_RULE,), **_WHERE),
    ),
    CARA_ELEM=SIMP(statut="f", typ="cara_elem"),
    TITRE=SIMP(statut="f", typ="TXM"),
    INFO=SIMP(statut="f", typ="I", defaut=1, into=(1, 2)),
)
