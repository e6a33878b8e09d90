"""The dispatcher's side of legacy syntax: check as written, translate, log.

:func:`translate_call` is called by the session's command proxy
for a command that has a legacy form (:mod:`asterlite.legacy.forms`). A legacy call is
validated against its legacy catalogue (precise messages for misspellings
in old decks), translated, and each legacy form is logged once as
``deprecated: <old form> (file:line); modern form: <new form>``. The
caller validates the result against the modern catalogue.
"""

from __future__ import annotations

from asterlite.catalog import load_catalogue, validate
from asterlite.errors import UnsupportedError
from asterlite.io.input_files import read_text_or_none
from asterlite.lang.values import CallSite, FactorDict
from asterlite.legacy.base import RESULT, Env, NewCall, Translation
from asterlite.legacy.forms import legacy_form
from asterlite.legacy.nodes import LegacyGroups
from asterlite.legacy.v15 import named_entities
from asterlite.legacy.version import session_version


def _unit_path(session):
    def resolve(unit: int):
        try:
            return session.input_path(unit)
        except Exception:  # no file on that unit: nothing to decide from
            return None

    return resolve


class ModernCall:
    """What a legacy call became: ``command, catalogue, kwargs = modern``, and
    :meth:`finish`, to give its result to the calls the translation makes after it."""

    def __init__(self, command, catalogue, kwargs, after, session, site):
        self.command, self.catalogue, self.kwargs = command, catalogue, kwargs
        self.after, self.session, self.site = after, session, site

    def __iter__(self):
        return iter((self.command, self.catalogue, self.kwargs))

    def finish(self, result):
        """Run the follow-up calls on ``result`` (each reuses it); return it."""
        for call in self.after:
            site = CallSite(location=self.site.location)
            kwargs = {k: result if v is RESULT else v for k, v in call.kwargs.items()}
            kwargs = run_new_calls(kwargs, self.session, site)
            made = self.session.command(call.command).deck_call([], kwargs, site)
            result = made if kwargs.get("reuse") is result else result
        return result


def legacy_groups(session) -> LegacyGroups:
    """The groups standing for the mesh nodes and cells the run's decks name (one per run)."""
    found = getattr(session, "_legacy_groups", None)
    if found is None:
        texts = [_text(path) for path in session.run.deck_files]
        found = LegacyGroups(session.run.units.values(), texts, named_entities(texts))
        session._legacy_groups = found
    return found


def _text(path) -> str:
    return read_text_or_none(path) or ""


def translate_call(catalogue, kwargs: dict, site: CallSite, session, reuse=None):
    """The :class:`ModernCall` of a call, or None if it is not legacy."""
    compat = legacy_form(catalogue.nom)
    if compat is None:
        return None
    env = Env(
        catalogue.nom,
        site.location,
        dict(site.keyword_locations),
        unit_path=_unit_path(session),
        version=session_version(session),
        legacy_groups=legacy_groups(session),
    )
    detect = getattr(compat, "detect", None)
    if detect is not None and not detect(kwargs, env):
        return None
    legacy = _legacy_catalogue(compat, catalogue, kwargs, env)
    if legacy is not None:
        validate(legacy, kwargs, site, reuse=reuse)
    translation: Translation | None = compat(kwargs, env)
    if translation is None:
        return None
    for note in translation.notes:
        session.log(note.text())
    modern = load_catalogue(translation.command)
    if modern is None:
        raise UnsupportedError(f"command {translation.command} is not supported", site.location)
    kwargs = run_new_calls(translation.kwargs, session, CallSite(location=site.location))
    return ModernCall(translation.command, modern, kwargs, translation.after, session, site)


def _legacy_catalogue(compat, own, kwargs: dict, env: Env):
    found = getattr(compat, "legacy_catalogue", None)
    return None if found is None else found(own, kwargs, env)


def run_new_calls(value, session, site: CallSite):
    """``value`` with each :class:`NewCall` replaced by the concept its command makes."""
    if isinstance(value, NewCall):
        kwargs = run_new_calls(value.kwargs, session, site)
        return session.command(value.command).deck_call([], kwargs, site)
    if isinstance(value, FactorDict):
        return FactorDict(
            {k: run_new_calls(v, session, site) for k, v in value.items()},
            location=value.location,
            keyword_locations=value.keyword_locations,
        )
    if isinstance(value, dict):
        return {k: run_new_calls(v, session, site) for k, v in value.items()}
    if isinstance(value, (list, tuple)):
        return type(value)(run_new_calls(v, session, site) for v in value)
    return value
