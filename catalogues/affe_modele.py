"""AFFE_MODELE: assign a physical phenomenon and finite elements to a mesh."""

from asterlite.catalogues.common import OUI_NON, group_ma, tout

from asterlite.catalog import AU_MOINS_UN, BLOC, FACT, OPER, SIMP, UN_PARMI, equal_to, is_in

# Mechanical modellings of code_aster 17 (the coupled THM/HM family is left out).
MODELISATION_MECANIQUE = (
    "2D_DIS_T", "2D_DIS_TR", "2D_FLUI_ABSO", "2D_FLUI_PESA", "2D_FLUI_STRU", "2D_FLUIDE",
    "3D", "3D_ABSO", "3D_FAISCEAU", "3D_FLUI_ABSO", "3D_FLUIDE", "3D_INCO_UPG", "3D_INCO_UP",
    "3D_INCO_UPO", "3D_SI", "3D_GRAD_VARI", "3D_GRAD_INCO", "3D_GVNO", "3D_JOINT",
    "3D_JOINT_HYME", "3D_INTERFACE", "3D_INTERFACE_S", "AXIS", "AXIS_FLUI_STRU",
    "AXIS_FLUI_ABSO", "AXIS_FLUIDE", "AXIS_FOURIER", "AXIS_INCO_UPG", "AXIS_INCO_UP",
    "AXIS_INCO_UPO", "AXIS_SI", "AXIS_GRAD_VARI", "AXIS_GRAD_INCO", "AXIS_GVNO",
    "AXIS_JOINT", "AXIS_INTERFACE", "AXIS_INTERFACE_S", "BARRE", "CABLE_GAINE", "2D_BARRE",
    "C_PLAN", "C_PLAN_SI", "CABLE", "CABLE_POULIE", "COQUE_3D", "COQUE_AXIS", "D_PLAN",
    "D_PLAN_GRAD_VARI", "D_PLAN_GRAD_INCO", "D_PLAN_GVNO", "D_PLAN_GRAD_SIGM", "PLAN_JOINT",
    "PLAN_JOINT_HYME", "PLAN_INTERFACE", "PLAN_INTERFACE_S", "D_PLAN_ABSO", "D_PLAN_INCO_UPG",
    "D_PLAN_INCO_UP", "D_PLAN_INCO_UPO", "D_PLAN_SI", "DIS_T", "DIS_TR", "DKT", "DKTG",
    "DST", "FLUI_STRU", "POU_FLUI_STRU", "GRILLE_EXCENTRE", "GRILLE_MEMBRANE", "MEMBRANE",
    "POU_D_E", "POU_D_EM", "POU_D_T", "POU_D_T_GD", "POU_D_TG", "POU_D_TGM", "POU_D_SQUE",
    "Q4G", "Q4GG", "TUYAU_3M", "TUYAU_6M", "COQUE_SOLIDE", "3D_HHO", "D_PLAN_HHO",
    "3D_GRAD_HHO", "D_PLAN_GRAD_HHO",
)  # fmt: skip

MODELISATION_THERMIQUE = (
    "3D", "3D_DIAG", "AXIS", "AXIS_DIAG", "AXIS_FOURIER", "COQUE", "COQUE_AXIS",
    "COQUE_PLAN", "PLAN", "PLAN_DIAG", "3D_HHO", "PLAN_HHO", "AXIS_HHO",
)  # fmt: skip

FLUID_MODELISATIONS = (
    "2D_FLUIDE", "2D_FLUI_ABSO", "2D_FLUI_PESA", "2D_FLUI_STRU", "3D_FLUIDE",
    "3D_FLUI_ABSO", "AXIS_FLUIDE", "AXIS_FLUI_STRU", "AXIS_FLUI_ABSO", "FLUI_STRU",
)  # fmt: skip

