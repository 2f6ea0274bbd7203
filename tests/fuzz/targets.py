"""Fuzz targets: every loader and the array entry points, each a function of one input (bytes).

A target passes an input when vistrack either returns finite results or raises VistrackError
(the one error type for bad input). Anything else fails it: another exception type, a NaN or
infinity in a result, a crash of the interpreter (the fuzzer sees the process die) or a hang
(the fuzzer's -timeout). ``tests/fuzz/fuzz.py`` drives them with atheris; ``tests/python/
test_fuzz_regressions.py`` replays the seeds and every stored finding (tests/fuzz/regressions/).

Loaders read files, so each input is written to a temporary file with the loader's suffix.
"""

from __future__ import annotations

import math
import os
import sys
import tempfile
from dataclasses import dataclass
from pathlib import Path
from typing import Any, Callable

REPO = Path(__file__).resolve().parents[2]
sys.path.insert(0, str(REPO / "tests" / "python"))
import numpy as np  # noqa: E402

import support.build_tree  # noqa: E402,F401  (imports vistrack from $VISTRACK_BUILD_DIR when set)
import vistrack as vt  # noqa: E402
from vistrack import VistrackError  # noqa: E402
from vistrack.follow_scenario import FollowScenario  # noqa: E402
from vistrack.intercept import InterceptProblem  # noqa: E402
from vistrack.io import read_loiter_scenario, read_plan, read_roads, read_route, read_vehicle_track  # noqa: E402
from vistrack.scenario import Scenario  # noqa: E402
from vistrack.sweep.spec import SweepSpec  # noqa: E402

SCRATCH = Path(tempfile.mkdtemp(prefix="vistrack-fuzz-", dir="/dev/shm" if os.path.isdir("/dev/shm") else None))


class Finding(AssertionError):
    """What a target found wrong (not a VistrackError)."""


def require_finite(value: Any, where: str = "result") -> None:
    """Every number reachable from ``value`` (floats, arrays, tuples, lists, dicts, results with
    attributes) is finite; Finding naming the first that is not."""
    if isinstance(value, (bool, int, str, bytes)) or value is None:
        return
    if isinstance(value, float):
        if not math.isfinite(value):
            raise Finding(f"{where} = {value}")
        return
    if isinstance(value, np.ndarray):
        if value.dtype.kind in "fc" and not np.all(np.isfinite(value)):
            raise Finding(f"{where} holds {value[~np.isfinite(value)][:3]}")
        return
    if isinstance(value, dict):
        for key, item in value.items():
            require_finite(item, f"{where}[{key!r}]")
        return
    if isinstance(value, (list, tuple)):
        for k, item in enumerate(value):
            require_finite(item, f"{where}[{k}]")
        return
    raise TypeError(f"require_finite: {type(value).__name__} at {where}")


def write(data: bytes, suffix: str) -> Path:
    """The input as a file with the loader's suffix (one scratch file per suffix, overwritten)."""
    path = SCRATCH / f"input{suffix}"
    path.write_bytes(data)
    return path


# --------------------------------------------------------------------------------------------
# Loaders


def documents(data: bytes) -> None:
    """The one bounded JSON/YAML reader (vistrack.io.documents) that every loader parses through;
    first byte even: JSON, odd: YAML. What it reads is within the limits (nesting, values with YAML
    aliases expanded), and a message quoting it is short however large it is (vistrack.preview)."""
    from vistrack.io.documents import MAX_DOCUMENT_DEPTH, parse_json, parse_yaml
    from vistrack.preview import PREVIEW_CHARACTERS, preview
    from vistrack.schema import fail

    try:
        text = data[1:].decode("utf-8")
    except UnicodeDecodeError:
        return  # read_text refuses it before any parser sees it
    parse = parse_json if not data or data[0] % 2 == 0 else parse_yaml
    result = parse(text, "document", "input")
    depth, stack = 0, [(result, 0)]
    while stack:  # every container is reached once per path: aliases are counted as the reader counts them
        item, level = stack.pop()
        if isinstance(item, (list, dict)):
            depth = max(depth, level + 1)
            if depth > MAX_DOCUMENT_DEPTH:
                raise Finding(f"read a document nested {depth} levels deep")
            stack.extend((child, level + 1) for child in (item.values() if isinstance(item, dict) else item))
    if len(preview(result)) > PREVIEW_CHARACTERS or len(str(fail("k", result, "x"))) > PREVIEW_CHARACTERS + 10:
        raise Finding("a preview longer than its limit")


