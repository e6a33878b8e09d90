"""Small inline SVG charts for the run report: lines, orbits, bars.

The report draws its own figures rather than asking matplotlib: the core
install has no matplotlib (it is the ``plot`` extra), one code path is the
one CI renders, and SVG keeps the page small, sharp at any zoom, and its
labels are text a browser can search and a test can read from the DOM.

Long series are thinned to a min/max envelope per horizontal pixel
(:func:`envelope`), so that every peak (an impact force) stays drawn.
"""

from __future__ import annotations

import math
from dataclasses import dataclass, field
from html import escape

import numpy as np

WIDTH, HEIGHT = 640, 360
MARGIN = {"left": 78, "right": 18, "top": 34, "bottom": 52}
COLOURS = ("#1f77b4", "#d62728", "#2ca02c", "#ff7f0e", "#9467bd", "#8c564b", "#e377c2", "#17becf")
OBSTACLE = "#111111"
GRID = "#e3e3e3"


@dataclass
class Series:
    label: str
    x: np.ndarray
    y: np.ndarray
    colour: str | None = None
    width: float = 1.3
    dashed: bool = False


@dataclass
class Chart:
    """A line chart: series, reference lines, labels and axis rules."""

    title: str
    x_label: str
    y_label: str
    series: list[Series] = field(default_factory=list)
    vertical: list[tuple[float, str]] = field(default_factory=list)  # (x, label)
    horizontal: list[tuple[float, str]] = field(default_factory=list)  # (y, label)
    equal_aspect: bool = False
    log_x: bool = False
    log_y: bool = False
    note: str = ""  # a line under the title, in a box (e.g. the gap)
    floor: float = 0.0  # an axis spans at least this fraction of the chart's scale


def nice_step(span: float, count: int = 6) -> float:
    """A round tick step (1, 2, 2.5 or 5 times a power of ten) giving about
    ``count`` ticks over ``span``."""
    if not span > 0 or not math.isfinite(span):
        return 1.0
    raw = span / count
    power = 10.0 ** math.floor(math.log10(raw))
    for factor in (1.0, 2.0, 2.5, 5.0, 10.0):
        if raw <= factor * power:
            return factor * power
    return 10.0 * power


def ticks(low: float, high: float, count: int = 6) -> list[float]:
    step = nice_step(high - low, count)
    first = math.ceil(low / step - 1e-9) * step
    values, value = [], first
    while value <= high + 1e-9 * step and len(values) < 50:
        values.append(0.0 if abs(value) < 1e-12 * step else value)
        value += step
    return values


def log_ticks(low: float, high: float) -> list[float]:
    return [10.0**k for k in range(math.floor(low), math.ceil(high) + 1) if low <= k <= high]


def tick_text(value: float, step: float) -> str:
    if value == 0.0:
        return "0"
    magnitude = abs(value)
    if magnitude >= 1e5 or magnitude < 1e-3:
        return f"{value:.3g}"
    decimals = max(
        0,
        -math.floor(math.log10(step))
        + (1 if step / 10.0 ** math.floor(math.log10(step)) == 2.5 else 0),
    )
    return f"{value:.{min(decimals, 6)}f}"


def envelope_index(y: np.ndarray, buckets: int = 1200) -> np.ndarray:
    """Indices of at most ~2 ``buckets`` samples of ``y``: each bucket of
    consecutive samples kept as its minimum and maximum, in order (peaks
    survive the thinning); every index when there are few."""
    y = np.asarray(y, float)
    n = len(y)
    if n <= 2 * buckets:
        return np.arange(n)
    edges = np.linspace(0, n, buckets + 1).astype(int)
    keep = {0, n - 1}
    for start, stop in zip(edges[:-1], edges[1:], strict=True):
        if stop <= start:
            continue
        chunk = y[start:stop]
        if not np.isfinite(chunk).any():
            keep.add(start)
            continue
        keep.add(start + int(np.nanargmin(chunk)))
        keep.add(start + int(np.nanargmax(chunk)))
    return np.array(sorted(keep), dtype=int)


def envelope(x: np.ndarray, y: np.ndarray, buckets: int = 1200) -> tuple[np.ndarray, np.ndarray]:
    """``(x, y)`` thinned by :func:`envelope_index`."""
    index = envelope_index(y, buckets)
    return np.asarray(x, float)[index], np.asarray(y, float)[index]


