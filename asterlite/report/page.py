"""The run report: one self-contained HTML page (no network, no script).

Sections, each present when the run has something for it: the verdict
(status, message, the note of a variant), the checks (VALE_REFE and
VALE_CALC apart, strict or not), the transients, shock statistics per
support with the wear chart, per shock its orbit in the obstacle plane and
its impact force, the energy balance (``ENERGIE``), curves (the deck's
functions, harmonic responses), the command timings, and the tail of
message.log. Every figure is inline SVG (:mod:`asterlite.report.svg`)
followed by its data as a CSV download (a ``data:`` link).
"""

from __future__ import annotations

import base64
import html
import io
import math
import time
from pathlib import Path

import numpy as np

from asterlite.post.plots import ORBIT_AXIS_FLOOR, is_two_node, obstacle_outline
from asterlite.report import svg
from asterlite.report.data import ReportData
from asterlite.version import __version__

GENERATOR = "asterlite report"
MAX_SHOCK_FIGURES = 8  # shocks drawn one by one (the largest forces first)
MAX_CSV_ROWS = 20_000
STATUS_COLOURS = {
    "PASS": "#1a7f37",
    "DONE": "#1a7f37",
    "NOOK": "#c2410c",
    "ERROR": "#b91c1c",
    "UNSUPPORTED": "#7c3aed",
    "INTERRUPTED": "#b91c1c",
    "KILLED": "#b91c1c",  # a run settled after it died (asterlite status)
    "RUNNING": "#555",
}

CSS = """
body{font-family:-apple-system,"Segoe UI",Helvetica,Arial,sans-serif;margin:0;color:#1f2328;
background:#f6f8fa}
main{max-width:1380px;margin:0 auto;padding:18px 24px 40px}
h1{font-size:22px;margin:6px 0 4px}h2{font-size:18px;margin:28px 0 8px;border-bottom:1px solid
#d0d7de;padding-bottom:4px}h3{font-size:15px;margin:16px 0 6px}
.status{display:inline-block;color:#fff;font-weight:700;padding:3px 12px;border-radius:14px;
font-size:16px;vertical-align:middle}
.meta{color:#57606a;font-size:13px}.note{background:#fff8c5;border:1px solid #d4a72c;
padding:8px 12px;border-radius:6px;margin:10px 0;font-size:14px}
pre{background:#fff;border:1px solid #d0d7de;padding:10px;overflow:auto;font-size:12px;
max-height:480px}
table{border-collapse:collapse;background:#fff;font-size:12px;margin:6px 0}
th,td{border:1px solid #d0d7de;padding:3px 7px;text-align:left;vertical-align:top}
th{background:#eaeef2}td.num{text-align:right;font-variant-numeric:tabular-nums;
font-family:ui-monospace,Menlo,Consolas,monospace}
td.ok{background:#dafbe1;color:#116329;font-weight:600}td.nook{background:#ffebe9;
color:#a40e26;font-weight:600}td.none{color:#8c959f}
.figures{display:flex;flex-wrap:wrap;gap:14px}figure{margin:0;background:#fff;
border:1px solid #d0d7de;padding:6px}figcaption{font-size:12px;color:#57606a;padding:2px 4px}
figcaption a{color:#0969da}
svg.chart text{font-family:Helvetica,Arial,sans-serif}svg.chart .title{font-size:13px;
font-weight:600}svg.chart .tick{font-size:11px;fill:#444}svg.chart .label{font-size:12px}
svg.chart .legend{font-size:11px}svg.chart .note{font-size:12px;font-weight:600}
.tbar{display:inline-block;height:9px;background:#0969da;vertical-align:middle}
"""


def esc(value) -> str:
    return html.escape("" if value is None else str(value))


