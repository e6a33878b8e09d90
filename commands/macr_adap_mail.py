"""MACR_ADAP_MAIL ADAPTATION='RAFFINEMENT_UNIFORME': the mesh MAILLAGE_N
refined once (asterlite.fem.refinement) bound to MAILLAGE_NP1; the other
adaptations (by an error field, by zones, coarsening) are refused by name."""

from __future__ import annotations

from collections import Counter

from asterlite.fem.refinement import RefinementError, refine_uniformly


def run(ctx, kw):
    mesh = kw["MAILLAGE_N"]
    try:
        refined = refine_uniformly(mesh)
    except RefinementError as exc:
        ctx.unsupported(str(exc), "MAILLAGE_N", kw)
    if kw.get("NOMBRE", "OUI") == "OUI":
        counts = ", ".join(f"{n} {k}" for k, n in sorted(Counter(refined.cell_types).items()))
        ctx.log(
            f"uniform refinement: {mesh.n_nodes} -> {refined.n_nodes} nodes, "
            f"{mesh.n_cells} -> {refined.n_cells} cells ({counts})"
        )
    ctx.bind(kw["MAILLAGE_NP1"], refined)
    return None
