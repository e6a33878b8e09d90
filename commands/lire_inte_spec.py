"""LIRE_INTE_SPEC: a spectral matrix read from a text file (FORMAT='ASTER').

The file gives ``DIM = n`` and then, for each term of the upper triangle in
row order (I = 1, J = 1..n; I = 2, J = 2..n; ...), a ``FONCTION_C`` block
with ``I =``, ``J =`` and ``VALEUR =`` followed by triples (frequency, then
real and imaginary parts, or modulus and phase in radians, as code_aster's
macro reads them) up to ``FINSF``.
The terms go to DEFI_INTE_SPEC as code_aster's macro passes them, so only
their values count: NOM_PARA, NOM_RESU, INTERPOL and PROL_* shape the
intermediate functions and do not reach the matrix.
"""

from __future__ import annotations

import re

import numpy as np
from asterlite.commands.defi_inte_spec import is_diagonal, stored_values

from asterlite.concepts.interspectrum import InterSpectrum
from asterlite.io.input_files import InputFileError, read_bounded_text
from asterlite.io.non_finite import finite_float


def run(ctx, kw):
    if kw["FORMAT"] != "ASTER":
        ctx.unsupported("LIRE_INTE_SPEC FORMAT='IDEAS' (dataset 58 files)", "FORMAT", kw)
    kw.mark_used("NOM_PARA", "NOM_RESU", "INTERPOL", "PROL_DROITE", "PROL_GAUCHE")
    try:
        path = ctx.session.input_path(kw["UNITE"])
        # rows of Python floats: about 30 bytes of memory per byte of text
        text = read_bounded_text(path, "inter-spectrum file", 30)
    except (KeyError, LookupError, OSError, InputFileError) as exc:
        ctx.error(f"no readable file on logical unit {kw['UNITE']} ({exc})", "UNITE", kw)
    try:
        keys, abscissas, values = parse_aster_interspectrum(text, kw["FORMAT_C"])
    except ValueError as exc:
        ctx.error(f"{path.name}: {exc}", "UNITE", kw)
    return InterSpectrum("FREQ", abscissas[-1], keys, values, title=kw.get("TITRE", ""))


def parse_aster_interspectrum(text: str, format_c: str):
    """(keys, abscissas of each term, stored values of each term)."""
    head, *blocks = text.split("FONCTION_C")
    match = re.search(r"DIM\s*=\s*(\d+)", head)
    if match is None:
        raise ValueError("no 'DIM = n' line before the first FONCTION_C")
    dim = int(match.group(1))
    expected = [(i, j) for i in range(1, dim + 1) for j in range(i, dim + 1)]
    if len(blocks) != len(expected):
        raise ValueError(
            f"DIM = {dim} needs {len(expected)} FONCTION_C blocks, found {len(blocks)}"
        )
    keys, abscissas, values = [], [], []
    start = len(head) + len("FONCTION_C")  # where each block starts in the text
    for block, key in zip(blocks, expected, strict=True):
        found = (_integer(block, "I"), _integer(block, "J"))
        if found != key:
            raise ValueError(f"terms must come in row order: expected I, J = {key}, found {found}")
        triples = _triples(block, key, text, start)
        start += len(block) + len("FONCTION_C")
        if format_c == "MODULE_PHASE":
            ordinates = triples[:, 1] * np.cos(triples[:, 2]) + 1j * (
                triples[:, 1] * np.sin(triples[:, 2])
            )
        else:
            ordinates = triples[:, 1] + 1j * triples[:, 2]
        keys.append(key)
        abscissas.append(triples[:, 0])
        values.append(stored_values(ordinates, is_diagonal(key)))
    for key, absc in zip(keys, abscissas, strict=True):
        if np.any(np.diff(absc) <= 0):  # DEFI_FONCTION's VERIF='CROISSANT'
            raise ValueError(f"term {key}: frequencies must increase strictly")
    sizes = {a.size for a in abscissas}
    if len(sizes) > 1:
        raise ValueError("every term must have the same number of points")
    return keys, abscissas, values


def _integer(block: str, name: str) -> int:
    match = re.search(rf"^\s*{name}\s*=\s*(-?\d+)", block, re.MULTILINE)
    if match is None:
        raise ValueError(f"a FONCTION_C block has no '{name} =' line")
    return int(match.group(1))


def _triples(block: str, key, text: str, block_start: int) -> np.ndarray:
    """The (frequency, value, value) triples of one term; a token that is not a
    finite number (``nan``, ``1.#QNAN``, a word) is refused at its line of
    ``text`` (where the block starts at ``block_start``)."""
    start = block.find("VALEUR =")
    end = block.find("FINSF")
    if start < 0 or end < 0:
        raise ValueError(f"term {key}: no 'VALEUR =' ... 'FINSF'")
    values_start = start + len("VALEUR =")
    numbers = []
    for match in re.finditer(r"\S+", block[values_start:end]):
        at = values_start + match.start()
        try:
            numbers.append(finite_float(match.group()))
        except ValueError as error:  # NonFiniteNumber names the token, else not shown
            line = text.count("\n", 0, block_start + at) + 1
            raise ValueError(f"line {line}: term {key}: {error}") from None
    if len(numbers) % 3 or not numbers:
        raise ValueError(f"term {key}: values must come in triples")
    return np.array(numbers).reshape(-1, 3)
