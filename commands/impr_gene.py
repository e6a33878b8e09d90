"""IMPR_GENE: print generalized results as text (FORMAT='RESULTAT', unit 8).

For each GENE occurrence:

- a ``tran_gene``: the generalized fields (NOM_CHAM, DEPL/VITE/ACCE by
  default) at the chosen archived instants (TOUT_ORDRE / TOUT_INST by
  default, NUME_ORDRE, LIST_ORDRE, INST, LIST_INST), one line per
  generalized component (NUME_CMP_GENE restricts them);
- a ``harm_gene``: the complex generalized fields at the chosen frequencies
  (NUME_ORDRE, LIST_ORDRE, FREQ, LIST_FREQ; all by default), one line per
  component with its real and imaginary parts;
- a ``vect_asse_gene``: its components (one state: TOUT_ORDRE and TOUT_CHAM
  change nothing);
- a ``mode_gene``: each mode (NUME_MODE / TOUT_MODE) with its frequency and
  generalized vector.

INFO_GENE='OUI' adds a header describing the result (modes, instants,
scheme); INFO_CMP_GENE='OUI' the frequency of the basis mode of each
component.
"""

from __future__ import annotations

import numpy as np

from asterlite.concepts.harmonic import HarmGene
from asterlite.concepts.modes import GeneralizedModes, GeneralizedVector
from asterlite.concepts.transient import TranGene
from asterlite.io.tables import fortran_real, write_lines
from asterlite.post.harmonic import selection_from_keywords as frequency_selection
from asterlite.post.restitution import FIELDS, as_tuple, selection_from_keywords

RULE = " " + "=" * 78
REAL = "E21.14"


def run(ctx, kw):
    path = ctx.session.output_path(int(kw.get("UNITE", 8)))
    lines: list[str] = []
    for occ in kw.factor("GENE"):
        lines.extend(occurrence_lines(ctx, occ))
    write_lines(path, lines)  # text units accumulate, as for IMPR_TABLE
    ctx.log(f"IMPR_GENE: {len(lines)} lines written to {path.name}")


def occurrence_lines(ctx, occ) -> list[str]:
    result = occ["RESU_GENE"]

    if isinstance(result, HarmGene):
        lines = [RULE, f" RESULTAT GENERALISE {result.name or ''} ({result.aster_type})"]
        return lines + harm_gene_lines(ctx, occ, result)
    if occ.get("FREQ") is not None or occ.get("LIST_FREQ") is not None:
        ctx.unsupported("access by FREQ (harmonic results)", "FREQ", occ)
    if occ.get("NOM_PARA") is not None and not isinstance(result, GeneralizedModes):
        ctx.unsupported("NOM_PARA in IMPR_GENE (mode_gene only)", "NOM_PARA", occ)
    lines = [RULE, f" RESULTAT GENERALISE {result.name or ''} ({result.aster_type})"]
    if occ.get("SOUS_TITRE"):
        lines.append(f" {occ['SOUS_TITRE']}")
    if isinstance(result, TranGene):
        return lines + tran_gene_lines(ctx, occ, result)
    if isinstance(result, GeneralizedVector):
        return lines + vector_lines(ctx, occ, result)
    if isinstance(result, GeneralizedModes):
        return lines + mode_gene_lines(ctx, occ, result)
    ctx.unsupported(f"IMPR_GENE of a {result.aster_type}", "RESU_GENE", occ)


def chosen_components(ctx, occ, count: int) -> np.ndarray:
    """0-based generalized components of NUME_CMP_GENE (all by default)."""
    numbers = as_tuple(occ.get("NUME_CMP_GENE"))
    every = occ.get("TOUT_CMP_GENE")
    if every == "NON":  # code_aster prints no component then
        return np.zeros(0, dtype=int)
    if not numbers or every == "OUI":
        return np.arange(count)
    bad = [n for n in numbers if not 1 <= int(n) <= count]
    if bad:
        ctx.error(f"NUME_CMP_GENE {bad[0]} outside 1..{count}", "NUME_CMP_GENE", occ)
    return np.asarray(numbers, dtype=int) - 1


def component_lines(values, components, frequencies=None) -> list[str]:
    header = " NUME_CMP_GENE                 VALEUR"
    if frequencies is not None:
        header += "              FREQ_MODE"
    lines = [header]
    for c in components:
        line = f" {c + 1:13d} {fortran_real(float(values[c]) + 0.0, REAL)}"
        if frequencies is not None:
            line += f" {fortran_real(float(frequencies[c]), REAL)}"
        lines.append(line)
    return lines