def geojson(data: bytes) -> None:
    env = vt.Environment.from_geojson(write(data, ".geojson"))
    require_finite(np.asarray(env.vertices), "vertices")
    require_finite(np.asarray(env.heights), "heights")


MESH_SUFFIXES = (".obj", ".off", ".ply", ".stl")


def mesh(data: bytes) -> None:
    """First byte: suffix (obj, off, ply, stl) and up axis; the rest is the file."""
    if not data:
        return
    suffix = MESH_SUFFIXES[data[0] % 4]
    env = vt.Environment.from_mesh(write(data[1:], suffix), up="y" if data[0] & 4 else "z")
    require_finite(np.asarray(env.vertices), "vertices")
    require_finite(float(env.max_height), "max_height")


def csv(data: bytes) -> None:
    poi = vt.PoiPath.from_csv(write(data, ".csv"), speed=5.0)
    for t in (0.0, 0.5 * poi.duration, poi.duration):
        require_finite(np.asarray(poi.position(t)), f"position({t})")
        require_finite(np.asarray(poi.velocity(t)), f"velocity({t})")
    require_finite(poi.length, "length")


_DEMO: vt.Environment | None = None


def demo() -> vt.Environment:
    global _DEMO
    if _DEMO is None:
        _DEMO = vt.Environment.demo()
    return _DEMO


def scenario(data: bytes) -> None:
    loaded = Scenario.load(write(data, ".yaml"))
    require_finite(loaded.to_dict(), "scenario")
    spec = loaded.poi
    if spec.waypoints is not None or spec.nodes is not None or spec.route is not None:
        poi = spec.build(demo())  # the demo's roads for nodes and routes
        work = vt.estimate_work(poi, loaded.planning)
        require_finite([work.volumes, work.bytes], "estimate_work")


def plan(data: bytes) -> None:
    loaded = read_plan(write(data, ".json"))
    t = np.asarray(loaded.times)
    require_finite(t, "times")
    for s in (t[0], 0.5 * (t[0] + t[-1]), t[-1]):
        require_finite([loaded.radius(float(s)), loaded.radius_rate(float(s))], f"R({s})")
    require_finite(np.asarray(loaded.centers), "centers")
    again = type(loaded).from_json(loaded.to_json())
    if list(again.radii) != list(loaded.radii):
        raise Finding("to_json/from_json changed the radii")


def _vv_checksum(body: bytes) -> bytes:
    """The VV file's trailer (visibility/volume_cache_io.cpp): FNV-1a over little-endian 8-byte words."""
    h, prime, mask = 14695981039346656037, 1099511628211, (1 << 64) - 1
    whole = len(body) - len(body) % 8
    for word in np.frombuffer(body[:whole], dtype="<u8").tolist():
        h = ((h ^ word) * prime) & mask
    for byte in body[whole:]:
        h = ((h ^ byte) * prime) & mask
    return h.to_bytes(8, "little")


def vv(data: bytes) -> None:
    """First byte odd: the rest's checksum trailer is recomputed, so a mutation reaches the
    checks behind the checksum (a fuzzer would almost never forge it)."""
    if not data:
        return
    body = data[1:]
    if data[0] & 1 and len(body) > 8:
        body = body[:-8] + _vv_checksum(body[:-8])
    volume = vt.VisibilityVolume.load(write(body, ".bin"))
    require_finite([volume.volume, volume.grid_volume()], "volume")
    require_finite(np.asarray(volume.vertices), "vertices")
    g = np.asarray(volume.poi)
    for polygon in volume.slice(float(g[2]) + 1.0):
        require_finite(np.asarray(polygon.outer), "slice")
    require_finite(vt.xor_volume(volume, volume), "xor_volume(vv, vv)")


