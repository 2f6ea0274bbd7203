"""Every file format vistrack reads or writes, in one place (autopilot missions: ``mission.py``).

- maps: GeoJSON footprints or any triangle mesh (:func:`load_environment`)
- orbit plans: JSON, plain (``vistrack.orbit_plan/1``) or with the VPs
  (``vistrack.visibility_orbit_plan/1``) (:func:`read_plan`, :func:`write_plan`)
- VV files: the binary ``vv-*.bin`` of the VV cache (:func:`volume_files`)
- closed-loop trajectories: CSV (:func:`write_trajectory`)
- JSON results (:func:`write_json`) and YAML (:func:`parse_yaml`, :func:`read_yaml_mapping`: a key given
  twice in one mapping is an error, not the last one silently kept)
- loiter scenarios: YAML (:func:`read_loiter_scenario`); loiter plans sampled as CSV
  (:func:`write_loiter_samples_csv`)
- GeoJSON in WGS84 of trajectories, orbit plans and missions (:func:`trajectory_geojson`,
  :func:`orbit_plan_geojson`, :func:`mission_geojson`, :func:`write_geojson`)
- waypoint routes: CSV x,y (:func:`read_route`, :func:`write_route`); flown trajectories: CSV
  (:func:`write_flight`)
- sweeps: road files (GeoJSON LineStrings, :func:`read_roads`) and the results table
  (``results.csv`` + ``results.parquet``, :func:`write_results_table`, :func:`read_results_table`)
- follow: vehicle tracks ``t,x,y`` (:func:`read_vehicle_track`), road paths
  (:func:`read_road_path`), follow trajectories as CSV (:func:`write_follow_trajectory`)

Every error names the option or key and the file: a missing or unreadable file, a file that is
not text, or text that is not the expected format raises VistrackError.
"""

from __future__ import annotations

import json
from collections.abc import Sequence
from pathlib import Path
from typing import TYPE_CHECKING, Any, Optional, Union

import numpy as np

from ._core import Environment, OrbitPlan, RoadNetwork, SimulationResult, VisibilityOrbitPlan, VistrackError

if TYPE_CHECKING:
    from ._core.flight import FlightTrajectory
    from .loiter import Coverage as LoiterCoverage
    from .loiter import Plan as LoiterPlan
    from .loiter import Scenario as LoiterScenario
    from .mission import Georeference, Mission

