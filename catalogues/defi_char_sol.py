"""DEFI_CHAR_SOL: the load a soil column applies on the lateral boundaries
of a model, from a transient result (RESU_INIT) or from a file of motions
(UNITE_TRAN_INIT)."""

from asterlite.catalog import AU_MOINS_UN, BLOC, MACRO, SIMP, UN_PARMI, exists

DEFI_CHAR_SOL = MACRO(
    nom="DEFI_CHAR_SOL",
    sd_prod="char_meca",
    reentrant="n",
    fr="Soil loads on the lateral boundaries of a model",
    regles=(UN_PARMI("UNITE_TRAN_INIT", "RESU_INIT"),),
    CHARGEMENT=SIMP(statut="f", typ="TXM", into=("FORCE", "ONDE_PLANE"), defaut="FORCE"),
    MODELE=SIMP(statut="o", typ="modele_sdaster"),
    UNITE_TRAN_INIT=SIMP(statut="f", typ="I"),
    RESU_INIT=SIMP(statut="f", typ=("dyna_trans", "evol_char", "evol_noli")),
    b_unite_tran=BLOC(
        condition=exists("UNITE_TRAN_INIT"),
        regles=(AU_MOINS_UN("GROUP_MA_DROITE", "GROUP_MA_GAUCHE"),),
        LONG_CARA=SIMP(statut="f", typ="R"),
        AXE=SIMP(statut="f", typ="TXM", into=("X", "Y", "Z")),
        NOM_PARA=SIMP(statut="f", typ="TXM", into=("Y", "Z"), defaut="Z"),
        Z0=SIMP(statut="f", typ="R", defaut=0.0),
        NOM_CMP=SIMP(statut="f", typ="TXM", into=("DX", "DY"), defaut="DX"),
        GROUP_MA_DROITE=SIMP(statut="f", typ="grma"),
        GROUP_MA_GAUCHE=SIMP(statut="f", typ="grma"),
        TABLE_MATER_ELAS=SIMP(statut="o", typ="table_sdaster"),
    ),
    b_resu=BLOC(
        condition=exists("RESU_INIT"),
        MATR_RIGI=SIMP(statut="f", typ="matr_asse_depl_r"),
        COEF=SIMP(statut="f", typ="R", defaut=1.0),
        NOM_CHAM_INIT=SIMP(
            statut="f", typ="TXM", defaut="FORC_NODA", into=("ACCE", "FORC_NODA", "REAC_NODA")
        ),
        DDL_EXCLUS=SIMP(statut="f", typ="TXM", into=("DX", "DY", "DZ", "DRX", "DRY", "DRZ")),
        MATR_AMOR=SIMP(statut="f", typ="matr_asse_depl_r"),
        NUME_DDL=SIMP(statut="f", typ="nume_ddl_sdaster"),
        LIST_INST=SIMP(statut="o", typ="listr8_sdaster"),
        PRECISION=SIMP(statut="f", typ="R", defaut=1.0e-6),
        CRITERE=SIMP(statut="f", typ="TXM", defaut="RELATIF", into=("RELATIF", "ABSOLU")),
    ),
    TITRE=SIMP(statut="f", typ="TXM"),
    INFO=SIMP(statut="f", typ="I", defaut=1, into=(1, 2)),
)