def mission(data: bytes) -> None:
    """First byte even: a QGroundControl .plan, odd: QGC WPL 110 (.waypoints)."""
    if not data:
        return
    loaded = vt.mission.load(write(data[1:], ".waypoints" if data[0] & 1 else ".plan"))
    require_finite(np.asarray(loaded.coordinates()), "coordinates")
    require_finite(list(loaded.home), "home")


def intercept(data: bytes) -> None:
    problem = InterceptProblem.load(write(data, ".yaml"), {})
    result = problem.solve()
    require_finite([result.angle, result.time, result.residual, result.path.length], "intercept")


def loiter(data: bytes) -> None:
    """A loiter scenario file, planned by the three methods in the given order; coverage when the
    flight is short enough to sample within the fuzzer's timeout."""
    loaded = read_loiter_scenario(write(data, ".yaml"))
    for method in ("fly_through", "tlpp", "ldlpp"):
        planned = loaded.plan(method)
        require_finite([planned.length, planned.flight_time, planned.transit_time], method)
        if planned.flight_time / loaded.dt <= 20000:
            covered = loaded.coverage(planned)
            require_finite([covered.time, covered.area, np.asarray(covered.time_per_aoi)], f"{method} coverage")


def follow(data: bytes) -> None:
    """A follow scenario file (loaded and validated, not flown: a valid flight may last hours)."""
    loaded = FollowScenario.load(write(data, ".yaml"))
    require_finite([loaded.uav.speed, loaded.uav.min_turn_radius, loaded.uav.altitude], "uav")
    require_finite([(leg.heading, leg.speed, leg.end_speed, leg.duration) for leg in loaded.legs], "legs")


def sweep(data: bytes) -> None:
    """A sweep file: validated and expanded into its cases (not run)."""
    spec = SweepSpec.load(write(data, ".yaml"))
    if spec.case_count <= 2000:
        cases = spec.cases()
        if len(cases) != spec.case_count:
            raise Finding(f"{len(cases)} cases, case_count = {spec.case_count}")


def route(data: bytes) -> None:
    """First byte: which reader (waypoint route CSV, vehicle track CSV, road GeoJSON); a route is
    then flown by the DWN guidance for at most ten simulated minutes."""
    if not data:
        return
    which, body = data[0] % 3, data[1:]
    if which == 0:
        points = read_route(write(body, ".csv"))
        require_finite(points, "route")
        flight = vt.waypoint_nav.fly(points, turn_radius=40.0, speed=16.0, max_time=600.0)
        require_finite(np.asarray(flight.trajectory), "trajectory")
    elif which == 1:
        times, positions = read_vehicle_track(write(body, ".csv"))
        require_finite([np.asarray(times), np.asarray(positions)], "track")
    else:
        roads = read_roads(write(body, ".geojson"))
        require_finite(np.asarray(roads.nodes), "nodes")


# --------------------------------------------------------------------------------------------
# Array entry points, driven by a stream of numbers from the input


class Numbers:
    """Floats and integers from the input bytes, with the values that break numerics (NaN, inf,
    1e308, 5e-324, 0, -0) made common; zeros once the input runs out."""

    SPECIAL = (0.0, -0.0, 1.0, -1.0, math.nan, math.inf, -math.inf, 1e308, -1e308, 5e-324, 1e-300, 1e300,
               1e7, -1e7, 1e-6, 1e4, math.pi, 2 * math.pi, 1e9, 1e-9)

    def __init__(self, data: bytes) -> None:
        self.data = data
        self.at = 0

    def byte(self) -> int:
        if self.at >= len(self.data):
            return 0
        self.at += 1
        return self.data[self.at - 1]

    def number(self) -> float:
        kind = self.byte()
        if kind < 64:
            return self.SPECIAL[kind % len(self.SPECIAL)]
        raw = bytes(self.byte() for _ in range(8))
        value = float(np.frombuffer(raw, dtype="<f8")[0])
        return value if kind < 192 else float(np.clip(value, -1e3, 1e3)) if math.isfinite(value) else value

    def integer(self, low: int, high: int) -> int:
        value = self.byte() | (self.byte() << 8) | (self.byte() << 16)
        return low + value % (high - low + 1)

    def rows(self, columns: int, most: int = 8, count: int | None = None) -> np.ndarray:
        n = self.integer(0, most) if count is None else count
        return np.array([[self.number() for _ in range(columns)] for _ in range(n)], dtype=float).reshape(n, columns)


