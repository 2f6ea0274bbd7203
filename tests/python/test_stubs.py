"""The type stubs shipped for the extension (python/vistrack/_core/*.pyi) match the bindings."""

from __future__ import annotations

import sys
from pathlib import Path

import pytest

import vistrack  # noqa: F401  (the stubs show the methods the package attaches: to_mission, from_geojson)
from support.paths import REPO


def test_stubs_are_up_to_date(tmp_path: Path, monkeypatch: pytest.MonkeyPatch) -> None:
    stubgen = pytest.importorskip("pybind11_stubgen", reason="pybind11-stubgen not installed")
    monkeypatch.setattr(sys, "argv", ["pybind11-stubgen", "vistrack._core", "-o", str(tmp_path),
                                      "--ignore-all-errors"])
    stubgen.main()
    fresh_dir = tmp_path / "vistrack" / "_core"
    shipped_dir = REPO / "python" / "vistrack" / "_core"
    fresh_names = sorted(p.name for p in fresh_dir.glob("*.pyi"))
    assert fresh_names == sorted(p.name for p in shipped_dir.glob("*.pyi")), "run bash scripts/stubs.sh"
    for name in fresh_names:
        fresh = (fresh_dir / name).read_text()
        shipped = (shipped_dir / name).read_text()
        assert fresh == shipped, f"python/vistrack/_core/{name} is stale: run bash scripts/stubs.sh"
