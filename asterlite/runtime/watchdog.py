"""The run's limits moved to :mod:`asterlite.watchdog` (the package's base,
beside ``errors.py``, so that dynamics and io no longer climb up to
``runtime/``). This name stays only for ``asterlite/dynamics/`` until its
imports are switched (issue 28, item 4): it is the same module object, not
a copy, so the limits' state is shared."""

import sys

from asterlite import watchdog

sys.modules[__name__] = watchdog
