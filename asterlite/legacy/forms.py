"""The ``compat_syntax`` objects catalogues hang on their commands.

A :class:`LegacyForm` says when a call is written in a legacy form
(``detect``), which catalogue checks it as written (``legacy_catalogue``:
the command's own for a renamed command, a legacy catalogue for a command
whose keywords changed, or none when the modern catalogue checks it after
translation) and how it becomes a modern call (``translate``).
"""

from __future__ import annotations

from collections.abc import Callable

from asterlite.legacy import dyna, misc, modes
from asterlite.legacy.base import Env, Translation

OWN = "own"  # the legacy command's own catalogue checks the call as written


class LegacyForm:
    """A command's ``compat_syntax``: ``form(kwargs, env) -> Translation | None``."""

    def __init__(
        self,
        translate: Callable[[dict, Env], Translation],
        *,
        detect: Callable[[dict, Env], bool] | None = None,
        legacy_catalogue=None,
    ):
        self.translate = translate
        self.detect = detect
        self._legacy_catalogue = legacy_catalogue

    def __call__(self, kwargs: dict, env: Env) -> Translation | None:
        if self.detect is not None and not self.detect(kwargs, env):
            return None
        return self.translate(kwargs, env)

    def legacy_catalogue(self, own):
        """The catalogue a legacy call is validated against before translating."""
        found = self._legacy_catalogue
        if found == OWN:
            return own
        return found() if callable(found) else found


def _legacy_dyna_vibra():
    from asterlite.catalogues.common_legacy import DYNA_VIBRA_V13

    return DYNA_VIBRA_V13


DYNA_TRAN_MODAL = LegacyForm(dyna.translate_dyna_tran_modal, legacy_catalogue=OWN)
DYNA_VIBRA = LegacyForm(
    dyna.translate_dyna_vibra, detect=dyna.is_legacy_dyna_vibra, legacy_catalogue=_legacy_dyna_vibra
)
MODE_ITER_SIMULT = LegacyForm(modes.translate_mode_iter_simult, legacy_catalogue=OWN)
MODE_ITER_INV = LegacyForm(modes.translate_mode_iter_inv, legacy_catalogue=OWN)
LIRE_MAILLAGE = LegacyForm(misc.translate_lire_maillage, detect=misc.is_legacy_lire_maillage)
START = LegacyForm(misc.translate_start, detect=misc.is_legacy_start)
