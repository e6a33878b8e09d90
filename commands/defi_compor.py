"""DEFI_COMPOR MULTIFIBRE: the material of each fibre group and the section
material (MATER_SECT: G for torsion, Rayleigh damping). asterlite computes
elastic fibres only (RELATION='ELAS')."""

from __future__ import annotations

from asterlite.concepts.fibres import MultifibreBehaviour
from asterlite.fem.selection import as_tuple


def run(ctx, kw):
    if not kw.factor("MULTIFIBRE"):
        ctx.unsupported("DEFI_COMPOR without MULTIFIBRE (crystal behaviours)", None, kw)
    geometry = kw["GEOM_FIBRE"]
    result = MultifibreBehaviour(geometry=geometry, section_material=kw["MATER_SECT"])
    for occ in kw.factor("MULTIFIBRE"):
        relation = occ.get("RELATION", "ELAS")
        if relation != "ELAS":
            ctx.unsupported(
                f"DEFI_COMPOR MULTIFIBRE RELATION={relation!r} (nonlinear fibres)", "RELATION", occ
            )
        for name in as_tuple(occ["GROUP_FIBRE"]):
            if name not in geometry.groups:
                ctx.error(f"GEOM_FIBRE has no fibre group {name!r}", "GROUP_FIBRE", occ)
            if name in result.group_material:
                ctx.error(f"the fibre group {name!r} is given twice", "GROUP_FIBRE", occ)
            result.group_material[name] = occ["MATER"]
            result.group_relation[name] = relation
    ctx.log(f"multifibre behaviour: {len(result.group_material)} fibre groups")
    return result
