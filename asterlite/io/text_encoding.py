"""The encoding of a study's text files: UTF-8, with or without a byte order
mark, else what the file declares, else Latin-1 as old French decks are.

Decks of code_aster 10-12 were written in ISO-8859-1 (their sources say
``# -*- coding: iso-8859-1 -*-``), some on Windows in Windows-1252; newer
ones in UTF-8, which editors on Windows start with a byte order mark. A
file's bytes are decoded, never altered:

1. a UTF-8 byte order mark: the rest must be UTF-8 (the mark is dropped);
2. a coding declaration on the first or second line, as Python reads one
   (``# -*- coding: latin-1 -*-``): that encoding, strictly;
3. valid UTF-8: UTF-8;
4. otherwise Windows-1252 when the file has bytes 0x80-0x9F (printable
   there: ``’``, ``€``, ``œ``; control codes in Latin-1) and they all decode,
   else Latin-1, which decodes any byte to the character of the same number.

:func:`decode_text` returns the text and the encoding used, in words.
"""

from __future__ import annotations

import codecs
import re

UTF8 = "UTF-8"
UTF8_BOM = "UTF-8 (with a byte order mark)"
LATIN1 = "Latin-1 (ISO-8859-1)"
WINDOWS_1252 = "Windows-1252"
# PEP 263: a comment on line 1 or 2 naming the file's encoding
_CODING = re.compile(rb"^[ \t\f]*#.*?coding[:=][ \t]*([-\w.]+)")


class TextEncodingError(ValueError):
    """The bytes do not decode as the file says they should."""


def decode_text(data: bytes) -> tuple[str, str]:
    """``(text, encoding)`` of a file's bytes (see the module's rules)."""
    if data.startswith(codecs.BOM_UTF8):
        return _strict(data[len(codecs.BOM_UTF8) :], "utf-8", "its byte order mark"), UTF8_BOM
    declared = declared_encoding(data)
    if declared is not None:
        return _strict(data, declared, "its coding declaration"), declared
    try:
        return data.decode("utf-8"), UTF8
    except UnicodeDecodeError:
        pass
    if re.search(rb"[\x80-\x9f]", data):
        try:
            return data.decode("cp1252"), WINDOWS_1252
        except UnicodeDecodeError:  # 0x81, 0x8d, 0x8f, 0x90, 0x9d: not Windows-1252
            pass
    return data.decode("latin-1"), LATIN1


def declared_encoding(data: bytes) -> str | None:
    """The encoding a coding declaration on line 1 or 2 names, as Python
    spells it (``iso8859-1``), or None; TextEncodingError for a name that is
    no encoding."""
    for number, line in enumerate(data.split(b"\n", 2)[:2], start=1):
        match = _CODING.match(line)
        if match:
            try:
                return codecs.lookup(match.group(1).decode("ascii")).name
            except LookupError:  # the name is not shown: the file may be anything
                message = f"line {number}: the coding declaration names no encoding Python knows"
                raise TextEncodingError(message) from None
        if line.strip() and not line.lstrip().startswith(b"#"):
            return None  # a declaration on line 2 only follows a comment line 1
    return None


def _strict(data: bytes, encoding: str, why: str) -> str:
    try:
        return data.decode(encoding)
    except LookupError:  # rot13, base64...: codecs, not text encodings
        raise TextEncodingError(f"{why} names no text encoding") from None
    except UnicodeDecodeError as error:
        line = data.count(b"\n", 0, error.start) + 1
        raise TextEncodingError(
            f"line {line}: byte {error.start + 1} is not {encoding}, as {why} says the file is"
        ) from None


_CODING_TEXT = re.compile(r"^([ \t\f]*#.*?coding[:=][ \t]*)[-\w.]+", re.MULTILINE)


def with_utf8_declaration(text: str) -> str:
    """``text`` whose coding declaration on line 1 or 2, if any, names UTF-8:
    for a file written back in UTF-8 (``asterlite port``)."""
    head, newline, rest = text.partition("\n")
    second, newline2, tail = rest.partition("\n")
    lines = _CODING_TEXT.sub(r"\1utf-8", head + newline + second, count=1)
    return lines + newline2 + tail
