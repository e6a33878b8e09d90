"""CALC_SPECTRE_IPM: floor response spectra corrected for the interaction
between the floor and the equipment it carries (code_aster 17's keywords)."""

from asterlite.catalog import BLOC, FACT, MACRO, SIMP, UN_PARMI, absent, equal_to, exists


def _equipment(support_key: str) -> FACT:
    return FACT(
        statut="o",
        max="**",
        NOM=SIMP(statut="o", typ="TXM"),
        **{
            support_key: SIMP(
                statut="o", typ="grno" if support_key == "GROUP_NO" else "no", max="**"
            )
        },  # fmt: skip
        RAPPORT_MASSE_TOTALE=SIMP(statut="o", typ="R", max=1),
        COEF_MASS_EQUIP=SIMP(statut="o", typ="R", max="**"),
        FREQ_SUPPORT=SIMP(statut="o", typ="R", max=1),
        AMOR_SUPPORT=SIMP(statut="o", typ="R", max=1),
        AMOR_EQUIP=SIMP(statut="o", typ="R", max="**"),
        FREQ_EQUIP=SIMP(statut="o", typ="R", max="**"),
    )


CALC_SPECTRE_IPM = MACRO(
    nom="CALC_SPECTRE_IPM",
    sd_prod="table_sdaster",
    reentrant="n",
    fr="Floor response spectra with the floor-equipment interaction",
    MAILLAGE=SIMP(statut="f", typ="maillage_sdaster"),
    b_maillage=BLOC(condition=exists("MAILLAGE"), EQUIPEMENT=_equipment("GROUP_NO")),
    b_no_maillage=BLOC(condition=absent("MAILLAGE"), EQUIPEMENT=_equipment("NOEUD")),
    CALCUL=SIMP(statut="o", typ="TXM", into=("ABSOLU", "RELATIF")),
    AMOR_SPEC=SIMP(statut="o", typ="R", max="**"),
    LIST_INST=SIMP(statut="f", typ="listr8_sdaster"),
    LIST_FREQ=SIMP(statut="f", typ="listr8_sdaster"),
    FREQ=SIMP(statut="f", typ="R", max="**"),
    NORME=SIMP(statut="o", typ="R"),
    b_rela=BLOC(
        condition=equal_to("CALCUL", "RELATIF"),
        RESU=FACT(
            statut="o",
            max=1,
            regles=(UN_PARMI("TABLE", "FONCTION"),),
            TABLE=SIMP(statut="f", typ="table_sdaster"),
            FONCTION=SIMP(statut="f", typ="fonction_sdaster"),
            ACCE_Z=SIMP(statut="o", typ="fonction_sdaster"),
        ),
    ),
    b_abso=BLOC(
        condition=equal_to("CALCUL", "ABSOLU"),
        RESU=FACT(
            statut="o",
            max=1,
            regles=(UN_PARMI("TABLE", "FONCTION"),),
            TABLE=SIMP(statut="f", typ="table_sdaster"),
            FONCTION=SIMP(statut="f", typ="fonction_sdaster"),
        ),
    ),
    TOLE_INIT=SIMP(statut="f", typ="R", max=1, defaut=1e-3),
    CORR_INIT=SIMP(statut="f", typ="TXM", defaut="NON", into=("OUI", "NON")),
)
