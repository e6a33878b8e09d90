"""The code_aster command language, per version, as data.

- :mod:`~asterlite.catalog.language.generate` writes
  ``catalogues/language/v<N>.json`` from code_aster's own catalogues
  (read by :mod:`~asterlite.catalog.language.reader` with :mod:`ast`, never
  executed; ``sd_prod`` functions read as decision tables by
  :mod:`~asterlite.catalog.language.sdprod`), converted to data by
  :mod:`~asterlite.catalog.language.convert` (shared with
  :mod:`~asterlite.catalog.language.legacy_layout`, code_aster 10-12's one
  ``cata.py``);
- :mod:`~asterlite.catalog.language.model` loads it lazily, one command at
  a time;
- :mod:`~asterlite.catalog.language.expression` evaluates the conditions
  of blocks and result types it holds, without ``eval``;
- :mod:`~asterlite.catalog.language.validate` checks a command call as
  code_aster's syntax checker does, reporting every finding.

Every verification deck of a code_aster snapshot is checked against this
data by :mod:`asterlite.tools.astest_check` (the acceptance test).

Nothing here imports numpy: ``asterlite check`` must start quickly.
"""
