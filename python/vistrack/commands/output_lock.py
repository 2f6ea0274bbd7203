"""One run at a time in an output folder: a command locks each folder it writes (``fcntl.flock`` on
the folder itself, so no file is added to it and nothing is left behind) from the moment it checks
the folder until it ends; a second run into a busy folder is refused with a one-line error naming
the option and the folder, instead of both writing into it (three ``vistrack waypoints`` runs with
different winds into one --out left a metrics.json of one wind beside trajectories of another).
The lock is the kernel's: it goes with the process, whatever way the process ends."""

from __future__ import annotations

import contextlib
import fcntl
import os
from pathlib import Path
from typing import Iterator

from .._core import VistrackError

__all__ = ["lock_folder", "output_locks"]

_commands: list[tuple[contextlib.ExitStack, set[Path]]] = []  # the running command's locks (innermost last)


@contextlib.contextmanager
def output_locks() -> Iterator[None]:
    """The scope of one command (``cli.main`` runs each command in it): folders locked within it are
    released at its end, and the folders it created and left empty (a failed run) removed."""
    with contextlib.ExitStack() as stack:
        _commands.append((stack, set()))
        try:
            yield
        finally:
            _commands.pop()


def lock_folder(folder: Path, flag: str) -> None:
    """Create ``folder`` if needed and lock it for the running command (nothing outside
    :func:`output_locks`); VistrackError naming ``flag`` and the folder when another run holds it."""
    if not _commands:
        return
    stack, held = _commands[-1]
    key = folder.resolve()
    if key in held:
        return
    created = [p for p in [folder, *folder.parents] if not p.exists()]
    try:
        folder.mkdir(parents=True, exist_ok=True)
        descriptor = os.open(folder, os.O_RDONLY | os.O_DIRECTORY)
    except OSError as error:
        _remove_empty(created)
        raise VistrackError(f"{flag} = {folder}: cannot create the folder ({error.strerror})") from None
    try:
        fcntl.flock(descriptor, fcntl.LOCK_EX | fcntl.LOCK_NB)
    except OSError:  # held by another run: the folder is that run's, left as it is
        os.close(descriptor)
        raise VistrackError(f"{flag} = {folder}: the folder is in use by another vistrack run (one run at a "
                            "time writes into an output folder)") from None
    held.add(key)
    # Callbacks run last first: removed if empty while still locked, then unlocked (closing the
    # descriptor releases the lock).
    stack.callback(os.close, descriptor)
    stack.callback(_remove_empty, created)


def _remove_empty(folders: list[Path]) -> None:
    """Remove the folders a run created (deepest first) that it left empty."""
    for folder in folders:
        try:
            folder.rmdir()
        except OSError:  # not empty (the run wrote into it) or gone
            return
