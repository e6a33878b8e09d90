"""Pictures of a transient result (``tran_gene``): node time histories
restituted from the modal basis, shock quantities, orbits in the obstacle
plane with the obstacle outline, and wear work rates per support.

Every ``*_figure`` function returns a :class:`matplotlib.figure.Figure`
built without pyplot (no global state, no display: safe in workers and
tests); :func:`save_figure` writes it as PNG or SVG. matplotlib (the ``plot``
extra) is imported only when a figure is made; without it a figure request
stops with a message saying how to install it. :func:`plot_from_store` is
``asterlite plot``: it reads a result saved by :mod:`asterlite.io.result_store`.
"""

from __future__ import annotations

from dataclasses import dataclass, field
from pathlib import Path

import numpy as np

from asterlite.concepts.modes import ModeResult
from asterlite.concepts.titles import compact, same_title, unique_titles
from asterlite.concepts.transient import ShockHistory, TranGene
from asterlite.extras import require
from asterlite.io.result_store import _shock_group_names as shock_group_names
from asterlite.io.result_store import load_tran_gene
from asterlite.post.wear import history_wear_power

IMAGE_FORMATS = (".png", ".svg")
NODAL_FIELDS = {"DEPL": "depl", "VITE": "vite", "ACCE": "acce"}
FIELD_UNITS = {"DEPL": "m", "VITE": "m/s", "ACCE": "m/s²"}
SHOCK_PLOTS = ("orbit", "wear")  # quantities that are not a stored field
# wear rates below this fraction of the largest rate of the result are rounding
# noise of FN·|VT| (a support that sticks or barely touches): drawn as zero
WEAR_NOISE_FLOOR = 1.0e-9


class PlotError(ValueError):
    """A plot request the result cannot satisfy (unknown node, shock, quantity...)."""


# ------------------------------------------------------------------ data


def node_index(mesh, node: str) -> int:
    """Index of a node given by name, or by a group holding exactly one node."""
    if node in mesh.node_names:
        return mesh.node_names.index(node)
    members = mesh.node_groups.get(node)
    if members is not None and len(members) == 1:
        return int(members[0])
    raise PlotError(f"no node {node!r} in the mesh (nodes: {_listing(mesh.node_names)})")


def node_history(tran: TranGene, node: str, component: str, field: str = "DEPL") -> np.ndarray:
    """One physical component at the archived instants: q(t) · φ(node, component)."""
    if field not in NODAL_FIELDS:
        raise PlotError(f"field {field!r}: expected one of {', '.join(NODAL_FIELDS)}")
    if not isinstance(tran.basis, ModeResult):  # generalized modes, or none: no mesh
        held = "no basis" if tran.basis is None else f"a {tran.basis.aster_type} basis"
        raise PlotError(
            f"node histories need a basis on a mesh; the result has {held} (restore it "
            "on physical DOFs in the deck: REST_SOUS_STRUC, REST_GENE_PHYS)"
        )
    numbering = tran.basis.numbering
    index = node_index(numbering.mesh, node)
    rows = [i for i, (n, c) in enumerate(numbering.dofs) if n == index and c == component]
    if not rows:
        present = sorted({c for n, c in numbering.dofs if n == index})
        raise PlotError(f"node {node} has no {component!r} (components: {', '.join(present)})")
    generalized = getattr(tran, NODAL_FIELDS[field])
    return np.asarray(generalized) @ np.asarray(tran.basis.shapes)[rows[0]]


def shock_names(tran: TranGene) -> list[str]:
    """One name per shock of the result: its title, made unique as
    DYNA_VIBRA makes them (results saved before it did may repeat one)."""
    return unique_titles([shock.name for shock in tran.shocks])


def find_shock(tran: TranGene, name: str) -> ShockHistory:
    """The shock ``name`` designates: its title (blanks ignored: code_aster's
    ``DIS_CHOC        00000002`` is also ``DIS_CHOC00000002``) or the name
    of its group in results.h5."""

    names = shock_names(tran)
    for candidates in (names, shock_group_names(tran.shocks)):
        for shock, title in zip(tran.shocks, candidates, strict=True):
            if same_title(name, title):
                return shock
    listed = _listing([repr(n) if " " in n else n for n in names])  # quoted when blank
    raise PlotError(f"no shock {name!r} in the result (shocks: {listed})")


