"""IMPR_TABLE: print a table (code_aster's TABLEAU text, CSV-like, xmgrace...)."""

from asterlite.catalogues.common_post import TABLE, table_filter

from asterlite.catalog import BLOC, FACT, MACRO, SIMP, equal_to

IMPR_TABLE = MACRO(
    nom="IMPR_TABLE",
    sd_prod=None,
    fr="Print the content of a table to a file",
    TABLE=SIMP(statut="o", typ=TABLE),
    FORMAT=SIMP(
        statut="f",
        typ="TXM",
        defaut="TABLEAU",
        into=("TABLEAU", "ASTER", "TABLEAU_CROISE", "AGRAF", "XMGRACE", "NUMPY"),
    ),
    b_pilote=BLOC(
        condition=equal_to("FORMAT", "XMGRACE"),
        PILOTE=SIMP(
            statut="f",
            typ="TXM",
            defaut="",
            into=(
                "",
                "POSTSCRIPT",
                "EPS",
                "MIF",
                "SVG",
                "PNM",
                "PNG",
                "JPEG",
                "PDF",
                "INTERACTIF",
                "INTERACTIF_BG",
            ),
        ),
        UNITE=SIMP(statut="f", typ="I", defaut=29, fr="Logical unit of the output file"),
    ),
    b_unite=BLOC(
        condition=~equal_to("FORMAT", "XMGRACE"),
        UNITE=SIMP(statut="f", typ="I", defaut=8, fr="Logical unit of the output file"),
    ),
    FILTRE=table_filter(vale_max="**"),
    TRI=FACT(
        statut="f",
        NOM_PARA=SIMP(statut="o", typ="TXM", max="**"),
        ORDRE=SIMP(statut="f", typ="TXM", defaut="CROISSANT", into=("CROISSANT", "DECROISSANT")),
    ),
    PAGINATION=SIMP(statut="f", typ="TXM", max="**"),
    FORMAT_R=SIMP(statut="f", typ="TXM", defaut="E12.5"),
    NOM_PARA=SIMP(statut="f", typ="TXM", max="**", fr="Columns to print"),
    IMPR_FONCTION=SIMP(statut="f", typ="TXM", defaut="NON", into=("OUI", "NON")),
    b_tableau=BLOC(
        condition=equal_to("FORMAT", "TABLEAU"),
        DEBUT_TABLE=SIMP(statut="f", typ="TXM"),
        FIN_TABLE=SIMP(statut="f", typ="TXM", defaut=""),
        SEPARATEUR=SIMP(statut="f", typ="TXM", defaut=" "),
        COMMENTAIRE=SIMP(statut="f", typ="TXM", defaut="#"),
        COMM_PARA=SIMP(statut="f", typ="TXM", defaut=""),
        DEBUT_LIGNE=SIMP(statut="f", typ="TXM", defaut=""),
        FIN_LIGNE=SIMP(statut="f", typ="TXM", defaut="\n"),
    ),
    b_forme=BLOC(
        condition=equal_to("FORMAT", "XMGRACE"),
        LEGENDE=SIMP(statut="f", typ="TXM"),
        STYLE=SIMP(statut="f", typ="I", val_min=0),
        COULEUR=SIMP(statut="f", typ="I", val_min=0),
        MARQUEUR=SIMP(statut="f", typ="I", val_min=0),
        FREQ_MARQUEUR=SIMP(statut="f", typ="I", defaut=0),
        BORNE_X=SIMP(statut="f", typ="R", min=2, max=2),
        BORNE_Y=SIMP(statut="f", typ="R", min=2, max=2),
        ECHELLE_X=SIMP(statut="f", typ="TXM", defaut="LIN", into=("LIN", "LOG")),
        ECHELLE_Y=SIMP(statut="f", typ="TXM", defaut="LIN", into=("LIN", "LOG")),
        GRILLE_X=SIMP(statut="f", typ="R", val_min=0.0),
        GRILLE_Y=SIMP(statut="f", typ="R", val_min=0.0),
        LEGENDE_X=SIMP(statut="f", typ="TXM"),
        LEGENDE_Y=SIMP(statut="f", typ="TXM"),
    ),
    TITRE=SIMP(statut="f", typ="TXM"),
    INFO=SIMP(statut="f", typ="I", defaut=1, into=(1, 2)),
)
