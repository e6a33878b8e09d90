"""Earlier results kept under ``previous-*/``: how many, and what may go.

A run into a folder that holds an earlier result moves it into a new
``previous-<time>/`` folder (:mod:`asterlite.runtime.outdir`). Without a
limit these pile up (a study's ``results.h5`` is copied aside at every
rerun), so a run keeps the ``keep`` most recent of them (3 by default,
``asterlite run --keep-previous N``; 0 keeps none) and deletes the older
ones, under one rule: asterlite deletes only what it can prove it made.

- Each ``previous-*`` folder a run makes is recorded in the run's signed
  manifest (:mod:`asterlite.runtime.manifest`): its identity (device,
  inode), when it was made, and the identity of every entry moved into it
  that a verified manifest listed as a run's own (files with their size and
  modification time, folders with their contents, recorded when their run
  finished). The next run inherits these records only from a summary that
  verifies; a summary that does not (edited, forged, unsigned, another
  user's) gives none, so nothing is deleted on its word.
- Deleting a recorded folder removes, through the output folder's
  descriptors (single names, never a symlink followed), only the recorded
  entries still identical to their record, then the folder if it is empty.
  A folder named ``previous-*`` that no verified manifest records, anything
  added to a recorded one since, or an entry replaced under a recorded name
  is never touched; a recorded folder that cannot be emptied is left whole
  and forgotten (never tried again).
"""

from __future__ import annotations

import os
import stat

from asterlite.runtime import manifest
from asterlite.runtime.write_boundary import OutputFolderError, WriteBoundary, entry_name

DEFAULT_KEEP = 3  # earlier results kept under previous-*/ (asterlite run --keep-previous)
# entries of a folder's recorded contents, and its depth: a larger tree is
# recorded without contents (then never deleted)
CONTENTS_CAP = 4096
CONTENTS_DEPTH = 8


def contents(folder: WriteBoundary, depth: int = 0, budget: list | None = None) -> dict | None:
    """The identities of everything under ``folder`` (files finished, folders
    with their own contents), or None when the tree holds something else
    (a symlink, a device) or is too large to record."""
    budget = [CONTENTS_CAP] if budget is None else budget
    if depth > CONTENTS_DEPTH:
        return None
    found = {}
    for name in sorted(folder.names()):
        budget[0] -= 1
        info = folder.lstat(name)
        if budget[0] < 0 or info is None:
            return None
        record = manifest.identity(info)
        if record["kind"] == "dir":
            inner = folder.folder(name)
            try:
                if not _same_entry(os.fstat(inner.fd), record):
                    return None
                record["contents"] = contents(inner, depth + 1, budget)
            finally:
                inner.close()
            if record["contents"] is None:
                return None
        elif record["kind"] != "file" or info.st_nlink != 1:
            return None
        found[name] = record
    return found


def entry_record(boundary: WriteBoundary, name: str, finished: bool) -> dict:
    """A manifest entry for ``name`` as it is now; a finished folder's
    record holds its contents (what lets it be deleted later)."""
    info = boundary.lstat(name)
    record = manifest.identity(info, finished)
    if finished and record["kind"] == "dir":
        inner = boundary.folder(name)
        try:
            if _same_entry(os.fstat(inner.fd), record):
                tree = contents(inner)
                if tree is not None:
                    record["contents"] = tree
        finally:
            inner.close()
    return record


def trusted_record(boundary: WriteBoundary, earlier, name: str) -> dict | None:
    """What the verified manifest of ``earlier`` (an EarlierResult) says of
    ``name``, about to be moved aside; the summary itself as it is, a plain
    file of this user. None when asterlite cannot tell the entry as its own."""
    if not earlier.verified:
        return None
    if name == "summary.json":
        info = boundary.lstat(name)
        plain = info is not None and stat.S_ISREG(info.st_mode) and info.st_nlink == 1
        return manifest.identity(info) if plain and info.st_uid == os.geteuid() else None
    record = earlier.entries.get(name)
    return record if isinstance(record, dict) else None


