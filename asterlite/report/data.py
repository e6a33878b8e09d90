"""What the run report shows, gathered from a live run or from its folder.

:class:`ReportData` holds the summary (``summary.json``'s dict), the
transient results (``tran_gene``: shocks, energy table), the curve sets
and the tail of ``message.log``. It comes from a run that just ended
(:func:`from_run`, ``asterlite run --report``) or from what a run left in
its folder (:func:`from_folder`, ``asterlite report OUTDIR``: summary.json,
results.h5 when the run saved it, curves.json, message.log).

Curve sets are the report's generic input for anything plotted against one
variable: the deck's functions (``RECU_FONCTION``, ``CALC_FONCTION``...),
harmonic responses (``harm_gene``, ``dyna_harmo``: amplitude against
frequency), and whatever a concept offers through a ``report_curves()``
method. A curve set is a plain dict, as curves.json stores it::

    {"title": "...", "x_label": "FREQ (Hz)", "y_label": "|DEPL N5 DY| (m)",
     "log_x": false, "log_y": true, "source": "HARMO",
     "series": [{"label": "N5 DY", "x": [...], "y": [...]}, ...]}
"""

from __future__ import annotations

import json
from dataclasses import dataclass, field
from pathlib import Path
from typing import Any

import numpy as np

from asterlite.concepts.base import Concept
from asterlite.concepts.function import Function
from asterlite.concepts.transient import TranGene
from asterlite.report.svg import envelope

CURVES_NAME = "curves.json"
LOG_TAIL_LINES = 400
MAX_POINTS = 4000  # per stored series (min/max envelope beyond)
MAX_CURVE_SETS = 24
HARMONIC_SERIES = 6  # the largest responses of a harmonic result


@dataclass
class ReportData:
    summary: dict
    results: list[tuple[str, Any]] = field(default_factory=list)  # (name, TranGene)
    curves: list[dict] = field(default_factory=list)
    log_tail: str = ""
    folder: Path | None = None
    notes: list[str] = field(default_factory=list)  # what could not be shown, and why


# ----------------------------------------------------------------- live run


def from_run(report, session, folder: Path | None = None) -> ReportData:
    """The data of a run that just ended (its session still in memory)."""

    summary = report.as_dict()
    results = []
    for name, concept in session.summaries.results_kept:
        if isinstance(concept, TranGene) and not any(r[0] == name for r in results):
            results.append((name, concept))
    data = ReportData(summary, results, collect_curves(session.namespace), folder=folder)
    if folder is not None:
        data.log_tail = log_tail(folder / "message.log")
    return data


def collect_curves(namespace: dict) -> list[dict]:
    """Curve sets of the deck's concepts, in the deck's order."""

    sets: list[dict] = []
    seen: set[int] = set()
    for name, concept in namespace.items():
        if not isinstance(concept, Concept) or id(concept) in seen:
            continue
        seen.add(id(concept))
        try:
            sets += curves_of(name, concept)
        except Exception:  # noqa: BLE001 - a concept that cannot be drawn is left out
            continue
        if len(sets) >= MAX_CURVE_SETS:
            break
    return sets[:MAX_CURVE_SETS]


def curves_of(name: str, concept) -> list[dict]:
    """The curve sets one concept gives (none for most)."""

    offered = getattr(type(concept), "report_curves", None)
    if callable(offered):
        return [thinned(curve) for curve in concept.report_curves()]
    if isinstance(concept, Function):
        return [function_curves(name, concept)]
    kinds = getattr(concept, "aster_types", ())
    if "harm_gene" in kinds or "dyna_harmo" in kinds:
        return harmonic_curves(name, concept)
    return []


def function_curves(name: str, function) -> dict:
    x = np.asarray(function.abscissas, dtype=float)
    y = np.asarray(function.ordinates)
    para, resu = str(function.NOM_PARA), str(function.NOM_RESU)
    if np.iscomplexobj(y):
        series = [{"label": f"|{name}|", "x": x, "y": np.abs(y)}]
        y_label = f"|{resu}|"
    else:
        series = [{"label": name, "x": x, "y": y.astype(float)}]
        y_label = resu
    return thinned(
        {
            "title": f"function {name}",
            "x_label": para,
            "y_label": y_label,
            "log_x": False,
            "log_y": _spans_decades(series),
            "source": name,
            "series": series,
        }
    )


