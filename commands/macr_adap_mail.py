"""MACR_ADAP_MAIL: the mesh MAILLAGE_N adapted as HOMARD does it, bound to
MAILLAGE_NP1. ADAPTATION='RAFFINEMENT_UNIFORME' refines every cell once
(asterlite.fem.refinement); 'RAFF_DERA_ZONE' refines the zones of ZONE
(asterlite.fem.zone_refinement). The other adaptations (by an error field,
coarsening) are refused by name by the catalogue."""

from __future__ import annotations

from collections import Counter

from asterlite.fem.refinement import RefinementError, refine_uniformly
from asterlite.fem.zone_refinement import ZONE_KEYWORDS, Zone, refine_zones

_ALL_ZONE_KEYWORDS = sorted({k for names in ZONE_KEYWORDS.values() for k in names})


def _zone(ctx, occ) -> Zone:
    kind = occ["TYPE"]
    needed = ZONE_KEYWORDS[kind]
    missing = [k for k in needed if occ.get(k) is None]
    if missing:
        ctx.error(f"a {kind} zone needs {', '.join(missing)}", "TYPE", occ)
    # code_aster hands every keyword given to HOMARD, which reads only those
    # of the zone's TYPE
    occ.mark_used(*(k for k in _ALL_ZONE_KEYWORDS if k not in needed))
    occ.mark_used("USAGE")  # 'RAFFINEMENT' only (the catalogue)
    values = {k: float(occ[k]) for k in needed}
    for axis in ("X", "Y", "Z"):
        low, high = values.get(f"{axis}_MINI"), values.get(f"{axis}_MAXI")
        if low is not None and high is not None and low > high:
            ctx.error(f"{axis}_MINI {low:g} exceeds {axis}_MAXI {high:g}", f"{axis}_MINI", occ)
    if kind in ("DISQUE_PERCE", "TUYAU") and values["RAYON_INT"] > values["RAYON_EXT"]:
        ctx.error("RAYON_INT exceeds RAYON_EXT", "RAYON_INT", occ)
    return Zone(kind, values)


def run(ctx, kw):
    mesh = kw["MAILLAGE_N"]
    adaptation = kw["ADAPTATION"]
    try:
        if adaptation == "RAFFINEMENT_UNIFORME":
            refined, detail = refine_uniformly(mesh), ""
        else:
            zones = [_zone(ctx, occ) for occ in kw.factor("ZONE")]
            adapted = refine_zones(mesh, zones, kw.get("NIVE_MAX"))
            refined, counts = adapted.mesh, adapted.counts
            detail = (
                f"; {counts['zone_edges']} edges in the zones, {counts['cut_edges']} cut, "
                f"{counts['split']} faces split in four, {counts['conformity']} for conformity"
            )
    except RefinementError as exc:
        ctx.unsupported(str(exc), "MAILLAGE_N", kw)
    if kw.get("NOMBRE", "OUI") == "OUI":
        counts = ", ".join(f"{n} {k}" for k, n in sorted(Counter(refined.cell_types).items()))
        what = "uniform refinement" if adaptation == "RAFFINEMENT_UNIFORME" else "zone refinement"
        ctx.log(
            f"{what}: {mesh.n_nodes} -> {refined.n_nodes} nodes, "
            f"{mesh.n_cells} -> {refined.n_cells} cells ({counts}){detail}"
        )
    ctx.bind(kw["MAILLAGE_NP1"], refined)
    return None
