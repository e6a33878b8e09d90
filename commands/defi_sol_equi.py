"""DEFI_SOL_EQUI: the equivalent-linear response of a horizontally layered
soil column to a vertical S wave (asterlite.harmonic.sol_equi computes it).

Computed, in 2D (FONC_SIGNAL) on the column the command meshes itself (no
MAILLAGE) with its sides tied (LIAISON absent or 'PERIODIQUE'), NOM_CMP='DX',
SURF='OUI', INTEGRATION='TEMPS':
- CHARGEMENT='ONDE_PLANE' with the accelerogram at the outcropping rock
  (LIEU_SIGNAL='AFFLEURANT') or at the free surface ('CHAMP_LIBRE': the
  column driven by the macro's white noise, drawn from the deck's random
  stream as GENE_FONC_ALEA, and its responses scaled by the signal over the
  surface's response);
- CHARGEMENT='MONO_APPUI' with the accelerogram at the outcrop or at the free
  surface (LIEU_SIGNAL='CHAMP_LIBRE', deconvolved);
the soil from TABLE_MATER_ELAS + TABLE_GEQUI_GMAX + TABLE_AMOR_EQUI or from
COUCHE + MATERIAU (LIST_EPSI). As code_aster's macro it returns the layers
for MISS (the strain-compatible moduli and damping, the substratum's cell,
the half-space) and prints the column's table (the iterations' moduli,
G/Gmax, γmax and peak accelerations at the bases of the layers, the final
moduli, Rayleigh coefficients and wave speeds) on UNITE_TABLE_RESU;
UNITE_RESU_TRAN receives the histories as IMPR_FONCTION TABLEAU blocks
(accelerations; with TOUT_CHAM velocities and displacements; with
TOUT_ACCE the strains GAM_k and stresses TAU_k; with TOUT_CHAM the nodal
shear forces FY, the block DEFI_CHAR_SOL reads); UNITE_RESU_SPEC the
oscillator spectra (5 %, on LIST_FREQ_SPEC_OSCI) and the transfer function
between the outcrop and the free surface.

Every call draws that white noise, as code_aster, so that the deck's later
draws stay the same. Unsupported by name (catalogues/defi_sol_equi.py
leaves them out): DSP, UNITE_TRAN_INIT, 3D (FONC_SIGNAL_X), MAILLAGE,
LIAISON='SANS', NOM_CMP='DY', SURF='NON', CORRECTION='BYRNE',
INTEGRATION='FREQUENCE', LIST_FREQ, and spectra without
LIST_FREQ_SPEC_OSCI (code_aster's default list)."""

from __future__ import annotations

import math

import numpy as np

from asterlite.concepts.interspectrum import InterSpectrum
from asterlite.concepts.table import Table
from asterlite.harmonic.soil_column import StrainCurve
from asterlite.harmonic.sol_equi import ColumnCell, equivalent_linear_column, signal_grid
from asterlite.io.tables import fortran_real, table_lines, write_lines
from asterlite.post import functions as fops
from asterlite.post import spectral
from asterlite.post.restitution import values_of

_ELAS_COLUMNS = ("Y", "M", "RHO", "Emax", "NU", "AH", "GDgam")
# the macro's Rayleigh fit of the hysteretic damping between 1 and 15 Hz
# (with its 3.14)
_F1, _F2 = 1.0, 15.0
_AAMULT = 1.0 / (2.0 * 3.14 * (_F1 + _F2))
_ABMULT = 2.0 * 3.14 * _F1 * _F2 / (_F1 + _F2)
_CA = 1.0 / (0.5 + _F1 * _F2 / (_F1 + _F2) * math.log(_F2 / _F1) / (_F2 - _F1))


