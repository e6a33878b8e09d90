"""DEFI_LIST_INST: the instants of a nonlinear computation and what to do
when a step fails (METHODE='MANUEL', failure on ERREUR)."""

from asterlite.catalog import BLOC, FACT, OPER, SIMP, UN_PARMI, equal_to


def _subdivision(**extra):
    return dict(
        SUBD_METHODE=SIMP(statut="f", typ="TXM", defaut="MANUEL", into=("MANUEL", "AUTO")),
        b_deco_manu=BLOC(
            condition=equal_to("SUBD_METHODE", "MANUEL"),
            SUBD_PAS=SIMP(statut="f", typ="I", defaut=4, val_min=2),
            SUBD_NIVEAU=SIMP(statut="f", typ="I", defaut=3, val_min=0),
            SUBD_PAS_MINI=SIMP(statut="f", typ="R", defaut=0.0, val_min=0.0),
        ),
        b_deco_auto=BLOC(
            condition=equal_to("SUBD_METHODE", "AUTO"),
            SUBD_PAS_MINI=SIMP(statut="f", typ="R", defaut=0.0, val_min=0.0),
        ),
        **extra,
    )


DEFI_LIST_INST = OPER(
    nom="DEFI_LIST_INST",
    sd_prod="list_inst",
    reentrant="n",
    fr="Instants of a nonlinear computation and its time-step cutting on failure",
    MODELE=SIMP(statut="f", typ="modele_sdaster"),
    METHODE=SIMP(statut="f", typ="TXM", defaut="MANUEL", into=("MANUEL",)),
    b_manuel=BLOC(
        condition=equal_to("METHODE", "MANUEL"),
        DEFI_LIST=FACT(
            statut="o",
            regles=(UN_PARMI("LIST_INST", "VALE"),),
            VALE=SIMP(statut="f", typ="R", max="**"),
            LIST_INST=SIMP(statut="f", typ="listr8_sdaster"),
        ),
    ),
    ECHEC=FACT(
        statut="d",
        max="**",
        EVENEMENT=SIMP(statut="f", typ="TXM", defaut="ERREUR", into=("ERREUR",)),
        b_erreur=BLOC(
            condition=equal_to("EVENEMENT", "ERREUR"),
            ACTION=SIMP(
                statut="f", typ="TXM", defaut="DECOUPE", into=("ARRET", "DECOUPE", "ITER_SUPPL")
            ),
            b_deco=BLOC(condition=equal_to("ACTION", "DECOUPE"), **_subdivision()),
            b_supp=BLOC(
                condition=equal_to("ACTION", "ITER_SUPPL"),
                **_subdivision(PCENT_ITER_PLUS=SIMP(statut="f", typ="I", defaut=50, val_min=20)),
            ),
        ),
    ),
    INFO=SIMP(statut="f", typ="I", defaut=1, into=(1, 2)),
)
