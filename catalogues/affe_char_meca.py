"""AFFE_CHAR_MECA: constant mechanical loads and boundary conditions.

``mechanical_loads(value_type)`` builds the factor keywords shared with
AFFE_CHAR_MECA_F, where the values are functions instead of reals.
"""

from asterlite.catalogues.common import OUI_NON, group_ma, group_no, noeud, tout

from asterlite.catalog import (
    AU_MOINS_UN,
    BLOC,
    EXCLUS,
    FACT,
    OPER,
    SIMP,
    UN_PARMI,
    absent,
    equal_to,
    exists,
)

# degrees of freedom a mechanical model may carry (the common subset of code_aster's list)
DDL_MECANIQUE = (
    "DX", "DY", "DZ", "DRX", "DRY", "DRZ", "GRX", "PRES", "PHI", "PSI", "TEMP", "PRE1", "PRE2",
    "DRGX", "DRGY", "DRGZ", "GONF", "UI2", "UI3", "VI2", "VI3", "WI2", "WI3", "UO2", "UO3",
    "VO2", "VO3", "WO2", "WO3", "WO", "WI1", "WO1", "H1X", "H1Y", "H1Z", "K1", "K2", "K3",
)  # fmt: skip
TRANSLATIONS_ROTATIONS = ("DX", "DY", "DZ", "DRX", "DRY", "DRZ")
FORCES_MOMENTS = ("FX", "FY", "FZ", "MX", "MY", "MZ")


def _values(names, value_type) -> dict:
    return {name: SIMP(statut="f", typ=value_type) for name in names}


