"""CALC_TABLE: a sequence of operations on a table (filter, extract, sort, formulas...)."""

from asterlite.catalogues.common_post import COMPARAISONS, TABLE, concept_is

from asterlite.catalog import BLOC, FACT, MACRO, SIMP, UN_PARMI, equal_to

ANY_VALUE = ("R", "I", "C", "TXM")  # code_aster does not check these values
_TYPES = {"TABLE_FONCTION": "table_fonction", "TABLE_CONTAINER": "table_container"}


def calc_table_type(kw) -> str:
    """TYPE_TABLE if given, else the most specific type among the tables used."""
    if kw.get("TYPE_TABLE") is not None:
        return _TYPES.get(kw["TYPE_TABLE"], "table_sdaster")
    tables = [kw.get("TABLE")] + [action.get("TABLE") for action in kw.get("ACTION") or []]
    if any(concept_is(table, "table_fonction") for table in tables):
        return "table_fonction"
    if any(concept_is(table, "table_container") for table in tables):
        return "table_container"
    return "table_sdaster"


def _names(statut: str = "o", fr: str = "", **options) -> SIMP:
    return SIMP(statut=statut, typ="TXM", max="**", fr=fr, **options)


CALC_TABLE = MACRO(
    nom="CALC_TABLE",
    sd_prod=calc_table_type,
    reentrant="f",
    fr="Operations on a table",
    TABLE=SIMP(statut="o", typ=TABLE),
    ACTION=FACT(
        statut="o",
        max="**",
        fr="One operation, applied in order",
        OPERATION=SIMP(
            statut="o",
            typ="TXM",
            into=(
                "FILTRE",
                "EXTR",
                "RENOMME",
                "TRI",
                "COMB",
                "AJOUT_LIGNE",
                "OPER",
                "SUPPRIME",
                "UNIQUE",
                "AJOUT_COLONNE",
                "STATISTIQUES",
                "CALCUL",
            ),
        ),
        b_filtre=BLOC(
            condition=equal_to("OPERATION", "FILTRE"),
            fr="Keep the rows meeting a criterion",
            NOM_PARA=SIMP(statut="o", typ="TXM"),
            CRIT_COMP=SIMP(statut="f", typ="TXM", defaut="EQ", into=COMPARAISONS + ("REGEXP",)),
            b_vale=BLOC(
                condition=equal_to("CRIT_COMP", ("EQ", "NE", "GT", "LT", "GE", "LE")),
                regles=(UN_PARMI("VALE", "VALE_I", "VALE_K", "VALE_C"),),
                VALE=SIMP(statut="f", typ="R", max="**"),
                VALE_I=SIMP(statut="f", typ="I", max="**"),
                VALE_C=SIMP(statut="f", typ="C", max="**"),
                VALE_K=SIMP(statut="f", typ="TXM", max="**"),
            ),
            b_regexp=BLOC(
                condition=equal_to("CRIT_COMP", "REGEXP"), VALE_K=SIMP(statut="o", typ="TXM")
            ),
            b_crit=BLOC(
                condition=equal_to("CRIT_COMP", ("EQ", "NE")),
                CRITERE=SIMP(statut="f", typ="TXM", defaut="RELATIF", into=("RELATIF", "ABSOLU")),
                PRECISION=SIMP(statut="f", typ="R", defaut=1.0e-3),
            ),
        ),
        b_extr=BLOC(condition=equal_to("OPERATION", "EXTR"), NOM_PARA=_names(fr="Columns to keep")),
        b_suppr=BLOC(
            condition=equal_to("OPERATION", "SUPPRIME"), NOM_PARA=_names(fr="Columns to remove")
        ),
        b_supdbl=BLOC(
            condition=equal_to("OPERATION", "UNIQUE"),
            NOM_PARA=_names(fr="Columns whose repeated values remove a row"),
            FORMAT_R=SIMP(statut="f", typ="TXM"),
        ),
        b_renomme=BLOC(
            condition=equal_to("OPERATION", "RENOMME"),
            NOM_PARA=SIMP(statut="o", typ="TXM", min=2, max=2, fr="(old name, new name)"),
        ),
        b_tri=BLOC(
            condition=equal_to("OPERATION", "TRI"),
            NOM_PARA=_names(),
            ORDRE=SIMP(
                statut="f", typ="TXM", defaut="CROISSANT", into=("CROISSANT", "DECROISSANT")
            ),
        ),
        b_comb=BLOC(
            condition=equal_to("OPERATION", "COMB"),
            TABLE=SIMP(statut="o", typ=TABLE, fr="Table whose columns are merged in"),
            NOM_PARA=_names(statut="f", fr="Columns that must match for rows to merge"),
            RESTREINT=SIMP(statut="f", typ="TXM", into=("OUI", "NON"), defaut="NON"),
            FORMAT_R=SIMP(statut="f", typ="TXM"),
        ),
        b_ajout_lig=BLOC(
            condition=equal_to("OPERATION", "AJOUT_LIGNE"),
            NOM_PARA=_names(),
            VALE=SIMP(statut="o", typ=ANY_VALUE, max="**"),
        ),
        b_ajout_col=BLOC(
            condition=equal_to("OPERATION", "AJOUT_COLONNE"),
            regles=(UN_PARMI("VALE", "VALE_COLONNE"),),
            NOM_PARA=_names(),
            VALE=SIMP(statut="f", typ=ANY_VALUE, max="**"),
            VALE_COLONNE=SIMP(statut="f", typ=ANY_VALUE, max="**"),
        ),
        b_oper=BLOC(
            condition=equal_to("OPERATION", "OPER"),
            fr="Add a column computed by a formula of other columns",
            FORMULE=SIMP(statut="o", typ="formule"),
            NOM_PARA=SIMP(statut="o", typ="TXM", fr="Name of the new column"),
            NOM_COLONNE=_names(statut="f", fr="Columns used as the formula's parameters"),
        ),
        b_calcul=BLOC(
            condition=equal_to("OPERATION", "CALCUL"),
            NOM_PARA=_names(),
            TYPE_CALCUL=SIMP(
                statut="o",
                typ="TXM",
                max="**",
                into=("MAXI", "MINI", "SOMM", "MOY", "MAXI_ABS", "MINI_ABS", "SOMM_ABS"),
            ),
        ),
    ),
    TYPE_TABLE=SIMP(statut="c", typ="TXM", into=("TABLE", "TABLE_FONCTION", "TABLE_CONTAINER")),
    TITRE=SIMP(statut="f", typ="TXM"),
    INFO=SIMP(statut="f", typ="I", defaut=1, into=(1, 2)),
)