def path_index(x: np.ndarray, y: np.ndarray, max_points: int = 3000) -> np.ndarray:
    """Indices of a path in the plane (an orbit) thinned to about
    ``max_points``: every k-th point, plus where each coordinate reaches its
    extremes."""
    x, y = np.asarray(x, float), np.asarray(y, float)
    n = len(x)
    if n <= max_points:
        return np.arange(n)
    keep = set(range(0, n, math.ceil(n / max_points)))
    for values in (x, y):
        if np.isfinite(values).any():
            keep |= {int(np.nanargmin(values)), int(np.nanargmax(values))}
    keep.add(n - 1)
    return np.array(sorted(keep), dtype=int)


def _range(values: list[np.ndarray], log: bool) -> tuple[float, float]:
    parts = [np.asarray(v, float).ravel() for v in values if np.size(v)]
    data = np.concatenate(parts) if parts else np.zeros(0)
    data = data[np.isfinite(data)]
    if log:
        data = data[data > 0]
        if not data.size:
            return 0.0, 1.0
        return math.log10(data.min()), math.log10(data.max())
    if not data.size:
        return 0.0, 1.0
    return float(data.min()), float(data.max())


def _widen(low: float, high: float, floor: float, pad: float = 0.05) -> tuple[float, float]:
    span = high - low
    if span < floor:
        middle = 0.5 * (low + high)
        low, high, span = middle - 0.5 * floor, middle + 0.5 * floor, floor
    if span <= 0:
        size = abs(low) or 1.0
        return low - 0.5 * size, high + 0.5 * size
    return low - pad * span, high + pad * span