__all__ = [
    "GEOJSON_SUFFIXES",
    "append_json_line",
    "feature_collection",
    "footprint_environment",
    "line_feature",
    "load_environment",
    "lon_lat",
    "mission_geojson",
    "orbit_plan_geojson",
    "parse_yaml",
    "point_feature",
    "read_loiter_scenario",
    "read_plan",
    "read_results_table",
    "read_road_path",
    "read_roads",
    "read_route",
    "read_text",
    "read_vehicle_track",
    "read_yaml_mapping",
    "trajectory_geojson",
    "volume_files",
    "write_flight",
    "write_follow_trajectory",
    "write_geojson",
    "write_json",
    "write_loiter_samples_csv",
    "write_plan",
    "write_results_table",
    "write_route",
    "write_trajectory",
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


def load_environment(path: str | Path, up: str = "z", kind: Optional[str] = None,
                     origin: Georeference | None = None) -> Environment:
    """A city from a file: GeoJSON 2.5D footprints or any triangle mesh (OBJ, PLY, STL, OFF), whose
    up axis is ``up`` ("z", or "y" for Y-up files such as the Charlotte and campus OBJ exports,
    where north is -Z). ``kind`` "geojson" or "mesh"; by default from the suffix
    (``.geojson``/``.json`` are GeoJSON). ``origin`` becomes ``env.origin``; a longitude/latitude
    GeoJSON is projected about it (without it: about the data's centre)."""
    text = str(path)
    if kind is None:
        kind = "geojson" if Path(text).suffix.lower() in GEOJSON_SUFFIXES else "mesh"
    if kind == "geojson":
        return Environment.from_geojson(text, origin=origin)
    env = Environment.from_mesh(text, up)
    env.origin = origin
    return env


def footprint_environment(map_path: str | Path | None, footprints: str | Path | None = None,
                          origin: Georeference | None = None) -> Environment | None:
    """Building footprints to draw under a figure without loading the map for planning: the
    given GeoJSON, else a GeoJSON map itself, else ``buildings.geojson`` beside a mesh map
    (Charlotte ships both), else None. Longitude/latitude files are projected about ``origin``
    (else their centre), as the map is."""
    if footprints:
        return Environment.from_geojson(str(footprints), origin=origin)
    if not map_path:
        return None
    map_file = Path(map_path)
    if map_file.suffix.lower() in GEOJSON_SUFFIXES:
        return Environment.from_geojson(str(map_file), origin=origin)
    beside = map_file.with_name("buildings.geojson")
    return Environment.from_geojson(str(beside), origin=origin) if beside.exists() else None


def read_plan(path: str | Path, key: str = "plan") -> AnyPlan:
    """An orbit plan JSON file, by its ``format``: a VisibilityOrbitPlan (``vistrack orbits``,
    ``vistrack run``) or a plain OrbitPlan (times, radii and the POI path)."""
    text = read_text(path, key)
    try:
        data = json.loads(text)
    except json.JSONDecodeError as error:
        raise VistrackError(f"{key} = {path}: not JSON ({error.msg} at line {error.lineno})") from None
    except RecursionError:
        raise VistrackError(f"{key} = {path}: not JSON (nested too deeply)") from None
    except ValueError:  # after JSONDecodeError, its subclass: integers of more than 4300 digits
        raise VistrackError(f"{key} = {path}: not JSON (a number too long to read)") from None
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


def parse_yaml(text: str, key: str, path: str | Path) -> Any:
    """The YAML document in ``text`` (read from ``path``) as plain data, through a safe loader that
    refuses a key given twice in one mapping (PyYAML would keep the last one without a word);
    VistrackError naming ``key``, the file and the line for anything that is not valid YAML."""
    import yaml

    class UniqueKeyLoader(yaml.SafeLoader):
        def construct_mapping(self, node: yaml.MappingNode, deep: bool = False) -> dict[Any, Any]:
            seen: set[Any] = set()
            for key_node, _ in node.value:
                if key_node.tag == "tag:yaml.org,2002:merge":
                    continue  # "<<: *base" merges keys that the mapping may override
                name = self.construct_object(key_node, deep=deep)
                try:
                    duplicated = name in seen
                except TypeError:  # an unhashable key: SafeLoader reports it
                    continue
                if duplicated:
                    raise yaml.constructor.ConstructorError(
                        "while constructing a mapping", node.start_mark,
                        f"found the key {name!r} twice (a YAML key is given once)", key_node.start_mark)
                seen.add(name)
            return super().construct_mapping(node, deep)

    try:
        return yaml.load(text, Loader=UniqueKeyLoader)
    except yaml.YAMLError as error:
        reason = " ".join(str(error).split())
        raise VistrackError(f"{key} = {path}: not valid YAML ({reason})") from None
    except RecursionError:
        raise VistrackError(f"{key} = {path}: not valid YAML (nested too deeply)") from None
    except ValueError:  # Python refuses integers of more than 4300 digits
        raise VistrackError(f"{key} = {path}: not valid YAML (a number too long to read)") from None


def read_yaml_mapping(path: str | Path, key: str) -> dict[str, Any]:
    """A YAML file holding one mapping (empty file: empty mapping)."""
    data = parse_yaml(read_text(path, key), key, path)
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


# ---------------------------------------------------------------------------------------------
# GeoJSON in WGS84 (RFC 7946: [longitude, latitude]) of trajectories, orbit plans and missions,
# for any GIS tool to show over a map. Local points go through the georeference's map plane
# (Georeference.to_latlon), the same one maps come in through.
# ---------------------------------------------------------------------------------------------


def lon_lat(points: Any, georeference: Georeference) -> list[list[float]]:
    """[[lon, lat], ...] of local points, rows (x, y[, ...])."""
    array = np.asarray(points, dtype=float)
    if array.ndim != 2 or array.shape[1] < 2 or len(array) == 0:
        raise VistrackError(f"points = array of shape {array.shape}: must be rows (x, y) in local metres")
    lat, lon = georeference.to_latlon(array[:, 0], array[:, 1])
    return [[float(a), float(b)] for a, b in zip(np.atleast_1d(lon), np.atleast_1d(lat))]


def line_feature(points: Any, georeference: Georeference, properties: dict[str, Any] | None = None) -> dict[str, Any]:
    """A LineString Feature through local points."""
    return {"type": "Feature", "properties": dict(properties or {}),
            "geometry": {"type": "LineString", "coordinates": lon_lat(points, georeference)}}


def point_feature(point: Sequence[float], georeference: Georeference,
                  properties: dict[str, Any] | None = None) -> dict[str, Any]:
    """A Point Feature at a local point (x, y)."""
    return {"type": "Feature", "properties": dict(properties or {}),
            "geometry": {"type": "Point", "coordinates": lon_lat([point[:2]], georeference)[0]}}


def feature_collection(features: list[dict[str, Any]], **members: Any) -> dict[str, Any]:
    """A FeatureCollection (extra top-level members, e.g. the origin, kept as given)."""
    return {"type": "FeatureCollection", **members, "features": features}


def trajectory_geojson(result: SimulationResult, georeference: Georeference,
                       properties: dict[str, Any] | None = None) -> dict[str, Any]:
    """The flown path of a simulation (``result.state`` rows x, y, psi) as a LineString, with
    its duration and visibility fraction."""
    state = np.asarray(result.state, dtype=float)
    fraction = result.visibility_fraction  # None when simulated without a scene
    props = {"kind": "trajectory", "duration_s": float(result.t[-1] - result.t[0]),
             "visibility_fraction": None if fraction is None else float(fraction), **(properties or {})}
    return line_feature(state[:, :2], georeference, props)


def orbit_plan_geojson(plan: OrbitPlan, georeference: Georeference) -> list[dict[str, Any]]:
    """An orbit plan's features: the POI path (LineString) and one Point per sample at the orbit
    centre g(t_k) with its time and radius."""
    features = [line_feature(np.asarray(plan.poi.waypoints)[:, :2], georeference,
                             {"kind": "poi_path", "speed_mps": float(plan.poi.speed)})]
    for k, (t, center, radius) in enumerate(zip(plan.times, np.asarray(plan.centers), plan.radii)):
        features.append(point_feature(center, georeference, {"kind": "orbit_center", "sample": k,
                                                             "time_s": float(t), "radius_m": float(radius)}))
    return features


def mission_geojson(mission: Mission) -> dict[str, Any]:
    """A mission over a map: the home Point, the route (LineString from home through every item
    with a coordinate) and one Point per such item (command, its parameters, altitude)."""
    from .mission import Frame

    lat, lon, alt = mission.home
    features: list[dict[str, Any]] = [{"type": "Feature",
                                       "properties": {"kind": "home", "altitude_amsl_m": alt},
                                       "geometry": {"type": "Point", "coordinates": [lon, lat]}}]
    route = [[lon, lat]]
    mode = {int(Frame.GLOBAL): "amsl", int(Frame.GLOBAL_RELATIVE_ALT): "relative"}
    for seq, item in enumerate(mission.items, start=1):
        if not item.has_coordinate:
            continue
        route.append([item.lon, item.lat])
        features.append({"type": "Feature",
                         "properties": {"kind": "mission_item", "seq": seq, "command": item.command,
                                        "name": item.name, "params": list(item.params), "altitude_m": item.alt,
                                        "altitude_mode": mode[item.frame]},
                         "geometry": {"type": "Point", "coordinates": [item.lon, item.lat]}})
    features.insert(1, {"type": "Feature", "properties": {"kind": "route"},
                        "geometry": {"type": "LineString", "coordinates": route}})
    return feature_collection(features)


def write_geojson(collection: dict[str, Any], path: str | Path) -> Path:
    """Write a FeatureCollection (full double precision)."""
    path = Path(path)
    try:
        path.write_text(json.dumps(collection, indent=1, allow_nan=False) + "\n", encoding="utf-8")
    except OSError as error:
        raise VistrackError(f"path = {path}: cannot write the file ({error.strerror})") from None
    return path
# ---- waypoint navigation (issue 13): routes and flown trajectories --------------------------------

def read_route(path: str | Path, key: str = "route") -> np.ndarray:
    """A route as an (n, 2) array from CSV: a header naming columns ``x`` and ``y`` (others are
    ignored), or two numeric columns without a header; ``#`` starts a comment line. Errors name
    ``key``, the file and the line."""
    import csv

    text = read_text(path, key)
    lines = [(number, line) for number, line in enumerate(text.splitlines(), start=1)
             if line.strip() and not line.lstrip().startswith("#")]
    if not lines:
        raise VistrackError(f"{key} = {path}: no waypoints in the file")
    rows = list(csv.reader(line for _, line in lines))
    header = [cell.strip().lower() for cell in rows[0]]
    columns = (0, 1)
    body = list(zip((n for n, _ in lines), rows))
    if "x" in header or "y" in header:
        if "x" not in header or "y" not in header:
            raise VistrackError(f"{key} = {path}: the header needs both columns x and y, got {rows[0]}")
        columns = (header.index("x"), header.index("y"))
        body = body[1:]
    points = []
    for number, row in body:
        try:
            point = [float(row[c]) for c in columns]
        except (IndexError, ValueError):
            raise VistrackError(f"{key} = {path}: line {number} is not two numbers x, y: {','.join(row)!r}") from None
        if not all(np.isfinite(point)):
            raise VistrackError(f"{key} = {path}: line {number} has a value that is not finite: {point}")
        points.append(point)
    if len(points) < 2:
        raise VistrackError(f"{key} = {path}: {len(points)} waypoint(s), at least two are needed")
    return np.array(points, dtype=float)


def write_route(points: np.ndarray, path: str | Path) -> Path:
    """An (n, 2) route as CSV with the header x,y (what :func:`read_route` reads)."""
    file = Path(path)
    file.write_text("x,y\n" + "".join(f"{x!r},{y!r}\n" for x, y in points.tolist()), encoding="utf-8")
    return file


def write_flight(trajectory: "FlightTrajectory", path: str | Path) -> Path:
    """A flown trajectory (``vistrack.flight.FlightTrajectory``) as CSV, full double precision:
    t,x,y,psi,command,target_x,target_y,target_index,wind_east,wind_north."""
    file = Path(path)
    columns: list[list[Any]] = [
        trajectory.t.tolist(), trajectory.x.tolist(), trajectory.y.tolist(), trajectory.psi.tolist(),
        trajectory.command.tolist(), trajectory.target[:, 0].tolist(), trajectory.target[:, 1].tolist(),
        trajectory.target_index.tolist(), trajectory.wind[:, 0].tolist(), trajectory.wind[:, 1].tolist()]
    lines = ["t,x,y,psi,command,target_x,target_y,target_index,wind_east,wind_north\n"]
    for row in zip(*columns):
        lines.append(",".join(repr(v) for v in row) + "\n")
    file.write_text("".join(lines), encoding="utf-8")
    return file


# --- Sweeps (vistrack.sweep): road files, the results table ---------------------------------------

ROAD_MERGE_DISTANCE = 0.5  # m: vertices of different LineStrings this close are one road node


def read_roads(path: str | Path, key: str = "routes.roads") -> RoadNetwork:
    """A road network from a GeoJSON file of LineString / MultiLineString features in local
    (east, north) metres: every vertex is a node, consecutive vertices are joined by an edge, and
    vertices closer than ``ROAD_MERGE_DISTANCE`` (lines meeting at a junction) are one node. Roads
    meet only where they share a vertex, as in OpenStreetMap ways."""
    import numpy as np
    from scipy.spatial import cKDTree

    text = read_text(path, key)
    try:
        data = json.loads(text)
    except json.JSONDecodeError as error:
        raise VistrackError(f"{key} = {path}: not JSON ({error.msg} at line {error.lineno})") from None
    features = data.get("features") if isinstance(data, dict) else None
    if not isinstance(features, list):
        raise VistrackError(f"{key} = {path}: not a GeoJSON FeatureCollection (no 'features' list)")
    lines: list[list[tuple[float, float]]] = []
    for i, feature in enumerate(features):
        geometry = feature.get("geometry") if isinstance(feature, dict) else None
        kind = geometry.get("type") if isinstance(geometry, dict) else None
        coordinates = geometry.get("coordinates") if isinstance(geometry, dict) else None
        if kind not in ("LineString", "MultiLineString") or not isinstance(coordinates, list):
            raise VistrackError(f"{key} = {path}: features[{i}] is {kind!r}, not a LineString or MultiLineString")
        for part in [coordinates] if kind == "LineString" else coordinates:
            try:
                line = [(float(p[0]), float(p[1])) for p in part]
            except (TypeError, ValueError, IndexError):
                raise VistrackError(f"{key} = {path}: features[{i}] has a position that is not [x, y]") from None
            if len(line) < 2 or not np.isfinite(line).all():
                raise VistrackError(f"{key} = {path}: features[{i}] needs at least two finite positions")
            lines.append(line)
    if not lines:
        raise VistrackError(f"{key} = {path}: no roads in the file")
    vertices = np.array([p for line in lines for p in line])
    # Union-find over vertices closer than the merge distance; a node is each group's first vertex.
    parent = list(range(len(vertices)))

    def root(i: int) -> int:
        while parent[i] != i:
            parent[i] = parent[parent[i]]
            i = parent[i]
        return i

    for a, b in sorted(cKDTree(vertices).query_pairs(ROAD_MERGE_DISTANCE)):
        ra, rb = root(a), root(b)
        parent[max(ra, rb)] = min(ra, rb)
    node_of: dict[int, int] = {}
    for i in range(len(vertices)):
        node_of.setdefault(root(i), len(node_of))
    nodes = np.array([vertices[r] for r in sorted(node_of, key=node_of.__getitem__)])
    edges: set[tuple[int, int]] = set()
    first = 0
    for line in lines:
        ids = [node_of[root(first + k)] for k in range(len(line))]
        first += len(line)
        edges.update((min(a, b), max(a, b)) for a, b in zip(ids, ids[1:]) if a != b)
    return RoadNetwork(nodes, np.array(sorted(edges), dtype=np.int64).reshape(-1, 2))


def _table_column(values: list[Any]) -> tuple[str, list[Any]]:
    """A column's type ("bool", "int", "float" or "string") and its values, None where missing;
    mixed or non-scalar values become text (JSON for lists and mappings)."""
    present = [v for v in values if v is not None]
    if present and all(isinstance(v, bool) for v in present):
        return "bool", values
    if all(isinstance(v, int) and not isinstance(v, bool) for v in present):
        return ("int", values) if present else ("string", values)
    if all(isinstance(v, (int, float)) and not isinstance(v, bool) for v in present):
        return "float", [None if v is None else float(v) for v in values]
    return "string", [None if v is None else v if isinstance(v, str) else json.dumps(v) for v in values]


def write_results_table(rows: list[dict[str, Any]], columns: list[str], folder: str | Path,
                        metadata: Optional[dict[str, Any]] = None) -> list[Path]:
    """A sweep's table, one row per case in the given order, as ``results.csv`` (floats written
    with every digit, missing values empty) and ``results.parquet`` (typed columns: bool, int64,
    float64 or string; ``metadata`` kept as JSON under the schema key ``vistrack.sweep``)."""
    import csv

    import pyarrow as pa
    import pyarrow.parquet as pq

    root = Path(folder)
    root.mkdir(parents=True, exist_ok=True)
    typed = {name: _table_column([row.get(name) for row in rows]) for name in columns}
    csv_file = root / "results.csv"
    with csv_file.open("w", newline="", encoding="utf-8") as stream:
        writer = csv.writer(stream)
        writer.writerow(columns)
        for i in range(len(rows)):
            writer.writerow(["" if typed[c][1][i] is None else repr(typed[c][1][i]) if typed[c][0] == "float"
                             else typed[c][1][i] for c in columns])
    arrow_types = {"bool": pa.bool_(), "int": pa.int64(), "float": pa.float64(), "string": pa.string()}
    table = pa.table({c: pa.array(typed[c][1], type=arrow_types[typed[c][0]]) for c in columns})
    if metadata is not None:
        table = table.replace_schema_metadata({"vistrack.sweep": json.dumps(metadata)})
    parquet_file = root / "results.parquet"
    pq.write_table(table, parquet_file)
    return [csv_file, parquet_file]


def read_results_table(path: str | Path) -> list[dict[str, Any]]:
    """The rows of a ``results.parquet`` written by :func:`write_results_table`, in file order."""
    import pyarrow.parquet as pq

    if not Path(path).is_file():
        raise VistrackError(f"results = {path}: no such file")
    rows: list[dict[str, Any]] = pq.read_table(path).to_pylist()
    return rows


def append_json_line(data: Any, path: str | Path) -> None:
    """One JSON document as one line at the end of a file (rows of a sweep as they arrive)."""
    with Path(path).open("a", encoding="utf-8") as stream:
        stream.write(json.dumps(data) + "\n")


# ---------------------------------------------------------------------------------------------
# Loiter planning (issue 14): scenario YAML, the sampled path as CSV
# ---------------------------------------------------------------------------------------------


def read_loiter_scenario(path: str | Path) -> LoiterScenario:
    """A loiter scenario file (examples/loiter_*.yaml); every bad value names its key."""
    from . import schema
    from .georeference import Georeference
    from .loiter import Camera, Scenario

    data = read_yaml_mapping(path, "scenario")
    allowed = {"name", "aois", "start", "end", "turn_radius", "speed", "aoi_radius", "turns", "camera",
               "threshold", "dt", "paper", "origin"}
    schema.reject_unknown(data, allowed)

    raw_aois = data.get("aois")
    if not isinstance(raw_aois, list) or not raw_aois:
        raise schema.fail("aois", raw_aois, "must be a non-empty list of [x, y] AOI centres")
    aois = np.array([schema.pair(f"aois[{i}]", a) for i, a in enumerate(raw_aois)], dtype=float)
    camera_section = schema.section(data, "camera", {"fov_deg", "max_gimbal_deg", "altitude", "levelled"})
    camera = schema.apply_checks(Camera(), camera_section, "camera", {
        "fov_deg": schema.positive, "max_gimbal_deg": lambda k, v: schema.number(k, v, low=0.0),
        "altitude": schema.positive, "levelled": schema.boolean})
    paper = data.get("paper") or {}
    if not isinstance(paper, dict):
        raise schema.fail("paper", paper, "must map a method to its Table 1 numbers")
    for method, numbers in paper.items():
        if not isinstance(numbers, dict):
            raise schema.fail(f"paper.{method}", numbers, "must map a quantity to a number")
    paper_numbers = {str(method): {str(name): schema.number(f"paper.{method}.{name}", value)
                                   for name, value in numbers.items()} for method, numbers in paper.items()}
    scenario = Scenario(
        aois=aois,
        name=str(data.get("name", Path(path).stem)),
        start=schema.pair("start", data.get("start", [0.0, 0.0])),
        end=schema.pair("end", data.get("end", [0.0, 0.0])),
        turn_radius=schema.positive("turn_radius", data.get("turn_radius", 46.0)),
        speed=schema.positive("speed", data.get("speed", 12.0)),
        aoi_radius=schema.positive("aoi_radius", data.get("aoi_radius", 46.0)),
        turns=schema.integer("turns", data.get("turns", 1), 1, 1000),
        camera=camera,
        threshold=schema.number("threshold", data.get("threshold", 0.75), low=0.0, high=1.0, low_open=True),
        dt=schema.positive("dt", data.get("dt", 1.0)),
        paper=paper_numbers,
        origin=None if data.get("origin") is None else Georeference.from_value(data["origin"], "origin"),
    )
    # The planner's own checks (overlapping circles, R < r, start inside a circle) name the key.
    scenario.plan("tlpp")
    return scenario


def write_loiter_samples_csv(path: str | Path, plan: LoiterPlan, coverage: LoiterCoverage, dt: float,
                             threshold: float = 0.75) -> Path:
    """The plan sampled every dt (as the coverage was): t, x, y, psi, turn rate, segment role, the AOI
    most in view, the gimbal angle and the AOIs covered at that step."""
    samples = plan.sample_states(dt, False)
    roles = [plan.segments[k].role for k in samples.segment]
    covered = [";".join(str(i) for i in np.flatnonzero(row >= threshold)) for row in coverage.fraction]
    file = Path(path)
    file.parent.mkdir(parents=True, exist_ok=True)
    with open(file, "w", encoding="utf-8") as out:
        out.write("t,x,y,psi,turn_rate,role,pointed_aoi,gimbal_rad,covered_aois\n")
        for k in range(samples.poses.shape[0]):
            x, y, psi = samples.poses[k]
            out.write(f"{samples.t[k]:.6f},{x:.6f},{y:.6f},{psi:.9f},{samples.turn_rate[k]:.9f},{roles[k]},"
                      f"{coverage.pointed[k]},{coverage.gimbal[k]:.6f},{covered[k]}\n")
    return file


# ---- follow (issue 15): vehicle tracks, road paths, follow trajectories -------------------------


def _numeric_rows(path: str | Path, key: str, columns: tuple[int, ...]) -> np.ndarray:
    """The rows of a comma-separated numeric file (a header line is skipped), each with one of
    ``columns`` counts; VistrackError naming the key, the line and the value otherwise."""
    import numpy as np

    rows: list[list[float]] = []
    for number, line in enumerate(read_text(path, key).splitlines(), start=1):
        cells = [c.strip() for c in line.split(",")]
        if not line.strip() or line.lstrip().startswith("#"):
            continue
        try:
            values = [float(c) for c in cells]
        except ValueError:
            if not rows and number == 1:
                continue  # a header
            raise VistrackError(f"{key} = {path}: line {number} is not numbers: {line.strip()!r}") from None
        if len(values) not in columns:
            raise VistrackError(f"{key} = {path}: line {number} has {len(values)} values, expected "
                                f"{' or '.join(str(c) for c in columns)}")
        rows.append(values[: min(columns)])
    if len(rows) < 2:
        raise VistrackError(f"{key} = {path}: needs at least two rows, found {len(rows)}")
    return np.array(rows, dtype=float)


def read_vehicle_track(path: str | Path, key: str = "vehicle.track") -> tuple[np.ndarray, np.ndarray]:
    """A ground vehicle's track: one ``t,x,y`` per line (s, m; a header line allowed). Returns the
    times (n,) and positions (n, 2); GroundVehicle checks that the times increase and are finite."""
    rows = _numeric_rows(path, key, (3,))
    return rows[:, 0].copy(), rows[:, 1:3].copy()


def read_road_path(path: str | Path, key: str = "road") -> np.ndarray:
    """A road polyline, one ``x,y`` or ``x,y,z`` per line (the data's POI paths): (n, 2)."""
    return _numeric_rows(path, key, (2, 3))[:, :2].copy()


def write_follow_trajectory(result: Any, path: str | Path) -> Path:
    """A follow run as CSV, one sample per line, full precision: t, the UAV (x, y, psi, turn rate,
    bank), the vehicle, the offset point, the desired position, the waypoint flown to, the mode,
    the tracking error, the along-track lag, the camera's view (0/1) and, when evaluated, the
    line of sight (0/1). ``result``: a vistrack.follow.FollowResult."""
    import numpy as np

    run = result.run
    columns = {
        "t": np.asarray(run.t), "x": result.state[:, 0], "y": result.state[:, 1], "psi": result.state[:, 2],
        "turn_rate": np.asarray(run.turn_rate), "bank": np.asarray(run.bank),
        "vehicle_x": result.vehicle[:, 0], "vehicle_y": result.vehicle[:, 1],
        "offset_x": result.offset_point[:, 0], "offset_y": result.offset_point[:, 1],
        "desired_x": result.desired[:, 0], "desired_y": result.desired[:, 1],
        "target_x": np.asarray(run.target)[:, 0], "target_y": np.asarray(run.target)[:, 1],
        "tracking_error": np.asarray(run.tracking_error), "along_track_lag": np.asarray(run.along_track_lag),
        "in_view": result.in_view.astype(int),
    }
    if result.line_of_sight is not None:
        columns["line_of_sight"] = result.line_of_sight.astype(int)
    mode = result.mode
    names = list(columns)
    lines = [",".join([*names[:16], "mode", *names[16:]])]
    values = list(columns.values())
    for i in range(len(mode)):
        cells = [repr(float(v[i])) for v in values[:16]] + [str(mode[i])] + [str(int(v[i])) for v in values[16:]]
        lines.append(",".join(cells))
    file = Path(path)
    file.write_text("\n".join(lines) + "\n", encoding="utf-8")
    return file
