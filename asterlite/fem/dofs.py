"""Degrees of freedom carried by each modelisation, in code_aster's component order."""

from __future__ import annotations

from asterlite.fem.pipe import node_components

#: Component order inside a node (code_aster's DEPL_R order).
COMPONENT_ORDER = ("DX", "DY", "DZ", "DRX", "DRY", "DRZ", "GRX", *node_components(6)[6:])
COMPONENT_RANK = {c: i for i, c in enumerate(COMPONENT_ORDER)}

TRANSLATIONS = ("DX", "DY", "DZ")
ROTATIONS = ("DRX", "DRY", "DRZ")

#: Components per node for each modelisation asterlite knows.
MODELISATION_COMPONENTS: dict[str, tuple[str, ...]] = {
    "DIS_T": ("DX", "DY", "DZ"),
    "DIS_TR": ("DX", "DY", "DZ", "DRX", "DRY", "DRZ"),
    "2D_DIS_T": ("DX", "DY"),
    "2D_DIS_TR": ("DX", "DY", "DRZ"),
    "POU_D_E": ("DX", "DY", "DZ", "DRX", "DRY", "DRZ"),
    "POU_D_T": ("DX", "DY", "DZ", "DRX", "DRY", "DRZ"),
    "POU_D_TG": ("DX", "DY", "DZ", "DRX", "DRY", "DRZ", "GRX"),
    "POU_D_EM": ("DX", "DY", "DZ", "DRX", "DRY", "DRZ"),
    "POU_D_TGM": ("DX", "DY", "DZ", "DRX", "DRY", "DRZ", "GRX"),
    "BARRE": ("DX", "DY", "DZ"),
    "2D_BARRE": ("DX", "DY"),
    "3D": ("DX", "DY", "DZ"),
    "D_PLAN": ("DX", "DY"),
    "C_PLAN": ("DX", "DY"),
    "AXIS": ("DX", "DY"),
    "DKT": ("DX", "DY", "DZ", "DRX", "DRY", "DRZ"),
    "3D_ABSO": ("DX", "DY", "DZ"),
    "D_PLAN_ABSO": ("DX", "DY"),
    # pipes: beam DOFs plus the Fourier terms of the ovalisation (code_aster's MET3SEG3...)
    "TUYAU_3M": node_components(3),
    "TUYAU_6M": node_components(6),
}

DISCRETE_MODELISATIONS = ("DIS_T", "DIS_TR", "2D_DIS_T", "2D_DIS_TR")

#: Cell types each modelisation accepts.
MODELISATION_CELLS: dict[str, tuple[str, ...]] = {
    "DIS_T": ("POI1", "SEG2"),
    "DIS_TR": ("POI1", "SEG2"),
    "2D_DIS_T": ("POI1", "SEG2"),
    "2D_DIS_TR": ("POI1", "SEG2"),
    "POU_D_E": ("SEG2",),
    "POU_D_T": ("SEG2",),
    "POU_D_TG": ("SEG2",),
    "POU_D_EM": ("SEG2",),
    "POU_D_TGM": ("SEG2",),
    "BARRE": ("SEG2",),
    "2D_BARRE": ("SEG2",),
    # volumes, plus the faces and edges that carry loads (code_aster's MECA_FACE*, MECA_ARETE*)
    "3D": (
        *("HEXA8", "HEXA20", "HEXA27", "PENTA6", "PENTA15", "TETRA4", "TETRA10"),
        *("PYRAM5", "PYRAM13", "TRIA3", "TRIA6", "QUAD4", "QUAD8", "QUAD9", "SEG2", "SEG3"),
    ),
    # surfaces, plus the edges that carry loads (code_aster's MEPLSE2/3, MEAXSE2/3)
    **{
        name: ("TRIA3", "TRIA6", "QUAD4", "QUAD8", "QUAD9", "SEG2", "SEG3")
        for name in ("D_PLAN", "C_PLAN", "AXIS")
    },
    # plates, plus the edges that carry loads (code_aster's MEBODKT)
    "DKT": ("TRIA3", "QUAD4", "SEG2"),
    # paraxial absorbing boundaries (code_aster's MEAB_FACE*, MEPASE*)
    "3D_ABSO": ("TRIA3", "TRIA6", "QUAD4", "QUAD8", "QUAD9"),
    "D_PLAN_ABSO": ("SEG2", "SEG3"),
    "TUYAU_3M": ("SEG3", "SEG4"),
    "TUYAU_6M": ("SEG3",),
}


def sort_components(components) -> tuple[str, ...]:
    """Components in code_aster's order (unknown names last, alphabetically)."""
    return tuple(sorted(set(components), key=lambda c: (COMPONENT_RANK.get(c, 99), c)))