def num(value, digits: int = 6) -> str:
    if value is None:
        return ""
    if isinstance(value, (list, tuple)) and len(value) == 2:  # a complex value
        return f"{num(value[0], digits)}{value[1]:+.{digits}g}j"
    if isinstance(value, bool):
        return str(value)
    if isinstance(value, (int, float, np.floating, np.integer)):
        value = float(value)
        if not math.isfinite(value):
            return str(value)
        return f"{value:.{digits}g}"
    return str(value)


def csv_link(name: str, columns: list[str], rows, of: int | None = None) -> str:
    """A download link holding the figure's data as CSV (a data: URI): the
    points drawn (``of``: how many the result archived when the figure shows
    fewer, its extremes kept; results.h5 holds them all)."""
    text = io.StringIO()
    text.write(",".join(columns) + "\n")
    count = 0
    for row in rows:
        text.write(
            ",".join(
                "" if v is None else (repr(float(v)) if _is_number(v) else f'"{v}"') for v in row
            )
            + "\n"
        )
        count += 1
        if count >= MAX_CSV_ROWS:
            break
    encoded = base64.b64encode(text.getvalue().encode()).decode()
    return (
        f'<a class="csv" download="{esc(name)}.csv" '
        f'href="data:text/csv;charset=utf-8;base64,{encoded}">data (CSV, {count} rows)</a>'
        + (f" drawn of {of} archived (extremes kept)" if of is not None and of > count else "")
    )


def _is_number(value) -> bool:
    return isinstance(value, (int, float, np.floating, np.integer)) and not isinstance(value, bool)


def figure(svg_text: str, caption: str, csv: str = "") -> str:
    link = f" {csv}" if csv else ""
    return f"<figure>{svg_text}<figcaption>{esc(caption)}{link}</figcaption></figure>"


def series_csv(name: str, series: list[svg.Series], x_name: str, of: int | None = None) -> str:
    """CSV of series sharing an abscissa when they do, else long form."""
    if series and all(
        len(s.x) == len(series[0].x) and np.array_equal(s.x, series[0].x) for s in series
    ):
        columns = [x_name] + [s.label or f"y{k + 1}" for k, s in enumerate(series)]
        rows = zip(series[0].x, *[s.y for s in series], strict=True)
        return csv_link(name, columns, rows, of=of)
    rows = ((s.label, x, y) for s in series for x, y in zip(s.x, s.y, strict=True))
    return csv_link(name, ["series", x_name, "value"], rows)


# ------------------------------------------------------------------ sections


def header(data: ReportData) -> str:
    s = data.summary
    status = str(s.get("status", "?"))
    colour = STATUS_COLOURS.get(status, "#555")
    checks = ""
    if s.get("checks_total"):
        checks = f" &middot; checks {s.get('checks_ok')}/{s.get('checks_total')} OK"
    out = [
        f"<h1>{esc(s.get('deck', 'deck'))} "
        f'<span class="status" id="status" style="background:{colour}">{esc(status)}</span></h1>',
        f'<div class="meta">{num(s.get("seconds"), 4)} s{checks} &middot; asterlite '
        f"{esc(_version())} &middot; report written {esc(time.strftime('%Y-%m-%d %H:%M:%S'))}"
        + (f" &middot; folder {esc(Path(data.folder).resolve())}" if data.folder else "")
        + "</div>",
    ]
    if s.get("overrides"):
        changed = ", ".join(f"{k}={v!r}" for k, v in s["overrides"].items())
        out.append(f'<div class="meta">variables set for this run: {esc(changed)}</div>')
    if s.get("message"):
        out.append(f'<pre id="message">{esc(s["message"])}</pre>')
    if s.get("note"):
        out.append(f'<div class="note" id="note">{esc(s["note"])}</div>')
    for note in data.notes:
        out.append(f'<div class="note">{esc(note)}</div>')
    return "\n".join(out)


def _version() -> str:
    return __version__