def render(chart: Chart, width: int = WIDTH, height: int = HEIGHT, chart_id: str = "") -> str:
    """The chart as an ``<svg>`` element (no external reference)."""
    left, top = MARGIN["left"], MARGIN["top"]
    plot_w = width - left - MARGIN["right"]
    plot_h = height - top - MARGIN["bottom"]
    xs = [s.x for s in chart.series] + [np.array([v for v, _ in chart.vertical])]
    ys = [s.y for s in chart.series] + [np.array([v for v, _ in chart.horizontal])]
    x_low, x_high = _range(xs, chart.log_x)
    y_low, y_high = _range(ys, chart.log_y)
    scale = max(abs(x_low), abs(x_high), abs(y_low), abs(y_high), x_high - x_low, y_high - y_low)
    floor = chart.floor * scale if not (chart.log_x or chart.log_y) else 0.0
    x_low, x_high = _widen(x_low, x_high, floor if chart.floor else 0.0, 0.02)
    y_low, y_high = _widen(y_low, y_high, floor if chart.floor else 0.0)
    if chart.equal_aspect:  # same metres per pixel on both axes
        per_pixel = max((x_high - x_low) / plot_w, (y_high - y_low) / plot_h)
        x_mid, y_mid = 0.5 * (x_low + x_high), 0.5 * (y_low + y_high)
        x_low, x_high = x_mid - 0.5 * per_pixel * plot_w, x_mid + 0.5 * per_pixel * plot_w
        y_low, y_high = y_mid - 0.5 * per_pixel * plot_h, y_mid + 0.5 * per_pixel * plot_h

    def px(value):
        value = np.log10(np.maximum(value, 1e-300)) if chart.log_x else value
        return left + (np.asarray(value, float) - x_low) / (x_high - x_low) * plot_w

    def py(value):
        value = np.log10(np.maximum(value, 1e-300)) if chart.log_y else value
        return top + plot_h - (np.asarray(value, float) - y_low) / (y_high - y_low) * plot_h

    out = [
        f'<svg xmlns="http://www.w3.org/2000/svg" class="chart" role="img" '
        f'viewBox="0 0 {width} {height}" width="{width}" height="{height}"'
        + (f' id="{escape(chart_id)}"' if chart_id else "")
        + f' aria-label="{escape(chart.title)}">',
        f'<rect x="0" y="0" width="{width}" height="{height}" fill="#ffffff"/>',
        f'<text x="{width / 2:.1f}" y="20" text-anchor="middle" class="title">'
        f"{escape(chart.title)}</text>",
    ]
    clip = f"clip{abs(hash((chart.title, chart_id))) % 10**8}"
    out.append(
        f'<clipPath id="{clip}"><rect x="{left}" y="{top}" width="{plot_w}" '
        f'height="{plot_h}"/></clipPath>'
    )
    # grid and ticks
    x_ticks = log_ticks(x_low, x_high) if chart.log_x else ticks(x_low, x_high)
    y_ticks = log_ticks(y_low, y_high) if chart.log_y else ticks(y_low, y_high)
    x_step = nice_step(x_high - x_low) if not chart.log_x else 1.0
    y_step = nice_step(y_high - y_low) if not chart.log_y else 1.0
    for value in x_ticks:
        x = float(px(value))
        out.append(
            f'<line x1="{x:.1f}" y1="{top}" x2="{x:.1f}" y2="{top + plot_h}" stroke="{GRID}"/>'
        )
        text = f"{value:.0e}" if chart.log_x else tick_text(value, x_step)
        out.append(
            f'<text x="{x:.1f}" y="{top + plot_h + 16}" text-anchor="middle" class="tick">'
            f"{escape(text)}</text>"
        )
    for value in y_ticks:
        y = float(py(value))
        out.append(
            f'<line x1="{left}" y1="{y:.1f}" x2="{left + plot_w}" y2="{y:.1f}" stroke="{GRID}"/>'
        )
        text = f"{value:.0e}" if chart.log_y else tick_text(value, y_step)
        out.append(
            f'<text x="{left - 6}" y="{y + 4:.1f}" text-anchor="end" class="tick">'
            f"{escape(text)}</text>"
        )
    out.append(
        f'<rect x="{left}" y="{top}" width="{plot_w}" height="{plot_h}" fill="none" stroke="#777"/>'
    )
    # reference lines (obstacle walls...)
    for value, label in chart.vertical:
        x = float(px(value))
        out.append(
            f'<line x1="{x:.1f}" y1="{top}" x2="{x:.1f}" y2="{top + plot_h}" '
            f'stroke="{OBSTACLE}" stroke-width="1.8"><title>{escape(label)}</title></line>'
        )
    for value, label in chart.horizontal:
        y = float(py(value))
        out.append(
            f'<line x1="{left}" y1="{y:.1f}" x2="{left + plot_w}" y2="{y:.1f}" '
            f'stroke="{OBSTACLE}" stroke-width="1.8"><title>{escape(label)}</title></line>'
        )
    # the series
    for k, series in enumerate(chart.series):
        colour = series.colour or COLOURS[k % len(COLOURS)]
        x, y = np.asarray(series.x, float), np.asarray(series.y, float)
        good = np.isfinite(x) & np.isfinite(y)
        if chart.log_x:
            good &= x > 0
        if chart.log_y:
            good &= y > 0
        points = np.column_stack([px(x[good]), py(y[good])]) if good.any() else np.zeros((0, 2))
        if not len(points):
            continue
        path = " ".join(f"{a:.1f},{b:.1f}" for a, b in points)
        dash = ' stroke-dasharray="6 4"' if series.dashed else ""
        out.append(
            f'<polyline clip-path="url(#{clip})" fill="none" stroke="{colour}" '
            f'stroke-width="{series.width}"{dash} points="{path}"><title>'
            f"{escape(series.label)}</title></polyline>"
        )
    # axis labels
    out.append(
        f'<text x="{left + plot_w / 2:.1f}" y="{height - 12}" text-anchor="middle" class="label">'
        f"{escape(chart.x_label)}</text>"
    )
    out.append(
        f'<text transform="translate(16 {top + plot_h / 2:.1f}) rotate(-90)" '
        f'text-anchor="middle" class="label">{escape(chart.y_label)}</text>'
    )
    # legend and note, on opaque boxes above the curves
    labelled = [(k, s) for k, s in enumerate(chart.series) if s.label]
    if len(labelled) > 1:
        box_h = 16 * len(labelled) + 8
        longest = max(len(s.label) for _, s in labelled)
        box_w = min(12 + 7 * longest + 26, plot_w - 10)
        x0, y0 = left + plot_w - box_w - 6, top + 6
        out.append(
            f'<rect x="{x0}" y="{y0}" width="{box_w}" height="{box_h}" fill="#fff" '
            f'fill-opacity="0.92" stroke="#bbb"/>'
        )
        for row, (k, series) in enumerate(labelled):
            colour = series.colour or COLOURS[k % len(COLOURS)]
            y = y0 + 14 + 16 * row
            out.append(
                f'<line x1="{x0 + 6}" y1="{y - 4}" x2="{x0 + 24}" y2="{y - 4}" '
                f'stroke="{colour}" stroke-width="2"/>'
            )
            out.append(f'<text x="{x0 + 30}" y="{y}" class="legend">{escape(series.label)}</text>')
    if chart.note:
        width_note = min(12 + 7 * len(chart.note), plot_w - 10)
        x0, y0 = left + 6, top + plot_h - 26
        out.append(
            f'<rect x="{x0}" y="{y0}" width="{width_note}" height="20" fill="#fff" '
            f'fill-opacity="0.92" stroke="#d62728"/>'
        )
        out.append(
            f'<text x="{x0 + 6}" y="{y0 + 14}" class="note" fill="#d62728">'
            f"{escape(chart.note)}</text>"
        )
    out.append("</svg>")
    return "\n".join(out)


