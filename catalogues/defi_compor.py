"""DEFI_COMPOR: behaviour of the fibre groups of multifibre beams
(MULTIFIBRE); the crystal behaviours (MONOCRISTAL, POLYCRISTAL) are
language-only."""

from asterlite.catalog import FACT, OPER, PRESENT_PRESENT, SIMP, UN_PARMI

DEFI_COMPOR = OPER(
    nom="DEFI_COMPOR",
    sd_prod="compor_sdaster",
    reentrant="n",
    fr="Material and behaviour of each fibre group of multifibre beams",
    regles=(
        UN_PARMI("MONOCRISTAL", "POLYCRISTAL", "MULTIFIBRE"),
        PRESENT_PRESENT("MULTIFIBRE", "GEOM_FIBRE", "MATER_SECT"),
    ),
    GEOM_FIBRE=SIMP(statut="f", typ="gfibre_sdaster"),
    MATER_SECT=SIMP(statut="f", typ="mater_sdaster"),
    MULTIFIBRE=FACT(
        statut="f",
        max="**",
        GROUP_FIBRE=SIMP(statut="o", typ="TXM", max="**"),
        MATER=SIMP(statut="o", typ="mater_sdaster"),
        RELATION=SIMP(
            statut="f",
            typ="TXM",
            defaut="ELAS",
            into=(
                "ELAS",
                "CORR_ACIER",
                "BETON_GRANGER",
                "GRAN_IRRA_LOG",
                "MAZARS_UNIL",
                "VISC_IRRA_LOG",
                "VMIS_CINE_GC",
                "VMIS_CINE_LINE",
                "VMIS_ISOT_LINE",
                "VMIS_ISOT_TRAC",
            ),
        ),  # fmt: skip
    ),
)
