"""IMPR_FONCTION: write functions to a file for a curve plotter (table, xmgrace, agraf)."""

from asterlite.catalogues.common_post import is_type

from asterlite.catalog import BLOC, FACT, MACRO, SIMP, UN_PARMI, equal_to, exists


def _graph_layout() -> dict:
    return dict(
        TITRE=SIMP(statut="f", typ="TXM", fr="Title of the graph"),
        SOUS_TITRE=SIMP(statut="f", typ="TXM", fr="Subtitle of the graph"),
        BORNE_X=SIMP(statut="f", typ="R", min=2, max=2, fr="Range of the abscissas"),
        BORNE_Y=SIMP(statut="f", typ="R", min=2, max=2, fr="Range of the ordinates"),
        ECHELLE_X=SIMP(statut="f", typ="TXM", defaut="LIN", into=("LIN", "LOG")),
        ECHELLE_Y=SIMP(statut="f", typ="TXM", defaut="LIN", into=("LIN", "LOG")),
        GRILLE_X=SIMP(statut="f", typ="R", val_min=0.0, fr="Vertical grid step"),
        GRILLE_Y=SIMP(statut="f", typ="R", val_min=0.0, fr="Horizontal grid step"),
        LEGENDE_X=SIMP(statut="f", typ="TXM", fr="Label of the abscissa axis"),
        LEGENDE_Y=SIMP(statut="f", typ="TXM", fr="Label of the ordinate axis"),
    )


IMPR_FONCTION = MACRO(
    nom="IMPR_FONCTION",
    sd_prod=None,
    fr="Print functions or lists of reals for a curve plotter",
    FORMAT=SIMP(
        statut="f",
        typ="TXM",
        defaut="TABLEAU",
        into=("TABLEAU", "AGRAF", "XMGRACE", "LISS_ENVELOP"),
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
    b_agraf=BLOC(
        condition=equal_to("FORMAT", "AGRAF"),
        UNITE=SIMP(statut="f", typ="I", defaut=25),
        UNITE_DIGR=SIMP(statut="f", typ="I", defaut=26, fr="Unit of the Agraf directives"),
    ),
    b_format1=BLOC(
        condition=~equal_to("FORMAT", "LISS_ENVELOP"),
        COURBE=FACT(
            statut="o",
            max="**",
            fr="One curve to plot",
            regles=(UN_PARMI("FONCTION", "LIST_RESU", "FONC_X", "ABSCISSE"),),
            FONCTION=SIMP(
                statut="f", typ=("fonction_sdaster", "formule", "fonction_c", "nappe_sdaster")
            ),
            LIST_RESU=SIMP(statut="f", typ="listr8_sdaster", fr="Ordinates as a list of reals"),
            FONC_X=SIMP(statut="f", typ=("fonction_sdaster", "formule")),
            ABSCISSE=SIMP(statut="f", typ="R", max="**"),
            b_fonction=BLOC(
                condition=exists("FONCTION"), LIST_PARA=SIMP(statut="f", typ="listr8_sdaster")
            ),
            b_fonction_c=BLOC(
                condition=is_type("FONCTION", "fonction_c", "formule_c"),
                PARTIE=SIMP(statut="f", typ="TXM", into=("REEL", "IMAG")),
            ),
            b_list_resu=BLOC(
                condition=exists("LIST_RESU"), LIST_PARA=SIMP(statut="o", typ="listr8_sdaster")
            ),
            b_fonc_x=BLOC(
                condition=exists("FONC_X"),
                FONC_Y=SIMP(statut="o", typ=("fonction_sdaster", "formule")),
                LIST_PARA=SIMP(statut="f", typ="listr8_sdaster"),
            ),
            b_vale_resu=BLOC(
                condition=exists("ABSCISSE"), ORDONNEE=SIMP(statut="o", typ="R", max="**")
            ),
            LEGENDE=SIMP(statut="f", typ="TXM", fr="Legend of the curve"),
            STYLE=SIMP(statut="f", typ="I", val_min=0),
            COULEUR=SIMP(statut="f", typ="I", val_min=0),
            MARQUEUR=SIMP(statut="f", typ="I", val_min=0),
            FREQ_MARQUEUR=SIMP(statut="f", typ="I", defaut=0),
            TRI=SIMP(statut="f", typ="TXM", defaut="N", into=("N", "X", "Y", "XY", "YX")),
        ),
    ),
    b_format2=BLOC(
        condition=equal_to("FORMAT", "LISS_ENVELOP"),
        COURBE=FACT(
            statut="o",
            max="**",
            regles=(UN_PARMI("NAPPE", "NAPPE_LISSEE"),),
            NAPPE=SIMP(statut="f", typ="nappe_sdaster"),
            NAPPE_LISSEE=SIMP(statut="f", typ="nappe_sdaster"),
        ),
    ),
    b_tableau=BLOC(
        condition=equal_to("FORMAT", "TABLEAU"),
        UNITE=SIMP(statut="f", typ="I", defaut=8, fr="Logical unit of the output file"),
        TITRE=SIMP(statut="f", typ="TXM"),
        SOUS_TITRE=SIMP(statut="f", typ="TXM"),
        SEPARATEUR=SIMP(statut="f", typ="TXM", defaut=" "),
        COMMENTAIRE=SIMP(statut="f", typ="TXM", defaut="#"),
        COMM_PARA=SIMP(statut="f", typ="TXM", defaut=""),
        DEBUT_LIGNE=SIMP(statut="f", typ="TXM", defaut=""),
        FIN_LIGNE=SIMP(statut="f", typ="TXM", defaut="\n"),
        FORMAT_R=SIMP(statut="f", typ="TXM", defaut="E12.5"),
    ),
    b_graphique=BLOC(condition=~equal_to("FORMAT", "TABLEAU"), **_graph_layout()),
    b_liss_enveloppe=BLOC(
        condition=equal_to("FORMAT", "LISS_ENVELOP"), UNITE=SIMP(statut="f", typ="I", defaut=25)
    ),
    INFO=SIMP(statut="f", typ="I", defaut=1, into=(1, 2)),
)
