"""REST_SPEC_TEMP: a harmonic result to time by FFT, or a transient to frequencies."""

from asterlite.catalogues.common_post import concept_is

from asterlite.catalog import BLOC, OPER, SIMP, UN_PARMI, equal_to


def rest_spec_temp_type(kw) -> str:
    """A transient from a harmonic result and the converse (generalized likewise)."""
    resu = kw.get("RESULTAT")
    if resu is not None:
        return "dyna_harmo" if concept_is(resu, "dyna_trans") else "dyna_trans"
    return "harm_gene" if concept_is(kw.get("RESU_GENE"), "tran_gene") else "tran_gene"


REST_SPEC_TEMP = OPER(
    nom="REST_SPEC_TEMP",
    sd_prod=rest_spec_temp_type,
    reentrant="n",
    fr="Fourier transform of a result: frequency to time, or time to frequency",
    regles=(UN_PARMI("RESU_GENE", "RESULTAT"),),
    INFO=SIMP(statut="f", typ="I", defaut=1, into=(1, 2)),
    RESU_GENE=SIMP(statut="f", typ=("harm_gene", "tran_gene")),
    RESULTAT=SIMP(statut="f", typ=("dyna_harmo", "dyna_trans")),
    METHODE=SIMP(statut="f", typ="TXM", defaut="PROL_ZERO", into=("PROL_ZERO", "TRONCATURE")),
    SYMETRIE=SIMP(statut="f", typ="TXM", defaut="OUI", into=("OUI", "NON")),
    TOUT_CHAM=SIMP(statut="f", typ="TXM", into=("OUI",)),
    NOM_CHAM=SIMP(statut="f", typ="TXM", max=3, into=("DEPL", "VITE", "ACCE")),
    # distributes the DOFs over MPI processes: the values do not depend on it
    ACCELERATION_MPI=SIMP(statut="c", typ="TXM", defaut="OUI", into=("OUI", "NON")),
    prol_puissance_sup=BLOC(
        condition=equal_to("METHODE", "PROL_ZERO"), N_PUIS=SIMP(statut="o", typ="I")
    ),
)