def folder_record(boundary: WriteBoundary, name: str, moved: dict, made: float) -> dict:
    """The manifest record of the ``previous-*`` folder ``name`` a run made
    at ``made`` (epoch seconds), holding ``moved`` (name: trusted record)."""
    record = manifest.identity(boundary.lstat(name))
    record.update(made=round(made, 6), contents=moved)
    return record


def live_records(boundary: WriteBoundary, records: dict) -> dict:
    """The records whose folder is still the one recorded (a folder removed
    or replaced by the user is forgotten)."""
    kept = {}
    for name, record in records.items():
        if not isinstance(name, str) or not name.startswith("previous-"):
            continue
        try:
            info = boundary.lstat(name)
        except OutputFolderError:
            continue
        if info is not None and isinstance(record, dict) and manifest.matches(record, info):
            kept[name] = record
    return kept


def prune(boundary: WriteBoundary, records: dict, keep: int) -> tuple[dict, list, list]:
    """Delete the recorded folders beyond the ``keep`` most recent.
    Returns (the records kept, the names deleted, the names left because they
    hold what asterlite did not put there)."""
    order = sorted(records, key=lambda name: _made(records[name]), reverse=True)
    kept = {name: records[name] for name in order[:keep]}
    deleted, left = [], []
    for name in order[keep:]:
        try:
            removed = remove_recorded(boundary, name, records[name])
        except OSError:  # a permission changed, a file system gone read-only
            removed = False
        (deleted if removed else left).append(name)
    return kept, deleted, left


def notes(keep: int, made: str | None, deleted: list, left: list) -> list[str]:
    """What the log says of a pruning: the earlier result just moved to
    ``made`` and deleted at once (keep 0), the older folders deleted, the
    ones left because they hold what asterlite did not put there."""
    lines = []
    deleted = sorted(deleted)
    if made is not None and made in deleted:
        deleted.remove(made)
        lines.append(
            f"the earlier result was deleted (asterlite run --keep-previous {keep}: "
            "no earlier result kept)"
        )
    if deleted:
        beyond = (
            f"beyond the {keep} most recent (asterlite run --keep-previous N)"
            if keep
            else "(asterlite run --keep-previous 0: none kept)"
        )
        lines.append(
            f"deleted {len(deleted)} earlier result(s) {beyond}: "
            + ", ".join(f"{name}/" for name in deleted)
        )
    lines += [
        f"{name}/ is left as it is: it holds entries asterlite cannot tell as its own"
        for name in sorted(left)
    ]
    return lines


def remove_recorded(boundary: WriteBoundary, name: str, record: dict) -> bool:
    """Remove the entry ``name`` as far as ``record`` describes it: a file
    identical to its record, a folder's recorded contents and then the
    folder if that left it empty. True when nothing is left under the name."""
    try:
        entry_name(name)
    except OutputFolderError:
        return False
    info = boundary.lstat(name)
    if info is None:
        return True
    if not isinstance(record, dict) or not manifest.matches(record, info):
        return False
    if record.get("kind") == "file":
        os.unlink(name, dir_fd=boundary.fd)
        return True
    inner_records = record.get("contents")
    if not isinstance(inner_records, dict):
        return False
    try:
        inner = boundary.folder(name)
    except OSError:
        return False
    try:
        if not _same_entry(os.fstat(inner.fd), record):  # swapped since the lstat
            return False
        for child, child_record in inner_records.items():
            if isinstance(child, str):
                remove_recorded(inner, child, child_record)
        empty = not inner.names()
    finally:
        inner.close()
    if empty:
        os.rmdir(name, dir_fd=boundary.fd)
    return empty


def _same_entry(info: os.stat_result, record: dict) -> bool:
    return (
        stat.S_ISDIR(info.st_mode)
        and record.get("dev") == info.st_dev
        and record.get("ino") == info.st_ino
    )


def _made(record) -> float:
    made = record.get("made") if isinstance(record, dict) else None
    return float(made) if isinstance(made, (int, float)) else 0.0
