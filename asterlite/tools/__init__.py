"""Tools that drive the run from outside it: they may import ``runtime/``,
nothing below them imports them.

- :mod:`~asterlite.tools.astest_check` checks every verification deck of a
  code_aster snapshot as ``asterlite check`` does (the acceptance test of
  the language data in :mod:`asterlite.catalog.language`).
"""
