"""DEFI_CHAR_SOL from a transient result (RESU_INIT), as code_aster's macro
builds it: an AFFE_CHAR_MECA EVOL_CHAR whose history is

- CHARGEMENT='FORCE': CREA_RESU CONV_RESU of NOM_CHAM_INIT onto NUME_DDL,
  times COEF, without or with DDL_EXCLUS;
- CHARGEMENT='ONDE_PLANE': CREA_RESU KUCV, C v (+ K u with MATR_RIGI).

From a file of soil signals (UNITE_TRAN_INIT, the UNITE_RESU_TRAN tables
DEFI_SOL_EQUI writes), CHARGEMENT='FORCE' in 2D: the sixth block of the
file holds INST, then the nodal shear force at the free surface (column 2)
and at the base of each row of TABLE_MATER_ELAS (columns 3, 4, ..., the last
one the base of the substratum's cell). As code_aster's macro, the forces at
the depths Z0 (surface) and Z0 - Y of every row make a nappe of the
vertical coordinate Y and of INST (DEFI_NAPPE, linear between the depths,
no extension beyond them), applied as FORCE_NODALE to the nodes of
GROUP_MA_GAUCHE and, with the opposite sign, GROUP_MA_DROITE: FY for
NOM_CMP='DX', FX for 'DY'. The file's ONDE_PLANE branch and 3D (AXE) are
refused by name."""

from __future__ import annotations

from pathlib import Path

import numpy as np
from asterlite.commands.crea_resu_conv import convert, kucv
from asterlite.commands.defi_fonction import check_abscissas
from asterlite.commands.lire_fonction import column, numeric_blocks

from asterlite.concepts.assembly import MechanicalLoad, ValueInTime
from asterlite.concepts.function import Function, Nappe
from asterlite.fem.selection import node_group_members
from asterlite.io.input_files import InputFileError, read_bounded_text
from asterlite.post.functions import combine


def run(ctx, kw):
    kw.mark_used("INFO", "TITRE")  # the listing only
    if kw.get("UNITE_TRAN_INIT") is not None:
        return _from_signal_file(ctx, kw)
    model = kw["MODELE"]
    if kw.get("CHARGEMENT", "FORCE") == "FORCE":
        if kw.get("NUME_DDL") is None:
            # code_aster's CONV_RESU needs the numbering of the forces
            ctx.error("CHARGEMENT='FORCE' needs NUME_DDL", "NUME_DDL", kw)
        history = convert(ctx, kw, "EVOL_CHAR", kw["NUME_DDL"])
    else:
        if kw.get("MATR_AMOR") is None:
            ctx.error("CHARGEMENT='ONDE_PLANE' needs MATR_AMOR (C v)", "MATR_AMOR", kw)
        history = kucv(ctx, kw, "EVOL_CHAR")
    if history.numbering.mesh is not model.mesh:
        ctx.error("RESU_INIT is on another mesh than MODELE", "RESU_INIT", kw)
    load = MechanicalLoad(model=model)
    load.extra["EVOL_CHAR"] = history
    return load


# the columns code_aster's macro extracts from TABLE_MATER_ELAS (CALC_TABLE EXTR)
_SOIL_COLUMNS = ("Y", "M", "RHO", "Emax", "NU", "AH", "GDgam")
_FORCE_BLOCK = 6  # the block of the shear forces in DEFI_SOL_EQUI's UNITE_RESU_TRAN


