"""VV files: the binary ``vv-*.bin`` of the VV cache."""

from __future__ import annotations

from pathlib import Path

from .._core import VistrackError

__all__ = ["volume_files"]


def volume_files(folder: str | Path, key: str = "--from-volumes") -> list[Path]:
    """The VV files (``*.bin``) in a folder, sorted by name; VistrackError when none."""
    root = Path(folder)
    if not root.is_dir():
        raise VistrackError(f"{key} = {folder}: is not a folder")
    files = sorted(p for p in root.iterdir() if p.is_file() and p.suffix == ".bin")
    if not files:
        raise VistrackError(f"{key} = {folder}: no VV files (*.bin) in the folder")
    return files