def verdict_cell(comparison) -> str:
    if not comparison:
        return '<td class="none" colspan="4">-</td>'
    ok = bool(comparison.get("ok"))
    return (
        f'<td class="num">{num(comparison.get("expected"), 10)}</td>'
        f'<td class="num">{num(comparison.get("error"), 3)}</td>'
        f'<td class="num">{num(comparison.get("tolerance"), 3)}</td>'
        f'<td class="{"ok" if ok else "nook"}">{"OK" if ok else "NOOK"}</td>'
    )


def checks_section(data: ReportData) -> str:
    s = data.summary
    tests = s.get("tests") or []
    if not tests:
        return (
            '<h2 id="checks">Checks</h2><p>The deck makes no TEST_* check: its status is '
            f"{esc(s.get('status'))} (DONE: ran to its end).</p>"
        )
    verdicts = s.get("verdicts") or {}

    def count(kind):
        c = verdicts.get(kind) or {}
        return f"{c.get('ok', 0)}/{c.get('total', 0)}" if c.get("total") else "-"

    lines = s.get("test_lines") or [None] * len(tests)
    rows = []
    for k, (test, line) in enumerate(zip(tests, lines, strict=False)):
        comparisons = test.get("comparisons") or {}
        ok = bool(test.get("ok"))
        strict = "yes" if test.get("strict") else "no"
        rows.append(
            "<tr>"
            f'<td class="num">{k + 1}</td><td class="num">{esc(line or "")}</td>'
            f"<td>{esc(test.get('command'))}</td><td>{esc(test.get('label'))}</td>"
            f'<td class="num">{num(test.get("value"), 12)}</td>'
            f"<td>{esc(test.get('reference'))}</td>"
            f"{verdict_cell(comparisons.get('VALE_REFE'))}"
            f"{verdict_cell(comparisons.get('VALE_CALC'))}"
            f'<td class="{"ok" if ok else "nook"}">{"OK" if ok else "NOOK"}</td>'
            f"<td>{strict}</td></tr>"
        )
    return (
        '<h2 id="checks">Checks</h2>'
        f"<p>{s.get('checks_ok')}/{s.get('checks_total')} OK, {s.get('strict_ok')} strict "
        "(also within code_aster's own tolerance) &middot; VALE_REFE (independent references): "
        f"{count('VALE_REFE')} hold &middot; VALE_CALC (non-regression against the deck's "
        f"computed values): {count('VALE_CALC')} hold</p>"
        '<table id="checks-table"><thead><tr><th rowspan="2">#</th><th rowspan="2">line</th>'
        '<th rowspan="2">command</th><th rowspan="2">what</th><th rowspan="2">value</th>'
        '<th rowspan="2">reference</th><th colspan="4">VALE_REFE</th>'
        '<th colspan="4">VALE_CALC</th><th rowspan="2">verdict</th><th rowspan="2">strict</th>'
        "</tr><tr><th>expected</th><th>error</th><th>tolerance</th><th></th><th>expected</th>"
        "<th>error</th><th>tolerance</th><th></th></tr></thead><tbody>"
        + "".join(rows)
        + "</tbody></table>"
    )


def timings_section(data: ReportData) -> str:
    commands = data.summary.get("commands") or []
    if not commands:
        return ""
    longest = max((c.get("seconds") or 0.0 for c in commands), default=0.0) or 1.0
    rows = "".join(
        f'<tr><td>{esc(c.get("command"))}</td><td class="num">{esc(c.get("line"))}</td>'
        f'<td>{esc(c.get("result") or "")}</td><td class="num">{num(c.get("seconds"), 4)}</td>'
        f'<td><span class="tbar" style="width:{200 * (c.get("seconds") or 0) / longest:.0f}px">'
        "</span></td></tr>"
        for c in commands
    )
    return (
        '<h2 id="timings">Commands</h2><table id="timings-table"><thead><tr><th>command</th>'
        "<th>line</th><th>result</th><th>seconds</th><th></th></tr></thead><tbody>"
        + rows
        + "</tbody></table>"
    )


