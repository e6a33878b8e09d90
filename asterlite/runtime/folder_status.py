"""``asterlite status DIR``: what became of the run in an output folder.

A run in progress holds the folder's lock: its status is RUNNING, with the
command it is in (the record its lock file keeps). A summary saying RUNNING
while nobody holds the lock is a run that was killed outright (SIGKILL, the
out-of-memory killer, a stopped machine): the folder is settled as the next
run would settle it — its summary says KILLED and where the run was, its
staging folder becomes ``incomplete/``, the stale lock is removed. A folder
this user may not write is only read: its status is told, nothing settled.
"""

from __future__ import annotations

import errno
import fcntl
import os
from dataclasses import dataclass, field
from pathlib import Path

from asterlite.runtime.outdir import (
    LOCK_NAME,
    SUMMARY_NAME,
    OutputFolder,
    OutputFolderBusy,
    OutputFolderError,
    describe_record,
    lock_record,
    read_earlier_result,
)
from asterlite.runtime.write_boundary import WriteBoundary

EXIT_RUNNING = 3  # a run is on: no verdict yet
_EXIT = {"PASS": 0, "DONE": 0, "NOOK": 1}


@dataclass
class FolderStatus:
    status: str  # a run's status, RUNNING, or NONE (no run there)
    lines: list[str] = field(default_factory=list)

    @property
    def exit_code(self) -> int:
        if self.status == "RUNNING":
            return EXIT_RUNNING
        return _EXIT.get(self.status, 2)


def folder_status(path: Path) -> FolderStatus:
    """The status of the run in ``path``, settling a killed one."""
    path = Path(path)
    if not path.is_dir():
        return FolderStatus("NONE", [f"{path}: no such folder"])
    if not (os.path.lexists(path / SUMMARY_NAME) or os.path.lexists(path / LOCK_NAME)):
        return FolderStatus("NONE", [f"{path}: no asterlite run there (no {SUMMARY_NAME})"])
    folder = OutputFolder(path)
    try:
        folder.take()
    except OutputFolderBusy as busy:
        folder.release()
        return _running(path, busy.record)
    except OSError as error:
        folder.release()
        if error.errno in (errno.EACCES, errno.EPERM, errno.EROFS):  # not this user's to settle
            return _read_only(path)
        return FolderStatus("NONE", [f"{path}: {_text(error)}"])
    except OutputFolderError as error:
        folder.release()
        return FolderStatus("NONE", [f"{path}: {_text(error)}"])
    try:
        return _settled(path, folder)
    except (OutputFolderError, OSError) as error:
        return FolderStatus("NONE", [f"{path}: {_text(error)}"])
    finally:
        folder.release()


def _settled(path: Path, folder: OutputFolder) -> FolderStatus:
    stale = folder.stale_record is not None
    earlier = folder.settle_earlier()
    cleared = ["a stale lock: the run that held it had ended"] if stale else []
    if earlier is None:
        return FolderStatus("NONE", [f"{path}: no asterlite result there", *_said(cleared)])
    data = earlier.data
    status = str(data.get("status"))
    if status == "RUNNING":  # not settled: its summary is not verified as ours
        where = describe_record(folder.stale_record)
        lines = [
            f"{path}: KILLED — summary.json says RUNNING but no run holds the folder: the run "
            f"ended without its result{' ' + where if where else ''}",
            "  summary.json is not verified as written by your asterlite (another user's, "
            "an older version's): left as is; the next run moves it aside",
        ]
        return FolderStatus("KILLED", lines + _said(cleared))
    if folder.earlier_note:
        cleared.append("the run's files to incomplete/, its summary to KILLED")
    return FolderStatus(status, _final_lines(path, data) + _said(cleared))


def _read_only(path: Path) -> FolderStatus:
    """The status of a folder this user may not write: read, nothing settled."""
    boundary = WriteBoundary.open(path)
    try:
        earlier = read_earlier_result(boundary)
        if earlier is None:
            return FolderStatus("NONE", [f"{path}: no asterlite result there"])
        if earlier.status != "RUNNING":
            return FolderStatus(earlier.status, _final_lines(path, earlier.data))
        record = _held_lock_record(boundary)
        if record is not None:
            return _running(path, record)
        return FolderStatus(
            "KILLED",
            [
                f"{path}: KILLED — summary.json says RUNNING but no run holds the folder "
                "(read-only here: left as is)"
            ],
        )
    except (OutputFolderError, OSError) as error:
        return FolderStatus("NONE", [f"{path}: {_text(error)}"])
    finally:
        boundary.close()


def _held_lock_record(boundary: WriteBoundary) -> dict | None:
    """The record of the lock a live run holds, None when none is held."""

    flags = os.O_RDONLY | os.O_NOFOLLOW | os.O_NONBLOCK | os.O_CLOEXEC
    try:
        descriptor = os.open(LOCK_NAME, flags, dir_fd=boundary.fd)
    except OSError:
        return None
    try:
        fcntl.flock(descriptor, fcntl.LOCK_SH | fcntl.LOCK_NB)
    except BlockingIOError:
        return lock_record(descriptor)
    except OSError:
        return None
    finally:
        os.close(descriptor)
    return None


def _final_lines(path: Path, data: dict) -> list[str]:
    message = str(data.get("message") or "").strip().splitlines()
    lines = [f"{path}: {data.get('status')}" + (f" — {message[0]}" if message else "")]
    lines += [f"  {line}" for line in message[1:5]]
    output = data.get("output") if isinstance(data.get("output"), dict) else {}
    started = output.get("started")
    lines.append(f"  deck {data.get('deck')}" + (f", started {started}" if started else ""))
    if isinstance(data.get("checks_total"), int) and data["checks_total"]:
        lines.append(f"  checks {data.get('checks_ok')}/{data['checks_total']} OK")
    return lines


def _running(path: Path, record: dict) -> FolderStatus:
    where = describe_record(record)
    pid = record.get("pid") if isinstance(record.get("pid"), int) else "?"
    return FolderStatus("RUNNING", [f"{path}: RUNNING — pid {pid}{', ' + where if where else ''}"])


def _said(cleared: list[str]) -> list[str]:
    return [f"  cleared: {item}" for item in cleared]


def _text(error: Exception) -> str:
    if isinstance(error, OSError):
        return error.strerror or str(error)
    return str(error)
