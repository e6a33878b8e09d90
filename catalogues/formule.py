"""FORMULE: a function defined by a Python expression of its parameters.

Like code_aster's ``FORM``, FORMULE accepts *any* other keyword: each extra
keyword names a value or a function the expression uses, e.g.
``FORMULE(VALE="F(INST)", NOM_PARA="INST", F=myfunc)``. Only the keywords
below are checked; the runtime passes the extra keywords to the formula's
evaluation context (see ``extra_keywords``).
"""

from asterlite.catalog import OPER, SIMP, UN_PARMI


def formule_type(kw) -> str:
    """formule_c for a complex expression (VALE_C), formule otherwise."""
    return "formule_c" if kw.get("VALE_C") is not None else "formule"


FORMULE = OPER(
    nom="FORMULE",
    sd_prod=formule_type,
    reentrant="n",
    extra_keywords=True,  # the names the expression refers to
    fr="Define a real or complex formula from a mathematical expression",
    regles=(UN_PARMI("VALE", "VALE_C"),),
    VALE=SIMP(statut="f", typ="TXM", fr="Expression of a real formula"),
    VALE_C=SIMP(statut="f", typ="TXM", fr="Expression of a complex formula"),
    NOM_PARA=SIMP(statut="o", typ="TXM", max="**", fr="Names of the parameters"),
)