def transients_section(data: ReportData) -> str:
    runs = data.summary.get("transients") or []
    if not runs:
        return ""
    rows = []
    for run in runs:
        energy = ""
        if run.get("energy_residual") is not None:
            energy = (
                f"{num(run['energy_residual'], 4)} J ("
                f"{num(run.get('energy_residual_ratio'), 3)} of the largest total energy)"
            )
        rows.append(
            f"<tr><td>{esc(run.get('result'))}</td><td>{esc(run.get('scheme'))}</td>"
            f'<td class="num">{esc(run.get("steps"))}</td>'
            f'<td class="num">{esc(run.get("rejected_steps"))}</td>'
            f'<td class="num">{num(run.get("min_step"), 4)}..{num(run.get("max_step"), 4)}</td>'
            f'<td class="num">{num(run.get("t_start"), 6)}..{num(run.get("t_end"), 6)}</td>'
            f'<td class="num">{num(run.get("integration_seconds"), 4)}</td><td>{energy}</td></tr>'
        )
    return (
        '<h2 id="transients">Transients</h2><table><thead><tr><th>result</th><th>scheme</th>'
        "<th>steps</th><th>rejected</th><th>step (s)</th><th>time (s)</th>"
        "<th>integration (s)</th><th>energy residual</th></tr></thead><tbody>"
        + "".join(rows)
        + "</tbody></table>"
    )


def shocks_section(data: ReportData) -> str:
    shocks = data.summary.get("shocks") or []
    if not shocks:
        return ""
    supports = data.summary.get("supports") or []
    rows = []
    for k, shock in enumerate(shocks):
        support = supports[k] if k < len(supports) else {}
        nodes = " - ".join(n for n in (support.get("node_1"), support.get("node_2")) if n)
        rows.append(
            f"<tr><td>{esc(shock.get('result'))}</td><td>{esc(shock.get('shock'))}</td>"
            f"<td>{esc(support.get('relation', ''))}</td><td>{esc(nodes)}</td>"
            f"<td>{esc(support.get('obstacle') or '')}</td>"
            f'<td class="num">{num(support.get("gap"), 4)}</td>'
            f'<td class="num">{esc(shock.get("impacts"))}</td>'
            f'<td class="num">{num(shock.get("max_FN"), 5)}</td>'
            f'<td class="num">{num(shock.get("mean_FN"), 5)}</td>'
            f'<td class="num">{100 * float(shock.get("contact_fraction") or 0):.1f} %</td>'
            f'<td class="num">{num(shock.get("wear_power"), 5)}</td></tr>'
        )
    title = '<h2 id="shocks">Shocks per support</h2><p>From the archived instants.</p>'
    head = (
        '<table id="shocks-table"><thead><tr><th>result</th><th>shock</th><th>relation</th>'
        "<th>nodes</th><th>obstacle</th><th>gap (m)</th><th>impacts</th><th>max FN (N)</th>"
        "<th>mean FN (N)</th><th>contact</th><th>wear power (W)</th></tr></thead><tbody>"
        + "".join(rows)
        + "</tbody></table>"
    )
    labels = [
        (f"{s.get('result')}/" if len({x.get("result") for x in shocks}) > 1 else "")
        + str(s.get("shock")).replace("        ", " ")
        for s in shocks
    ]
    wear = [float(s.get("wear_power") or 0.0) for s in shocks]
    if not any(wear):
        return (
            title
            + head
            + "<p>The wear work rate is 0 at every support (no friction, or no sliding).</p>"
        )
    chart = svg.bars("wear work rate per support", labels, wear, "mean FN·|VT| (W)")
    csv = csv_link(
        "wear",
        ["result", "shock", "impacts", "max_FN_N", "mean_FN_N", "contact_fraction", "wear_W"],
        (
            [s.get("result"), s.get("shock"), s.get("impacts"), s.get("max_FN"),
             s.get("mean_FN"), s.get("contact_fraction"), s.get("wear_power")]
            for s in shocks
        ),
    )  # fmt: skip
    return (
        title
        + '<div class="figures"><div>'
        + head
        + "</div>"
        + figure(chart, "Archard wear work rate, code_aster's PUIS_USURE", csv)
        + "</div>"
    )


