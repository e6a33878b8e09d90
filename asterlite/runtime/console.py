"""What a run prints on the terminal, which may go away while it runs.

``asterlite run deck | head -c 5`` closes the pipe after five bytes; a
closed terminal makes writes fail with EIO. The run's result is in
``message.log`` and ``summary.json``, and its exit status is its verdict's:
a stream that cannot be written any more is silenced (its descriptor
pointed at /dev/null, so that Python's final flush does not fail either)
and the run goes on.
"""

from __future__ import annotations

import os
import sys

_silenced: set[int] = set()  # id() of the streams silenced


def say(text: str, stream=None) -> None:
    """Print a line on ``stream`` (standard output), unless it is gone."""
    stream = sys.stdout if stream is None else stream
    if stream is None or id(stream) in _silenced:
        return
    try:
        print(text, file=stream, flush=True)
    except (BrokenPipeError, ConnectionResetError, OSError, ValueError):
        silence(stream)


def silence(stream) -> None:
    """Point ``stream``'s descriptor at /dev/null and never write it again."""
    _silenced.add(id(stream))
    try:
        descriptor = stream.fileno()
    except (AttributeError, OSError, ValueError):  # a stream without a descriptor (a test's)
        return
    null = os.open(os.devnull, os.O_WRONLY)
    try:
        os.dup2(null, descriptor)
    finally:
        os.close(null)
