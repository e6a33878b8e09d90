"""What ``summary.json`` and message.log's summary get beyond the runner's
own fields, for the reader and for the run report (``asterlite report``).

:func:`summary_fields` is called by :mod:`asterlite.runtime.runner` when a
run ends (``RunReport.extras``, merged into ``summary.json``):

- ``verdicts``: the VALE_REFE and VALE_CALC comparisons counted apart
  (:mod:`asterlite.runtime.verdicts`);
- ``deck_values`` and ``note``: for a run with deck variables replaced
  (``sweep``, the Python API), the deck's own values of them and why the
  run is NOOK when only its VALE_CALC checks fail;
- ``test_lines``: the deck line of each check, in the order of ``tests``;
- ``supports``: per shock, in the order of ``shocks``: its relation, nodes,
  obstacle and gap.

It must never stop a run: anything it cannot work out is left out.
"""

from __future__ import annotations

from asterlite.runtime import verdicts as V
from asterlite.runtime.verdicts import CALC, REFE, verdict_text


def summary_fields(report, session) -> dict:
    fields: dict = {}
    try:
        overrides = dict(getattr(report, "overrides", None) or {})
        fields["verdicts"] = V.verdicts(report.tests)
        fields["test_lines"] = [
            t.location.line if getattr(t, "location", None) is not None else None
            for t in report.tests
        ]
        if overrides:
            deck_files = getattr(getattr(session, "run", None), "deck_files", None)
            assignments = V.deck_assignments(deck_files, overrides)
            fields["deck_values"] = assignments
            note = V.variant_note(report.tests, overrides, assignments)
            if note:
                fields["note"] = note
        if report.shocks:
            fields["supports"] = supports(getattr(session, "produced", ()))
    except Exception:  # noqa: BLE001 - extra information only, never a failed run
        pass
    return fields


def supports(produced) -> list[dict]:
    """Per shock of the run's tran_gene results (the order of the runner's
    ``shocks``): relation, nodes, obstacle, gap and normal stiffness."""
    from asterlite.concepts.transient import TranGene

    rows = []
    for _, name, concept in produced:
        if not isinstance(concept, TranGene):
            continue
        for shock in concept.shocks:
            parameters = shock.parameters or {}
            rows.append(
                {
                    "result": name,
                    "shock": shock.name,
                    "relation": shock.relation,
                    "node_1": shock.node_1,
                    "node_2": shock.node_2,
                    "obstacle": _plain(parameters.get("OBSTACLE")),
                    "gap": _plain(parameters.get("JEU")),
                    "stiffness": _plain(parameters.get("RIGI_NOR")),
                }
            )
    return rows


def _plain(value):
    if value is None:
        return None
    if hasattr(value, "item"):
        try:
            return value.item()
        except (ValueError, AttributeError):
            return str(value)
    return value if isinstance(value, (int, float, str, bool)) else str(value)


def summary_lines(report) -> list[str]:
    """The lines message.log's summary gets (after the checks): the two
    kinds of comparison counted apart, and the note of a variant."""

    extras = getattr(report, "extras", None) or {}
    if not report.tests or "verdicts" not in extras:
        return []
    counts = extras["verdicts"]
    lines = [
        f"  VALE_REFE (references): {verdict_text(counts, REFE)} hold;"
        f" VALE_CALC (non-regression): {verdict_text(counts, CALC)} hold"
    ]
    if extras.get("note"):
        lines.append(f"  note: {extras['note']}")
    return lines
