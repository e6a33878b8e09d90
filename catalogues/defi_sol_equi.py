"""DEFI_SOL_EQUI: equivalent-linear response of a layered soil column
(code_aster 17's catalogue; commands/defi_sol_equi.py says which branches
asterlite computes)."""

from asterlite.catalog import (
    BLOC,
    ENSEMBLE,
    EXCLUS,
    FACT,
    MACRO,
    SIMP,
    UN_PARMI,
    absent,
    equal_to,
    exists,
)


def _signal_keywords(tout_cham_default):
    """The keywords both CHARGEMENT blocks share (TOUT_CHAM's default differs)."""
    return dict(
        FONC_SIGNAL=SIMP(statut="f", typ="fonction_sdaster"),
        FONC_SIGNAL_X=SIMP(statut="f", typ="fonction_sdaster"),
        FONC_SIGNAL_Y=SIMP(statut="f", typ="fonction_sdaster"),
        FONC_SIGNAL_Z=SIMP(statut="f", typ="fonction_sdaster"),
        TOUT_CHAM=SIMP(statut="f", typ="TXM", into=("OUI", "NON"), defaut=tout_cham_default),
        TOUT_ACCE=SIMP(statut="f", typ="TXM", into=("OUI", "NON"), defaut="OUI"),
        b_TOUTACCE=BLOC(
            condition=equal_to("TOUT_ACCE", "NON"),
            LIST_COUCHE_ACCE=SIMP(statut="f", typ="grma", max="**"),
        ),
        NOM_CMP=SIMP(statut="f", typ="TXM", into=("DX", "DY"), defaut="DX"),
        GROUP_MA_ARRETE_1=SIMP(statut="f", typ="grma"),
        GROUP_MA_ARRETE_2=SIMP(statut="f", typ="grma"),
        b_MAIL3D=BLOC(
            condition=exists("FONC_SIGNAL_X"),
            MAILLAGE=SIMP(statut="o", typ="maillage_sdaster"),
        ),
        b_MAIL2D=BLOC(
            condition=absent("FONC_SIGNAL_X"),
            MAILLAGE=SIMP(statut="f", typ="maillage_sdaster"),
        ),
        b_BYRNE=BLOC(
            condition=absent("GROUP_MA_ARRETE_1"),
            CORRECTION=SIMP(statut="f", typ="TXM", into=("BYRNE", "SANS"), defaut="SANS"),
            b_CORRECTION=BLOC(
                condition=equal_to("CORRECTION", "BYRNE"),
                COEF_KSI=SIMP(statut="f", typ="R", defaut=0.666666667),
            ),
        ),
    )


_ARRETES = ENSEMBLE(
    "FONC_SIGNAL_X", "FONC_SIGNAL_Y", "FONC_SIGNAL_Z", "GROUP_MA_ARRETE_1", "GROUP_MA_ARRETE_2"
)

