"""IMPR_RESU: write meshes, fields and results (MED, RESULTAT text, ASTER, GMSH, IDEAS)."""

from asterlite.catalogues.common_post import NOM_CHAM, any_given, is_type, precision_blocs

from asterlite.catalog import AU_MOINS_UN, BLOC, EXCLUS, FACT, PROC, SIMP, equal_to, exists

_ACCESS = (
    "TOUT_ORDRE", "NUME_ORDRE", "INST", "FREQ", "NUME_MODE", "NOEUD_CMP", "LIST_INST",
    "LIST_FREQ", "LIST_ORDRE", "NOM_CAS", "ANGLE",
)  # fmt: skip


def _extraction() -> BLOC:
    """Which fields and which instants/modes of a result to write."""
    return BLOC(
        condition=exists("RESULTAT"),
        regles=(EXCLUS("TOUT_CHAM", "NOM_CHAM"), EXCLUS(*_ACCESS)),
        TOUT_CHAM=SIMP(statut="f", typ="TXM", into=("OUI", "NON")),
        NOM_CHAM=SIMP(statut="f", typ="TXM", max="**", into=NOM_CHAM),
        TOUT_ORDRE=SIMP(statut="f", typ="TXM", into=("OUI",)),
        NUME_ORDRE=SIMP(statut="f", typ="I", max="**"),
        NUME_MODE=SIMP(statut="f", typ="I", max="**"),
        LIST_ORDRE=SIMP(statut="f", typ="listis_sdaster"),
        NOEUD_CMP=SIMP(statut="f", typ="TXM", max="**"),
        NOM_CAS=SIMP(statut="f", typ="TXM", max="**"),
        ANGLE=SIMP(statut="f", typ="R", max="**"),
        FREQ=SIMP(statut="f", typ="R", max="**"),
        LIST_FREQ=SIMP(statut="f", typ="listr8_sdaster"),
        INST=SIMP(statut="f", typ="R", max="**"),
        LIST_INST=SIMP(statut="f", typ="listr8_sdaster"),
        b_acce_reel=BLOC(
            condition=any_given("ANGLE", "FREQ", "LIST_FREQ", "INST", "LIST_INST"),
            **precision_blocs(),
        ),
    )


def _what() -> dict:
    return dict(
        MAILLAGE=SIMP(statut="f", typ=("maillage_sdaster", "squelette")),
        CARA_ELEM=SIMP(statut="f", typ="cara_elem"),
        CHAM_GD=SIMP(statut="f", typ="cham_gd_sdaster"),
        RESULTAT=SIMP(statut="f", typ="resultat_sdaster"),
        b_extrac=_extraction(),
    )


_WHERE = dict(
    TOUT=SIMP(statut="f", typ="TXM", into=("OUI",)),
    GROUP_NO=SIMP(statut="f", typ="grno", max="**"),
    MAILLE=SIMP(statut="c", typ="ma", max="**"),
    GROUP_MA=SIMP(statut="f", typ="grma", max="**"),
)

