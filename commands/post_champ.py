"""POST_CHAMP EXTR_COQUE: a copy of a result whose plate fields on layers
(SIEF_ELGA, SIGM_ELNO of DKT cells: 3 sub-points per layer, bottom, middle,
top) are replaced by their values on one layer (NUME_COUCHE) and level
(NIVE_COUCHE), without sub-points. Other extractions are refused by name."""

from __future__ import annotations

import copy

from asterlite.concepts.assembly import ElementField
from asterlite.post.restitution import as_tuple

_LEVELS = {"INF": 0, "MOY": 1, "SUP": 2}


def run(ctx, kw):
    for other in ("EXTR_TUYAU", "EXTR_PMF", "MIN_MAX_SP", "COQU_EXCENT"):
        if kw.factor(other):
            ctx.unsupported(f"POST_CHAMP {other}", other, kw)
    for selection in ("NUME_ORDRE", "INST", "FREQ", "GROUP_MA"):
        if kw.get(selection) is not None:
            ctx.unsupported(f"POST_CHAMP {selection} (every order and cell is kept)", selection, kw)
    kw.mark_used("TOUT_ORDRE")
    kw.mark_used("TOUT")
    occ = kw.factor("EXTR_COQUE")[0]
    source = kw["RESULTAT"]
    fields = getattr(source, "element_fields", None) or {}
    result = copy.copy(source)
    result.name = None
    result.element_fields = {}
    result.node_fields = {}
    layer = int(occ.get("NUME_COUCHE", 1))
    level = _LEVELS[occ.get("NIVE_COUCHE", "MOY")]
    for name in as_tuple(occ["NOM_CHAM"]):
        field = fields.get(name)
        if field is None:
            ctx.error(f"the result has no field {name} (CALC_CHAMP it first)", "NOM_CHAM", occ)
        if field.sub_points % 3 or field.sub_points < 3:
            ctx.unsupported(
                f"POST_CHAMP EXTR_COQUE of {name}: not a field on plate layers", "NOM_CHAM", occ
            )
        layers = field.sub_points // 3
        if not 1 <= layer <= layers:
            ctx.error(f"NUME_COUCHE={layer}: {name} has {layers} layer(s)", "NUME_COUCHE", occ)
        sub = 3 * (layer - 1) + level
        kept = field.values[:, :, sub :: field.sub_points, :]
        result.element_fields[name] = ElementField(name, field.cells, field.components, kept.copy())
    ctx.log(f"POST_CHAMP EXTR_COQUE layer {layer} {occ.get('NIVE_COUCHE', 'MOY')}")
    return result