def shock_quantity(shock: ShockHistory, quantity: str) -> np.ndarray:
    if quantity not in shock.fields:
        raise PlotError(
            f"shock {shock.name} has no {quantity!r} (stored: {_listing(list(shock.fields))}, "
            f"or {' / '.join(SHOCK_PLOTS)})"
        )
    return np.asarray(shock.fields[quantity])


def is_two_node(shock: ShockHistory) -> bool:
    return str(shock.parameters.get("OBSTACLE", "")).startswith("BI_")


def orbit_coordinates(shock: ShockHistory) -> tuple[np.ndarray, np.ndarray]:
    """The node's path in the obstacle plane (local y, z): node 1's position
    relative to ORIG_OBST, or node 1 relative to node 2 for BI_* obstacles."""
    prefix = "REL" if is_two_node(shock) else "LOC"
    return shock_quantity(shock, f"DY{prefix}"), shock_quantity(shock, f"DZ{prefix}")


def wear_work_rates(tran: TranGene) -> dict[str, float]:
    """The Archard wear power (W, code_aster's PUIS_USURE: mean FN·|VT| over
    the sliding intervals, :func:`asterlite.post.wear.wear_power`) of each
    shock over the run."""

    return {
        name: history_wear_power(tran.times, shock.fields)
        for name, shock in zip(shock_names(tran), tran.shocks, strict=True)
    }


@dataclass
class ObstacleOutline:
    """What bounds the orbit: curves (y, z) to draw, whether the plane should be
    shown to scale, and the gap as an arrow from ``gap_start`` to ``gap_end``."""

    curves: list[tuple[np.ndarray, np.ndarray]] = field(default_factory=list)
    horizontal: list[float] = field(default_factory=list)  # lines z = value
    vertical: list[float] = field(default_factory=list)  # lines y = value
    equal_aspect: bool = False
    gap_label: str = ""
    gap_start: tuple[float, float] = (0.0, 0.0)
    gap_end: tuple[float, float] = (0.0, 0.0)


def circle(radius: float, points: int = 181) -> tuple[np.ndarray, np.ndarray]:
    angle = np.linspace(0.0, 2.0 * np.pi, points)
    return radius * np.cos(angle), radius * np.sin(angle)


def polar_polygon(polar) -> tuple[np.ndarray, np.ndarray]:
    """A DISCRET obstacle's (angle deg, radius) rows as a closed (y, z) polygon."""
    polar = np.asarray(polar, dtype=float).reshape(-1, 2)
    angle, radius = np.radians(polar[:, 0]), polar[:, 1]
    y, z = radius * np.cos(angle), radius * np.sin(angle)
    return np.append(y, y[0]), np.append(z, z[0])


