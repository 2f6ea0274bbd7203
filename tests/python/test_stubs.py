"""The type stubs shipped for the extension (python/vistrack/_core/*.pyi) match the bindings."""

from __future__ import annotations

import sys
from pathlib import Path

import pytest

REPO = Path(__file__).resolve().parents[2]


def test_stubs_are_up_to_date(tmp_path: Path, monkeypatch: pytest.MonkeyPatch) -> None:
    stubgen = pytest.importorskip("pybind11_stubgen", reason="pybind11-stubgen not installed")
    monkeypatch.setattr(sys, "argv", ["pybind11-stubgen", "vistrack._core", "-o", str(tmp_path),
                                      "--ignore-all-errors"])
    stubgen.main()
    for name in ("__init__.pyi", "dubins.pyi"):
        shipped = (REPO / "python" / "vistrack" / "_core" / name).read_text()
        fresh = (tmp_path / "vistrack" / "_core" / name).read_text()
        assert fresh == shipped, f"regenerate python/vistrack/_core/{name} (see README, Development)"