def mechanical_loads(value_type) -> dict:
    """Factor keywords of AFFE_CHAR_MECA (value_type 'R') or _F (functions)."""
    return dict(
        DDL_IMPO=FACT(
            statut="f",
            max="**",
            fr="Impose values of degrees of freedom on nodes",
            regles=(
                AU_MOINS_UN("TOUT", "GROUP_MA", "GROUP_NO", "NOEUD"),
                AU_MOINS_UN(*DDL_MECANIQUE, "BLOCAGE", "LIAISON"),
            ),
            TOUT=tout(),
            NOEUD=noeud(),
            GROUP_NO=group_no(),
            GROUP_MA=group_ma(),
            SANS_GROUP_MA=group_ma(),
            SANS_GROUP_NO=group_no(),
            BLOCAGE=SIMP(
                statut="f",
                typ="TXM",
                min=1,
                max=3,
                into=("DEPLACEMENT", "ROTATION", "TUYAU_FOURIER"),
            ),
            # deprecated spelling of BLOCAGE=('DEPLACEMENT', 'ROTATION'), still accepted
            LIAISON=SIMP(statut="f", typ="TXM", into=("ENCASTRE",)),
            **_values(DDL_MECANIQUE, value_type),
        ),
        DDL_POUTRE=FACT(
            statut="f",
            max="**",
            fr="Block degrees of freedom in the local frame of a beam",
            regles=(
                AU_MOINS_UN("TOUT", "GROUP_MA", "GROUP_NO"),
                AU_MOINS_UN(*TRANSLATIONS_ROTATIONS),
                UN_PARMI("VECT_Y", "ANGL_VRIL"),
            ),
            TOUT=tout(),
            GROUP_NO=group_no(),
            GROUP_MA=group_ma(),
            SANS_GROUP_MA=group_ma(),
            SANS_GROUP_NO=group_no(),
            **_values(TRANSLATIONS_ROTATIONS, value_type),
            VECT_Y=SIMP(statut="f", typ="R", min=3, max=3),
            ANGL_VRIL=SIMP(statut="f", typ="R"),
            GROUP_MA_REPE=SIMP(statut="f", typ="grma"),
        ),
        FACE_IMPO=FACT(
            statut="f",
            max="**",
            fr="Impose degrees of freedom on all nodes of faces",
            regles=(
                AU_MOINS_UN(*TRANSLATIONS_ROTATIONS, "DNOR", "DTAN", "PRES", "PHI", "TEMP"),
                EXCLUS("DNOR", "DX"),
                EXCLUS("DNOR", "DY"),
                EXCLUS("DNOR", "DZ"),
                EXCLUS("DTAN", "DX"),
                EXCLUS("DTAN", "DY"),
                EXCLUS("DTAN", "DZ"),
            ),
            GROUP_MA=group_ma(),
            SANS_GROUP_MA=group_ma(),
            SANS_GROUP_NO=group_no(),
            **_values(TRANSLATIONS_ROTATIONS + ("DNOR", "DTAN", "PRES", "PHI", "TEMP"), value_type),
        ),
        LIAISON_DDL=FACT(
            statut="f",
            max="**",
            fr="Linear relation between degrees of freedom of nodes",
            regles=(UN_PARMI("GROUP_NO", "NOEUD"),),
            GROUP_NO=SIMP(statut="f", typ="grno", max="**"),
            NOEUD=noeud(),
            DDL=SIMP(statut="o", typ="TXM", into=DDL_MECANIQUE, max="**"),
            COEF_MULT=SIMP(statut="o", typ="R", max="**"),
            COEF_IMPO=SIMP(statut="o", typ=value_type),
        ),
        LIAISON_OBLIQUE=FACT(
            statut="f",
            max="**",
            regles=(AU_MOINS_UN("GROUP_MA", "GROUP_NO"), AU_MOINS_UN(*TRANSLATIONS_ROTATIONS)),
            GROUP_NO=group_no(),
            GROUP_MA=group_ma(),
            SANS_GROUP_MA=group_ma(),
            SANS_GROUP_NO=group_no(),
            ANGL_NAUT=SIMP(statut="o", typ="R", max=3),
            **_values(TRANSLATIONS_ROTATIONS, value_type),
        ),
        LIAISON_GROUP=FACT(
            statut="f",
            max="**",
            fr="Same linear relation between pairs of nodes",
            regles=(
                UN_PARMI("GROUP_MA_1", "GROUP_NO_1"),
                UN_PARMI("GROUP_MA_2", "GROUP_NO_2"),
                EXCLUS("GROUP_MA_1", "GROUP_NO_2"),
                EXCLUS("GROUP_NO_1", "GROUP_MA_2"),
            ),
            GROUP_MA_1=group_ma(),
            GROUP_MA_2=group_ma(),
            GROUP_NO_1=group_no(),
            GROUP_NO_2=group_no(),
            SANS_GROUP_NO=group_no(),
            DDL_1=SIMP(statut="o", typ="TXM", into=DDL_MECANIQUE + ("DNOR",), max="**"),
            COEF_MULT_1=SIMP(statut="o", typ="R", max="**"),
            DDL_2=SIMP(statut="o", typ="TXM", into=DDL_MECANIQUE + ("DNOR",), max="**"),
            COEF_MULT_2=SIMP(statut="o", typ="R", max="**"),
            COEF_IMPO=SIMP(statut="o", typ=value_type),
            TRAN=SIMP(statut="f", typ="R", max=3),
            ANGL_NAUT=SIMP(statut="f", typ="R", max=3),
            CENTRE=SIMP(statut="f", typ="R", max=3),
        ),
        LIAISON_SOLIDE=FACT(
            statut="f",
            max="**",
            fr="Rigid part of a structure",
            regles=(UN_PARMI("GROUP_NO", "GROUP_MA"),),
            GROUP_NO=group_no(),
            GROUP_MA=group_ma(),
            SANS_GROUP_MA=group_ma(),
            SANS_GROUP_NO=group_no(),
            DIST_MIN=SIMP(statut="f", typ="R"),
        ),
        LIAISON_UNIF=FACT(
            statut="f",
            max="**",
            fr="Same unknown value of degrees of freedom on a set of nodes",
            regles=(UN_PARMI("GROUP_NO", "GROUP_MA"),),
            GROUP_NO=group_no(),
            GROUP_MA=group_ma(),
            SANS_GROUP_MA=group_ma(),
            SANS_GROUP_NO=group_no(),
            DDL=SIMP(statut="o", typ="TXM", into=DDL_MECANIQUE, max="**"),
        ),
        FORCE_NODALE=FACT(
            statut="f",
            max="**",
            fr="Nodal forces and moments",
            regles=(UN_PARMI("GROUP_NO", "NOEUD"), AU_MOINS_UN(*FORCES_MOMENTS)),
            GROUP_NO=group_no(),
            NOEUD=noeud(),
            **_values(FORCES_MOMENTS, value_type),
            ANGL_NAUT=SIMP(statut="f", typ=value_type, max=3),
        ),
        FORCE_FACE=FACT(
            statut="f",
            max="**",
            fr="Surface forces on faces of volume elements",
            regles=(AU_MOINS_UN("FX", "FY", "FZ"),),
            GROUP_MA=group_ma(),
            **_values(("FX", "FY", "FZ"), value_type),
        ),
        FORCE_ARETE=FACT(
            statut="f",
            max="**",
            fr="Line forces on edges",
            regles=(AU_MOINS_UN(*FORCES_MOMENTS),),
            GROUP_MA=group_ma(),
            **_values(FORCES_MOMENTS, value_type),
        ),
        FORCE_CONTOUR=FACT(
            statut="f",
            max="**",
            fr="Line forces on the contour of 2D elements",
            regles=(AU_MOINS_UN("FX", "FY", "FZ", "MX", "MY", "MZ"),),
            GROUP_MA=group_ma(),
            **_values(FORCES_MOMENTS, value_type),
        ),
        FORCE_INTERNE=FACT(
            statut="f",
            max="**",
            fr="Volume forces",
            regles=(AU_MOINS_UN("TOUT", "GROUP_MA"), AU_MOINS_UN("FX", "FY", "FZ")),
            TOUT=tout(),
            GROUP_MA=group_ma(),
            **_values(("FX", "FY", "FZ"), value_type),
        ),
        FORCE_POUTRE=FACT(
            statut="f",
            max="**",
            fr="Distributed forces on beams",
            regles=(
                AU_MOINS_UN("TOUT", "GROUP_MA"),
                AU_MOINS_UN(*FORCES_MOMENTS, "N", "VY", "VZ", "MT", "MFY", "MFZ"),
            ),
            TOUT=tout(),
            GROUP_MA=group_ma(),
            TYPE_CHARGE=SIMP(statut="f", typ="TXM", defaut="FORCE", into=("FORCE", "VENT")),
            **_values(FORCES_MOMENTS + ("N", "VY", "VZ", "MT", "MFY", "MFZ"), value_type),
        ),
        PRES_REP=FACT(
            statut="f",
            max="**",
            fr="Pressure on faces or edges",
            regles=(AU_MOINS_UN("TOUT", "GROUP_MA"), AU_MOINS_UN("PRES", "CISA_2D")),
            TOUT=tout(),
            GROUP_MA=group_ma(),
            PRES=SIMP(statut="f", typ=value_type),
            CISA_2D=SIMP(statut="f", typ=value_type),
        ),
        PRE_EPSI=FACT(
            statut="f",
            max="**",
            fr="Initial strains",
            regles=(AU_MOINS_UN("TOUT", "GROUP_MA"),),
            TOUT=tout(),
            GROUP_MA=group_ma(),
            **_values(
                (
                    "EPXX",
                    "EPYY",
                    "EPZZ",
                    "EPXY",
                    "EPXZ",
                    "EPYZ",
                    "EPX",
                    "KY",
                    "KZ",
                    "EXX",
                    "EYY",
                    "EXY",
                    "KXX",
                    "KYY",
                    "KXY",
                ),
                value_type,
            ),  # fmt: skip
        ),
    )