def harmonic_curves(name: str, result) -> list[dict]:
    """Amplitude against frequency: for a harm_gene each generalized
    coordinate, for a dyna_harmo each DOF, the largest peaks first."""
    frequencies = np.asarray(result.frequencies, dtype=float)
    sets = []
    for field_name in ("DEPL", "VITE", "ACCE"):
        values = result.fields.get(field_name) if hasattr(result, "fields") else None
        if values is None or frequencies.size < 2:
            continue
        amplitude = np.abs(np.asarray(values))
        peaks = amplitude.max(axis=0)
        order = [int(k) for k in np.argsort(-peaks)[:HARMONIC_SERIES] if peaks[k] > 0]
        if "harm_gene" in result.aster_types:
            labels = [f"q{k + 1}" for k in order]
            what = "generalized coordinate"
        else:
            numbering = result.numbering
            mesh = getattr(numbering, "mesh", None)
            labels = []
            for k in order:
                node, component = numbering.dofs[k]
                node_name = mesh.node_names[node] if mesh is not None else str(node)
                labels.append(f"{node_name} {component}")
            what = "DOF"
        series = [
            {"label": label, "x": frequencies, "y": amplitude[:, k]}
            for label, k in zip(labels, order, strict=True)
        ]
        if not series:
            continue
        sets.append(
            thinned(
                {
                    "title": f"{name}: |{field_name}| per {what} (largest peaks)",
                    "x_label": "FREQ (Hz)",
                    "y_label": f"|{field_name}|",
                    "log_x": False,
                    "log_y": _spans_decades(series),
                    "source": name,
                    "series": series,
                }
            )
        )
        break  # the first field computed (DEPL when there is one)
    return sets


def _spans_decades(series: list[dict]) -> bool:
    values = np.concatenate([np.abs(np.asarray(s["y"], float)) for s in series])
    values = values[np.isfinite(values) & (values > 0)]
    if not values.size:
        return False
    lowest = min(float(np.nanmin(np.asarray(s["y"], float))) for s in series)
    return bool(values.max() / values.min() > 1.0e3 and lowest > 0)


def thinned(curve: dict) -> dict:
    """A curve set whose series hold plain lists, at most MAX_POINTS points
    each (a min/max envelope beyond: peaks kept)."""

    out = dict(curve)
    out["series"] = []
    for series in curve.get("series", []):
        x, y = envelope(series["x"], series["y"], MAX_POINTS // 2)
        out["series"].append({"label": str(series.get("label", "")), "x": x, "y": y})
    return out


# ----------------------------------------------------------------- a folder


def from_folder(folder: Path) -> ReportData:
    """The data a run left in its folder (summary.json is required)."""
    folder = Path(folder)
    summary_path = folder / "summary.json"
    if not summary_path.is_file():
        raise FileNotFoundError(f"{folder}: no summary.json (is it a run's output folder?)")
    summary = json.loads(summary_path.read_text(encoding="utf-8"))
    data = ReportData(summary, folder=folder, log_tail=log_tail(folder / "message.log"))
    store = folder / "results.h5"
    if store.is_file():
        from asterlite.io.result_store import load_tran_gene, stored_names

        try:
            data.results = [(name, load_tran_gene(store, name)) for name in stored_names(store)]
        except Exception as error:  # noqa: BLE001 - the rest of the page still helps
            data.notes.append(f"results.h5 could not be read: {error}")
    elif summary.get("shocks") or summary.get("transients"):
        data.notes.append(
            "no results.h5 in the folder: time histories, orbits and energy are drawn when "
            "the run saves its results (asterlite run --report, or --save-results)"
        )
    curves = folder / CURVES_NAME
    if curves.is_file():
        try:
            data.curves = json.loads(curves.read_text(encoding="utf-8")).get("curves", [])
        except ValueError as error:
            data.notes.append(f"{CURVES_NAME} could not be read: {error}")
    return data


def curves_json(curves: list[dict]) -> str:
    """curves.json's text."""

    def plain(value):
        if isinstance(value, np.ndarray):
            return [None if not np.isfinite(v) else float(v) for v in value.astype(float)]
        if isinstance(value, (np.floating, np.integer, np.bool_)):
            return value.item()
        if isinstance(value, dict):
            return {k: plain(v) for k, v in value.items()}
        if isinstance(value, list):
            return [plain(v) for v in value]
        return value

    return json.dumps({"curves": plain(curves)})


def log_tail(path: Path, lines: int = LOG_TAIL_LINES) -> str:
    try:
        with open(path, "rb") as stream:
            stream.seek(0, 2)
            size = stream.tell()
            stream.seek(max(0, size - 200_000))
            text = stream.read().decode("utf-8", "replace")
    except OSError:
        return ""
    return "\n".join(text.splitlines()[-lines:])
