"""AFFE_CHAR_MECA: kinematic relations (DDL_IMPO, LIAISON_DDL) and nodal loads
(FORCE_NODALE, PESANTEUR) on a model."""

from __future__ import annotations

from asterlite.concepts.assembly import LinearRelation, MechanicalLoad
from asterlite.fem.selection import as_tuple, named_nodes, node_group_members, select_nodes

_DDL_COMPONENTS = ("DX", "DY", "DZ", "DRX", "DRY", "DRZ", "GRX")
_FORCE_COMPONENTS = {"FX": "DX", "FY": "DY", "FZ": "DZ", "MX": "DRX", "MY": "DRY", "MZ": "DRZ"}
_HANDLED = ("MODELE", "DDL_IMPO", "LIAISON_DDL", "FORCE_NODALE", "PESANTEUR", "INFO", "VERI_NORM")
_ENCASTRE = ("DX", "DY", "DZ", "DRX", "DRY", "DRZ")


def _ddl_impo(ctx, model, components, load, occ) -> None:
    mesh = model.mesh
    everywhere = occ.get("TOUT") == "OUI"
    nodes = select_nodes(ctx, occ, mesh, all_nodes=list(components))
    imposed = {c: float(occ[c]) for c in _DDL_COMPONENTS if occ.get(c) is not None}
    if occ.get("LIAISON") == "ENCASTRE":
        imposed.update({c: 0.0 for c in _ENCASTRE})
        optional = set(_ENCASTRE) - {c for c in _DDL_COMPONENTS if occ.get(c) is not None}
    else:
        optional = set()
    if not imposed:
        ctx.error("no component is imposed", None, occ)
    for comp, value in imposed.items():
        applied = 0
        for node in nodes:
            carried = components.get(int(node), ())
            if comp not in carried:
                if everywhere or comp in optional:
                    continue
                ctx.error(
                    f"node {mesh.node_names[node]} has no {comp} DOF in this model",
                    comp,
                    occ,
                )
            load.relations.append(LinearRelation([(int(node), comp, 1.0)], value))
            applied += 1
        if applied == 0 and comp not in optional:
            ctx.error(f"no node of the selection carries {comp}", comp, occ)


def _liaison_ddl(ctx, model, components, load, occ) -> None:
    mesh = model.mesh
    nodes = node_group_members(ctx, occ, mesh) + named_nodes(ctx, occ, mesh)
    ddl = as_tuple(occ.get("DDL"))
    coefs = as_tuple(occ.get("COEF_MULT"))
    if not (len(nodes) == len(ddl) == len(coefs)):
        ctx.error(
            f"LIAISON_DDL needs as many nodes ({len(nodes)}), DDL ({len(ddl)}) and "
            f"COEF_MULT ({len(coefs)})",
            "DDL",
            occ,
        )
    terms = []
    for node, comp, coef in zip(nodes, ddl, coefs, strict=True):
        if comp not in components.get(int(node), ()):
            ctx.error(f"node {mesh.node_names[node]} has no {comp} DOF in this model", "DDL", occ)
        terms.append((int(node), comp, float(coef)))
    load.relations.append(LinearRelation(terms, float(occ.get("COEF_IMPO", 0.0) or 0.0)))


def _force_nodale(ctx, model, components, load, occ) -> None:
    mesh = model.mesh
    if occ.get("ANGL_NAUT") is not None:
        ctx.unsupported("FORCE_NODALE with ANGL_NAUT", "ANGL_NAUT", occ)
    nodes = select_nodes(ctx, occ, mesh, all_nodes=list(components))
    given = {k: float(occ[k]) for k in _FORCE_COMPONENTS if occ.get(k) is not None}
    if not given:
        ctx.error("no force component is given", None, occ)
    for key, value in given.items():
        comp = _FORCE_COMPONENTS[key]
        for node in nodes:
            if comp not in components.get(int(node), ()):
                ctx.error(f"node {mesh.node_names[node]} has no {comp} DOF in this model", key, occ)
            load.nodal_forces.append((int(node), comp, value))


def run(ctx, kw):
    model = kw["MODELE"]
    components = model.node_components()
    load = MechanicalLoad(model=model)
    for occ in kw.factor("DDL_IMPO"):
        _ddl_impo(ctx, model, components, load, occ)
    for occ in kw.factor("LIAISON_DDL"):
        _liaison_ddl(ctx, model, components, load, occ)
    for occ in kw.factor("FORCE_NODALE"):
        _force_nodale(ctx, model, components, load, occ)
    if kw.get("PESANTEUR"):
        occ = kw.factor("PESANTEUR")[0]
        load.extra["PESANTEUR"] = {
            "GRAVITE": float(occ["GRAVITE"]),
            "DIRECTION": tuple(float(x) for x in as_tuple(occ["DIRECTION"])),
        }
    for key, value in kw.items():
        if key not in _HANDLED and isinstance(value, list) and value:
            ctx.unsupported(f"AFFE_CHAR_MECA/{key}", key, kw)
    ctx.log(f"load: {len(load.relations)} relations, {len(load.nodal_forces)} nodal forces")
    return load