# the options of code_aster's LIAISON_ELEM, each with its own keywords
LIAISON_ELEM = FACT(
    statut="f",
    max="**",
    fr="Connect a beam node to a face of a solid, a shell edge or a pipe",
    OPTION=SIMP(
        statut="o",
        typ="TXM",
        into=(
            "3D_TUYAU",
            "COQ_3D",
            "3D_POU",
            "3D_POU_ARLEQUIN",
            "2D_POU",
            "COQ_POU",
            "COQ_TUYAU",
            "PLAQ_POUT_ORTH",
        ),
    ),  # fmt: skip
    b_3d_pou=BLOC(
        condition=equal_to("OPTION", ("3D_POU", "2D_POU")),
        regles=(UN_PARMI("GROUP_NO_2", "GROUP_MA_2"),),
        GROUP_MA_1=group_ma(),
        GROUP_NO_2=SIMP(statut="f", typ="grno"),
        GROUP_MA_2=SIMP(statut="f", typ="grma"),
        ANGL_MAX=SIMP(statut="f", typ="R", defaut=1.0),
    ),
    b_coq_3d=BLOC(
        condition=equal_to("OPTION", "COQ_3D"),
        GROUP_MA_COQUE=SIMP(statut="o", typ="grma"),
        GROUP_MA_MASSIF=SIMP(statut="o", typ="grma"),
        CARA_ELEM=SIMP(statut="o", typ="cara_elem"),
        COEF_RIGI_DRZ=SIMP(statut="f", typ="R", defaut=1.0e-05),
    ),
    b_3d_pou_arlequin=BLOC(
        condition=equal_to("OPTION", "3D_POU_ARLEQUIN"),
        GROUP_MA_1=group_ma(),
        GROUP_MA_2=group_ma(),
        CARA_ELEM=SIMP(statut="o", typ="cara_elem"),
        CHAM_MATER=SIMP(statut="o", typ="cham_mater"),
    ),
    b_coq_pou_tuy=BLOC(
        condition=equal_to("OPTION", ("COQ_POU", "COQ_TUYAU", "3D_TUYAU")),
        GROUP_MA_1=group_ma(),
        GROUP_NO_2=SIMP(statut="f", typ="grno"),
        CARA_ELEM=SIMP(statut="o", typ="cara_elem"),
        AXE_POUTRE=SIMP(statut="o", typ="R", max=3),
        b_3d_tuyau=BLOC(
            condition=equal_to("OPTION", "3D_TUYAU"),
            ANGL_MAX=SIMP(statut="f", typ="R", defaut=1.0),
        ),
    ),
    b_plaq_pout_orth=BLOC(
        condition=equal_to("OPTION", "PLAQ_POUT_ORTH"),
        GROUP_MA_1=group_ma(),
        GROUP_NO_2=SIMP(statut="f", typ="grno"),
        ANGL_MAX=SIMP(statut="f", typ="R", defaut=1.0),
        VERIF_EXCENT=SIMP(statut="f", typ="TXM", defaut="OUI", into=OUI_NON),
    ),
)


