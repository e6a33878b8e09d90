"""Which entries of an output folder a run made: a list asterlite can trust.

A run lists its files in ``summary.json`` (``output.files``), and the next
run into the folder moves them aside. A ``summary.json`` is only text: one
written by hand, by another user, or copied from another folder could list
``.git`` or the deck. So the summary also carries a manifest:

- for each entry the run made, its identity when the summary was written
  (kind, device, inode; size and modification time of a finished file; the
  contents of a finished folder);
- the ``previous-*`` folders asterlite made in the folder, with what it
  moved into them (:mod:`asterlite.runtime.previous_results`: what a later
  run may delete);
- the identity of the folder itself;
- an HMAC-SHA256 of the whole summary, keyed by a secret of this user
  (``~/.config/asterlite/manifest.key``, 32 random bytes, mode 0600, in a
  folder only this user may write: :mod:`asterlite.trusted_paths`).

The next run moves aside (and deletes, among older ``previous-*`` folders)
only the entries of a summary whose HMAC verifies with this user's key, in
the same folder, and whose identity still matches what is there. Anyone
who can forge the HMAC can read the user's key, and so could already write
to the user's files.
"""

from __future__ import annotations

import hashlib
import hmac
import json
import os
import stat
from pathlib import Path

from asterlite.trusted_paths import trusted_folder

KEY_NAME = "manifest.key"
KEY_BYTES = 32
_key_cache: dict[str, bytes | None] = {}


def key_folder() -> Path:
    """``$XDG_CONFIG_HOME/asterlite``, else ``~/.config/asterlite``."""
    base = os.environ.get("XDG_CONFIG_HOME") or os.path.join(os.path.expanduser("~"), ".config")
    return Path(base) / "asterlite"


def user_key() -> bytes | None:
    """This user's manifest key (made on first use); None when no private
    folder can hold it (then summaries are not signed: see module doc)."""
    folder = key_folder()
    cached = _key_cache.get(str(folder))
    if cached is not None:
        return cached
    try:
        folder.mkdir(mode=0o700, parents=True, exist_ok=True)
    except OSError:
        return None
    if not trusted_folder(folder):
        return None
    key = _read_key(folder / KEY_NAME)
    if key is None:
        key = _make_key(folder)
    if key is not None:
        _key_cache[str(folder)] = key
    return key


def _read_key(path: Path) -> bytes | None:
    """The key file's bytes if it is this user's private regular file."""
    try:
        descriptor = os.open(path, os.O_RDONLY | os.O_NOFOLLOW | os.O_CLOEXEC)
    except OSError:
        return None
    try:
        info = os.fstat(descriptor)
        private = info.st_uid == os.geteuid() and not info.st_mode & 0o077
        if not stat.S_ISREG(info.st_mode) or not private or info.st_size != KEY_BYTES:
            return None
        key = os.read(descriptor, KEY_BYTES)
        return key if len(key) == KEY_BYTES else None
    finally:
        os.close(descriptor)


def _make_key(folder: Path) -> bytes | None:
    """Write a new key aside, then link it to its name: two processes making
    the key at once end up with the same one (the first linked)."""
    temporary = folder / f".{KEY_NAME}.{os.getpid()}"
    try:
        descriptor = os.open(
            temporary, os.O_WRONLY | os.O_CREAT | os.O_EXCL | os.O_NOFOLLOW | os.O_CLOEXEC, 0o600
        )
        try:
            os.write(descriptor, os.urandom(KEY_BYTES))
        finally:
            os.close(descriptor)
        try:
            os.link(temporary, folder / KEY_NAME)
        except FileExistsError:
            pass
    except OSError:
        return None
    finally:
        try:
            os.unlink(temporary)
        except OSError:
            pass
    return _read_key(folder / KEY_NAME)


# ------------------------------------------------------------------ entries


def identity(info: os.stat_result, finished: bool = True) -> dict:
    """What makes an entry the one a run made. A file still growing (the log
    of a running run) is known by its inode alone."""
    kind = (
        "dir" if stat.S_ISDIR(info.st_mode) else "file" if stat.S_ISREG(info.st_mode) else "other"
    )
    record = {"kind": kind, "dev": info.st_dev, "ino": info.st_ino}
    if finished and kind == "file":
        record.update(size=info.st_size, mtime_ns=info.st_mtime_ns)
    return record


def matches(record: dict, info: os.stat_result) -> bool:
    """``info`` (an lstat) is the entry ``record`` describes."""
    if not isinstance(record, dict):
        return False
    now = identity(info)
    if record.get("kind") != now["kind"] or now["kind"] == "other":
        return False
    if now["kind"] == "file" and info.st_nlink != 1:  # a name added since: not ours alone
        return False
    keys = ("dev", "ino", "size", "mtime_ns") if "size" in record else ("dev", "ino")
    return all(record.get(key) == now[key] for key in keys)


# -------------------------------------------------------------- signatures


def _canonical(data: dict) -> bytes:
    """The bytes signed: the summary as JSON, keys sorted, without the HMAC."""
    plain = json.loads(json.dumps(data))  # tuples as lists, as a reader gets them
    manifest = plain.get("manifest")
    if isinstance(manifest, dict):
        manifest.pop("hmac", None)
    return json.dumps(plain, sort_keys=True, separators=(",", ":"), ensure_ascii=True).encode()


def sign(
    data: dict, folder_info: os.stat_result, entries: dict, previous: dict | None = None
) -> None:
    """Add the manifest (entries, the ``previous-*`` folders asterlite made
    here, folder, HMAC) to the summary ``data``."""
    data["manifest"] = {"folder": [folder_info.st_dev, folder_info.st_ino], "entries": entries}
    if previous:
        data["manifest"]["previous"] = previous
    key = user_key()
    if key is not None:
        data["manifest"]["hmac"] = hmac.new(key, _canonical(data), hashlib.sha256).hexdigest()


def verified_entries(data: dict, folder_info: os.stat_result) -> dict | None:
    """The manifest's entries when this user's asterlite signed ``data`` for
    this folder; None for any other summary (unsigned, forged, another
    user's, copied from elsewhere, edited)."""
    manifest = verified_manifest(data, folder_info)
    if manifest is None:
        return None
    entries = manifest.get("entries")
    return entries if isinstance(entries, dict) else None


def verified_previous(data: dict, folder_info: os.stat_result) -> dict:
    """The ``previous-*`` folders a verified manifest records as made by
    asterlite in this folder ({} for any summary that does not verify)."""
    manifest = verified_manifest(data, folder_info)
    previous = manifest.get("previous") if manifest is not None else None
    return previous if isinstance(previous, dict) else {}


def verified_manifest(data: dict, folder_info: os.stat_result) -> dict | None:
    """The manifest of ``data`` when this user's asterlite signed it for this
    folder, else None."""
    manifest = data.get("manifest") if isinstance(data, dict) else None
    if not isinstance(manifest, dict) or not isinstance(manifest.get("hmac"), str):
        return None
    key = user_key()
    if key is None:
        return None
    try:
        expected = hmac.new(key, _canonical(data), hashlib.sha256).hexdigest()
    except (TypeError, ValueError, RecursionError):
        return None
    if not hmac.compare_digest(expected, manifest["hmac"]):
        return None
    if manifest.get("folder") != [folder_info.st_dev, folder_info.st_ino]:
        return None
    return manifest