IMPR_RESU = PROC(
    nom="IMPR_RESU",
    fr="Print a mesh and/or results in various formats",
    FORMAT=SIMP(
        statut="f", typ="TXM", defaut="MED", into=("RESULTAT", "IDEAS", "ASTER", "MED", "GMSH")
    ),
    PROC0=SIMP(statut="f", typ="TXM", into=("OUI", "NON")),
    b_modele=BLOC(
        condition=~equal_to("FORMAT", "MED"),
        # code_aster needs it to print element fields; asterlite's fields carry their cells
        MODELE=SIMP(statut="f", typ="modele_sdaster", no_effect="model of the printed fields"),
    ),
    b_format_resultat=BLOC(
        condition=equal_to("FORMAT", "RESULTAT"), UNITE=SIMP(statut="f", typ="I", defaut=8)
    ),
    b_format_ideas=BLOC(
        condition=equal_to("FORMAT", "IDEAS"),
        UNITE=SIMP(statut="f", typ="I", defaut=30),
        VERSION=SIMP(statut="f", typ="I", defaut=5, into=(4, 5)),
    ),
    b_format_aster=BLOC(
        condition=equal_to("FORMAT", "ASTER"), UNITE=SIMP(statut="f", typ="I", defaut=26)
    ),
    b_format_med=BLOC(
        condition=equal_to("FORMAT", "MED"),
        UNITE=SIMP(statut="f", typ="I", defaut=80),
        VERSION_MED=SIMP(statut="f", typ="TXM", defaut="3.3.1", into=("3.3.1", "4.0.0", "4.1.0")),
        FICHIER_UNIQUE=SIMP(statut="f", typ="TXM", defaut="NON", into=("OUI", "NON")),
    ),
    b_format_gmsh=BLOC(
        condition=equal_to("FORMAT", "GMSH"),
        UNITE=SIMP(statut="f", typ="I", defaut=37),
        VERSION=SIMP(statut="f", typ="R", defaut=1.2, into=(1.0, 1.2)),
    ),
    b_fmt_med=BLOC(
        condition=equal_to("FORMAT", "MED"),
        RESU=FACT(
            statut="o",
            max="**",
            regles=(
                AU_MOINS_UN("CHAM_GD", "RESULTAT", "MAILLAGE"),
                EXCLUS("CHAM_GD", "RESULTAT"),
                EXCLUS("TOUT_CMP", "NOM_CMP"),
            ),
            **_what(),
            b_rangement=BLOC(
                condition=is_type("RESULTAT", "mult_elas"),
                TYPE_NOM=SIMP(
                    statut="f", typ="TXM", defaut="NUME_ORDRE", into=("NUME_ORDRE", "NOM_CAS")
                ),
            ),
            INFO_MAILLAGE=SIMP(statut="f", typ="TXM", defaut="NON", into=("OUI", "NON")),
            PARTIE=SIMP(statut="f", typ="TXM", into=("REEL", "IMAG", "MODULE", "PHASE")),
            IMPR_NOM_VARI=SIMP(statut="f", typ="TXM", defaut="OUI", into=("OUI", "NON")),
            b_param=BLOC(
                condition=exists("RESULTAT"), NOM_PARA=SIMP(statut="f", typ="TXM", max="**")
            ),
            TOUT_CMP=SIMP(statut="f", typ="TXM", into=("OUI",)),
            NOM_CMP=SIMP(statut="f", typ="TXM", max="**"),
            b_med=BLOC(
                condition=exists("CHAM_GD") | exists("RESULTAT"),
                regles=(EXCLUS("NOM_CHAM_MED", "NOM_RESU_MED"),),
                NOM_CHAM_MED=SIMP(statut="f", typ="TXM", max="**"),
                NOM_RESU_MED=SIMP(statut="f", typ="TXM"),
            ),
            **_WHERE,
            SOUS_TITRE=SIMP(statut="f", typ="TXM"),
        ),
    ),
    b_fmt_resultat=BLOC(
        condition=equal_to("FORMAT", "RESULTAT"),
        RESU=FACT(
            statut="f",
            max="**",
            regles=(
                AU_MOINS_UN("CHAM_GD", "RESULTAT", "MAILLAGE"),
                EXCLUS("CHAM_GD", "RESULTAT"),
                EXCLUS("TOUT_PARA", "NOM_PARA"),
                EXCLUS("TOUT_CMP", "NOM_CMP"),
            ),
            **_what(),
            PARTIE=SIMP(statut="f", typ="TXM", into=("REEL", "IMAG", "MODULE", "PHASE")),
            TOUT_PARA=SIMP(statut="f", typ="TXM", into=("OUI", "NON")),
            NOM_PARA=SIMP(statut="f", typ="TXM", max="**"),
            FORM_TABL=SIMP(statut="f", typ="TXM", defaut="NON", into=("OUI", "NON", "EXCEL")),
            TOUT_CMP=SIMP(statut="f", typ="TXM", into=("OUI",)),
            NOM_CMP=SIMP(statut="f", typ="TXM", max="**"),
            b_topologie=BLOC(condition=exists("CHAM_GD") | exists("RESULTAT"), **_WHERE),
            VALE_MAX=SIMP(statut="f", typ="TXM", into=("OUI",)),
            VALE_MIN=SIMP(statut="f", typ="TXM", into=("OUI",)),
            BORNE_SUP=SIMP(statut="f", typ="R"),
            BORNE_INF=SIMP(statut="f", typ="R"),
            IMPR_COOR=SIMP(statut="f", typ="TXM", defaut="NON", into=("OUI", "NON")),
            FORMAT_R=SIMP(statut="f", typ="TXM", defaut="1PE21.14"),
            SOUS_TITRE=SIMP(statut="f", typ="TXM"),
        ),
    ),
    b_fmt_other=BLOC(
        condition=equal_to("FORMAT", ("ASTER", "GMSH", "IDEAS")),
        RESU=FACT(
            statut="f",
            max="**",
            regles=(AU_MOINS_UN("CHAM_GD", "RESULTAT", "MAILLAGE"), EXCLUS("CHAM_GD", "RESULTAT")),
            **_what(),
            PARTIE=SIMP(statut="f", typ="TXM", into=("REEL", "IMAG")),
            TOUT_CMP=SIMP(statut="f", typ="TXM", into=("OUI",)),
            NOM_CMP=SIMP(statut="f", typ="TXM", max="**"),
            b_topologie=BLOC(condition=exists("CHAM_GD") | exists("RESULTAT"), **_WHERE),
            SOUS_TITRE=SIMP(statut="f", typ="TXM"),
        ),
    ),
)