DEFI_SOL_EQUI = MACRO(
    nom="DEFI_SOL_EQUI",
    sd_prod="table_sdaster",
    reentrant="n",
    fr="Equivalent-linear response of a layered soil column",
    regles=(
        ENSEMBLE("TABLE_MATER_ELAS", "TABLE_GEQUI_GMAX", "TABLE_AMOR_EQUI"),
        ENSEMBLE("GROUP_MA_DROITE", "GROUP_MA_GAUCHE"),
    ),
    LIEU_SIGNAL=SIMP(
        statut="f", typ="TXM", into=("AFFLEURANT", "CHAMP_LIBRE"), defaut="AFFLEURANT"
    ),
    CHARGEMENT=SIMP(statut="f", typ="TXM", into=("MONO_APPUI", "ONDE_PLANE"), defaut="MONO_APPUI"),
    b_ONDE=BLOC(
        condition=equal_to("CHARGEMENT", "ONDE_PLANE"),
        regles=(
            UN_PARMI("FONC_SIGNAL", "UNITE_TRAN_INIT", "FONC_SIGNAL_X"),
            _ARRETES,
            EXCLUS("FONC_SIGNAL_X", "LIAISON"),
        ),
        UNITE_TRAN_INIT=SIMP(statut="f", typ="I"),
        LIAISON=SIMP(statut="f", typ="TXM", into=("PERIODIQUE", "SANS")),
        MASS_PENA=SIMP(statut="f", typ="R"),
        LONG_CARA=SIMP(statut="f", typ="R"),
        **_signal_keywords("OUI"),
    ),
    b_MONO=BLOC(
        condition=equal_to("CHARGEMENT", "MONO_APPUI"),
        regles=(UN_PARMI("FONC_SIGNAL", "DSP", "FONC_SIGNAL_X"), _ARRETES),
        DSP=SIMP(statut="f", typ="fonction_sdaster"),
        b_type_dsp=BLOC(
            condition=exists("DSP"),
            DUREE=SIMP(statut="o", typ="R", val_min=0.0),
            UNITE_RESU_DSP=SIMP(statut="o", typ="I"),
        ),
        **_signal_keywords("NON"),
    ),
    CORR_AMOR=SIMP(statut="f", typ="TXM", into=("OUI", "NON"), defaut="NON"),
    LIST_FREQ_SPEC_OSCI=SIMP(statut="f", typ="listr8_sdaster"),
    LIST_FREQ=SIMP(statut="f", typ="listr8_sdaster"),
    MAILLAGE=SIMP(statut="f", typ="maillage_sdaster"),
    GROUP_MA_DROITE=SIMP(statut="o", typ="grma"),
    GROUP_MA_GAUCHE=SIMP(statut="o", typ="grma"),
    GROUP_MA_SUBSTR=SIMP(statut="o", typ="grma"),
    GROUP_MA_COL=SIMP(statut="o", typ="grma"),
    COEF_VARI_MATE=SIMP(statut="f", typ="R", defaut=1.0),
    COEF_AMPL_ACCE=SIMP(statut="f", typ="R", defaut=1.0),
    COEF_GAMMA=SIMP(statut="f", typ="R", defaut=0.65),
    NMAX_ITER=SIMP(statut="f", typ="I", defaut=10, val_min=1),
    RESI_RELA=SIMP(statut="f", typ="R", defaut=0.05),
    FREQ_COUP=SIMP(statut="f", typ="R"),
    FREQ_FILTRE=SIMP(statut="f", typ="R", defaut=0.0),
    INTEGRATION=SIMP(statut="f", typ="TXM", into=("TEMPS", "FREQUENCE"), defaut="TEMPS"),
    SURF=SIMP(statut="f", typ="TXM", into=("OUI", "NON"), defaut="NON"),
    b_SURF=BLOC(
        condition=equal_to("SURF", "NON"),
        NIVE_COUCH_ENFO=SIMP(statut="o", typ="I"),
        NB_RECEPTEUR=SIMP(statut="f", typ="I", into=(2, 4), defaut=2),
    ),
    UNITE_TABLE_RESU=SIMP(statut="f", typ="I"),
    UNITE_RESU_TRAN=SIMP(statut="f", typ="I", defaut=40),
    UNITE_RESU_SPEC=SIMP(statut="f", typ="I", defaut=55),
    TABLE_MATER_ELAS=SIMP(statut="f", typ="table_sdaster"),
    TABLE_GEQUI_GMAX=SIMP(statut="f", typ="table_sdaster"),
    TABLE_AMOR_EQUI=SIMP(statut="f", typ="table_sdaster"),
    SEPARATEUR=SIMP(statut="f", typ="TXM", defaut=" "),
    LIST_EPSI=SIMP(statut="f", typ="listr8_sdaster"),
    b_ntabl_mater=BLOC(
        condition=absent("TABLE_MATER_ELAS"),
        MATERIAU=FACT(
            statut="f",
            max="**",
            GAMMA=SIMP(statut="o", typ="R", max="**"),
            G_GMAX=SIMP(statut="o", typ="R", max="**"),
            D=SIMP(statut="o", typ="R", max="**"),
        ),
        COUCHE=FACT(
            statut="f",
            max="**",
            EPAIS=SIMP(statut="o", typ="R"),
            GROUP_MA=SIMP(statut="o", typ="grma"),
            E=SIMP(statut="o", typ="R"),
            NU=SIMP(statut="o", typ="R"),
            RHO=SIMP(statut="o", typ="R"),
            AMOR_HYST=SIMP(statut="o", typ="R"),
            NUME_MATE=SIMP(statut="o", typ="I"),
            N1=SIMP(statut="f", typ="R"),
        ),
    ),
    TITRE=SIMP(statut="f", typ="TXM"),
    INFO=SIMP(statut="f", typ="I", defaut=1, into=(1, 2)),
)
