"""``aster.getvectjev(name)``: a concept's vector read by its JEVEUX name.

code_aster stores each data structure as named vectors: the structure's
name padded to 19 characters, then the vector's suffix (``.VALE``...).
Decks name the structure by the deck variable (code_aster up to 14) or by
the name code_aster 15 generated for it ("0000001b", see
:mod:`asterlite.legacy.v15_names`). The vectors asterlite can rebuild are
laid out as code_aster lays them out:

- a function's ``.VALE``: the abscissas, then the ordinates (complex
  ordinates as real/imaginary pairs); a list's ``.VALE``: its values;
- a ``tran_gene``'s ``.DEPL``/``.VITE``/``.ACCE`` (the modal coordinates
  instant after instant), ``.DISC`` (instants), ``.ORDR`` (NUME_ORDRE),
  ``.PTEM`` (the step leading to each instant) and, for its nonlinearities
  (structure ``<name, 16 characters>.NL``), ``.TYPE`` (the relation's code),
  ``.VIND`` (where each one's internal variables start, from 1), ``.VINT``
  (all internal variables, instant after instant) and ``.INTI`` (title,
  node 1, node 2 and two substructure names per nonlinearity).

Any other name is refused by name.
"""

from __future__ import annotations

import numpy as np

from asterlite.concepts.base import Concept
from asterlite.concepts.function import Function
from asterlite.concepts.lists import ListInt, ListReal
from asterlite.concepts.transient import TranGene
from asterlite.errors import UnsupportedError
from asterlite.legacy.v15_names import GENERATED_NAME
from asterlite.post.deck_api import NONLINEARITY_CODES, internal_variables

STRUCTURE_WIDTH = 19  # characters of a structure's name before the vector's suffix
SUBSTRUCTURE_WIDTH = 16  # a tran_gene's nonlinearities live in "<16 chars>.NL"


def split_name(name: str) -> tuple[str, str, str]:
    """(structure, substructure, suffix) of a JEVEUX vector name:
    ``'INTEGR          .NL.VINT'`` gives ``('INTEGR', '.NL', '.VINT')``."""
    if not isinstance(name, str):
        raise UnsupportedError(f"aster.getvectjev: a name is a string, got {name!r}")
    if len(name) <= STRUCTURE_WIDTH or name[STRUCTURE_WIDTH] != ".":
        raise UnsupportedError(
            f"aster.getvectjev({name!r}): a JEVEUX vector name is the structure's name "
            "padded to 19 characters, then the suffix (e.g. 'NAME               .VALE')"
        )
    structure = name[:STRUCTURE_WIDTH]
    suffix = name[STRUCTURE_WIDTH:].strip()
    sub = structure[SUBSTRUCTURE_WIDTH:]
    if sub.startswith("."):  # a structure inside another one (".NL")
        return structure[:SUBSTRUCTURE_WIDTH].strip(), sub.strip(), suffix
    return structure.strip(), "", suffix


def find_concept(session, structure: str, quoted: str):
    """The concept a structure name stands for: a generated code_aster 15
    name, or (code_aster up to 14) the deck variable's name."""
    if GENERATED_NAME.match(structure):
        names = getattr(session, "generated_names", None)
        concept, why = names.lookup(structure) if names is not None else (None, "")
        if concept is None:
            raise UnsupportedError(
                f"aster.getvectjev({quoted!r}): {structure} is a name code_aster 15 "
                f"generates; asterlite cannot tell which concept it is ({why})"
            )
        return concept
    value = session.namespace.get(structure)
    if not isinstance(value, Concept):
        raise UnsupportedError(
            f"aster.getvectjev({quoted!r}): no concept named {structure} in the deck"
        )
    return value


def getvectjev(session, name: str) -> tuple:
    """The vector ``name`` as code_aster returns it (a tuple)."""
    structure, sub, suffix = split_name(name)
    concept = find_concept(session, structure, name)
    values = concept_vector(concept, sub, suffix)
    if values is None:
        raise UnsupportedError(
            f"aster.getvectjev({name!r}): asterlite does not rebuild the vector "
            f"{sub}{suffix} of {type(concept).__name__} {concept.name or structure} "
            f"({readable_vectors(concept)})"
        )
    return tuple(values)


def readable_vectors(concept) -> str:
    if isinstance(concept, (Function, ListReal, ListInt)):
        return "it reads .VALE"
    if isinstance(concept, TranGene):
        return "it reads .DEPL .VITE .ACCE .DISC .ORDR .PTEM .NL.TYPE .NL.VIND .NL.VINT .NL.INTI"
    return "none for this kind of concept"


def concept_vector(concept, sub: str, suffix: str):
    """The values of one vector of ``concept``, or None if not rebuilt."""

    if isinstance(concept, Function) and not sub and suffix == ".VALE":
        return concept.getValues()
    if isinstance(concept, (ListReal, ListInt)) and not sub and suffix == ".VALE":
        return concept.values.tolist()
    if isinstance(concept, TranGene):
        if not sub:
            return tran_gene_vector(concept, suffix)
        if sub == ".NL":
            return nonlinear_vector(concept, suffix)
    return None


def tran_gene_vector(result, suffix: str):
    states = {".DEPL": result.depl, ".VITE": result.vite, ".ACCE": result.acce}
    if suffix in states:
        # one block of n_modes values per archived instant
        return np.asarray(states[suffix], dtype=float).ravel().tolist()
    if suffix == ".DISC":
        return [float(t) for t in result.times]
    if suffix == ".ORDR":
        return [int(o) for o in result.order]
    if suffix == ".PTEM" and result.step_sizes is not None:
        return [float(s) for s in result.step_sizes]
    return None


def nonlinear_vector(result, suffix: str):
    shocks = result.shocks
    if not shocks:
        return None
    if suffix == ".TYPE":
        if any(s.relation not in NONLINEARITY_CODES for s in shocks):
            return None  # a relation code_aster 15 did not have
        return [NONLINEARITY_CODES[s.relation] for s in shocks]
    if suffix == ".INTI":
        return [item for s in shocks for item in (s.name, s.node_1, s.node_2 or "", "", "")]
    blocks = [internal_variables(s) for s in shocks]
    if suffix == ".VIND":
        return np.concatenate([[1], 1 + np.cumsum([b.shape[1] for b in blocks])]).tolist()
    if suffix == ".VINT":
        # per archived instant, every nonlinearity's variables in turn
        return np.hstack(blocks).ravel().tolist()
    return None