# Laplace force per unit length on beam conductors; its intensity in time
# (mu0 i1 i2 / 2 pi) comes from a FONC_MULT such as DEFI_FONC_ELEC's
FORCE_ELEC = FACT(
    statut="f",
    max="**",
    fr="Laplace force on beam conductors from a second, straight conductor",
    regles=(UN_PARMI("TOUT", "GROUP_MA"),),
    TOUT=tout(),
    GROUP_MA=group_ma(),
    POSITION=SIMP(statut="f", typ="TXM", into=("PARA", "INFI", "FINI")),
    b_force=BLOC(
        condition=absent("POSITION"),
        FX=SIMP(statut="f", typ="R", defaut=0.0),
        FY=SIMP(statut="f", typ="R", defaut=0.0),
        FZ=SIMP(statut="f", typ="R", defaut=0.0),
    ),
    b_parallel=BLOC(
        condition=equal_to("POSITION", "PARA"),
        regles=(UN_PARMI("TRANS", "DIST"),),
        TRANS=SIMP(statut="f", typ="R", max=3),
        DIST=SIMP(statut="f", typ="R"),
        b_point2=BLOC(condition=exists("DIST"), POINT2=SIMP(statut="o", typ="R", max=3)),
    ),
    b_line=BLOC(
        condition=equal_to("POSITION", ("FINI", "INFI")),
        POINT1=SIMP(statut="o", typ="R", max=3),
        POINT2=SIMP(statut="o", typ="R", max=3),
    ),
)