def orbit_chart(tran_name: str, shock) -> tuple[svg.Chart, str, np.ndarray] | None:
    """The orbit's chart, the field prefix (LOC, or REL for two nodes) and
    the archived instants drawn."""

    prefix = "REL" if is_two_node(shock) else "LOC"
    fields = shock.fields
    if f"DY{prefix}" not in fields or f"DZ{prefix}" not in fields:
        return None
    y = np.asarray(fields[f"DY{prefix}"], float)
    z = np.asarray(fields[f"DZ{prefix}"], float)
    drawn = svg.path_index(y, z)
    outline = obstacle_outline(dict(shock.parameters or {}))
    relative = " (node 1 - node 2)" if prefix == "REL" else ""
    kind = (shock.parameters or {}).get("OBSTACLE", "?")
    chart = svg.Chart(
        title=f"{tran_name}: orbit at {shock.name.strip()} ({kind})",
        x_label=f"local y{relative} (m)",
        y_label=f"local z{relative} (m)",
        series=[svg.Series("orbit", y[drawn], z[drawn])],
        vertical=[(v, "obstacle") for v in outline.vertical],
        horizontal=[(v, "obstacle") for v in outline.horizontal],
        equal_aspect=outline.equal_aspect,
        note=outline.gap_label,
        floor=ORBIT_AXIS_FLOOR,
    )
    for curve_y, curve_z in outline.curves:
        chart.series.append(
            svg.Series("obstacle", curve_y, curve_z, colour=svg.OBSTACLE, width=1.8)
        )
    return chart, prefix, drawn


def shock_figures(data: ReportData) -> str:
    out = []
    for tran_name, tran in data.results:
        shocks = [s for s in tran.shocks if "FN" in s.fields]
        if not shocks:
            continue
        peaks = [
            float(np.max(np.abs(np.asarray(s.fields["FN"], float)), initial=0.0)) for s in shocks
        ]
        order = sorted(range(len(shocks)), key=lambda k: -peaks[k])[:MAX_SHOCK_FIGURES]
        times = np.asarray(tran.times, float)
        out.append(f"<h3>{esc(tran_name)}: orbits and impact forces</h3>")
        if len(shocks) > len(order):
            out.append(f"<p>The {len(order)} shocks of largest peak force, of {len(shocks)}.</p>")
        out.append('<div class="figures">')
        for k in sorted(order):
            shock = shocks[k]
            title = shock.name.strip()
            made = orbit_chart(tran_name, shock)
            if made is not None:
                chart, prefix, drawn = made
                y = np.asarray(shock.fields[f"DY{prefix}"], float)[drawn]
                z = np.asarray(shock.fields[f"DZ{prefix}"], float)[drawn]
                csv = csv_link(
                    f"{tran_name}_{_file(title)}_orbit",
                    ["INST", f"DY{prefix}", f"DZ{prefix}"],
                    zip(times[drawn], y, z, strict=True),
                    of=len(times),
                )
                out.append(figure(svg.render(chart, 460, 400), f"orbit, {title}", csv))
            fn = np.asarray(shock.fields["FN"], float)
            drawn = svg.envelope_index(fn)
            chart = svg.Chart(
                title=f"{tran_name}: impact force at {title}",
                x_label="time (s)",
                y_label="FN (N)",
                series=[svg.Series("FN", times[drawn], fn[drawn])],
            )
            rows = zip(times[drawn], fn[drawn], strict=True)
            csv = csv_link(f"{tran_name}_{_file(title)}_FN", ["INST", "FN"], rows, of=len(times))
            out.append(figure(svg.render(chart, 560, 400), f"normal force, {title}", csv))
        out.append("</div>")
    return ('<h2 id="shock-figures">Orbits and forces</h2>' + "".join(out)) if out else ""