def tran_gene_lines(ctx, occ, result: TranGene) -> list[str]:
    if occ.get("NUME_MODE") is not None or occ.get("TOUT_MODE") is not None:
        ctx.error("NUME_MODE / TOUT_MODE apply to mode_gene results", "NUME_MODE", occ)
    fields = FIELDS
    if occ.get("NOM_CHAM") is not None and occ.get("TOUT_CHAM") != "OUI":
        fields = tuple(dict.fromkeys(as_tuple(occ["NOM_CHAM"])))
        other = [f for f in fields if f not in FIELDS]
        if other:
            ctx.unsupported(f"NOM_CHAM={other[0]!r} (DEPL, VITE, ACCE)", "NOM_CHAM", occ)
    selection = selection_from_keywords(ctx, occ, result.times, result.order)
    components = chosen_components(ctx, occ, result.n_modes)
    frequencies = result.basis.frequencies if occ.get("INFO_CMP_GENE") == "OUI" else None
    lines = info_lines(result) if occ.get("INFO_GENE") == "OUI" else []
    for field in fields:
        states = selection.apply(getattr(result, field.lower()))
        for k, instant in enumerate(selection.times):
            lines.append(" " + "-" * 78)
            lines.append(f" CHAMP GENERALISE {field}")
            archived = selection.weight[k] == 0.0
            order = result.order[selection.lower[k]] if archived else selection.order[k]
            lines.append(
                f" NUMERO D'ORDRE: {int(order):8d} "
                f"INST: {fortran_real(float(instant), 'E12.5').strip()}"
            )
            lines.extend(component_lines(states[k], components, frequencies))
    return lines


def info_lines(result: TranGene) -> list[str]:
    info = result.info
    text = [
        f" BASE MODALE: {result.basis.name or ''} ({result.n_modes} modes)",
        f" INSTANTS ARCHIVES: {len(result.times)}"
        + (f" de {result.times[0]:g} a {result.times[-1]:g}" if len(result.times) else ""),
        f" SCHEMA: {result.scheme} PAS: {fortran_real(float(result.step), 'E12.5').strip()}",
    ]
    if "steps" in info:
        text.append(f" PAS CALCULES: {info['steps']}  PAS REJETES: {info.get('rejected_steps', 0)}")
    if result.shocks:
        text.append(f" NON-LINEARITES: {', '.join(s.name for s in result.shocks)}")
    return text


def harm_gene_lines(ctx, occ, result) -> list[str]:
    """The fields of a harm_gene at the chosen frequencies (code_aster's irgene
    / irvgen: real and imaginary parts of each generalized component)."""

    if occ.get("NUME_MODE") is not None or occ.get("TOUT_MODE") is not None:
        ctx.error("NUME_MODE / TOUT_MODE apply to mode_gene results", "NUME_MODE", occ)
    fields = tuple(result.fields)
    if occ.get("NOM_CHAM") is not None and occ.get("TOUT_CHAM") != "OUI":
        fields = tuple(dict.fromkeys(as_tuple(occ["NOM_CHAM"])))
        missing = [f for f in fields if f not in result.fields]
        if missing:
            ctx.error(f"{result.name or ''} has no field {missing[0]}", "NOM_CHAM", occ)
    occ.mark_used("TOUT_CHAM")  # 'OUI': every field, the default
    selection = frequency_selection(ctx, occ, result.frequencies, result.order)
    rows = np.asarray(selection.lower, dtype=int)
    components = chosen_components(ctx, occ, int(result.n_modes))
    lines = []
    for field in fields:
        values = np.asarray(result.fields[field])
        for row in rows:
            lines.append(" " + "-" * 78)
            lines.append(f" VECTEUR GENERALISE DE NOM SYMBOLIQUE  {field}")
            frequency = fortran_real(float(result.frequencies[row]), "E12.5").strip()
            lines.append(f" NUMERO D'ORDRE: {int(result.order[row]):8d} FREQUENCE: {frequency}")
            lines.append(" NUME_CMP          VALEUR")
            for c in components:
                z = complex(values[row, c])
                lines.append(
                    f"   {c + 1:5d}   {fortran_real(z.real + 0.0, 'E12.5')} "
                    f"{fortran_real(z.imag + 0.0, 'E12.5')}"
                )
    return lines