def bars(
    title: str,
    labels: list[str],
    values: list[float],
    y_label: str,
    width: int = WIDTH,
    height: int = HEIGHT,
) -> str:
    """A bar chart (one bar per label), labels under the bars (slanted when long)."""
    left, top = MARGIN["left"], MARGIN["top"]
    longest = max((len(label) for label in labels), default=0)
    slanted = longest * 7 > (width - left - MARGIN["right"]) / max(len(labels), 1)
    bottom = min(40 + 5 * longest, 160) if slanted else MARGIN["bottom"]
    height = height + (bottom - MARGIN["bottom"])
    plot_w = width - left - MARGIN["right"]
    plot_h = height - top - bottom
    values = [float(v) if math.isfinite(float(v)) else 0.0 for v in values]
    high = max([0.0, *values])
    low = min([0.0, *values])
    if high == low:
        high = 1.0
    low, high = _widen(low, high, 0.0, 0.0)
    high += 0.05 * (high - low)

    def py(value):
        return top + plot_h - (value - low) / (high - low) * plot_h

    out = [
        f'<svg xmlns="http://www.w3.org/2000/svg" class="chart" role="img" '
        f'viewBox="0 0 {width} {height}" width="{width}" height="{height}" '
        f'aria-label="{escape(title)}">',
        f'<rect x="0" y="0" width="{width}" height="{height}" fill="#ffffff"/>',
        f'<text x="{width / 2:.1f}" y="20" text-anchor="middle" class="title">'
        f"{escape(title)}</text>",
    ]
    step = nice_step(high - low)
    for value in ticks(low, high):
        y = py(value)
        out.append(
            f'<line x1="{left}" y1="{y:.1f}" x2="{left + plot_w}" y2="{y:.1f}" stroke="{GRID}"/>'
        )
        out.append(
            f'<text x="{left - 6}" y="{y + 4:.1f}" text-anchor="end" class="tick">'
            f"{escape(tick_text(value, step))}</text>"
        )
    slot = plot_w / max(len(labels), 1)
    for k, (label, value) in enumerate(zip(labels, values, strict=True)):
        x = left + k * slot + 0.15 * slot
        y0, y1 = py(max(value, 0.0)), py(min(value, 0.0))
        out.append(
            f'<rect class="bar" x="{x:.1f}" y="{y0:.1f}" width="{0.7 * slot:.1f}" '
            f'height="{max(y1 - y0, 0.0):.1f}" fill="{COLOURS[3]}"><title>{escape(label)}: '
            f"{value:.4g}</title></rect>"
        )
        cx, cy = left + (k + 0.5) * slot, top + plot_h + 14
        if slanted:
            out.append(
                f'<text transform="translate({cx:.1f} {cy:.1f}) rotate(-35)" text-anchor="end" '
                f'class="tick">{escape(label)}</text>'
            )
        else:
            out.append(
                f'<text x="{cx:.1f}" y="{cy:.1f}" text-anchor="middle" class="tick">'
                f"{escape(label)}</text>"
            )
    out.append(
        f'<rect x="{left}" y="{top}" width="{plot_w}" height="{plot_h}" fill="none" stroke="#777"/>'
    )
    out.append(
        f'<text transform="translate(16 {top + plot_h / 2:.1f}) rotate(-90)" '
        f'text-anchor="middle" class="label">{escape(y_label)}</text>'
    )
    out.append("</svg>")
    return "\n".join(out)