def obstacle_outline(parameters: dict) -> ObstacleOutline:
    """The obstacle in its plane, from a shock's stored parameters
    (OBSTACLE, JEU, DIST_1, DIST_2, and POLAR for DISCRET)."""
    kind = str(parameters.get("OBSTACLE", ""))
    gap = float(parameters.get("JEU", 0.0))
    dist = float(parameters.get("DIST_1", 0.0)) + float(parameters.get("DIST_2", 0.0))
    if kind == "PLAN_Y":
        return ObstacleOutline(vertical=[-gap, gap], **_gap_arrow("JEU", gap))
    if kind == "PLAN_Z":
        return ObstacleOutline(horizontal=[-gap, gap], **_gap_arrow("JEU", gap, (0.0, gap)))
    if kind == "CERCLE":
        return ObstacleOutline([circle(gap)], equal_aspect=True, **_gap_arrow("JEU", gap))
    if kind == "DISCRET":  # the polygon is the obstacle (JEU plays no part): gap = r_min
        polar = parameters.get("POLAR")
        if polar is None:
            return ObstacleOutline(equal_aspect=True)
        y, z = polar_polygon(polar)
        nearest = int(np.argmin(np.hypot(y, z)))
        r_min = float(np.hypot(y[nearest], z[nearest]))
        arrow = _gap_arrow("r_min", r_min, (float(y[nearest]), float(z[nearest])))
        return ObstacleOutline([(y, z)], equal_aspect=True, **arrow)
    if kind == "BI_PLAN_Y":  # relative y; which side stays in contact depends on the rest side
        return ObstacleOutline(vertical=[-dist, dist], **_gap_arrow("DIST_1+DIST_2", dist))
    if kind == "BI_PLAN_Z":
        return ObstacleOutline(
            horizontal=[-dist, dist], **_gap_arrow("DIST_1+DIST_2", dist, (0.0, dist))
        )
    if kind == "BI_CERCLE":
        return ObstacleOutline(
            [circle(dist)], equal_aspect=True, **_gap_arrow("DIST_1+DIST_2", dist)
        )
    if kind == "BI_CERC_INT":
        radius = float(parameters.get("DIST_2", 0.0)) - float(parameters.get("DIST_1", 0.0))
        return ObstacleOutline(
            [circle(radius)], equal_aspect=True, **_gap_arrow("DIST_2-DIST_1", radius)
        )
    return ObstacleOutline()


def _gap_arrow(name: str, size: float, end: tuple[float, float] | None = None) -> dict:
    return {
        "gap_label": f"{name} = {size:.4g}",
        "gap_start": (0.0, 0.0),
        "gap_end": end if end is not None else (size, 0.0),
    }


# --------------------------------------------------------------- figures


def _new_figure(size=(7.0, 4.5)):
    """A pyplot-free Figure (Agg canvas): no display, no global state."""

    Figure = require("matplotlib.figure", "drawing a figure").Figure
    return Figure(figsize=size, layout="constrained")


def _quantity_unit(quantity: str) -> str:
    if quantity.startswith("F"):
        return "N"
    if quantity.startswith("D"):
        return "m"
    if quantity.startswith("V"):
        return "m/s"
    return ""


def _axis_label(name: str, unit: str) -> str:
    return f"{name} ({unit})" if unit else name


def node_history_figure(tran: TranGene, node: str, component: str, field: str = "DEPL"):
    """Time history of one component of a node, restituted from the modal basis."""
    values = node_history(tran, node, component, field)
    figure = _new_figure()
    axes = figure.add_subplot()
    axes.plot(tran.times, values, label=f"{node} {component}")
    axes.set_xlabel("time (s)")
    axes.set_ylabel(_axis_label(f"{field} {component} at {node}", FIELD_UNITS[field]))
    axes.set_title(f"{tran.name or 'tran_gene'}: {field} {component} at node {node}")
    axes.grid(True, alpha=0.3)
    return figure


def shock_history_figure(tran: TranGene, shock_name: str, quantity: str = "FN"):
    """Time history of one stored quantity of a shock (FN: the impact force)."""
    shock = find_shock(tran, shock_name)
    values = shock_quantity(shock, quantity)
    figure = _new_figure()
    axes = figure.add_subplot()
    axes.plot(tran.times, values, label=f"{shock.name} {quantity}")
    axes.set_xlabel("time (s)")
    axes.set_ylabel(_axis_label(f"{quantity} at {shock.name}", _quantity_unit(quantity)))
    what = "impact force" if quantity == "FN" else quantity
    axes.set_title(f"{tran.name or 'tran_gene'}: {what} at shock {shock.name} ({shock.node_1})")
    axes.grid(True, alpha=0.3)
    return figure