def vector_lines(ctx, occ, vector: GeneralizedVector) -> list[str]:
    # one vector, one state: TOUT_ORDRE / TOUT_CHAM ('OUI') select all there is
    occ.mark_used("TOUT_ORDRE", "TOUT_CHAM")
    values = np.asarray(vector.values, dtype=float).ravel()
    if getattr(vector.numbering, "model", None) is not None:
        return substructured_vector_lines(occ, vector, values)
    components = chosen_components(ctx, occ, values.size)
    frequencies = None
    if occ.get("INFO_CMP_GENE") == "OUI":
        frequencies = vector.basis.frequencies
    return [f" VECTEUR GENERALISE ({vector.kind})"] + component_lines(
        values, components, frequencies
    )


def substructured_vector_lines(occ, vector, values) -> list[str]:
    """A vector of a generalized model: its substructures' unknowns (code_aster
    skips the Lagrange multipliers and the NUME_CMP_GENE beyond them);
    INFO_CMP_GENE gives each one's mode frequency in its substructure's basis."""
    numbers = as_tuple(occ.get("NUME_CMP_GENE"))
    components = np.arange(values.size)
    if occ.get("TOUT_CMP_GENE") == "NON":
        components = np.zeros(0, dtype=int)
    elif numbers:
        components = np.array([int(n) - 1 for n in numbers if 1 <= int(n) <= values.size])
    frequencies = None
    if occ.get("INFO_CMP_GENE") == "OUI":
        subs = vector.numbering.model.substructures
        frequencies = np.concatenate([s.macro.basis.frequencies for s in subs])
    return [f" VECTEUR GENERALISE ({vector.kind})"] + component_lines(
        values, components, frequencies
    )


def mode_gene_lines(ctx, occ, modes: GeneralizedModes) -> list[str]:
    numbers = [int(n) for n in modes.mode_numbers]
    wanted = as_tuple(occ.get("NUME_MODE")) or as_tuple(occ.get("NUME_ORDRE"))
    if wanted and occ.get("TOUT_MODE") != "OUI":
        missing = [n for n in wanted if int(n) not in numbers]
        if missing:
            ctx.error(f"mode {missing[0]} is not stored (modes {numbers})", "NUME_MODE", occ)
        picked = [numbers.index(int(n)) for n in wanted]
    else:
        picked = list(range(modes.n_modes))
    if getattr(modes.numbering, "model", None) is not None:  # substructured: no Lagrange
        count = modes.vectors.shape[0]
        numbers_cmp = as_tuple(occ.get("NUME_CMP_GENE"))
        components = np.array([int(n) - 1 for n in numbers_cmp if 1 <= int(n) <= count])
        if not numbers_cmp or occ.get("TOUT_CMP_GENE") == "OUI":
            components = np.arange(count)
    else:
        components = chosen_components(ctx, occ, modes.vectors.shape[0])
    if occ.get("TOUT_CMP_GENE") == "NON":
        components = np.zeros(0, dtype=int)
    names = parameter_names(ctx, occ, modes)
    with_vector = occ.get("TOUT_CHAM") != "NON"
    frequencies = component_frequencies(modes) if occ.get("INFO_CMP_GENE") == "OUI" else None
    if not with_vector:
        occ.mark_used("NOM_CHAM")
    lines = []
    if occ.get("INFO_GENE") == "OUI":
        lines.append(f" MODES GENERALISES: {modes.n_modes} modes, {modes.vectors.shape[0]} DDL")
    for k in picked:
        lines.append(" " + "-" * 78)
        lines.append(
            f" NUME_MODE: {numbers[k]:8d} FREQ: "
            f"{fortran_real(float(modes.frequencies[k]), 'E12.5').strip()}"
        )
        for name in names:  # NOM_PARA / TOUT_PARA: one line per parameter
            value = np.asarray(modes.parameters[name])[k]
            text = fortran_real(float(value), REAL) if np.isreal(value) else str(value)
            lines.append(f" {name:<16s} {text}")
        if with_vector:
            lines.extend(component_lines(modes.vectors[:, k], components, frequencies))
    return lines


def component_frequencies(modes) -> np.ndarray:
    """The frequency of the basis vector behind each generalized unknown."""
    numbering = modes.numbering
    model = getattr(numbering, "model", None)
    if model is not None:
        return np.concatenate([s.macro.basis.frequencies for s in model.substructures])
    return np.asarray(numbering.basis.frequencies)


def parameter_names(ctx, occ, modes) -> list[str]:
    """The parameters NOM_PARA names (all with TOUT_PARA='OUI', none by default)."""
    if occ.get("TOUT_PARA") == "OUI":
        return [k for k, v in modes.parameters.items() if np.ndim(v) == 1]
    names = list(as_tuple(occ.get("NOM_PARA")))
    missing = [n for n in names if n not in modes.parameters]
    if missing:
        ctx.error(f"the modes have no parameter {missing[0]}", "NOM_PARA", occ)
    return names