AFFE_CHAR_MECA = OPER(
    nom="AFFE_CHAR_MECA",
    sd_prod="char_meca",
    reentrant="n",
    fr="Constant mechanical loads and boundary conditions",
    regles=(
        AU_MOINS_UN(
            "PESANTEUR",
            "ROTATION",
            "DDL_IMPO",
            "DDL_POUTRE",
            "FACE_IMPO",
            "LIAISON_DDL",
            "LIAISON_OBLIQUE",
            "LIAISON_GROUP",
            "LIAISON_SOLIDE",
            "LIAISON_UNIF",
            "LIAISON_ELEM",
            "LIAISON_CHAMNO",
            "VECT_ASSE",
            "FORCE_NODALE",
            "FORCE_FACE",
            "FORCE_ARETE",
            "FORCE_CONTOUR",
            "FORCE_INTERNE",
            "PRES_REP",
            "PRE_EPSI",
            "FORCE_POUTRE",
            "FORCE_ELEC",
            "FORCE_TUYAU",
            "EVOL_CHAR",
        ),
    ),  # fmt: skip
    VERI_AFFE=SIMP(statut="f", typ="TXM", defaut="OUI", into=OUI_NON),
    VERI_NORM=SIMP(statut="f", typ="TXM", defaut="OUI", into=OUI_NON),
    MODELE=SIMP(statut="o", typ="modele_sdaster"),
    CARA_ELEM=SIMP(statut="f", typ="cara_elem"),
    CHAM_MATER=SIMP(statut="f", typ="cham_mater"),
    DOUBLE_LAGRANGE=SIMP(statut="f", typ="TXM", into=OUI_NON, defaut="OUI"),
    EVOL_CHAR=SIMP(
        statut="f", typ="evol_char", fr="A load history: its nodal forces, linear in time"
    ),
    LIAISON_ELEM=LIAISON_ELEM,
    FORCE_ELEC=FORCE_ELEC,
    LIAISON_CHAMNO=FACT(
        statut="f",
        max=1,
        fr="One relation whose coefficients are the values of a nodal field",
        CHAM_NO=SIMP(statut="o", typ="cham_no_sdaster"),
        COEF_IMPO=SIMP(statut="o", typ="R"),
    ),
    PESANTEUR=FACT(
        statut="f",
        fr="Gravity",
        GROUP_MA=group_ma(),
        GRAVITE=SIMP(statut="o", typ="R"),
        DIRECTION=SIMP(statut="o", typ="R", min=3, max=3),
    ),
    ROTATION=FACT(
        statut="f",
        fr="Rotation about an axis (centrifugal load)",
        GROUP_MA=group_ma(),
        SANS_GROUP_MA=group_ma(),
        VITESSE=SIMP(statut="o", typ="R"),
        AXE=SIMP(statut="o", typ="R", min=2, max=3),
        CENTRE=SIMP(statut="f", typ="R", min=2, max=3),
    ),
    VECT_ASSE=SIMP(statut="f", typ="cham_no_sdaster"),
    FORCE_TUYAU=FACT(
        statut="f",
        max="**",
        fr="Pressure inside pipe elements (TUYAU_3M, TUYAU_6M)",
        regles=(AU_MOINS_UN("TOUT", "GROUP_MA"),),
        TOUT=tout(),
        GROUP_MA=group_ma(),
        PRES=SIMP(statut="f", typ="R"),
    ),
    INFO=SIMP(statut="f", typ="I", defaut=1, into=(1, 2)),
    **mechanical_loads("R"),
)

__all__ = ["AFFE_CHAR_MECA", "DDL_MECANIQUE", "mechanical_loads"]