def run(ctx, kw):
    # the catalogue keeps the branches computed here (the others are
    # unsupported by name there); these three are read by code_aster's macro
    # on branches it does not take here (UNITE_TRAN_INIT,
    # INTEGRATION='FREQUENCE'); INFO the listing only
    kw.mark_used("MASS_PENA", "LONG_CARA", "FREQ_FILTRE", "INFO")
    cvar = float(kw.get("COEF_VARI_MATE", 1.0))
    if kw.get("TABLE_MATER_ELAS") is not None:
        cells, gg, dg = _from_tables(ctx, kw, cvar)
    else:
        cells, gg, dg = _from_layers(ctx, kw, cvar)
    if len(cells) < 2:
        ctx.error("the column needs at least one layer and the substratum", None, kw)
    for key in ("GROUP_MA_DROITE", "GROUP_MA_GAUCHE", "GROUP_MA_SUBSTR", "GROUP_MA_COL"):
        kw.mark_used(key)  # the names of the groups of the macro's own mesh
    try:
        grid = signal_grid(
            kw["FONC_SIGNAL"], kw.get("FREQ_COUP"), pad=kw.get("CHARGEMENT") == "ONDE_PLANE"
        )
        noise = _white_noise(ctx, kw, grid)
        result, grid = equivalent_linear_column(
            cells,
            kw["FONC_SIGNAL"],
            gg,
            dg,
            freq_cut=kw.get("FREQ_COUP"),
            coef_gamma=float(kw.get("COEF_GAMMA", 0.65)),
            resi_rela=float(kw.get("RESI_RELA", 0.05)),
            nmax_iter=int(kw.get("NMAX_ITER", 10)),
            lysmer=kw.get("CORR_AMOR", "NON") == "OUI",
            amplitude=float(kw.get("COEF_AMPL_ACCE", 1.0)),
            loading=kw.get("CHARGEMENT", "MONO_APPUI"),
            location=kw.get("LIEU_SIGNAL", "AFFLEURANT"),
            noise=noise,
        )
    except ValueError as exc:
        ctx.error(str(exc), "FONC_SIGNAL", kw)
    ctx.log(
        f"DEFI_SOL_EQUI: {len(cells) - 1} layers, {grid.times.size} instants, df={grid.df:g} Hz, "
        f"{grid.cut_index} frequencies, {len(result.changes)} analyses, "
        f"largest modulus change {result.changes[-1]:.3e}"
    )
    table = _layers_table(cells, result)
    title = kw.get("TITRE") or ""
    table_title = (
        f"Resultats du calcul lineaire equivalent avec E={cvar}*E0 "
        "Les valeurs max sont calculees au 1er Point de Gauss de la couche definie par sa "
        "cote inferieure Y"
    )
    unit = kw.get("UNITE_TABLE_RESU")
    lines = table_lines(table, title=table_title, real_format="E13.7")
    separator = kw.get("SEPARATEUR", " ")
    if separator != " ":
        lines = [line if line.startswith("#") else separator.join(line.split()) for line in lines]
    write_lines(ctx.session.output_path(int(unit) if unit is not None else 8), lines)
    _write_histories(ctx, kw, cells, result, grid, title, cvar)
    _write_spectra(ctx, kw, result, grid, title)
    return _soil_table(cells, result)


def _white_noise(ctx, kw, grid):
    """The macro's draw of a white noise (GENE_FONC_ALEA of a unit spectrum
    from df to the cut frequency, for tfin + dt seconds up to fmax, from the
    deck's random stream), scaled by 1 / √(2π fmax): the velocity of the
    ONDE_PLANE from the free field. Drawn on every call, as code_aster, so
    that the deck's later draws stay the same."""
    knots = np.array([0.0, grid.df, grid.cut, grid.cut + grid.df])
    spectrum = InterSpectrum("FREQ", knots, [(1, 1)], [np.array([1.0, 1.0, 1.0, 0.0])])
    duration = float(grid.times[-1]) + grid.dt
    try:
        frequencies = spectral.generation_grid(knots, True, 0.0, grid.fmax, None, duration)
        factors = np.array(
            [spectral.factor(m) for m in spectral.sampled_matrix(spectrum, frequencies, True)]
        )
    except ValueError as exc:
        ctx.error(f"the macro's white noise: {exc}", "FONC_SIGNAL", kw)
    phases = spectral.deck_phases(ctx.session, None)
    signals = spectral.generate(factors, frequencies.stored_frequencies(), 1, phases)
    return signals.times, signals.values[0] / math.sqrt(2.0 * math.pi * grid.fmax)


def _curve(ctx, kw, keyword, strains, values, what):
    try:
        return StrainCurve(tuple(float(x) for x in strains), tuple(float(y) for y in values))
    except ValueError as exc:
        ctx.error(f"{what}: {exc}", keyword, kw)


