"""GENE_FONC_ALEA: time signals drawn from a spectral matrix.

code_aster's op0118 algorithm (see asterlite.post.spectral): sampling of the
matrix on the generation grid, factorization frequency by frequency, random
phases from the deck's random stream (Python's generator seeded with 0 at
the first draw of the deck, or with INIT_ALEA), inverse FFT; NB_TIRAGE
draws are concatenated after a first value 0 at t = 0. The result is an
``interspectre`` of time signals (NUME_ORDRE 1..dim) for RECU_FONCTION.
"""

from __future__ import annotations

import numpy as np

from asterlite.concepts.interspectrum import InterSpectrum
from asterlite.post import spectral


def run(ctx, kw):
    inter = kw["INTE_SPEC"]
    if kw.get("NUME_VITE_FLUI") is not None:
        ctx.unsupported(
            "GENE_FONC_ALEA NUME_VITE_FLUI (fluid-elastic spectra)", "NUME_VITE_FLUI", kw
        )
    if inter.abscissa != "FREQ":
        ctx.error("INTE_SPEC must be a spectral matrix of frequency", "INTE_SPEC", kw)
    if inter.keyed_by_nodes:
        ctx.unsupported("GENE_FONC_ALEA of a matrix keyed by nodes", "INTE_SPEC", kw)
    _check_triangle(ctx, kw, inter)
    interpolate = kw["INTERPOL"] == "OUI"
    duree = kw.get("DUREE_TIRAGE")
    try:
        grid = spectral.generation_grid(
            inter.disc,
            interpolate,
            kw.get("FREQ_INIT"),
            kw.get("FREQ_FIN"),
            kw.get("NB_POIN"),
            -1.0 if duree is None else duree,
        )
        if not spectral.is_power_of_two(grid.frequencies.size):
            ctx.error(
                f"the generation needs a power of two of frequencies, not {grid.frequencies.size}",
                "NB_POIN",
                kw,
            )
        matrices = spectral.sampled_matrix(inter, grid, interpolate)
        factors = np.array([spectral.factor(m) for m in matrices])
    except ValueError as exc:
        ctx.error(str(exc), "INTE_SPEC", kw)
    for warning in grid.warnings:
        ctx.log(f"<A> {warning}")
    phases = spectral.deck_phases(ctx.session, kw.get("INIT_ALEA"))
    signals = spectral.generate(factors, grid.stored_frequencies(), int(kw["NB_TIRAGE"]), phases)
    ctx.log(
        f"time step {signals.dt:.4e}, from 0 to {signals.times[-1]:.4e}, "
        f"{signals.n_fft} FFT points, {signals.values.shape[0]} signals"
    )
    dim = signals.values.shape[0]
    return InterSpectrum(
        "INST",
        signals.times,
        keys=list(range(1, dim + 1)),
        values=[signals.values[k].copy() for k in range(dim)],
        title=kw.get("TITRE", ""),
    )


def _check_triangle(ctx, kw, inter) -> None:
    numbers = inter.order_numbers()
    if numbers != list(range(1, len(numbers) + 1)):
        ctx.error(f"order numbers must run 1..n, found {numbers}", "INTE_SPEC", kw)
    needed = {(i, j) for j in numbers for i in numbers if i <= j}
    if set(inter.keys) != needed:
        missing = sorted(needed - set(inter.keys))
        ctx.error(
            f"the upper triangle of the matrix is incomplete (missing {missing})", "INTE_SPEC", kw
        )
