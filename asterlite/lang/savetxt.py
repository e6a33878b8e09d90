"""``numpy.savetxt`` for decks: a table of numbers written into the run's output folder.

code_aster decks save arrays they extracted (``np.savetxt("fx.csv", F, delimiter=",")``)
into the job's working directory. Here the file goes to the output folder of
the run and nowhere else: the name must be a plain file name (no directory),
the run's guard refuses the names it keeps for itself or did not create, and
the run opens it (:func:`set_writer`, set by :class:`asterlite.runtime.session.Session`).
Formats are printf fields on numbers with widths and precisions of at most two
digits; the file's size is bounded by the run's output cap; nothing is written
outside a run (``asterlite check`` validates the call and writes nothing).
"""

from __future__ import annotations

import re
from collections.abc import Callable
from contextvars import ContextVar
from typing import TextIO

from asterlite.errors import DeckRuntimeError
from asterlite.lang import limits as guards
from asterlite.lang.limits import Limits

# writer(name): a new text stream for a deck-written file in the run's output
# folder, or None when nothing is to be written (asterlite check)
_writer: ContextVar[Callable[[str], TextIO | None] | None] = ContextVar("deck_writer", default=None)

# one printf field on a number: flags, width and precision of at most two digits
_FIELD = r"%[-+ 0#]*\d{0,2}(?:\.\d{0,2})?[eEfFgGdiu]"
_FORMAT = re.compile(rf"(?:[^%]|%%)*{_FIELD}(?:[^%]|%%)*")
_TEXT_KEYWORDS = ("delimiter", "newline", "header", "footer", "comments")
_MAX_TEXT = 100_000  # characters of a header, delimiter...
_ENCODINGS = (None, "utf-8", "utf8", "latin1", "latin-1", "ascii", "bytes")


def set_writer(writer: Callable[[str], TextIO | None] | None):
    """Route deck-written files to ``writer`` (None: refused); returns the token to reset."""
    return _writer.set(writer)


def reset_writer(token) -> None:
    _writer.reset(token)


def make_savetxt(limits: Limits):
    """The deck's ``numpy.savetxt``."""

    def savetxt(
        fname,
        X,
        fmt="%.18e",
        delimiter=" ",
        newline="\n",
        header="",
        footer="",
        comments="# ",
        encoding=None,
    ):
        writer = _writer.get()
        if writer is None:
            raise DeckRuntimeError("numpy.savetxt writes files of a run: not available here")
        texts = dict(
            zip(_TEXT_KEYWORDS, (delimiter, newline, header, footer, comments), strict=True)
        )
        _check_arguments(fname, fmt, texts, encoding)
        array = _table(X, limits)
        stream = writer(fname)
        if stream is None:  # asterlite check: nothing is written
            return None
        fmt = list(fmt) if isinstance(fmt, (list, tuple)) else fmt
        try:
            with stream:  # numpy writes row by row: no whole text in memory
                guards.numpy_or_none().savetxt(stream, array, fmt=fmt, **texts)
        except OSError as error:  # the run's output cap (EFBIG), a full disk
            raise DeckRuntimeError(f"numpy.savetxt: {fname} not written ({error})") from None
        return None

    savetxt.deck_unknown_policy = "deep"  # asterlite.lang.library.DEEP
    return savetxt


def _check_arguments(fname, fmt, texts: dict, encoding) -> None:
    if not isinstance(fname, str) or not _plain_name(fname):
        raise DeckRuntimeError(
            f"numpy.savetxt: {fname!r} is not a plain file name (decks write only into "
            "the run's output folder, without directories)"
        )
    for keyword, text in texts.items():
        if not isinstance(text, str):
            raise DeckRuntimeError(f"numpy.savetxt: {keyword} must be a string")
        if len(text) > _MAX_TEXT:
            raise guards.exceeded(f"numpy.savetxt {keyword} length", _MAX_TEXT)
    for one in _formats(fmt):
        if not isinstance(one, str) or not _FORMAT.fullmatch(one):
            raise DeckRuntimeError(
                f"numpy.savetxt: fmt {one!r} is not one printf field on a number "
                "(such as '%.6e', '%10.4f', '%d'; widths and precisions up to 99)"
            )
    if encoding not in _ENCODINGS:
        raise DeckRuntimeError(f"numpy.savetxt: encoding {encoding!r} is not supported")


def _plain_name(name: str) -> bool:
    return bool(name) and name not in (".", "..") and not any(c in name for c in "/\\\0")


def _formats(fmt) -> list:
    if isinstance(fmt, (list, tuple)):
        if not fmt or len(fmt) > 10_000:
            raise DeckRuntimeError("numpy.savetxt: fmt lists one format per column")
        return list(fmt)
    return [fmt]


def _table(values, limits: Limits):
    """``values`` as a 1-D or 2-D array of real or integer numbers."""
    np = guards.numpy_or_none()
    guards.check_nested_size((values,), limits)
    try:
        array = np.asarray(values)
    except (TypeError, ValueError) as error:
        raise DeckRuntimeError(f"numpy.savetxt: X is not a table of numbers ({error})") from None
    if array.dtype.kind not in "biuf" or array.ndim not in (1, 2):
        raise DeckRuntimeError(
            f"numpy.savetxt: X must be a 1-D or 2-D array of real numbers "
            f"(got {array.ndim}-D {array.dtype})"
        )
    guards.check_length(array.size, limits, "numpy.savetxt size")
    return array
