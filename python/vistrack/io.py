"""Every file format vistrack reads or writes, in one place (autopilot missions: ``mission.py``).

- maps: GeoJSON footprints or any triangle mesh (:func:`load_environment`)
- orbit plans: JSON, plain (``vistrack.orbit_plan/1``) or with the VPs
  (``vistrack.visibility_orbit_plan/1``) (:func:`read_plan`, :func:`write_plan`)
- VV files: the binary ``vv-*.bin`` of the VV cache (:func:`volume_files`)
- closed-loop trajectories: CSV (:func:`write_trajectory`)
- JSON results (:func:`write_json`) and YAML mappings (:func:`read_yaml_mapping`)

Every error names the option or key and the file: a missing or unreadable file, a file that is
not text, or text that is not the expected format raises VistrackError.
"""

from __future__ import annotations

import json
from pathlib import Path
from typing import Any, Optional, Union

from ._core import Environment, OrbitPlan, SimulationResult, VisibilityOrbitPlan, VistrackError

__all__ = [
    "GEOJSON_SUFFIXES", "footprint_environment", "load_environment", "read_plan", "read_text",
    "read_yaml_mapping", "volume_files", "write_json", "write_plan", "write_trajectory",
]

GEOJSON_SUFFIXES = (".geojson", ".json")
AnyPlan = Union[OrbitPlan, VisibilityOrbitPlan]


def read_text(path: str | Path, key: str) -> str:
    """The UTF-8 text of a file; VistrackError naming ``key`` when it is missing, a folder,
    unreadable or not UTF-8 text."""
    file = Path(path)
    if file.is_dir():
        raise VistrackError(f"{key} = {path}: is a folder, not a file")
    try:
        return file.read_text(encoding="utf-8")
    except OSError as error:
        raise VistrackError(f"{key} = {path}: cannot read the file ({error.strerror})") from None
    except UnicodeDecodeError as error:
        raise VistrackError(f"{key} = {path}: not UTF-8 text (byte {error.start})") from None


def load_environment(path: str | Path, up: str = "z", kind: Optional[str] = None) -> Environment:
    """A city from a file: GeoJSON 2.5D footprints or any triangle mesh (OBJ, PLY, STL, OFF), whose
    up axis is ``up`` ("z", or "y" for Y-up files such as the Charlotte and campus OBJ exports,
    where north is -Z). ``kind`` "geojson" or "mesh"; by default from the suffix
    (``.geojson``/``.json`` are GeoJSON)."""
    text = str(path)
    if kind is None:
        kind = "geojson" if Path(text).suffix.lower() in GEOJSON_SUFFIXES else "mesh"
    if kind == "geojson":
        return Environment.from_geojson(text)
    return Environment.from_mesh(text, up)


def footprint_environment(map_path: str | Path | None, footprints: str | Path | None = None) -> Environment | None:
    """Building footprints to draw under a figure without loading the map for planning: the
    given GeoJSON, else a GeoJSON map itself, else ``buildings.geojson`` beside a mesh map
    (Charlotte ships both), else None."""
    if footprints:
        return Environment.from_geojson(str(footprints))
    if not map_path:
        return None
    map_file = Path(map_path)
    if map_file.suffix.lower() in GEOJSON_SUFFIXES:
        return Environment.from_geojson(str(map_file))
    beside = map_file.with_name("buildings.geojson")
    return Environment.from_geojson(str(beside)) if beside.exists() else None


def read_plan(path: str | Path, key: str = "plan") -> AnyPlan:
    """An orbit plan JSON file, by its ``format``: a VisibilityOrbitPlan (``vistrack orbits``,
    ``vistrack run``) or a plain OrbitPlan (times, radii and the POI path)."""
    text = read_text(path, key)
    try:
        data = json.loads(text)
    except json.JSONDecodeError as error:
        raise VistrackError(f"{key} = {path}: not JSON ({error.msg} at line {error.lineno})") from None
    if isinstance(data, dict) and data.get("format") == "vistrack.visibility_orbit_plan/1":
        return VisibilityOrbitPlan.from_json(text)
    return OrbitPlan.from_json(text)


def write_plan(plan: AnyPlan, path: str | Path) -> Path:
    """The plan as JSON (what :func:`read_plan` reads back)."""
    file = Path(path)
    file.write_text(plan.to_json(), encoding="utf-8")
    return file


def write_trajectory(result: SimulationResult, path: str | Path) -> Path:
    """A closed-loop trajectory as CSV, one sample per line, full double precision (the header is
    in ``SimulationResult.to_csv``)."""
    file = Path(path)
    file.write_text(result.to_csv(), encoding="utf-8")
    return file


def write_json(data: Any, path: str | Path) -> Path:
    """Indented JSON of plain data (results, metrics, summaries)."""
    file = Path(path)
    file.write_text(json.dumps(data, indent=1) + "\n", encoding="utf-8")
    return file


def read_yaml_mapping(path: str | Path, key: str) -> dict[str, Any]:
    """A YAML file holding one mapping (empty file: empty mapping)."""
    import yaml

    text = read_text(path, key)
    try:
        data = yaml.safe_load(text)
    except yaml.YAMLError as error:
        raise VistrackError(f"{key} = {path}: not valid YAML ({error})") from None
    if data is None:
        return {}
    if not isinstance(data, dict):
        raise VistrackError(f"{key} = {path}: expected a mapping of keys to values, not {type(data).__name__}")
    return data


def volume_files(folder: str | Path, key: str = "--from-volumes") -> list[Path]:
    """The VV files (``*.bin``) in a folder, sorted by name; VistrackError when none."""
    root = Path(folder)
    if not root.is_dir():
        raise VistrackError(f"{key} = {folder}: is not a folder")
    files = sorted(p for p in root.iterdir() if p.is_file() and p.suffix == ".bin")
    if not files:
        raise VistrackError(f"{key} = {folder}: no VV files (*.bin) in the folder")
    return files