def _file(text: str) -> str:
    return "".join(c if c.isalnum() or c in "-_" else "_" for c in text)


def energy_section(data: ReportData) -> str:
    out = []
    for tran_name, tran in data.results:
        table = (getattr(tran, "tables", None) or {}).get("PARA_CALC")
        if table is None or "INST" not in table.columns:
            continue
        columns = [c for c in table.columns if c != "INST"]
        times = np.array([row.get("INST", np.nan) for row in table.rows], float)
        values = {
            name: np.array([row.get(name, np.nan) for row in table.rows], float) for name in columns
        }
        drawn = np.unique(np.concatenate([svg.envelope_index(v, 600) for v in values.values()]))
        series = [
            svg.Series(name, times[drawn], v[drawn], dashed=name == "RESIDU")
            for name, v in values.items()
        ]
        chart = svg.Chart(
            title=f"{tran_name}: energy balance (ENERGIE)",
            x_label="time (s)",
            y_label="energy (J)",
            series=series,
        )
        csv = series_csv(f"{tran_name}_energy", series, "INST", of=len(times))
        out.append(figure(svg.render(chart, 760, 420), "energy balance (PARA_CALC table)", csv))
    if not out:
        return ""
    return '<h2 id="energy">Energy balance</h2><div class="figures">' + "".join(out) + "</div>"


def curves_section(data: ReportData) -> str:
    if not data.curves:
        return ""
    out = []
    for k, curve in enumerate(data.curves):
        series = [
            svg.Series(s.get("label", ""), np.asarray(s["x"], float), np.asarray(s["y"], float))
            for s in curve.get("series", [])
        ]
        if not series:
            continue
        chart = svg.Chart(
            title=str(curve.get("title", f"curve {k + 1}")),
            x_label=str(curve.get("x_label", "")),
            y_label=str(curve.get("y_label", "")),
            series=series,
            log_x=bool(curve.get("log_x")),
            log_y=bool(curve.get("log_y")),
        )
        csv = series_csv(f"curve_{k + 1}_{_file(str(curve.get('source', '')))}", series,
                         str(curve.get("x_label", "x")))  # fmt: skip
        out.append(figure(svg.render(chart, 560, 380), str(curve.get("title", "")), csv))
    return (
        '<h2 id="curves">Curves</h2><p>The deck\'s functions and harmonic responses.</p>'
        '<div class="figures">' + "".join(out) + "</div>"
    )


def log_section(data: ReportData) -> str:
    if not data.log_tail:
        return ""
    return (
        '<h2 id="log">message.log</h2><details><summary>its last lines</summary>'
        f"<pre>{esc(data.log_tail)}</pre></details>"
    )


def render(data: ReportData) -> str:
    s = data.summary
    body = [
        header(data),
        checks_section(data),
        transients_section(data),
        shocks_section(data),
        shock_figures(data),
        energy_section(data),
        curves_section(data),
        timings_section(data),
        log_section(data),
    ]
    return (
        '<!DOCTYPE html>\n<html lang="en"><head><meta charset="utf-8">'
        f'<meta name="generator" content="{GENERATOR}">'
        '<meta name="viewport" content="width=device-width, initial-scale=1">'
        '<meta http-equiv="Content-Security-Policy" content="default-src \'none\'; '
        "img-src data:; style-src 'unsafe-inline'\">"
        f"<title>{esc(s.get('deck', 'run'))}: {esc(s.get('status'))} - asterlite report</title>"
        f"<style>{CSS}</style></head><body><main>\n"
        + "\n".join(part for part in body if part)
        + "\n</main></body></html>\n"
    )
