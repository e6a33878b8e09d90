"""Nonlinearities of DYNA_VIBRA on the nodes of substructures.

With SOUS_STRUC_1/2 (SOUS_STRUC for the other relations) the nodes are
looked up in the substructures' own meshes; their coordinates and mode
shapes are seen in the global frame (:func:`restitution.global_view`).
REPERE names a substructure whose frame ORIG_OBST (a point) and
NORM_OBST (a direction) are given in; GLOBAL leaves them as they are."""

from __future__ import annotations

import numpy as np

from asterlite.concepts.substructure import SubstructuredNumbering
from asterlite.substructure.restitution import global_view


class SubstructureError(ValueError):
    """A substructure name the generalized model does not have."""

    def __init__(self, message: str, keyword: str):
        super().__init__(message)
        self.keyword = keyword


def coupled_model(modes):
    """The generalized model behind the modes of a transient, or None."""
    numbering = getattr(modes, "numbering", None)
    if isinstance(numbering, SubstructuredNumbering):
        return numbering.model
    return None


def substructure_view(modes, name: str, keyword: str):
    """The modes seen on substructure ``name`` in the global frame."""
    model = coupled_model(modes)
    if model is None:
        raise SubstructureError(
            f"{keyword} needs a basis computed on a generalized model (DEFI_MODELE_GENE)",
            keyword,
        )
    if model.find(name) is None:
        raise SubstructureError(f"no substructure {name!r} in the generalized model", keyword)
    return global_view(modes, name)


def in_global_frame(modes, repere: str, point=None, direction=None):
    """(point, direction) given in the frame of substructure ``repere``, in
    the global frame (None stays None)."""
    if repere == "GLOBAL":
        return point, direction
    model = coupled_model(modes)
    sub = None if model is None else model.find(repere)
    if sub is None:
        raise SubstructureError(f"REPERE {repere!r} is not a substructure of the model", "REPERE")
    if point is not None:
        point = sub.to_global(np.asarray(point, dtype=float)[None, :])[0]
    if direction is not None:
        direction = sub.rotation @ np.asarray(direction, dtype=float)
    return point, direction
