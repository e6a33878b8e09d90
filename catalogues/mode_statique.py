"""MODE_STATIQUE: static modes (unit displacement, force or acceleration)."""

from asterlite.catalogues.common import C_SOLVEUR, NO_EFFECT_STORED, noeud, tout

from asterlite.catalog import BLOC, FACT, OPER, PRESENT_PRESENT, SIMP, UN_PARMI, exists


def _unit_loads(fr: str) -> FACT:
    """MODE_STAT / FORCE_NODALE: where and on which components."""
    return FACT(
        statut="f",
        max="**",
        fr=fr,
        regles=(
            UN_PARMI("TOUT", "NOEUD", "GROUP_NO"),
            UN_PARMI("TOUT_CMP", "AVEC_CMP", "SANS_CMP"),
        ),
        TOUT=tout(),
        NOEUD=noeud(),
        GROUP_NO=SIMP(statut="f", typ="grno", max="**"),
        TOUT_CMP=SIMP(statut="f", typ="TXM", into=("OUI",)),
        AVEC_CMP=SIMP(statut="f", typ="TXM", max="**"),
        SANS_CMP=SIMP(statut="f", typ="TXM", max="**"),
    )


MODE_STATIQUE = OPER(
    nom="MODE_STATIQUE",
    sd_prod="mode_meca",
    reentrant="n",
    fr="Static deformed shapes for unit displacements, forces or accelerations",
    regles=(
        UN_PARMI("MODE_STAT", "FORCE_NODALE", "PSEUDO_MODE", "MODE_INTERF"),
        PRESENT_PRESENT("MODE_INTERF", "MATR_MASS"),
        PRESENT_PRESENT("PSEUDO_MODE", "MATR_MASS"),
    ),
    CHAM_MATER=SIMP(statut="f", typ="cham_mater", no_effect=NO_EFFECT_STORED),
    CARA_ELEM=SIMP(statut="f", typ="cara_elem", no_effect=NO_EFFECT_STORED),
    MATR_RIGI=SIMP(statut="o", typ="matr_asse_depl_r"),
    MATR_MASS=SIMP(statut="f", typ="matr_asse_depl_r"),
    MODE_STAT=_unit_loads("Unit imposed displacements"),
    FORCE_NODALE=_unit_loads("Unit nodal forces"),
    PSEUDO_MODE=FACT(
        statut="f",
        max="**",
        fr="Unit accelerations",
        regles=(UN_PARMI("AXE", "DIRECTION", "TOUT", "GROUP_NO"),),
        AXE=SIMP(statut="f", typ="TXM", into=("X", "Y", "Z"), max=3),
        DIRECTION=SIMP(statut="f", typ="R", min=3, max=3),
        TOUT=tout(),
        GROUP_NO=SIMP(statut="f", typ="grno", max="**"),
        b_dir=BLOC(condition=exists("DIRECTION"), NOM_DIR=SIMP(statut="o", typ="TXM")),
        b_cmp=BLOC(
            condition=exists("TOUT") | exists("NOEUD") | exists("GROUP_NO"),
            regles=(UN_PARMI("TOUT_CMP", "AVEC_CMP", "SANS_CMP"),),
            TOUT_CMP=SIMP(statut="f", typ="TXM", into=("OUI",)),
            AVEC_CMP=SIMP(statut="f", typ="TXM", max="**"),
            SANS_CMP=SIMP(statut="f", typ="TXM", max="**"),
        ),
    ),
    MODE_INTERF=FACT(
        statut="f",
        regles=(UN_PARMI("TOUT", "GROUP_NO"), UN_PARMI("TOUT_CMP", "AVEC_CMP", "SANS_CMP")),
        TOUT=tout(),
        GROUP_NO=SIMP(statut="f", typ="grno", max="**"),
        TOUT_CMP=SIMP(statut="f", typ="TXM", into=("OUI",)),
        AVEC_CMP=SIMP(statut="f", typ="TXM", max="**"),
        SANS_CMP=SIMP(statut="f", typ="TXM", max="**"),
        NB_MODE=SIMP(statut="f", typ="I", defaut=1),
        SHIFT=SIMP(statut="f", typ="R", defaut=1.0),
    ),
    SOLVEUR=C_SOLVEUR("MODE_STATIQUE"),
    TITRE=SIMP(statut="f", typ="TXM"),
    INFO=SIMP(statut="f", typ="I", defaut=1, into=(1, 2)),
)