def orbit_figure(tran: TranGene, shock_name: str, polar=None):
    """The shock node's orbit in the obstacle plane with the obstacle and its gap.

    ``polar``: a DISCRET obstacle's (angle deg, radius) rows (``Obstacle.polar``),
    for results whose shock parameters do not carry them as ``POLAR``."""
    shock = find_shock(tran, shock_name)
    y, z = orbit_coordinates(shock)
    parameters = dict(shock.parameters)
    if polar is not None:
        parameters["POLAR"] = polar
    outline = obstacle_outline(parameters)
    figure = _new_figure((6.0, 6.0) if outline.equal_aspect else (7.0, 4.5))
    axes = figure.add_subplot()
    axes.plot(y, z, linewidth=0.8, label="orbit")
    for curve_y, curve_z in outline.curves:
        axes.plot(curve_y, curve_z, color="black", linewidth=1.5, label="obstacle")
    for value in outline.vertical:
        axes.axvline(value, color="black", linewidth=1.5, label="obstacle")
    for value in outline.horizontal:
        axes.axhline(value, color="black", linewidth=1.5, label="obstacle")
    if outline.gap_label:
        axes.annotate(
            "",
            xy=outline.gap_end,
            xytext=outline.gap_start,
            arrowprops={"arrowstyle": "<->", "color": "tab:red"},
            zorder=4,
        )
        # in a corner on an opaque box: beside the arrow it sat under the orbit
        axes.text(
            0.02,
            0.03,
            outline.gap_label,
            transform=axes.transAxes,
            color="tab:red",
            ha="left",
            va="bottom",
            zorder=5,
            bbox={"boxstyle": "round,pad=0.3", "facecolor": "white", "alpha": 0.9, "lw": 0},
        )
    relative = " (node 1 - node 2)" if is_two_node(shock) else ""
    axes.set_xlabel(f"local y{relative} (m)")
    axes.set_ylabel(f"local z{relative} (m)")
    kind = shock.parameters.get("OBSTACLE", "?")
    axes.set_title(f"{tran.name or 'tran_gene'}: orbit at shock {shock.name} ({kind})")
    if outline.equal_aspect:
        axes.set_aspect("equal", adjustable="datalim")
    else:
        floor_axes(axes, (y, z), outline)
    handles, labels = axes.get_legend_handles_labels()
    unique = dict(zip(labels, handles, strict=True))
    axes.legend(unique.values(), unique.keys(), loc="upper right")
    axes.grid(True, alpha=0.3)
    return figure


# an axis of an orbit spans at least this fraction of the orbit's scale (the
# gap, the obstacle or the largest motion): the motion of a PLAN_Z shock along
# y is round-off (3e-17 m for a gap of 1e-4 m), which autoscaling spread over
# the whole axis as if it were large lateral motion; motion above the floor
# is physics and keeps its autoscaled axis
ORBIT_AXIS_FLOOR = 1.0e-4


def floor_axes(axes, data: tuple[np.ndarray, np.ndarray], outline: ObstacleOutline) -> None:
    """Give each axis of an orbit plot at least :data:`ORBIT_AXIS_FLOOR` of
    the plot's scale: the largest of the obstacle's extent and the motion."""
    y, z = (np.asarray(values, dtype=float) for values in data)
    along_y = [y, np.asarray(outline.vertical, float), [outline.gap_end[0]]]
    along_z = [z, np.asarray(outline.horizontal, float), [outline.gap_end[1]]]
    for curve_y, curve_z in outline.curves:
        along_y.append(np.asarray(curve_y, float))
        along_z.append(np.asarray(curve_z, float))
    ranges = []
    for parts in (along_y, along_z):
        values = np.concatenate([np.ravel(p) for p in parts])
        values = values[np.isfinite(values)]
        ranges.append((values.min(), values.max()) if values.size else (0.0, 0.0))
    scale = max(max(abs(lo), abs(hi), hi - lo) for lo, hi in ranges)
    if not scale > 0.0:
        return
    floor = ORBIT_AXIS_FLOOR * scale
    for (lo, hi), set_limits in zip(ranges, (axes.set_xlim, axes.set_ylim), strict=True):
        if hi - lo < floor:
            middle = 0.5 * (lo + hi)
            set_limits(middle - 0.5 * floor, middle + 0.5 * floor)