def _call(numbers: Numbers) -> Any:
    """One API call chosen and fed by the input."""
    n = numbers
    which = n.integer(0, 21)
    if which == 0:
        return vt.dubins.shortest_path((n.number(), n.number(), n.number()), (n.number(), n.number(), n.number()),
                                       n.number()).sample(max(n.number(), 1e-3) if n.byte() & 1 else 1.0)
    if which == 1:
        q0s = n.rows(3)
        lengths, _ = vt.dubins.shortest_lengths(q0s, n.rows(3, count=len(q0s)), n.number(),
                                                threads=n.integer(-2, 200000))
        return lengths
    if which == 2:
        path = vt.dubins.path_to_circle((n.number(), n.number(), n.number()), n.number(), (n.number(), n.number()),
                                        n.number(), n.number(), "cw" if n.byte() & 1 else "ccw")
        return [path.length, path.goal]
    if which == 3:
        result = vt.dubins.intercept_circle((n.number(), n.number(), n.number()), n.number(), n.number(),
                                            (n.number(), n.number()), n.number(), n.number(), n.number(),
                                            "cw" if n.byte() & 1 else "ccw")
        return [result.angle, result.time, result.path.length]
    if which == 4:
        poi = vt.PoiPath(n.rows(n.integer(2, 3)), n.number())
        t = n.number()
        return [np.asarray(poi.position(t)), np.asarray(poi.velocity(t)), poi.heading(t), poi.length]
    if which == 5:
        return vt.wrap_to_pi(n.number())
    if which == 6:
        grid = vt.DirectionGrid.from_resolution(n.number())
        return [grid.elevation(n.integer(-5, 4000)), grid.azimuth(n.integer(-5, 4000))]
    if which == 7:
        polygon = vt.Polygon(n.rows(2))
        return vt.max_inscribed_radius([polygon], (n.number(), n.number()))
    if which == 8:
        roads = vt.RoadNetwork(n.rows(2), np.array([[n.integer(-2, 10), n.integer(-2, 10)] for _ in range(3)]))
        return roads.shortest_route(n.integer(-1, 5), n.integer(-1, 5))
    if which == 9:
        return vt.visibility_volume(demo(), (n.number(), n.number(), n.number()), n.number(),
                                    resolution_deg=30.0, with_mesh=n.integer(0, 1) == 1).volume
    if which == 10:
        uav = vt.Uav(speed=n.number(), min_turn_radius=n.number(), altitude=n.number())
        return vt.min_feasible_radius(uav, n.number())
    if which == 11:
        planning = vt.Planning(spacing=n.number(), min_spacing=n.number(), max_depth=n.integer(0, 30))
        poi = vt.PoiPath(n.rows(2), n.number())
        work = vt.estimate_work(poi, planning)
        return [work.volumes, work.bytes]
    if which == 12:
        orbit = vt.OrbitState(center=(n.number(), n.number()), center_velocity=(n.number(), n.number()),
                              radius=n.number(), radius_rate=n.number())
        gains = vt.GuidanceGains(speed=n.number(), beta=n.number(), k_psi=n.number(), max_turn_rate=n.number())
        s = vt.steering((n.number(), n.number(), n.number()), orbit, gains)
        return [s.command, s.field.heading, s.field.heading_rate]
    if which == 13:
        curvature = vt.orbit_curvature(n.number(), n.number(), n.number(), n.number(), n.number())
        if math.isnan(curvature):
            raise Finding("orbit_curvature = nan")
        return curvature if math.isfinite(curvature) else 0.0  # +inf: no orbit-following motion (documented)
    if which == 14:
        scene = vt.visibility_scene(demo())
        if n.byte() & 1:
            a = n.rows(3, 4)
            return np.asarray(scene.line_of_sight(a, n.rows(3, count=len(a))), dtype=float)
        hits = np.asarray(scene.first_hits((n.number(), n.number(), n.number()), n.rows(3, 4), n.number()))
        if np.any(np.isnan(hits)):
            raise Finding(f"first_hits = {hits}")
        return hits[np.isfinite(hits)]  # +inf: nothing hit (documented)
    if which == 15:
        plan = vt.constant_radius_plan(vt.PoiPath(n.rows(2), n.number()), n.number(),
                                       vt.Uav(speed=n.number(), min_turn_radius=n.number()))
        return [plan.radius(n.number()), plan.radius_rate(n.number())]
    if which == 16:
        return vt.tune_turn_rate(n.number(), n.number(), n.number(), n.number(), n.number(), num_radii=8,
                                 num_angles=8, num_heading_errors=5).max_turn_rate
    if which == 18:
        point = vt.waypoint_nav.turning_point((n.number(), n.number(), n.number()), (n.number(), n.number()),
                                              (n.number(), n.number()), n.number(), (n.number(), n.number()))
        if not point.feasible:
            return []
        return [point.length, np.asarray(point.point), point.theta, point.heading_at_waypoint]
    if which == 19:
        return np.asarray(vt.waypoint_nav.reachability((n.number(), n.number(), n.number()), n.rows(2, 4),
                                                       n.number()))
    if which == 20:
        planned = vt.loiter.plan(n.rows(2, 5), ("fly_through", "tlpp", "ldlpp")[n.integer(0, 2)],
                                 (n.number(), n.number()), (n.number(), n.number()), n.number(), n.number(),
                                 n.number(), n.integer(-1, 4), "best" if n.byte() & 1 else "given")
        return [planned.length, planned.flight_time, planned.transit_time]
    if which == 21:
        options = vt.waypoint_nav.Options(turn_radius=n.number(), speed=n.number(), dt=n.number(),
                                          max_time=n.number() if n.byte() & 1 else None)
        return vt.waypoint_nav.navigation_time_limit(n.rows(2, 4), (n.number(), n.number(), n.number()), options)
    return vt.dubins.length_to_circle((n.number(), n.number(), n.number()), n.number(), (n.number(), n.number()),
                                      n.number(), [n.number() for _ in range(3)])


def arrays(data: bytes) -> None:
    numbers = Numbers(data)
    for _ in range(4):
        try:
            result = _call(numbers)
        except VistrackError:
            continue
        require_finite(result if not isinstance(result, np.ndarray) else np.asarray(result, dtype=float))


@dataclass(frozen=True)
class Target:
    name: str
    run: Callable[[bytes], None]
    max_len: int  # longest input the fuzzer makes (bytes)


TARGETS = {t.name: t for t in (
    Target("documents", documents, 4096),
    Target("geojson", geojson, 8192),
    Target("mesh", mesh, 8192),
    Target("csv", csv, 2048),
    Target("scenario", scenario, 4096),
    Target("plan", plan, 16384),
    Target("vv", vv, 1 << 20),
    Target("mission", mission, 8192),
    Target("intercept", intercept, 1024),
    Target("loiter", loiter, 4096),
    Target("follow", follow, 4096),
    Target("sweep", sweep, 4096),
    Target("route", route, 4096),
    Target("arrays", arrays, 1024),
)}


def check(target: Target, data: bytes) -> None:
    """Run one input; VistrackError is the expected way to refuse it, anything else propagates."""
    try:
        target.run(data)
    except VistrackError:
        pass
