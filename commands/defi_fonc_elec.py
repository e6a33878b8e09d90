"""DEFI_FONC_ELEC: mu0 i1(t) i2(t) / (2 pi) for short-circuit currents, the
function of INST (NOM_RESU='ELEC') that multiplies a FORCE_ELEC load.

Each current is a 50 Hz (FREQ) wave with its decaying offset:
``i(t) = sqrt(2) I (cos(w tau + phi) - exp(-tau / T) cos phi)`` from the
start ``tau = 0`` of the short circuit, so that the product is
``4e-7 I1 I2 (cos(w tau + phi1) - e1 cos phi1)(cos(w tau + phi2) - e2 cos phi2)``
(SIGNAL='COMPLET'), or, averaged over a period (SIGNAL='CONTINU'),
``4e-7 I1 I2 (exp(-tau (1/T1 + 1/T2)) cos phi1 cos phi2 + cos(phi2 - phi1) / 2)``.

As code_aster's macro-command builds it, the function is tabulated every
1 / (40 FREQ) over each COUR occurrence from INST_CC_INIT (the last
instant before INST_CC_FIN), linear in between and constant outside. An
occurrence that starts where the first one ends continues the first one's
wave (tau keeps counting from the first start); any other starts a new short
circuit (tau from its INST_CC_INIT), with a zero at the previous end. The
table ends with a zero two steps after its last instant. (COUR_PRIN and
INTC_CC_*, which code_aster 17 cannot compute, are not in asterlite's
catalogue: see asterlite.catalogues.defi_fonc_elec.)
"""

from __future__ import annotations

from math import cos, exp, pi

import numpy as np

from asterlite.concepts.function import Function

#: mu0 / (2 pi) times 2: the currents are given by their RMS values I
_COEF = 4.0e-7
#: code_aster's tolerance on "this occurrence starts where the first ends"
_SAME_INSTANT = 1.0e-7


def _complete(t, i1, i2, freq, start, phi1, phi2, tau1, tau2) -> float:
    omega_t = 2 * pi * freq * (t - start)
    a1, a2 = phi1 * pi / 180.0, phi2 * pi / 180.0
    value = _COEF * i1 * i2
    value = value * (cos(omega_t + a1) - exp(-(t - start) / tau1) * cos(a1))
    return value * (cos(omega_t + a2) - exp(-(t - start) / tau2) * cos(a2))


def _averaged(t, i1, i2, start, phi1, phi2, tau1, tau2) -> float:
    a1, a2 = phi1 * pi / 180.0, phi2 * pi / 180.0
    decay = exp(-(t - start) * (1.0 / tau1 + 1.0 / tau2)) * cos(a1) * cos(a2)
    return _COEF * i1 * i2 * (decay + 0.5 * cos(a2 - a1))


def run(ctx, kw):
    freq = float(kw.get("FREQ", 50.0))
    if freq <= 0.0:
        ctx.error("FREQ must be positive", "FREQ", kw)
    averaged = kw.get("SIGNAL", "COMPLET") == "CONTINU"
    step = 1.0 / (40.0 * freq)
    occurrences = kw.factor("COUR")
    times: list[float] = []
    values: list[float] = []
    first_end = float(occurrences[0]["INST_CC_FIN"])
    start = float(occurrences[0]["INST_CC_INIT"])
    for rank, occ in enumerate(occurrences):
        begin, end = float(occ["INST_CC_INIT"]), float(occ["INST_CC_FIN"])
        for key in ("TAU_CC_1", "TAU_CC_2"):
            if float(occ[key]) == 0.0:
                ctx.error(f"{key} is zero: the offset's time constant divides", key, occ)
        if rank > 0 and abs(begin - first_end) >= _SAME_INSTANT:
            # a new short circuit: its own time origin, a zero where the last one ended
            start = begin
            times.append(first_end)
            values.append(0.0)
            first_end = end
        # code_aster's sampling: numpy.arange of the count, scaled, shifted
        instants = (np.arange((end - begin) / step) * step + begin).tolist()
        args = (
            float(occ["INTE_CC_1"]),
            float(occ["INTE_CC_2"]),
            start,
            float(occ["PHI_CC_1"]),
            float(occ["PHI_CC_2"]),
            float(occ["TAU_CC_1"]),
            float(occ["TAU_CC_2"]),
        )
        times += instants
        if averaged:
            values += [_averaged(t, *args) for t in instants]
        else:
            values += [_complete(t, *args[:2], freq, *args[2:]) for t in instants]
    if not times:
        ctx.error("COUR gives no instant: INST_CC_FIN must follow INST_CC_INIT", "COUR", kw)
    times.append(times[-1] + 2 * step)
    values.append(0.0)
    x = np.asarray(times)
    if np.any(np.diff(x) <= 0.0):
        i = int(np.argmax(np.diff(x) <= 0.0))
        ctx.error(
            f"the instants of COUR do not increase ({x[i]:g} then {x[i + 1]:g}): the "
            "occurrences must follow one another in time",
            "COUR",
            kw,
        )
    return Function(
        x,
        np.asarray(values),
        NOM_PARA="INST",
        NOM_RESU="ELEC",
        INTERPOL=("LIN", "LIN"),
        PROL_GAUCHE="CONSTANT",
        PROL_DROITE="CONSTANT",
    )
