"""INCLUDE_MATERIAU: evaluate a material data file and define its material.

A material file is deck text that builds functions with a few commands
(DEFI_FONCTION, CALC_FONCTION...) and ends with
``motscles = defi_motscles(ELAS=_F(...), ELAS_FO=_F(...), ...)``. It is
evaluated by asterlite's own deck evaluator (never ``exec``), in a namespace
holding what code_aster gives such files: ``coef_unit(expo)`` (1, or
``10**expo`` with UNITE_LONGUEUR='MM'), ``temp_eval(f)`` (``f(TEMP_EVAL)``
with EXTRACTION, else ``f``), ``coef_mult``, ``prol`` (PROL_GAUCHE /
PROL_DROITE), ``option``, ``defi_motscles``. Each factor keyword may carry
``extraction=True`` (kept only with EXTRACTION) or ``False`` (only without);
with EXTRACTION, only the behaviours named in COMPOR are kept. The remaining
keywords define the material with DEFI_MATERIAU.

FICHIER names a file of the study (an ``F nom`` line of the export).
NOM_AFNOR reads code_aster's catalogue of materials, which is installed with
code_aster and not shipped with asterlite: refused.
"""

from __future__ import annotations

from asterlite.io.input_files import read_deck_text
from asterlite.lang import Evaluator, base_namespace, parse_deck
from asterlite.lang.values import CallSite

#: commands a material file may call (code_aster's list)
FILE_COMMANDS = (
    "DEFI_LIST_REEL",
    "DEFI_FONCTION",
    "DEFI_CONSTANTE",
    "DEFI_NAPPE",
    "FORMULE",
    "CALC_FONCTION",
    "CALC_FONC_INTERP",
    "DETRUIRE",
)
EXTRACTION_FLAG = "extraction"


def _data_file(ctx, kw):
    name = str(kw["FICHIER"])
    for path in ctx.session.run.helper_modules.values():
        if path.name == name:
            return path
    ctx.error(
        f"file {name!r} is not among the study's files (add an 'F nom {name} D 0' line "
        "to the export)",
        "FICHIER",
        kw,
    )


def _context(ctx, kw) -> dict:
    extraction = kw.factor("EXTRACTION")
    temperature = float(extraction[0]["TEMP_EVAL"]) if extraction else None
    millimetres = kw.get("UNITE_LONGUEUR", "M") == "MM"
    namespace = base_namespace(print_hook=lambda text: ctx.log(text.rstrip("\n")))

    def coef_unit(expo):
        return 10.0 ** float(expo) if millimetres else 1.0

    def temp_eval(function):
        return function(temperature) if temperature is not None else function

    def defi_motscles(**keywords):
        return dict(keywords)

    namespace.update(
        coef_unit=coef_unit,
        temp_eval=temp_eval,
        defi_motscles=defi_motscles,
        coef_mult=float(kw.get("COEF_MULT", 1.0)),
        prol={"droite": kw.get("PROL_DROITE"), "gauche": kw.get("PROL_GAUCHE")},
        option=kw.get("OPTION"),
    )
    for name in FILE_COMMANDS:
        namespace[name] = ctx.session.command(name)
    return namespace


def _evaluate(ctx, path, namespace) -> dict:
    text = read_deck_text(path, "material file")
    module = parse_deck(text, str(path), private_names=True, study_file=True)
    Evaluator(namespace, module_loader=ctx.session.load_module).run(module)
    keywords = namespace.get("motscles")
    if not isinstance(keywords, dict):
        ctx.error(f"{path.name} defines no 'motscles = defi_motscles(...)'", "FICHIER")
    return keywords


def _filtered(ctx, kw, keywords: dict) -> dict:
    """The behaviours to define, as code_aster keeps them."""
    extraction = kw.factor("EXTRACTION")
    kept_behaviours = set(extraction[0]["COMPOR"]) if extraction else None
    out = {}
    for behaviour, value in keywords.items():
        if kept_behaviours is not None and behaviour not in kept_behaviours:
            continue
        occurrences = list(value) if isinstance(value, (list, tuple)) else [value]
        if len(occurrences) != 1:
            ctx.error(f"the file gives {behaviour} {len(occurrences)} times", "FICHIER", kw)
        occurrence = occurrences[0]
        flag = occurrence.get(EXTRACTION_FLAG)
        if flag is not None and bool(flag) != bool(extraction):
            continue
        if flag is not None:
            occurrence = type(occurrence)(occurrence)
            del occurrence[EXTRACTION_FLAG]
        out[behaviour] = occurrence
    return out


def run(ctx, kw):
    if kw.get("NOM_AFNOR") is not None:
        ctx.unsupported(
            "INCLUDE_MATERIAU NOM_AFNOR: code_aster's catalogue of materials is installed "
            "with code_aster, not with asterlite (give the file with FICHIER)",
            "NOM_AFNOR",
            kw,
        )
    path = _data_file(ctx, kw)
    keywords = _filtered(ctx, kw, _evaluate(ctx, path, _context(ctx, kw)))
    if kw.get("INFO") == 2:
        ctx.log(f"keywords from {path.name}: {', '.join(sorted(keywords))}")
    defi_materiau = _context_command(ctx, "DEFI_MATERIAU")
    site = CallSite(location=ctx.location, assigned_name=ctx.result_name)
    return defi_materiau.deck_call([], keywords, site)


def _context_command(ctx, name: str):
    return ctx.session.command(name)
