"""Concepts of multifibre beams: the fibre geometry (DEFI_GEOM_FIBRE) and
the behaviour of each fibre group (DEFI_COMPOR MULTIFIBRE)."""

from __future__ import annotations

from dataclasses import dataclass, field

import numpy as np

from asterlite.concepts.assembly import Material
from asterlite.concepts.base import Concept


@dataclass(eq=False)
class FibreGroup:
    """Fibres of one group: positions (y, z) in the section frame and areas."""

    y: np.ndarray
    z: np.ndarray
    area: np.ndarray


@dataclass(eq=False)
class FibreGeometry(Concept):
    """``DEFI_GEOM_FIBRE`` result: fibre groups by name, in definition order."""

    aster_types = ("gfibre_sdaster",)

    groups: dict[str, FibreGroup] = field(default_factory=dict)


@dataclass(eq=False)
class MultifibreBehaviour(Concept):
    """``DEFI_COMPOR`` MULTIFIBRE result: the material and relation of each
    fibre group, and the section material (MATER_SECT: torsion, damping)."""

    aster_types = ("compor_sdaster",)

    geometry: FibreGeometry
    section_material: Material
    group_material: dict[str, Material] = field(default_factory=dict)
    group_relation: dict[str, str] = field(default_factory=dict)
