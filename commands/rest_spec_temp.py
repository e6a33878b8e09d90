"""REST_SPEC_TEMP: a physical harmonic result to a transient by inverse FFT,
or a transient to a harmonic result by FFT, DOF by DOF
(asterlite.post.result_fourier holds the transforms).

The transient's orders are numbered from 0, the harmonic result's from 1, as
code_aster stores them. Fields: NOM_CHAM, else (TOUT_CHAM) DEPL, VITE and
ACCE; from a harmonic result, those it holds. ACCELERATION_MPI distributes
the DOFs over MPI processes in code_aster; asterlite computes them all in
one process, with the same values."""

from __future__ import annotations

import numpy as np

from asterlite.concepts.harmonic import DynaHarmo
from asterlite.concepts.transient import DynaTrans
from asterlite.post.result_fourier import frequency_to_time, time_to_frequency

FIELDS = ("DEPL", "VITE", "ACCE")


def run(ctx, kw):
    if kw.get("RESU_GENE") is not None:
        ctx.unsupported("REST_SPEC_TEMP of a generalized result (RESU_GENE)", "RESU_GENE", kw)
    result = kw["RESULTAT"]
    method = kw["METHODE"]
    symmetric = kw["SYMETRIE"] == "OUI"
    extra_power = int(kw.get("N_PUIS") or 0)
    # TOUT_CHAM asks for the three fields, the default; ACCELERATION_MPI only
    # shares the DOFs among processes
    kw.mark_used("TOUT_CHAM")
    kw.mark_used("ACCELERATION_MPI")
    asked = tuple(kw.get("NOM_CHAM") or ()) or FIELDS
    common = dict(
        numbering=result.numbering,
        model=result.model,
        materials=result.materials,
        characteristics=result.characteristics,
        mass_matrix=result.mass_matrix,
    )
    if isinstance(result, DynaHarmo):
        names = [name for name in asked if name in result.fields]
        if not names:
            ctx.error(
                f"the harmonic result holds none of the fields {', '.join(asked)}",
                "NOM_CHAM",
                kw,
            )
        fields, instants = {}, None
        for name in names:
            try:
                instants, fields[name] = frequency_to_time(
                    np.asarray(result.frequencies, dtype=float),
                    result.fields[name],
                    method,
                    symmetric,
                    extra_power,
                )
            except ValueError as exc:
                ctx.error(str(exc), "RESULTAT", kw)
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
    fields, frequencies = {}, None
    for name in asked:
        try:
            frequencies, fields[name] = time_to_frequency(
                times,
                np.asarray(result.fields[name], dtype=float),
                method,
                symmetric,
                extra_power,
            )
        except ValueError as exc:
            ctx.error(str(exc), "RESULTAT", kw)
    ctx.log(
        f"REST_SPEC_TEMP: {len(times)} instants -> {len(frequencies)} frequencies, "
        f"step {frequencies[1] - frequencies[0]:g} Hz ({', '.join(asked)})"
    )
    return DynaHarmo(
        frequencies=frequencies, order=np.arange(1, len(frequencies) + 1), fields=fields, **common
    )
