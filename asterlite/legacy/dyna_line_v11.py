"""DYNA_LINE_TRAN and DYNA_LINE_HARM (code_aster 10-12) as DYNA_VIBRA.

code_aster 11's own DYNA_VIBRA was a macro that handed its keywords, less
TYPE_CALCUL and BASE_CALCUL, unchanged to DYNA_LINE_TRAN (a transient on the
physical basis), DYNA_TRAN_MODAL (on a generalized one) or DYNA_LINE_HARM (a
harmonic response, physical or generalized): a DYNA_LINE_TRAN or
DYNA_LINE_HARM call is the DYNA_VIBRA call with those two keywords added
(and, on a generalized basis, EXCIT's VECT_ASSE named VECT_ASSE_GENE, as
code_aster 12 renamed it).
What today's DYNA_VIBRA no longer accepts is then refused by its catalogue,
by name.

The keywords of code_aster 10 that 11 had already replaced in these commands
(the scheme factors NEWMARK=_F(ALPHA, DELTA), WILSON, DIFF_CENTRE, ADAPT,
ETAT_INIT/DYNA_TRANS, ...: the ``legacy`` names code_aster 11's language
data keeps for them) are refused by name: asterlite does not translate them.
"""

from __future__ import annotations

from asterlite.catalog.language.model import keyword_paths
from asterlite.legacy.base import Env, Translation, factor
from asterlite.legacy.language_data import old_language

TARGET = "DYNA_VIBRA"
GENERALIZED = ("matr_asse_gene_r", "matr_asse_gene_c")


def translate_dyna_line_tran(kwargs: dict, env: Env) -> Translation:
    _refuse_older_names("DYNA_LINE_TRAN", kwargs, env)
    env.note("DYNA_LINE_TRAN", "DYNA_VIBRA(TYPE_CALCUL='TRAN', BASE_CALCUL='PHYS')")
    header = {"TYPE_CALCUL": "TRAN", "BASE_CALCUL": "PHYS"}
    return Translation(TARGET, {**header, **kwargs}, env.notes)


def translate_dyna_line_harm(kwargs: dict, env: Env) -> Translation:
    _refuse_older_names("DYNA_LINE_HARM", kwargs, env)
    base = "GENE" if _is_generalized(kwargs.get("MATR_RIGI")) else "PHYS"
    env.note("DYNA_LINE_HARM", f"DYNA_VIBRA(TYPE_CALCUL='HARM', BASE_CALCUL='{base}')")
    header = {"TYPE_CALCUL": "HARM", "BASE_CALCUL": base}
    out = dict(kwargs)
    if base == "GENE" and "EXCIT" in out:  # code_aster 12's name on a generalized basis
        out["EXCIT"] = tuple(_generalized_load(o, env) for o in _occurrences(out["EXCIT"]))
    return Translation(TARGET, {**header, **out}, env.notes)


def _occurrences(value) -> list:
    return list(value) if isinstance(value, (list, tuple)) else [value]


def _generalized_load(occurrence, env: Env):
    if not isinstance(occurrence, dict) or "VECT_ASSE" not in occurrence:
        return occurrence
    env.note("DYNA_LINE_HARM/EXCIT/VECT_ASSE", "VECT_ASSE_GENE", occurrence, "VECT_ASSE")
    renamed = {("VECT_ASSE_GENE" if k == "VECT_ASSE" else k): v for k, v in occurrence.items()}
    new = factor(renamed, occurrence)
    if "VECT_ASSE" in new.keyword_locations:
        new.keyword_locations["VECT_ASSE_GENE"] = new.keyword_locations["VECT_ASSE"]
    return new


def _is_generalized(matrix) -> bool:
    """A generalized matrix (code_aster 11's DYNA_LINE_HARM took both kinds)."""
    satisfies = getattr(matrix, "satisfies", None)
    return satisfies is not None and any(satisfies(name) for name in GENERALIZED)


def _refuse_older_names(command: str, kwargs: dict, env: Env) -> None:
    """Refuse a keyword code_aster 10 had where code_aster 11 has none."""
    data = old_language().command(command)
    older = set(data.get("legacy", ()))
    known = keyword_paths(data)

    def visit(level: dict, prefix: tuple[str, ...]) -> None:
        for key, value in level.items():
            path = (*prefix, key)
            if key in older and path not in known:
                env.unsupported(
                    f"{'/'.join(path)} is code_aster 10's spelling, which code_aster "
                    "11 had replaced; asterlite does not translate it",
                    level if prefix else None,
                    key,
                )
            occurrences = value if isinstance(value, (list, tuple)) else (value,)
            for occurrence in occurrences:
                if isinstance(occurrence, dict):
                    visit(occurrence, path)

    visit(kwargs, ())
