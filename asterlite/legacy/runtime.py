"""The dispatcher's side of legacy syntax: check as written, translate, log.

:func:`translate_call` is called by :class:`asterlite.runtime.session.CommandProxy`
for a command whose catalogue has a ``compat_syntax``. A legacy call is
validated against its legacy catalogue (precise messages for misspellings
in old decks), translated, and each legacy form is logged once as
``deprecated: <old form> (file:line); modern form: <new form>``. The
caller validates the result against the modern catalogue.
"""

from __future__ import annotations

from asterlite.catalog import load_catalogue, validate
from asterlite.errors import UnsupportedError
from asterlite.lang.values import CallSite, FactorDict
from asterlite.legacy.base import Env, NewCall, Translation
from asterlite.legacy.nodes import group_resolver


def _unit_path(session):
    def resolve(unit: int):
        try:
            return session.input_path(unit)
        except Exception:  # no file on that unit: nothing to decide from
            return None

    return resolve


def translate_call(catalogue, kwargs: dict, site: CallSite, session, reuse=None):
    """The modern (command, catalogue, kwargs) of a call, or None if it is not legacy."""
    compat = catalogue.compat_syntax
    env = Env(
        catalogue.nom,
        site.location,
        dict(site.keyword_locations),
        unit_path=_unit_path(session),
        node_group=group_resolver(session.run.units.values()),
    )
    detect = getattr(compat, "detect", None)
    if detect is not None and not detect(kwargs, env):
        return None
    legacy = getattr(compat, "legacy_catalogue", lambda own: None)(catalogue)
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
    return translation.command, modern, kwargs


def run_new_calls(value, session, site: CallSite):
    """``value`` with each :class:`NewCall` replaced by the concept its command makes."""
    from asterlite.runtime.session import CommandProxy

    if isinstance(value, NewCall):
        kwargs = run_new_calls(value.kwargs, session, site)
        return CommandProxy(value.command, session).deck_call([], kwargs, site)
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
