"""REST_SPEC_TEMP: a harmonic result (physical or generalized) to a
transient by inverse FFT, or a transient to a harmonic result by FFT, DOF by
DOF (asterlite.post.result_fourier holds the transforms).

The transient's orders are numbered from 0, the harmonic result's from 1
(generalized results: both from 0), as code_aster stores them. Fields:
NOM_CHAM, else (TOUT_CHAM) DEPL, VITE and ACCE; from a harmonic result,
those it holds. ACCELERATION_MPI distributes the DOFs over MPI processes in
code_aster; asterlite computes them all in one process, with the same
values."""

from __future__ import annotations

import numpy as np

from asterlite.concepts.harmonic import DynaHarmo, HarmGene
from asterlite.concepts.transient import DynaTrans, TranGene
from asterlite.post.result_fourier import frequency_to_time, time_to_frequency

FIELDS = ("DEPL", "VITE", "ACCE")


def run(ctx, kw):
    method = kw["METHODE"]
    symmetric = kw["SYMETRIE"] == "OUI"
    extra_power = int(kw.get("N_PUIS") or 0)
    # TOUT_CHAM asks for the three fields, the default; ACCELERATION_MPI only
    # shares the DOFs among processes
    kw.mark_used("TOUT_CHAM")
    kw.mark_used("ACCELERATION_MPI")
    asked = tuple(kw.get("NOM_CHAM") or ()) or FIELDS
    if kw.get("RESU_GENE") is not None:
        return _generalized(ctx, kw, kw["RESU_GENE"], asked, method, symmetric, extra_power)
    result = kw["RESULTAT"]
    common = dict(
        numbering=result.numbering,
        model=result.model,
        materials=result.materials,
        characteristics=result.characteristics,
        mass_matrix=result.mass_matrix,
    )
    options = (method, symmetric, extra_power)
    if isinstance(result, DynaHarmo):
        names = _harmonic_names(ctx, kw, result, asked)
        instants, fields = _transformed(
            ctx,
            kw,
            "RESULTAT",
            frequency_to_time,
            result.frequencies,
            result.fields,
            names,
            options,
        )
        ctx.log(
            f"REST_SPEC_TEMP: {len(result.frequencies)} frequencies -> {len(instants)} "
            f"instants, step {instants[1] - instants[0]:g} s ({', '.join(names)})"
        )
        return DynaTrans(times=instants, order=np.arange(len(instants)), fields=fields, **common)
    if not isinstance(result, DynaTrans):
        ctx.error("RESULTAT must be a dyna_harmo or a dyna_trans", "RESULTAT", kw)
    missing = [name for name in asked if name not in result.fields]
    if missing:
        ctx.error(f"the transient result has no field {missing[0]}", "NOM_CHAM", kw)
    times = np.asarray(result.times, dtype=float)
    steps = np.diff(times)
    if steps.size and np.any(np.abs(steps - steps[0]) > 1e-6 * abs(steps[0])):
        ctx.log("REST_SPEC_TEMP: the instants are not evenly spaced; the first step is used")
    stored = {name: np.asarray(result.fields[name], dtype=float) for name in asked}
    frequencies, fields = _transformed(
        ctx, kw, "RESULTAT", time_to_frequency, times, stored, asked, options
    )
    ctx.log(
        f"REST_SPEC_TEMP: {len(times)} instants -> {len(frequencies)} frequencies, "
        f"step {frequencies[1] - frequencies[0]:g} Hz ({', '.join(asked)})"
    )
    return DynaHarmo(
        frequencies=frequencies, order=np.arange(1, len(frequencies) + 1), fields=fields, **common
    )


def _generalized(ctx, kw, result, asked, method, symmetric, extra_power):
    """harm_gene -> tran_gene and back, on the same basis. As code_aster's
    ecresu: orders from 0; a field not asked for is zero in a tran_gene
    (which always holds the three) and absent from a harm_gene."""
    options = (method, symmetric, extra_power)
    if isinstance(result, HarmGene):
        names = _harmonic_names(ctx, kw, result, asked)
        instants, fields = _transformed(
            ctx,
            kw,
            "RESU_GENE",
            frequency_to_time,
            result.frequencies,
            result.fields,
            names,
            options,
        )
        zero = np.zeros_like(next(iter(fields.values())))
        ctx.log(
            f"REST_SPEC_TEMP: {len(result.frequencies)} frequencies -> {len(instants)} "
            f"instants ({', '.join(names)})"
        )
        return TranGene(
            basis=result.basis,
            times=instants,
            order=np.arange(len(instants)),
            depl=fields.get("DEPL", zero),
            vite=fields.get("VITE", zero),
            acce=fields.get("ACCE", zero),
            step=float(instants[1] - instants[0]),
            info={"source": "REST_SPEC_TEMP"},
        )
    if not isinstance(result, TranGene):
        ctx.error("RESU_GENE must be a harm_gene or a tran_gene", "RESU_GENE", kw)
    stored = {"DEPL": result.depl, "VITE": result.vite, "ACCE": result.acce}
    stored = {name: np.asarray(stored[name], dtype=float) for name in asked}
    frequencies, fields = _transformed(
        ctx, kw, "RESU_GENE", time_to_frequency, result.times, stored, asked, options
    )
    ctx.log(
        f"REST_SPEC_TEMP: {len(result.times)} instants -> {len(frequencies)} frequencies "
        f"({', '.join(asked)})"
    )
    return HarmGene(
        basis=result.basis,
        numbering=getattr(result, "numbering", None),
        frequencies=frequencies,
        order=np.arange(len(frequencies)),
        fields=fields,
    )


def _harmonic_names(ctx, kw, result, asked) -> list[str]:
    """The fields asked for that the harmonic result holds (an error if none)."""
    names = [name for name in asked if name in result.fields]
    if not names:
        ctx.error(
            f"the harmonic result holds none of the fields {', '.join(asked)}", "NOM_CHAM", kw
        )
    return names


def _transformed(ctx, kw, keyword, transform, abscissa, stored, names, options):
    """The fields ``names`` of ``stored`` through ``transform``
    (frequency_to_time or time_to_frequency) over ``abscissa``: (the new
    abscissa, the fields); a transform's refusal is an error at ``keyword``."""
    abscissa = np.asarray(abscissa, dtype=float)
    fields, out = {}, None
    for name in names:
        try:
            out, fields[name] = transform(abscissa, stored[name], *options)
        except ValueError as exc:
            ctx.error(str(exc), keyword, kw)
    return out, fields
