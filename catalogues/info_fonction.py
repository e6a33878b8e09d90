"""INFO_FONCTION: characteristic values of functions (extrema, RMS, norm, seismic indicators)."""

from asterlite.catalogues.common_post import precision_blocs

from asterlite.catalog import BLOC, FACT, MACRO, SIMP, UN_PARMI, exists, is_in

INFO_FONCTION = MACRO(
    nom="INFO_FONCTION",
    sd_prod="table_sdaster",
    reentrant="n",
    fr="Compute characteristic values of functions into a table",
    regles=(UN_PARMI("MAX", "RMS", "NOCI_SEISME", "NORME", "ECART_TYPE"),),
    RMS=FACT(
        statut="f",
        max="**",
        fr="Root mean square of a function",
        METHODE=SIMP(statut="f", typ="TXM", defaut="TRAPEZE", into=("SIMPSON", "TRAPEZE")),
        FONCTION=SIMP(statut="o", typ="fonction_sdaster"),
        INST_INIT=SIMP(statut="f", typ="R", fr="Start of the signal"),
        INST_FIN=SIMP(statut="f", typ="R", fr="End of the signal"),
        **precision_blocs(),
    ),
    NOCI_SEISME=FACT(
        statut="f",
        fr="Seismic harmfulness indicators of an accelerogram",
        regles=(UN_PARMI("FONCTION", "SPEC_OSCI"),),
        FONCTION=SIMP(statut="f", typ="fonction_sdaster"),
        SPEC_OSCI=SIMP(statut="f", typ="nappe_sdaster"),
        b_option_f=BLOC(
            condition=exists("FONCTION"),
            OPTION=SIMP(
                statut="f",
                typ="TXM",
                defaut="TOUT",
                into=(
                    "INTE_ARIAS",
                    "INTE_SPEC",
                    "VITE_ABSO_CUMU",
                    "DUREE_PHAS_FORT",
                    "MAXI",
                    "ACCE_SUR_VITE",
                    "ASA",
                    "TOUT",
                ),
            ),
            b_asa=BLOC(
                condition=is_in("OPTION", ("TOUT", "ASA")),
                FREQ_FOND=SIMP(statut="o", typ="R", val_min=0.0),
                FREQ_PAS=SIMP(statut="f", typ="R", defaut=0.01),
                NORME=SIMP(statut="f", typ="R", defaut=1.0),
                RATIO=SIMP(statut="f", typ="R", defaut=0.40),
            ),
            b_amor_red=BLOC(
                condition=is_in("OPTION", ("TOUT", "INTE_SPEC", "ASA")),
                AMOR_REDUIT=SIMP(statut="o", typ="R"),
            ),
            b_pesanteur=BLOC(
                condition=is_in("OPTION", ("TOUT", "INTE_ARIAS", "DUREE_PHAS_FORT")),
                PESANTEUR=SIMP(statut="o", typ="R"),
            ),
        ),
        b_option_n=BLOC(
            condition=exists("SPEC_OSCI"),
            OPTION=SIMP(statut="f", typ="TXM", defaut="INTE_SPEC", into=("INTE_SPEC",)),
            NATURE=SIMP(statut="o", typ="TXM", into=("DEPL", "VITE", "ACCE")),
            AMOR_REDUIT=SIMP(statut="o", typ="R"),
        ),
        INST_INIT=SIMP(statut="f", typ="R"),
        INST_FIN=SIMP(statut="f", typ="R"),
        COEF=SIMP(statut="f", typ="R", defaut=0.0),
        FREQ_INIT=SIMP(statut="f", typ="R", defaut=0.4),
        FREQ_FIN=SIMP(statut="f", typ="R", defaut=10.0),
        LIST_FREQ=SIMP(statut="f", typ="listr8_sdaster"),
        FREQ=SIMP(statut="f", typ="R", max="**"),
        NORME=SIMP(statut="f", typ="R", defaut=1.0),
        BORNE_INF=SIMP(statut="f", typ="R", defaut=0.05),
        BORNE_SUP=SIMP(statut="f", typ="R", defaut=0.95),
        b_acce_reel=BLOC(
            condition=exists("INST_INIT")
            | exists("INST_FIN")
            | exists("FREQ_INIT")
            | exists("FREQ_FIN"),
            **precision_blocs(),
        ),
    ),
    MAX=FACT(
        statut="f",
        fr="Local extrema of functions",
        FONCTION=SIMP(statut="o", typ=("fonction_sdaster", "nappe_sdaster"), max="**"),
        INTERVALLE=SIMP(
            statut="f", typ="R", min=2, max="**", fr="Bounds (low1, high1, low2, high2...)"
        ),
    ),
    NORME=FACT(statut="f", fr="L2 norm of a nappe", FONCTION=SIMP(statut="o", typ="nappe_sdaster")),
    ECART_TYPE=FACT(
        statut="f",
        fr="Standard deviation of a function",
        METHODE=SIMP(statut="f", typ="TXM", defaut="TRAPEZE", into=("SIMPSON", "TRAPEZE")),
        FONCTION=SIMP(statut="o", typ="fonction_sdaster"),
        INST_INIT=SIMP(statut="f", typ="R"),
        INST_FIN=SIMP(statut="f", typ="R"),
        **precision_blocs(),
    ),
    INFO=SIMP(statut="f", typ="I", defaut=1, into=(1, 2)),
)