def wear_bars(rates: dict[str, float], floor: float = WEAR_NOISE_FLOOR) -> tuple[dict, dict]:
    """(the rates to draw, the rates drawn as zero): a rate whose size is at
    most ``floor`` times the largest is rounding noise, not wear."""
    largest = max((abs(r) for r in rates.values()), default=0.0)
    noise = {n: r for n, r in rates.items() if r != 0.0 and abs(r) <= floor * largest}
    drawn = {n: (0.0 if n in noise else r) for n, r in rates.items()}
    return drawn, noise


def wear_figure(tran: TranGene, wanted_names: list[str] | None = None):
    """Bar chart of the wear work rate (mean FN·|VT|) of each support. Rates
    below :data:`WEAR_NOISE_FLOOR` of the largest rate of the result (all its
    supports, also when only some are drawn) are drawn as zero, as the figure
    says: noise of 3e-14 W would otherwise fill the axes when drawn alone."""
    all_rates = wear_work_rates(tran)
    drawn, noise = wear_bars(all_rates)
    if wanted_names:
        names = dict(zip(map(id, tran.shocks), shock_names(tran), strict=True))
        wanted = [names[id(find_shock(tran, name))] for name in wanted_names]
        drawn = {name: drawn[name] for name in wanted}
        noise = {name: rate for name, rate in noise.items() if name in wanted}
    figure = _new_figure()
    axes = figure.add_subplot()
    axes.bar(list(drawn), list(drawn.values()), color="tab:orange")
    axes.set_xlabel("shock")
    axes.set_ylabel("wear work rate, mean FN·|VT| (W)")
    axes.set_title(f"{tran.name or 'tran_gene'}: wear work rate per support")
    axes.grid(True, axis="y", alpha=0.3)
    if noise:
        largest = max(abs(r) for r in all_rates.values())
        listed = ", ".join(f"{name} {rate:.2g} W" for name, rate in noise.items())
        axes.text(
            0.01,
            0.98,
            f"drawn as 0, below {WEAR_NOISE_FLOOR:g} x the largest rate ({largest:.4g} W):"
            f" {listed}",
            transform=axes.transAxes,
            ha="left",
            va="top",
            fontsize=8,
            wrap=True,
        )
    if not any(drawn.values()):
        axes.set_ylim(0.0, 1.0)  # no wear: an empty axis, not autoscaled noise
    return figure


def save_figure(figure, path: Path) -> Path:
    """Write a figure as PNG or SVG (chosen by the suffix)."""
    path = Path(path)
    if path.suffix.lower() not in IMAGE_FORMATS:
        raise PlotError(f"{path.name}: the image must end in {' or '.join(IMAGE_FORMATS)}")
    path.parent.mkdir(parents=True, exist_ok=True)
    figure.savefig(path, dpi=120)
    return path


# --------------------------------------------------------------- command


def figure_for(
    tran: TranGene,
    *,
    node: str | None = None,
    component: str | None = None,
    shock: str | None = None,
    quantity: str | None = None,
    field: str = "DEPL",
):
    """The figure an ``asterlite plot`` request asks for, and a file stem naming it."""
    if node is not None:
        if not component or shock is not None or quantity is not None:
            raise PlotError("--node needs --cmp (and no --shock/--quantity)")
        return node_history_figure(tran, node, component, field), f"{node}_{component}"
    stem = compact(shock) if shock else None  # a file name without blanks
    if quantity == "wear":
        names = [shock] if shock else None
        return wear_figure(tran, names), f"{stem or 'supports'}_wear"
    if shock is None:
        shocks = _listing([s.name for s in tran.shocks])
        raise PlotError(
            f"choose --node with --cmp, --shock NAME [--quantity FN|...|orbit|wear], "
            f"or --quantity wear (shocks: {shocks})"
        )
    if quantity == "orbit":
        return orbit_figure(tran, shock), f"{stem}_orbit"
    quantity = quantity or "FN"
    return shock_history_figure(tran, shock, quantity), f"{stem}_{quantity}"


