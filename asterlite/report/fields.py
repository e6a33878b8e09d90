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
            fields["supports"] = list(session.summaries.supports)
    except Exception:  # noqa: BLE001 - extra information only, never a failed run
        pass
    return fields


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