AFFE_MODELE = OPER(
    nom="AFFE_MODELE",
    sd_prod="modele_sdaster",
    reentrant="n",
    fr="Assign the phenomenon and the finite elements on a mesh",
    regles=(AU_MOINS_UN("AFFE", "AFFE_SOUS_STRUC"),),
    MAILLAGE=SIMP(statut="o", typ="maillage_sdaster"),
    INFO=SIMP(statut="f", typ="I", defaut=1, into=(1, 2)),
    GRANDEUR_CARA=FACT(
        statut="f",
        LONGUEUR=SIMP(statut="f", typ="R", val_min=0),
        PRESSION=SIMP(statut="f", typ="R", val_min=0),
        TEMPERATURE=SIMP(statut="f", typ="R", val_min=0),
    ),
    AFFE_SOUS_STRUC=FACT(
        statut="f",
        regles=(UN_PARMI("TOUT", "SUPER_MAILLE"),),
        TOUT=tout(),
        SUPER_MAILLE=SIMP(statut="f", typ="ma", max="**"),
        PHENOMENE=SIMP(statut="f", typ="TXM", defaut="MECANIQUE", into=("MECANIQUE",)),
    ),
    AFFE=FACT(
        statut="f",
        max="**",
        regles=(UN_PARMI("TOUT", "GROUP_MA"),),
        TOUT=tout(),
        GROUP_MA=group_ma(),
        PHENOMENE=SIMP(statut="o", typ="TXM", into=("MECANIQUE", "THERMIQUE", "ACOUSTIQUE")),
        b_mecanique=BLOC(
            condition=equal_to("PHENOMENE", "MECANIQUE"),
            MODELISATION=SIMP(statut="o", typ="TXM", into=MODELISATION_MECANIQUE),
            b_formu_hho=BLOC(
                condition=is_in("MODELISATION", ("3D_HHO", "D_PLAN_HHO")),
                FORMULATION=SIMP(
                    statut="f",
                    typ="TXM",
                    defaut="LINEAIRE",
                    into=("LINEAIRE", "QUADRATIQUE", "CUBIQUE", "QUARTIQUE"),
                ),
            ),
            b_formu_hho_grad=BLOC(
                condition=is_in("MODELISATION", ("D_PLAN_GRAD_HHO", "3D_GRAD_HHO")),
                FORMULATION=SIMP(
                    statut="f", typ="TXM", defaut="LINEAIRE", into=("LINEAIRE", "QUADRATIQUE")
                ),
            ),
            b_formu_fsi=BLOC(
                condition=is_in("MODELISATION", FLUID_MODELISATIONS),
                FORMULATION=SIMP(
                    statut="f", typ="TXM", defaut="U_P_PHI", into=("U_P_PHI", "U_P", "U_PSI")
                ),
            ),
        ),
        b_thermique=BLOC(
            condition=equal_to("PHENOMENE", "THERMIQUE"),
            MODELISATION=SIMP(statut="o", typ="TXM", into=MODELISATION_THERMIQUE),
        ),
        b_acoustique=BLOC(
            condition=equal_to("PHENOMENE", "ACOUSTIQUE"),
            MODELISATION=SIMP(statut="o", typ="TXM", into=("3D", "PLAN", "3D_ABSO", "PLAN_ABSO")),
        ),
    ),
    DISTRIBUTION=FACT(
        statut="d",
        no_effect="distribution of the elements over the processes of a parallel run",
        fr="Parallel distribution of the elements",
        METHODE=SIMP(
            statut="f",
            typ="TXM",
            defaut="SOUS_DOMAINE",
            into=("MAIL_CONTIGU", "MAIL_DISPERSE", "CENTRALISE", "GROUP_ELEM", "SOUS_DOMAINE"),
        ),
        b_dist_maille=BLOC(
            condition=is_in("METHODE", ("MAIL_DISPERSE", "MAIL_CONTIGU")),
            CHARGE_PROC0_MA=SIMP(statut="f", typ="I", defaut=100, val_min=0, val_max=100),
        ),
        b_partition=BLOC(
            condition=equal_to("METHODE", "SOUS_DOMAINE"),
            NB_SOUS_DOMAINE=SIMP(statut="f", typ="I"),
            PARTITIONNEUR=SIMP(statut="f", typ="TXM", defaut="METIS", into=("METIS", "SCOTCH")),
        ),
    ),
    VERI_JACOBIEN=SIMP(statut="f", typ="TXM", into=OUI_NON, defaut="OUI"),
    VERI_NORM_IFS=SIMP(statut="f", typ="TXM", into=OUI_NON, defaut="OUI"),
    VERI_PLAN=SIMP(statut="f", typ="TXM", into=OUI_NON, defaut="OUI"),
)