def _from_tables(ctx, kw, cvar):
    table = kw["TABLE_MATER_ELAS"]
    missing = [c for c in _ELAS_COLUMNS if c not in table.columns]
    if missing:
        ctx.error(f"TABLE_MATER_ELAS has no column {', '.join(missing)}", "TABLE_MATER_ELAS", kw)
    cells = []
    for n, row in enumerate(table.rows, start=1):
        if any(row.get(c) is None for c in _ELAS_COLUMNS):
            ctx.error(f"TABLE_MATER_ELAS row {n} lacks a value", "TABLE_MATER_ELAS", kw)
        cells.append(
            ColumnCell(
                float(row["Y"]), str(row["M"]), float(row["RHO"]), cvar * float(row["Emax"]),
                float(row["NU"]), float(row["AH"]), int(row["GDgam"]),
            )
        )  # fmt: skip
    count = max(c.curves for c in cells)
    # curve j is column j + 1 of each table (the first being the strains)
    gg, dg = {}, {}
    for keyword, store, what in (
        ("TABLE_GEQUI_GMAX", gg, "G/Gmax"),
        ("TABLE_AMOR_EQUI", dg, "damping"),
    ):
        curves = kw[keyword]
        if len(curves.columns) < count + 1:
            ctx.error(
                f"{keyword} has {len(curves.columns) - 1} curves, the layers ask for {count}",
                keyword,
                kw,
            )
        strains = curves.column(curves.columns[0])
        for j in range(1, count + 1):
            store[j] = _curve(ctx, kw, keyword, strains, curves.column(curves.columns[j]), what)
    for j, curve in dg.items():
        if max(curve.values) > 2.0:
            ctx.error(f"damping curve {j} exceeds 2", "TABLE_AMOR_EQUI", kw)
    _check_depths(ctx, kw, cells, "TABLE_MATER_ELAS")
    return cells, gg, dg


def _from_layers(ctx, kw, cvar):
    materials = kw.factor("MATERIAU")
    layers = kw.factor("COUCHE")
    if not materials or not layers:
        ctx.error("without TABLE_MATER_ELAS, COUCHE and MATERIAU are needed", "COUCHE", kw)
    # the macro resamples every curve on LIST_EPSI, or else on the strains of
    # the last MATERIAU
    grid = values_of(kw["LIST_EPSI"]) if kw.get("LIST_EPSI") else materials[-1]["GAMMA"]
    gg, dg = {}, {}
    for j, occ in enumerate(materials, start=1):
        for key, store in (("G_GMAX", gg), ("D", dg)):
            given = _curve(ctx, kw, "MATERIAU", occ["GAMMA"], occ[key], f"MATERIAU {j} {key}")
            store[j] = _curve(
                ctx, kw, "MATERIAU", grid, [given(x) for x in grid], f"MATERIAU {j} {key}"
            )
    cells, depth = [], 0.0
    for occ in layers:
        if float(occ["AMOR_HYST"]) > 2.0:
            ctx.error("AMOR_HYST exceeds 2", "COUCHE", kw)
        if int(occ["NUME_MATE"]) not in gg:
            ctx.error(f"NUME_MATE {occ['NUME_MATE']} is no MATERIAU", "COUCHE", kw)
        depth += float(occ["EPAIS"])
        cells.append(
            ColumnCell(
                depth, str(occ["GROUP_MA"]), float(occ["RHO"]), cvar * float(occ["E"]),
                float(occ["NU"]), float(occ["AMOR_HYST"]), int(occ["NUME_MATE"]),
            )
        )  # fmt: skip
        kw.mark_used("N1")  # the Byrne correction's SPT count
    _check_depths(ctx, kw, cells, "COUCHE")
    return cells, gg, dg


def _check_depths(ctx, kw, cells, keyword):
    depths = [0.0] + [c.depth for c in cells]
    if any(b <= a for a, b in zip(depths, depths[1:], strict=False)):
        ctx.error("the depths Y of the layers' bases must increase from 0", keyword, kw)


