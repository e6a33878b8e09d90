"""The legacy forms of commands (code_aster's ``compat_syntax``), by command name.

A :class:`LegacyForm` says when a call is written in a legacy form
(``detect``), which catalogue checks it as written (``legacy_catalogue``:
the command's own for a renamed command, a legacy catalogue for a command
whose keywords changed, or none when the modern catalogue checks it after
translation) and how it becomes a modern call (``translate``).

:func:`legacy_form` looks a command's form up in :data:`FORMS`: the run, the
porter and ``asterlite check`` ask it; the catalogues do not know the
version layer.
"""

from __future__ import annotations

from collections.abc import Callable

from asterlite.legacy import dyna, dyna_line_v11, macros_v11, misc, modes, v15
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

    def legacy_catalogue(self, own, kwargs=None, env=None):
        """The catalogue a legacy call is validated against before translating."""
        found = self._legacy_catalogue
        if found == OWN:
            return own
        return found() if callable(found) else found


class FirstOf(LegacyForm):
    """The first of several legacy forms of a command whose ``detect`` accepts the call
    (a command that changed more than once: DYNA_VIBRA of code_aster 13 and of 15)."""

    def __init__(self, *forms: LegacyForm):
        self.forms = forms
        super().__init__(self._translate, detect=lambda kw, env: self._form(kw, env) is not None)

    def _form(self, kwargs: dict, env: Env) -> LegacyForm | None:
        for form in self.forms:
            if form.detect is None or form.detect(kwargs, env):
                return form
        return None

    def _translate(self, kwargs: dict, env: Env) -> Translation | None:
        form = self._form(kwargs, env)
        return None if form is None else form.translate(kwargs, env)

    def legacy_catalogue(self, own, kwargs=None, env=None):
        form = self._form(kwargs or {}, env) if env is not None else None
        return None if form is None else form.legacy_catalogue(own, kwargs, env)


def _v15(command_translate=v15.translate_call, detect=v15.is_v15_call) -> LegacyForm:
    """A code_aster 15 form (NOEUD/MAILLE...), checked by today's catalogue once translated."""
    return LegacyForm(command_translate, detect=detect)


def _legacy_dyna_vibra():
    # deferred: the legacy catalogue builds on today's DYNA_VIBRA catalogue,
    # ~20 ms of start-up (python -X importtime) that decks without a
    # pre-COMPORTEMENT DYNA_VIBRA never need
    from asterlite.catalogues.common_legacy import DYNA_VIBRA_V13

    return DYNA_VIBRA_V13


DYNA_TRAN_MODAL = LegacyForm(dyna.translate_dyna_tran_modal, legacy_catalogue=OWN)
DYNA_VIBRA = FirstOf(
    LegacyForm(
        dyna.translate_dyna_vibra,
        detect=dyna.is_legacy_dyna_vibra,
        legacy_catalogue=_legacy_dyna_vibra,
    ),
    _v15(v15.translate_dyna_vibra, v15.is_v15_dyna_vibra),
)
MODE_ITER_SIMULT = LegacyForm(modes.translate_mode_iter_simult, legacy_catalogue=OWN)
MODE_ITER_INV = LegacyForm(modes.translate_mode_iter_inv, legacy_catalogue=OWN)
LIRE_MAILLAGE = LegacyForm(misc.translate_lire_maillage, detect=misc.is_legacy_lire_maillage)
# code_aster 15: NOEUD/MAILLE where code_aster 17 takes groups, keywords that had no effect
V15_ENTITIES = _v15()
CREA_RESU = _v15(v15.translate_crea_resu, v15.is_v15_crea_resu)
START = LegacyForm(misc.translate_start, detect=misc.is_legacy_start)
# code_aster 10-11 macro-commands, renamed in code_aster 12 (asterlite.legacy.macros_v11)
MACRO_PROJ_BASE = LegacyForm(macros_v11.translate_macro_proj_base, legacy_catalogue=OWN)
MACRO_MATR_ASSE = LegacyForm(macros_v11.translate_macro_matr_asse, legacy_catalogue=OWN)
# code_aster 10-12 commands that code_aster 11's DYNA_VIBRA ran with its own keywords
# (asterlite.legacy.dyna_line_v11); today's DYNA_VIBRA catalogue checks the translation
DYNA_LINE_TRAN = LegacyForm(dyna_line_v11.translate_dyna_line_tran)
DYNA_LINE_HARM = LegacyForm(dyna_line_v11.translate_dyna_line_harm)

# command -> its legacy form
FORMS: dict[str, LegacyForm] = {
    "AFFE_CARA_ELEM": V15_ENTITIES,
    "AFFE_MODELE": V15_ENTITIES,
    "CALC_CHAMP": V15_ENTITIES,
    "CALC_CHAR_SEISME": V15_ENTITIES,
    "CREA_RESU": CREA_RESU,
    "DEBUT": START,  # CODE=_F(NOM=...) of older versions
    "DYNA_LINE": V15_ENTITIES,
    "DYNA_LINE_HARM": DYNA_LINE_HARM,
    "DYNA_LINE_TRAN": DYNA_LINE_TRAN,
    "DYNA_TRAN_MODAL": DYNA_TRAN_MODAL,
    "DYNA_VIBRA": DYNA_VIBRA,  # CHOC=_F(...) and other pre-COMPORTEMENT keywords
    "LIRE_MAILLAGE": LIRE_MAILLAGE,  # no FORMAT on a text mesh: legacy default 'ASTER'
    "MACRO_MATR_ASSE": MACRO_MATR_ASSE,
    "MACRO_PROJ_BASE": MACRO_PROJ_BASE,
    "MODE_ITER_INV": MODE_ITER_INV,
    "MODE_ITER_SIMULT": MODE_ITER_SIMULT,
    "POURSUITE": START,
    "RECU_FONCTION": V15_ENTITIES,
    "TEST_RESU": V15_ENTITIES,
}


def legacy_form(command: str) -> LegacyForm | None:
    """The legacy form of ``command``, or None when it has none."""
    return FORMS.get(command)
