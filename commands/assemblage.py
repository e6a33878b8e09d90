"""ASSEMBLAGE: element matrices + numbering + assembly in one command; every
result is bound to its CO(...) name."""

from __future__ import annotations

from asterlite.commands.nume_ddl import numbering_for

from asterlite.concepts.assembly import (
    AssembledMatrix,
    ComplexAssembledMatrix,
    DofNumbering,
    NodalField,
)
from asterlite.fem.assemble import assemble_blocks, assemble_terms
from asterlite.fem.elements import ElementError
from asterlite.fem.loads import load_terms
from asterlite.fem.options import COMPLEX_OPTIONS, MATRIX_KIND, OPTIONS, option_blocks
from asterlite.fem.selection import as_tuple


def run(ctx, kw):
    model = kw["MODELE"]
    characteristics = kw.get("CARA_ELEM")
    materials = kw.get("CHAM_MATER")
    loads = list(as_tuple(kw.get("CHARGE")))
    given = kw.get("NUME_DDL")
    if isinstance(given, DofNumbering):
        numbering = given
    else:
        numbering = numbering_for(model, loads, characteristics, materials)
        if given is not None:
            ctx.bind(given, numbering)
    for occ in kw.factor("MATR_ASSE"):
        option = occ["OPTION"]
        if option not in OPTIONS:
            ctx.unsupported(f"ASSEMBLAGE OPTION={option!r}", "OPTION", occ)
        try:
            blocks = option_blocks(model, characteristics, option, materials=materials)
        except NotImplementedError as exc:
            ctx.unsupported(str(exc), "MODELE", kw)
        except (ElementError, ValueError) as exc:
            ctx.error(str(exc), "CARA_ELEM", kw)
        matrix = assemble_blocks(blocks, numbering)
        is_complex = option in COMPLEX_OPTIONS
        cls = ComplexAssembledMatrix if is_complex else AssembledMatrix
        assembled = cls(
            numbering=numbering,
            matrix=matrix.astype(complex) if is_complex else matrix,
            kind=MATRIX_KIND[option],
            model=model,
            characteristics=characteristics,
            materials=materials,
        )
        ctx.bind(occ["MATRICE"], assembled)
    for occ in kw.factor("VECT_ASSE"):
        if occ.get("OPTION", "CHAR_MECA") != "CHAR_MECA":
            ctx.unsupported(f"ASSEMBLAGE VECT_ASSE OPTION={occ['OPTION']!r}", "OPTION", occ)
        terms = []
        # code_aster (assemblage_ops) assembles the call's CHARGE and the
        # occurrence's, each load once
        occurrence_loads = [c for c in as_tuple(occ.get("CHARGE")) if c not in loads]
        for load in loads + occurrence_loads:
            try:
                terms.extend(load_terms(load, characteristics, materials))
            except (ElementError, ValueError) as exc:
                ctx.error(str(exc), "CHARGE", occ)
        try:
            values = assemble_terms(terms, numbering)
        except KeyError as exc:
            ctx.error(f"load on DOFs the numbering does not have: {exc.args[0]}", "CHARGE", occ)
        ctx.bind(occ["VECTEUR"], NodalField(numbering=numbering, values=values))
    return None