def _from_signal_file(ctx, kw):
    if kw.get("AXE") is not None:
        ctx.unsupported("DEFI_CHAR_SOL in 3D (AXE)", "AXE", kw)
    if kw.get("CHARGEMENT", "FORCE") != "FORCE":
        ctx.unsupported(
            "DEFI_CHAR_SOL CHARGEMENT='ONDE_PLANE' from a file (UNITE_TRAN_INIT)", "CHARGEMENT", kw
        )
    # code_aster's 2D FORCE branch reads neither: LONG_CARA serves its
    # ONDE_PLANE branch, NOM_PARA its 3D one
    kw.mark_used("LONG_CARA", "NOM_PARA")
    table = kw["TABLE_MATER_ELAS"]
    missing = [c for c in _SOIL_COLUMNS if c not in table.columns]
    if missing:
        ctx.error(f"TABLE_MATER_ELAS has no column {', '.join(missing)}", "TABLE_MATER_ELAS", kw)
    depths = [row.get("Y") for row in table.rows]
    if len(depths) < 2 or any(y is None for y in depths):
        ctx.error(
            "TABLE_MATER_ELAS needs a Y on each of its rows (layers, then the substratum)",
            "TABLE_MATER_ELAS",
            kw,
        )
    rows = len(depths)
    z0 = float(kw.get("Z0", 0.0))
    unit = int(kw["UNITE_TRAN_INIT"])
    path = Path(ctx.session.input_path(unit))
    if not path.exists():
        ctx.error(f"file {path} (unit {unit}) does not exist", "UNITE_TRAN_INIT", kw)
    try:
        blocks = numeric_blocks(read_bounded_text(path, "table of soil signals", 30))
        times = column(blocks, (_FORCE_BLOCK, 1), "UNITE_TRAN_INIT")
        # deepest first: the base of the last row (column rows + 2) up to the
        # free surface (column 2)
        signals = [
            column(blocks, (_FORCE_BLOCK, rows + 2 - k), "UNITE_TRAN_INIT") for k in range(rows + 1)
        ]
    except (InputFileError, ValueError) as exc:
        ctx.error(f"{path.name} (unit {unit}): {exc}", "UNITE_TRAN_INIT", kw)
    check_abscissas(ctx, kw, times)
    heights = [z0 - float(depths[rows - 1 - k]) for k in range(rows)] + [z0]
    if np.any(np.diff(heights) <= 0):
        ctx.error(
            "the Y of TABLE_MATER_ELAS must increase (depths of the layers' bases)",
            "TABLE_MATER_ELAS",
            kw,
        )

    def nappe(coef):
        functions = []
        for values in signals:
            read = Function(
                times,
                values,
                NOM_PARA="INST",
                INTERPOL=("LIN", "LIN"),
                PROL_GAUCHE="EXCLU",
                PROL_DROITE="CONSTANT",
            )
            functions.append(combine([read], [coef]))
        return Nappe(
            np.asarray(heights),
            functions,
            NOM_PARA="Y",
            NOM_PARA_FONC="INST",
            INTERPOL=("LIN", "LIN"),
            PROL_GAUCHE="EXCLU",
            PROL_DROITE="EXCLU",
        )

    component = "DY" if kw.get("NOM_CMP", "DX") == "DX" else "DX"
    model = kw["MODELE"]
    mesh = model.mesh
    components = model.node_components()
    load = MechanicalLoad(model=model)
    forces = load.extra.setdefault("FORCE_NODALE_INST", [])
    sides = [(s, c) for s, c in (("GROUP_MA_GAUCHE", 1.0), ("GROUP_MA_DROITE", -1.0)) if kw.get(s)]
    if not sides:
        ctx.error("GROUP_MA_GAUCHE or GROUP_MA_DROITE is needed", "GROUP_MA_GAUCHE", kw)
    for side, coef in sides:
        # code_aster's macro applies them as FORCE_NODALE on GROUP_NO of that name
        nodes = node_group_members(ctx, kw, mesh, keyword=side)
        values = nappe(coef)
        for node in nodes:
            if component not in components.get(int(node), ()):
                ctx.error(f"node {mesh.node_names[node]} has no {component} DOF", side, kw)
            point = tuple(
                float(x) for x in np.pad(mesh.coords[node], (0, 3 - len(mesh.coords[node])))
            )
            forces.append((int(node), component, ValueInTime(values, point)))
    return load
