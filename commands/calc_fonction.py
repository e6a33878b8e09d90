"""CALC_FONCTION: one operation on functions (numerics in asterlite.post.functions).

Supported: COMB, COMB_C, MULT (optionally re-tabulated on LIST_PARA), ABS,
ASSE, COMPOSE, DERIVE, INTEGRE, ENVELOPPE, EXTRACTION, FFT (real to
complex and back), INVERSE, PUISSANCE, SPEC_OSCI (NIGAM), CORR_ACCE
(FILTRAGE, POLYNOME). NOM_PARA, NOM_RESU, INTERPOL, PROL_* override the
attributes of the result.
"""

from __future__ import annotations

import numpy as np

from asterlite.concepts.function import Function, Nappe
from asterlite.errors import CommandError
from asterlite.post import functions as fops
from asterlite.post.restitution import as_tuple, values_of


def run(ctx, kw):
    operation = next(
        (k for k in ("COMB", "COMB_C", "MULT", "ABS", "ASSE", "COMPOSE", "DERIVE", "INTEGRE",
                     "ENVELOPPE", "EXTRACTION", "FFT", "INVERSE", "PUISSANCE", "SPEC_OSCI",
                     "CORR_ACCE")
         if kw.get(k) is not None),
        None,
    )  # fmt: skip
    if operation is None:
        given = next((k for k, v in dict.items(kw) if isinstance(v, list) and v), "operation")
        ctx.unsupported(f"CALC_FONCTION/{given}", given, kw)
    occurrences = kw.factor(operation)
    try:
        result = OPERATIONS[operation](ctx, occurrences, kw)
    except CommandError as exc:
        ctx.error(exc.message, operation, kw)
    if isinstance(result, Function):
        result = with_overrides(result, kw)
    return result


def _real_functions(ctx, occurrences, kw, key="FONCTION"):
    funcs = []
    for occ in occurrences:
        for func in as_tuple(occ[key]):
            if isinstance(func, Nappe):
                ctx.unsupported("CALC_FONCTION on a nappe", key, occ)
            funcs.append(func)
    return funcs


def _on_list_para(result: Function, kw) -> Function:
    if kw.get("LIST_PARA") is None:
        return result
    x = values_of(kw["LIST_PARA"])
    return result.with_values(x, result.evaluate(x))


def comb(ctx, occurrences, kw):
    funcs = _real_functions(ctx, occurrences, kw)
    return _on_list_para(fops.combine(funcs, [occ["COEF"] for occ in occurrences]), kw)


def comb_c(ctx, occurrences, kw):
    funcs = _real_functions(ctx, occurrences, kw)
    coefs = [
        occ["COEF_C"] if occ.get("COEF_C") is not None else occ["COEF_R"] for occ in occurrences
    ]
    coefs = [complex(c) for c in coefs]
    return _on_list_para(fops.combine(funcs, coefs), kw)


def mult(ctx, occurrences, kw):
    return _on_list_para(fops.multiply(_real_functions(ctx, occurrences, kw)), kw)


def single(occurrences):
    return occurrences[0]


OPERATIONS = {
    "COMB": comb,
    "COMB_C": comb_c,
    "MULT": mult,
    "ABS": lambda ctx, occ, kw: fops.absolute(single(occ)["FONCTION"]),
    "ASSE": lambda ctx, occ, kw: fops.concatenate(
        *as_tuple(single(occ)["FONCTION"]), single(occ).get("SURCHARGE", "DROITE")
    ),
    "COMPOSE": lambda ctx, occ, kw: fops.compose(
        single(occ)["FONC_RESU"], single(occ)["FONC_PARA"]
    ),
    "DERIVE": lambda ctx, occ, kw: fops.derivative(single(occ)["FONCTION"]),
    "INTEGRE": lambda ctx, occ, kw: fops.integrate(
        single(occ)["FONCTION"], single(occ).get("METHODE", "TRAPEZE"), single(occ).get("COEF", 0.0)
    ),
    "ENVELOPPE": lambda ctx, occ, kw: fops.envelope(
        _real_functions(ctx, occ, kw), single(occ).get("CRITERE", "SUP")
    ),
    "EXTRACTION": lambda ctx, occ, kw: fops.extract(single(occ)["FONCTION"], single(occ)["PARTIE"]),
    "INVERSE": lambda ctx, occ, kw: fops.inverse(single(occ)["FONCTION"]),
    "CORR_ACCE": lambda ctx, occ, kw: fops.corrected_accelerogram(
        single(occ)["FONCTION"],
        single(occ)["METHODE"],
        float(single(occ).get("FREQ_FILTRE", 0.05)),
        single(occ).get("CORR_DEPL", "NON") == "OUI",
    ),
    "PUISSANCE": lambda ctx, occ, kw: fops.power(
        single(occ)["FONCTION"], int(single(occ).get("EXPOSANT", 1))
    ),
}


def fft(ctx, occurrences, kw):
    occ = single(occurrences)
    func = occ["FONCTION"]
    method = occ.get("METHODE", "PROL_ZERO")
    if func.is_complex:
        return fops.inverse_fft(func, method, symmetric=occ.get("SYME", "OUI") == "OUI")
    return fops.fft(func, method)


def spec_osci(ctx, occurrences, kw):
    occ = single(occurrences)
    if occ.get("METHODE", "NIGAM") != "NIGAM":
        ctx.unsupported(f"SPEC_OSCI METHODE={occ['METHODE']}", "SPEC_OSCI", kw)
    if occ.get("AMOR_REDUIT") is None:
        ctx.unsupported(
            "SPEC_OSCI without AMOR_REDUIT (code_aster's default list)", "SPEC_OSCI", kw
        )
    if occ.get("LIST_FREQ") is not None:
        freqs = values_of(occ["LIST_FREQ"])
    elif occ.get("FREQ") is not None:
        freqs = values_of(occ["FREQ"])
    else:
        ctx.unsupported(
            "SPEC_OSCI without LIST_FREQ / FREQ (code_aster's default list)", "SPEC_OSCI", kw
        )
    func = occ["FONCTION"]
    nature = occ.get("NATURE", "ACCE")
    dampings = values_of(occ["AMOR_REDUIT"])
    curves = [
        Function(
            freqs,
            fops.response_spectrum(func, freqs, float(xi), nature, float(occ["NORME"])),
            NOM_PARA="FREQ",
            NOM_RESU=nature,
            INTERPOL=("LOG", "LOG"),
            PROL_GAUCHE="EXCLU",  # code_aster's spectra (15 and 17) stop below the first frequency
            PROL_DROITE="CONSTANT",
        )  # fmt: skip
        for xi in dampings
    ]
    if occ.get("TYPE_RESU") == "FONCTION" and len(curves) == 1:
        return with_overrides(curves[0], kw)
    return Nappe(
        dampings, curves, NOM_PARA="AMOR", NOM_RESU=nature, NOM_PARA_FONC="FREQ",
        INTERPOL=("LIN", "LOG"), PROL_GAUCHE="EXCLU", PROL_DROITE="EXCLU",
    )  # fmt: skip


OPERATIONS["FFT"] = fft
OPERATIONS["SPEC_OSCI"] = spec_osci


def with_overrides(func: Function, kw) -> Function:
    changes = {k: kw[k] for k in ("NOM_PARA", "NOM_RESU", "INTERPOL", "PROL_GAUCHE", "PROL_DROITE")
               if kw.get(k) is not None}  # fmt: skip
    if not changes:
        return func
    return func.with_values(func.abscissas, np.asarray(func.ordinates), **changes)
