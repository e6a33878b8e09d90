"""``python3 -m asterlite``: the same program as the ``asterlite`` command.

``python -m`` puts the current folder first on the module search path: a
``json.py`` or ``numpy.py`` in a study folder someone sent would be
imported instead of the real module. The entry goes before anything else
is imported (``asterlite/__init__.py`` imports nothing); worker pools and
child interpreters are isolated too (:mod:`asterlite.isolation`).
"""

import os
import sys

if (
    sys.path
    and not sys.flags.safe_path
    and os.path.realpath(sys.path[0] or ".") == os.path.realpath(os.getcwd())
):
    del sys.path[0]

from asterlite.cli import main  # noqa: E402 - after the search path is made safe

raise SystemExit(main())