def _soil_table(cells, result) -> Table:
    """What the macro returns (SURF='OUI'): the strain-compatible layers for
    a MISS computation, the substratum's cell, then the half-space."""
    table = Table()
    types = {"NUME_COUCHE": "I", "NUME_MATE": "I", "RECEPTEUR": "K8", "SOURCE": "K8"}
    for name in ("NUME_COUCHE", "EPAIS", "RHO", "E", "NU", "AMOR_HYST", "RECEPTEUR", "SOURCE",
                 "NUME_MATE", "SUBSTRATUM"):  # fmt: skip
        table.add_column(name, types.get(name, "K8" if name == "SUBSTRATUM" else "R"))
    last = len(result.changes) - 1
    top = 0.0
    for k, cell in enumerate(cells, start=1):
        layer = k < len(cells)
        table.add_row(
            {
                "NUME_COUCHE": k, "EPAIS": cell.depth - top, "RHO": cell.density,
                "E": result.young[last][k - 1] if layer else cell.young, "NU": cell.poisson,
                "AMOR_HYST": result.loss[last][k - 1] if layer else cell.loss,
                "RECEPTEUR": "OUI" if k == 1 else "NON", "SOURCE": "OUI" if k == 1 else "NON",
                "NUME_MATE": k,
            }
        )  # fmt: skip
        top = cell.depth
    base = cells[-1]
    table.add_row(
        {
            "NUME_COUCHE": len(cells) + 1, "EPAIS": 0.0, "RHO": base.density, "E": base.young,
            "NU": base.poisson, "AMOR_HYST": base.loss, "RECEPTEUR": "NON", "SOURCE": "NON",
            "NUME_MATE": len(cells), "SUBSTRATUM": "OUI",
        }
    )  # fmt: skip
    return table


def _layers_table(cells, result) -> Table:
    """The macro's table of the column (printed on UNITE_TABLE_RESU): the
    rows of TABLE_MATER_ELAS, the moduli and loss factors of the analyses
    before the last (E1, AH1, ...), those of the last (Efin, AHfin), the
    profiles of the last analysis (G/Gmax, γmax, peak acceleration in g at
    the base of each layer, the surface on a row Y=0), the Rayleigh
    coefficients, G and wave speeds of the final moduli."""
    table = Table()
    analysis = result.analysis
    runs = len(result.changes)
    peaks = np.max(np.abs(analysis.acceleration), axis=1) / 9.81
    layers = len(cells) - 1
    for k, cell in enumerate(cells):
        row = {
            "Y": cell.depth, "M": cell.name, "RHO": cell.density, "Emax": cell.young,
            "NU": cell.poisson, "AH": cell.loss, "GDgam": cell.curves,
        }  # fmt: skip
        layer = k < layers
        for it in range(1, runs - 1):
            row[f"E{it}"] = result.young[it][k] if layer else cell.young
            row[f"AH{it}"] = result.loss[it][k] if layer else cell.loss
        if layer:
            row["G/Gmax"] = result.ratio[runs - 1][k]
            row["gamma_max"] = float(analysis.gamma_max[k])
            row["accxmax"] = float(peaks[k + 1])
        efin = result.young[runs - 1][k] if layer else cell.young
        ahfin = result.loss[runs - 1][k] if layer else cell.loss
        g = efin / (2.0 * (1.0 + cell.poisson))
        row.update(
            E0=cell.young, AH0=cell.loss, Efin=efin, AHfin=ahfin,
            AAfin=_CA * _AAMULT * ahfin, ABfin=_CA * _ABMULT * ahfin, Gfin=g,
            VSfin=math.sqrt(g / cell.density),
            VPfin=math.sqrt(
                efin * (1 - cell.poisson)
                / ((1 - 2.0 * cell.poisson) * (1 + cell.poisson) * cell.density)
            ),
        )  # fmt: skip
        table.add_row(row, {"GDgam": "I", "M": "K8"})
    surface = {"Y": 0.0, "G/Gmax": 1.0, "gamma_max": 0.0, "accxmax": float(peaks[0])}
    surface.update({f"E{it}": 0.0 for it in range(1, runs - 1)})
    surface.update({f"AH{it}": 0.0 for it in range(1, runs - 1)})
    table.add_row(surface)
    return table


def _tableau(title, subtitle, abscissa, curves):
    """An IMPR_FONCTION FORMAT='TABLEAU' block of curves sharing abscissas
    (code_aster's layout: commented titles and legends, the parameters'
    names, then one line of %12.5E values per abscissa)."""
    lines = [f"# {title}", f"# {subtitle}"]
    for i, (legend, _) in enumerate(curves):
        lines += [f"# Courbe {i}", f"# {legend}"]
    lines.append(" ".join(["INST"] + [legend.split()[0] for legend, _ in curves]))
    values = np.vstack([abscissa] + [np.asarray(v, dtype=float) for _, v in curves])
    lines += [" ".join(fortran_real(float(x)) for x in column) for column in values.T]
    return lines


