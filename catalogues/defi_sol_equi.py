"""DEFI_SOL_EQUI: equivalent-linear response of a layered soil column, as
asterlite computes it (code_aster 17's keywords, defaults and rules for the
branches it takes; commands/defi_sol_equi.py tells them). Left out, so that
``asterlite check`` reports them unsupported: UNITE_TRAN_INIT, DSP, the 3D
signals (FONC_SIGNAL_X/Y/Z, GROUP_MA_ARRETE_*), MAILLAGE, LIST_FREQ,
LIAISON='SANS', NOM_CMP='DY', CORRECTION='BYRNE', INTEGRATION='FREQUENCE',
SURF='NON' (its default: SURF='OUI' must be given) and spectra without
LIST_FREQ_SPEC_OSCI. MASS_PENA, LONG_CARA (read with UNITE_TRAN_INIT only)
and FREQ_FILTRE (with INTEGRATION='FREQUENCE' only) change nothing here."""

from asterlite.catalog import BLOC, ENSEMBLE, FACT, MACRO, SIMP, absent, equal_to


def _signal_keywords(tout_cham_default):
    """The keywords both CHARGEMENT blocks share (TOUT_CHAM's default differs)."""
    return dict(
        FONC_SIGNAL=SIMP(statut="o", typ="fonction_sdaster"),
        TOUT_CHAM=SIMP(statut="f", typ="TXM", into=("OUI", "NON"), defaut=tout_cham_default),
        TOUT_ACCE=SIMP(statut="f", typ="TXM", into=("OUI", "NON"), defaut="OUI"),
        b_TOUTACCE=BLOC(
            condition=equal_to("TOUT_ACCE", "NON"),
            LIST_COUCHE_ACCE=SIMP(statut="f", typ="grma", max="**"),
        ),
        NOM_CMP=SIMP(statut="f", typ="TXM", into=("DX",), defaut="DX"),
        CORRECTION=SIMP(statut="f", typ="TXM", into=("SANS",), defaut="SANS"),
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
        LIAISON=SIMP(statut="f", typ="TXM", into=("PERIODIQUE",)),
        MASS_PENA=SIMP(statut="f", typ="R"),
        LONG_CARA=SIMP(statut="f", typ="R"),
        **_signal_keywords("OUI"),
    ),
    b_MONO=BLOC(condition=equal_to("CHARGEMENT", "MONO_APPUI"), **_signal_keywords("NON")),
    CORR_AMOR=SIMP(statut="f", typ="TXM", into=("OUI", "NON"), defaut="NON"),
    LIST_FREQ_SPEC_OSCI=SIMP(statut="o", typ="listr8_sdaster"),
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
    INTEGRATION=SIMP(statut="f", typ="TXM", into=("TEMPS",), defaut="TEMPS"),
    SURF=SIMP(statut="o", typ="TXM", into=("OUI",)),
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
