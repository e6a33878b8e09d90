"""TEST_RESU: check a value of a field or a result against a reference (prints OK/NOOK).

Each occurrence gives ``VALE_CALC`` (code_aster's own value: non-regression,
tolerance ``TOLE_MACHINE``) and, with ``REFERENCE``, ``VALE_REFE`` checked
within ``PRECISION`` (see ``common_post.test_reference``).
"""

from asterlite.catalogues.common_post import NOM_CHAM, is_type, test_reference

from asterlite.catalog import (
    AU_MOINS_UN,
    BLOC,
    EXCLUS,
    FACT,
    PRESENT_ABSENT,
    PRESENT_PRESENT,
    PROC,
    SIMP,
    UN_PARMI,
)

TEST_RESU = PROC(
    nom="TEST_RESU",
    fr="Extract a value from a data structure and compare it with a reference",
    regles=(
        AU_MOINS_UN(
            "CHAM_NO", "CHAM_ELEM", "CARTE", "RESU", "GENE", "OBJET", "TEST_NAN", "MAILLAGE"
        ),
    ),
    CHAM_NO=FACT(
        statut="f",
        max="**",
        fr="A component of a nodal field",
        regles=(PRESENT_PRESENT("GROUP_NO", "NOM_CMP"),),
        CHAM_GD=SIMP(statut="o", typ="cham_no_sdaster"),
        GROUP_NO=SIMP(statut="f", typ="grno"),
        NOM_CMP=SIMP(statut="f", typ="TXM"),
        **test_reference("CHAM_NO"),
    ),
    CARTE=FACT(
        statut="f",
        max="**",
        CHAM_GD=SIMP(statut="o", typ="carte_sdaster"),
        GROUP_MA=SIMP(statut="f", typ="grma"),
        NOM_CMP=SIMP(statut="o", typ="TXM"),
        **test_reference("CARTE", max=1),
    ),
    CHAM_ELEM=FACT(
        statut="f",
        max="**",
        fr="A component of an element field",
        regles=(
            EXCLUS("GROUP_NO", "POINT"),
            PRESENT_PRESENT("GROUP_NO", "NOM_CMP"),
            PRESENT_PRESENT("POINT", "NOM_CMP"),
        ),
        CHAM_GD=SIMP(statut="o", typ="cham_elem"),
        GROUP_MA=SIMP(statut="f", typ="grma"),
        POINT=SIMP(statut="f", typ="I"),
        SOUS_POINT=SIMP(statut="f", typ="I"),
        GROUP_NO=SIMP(statut="f", typ="grno"),
        NOM_CMP=SIMP(statut="f", typ="TXM"),
        **test_reference("CHAM_ELEM"),
    ),
    RESU=FACT(
        statut="f",
        max="**",
        fr="A field component or a parameter of a result at one order number",
        regles=(
            UN_PARMI("NUME_ORDRE", "INST", "FREQ", "NUME_MODE", "NOEUD_CMP", "NOM_CAS", "ANGLE"),
            UN_PARMI("NOM_CHAM", "PARA"),
            PRESENT_ABSENT("PARA", "GROUP_MA", "GROUP_NO", "POINT", "NOM_CMP", "NOM_VARI"),
            EXCLUS("GROUP_NO", "POINT"),
            EXCLUS("NOM_CMP", "NOM_VARI"),
        ),
        RESULTAT=SIMP(statut="o", typ="resultat_sdaster"),
        NUME_ORDRE=SIMP(statut="f", typ="I"),
        INST=SIMP(statut="f", typ="R"),
        FREQ=SIMP(statut="f", typ="R"),
        NUME_MODE=SIMP(statut="f", typ="I"),
        NOEUD_CMP=SIMP(statut="f", typ="TXM", min=2, max=2),
        NOM_CAS=SIMP(statut="f", typ="TXM"),
        ANGLE=SIMP(statut="f", typ="R"),
        PARA=SIMP(statut="f", typ="TXM"),
        NOM_CHAM=SIMP(statut="f", typ="TXM", into=NOM_CHAM),
        NOM_CMP=SIMP(statut="f", typ="TXM"),
        NOM_VARI=SIMP(statut="f", typ="TXM"),
        GROUP_MA=SIMP(statut="f", typ="grma"),
        GROUP_NO=SIMP(statut="f", typ="grno", max="**"),
        POINT=SIMP(statut="f", typ="I"),
        SOUS_POINT=SIMP(statut="f", typ="I"),
        **test_reference("RESU"),
    ),
    GENE=FACT(
        statut="f",
        max="**",
        fr="A generalized coordinate of a modal result or vector",
        RESU_GENE=SIMP(statut="o", typ=("vect_asse_gene", "tran_gene", "mode_gene", "harm_gene")),
        b_vect_asse=BLOC(
            condition=is_type("RESU_GENE", "vect_asse_gene"),
            NUME_CMP_GENE=SIMP(statut="o", typ="I"),
        ),
        b_mode=BLOC(
            condition=is_type("RESU_GENE", "mode_gene"),
            regles=(
                UN_PARMI("NUME_ORDRE", "FREQ", "NUME_MODE"),
                UN_PARMI("NOM_CHAM", "PARA"),
                PRESENT_PRESENT("NOM_CHAM", "NUME_CMP_GENE"),
            ),
            NOM_CHAM=SIMP(statut="f", typ="TXM", into=NOM_CHAM),
            NUME_CMP_GENE=SIMP(statut="f", typ="I"),
            PARA=SIMP(statut="f", typ="TXM"),
            NUME_ORDRE=SIMP(statut="f", typ="I"),
            NUME_MODE=SIMP(statut="f", typ="I"),
            FREQ=SIMP(statut="f", typ="R"),
        ),
        b_harm=BLOC(
            condition=is_type("RESU_GENE", "harm_gene"),
            regles=(UN_PARMI("NUME_ORDRE", "FREQ"),),
            NOM_CHAM=SIMP(statut="o", typ="TXM", into=NOM_CHAM),
            NUME_CMP_GENE=SIMP(statut="o", typ="I"),
            NUME_ORDRE=SIMP(statut="f", typ="I"),
            FREQ=SIMP(statut="f", typ="R"),
        ),
        b_tran=BLOC(
            condition=is_type("RESU_GENE", "tran_gene"),
            regles=(UN_PARMI("NUME_ORDRE", "INST"),),
            NOM_CHAM=SIMP(statut="o", typ="TXM", into=NOM_CHAM),
            NUME_CMP_GENE=SIMP(statut="o", typ="I"),
            NUME_ORDRE=SIMP(statut="f", typ="I"),
            INST=SIMP(statut="f", typ="R"),
        ),
        **test_reference("GENE"),
    ),
    OBJET=FACT(
        statut="f",
        max="**",
        NOM=SIMP(statut="o", typ="TXM"),
        **test_reference("OBJET", max=1),
    ),
    MAILLAGE=FACT(
        statut="f",
        max="**",
        fr="A count of mesh entities",
        MAILLAGE=SIMP(statut="o", typ="maillage_sdaster"),
        CARA=SIMP(
            statut="o",
            typ="TXM",
            into=(
                "NB_MAILLE",
                "NB_NOEUD",
                "NB_GROUP_MA",
                "NB_GROUP_NO",
                "NB_MA_GROUP_MA",
                "NB_NO_GROUP_NO",
            ),
        ),
        NOM_GROUP_MA=SIMP(statut="f", typ="grma"),
        NOM_GROUP_NO=SIMP(statut="f", typ="grno"),
        **test_reference("MAILLAGE", max=1),
    ),
    TEST_NAN=SIMP(statut="f", typ="TXM", into=("OUI", "NON")),
)