def _write_histories(ctx, kw, cells, result, grid, subtitle, cvar):
    analysis = result.analysis
    times = grid.times
    suffix = f" cvar={cvar} deltaE = {result.changes[-1]}"
    head = f"Resultats du calcul lineaire equivalent avec E={cvar}*E0"
    layers = analysis.strain.shape[0]
    all_layers = kw.get("TOUT_ACCE", "OUI") == "OUI"
    if all_layers:
        chosen = list(range(1, layers + 1))
    else:
        # the layers are named by the M (GROUP_MA) of their rows
        names = {cell.name: k for k, cell in enumerate(cells[:-1], start=1)}
        chosen = []
        for name in kw.get("LIST_COUCHE_ACCE") or ():
            if name == cells[-1].name:
                ctx.error(f"{name} is the substratum, not a layer", "LIST_COUCHE_ACCE", kw)
            if name not in names:
                # as code_aster: a message, and the name is left out
                ctx.log(f"DEFI_SOL_EQUI: layer {name} is not in the soil table, left out")
                continue
            chosen.append(names[name])
    acc = analysis.acceleration
    path = ctx.session.output_path(int(kw.get("UNITE_RESU_TRAN", 40)))
    curves = [("AX_CL" + suffix, acc[0]), ("AX_RA" + suffix, result.input_acceleration)]
    curves += [(f"AX_{d}" + suffix, acc[d]) for d in chosen]
    curves.append(("AX_BH" + suffix, acc[-1]))
    write_lines(path, _tableau(head + " acce", subtitle, times, curves))
    fields = kw.get("TOUT_CHAM", "OUI") == "OUI"
    if fields and all_layers:
        rows = [acc[0], result.input_acceleration] + [acc[d] for d in chosen] + [acc[-1]]
        names = ["CL", "RA"] + [str(d) for d in chosen] + ["BH"]
        on_grid = [fops.integrate(_history(times, r)) for r in rows]
        twice = [fops.integrate(f) for f in on_grid]
        for letter, funcs in (("VX", on_grid), ("DX", twice)):
            block = [
                (f"{letter}_{n}" + suffix, f.ordinates) for n, f in zip(names, funcs, strict=True)
            ]
            write_lines(path, _tableau(head, subtitle, times, block))
    if all_layers:
        write_lines(path, _tableau(head, subtitle, times, [
            (f"GAM_{d}" + suffix, analysis.strain[d - 1]) for d in chosen]))  # fmt: skip
        write_lines(path, _tableau(head, subtitle, times, [
            (f"TAU_{d}" + suffix, analysis.stress[d - 1]) for d in chosen]))  # fmt: skip
    if fields:
        force = analysis.force
        block = [("FY_CL" + suffix, force[0])]
        block += [(f"FY_{d}" + suffix, force[d]) for d in range(1, layers + 1)]
        block.append(("FY_BH" + suffix, force[-1]))
        write_lines(path, _tableau(head, subtitle, times, block))


def _history(times, values):
    from asterlite.concepts.function import Function

    return Function(times, values, NOM_PARA="INST", PROL_GAUCHE="CONSTANT", PROL_DROITE="CONSTANT")


def _write_spectra(ctx, kw, result, grid, subtitle):
    freqs = values_of(kw["LIST_FREQ_SPEC_OSCI"])
    analysis = result.analysis
    acc = analysis.acceleration
    rows = [("SAX_CL", acc[0]), ("SAX_RA", result.input_acceleration)]
    rows += [(f"SAX_{d}", acc[d]) for d in range(1, acc.shape[0] - 1)]
    rows.append(("SAX_BH", acc[-1]))
    curves = [
        (name, fops.response_spectrum(_history(grid.times, v), freqs, 0.05, "ACCE", 9.81))
        for name, v in rows
    ]
    lines = ["# Spectres CL et RA et ppt - input =RA", f"# {subtitle}"]
    lines.append(" ".join(["FREQ"] + [name for name, _ in curves]))
    values = np.vstack([freqs] + [v for _, v in curves])
    lines += [" ".join(fortran_real(float(x)) for x in column) for column in values.T]
    # the transfer function between the outcrop and the free surface
    # (FDT_RACL) and its modulus
    lines += [
        "# Fonctions de Transfert entre CL et RA et Module des FFT",
        "FREQ FDT_R FDT_I MODULE",
    ]
    lines += [
        " ".join(fortran_real(float(x)) for x in (f, z.real, z.imag, abs(z)))
        for f, z in zip(*result.transfer, strict=True)
    ]
    write_lines(ctx.session.output_path(int(kw.get("UNITE_RESU_SPEC", 55))), lines)
