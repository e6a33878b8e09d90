"""DEPL_INTERNE: the displacements inside a static superelement."""

from asterlite.catalog import OPER, SIMP


def _sdprod(kw) -> str:
    given = kw.get("DEPL_GLOBAL")
    for name in ("cham_no_sdaster", "evol_elas", "dyna_trans", "dyna_harmo", "mode_meca_c"):
        if getattr(given, "satisfies", lambda _t: False)(name):
            return name
    return "mode_meca"


DEPL_INTERNE = OPER(
    nom="DEPL_INTERNE",
    sd_prod=_sdprod,
    reentrant="n",
    fr="Restitute a displacement inside a superelement (its interior, or its measurement)",
    DEPL_GLOBAL=SIMP(
        statut="o",
        typ=(
            "cham_no_sdaster",
            "mode_meca",
            "mode_meca_c",
            "evol_elas",
            "dyna_trans",
            "dyna_harmo",
        ),
    ),
    SUPER_MAILLE=SIMP(statut="o", typ="ma"),
    NOM_CAS=SIMP(statut="f", typ="TXM", defaut=" "),
)
