"""POST_RCCM: RCC-M code checks. asterlite catalogues the piping rule B3600.

Only ``TYPE_RESU_MECA='B3600'`` (equivalent moment and fatigue of piping)
is catalogued; the vessel rules (EVOLUTION, ZE200a/b, B3200) are not.
"""

from asterlite.catalogues.common_post import TABLE, precision_blocs

from asterlite.catalog import BLOC, FACT, OPER, SIMP, UN_PARMI, equal_to, exists

POST_RCCM = OPER(
    nom="POST_RCCM",
    sd_prod="table_sdaster",
    reentrant="n",
    fr="RCC-M criteria for piping (B3600)",
    TYPE_RESU=SIMP(statut="f", typ="TXM", defaut="VALE_MAX", into=("VALE_MAX", "DETAILS")),
    INFO=SIMP(statut="f", typ="I", into=(1, 2)),
    TITRE=SIMP(statut="f", typ="TXM"),
    TYPE_RESU_MECA=SIMP(statut="o", typ="TXM", into=("B3600",)),
    b_tuyauterie=BLOC(
        condition=equal_to("TYPE_RESU_MECA", "B3600"),
        OPTION=SIMP(statut="o", typ="TXM", into=("FATIGUE", "MOMENT_EQUIVALENT")),
        ZONE_ANALYSE=FACT(
            statut="o",
            fr="Elements analysed",
            regles=(UN_PARMI("TOUT", "GROUP_MA"),),
            TOUT=SIMP(statut="f", typ="TXM", into=("OUI",)),
            GROUP_MA=SIMP(statut="f", typ="grma", max="**"),
        ),
        b_momeq=BLOC(
            condition=equal_to("OPTION", "MOMENT_EQUIVALENT"),
            RESU_MECA=FACT(
                statut="o",
                max=1,
                fr="Mechanical loading",
                regles=(UN_PARMI("CHAM_GD", "RESULTAT"),),
                CHAM_GD=SIMP(statut="f", typ="cham_elem"),
                RESULTAT=SIMP(statut="f", typ="resultat_sdaster"),
                b_extrac=BLOC(
                    condition=exists("RESULTAT"),
                    regles=(UN_PARMI("TOUT_ORDRE", "NUME_ORDRE", "INST"),),
                    NOM_CHAM=SIMP(statut="f", typ="TXM", defaut="EFGE_ELNO", into=("EFGE_ELNO",)),
                    TOUT_ORDRE=SIMP(statut="f", typ="TXM", into=("OUI",)),
                    NUME_ORDRE=SIMP(statut="f", typ="I", max="**"),
                    INST=SIMP(statut="f", typ="R", max="**"),
                    b_acce_reel=BLOC(condition=exists("INST"), **precision_blocs()),
                ),
            ),
        ),
        b_fatigue=BLOC(
            condition=equal_to("OPTION", "FATIGUE"),
            CHAM_MATER=SIMP(statut="o", typ="cham_mater"),
            TYPE_KE=SIMP(statut="f", typ="TXM", defaut="KE_MECA", into=("KE_MECA", "KE_MIXTE")),
            MODELE=SIMP(statut="o", typ="modele_sdaster"),
            CARA_ELEM=SIMP(statut="o", typ="cara_elem"),
            RESU_MECA=FACT(
                statut="o",
                max="**",
                regles=(UN_PARMI("CHAM_GD", "RESULTAT"),),
                NUME_CHAR=SIMP(statut="o", typ="I"),
                NOM_CHAR=SIMP(statut="f", typ="TXM"),
                CHAM_GD=SIMP(statut="f", typ="cham_gd_sdaster"),
                RESULTAT=SIMP(statut="f", typ="resultat_sdaster"),
                b_extrac=BLOC(
                    condition=exists("RESULTAT"),
                    regles=(UN_PARMI("TOUT_ORDRE", "NUME_ORDRE", "INST", "NOEUD_CMP"),),
                    NOM_CHAM=SIMP(statut="o", typ="TXM", into=("EFGE_ELNO", "SIEF_ELNO")),
                    TOUT_ORDRE=SIMP(statut="f", typ="TXM", into=("OUI",)),
                    NUME_ORDRE=SIMP(statut="f", typ="I"),
                    INST=SIMP(statut="f", typ="R"),
                    NOEUD_CMP=SIMP(statut="f", typ="TXM", max="**"),
                    b_acce_reel=BLOC(condition=exists("INST"), **precision_blocs()),
                ),
            ),
            INDI_SIGM=FACT(
                statut="o",
                max="**",
                fr="Stress indices",
                regles=(UN_PARMI("TOUT", "GROUP_MA"),),
                C1=SIMP(statut="f", typ="R", defaut=1.0),
                K1=SIMP(statut="f", typ="R", defaut=1.0),
                C2=SIMP(statut="f", typ="R", defaut=1.0),
                K2=SIMP(statut="f", typ="R", defaut=1.0),
                C3=SIMP(statut="f", typ="R", defaut=0.5),
                K3=SIMP(statut="f", typ="R", defaut=1.0),
                TOUT=SIMP(statut="f", typ="TXM", into=("OUI",)),
                GROUP_MA=SIMP(statut="f", typ="grma", max="**"),
                MAILLE=SIMP(statut="c", typ="ma", max="**"),
                b_grma=BLOC(
                    condition=exists("GROUP_MA") | exists("MAILLE"),
                    GROUP_NO=SIMP(statut="f", typ="grno", max="**"),
                ),
                TYPE_ELEM_STANDARD=SIMP(statut="f", typ="TXM", into=("DRO", "COU", "TRN", "TEE")),
            ),
            RESU_THER=FACT(
                statut="f",
                max="**",
                regles=(UN_PARMI("TOUT", "GROUP_MA"),),
                NUME_RESU_THER=SIMP(statut="o", typ="I"),
                TABL_RESU_THER=SIMP(statut="o", typ=TABLE),
                TABL_MOYE_THER=SIMP(statut="o", typ=TABLE),
                TOUT=SIMP(statut="f", typ="TXM", into=("OUI",)),
                GROUP_MA=SIMP(statut="f", typ="grma", max="**"),
                b_grma=BLOC(
                    condition=exists("GROUP_MA"), GROUP_NO=SIMP(statut="f", typ="grno", max="**")
                ),
            ),
            SEISME=FACT(
                statut="f",
                max="**",
                NB_OCCUR=SIMP(statut="o", typ="I"),
                NB_CYCL_SEISME=SIMP(statut="o", typ="I"),
                NUME_SITU=SIMP(statut="o", typ="I"),
                NOM_SITU=SIMP(statut="f", typ="TXM"),
                NUME_GROUPE=SIMP(statut="o", typ="I"),
                CHAR_ETAT=SIMP(statut="o", typ="I", max="**"),
                TEMP_REF=SIMP(statut="f", typ="R"),
            ),
            SITUATION=FACT(
                statut="o",
                max="**",
                NB_OCCUR=SIMP(statut="o", typ="I"),
                NUME_SITU=SIMP(statut="o", typ="I"),
                NOM_SITU=SIMP(statut="f", typ="TXM"),
                COMBINABLE=SIMP(statut="f", typ="TXM", defaut="OUI", into=("OUI", "NON")),
                NUME_GROUPE=SIMP(statut="o", typ="I"),
                NUME_PASSAGE=SIMP(statut="f", typ="I", min=2, max=2),
                NUME_RESU_THER=SIMP(statut="f", typ="I", max="**"),
                CHAR_ETAT_A=SIMP(statut="o", typ="I", max="**"),
                CHAR_ETAT_B=SIMP(statut="o", typ="I", max="**"),
                PRES_A=SIMP(statut="o", typ="R"),
                PRES_B=SIMP(statut="o", typ="R"),
                TEMP_REF_A=SIMP(statut="f", typ="R"),
                TEMP_REF_B=SIMP(statut="f", typ="R"),
            ),
        ),
    ),
)