def plot_from_store(
    store: Path,
    *,
    result: str | None = None,
    output: Path | None = None,
    **request,
) -> Path:
    """Load a tran_gene from an HDF5 store, draw what ``request`` asks for
    (see :func:`figure_for`) and save it; default file: next to the store,
    ``<store>_<what>.png``."""

    store = Path(store)
    try:
        tran = load_tran_gene(store, result)
    except KeyError as error:
        raise PlotError(error.args[0]) from None
    figure, stem = figure_for(tran, **request)
    path = output or store.with_name(f"{store.stem}_{tran.name}_{stem}.png")
    return save_figure(figure, path)


def _listing(names, limit: int = 12) -> str:
    names = [str(n) for n in names]
    more = f", ... ({len(names)} in all)" if len(names) > limit else ""
    return (", ".join(names[:limit]) or "none") + more


__all__ = [
    "ObstacleOutline",
    "PlotError",
    "figure_for",
    "node_history",
    "node_history_figure",
    "obstacle_outline",
    "orbit_figure",
    "plot_from_store",
    "save_figure",
    "shock_history_figure",
    "wear_bars",
    "wear_figure",
    "wear_work_rates",
]


# Grace's line styles, symbols and first colours, as IMPR_FONCTION numbers them
GRACE_LINESTYLES = {0: "None", 1: "-", 2: ":", 3: "--", 4: (0, (8, 4)), 5: "-.", 6: "-.", 7: "-."}
GRACE_SYMBOLS = {0: "", 1: "o", 2: "s", 3: "D", 4: "^", 5: "<", 6: "v", 7: ">", 8: "+", 9: "x"}
GRACE_COLOURS = {
    0: "white", 1: "black", 2: "red", 3: "green", 4: "blue", 5: "yellow", 6: "brown",
    7: "grey", 8: "violet", 9: "cyan", 10: "magenta", 11: "orange", 12: "indigo",
    13: "maroon", 14: "turquoise", 15: "darkgreen",
}  # fmt: skip


def _curve_style(style: dict) -> dict:
    """matplotlib options for IMPR_FONCTION's STYLE, COULEUR, MARQUEUR, FREQ_MARQUEUR."""
    options = {}
    if "STYLE" in style:
        options["linestyle"] = GRACE_LINESTYLES.get(int(style["STYLE"]), "-")
    if "COULEUR" in style:
        options["color"] = GRACE_COLOURS.get(int(style["COULEUR"]) % 16)
    if "MARQUEUR" in style:
        options["marker"] = GRACE_SYMBOLS.get(int(style["MARQUEUR"]), "*")
    if int(style.get("FREQ_MARQUEUR", 0)) > 0:
        options["markevery"] = int(style["FREQ_MARQUEUR"])
    return options


def curves_figure(curves, title: str = "", xlabel: str = "", ylabel: str = "", layout=None):
    """Figure of (x, y, legend[, style]) curves: the image IMPR_FONCTION draws;
    ``layout``: subtitle, axis scales, grid steps and bounds
    (asterlite.io.tables.grace_layout_lines)."""
    from matplotlib.ticker import MultipleLocator

    layout = layout or {}
    figure = _new_figure()
    axes = figure.add_subplot()
    for x, y, legend, *style in curves:
        axes.plot(x, y, label=legend or None, **_curve_style(style[0] if style else {}))
    subtitle = layout.get("subtitle")
    axes.set_title(f"{title}\n{subtitle}" if subtitle else title)
    axes.set_xlabel(xlabel)
    axes.set_ylabel(ylabel)
    for axis, ticks in (("x", axes.xaxis), ("y", axes.yaxis)):
        if layout.get(f"{axis}_scale") == "LOG":
            getattr(axes, f"set_{axis}scale")("log")
        elif layout.get(f"{axis}_grid"):
            ticks.set_major_locator(MultipleLocator(float(layout[f"{axis}_grid"])))
        if layout.get(f"{axis}_range") is not None:
            getattr(axes, f"set_{axis}lim")(*layout[f"{axis}_range"])
    axes.grid(alpha=0.3)
    if any(curve[2] for curve in curves):
        axes.legend()
    return figure
