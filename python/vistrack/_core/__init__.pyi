"""
vistrack C++ core: environment, Dubins, visibility, orbits, guidance, simulation, flight, waypoint navigation.
"""
from __future__ import annotations
import collections.abc
import numpy
import numpy.typing
import typing
import vistrack.georeference
import vistrack.mission.model
from . import limits
from . import dubins
from . import flight
from . import waypoint_nav
from . import loiter
from . import follow
__all__: list[str] = ['Ceiling', 'CircularOrbits', 'Control', 'DirectionGrid', 'Discretization', 'Environment', 'GuidanceGains', 'LocusCheck', 'MeshCheck', 'OdeResult', 'OdeStatistics', 'OrbitPlan', 'OrbitPlanner', 'OrbitState', 'Planning', 'PoiMotion', 'PoiPath', 'Polygon', 'RadiusProfile', 'RoadNetwork', 'Sensor', 'SimulationOptions', 'SimulationResult', 'SmoothRadiusLimits', 'Steering', 'TuningResult', 'Uav', 'VectorField', 'VisibilityOrbitPlan', 'VisibilityScene', 'VisibilityVolume', 'VistrackError', 'VolumeCost', 'WorkEstimate', 'check_closed_mesh', 'check_work', 'circular_orbits', 'constant_radius_plan', 'dubins', 'epsilon_max', 'estimate_work', 'flight', 'follow', 'grid_xor_volume', 'lambda_max', 'lemma6_curvature_bound', 'lemma7_min_gain', 'limits', 'loiter', 'lyapunov_term', 'max_inscribed_radius', 'max_orbit_curvature', 'mesh_volume', 'mesh_xor_volume', 'min_feasible_radius', 'one_minus_cos_over_x', 'orbit_configuration', 'orbit_curvature', 'orbit_polar_rate', 'orbit_signed_curvature', 'orbit_state', 'plan_on_volumes', 'plan_orbits', 'plane_visibility_polygon', 'radial_error_rate', 'radial_xor_volume', 'sample_vector_field', 'segment_boundaries', 'shares_direction_grid', 'shares_radial_mesh', 'simulate', 'sinc', 'slice_mesh', 'smooth_radius', 'smooth_radius_violation', 'solve_ode', 'steering', 'tune_turn_rate', 'vector_field', 'visibility_volume', 'visibility_volume_cost', 'visibility_volumes', 'visible_disk_radius', 'volume_bytes', 'waypoint_nav', 'wrap_to_pi', 'xor_volume']
class VistrackError(ValueError):
    pass
class Polygon:
    """
    A simple polygon with optional holes, in metres.
    """
    def __init__(self, outer: typing.Annotated[numpy.typing.ArrayLike, numpy.float64, "[m, 2]"], holes: collections.abc.Sequence[typing.Annotated[numpy.typing.ArrayLike, numpy.float64, "[m, 2]"]] = []) -> None:
        """
        outer: (n, 2) array; holes: list of (m, 2) arrays. A closing repeat is dropped.
        """
    def __repr__(self) -> str:
        ...
    def contains(self, point: typing.Annotated[numpy.typing.ArrayLike, numpy.float64, "[2, 1]"]) -> bool:
        """
        Even-odd containment; boundary points count as inside.
        """
    def distance_to_boundary(self, point: typing.Annotated[numpy.typing.ArrayLike, numpy.float64, "[2, 1]"]) -> float:
        """
        Distance from a point to the nearest edge of any ring.
        """
    @property
    def area(self) -> float:
        """
        Area minus holes, m^2.
        """
    @property
    def holes(self) -> list[typing.Annotated[numpy.typing.NDArray[numpy.float64], "[m, 2]"]]:
        """
        Holes, each (m, 2).
        """
    @property
    def outer(self) -> typing.Annotated[numpy.typing.NDArray[numpy.float64], "[m, 2]"]:
        """
        Outer ring (n, 2), without a closing repeat.
        """
class Uav:
    """
    The vehicle: constant speed, minimum turn radius, altitude, and how it turns: dynamics 'dubins' (the turn rate follows the guidance at once, the papers' vehicle) or 'roll' (the bank a first-order, rate-limited state: Beard & McLain ch. 9; SI units only).
    """
    def __init__(self, *, speed: typing.SupportsFloat | typing.SupportsIndex = 20.0, min_turn_radius: typing.SupportsFloat | typing.SupportsIndex = 50.0, altitude: typing.SupportsFloat | typing.SupportsIndex = 300.0, dynamics: str = 'dubins', roll_time_constant: typing.SupportsFloat | typing.SupportsIndex = 0.5, max_roll_rate_deg_s: typing.SupportsFloat | typing.SupportsIndex = 70.0) -> None:
        """
        speed v (m/s), min_turn_radius r_min (m), altitude h_UAV (m), dynamics 'dubins' or 'roll', the roll model's time constant tau (s; ArduPlane RLL2SRV_TCONST 0.5) and maximum roll rate (deg/s; PX4 FW_R_RMAX 70).
        """
    def __repr__(self) -> str:
        ...
    def validate(self) -> None:
        """
        Raise VistrackError naming the first invalid field.
        """
    @property
    def altitude(self) -> float:
        """
        h_UAV, m
        """
    @altitude.setter
    def altitude(self, arg0: typing.SupportsFloat | typing.SupportsIndex) -> None:
        ...
    @property
    def dynamics(self) -> str:
        """
        'dubins' or 'roll'
        """
    @dynamics.setter
    def dynamics(self, arg0: str) -> None:
        ...
    @property
    def max_roll_rate_deg_s(self) -> float:
        """
        the roll model's rate limit, deg/s
        """
    @max_roll_rate_deg_s.setter
    def max_roll_rate_deg_s(self, arg0: typing.SupportsFloat | typing.SupportsIndex) -> None:
        ...
    @property
    def min_turn_radius(self) -> float:
        """
        r_min, m
        """
    @min_turn_radius.setter
    def min_turn_radius(self, arg0: typing.SupportsFloat | typing.SupportsIndex) -> None:
        ...
    @property
    def roll_time_constant(self) -> float:
        """
        tau of the roll model, s
        """
    @roll_time_constant.setter
    def roll_time_constant(self, arg0: typing.SupportsFloat | typing.SupportsIndex) -> None:
        ...
    @property
    def speed(self) -> float:
        """
        v, m/s
        """
    @speed.setter
    def speed(self, arg0: typing.SupportsFloat | typing.SupportsIndex) -> None:
        ...
class PoiMotion:
    """
    The POI's defaults: its speed along the road path and its height above the surface where a point is given without z.
    """
    def __init__(self, *, speed: typing.SupportsFloat | typing.SupportsIndex = 5.0, height: typing.SupportsFloat | typing.SupportsIndex = 0.5) -> None:
        """
        speed v_g (m/s), height (m above the surface).
        """
    @property
    def height(self) -> float:
        """
        m above the surface
        """
    @property
    def speed(self) -> float:
        """
        v_g, m/s
        """
class Sensor:
    """
    Line-of-sight sensor: range d_max and optional altitude band.
    """
    def __init__(self, *, d_max: typing.SupportsFloat | typing.SupportsIndex = 400.0, altitude_band: tuple[typing.SupportsFloat | typing.SupportsIndex, typing.SupportsFloat | typing.SupportsIndex] | None = None) -> None:
        """
        d_max (m); altitude_band (h_lo, h_hi) in m or None for no band.
        """
    def validate(self) -> None:
        """
        Raise VistrackError naming the first invalid field.
        """
    @property
    def altitude_band(self) -> tuple[float, float] | None:
        """
        (h_lo, h_hi) in m, or None
        """
    @altitude_band.setter
    def altitude_band(self, arg0: tuple[typing.SupportsFloat | typing.SupportsIndex, typing.SupportsFloat | typing.SupportsIndex] | None) -> None:
        ...
    @property
    def d_max(self) -> float:
        """
        maximum viewing distance, m
        """
    @d_max.setter
    def d_max(self, arg0: typing.SupportsFloat | typing.SupportsIndex) -> None:
        ...
class Planning:
    """
    Adaptive placement of visibility volumes (section IV.B).
    """
    def __init__(self, *, spacing: typing.SupportsFloat | typing.SupportsIndex = 20.0, cutoff: typing.SupportsFloat | typing.SupportsIndex = 20000000.0, resolution_deg: typing.SupportsFloat | typing.SupportsIndex = 1.0, min_spacing: typing.SupportsFloat | typing.SupportsIndex = 1.0, max_depth: typing.SupportsInt | typing.SupportsIndex = 8, rate_margin: typing.SupportsFloat | typing.SupportsIndex = 0.0, locus: str = 'smooth', tracking_margin: typing.SupportsFloat | typing.SupportsIndex = 1.0, check_spacing: typing.SupportsFloat | typing.SupportsIndex = 10.0, check_min_spacing: typing.SupportsFloat | typing.SupportsIndex = 1.0, turn_share: typing.SupportsFloat | typing.SupportsIndex = 0.5, max_volumes: typing.SupportsInt | typing.SupportsIndex = 20000, radius_smoothing: typing.SupportsFloat | typing.SupportsIndex = 0.3) -> None:
        """
        spacing (m), cutoff d_cutoff (m^3), resolution_deg, min_spacing (m), max_depth, rate_margin; locus 'smooth' (checked between samples, C1, the default) or 'paper' (Algorithm 1, piecewise linear); tracking_margin (m), check_spacing and check_min_spacing (m), turn_share (smooth locus only); max_volumes (the largest worst-case VV count a plan may ask for); radius_smoothing (smooth locus only).
        """
    def validate(self) -> None:
        """
        Raise VistrackError naming the first invalid field.
        """
    @property
    def check_min_spacing(self) -> float:
        """
        smooth locus: the check halves intervals where R(t) touches its bound down to this (m)
        """
    @check_min_spacing.setter
    def check_min_spacing(self, arg0: typing.SupportsFloat | typing.SupportsIndex) -> None:
        ...
    @property
    def check_spacing(self) -> float:
        """
        smooth locus: MaxRadius is checked every check_spacing m of POI travel, then refined
        """
    @check_spacing.setter
    def check_spacing(self, arg0: typing.SupportsFloat | typing.SupportsIndex) -> None:
        ...
    @property
    def cutoff(self) -> float:
        """
        d_cutoff, m^3
        """
    @cutoff.setter
    def cutoff(self, arg0: typing.SupportsFloat | typing.SupportsIndex) -> None:
        ...
    @property
    def locus(self) -> str:
        """
        'smooth': R(t) checked against MaxRadius along the whole path, tracking_margin inside it, C1 with bounded d2R/dt2 (default); 'paper': Algorithm 1's piecewise-linear R(t) through the samples
        """
    @locus.setter
    def locus(self, arg1: str) -> None:
        ...
    @property
    def max_depth(self) -> int:
        """
        most halvings of one initial interval
        """
    @max_depth.setter
    def max_depth(self, arg0: typing.SupportsInt | typing.SupportsIndex) -> None:
        ...
    @property
    def max_volumes(self) -> int:
        """
        refuse, before computing any VV, a plan that may need more VVs than this (worst case: about path length / min_spacing, ~4.7 MB each at 1 degree)
        """
    @max_volumes.setter
    def max_volumes(self, arg0: typing.SupportsInt | typing.SupportsIndex) -> None:
        ...
    @property
    def min_spacing(self) -> float:
        """
        smallest spacing inserted, m
        """
    @min_spacing.setter
    def min_spacing(self, arg0: typing.SupportsFloat | typing.SupportsIndex) -> None:
        ...
    @property
    def radius_smoothing(self) -> float:
        """
        smooth locus, beyond the paper: weight of the d2R/dt2 penalty (holding the largest d2R/dt2 costs radius_smoothing / 2 of the ceiling's top radius); 0 = the largest-area R(t)
        """
    @radius_smoothing.setter
    def radius_smoothing(self, arg0: typing.SupportsFloat | typing.SupportsIndex) -> None:
        ...
    @property
    def rate_margin(self) -> float:
        """
        Algorithm 1 keeps |dR/dt| <= (1 - rate_margin)(v - v_g); 0 = Lemma 5's limit (the paper)
        """
    @rate_margin.setter
    def rate_margin(self, arg0: typing.SupportsFloat | typing.SupportsIndex) -> None:
        ...
    @property
    def resolution_deg(self) -> float:
        """
        VV ray grid step, degrees
        """
    @resolution_deg.setter
    def resolution_deg(self, arg0: typing.SupportsFloat | typing.SupportsIndex) -> None:
        ...
    @property
    def spacing(self) -> float:
        """
        initial spacing of VVs along the path, m
        """
    @spacing.setter
    def spacing(self, arg0: typing.SupportsFloat | typing.SupportsIndex) -> None:
        ...
    @property
    def tracking_margin(self) -> float:
        """
        smooth locus: R(t) stays this far inside MaxRadius (m)
        """
    @tracking_margin.setter
    def tracking_margin(self, arg0: typing.SupportsFloat | typing.SupportsIndex) -> None:
        ...
    @property
    def turn_share(self) -> float:
        """
        smooth locus: share of the turn rate Lemma 6 leaves free that d2R/dt2 may use, in (0, 1)
        """
    @turn_share.setter
    def turn_share(self, arg0: typing.SupportsFloat | typing.SupportsIndex) -> None:
        ...
class Control:
    """
    Guidance gains (section V): beta, k_psi, direction.
    """
    def __init__(self, *, beta: typing.SupportsFloat | typing.SupportsIndex = 0.025, k_psi: typing.SupportsFloat | typing.SupportsIndex = 20.0, direction: str = 'ccw') -> None:
        """
        beta (circulation), k_psi (heading gain), direction 'ccw' or 'cw'.
        """
    def validate(self) -> None:
        """
        Raise VistrackError naming the first invalid field.
        """
    @property
    def beta(self) -> float:
        """
        circulation parameter
        """
    @beta.setter
    def beta(self, arg0: typing.SupportsFloat | typing.SupportsIndex) -> None:
        ...
    @property
    def direction(self) -> str:
        """
        'ccw' or 'cw'
        """
    @direction.setter
    def direction(self, arg0: str) -> None:
        ...
    @property
    def k_psi(self) -> float:
        """
        heading gain
        """
    @k_psi.setter
    def k_psi(self, arg0: typing.SupportsFloat | typing.SupportsIndex) -> None:
        ...
class SimulationOptions:
    """
    Closed-loop integration settings.
    """
    def __init__(self, *, rtol: typing.SupportsFloat | typing.SupportsIndex = 1e-06, atol: typing.SupportsFloat | typing.SupportsIndex = 1e-08, max_step: typing.SupportsFloat | typing.SupportsIndex = 1.0, output_step: typing.SupportsFloat | typing.SupportsIndex = 0.1) -> None:
        """
        rtol, atol, max_step (s), output_step (s).
        """
    def validate(self) -> None:
        """
        Raise VistrackError naming the first invalid field.
        """
    @property
    def atol(self) -> float:
        """
        absolute tolerance
        """
    @atol.setter
    def atol(self, arg0: typing.SupportsFloat | typing.SupportsIndex) -> None:
        ...
    @property
    def max_step(self) -> float:
        """
        largest step, s
        """
    @max_step.setter
    def max_step(self, arg0: typing.SupportsFloat | typing.SupportsIndex) -> None:
        ...
    @property
    def output_step(self) -> float:
        """
        output sample spacing, s
        """
    @output_step.setter
    def output_step(self, arg0: typing.SupportsFloat | typing.SupportsIndex) -> None:
        ...
    @property
    def rtol(self) -> float:
        """
        relative tolerance
        """
    @rtol.setter
    def rtol(self, arg0: typing.SupportsFloat | typing.SupportsIndex) -> None:
        ...
class RoadNetwork:
    """
    Road graph G = (N, E): nodes on the ground plane; edges driven both ways unless one-way.
    """
    def __init__(self, nodes: typing.Annotated[numpy.typing.ArrayLike, numpy.float64, "[m, 2]"], edges: typing.Annotated[numpy.typing.ArrayLike, numpy.int64, "[m, 2]"], oneway: collections.abc.Sequence[bool] | None = None) -> None:
        """
        nodes: (n, 2) float array of positions in metres; edges: (m, 2) int array of node pairs; oneway: None (every edge two-way) or one bool per edge, True when the edge is driven only from its first node to its second.
        """
    def __repr__(self) -> str:
        ...
    def nearest_node(self, point: typing.Annotated[numpy.typing.ArrayLike, numpy.float64, "[2, 1]"]) -> int:
        """
        Index of the node closest to a point (x, y) (lowest index on ties).
        """
    def shortest_route(self, start: typing.SupportsInt | typing.SupportsIndex, goal: typing.SupportsInt | typing.SupportsIndex) -> list[int]:
        """
        Node indices of a shortest route along the edges from start to goal (Dijkstra, Euclidean edge lengths, one-way edges only their way), both included. VistrackError when goal is unreachable, saying so when only one-way streets stand in the way.
        """
    @property
    def edges(self) -> typing.Annotated[numpy.typing.NDArray[numpy.int64], "[m, 2]"]:
        """
        Edges as node index pairs, numpy int64 array (m, 2).
        """
    @property
    def nodes(self) -> typing.Annotated[numpy.typing.NDArray[numpy.float64], "[m, 2]"]:
        """
        Node positions, numpy array (n, 2).
        """
    @property
    def oneway(self) -> typing.Annotated[numpy.typing.NDArray[numpy.bool], "[m, 1]"]:
        """
        Per edge, True when it is driven only from edges[e][0] to edges[e][1]; bool array (m,).
        """
class Environment:
    """
    Obstacles (2.5D buildings or a triangle mesh), ground and road network.
    """
    @staticmethod
    def demo() -> Environment:
        """
        The embedded synthetic downtown (800 m x 800 m, street grid as road network, buildings 10-150 m tall). Deterministic.
        """
    @staticmethod
    def from_buildings(buildings: collections.abc.Iterable, roads: RoadNetwork | None = None) -> Environment:
        """
        Environment from a list of (Polygon, height), (Polygon, height, id) or (Polygon, height, id, min_height) (the base: a raised part from min_height to height; an (n, 2) array may stand for a Polygon without holes), validated as in from_geojson; optional RoadNetwork checked against every footprint.
        """
    @staticmethod
    def from_geojson(path: typing.Any, origin: typing.Any = None, project: typing.Callable[..., typing.Any] | None = vistrack.georeference.project_lon_lat) -> Environment:
        """
        2.5D buildings from a GeoJSON FeatureCollection of Polygon/MultiPolygon features: height from properties.height, else building:levels x 3 m; the base from properties.min_height (default 0, below the top); id from properties.id, else the feature index. Coordinates in local east-north metres, or WGS84 longitude/latitude (the GeoJSON default, as OpenStreetMap exports give; told apart by range, anything else is a VistrackError) projected to local metres by project(lon_lat, (lat, lon, alt)) (the package passes vistrack.georeference.project_lon_lat: pyproj, ellipsoidal tangent plane) about origin (lat, lon[, alt]) or a Georeference, else about the centre of the data's bounding box (rounded to 1e-7 degree); env.origin reports it. Footprints are validated (simple, >= 3 points, holes inside, positive height, disjoint interiors: overlaps up to 1 m^2 are taken as touching walls, and a footprint inside a building at least as tall as a building part) and normalised counter-clockwise.
        """
    @staticmethod
    def from_mesh(path: typing.Any, up: str = 'z') -> Environment:
        """
        Any mesh file CGAL reads (.obj .ply .stl .off): duplicate points merged, polygons triangulated, degenerate triangles dropped. up='y' maps a Y-up, north=-Z file (x, y, z) to east-north-up (x, -z, y). The ground level is the lowest vertex.
        """
    @staticmethod
    def from_osm(path: typing.Any, *, level_height: float = 3.0, roof_height: float = 0.0, default_height: float = 10.0, origin: typing.Any = None) -> Environment:
        """
        ``Environment.from_osm``: the environment of :func:`read_osm` (its summary dropped). ``path``
            an OSM file (str or Path); ``origin`` a Georeference or (lat, lon[, alt]), by default the
            centre of the data's bounding box. (Annotated ``Any``: the compiled module's stubs list it.)
        """
    @staticmethod
    def from_triangles(vertices: typing.Annotated[numpy.typing.ArrayLike, numpy.float64, "[m, 3]"], faces: typing.Annotated[numpy.typing.ArrayLike, numpy.int32, "[m, 3]"]) -> Environment:
        """
        Environment from triangles: vertices (n, 3) float in east-north-up metres, faces (m, 3) int indexing them. The ground level is the lowest vertex.
        """
    def __repr__(self) -> str:
        ...
    def line_of_sight(self, a: typing.Annotated[numpy.typing.ArrayLike, numpy.float64, "[m, 3]"], b: typing.Annotated[numpy.typing.ArrayLike, numpy.float64, "[m, 3]"]) -> numpy.typing.NDArray[numpy.bool]:
        """
        Bool array: segment a[k]-b[k] ((n, 3) each) is unobstructed by obstacles and ground. Builds a BVH per call: use VisibilityScene(env).line_of_sight for repeated queries.
        """
    @typing.overload
    def set_roads(self, roads: RoadNetwork) -> None:
        """
        Replace the road network; VistrackError naming the edge and the building when an edge crosses a footprint interior (running along a wall is allowed).
        """
    @typing.overload
    def set_roads(self, nodes: typing.Annotated[numpy.typing.ArrayLike, numpy.float64, "[m, 2]"], edges: typing.Annotated[numpy.typing.ArrayLike, numpy.int64, "[m, 2]"], oneway: collections.abc.Sequence[bool] | None = None) -> None:
        """
        Replace the road network from arrays nodes (n, 2), edges (m, 2) and optional oneway flags (m,).
        """
    @property
    def bounds(self) -> typing.Annotated[numpy.typing.NDArray[numpy.float64], "[2, 3]"]:
        """
        Axis-aligned bounds of the obstacles, numpy array (2, 3): [min, max].
        """
    @property
    def building_ids(self) -> list[int]:
        """
        Building ids (properties.id, else the feature index), list of int.
        """
    @property
    def faces(self) -> typing.Annotated[numpy.typing.NDArray[numpy.int32], "[m, 3]"]:
        """
        Obstacle triangles, numpy int32 array (m, 3) of vertex indices, outward oriented for buildings.
        """
    @property
    def fingerprint(self) -> int:
        """
        Deterministic 64-bit content hash of the geometry and roads, for caches.
        """
    @property
    def footprints(self) -> list[Polygon]:
        """
        Building footprints as a list of Polygon (outer counter-clockwise, holes clockwise).
        """
    @property
    def ground_level(self) -> float:
        """
        Height of the ground plane in metres (0 for buildings, lowest vertex for a mesh).
        """
    @property
    def heights(self) -> typing.Annotated[numpy.typing.NDArray[numpy.float64], "[m, 1]"]:
        """
        Building heights (their tops) in metres above the ground, numpy array (num_buildings,).
        """
    @property
    def max_height(self) -> float:
        """
        Tallest obstacle point above the ground level, in metres.
        """
    @property
    def min_heights(self) -> typing.Annotated[numpy.typing.NDArray[numpy.float64], "[m, 1]"]:
        """
        Building bases (min_height) in metres above the ground, numpy array (num_buildings,): 0 for a building standing on the ground, above 0 for a raised part with open space under it.
        """
    @property
    def num_buildings(self) -> int:
        """
        Number of 2.5D buildings (0 for an environment made from a mesh).
        """
    @property
    def num_triangles(self) -> int:
        """
        Number of obstacle triangles (the ground plane not counted).
        """
    @property
    def origin(self) -> tuple[float, float, float] | None:
        """
        Where local (0, 0, 0) lies on the Earth: (lat, lon, alt) in degrees and metres, or None when unknown. Set by from_geojson (its origin argument, or the origin a longitude/latitude file was projected about); assignable (a tuple or a vistrack.Georeference). Not part of the fingerprint.
        """
    @origin.setter
    def origin(self, arg1: typing.Any) -> None:
        ...
    @property
    def roads(self) -> RoadNetwork:
        """
        The road network (RoadNetwork).
        """
    @property
    def vertices(self) -> typing.Annotated[numpy.typing.NDArray[numpy.float64], "[m, 3]"]:
        """
        Obstacle vertices, numpy array (n, 3).
        """
class PoiPath:
    """
    A point of interest moving at constant speed through waypoints.
    """
    @staticmethod
    def from_csv(path: typing.Any, speed: typing.SupportsFloat | typing.SupportsIndex) -> PoiPath:
        """
        Read waypoints from a CSV file with lines x,y[,z].
        """
    @staticmethod
    def from_nodes(roads: RoadNetwork, nodes: collections.abc.Sequence[typing.SupportsInt | typing.SupportsIndex], speed: typing.SupportsFloat | typing.SupportsIndex) -> PoiPath:
        """
        Path through a sequence of road-network node indices, each consecutive pair joined by an edge.
        """
    @staticmethod
    def from_route(env: Environment, start: typing.Sequence[float], end: typing.Sequence[float], speed: float, crs: str = 'lonlat') -> PoiPath:
        """
        A POI driving at constant ``speed`` (m/s) along :func:`route_nodes`.
        """
    def __init__(self, waypoints: typing.Annotated[numpy.typing.ArrayLike, numpy.float64, "[m, n]"], speed: typing.SupportsFloat | typing.SupportsIndex) -> None:
        """
        Waypoints (n, 2) or (n, 3) in metres; speed in m/s (> 0).
        """
    def heading(self, t: typing.SupportsFloat | typing.SupportsIndex) -> float:
        """
        Direction of the velocity at t, radians.
        """
    def position(self, t: typing.SupportsFloat | typing.SupportsIndex) -> typing.Annotated[numpy.typing.NDArray[numpy.float64], "[3, 1]"]:
        """
        Position (3,) at time t (clamped to the path).
        """
    def velocity(self, t: typing.SupportsFloat | typing.SupportsIndex) -> typing.Annotated[numpy.typing.NDArray[numpy.float64], "[2, 1]"]:
        """
        Velocity (2,) of the segment containing t.
        """
    @property
    def duration(self) -> float:
        """
        Time to travel the whole path (s).
        """
    @property
    def length(self) -> float:
        """
        Path length in metres.
        """
    @property
    def node_times(self) -> list[float]:
        """
        Times t_i at each waypoint (s).
        """
    @property
    def speed(self) -> float:
        """
        Speed v_g in m/s.
        """
    @property
    def waypoints(self) -> typing.Annotated[numpy.typing.NDArray[numpy.float64], "[m, 3]"]:
        """
        Waypoints (n, 3) after dropping repeats.
        """
class DirectionGrid:
    """
    Angular grid of a VV: num_elevation rows x num_azimuth columns of equal angular size over the sphere; a VV samples its intervals at the cells' corners (corner).
    """
    @staticmethod
    def from_resolution(resolution_deg: typing.SupportsFloat | typing.SupportsIndex) -> DirectionGrid:
        """
        Grid with steps of about resolution_deg degrees (an even number of rows).
        """
    def azimuth(self, column: typing.SupportsInt | typing.SupportsIndex) -> float:
        """
        Centre azimuth of column j (rad, from +x).
        """
    def corner(self, row: typing.SupportsInt | typing.SupportsIndex, column: typing.SupportsInt | typing.SupportsIndex) -> typing.Annotated[numpy.typing.NDArray[numpy.float64], "[3, 1]"]:
        """
        Unit vector to corner (i, j), i in [0, num_elevation]: elevation -pi/2 + i*pi/num_elevation,
        azimuth j*2pi/num_azimuth (rows 0 and num_elevation are the poles). A VV's intervals are
        sampled on these rays.
        """
    def corner_weight(self, row: typing.SupportsInt | typing.SupportsIndex) -> float:
        """
        Trapezoid weight of each corner of row i (sr): half a cell below plus half a cell above.
        """
    def elevation(self, row: typing.SupportsInt | typing.SupportsIndex) -> float:
        """
        Centre elevation of row i (rad).
        """
    def solid_angle(self, row: typing.SupportsInt | typing.SupportsIndex) -> float:
        """
        Solid angle of each cell of row i (sr).
        """
    @property
    def num_azimuth(self) -> int:
        ...
    @property
    def num_corners(self) -> int:
        """
        Number of corners: (num_elevation + 1) * num_azimuth.
        """
    @property
    def num_elevation(self) -> int:
        ...
    @property
    def size(self) -> int:
        """
        Number of cells.
        """
class VisibilityVolume:
    """
    Visibility volume alpha(g) (eq. 4): per-direction visible intervals on a grid and a closed, outward-oriented triangle mesh (left out with with_mesh=False: has_mesh).
    """
    @staticmethod
    def load(path: typing.Any) -> VisibilityVolume:
        """
        The VV stored in a binary VV file (save_binary or the VV cache). VistrackError naming the file when it is missing, unreadable, truncated, corrupt (checksum) or of another format version.
        """
    def __repr__(self) -> str:
        ...
    def check(self) -> MeshCheck:
        """
        check_closed_mesh on this VV's mesh (VistrackError for a VV computed with with_mesh=False).
        """
    def grid_volume(self) -> float:
        """
        Volume represented by the grid intervals: sum over corners of corner_weight * (far^3 - near^3) / 3.
        """
    def save(self, path: str) -> None:
        """
        Write the mesh to .obj or .ply (VistrackError for a VV computed with with_mesh=False).
        """
    def save_binary(self, path: typing.Any) -> None:
        """
        Write the whole VV (grid intervals, mesh, volume) to a binary VV file, the format of the on-disk VV cache (vv-<hex>.bin, written by OrbitPlanner(cache_dir=...)); atomic (temporary file renamed). VistrackError for a VV computed with with_mesh=False.
        """
    def slice(self, altitude: typing.SupportsFloat | typing.SupportsIndex, all_parts: bool = False) -> list[Polygon]:
        """
        Visibility polygon at world altitude z: list of Polygon. By default only the part(s) containing the POI's vertical; all_parts=True keeps every part. VistrackError for a VV computed with with_mesh=False.
        """
    @property
    def altitude_band(self) -> tuple[float, float] | None:
        """
        (h_lo, h_hi) in world z, or None.
        """
    @property
    def d_max(self) -> float:
        """
        Maximum viewing distance (m).
        """
    @property
    def faces(self) -> typing.Annotated[numpy.typing.NDArray[numpy.int32], "[m, 3]"]:
        """
        Mesh triangles (m, 3) int32, outward oriented; VistrackError for a VV computed with with_mesh=False.
        """
    @property
    def far(self) -> numpy.typing.NDArray[numpy.float64]:
        """
        End of the visible interval per grid corner (near >= far: nothing visible).
        """
    @property
    def grid(self) -> DirectionGrid:
        """
        The direction grid.
        """
    @property
    def has_mesh(self) -> bool:
        """
        False for a VV computed with with_mesh=False: its intervals and volume only (no vertices,
        faces, slices or files; the XOR on the grid only).
        """
    @property
    def mesh_row_sines(self) -> list[float]:
        """
        Star VVs (POI in the band): sines of the elevations of the mesh's vertex rows (grid row
        boundaries plus the creases where d_max meets the ground or a band plane); empty otherwise,
        and with with_mesh=False.
        """
    @property
    def mesh_triangle_faces(self) -> list[int]:
        """
        Star VVs: faces[mesh_triangle_faces[t]:mesh_triangle_faces[t + 1]] are built over triangle slot
        t of the sphere of grid corners (two per quad, row-major); what the radial XOR reads. Empty
        otherwise, and with with_mesh=False.
        """
    @property
    def near(self) -> numpy.typing.NDArray[numpy.float64]:
        """
        Start of the visible interval per grid corner, (num_elevation + 1, num_azimuth) metres.
        """
    @property
    def poi(self) -> typing.Annotated[numpy.typing.NDArray[numpy.float64], "[3, 1]"]:
        """
        The POI g (3,).
        """
    @property
    def vertices(self) -> typing.Annotated[numpy.typing.NDArray[numpy.float64], "[m, 3]"]:
        """
        Mesh vertices (n, 3); VistrackError for a VV computed with with_mesh=False.
        """
    @property
    def volume(self) -> float:
        """
        Volume of the mesh (m^3); the same value when computed with with_mesh=False.
        """
class VisibilityScene:
    """
    Embree BVH of an environment (obstacles plus ground plane), built once and shared by every visibility query; thread-safe.
    """
    def __init__(self, env: Environment) -> None:
        """
        Build the BVH (validates the triangles first).
        """
    def first_hits(self, origin: typing.Annotated[numpy.typing.ArrayLike, numpy.float64, "[m, 1]"], directions: typing.Annotated[numpy.typing.ArrayLike, numpy.float64, "[m, 3]"], t_max: typing.SupportsFloat | typing.SupportsIndex = 1e+30) -> numpy.typing.NDArray[numpy.float64]:
        """
        Distance (m) to the first obstacle or ground hit along each direction (n, 3); inf when none.
        """
    def inside_obstacle(self, point: typing.Annotated[numpy.typing.ArrayLike, numpy.float64, "[3, 1]"]) -> bool:
        """
        Whether a point lies inside an obstacle.
        """
    def line_of_sight(self, a: typing.Annotated[numpy.typing.ArrayLike, numpy.float64, "[m, 3]"], b: typing.Annotated[numpy.typing.ArrayLike, numpy.float64, "[m, 3]"]) -> numpy.typing.NDArray[numpy.bool]:
        """
        Bool array: segment a[k]-b[k] is unobstructed (occlusion rays).
        """
    def poi_on_surface(self, points: typing.Annotated[numpy.typing.ArrayLike, numpy.float64, "[m, 3]"]) -> typing.Annotated[numpy.typing.NDArray[numpy.float64], "[m, 3]"]:
        """
        Where ground POIs stand: rows (x, y, h) of a POI path, h the height above the surface, become (x, y, surface_height(x, y) + h).
        """
    def surface_height(self, xy: typing.Annotated[numpy.typing.ArrayLike, numpy.float64, "[2, 1]"]) -> float:
        """
        Height of the topmost surface (obstacle or ground) under the vertical through xy (2,).
        """
    @property
    def fingerprint(self) -> int:
        """
        Fingerprint of the source environment.
        """
    @property
    def ground_level(self) -> float:
        """
        Ground plane height (m).
        """
    @property
    def num_triangles(self) -> int:
        """
        Obstacle triangles in the BVH.
        """
class VolumeCost:
    """
    Where one VV's time and rays went (for benchmarks).
    """
    @property
    def bounds_s(self) -> float:
        """
        s: per-column bounds of the rays that can hit an obstacle
        """
    @property
    def candidates_s(self) -> float:
        """
        s of refine_s (star VV): live corners, the search for jump candidates, the edge map
        """
    @property
    def corner_tests(self) -> int:
        """
        (corner direction, obstacle triangle) tests of the corner rays' first hits
        """
    @property
    def count_s(self) -> float:
        """
        s of mesh_s (star VV): numbering the vertices, counting the faces per slot
        """
    @property
    def embree_s(self) -> float:
        """
        s in Embree's rtcIntersect1M calls with their ray packing, per thread and summed over threads: within trace_s + refine_s when parallel=False
        """
    @property
    def fill_s(self) -> float:
        """
        s of mesh_s (star VV): the faces, with the volume
        """
    @property
    def first_pass_s(self) -> float:
        """
        s of refine_s (star VV): locating the grid edges' jumps
        """
    @property
    def mesh_s(self) -> float:
        """
        s: writing the mesh
        """
    @property
    def predicted_error(self) -> float:
        """
        with check_predicted=True: the largest |predicted / traced - 1| of those rays' visible distance
        """
    @property
    def predicted_misses(self) -> int:
        """
        with check_predicted=True (each predicted ray traced as well, and counted in refine_rays; the VV keeps the predictions): how many differ from Embree by more than 0.1 % in visible distance (where the ray grazes the occluder's edge closer than Embree's float test resolves)
        """
    @property
    def rays_skipped(self) -> int:
        """
        corner rays decided without Embree (the triangle tests, or the bounds)
        """
    @property
    def rays_traced(self) -> int:
        """
        corner rays handed to Embree (the grid's corner rows that are no mesh rows)
        """
    @property
    def refine_predicted(self) -> int:
        """
        refining rays decided without Embree: a ray just before an occluder's edge lies inside its cone and meets it at its plane
        """
    @property
    def refine_rays(self) -> int:
        """
        rays traced while refining
        """
    @property
    def refine_s(self) -> float:
        """
        s: locating the jumps of r and refining the mesh there
        """
    @property
    def second_pass_s(self) -> float:
        """
        s of refine_s (star VV): the split edges' new edges and their jumps
        """
    @property
    def trace_s(self) -> float:
        """
        s: corner rays (their first hits from the triangles' footprints) and the grid's intervals
        """
    @property
    def untwist_s(self) -> float:
        """
        s of refine_s (star VV): confirming the jumps (with the complex slots' pieces, which the mesh reuses) and untwisting the walls
        """
    @property
    def vertices_s(self) -> float:
        """
        s of mesh_s (star VV): the vertices
        """
    @property
    def volume_s(self) -> float:
        """
        s: summing its volume (with_mesh=False: the whole volume pass, in place of mesh_s)
        """
class MeshCheck:
    """
    CGAL's verdict on a mesh that should bound a solid.
    """
    def __repr__(self) -> str:
        ...
    @property
    def bounds_volume(self) -> bool:
        ...
    @property
    def closed(self) -> bool:
        ...
    @property
    def outward(self) -> bool:
        ...
    @property
    def polygon_mesh(self) -> bool:
        """
        Faces form an oriented 2-manifold.
        """
    @property
    def problem(self) -> str:
        """
        First failed property, '' when valid.
        """
    @property
    def self_intersecting(self) -> bool:
        ...
    @property
    def triangles_valid(self) -> bool:
        ...
    @property
    def valid(self) -> bool:
        ...
    @property
    def volume(self) -> float:
        """
        CGAL's volume (m^3).
        """
class RadiusProfile:
    """
    R(t) as the guidance follows it: piecewise linear between the knots (times, radii) when rates is empty (the paper's locus, Definition 2), else C1 piecewise quadratic with dR/dt = rates at the knots (the smooth locus).
    """
    def __init__(self, times: collections.abc.Sequence[typing.SupportsFloat | typing.SupportsIndex], radii: collections.abc.Sequence[typing.SupportsFloat | typing.SupportsIndex], rates: collections.abc.Sequence[typing.SupportsFloat | typing.SupportsIndex] = []) -> None:
        """
        Knots, R at the knots, and dR/dt at the knots (empty: piecewise linear).
        """
    def acceleration_at(self, t: typing.Annotated[numpy.typing.ArrayLike, numpy.float64]) -> numpy.typing.NDArray[numpy.float64]:
        """
        d2R/dt2 at every element of t (0 when piecewise linear).
        """
    def radius_at(self, t: typing.Annotated[numpy.typing.ArrayLike, numpy.float64]) -> numpy.typing.NDArray[numpy.float64]:
        """
        R(t) at every element of t (numpy in, numpy out).
        """
    def rate_at(self, t: typing.Annotated[numpy.typing.ArrayLike, numpy.float64]) -> numpy.typing.NDArray[numpy.float64]:
        """
        dR/dt at every element of t.
        """
    @property
    def min_radius(self) -> float:
        """
        The smallest R(t) (m).
        """
    @property
    def radii(self) -> list[float]:
        """
        R at the knots (m).
        """
    @property
    def rates(self) -> list[float]:
        """
        dR/dt at the knots (m/s); empty when piecewise linear.
        """
    @property
    def smooth(self) -> bool:
        """
        True for the C1 piecewise-quadratic form.
        """
    @property
    def times(self) -> list[float]:
        """
        Knot times (s).
        """
class OrbitPlan:
    """
    Time-varying reference orbit about the POI that the guidance follows (eq. 5): centred on the POI path g(t), of radius R(t) = `reference` (piecewise linear through (times, radii) for the paper's locus, C1 piecewise quadratic for the smooth one).
    """
    @staticmethod
    def from_json(text: str) -> OrbitPlan:
        """
        A plan from JSON text.
        """
    def radius(self, t: typing.SupportsFloat | typing.SupportsIndex) -> float:
        """
        R(t) of the reference.
        """
    def radius_acceleration(self, t: typing.SupportsFloat | typing.SupportsIndex) -> float:
        """
        d2R/dt2 of the reference.
        """
    def radius_at(self, t: typing.Annotated[numpy.typing.ArrayLike, numpy.float64]) -> numpy.typing.NDArray[numpy.float64]:
        """
        R(t) exactly as the controller follows it, at every element of t (numpy in, numpy out).
        """
    def radius_rate(self, t: typing.SupportsFloat | typing.SupportsIndex) -> float:
        """
        dR/dt of the reference (on the segment containing t).
        """
    def radius_rate_at(self, t: typing.Annotated[numpy.typing.ArrayLike, numpy.float64]) -> numpy.typing.NDArray[numpy.float64]:
        """
        dR/dt of the reference at every element of t.
        """
    def to_json(self) -> str:
        """
        The plan as JSON text.
        """
    def to_mission(self, georeference: vistrack.georeference.Georeference | typing.Sequence[float], altitude: float | None = None, *, direction: str = 'ccw', speed: float | None = None, start: typing.Sequence[float] | None = None, end: str = 'loiter', firmware: str = 'ardupilot', altitude_mode: str = 'relative') -> vistrack.mission.model.Mission:
        """
        An orbit plan as an autopilot mission: one NAV_LOITER_TIME per segment [t_k, t_k+1] about
            the POI's position at the segment's middle, with R(t) there, for the segment's duration.
        
            The autopilot circles fixed centres one after the other, so its orbit lags the moving POI by up
            to v_g (t_k+1 - t_k) / 2 and it flies no guidance law: a companion computer flying vistrack's
            vector field (eq. 74) along the plan (``vistrack simulate``) tracks far better; the mission is
            for a ground station's map, a plain autopilot, or a fallback.
        
            ``altitude`` / ``speed`` default to the plan's UAV (a VisibilityOrbitPlan); the mission first
            flies from ``start`` (local x, y; default home = the origin) to the tangent entry point of the
            first orbit, and ends with a loiter over the POI's last position (``end="loiter"``), a return
            to launch ("rtl") or nothing ("none"). For ArduPilot, which counts whole seconds, the segment
            boundaries are rounded to whole seconds from the start (the total stays within 0.5 s).
            
        """
    @property
    def centers(self) -> typing.Annotated[numpy.typing.NDArray[numpy.float64], "[m, 2]"]:
        """
        Orbit centres g(t_k), array (n, 2).
        """
    @property
    def feasible(self) -> bool:
        """
        Whether the plan is flyable (Lemmas 5 and 6).
        """
    @property
    def infeasibility(self) -> str:
        """
        Which sample or time fails and why.
        """
    @property
    def knot_times(self) -> list[float]:
        """
        Knots of the reference: where dR/dt or d2R/dt2 may jump (the closed loop restarts there).
        """
    @property
    def poi(self) -> PoiPath:
        """
        The POI path g(t).
        """
    @property
    def radii(self) -> list[float]:
        """
        R(t_k) on the reference (m).
        """
    @property
    def reference(self) -> RadiusProfile:
        """
        R(t) as the guidance follows it (a RadiusProfile, the piecewise-linear default filled in).
        """
    @property
    def times(self) -> list[float]:
        """
        Sample times t_k (s): the orbit centres g(t_k).
        """
class WorkEstimate:
    """
    The work a plan may ask for, known before any VV is computed.
    """
    def __repr__(self) -> str:
        ...
    @property
    def bytes(self) -> float:
        """
        Memory of all of them (bytes).
        """
    @property
    def bytes_per_volume(self) -> float:
        """
        Memory of one VV (bytes).
        """
    @property
    def initial_bytes(self) -> float:
        """
        Memory of the initial VVs (bytes): refused above limits.MAX_WORK_BYTES.
        """
    @property
    def initial_volumes(self) -> float:
        """
        The VVs every plan computes (one every spacing, and every node).
        """
    @property
    def volumes(self) -> float:
        """
        Worst-case number of VVs (every interval halved).
        """
class CircularOrbits:
    """
    Result of Algorithm 1 on given MaxRadius values.
    """
    @property
    def failing_samples(self) -> list[int]:
        """
        Samples that break Lemma 6.
        """
    @property
    def feasible(self) -> bool:
        """
        Every sample passes Lemma 6.
        """
    @property
    def infeasibility(self) -> str:
        """
        The first failing sample and why.
        """
    @property
    def min_feasible_radius(self) -> float:
        """
        r_min (1 + v_g/v)^2 (m).
        """
    @property
    def radii(self) -> list[float]:
        """
        R_k after the forward and backward rate passes (m).
        """
    @property
    def radius_rates(self) -> list[float]:
        """
        dR/dt per segment (m/s).
        """
class SmoothRadiusLimits:
    """
    Bounds of a smooth R(t): |dR/dt| <= max_rate and |d2R/dt2| <= turn_share (v / r_min - v (1 + v_g/v)^2 / R_lo) sqrt(v^2 - (v_g + |dR/dt|)^2).
    """
    def __init__(self, *, uav_speed: typing.SupportsFloat | typing.SupportsIndex = 20.0, poi_speed: typing.SupportsFloat | typing.SupportsIndex = 5.0, min_turn_radius: typing.SupportsFloat | typing.SupportsIndex = 50.0, max_rate: typing.SupportsFloat | typing.SupportsIndex = 15.0, turn_share: typing.SupportsFloat | typing.SupportsIndex = 0.5) -> None:
        """
        v, v_g, r_min, the rate bound (<= v - v_g), turn_share.
        """
    def max_acceleration(self, r_lo: typing.SupportsFloat | typing.SupportsIndex, rate: typing.SupportsFloat | typing.SupportsIndex) -> float:
        """
        The bound on |d2R/dt2| for R >= r_lo and dR/dt = rate.
        """
    @property
    def max_rate(self) -> float:
        ...
    @property
    def min_turn_radius(self) -> float:
        ...
    @property
    def poi_speed(self) -> float:
        ...
    @property
    def turn_share(self) -> float:
        ...
    @property
    def uav_speed(self) -> float:
        ...
class Ceiling:
    """
    An upper bound on R(t), piecewise linear: from starts[j] to ends[j] on [breaks[j], breaks[j+1]] (the smaller side at a break).
    """
    def __init__(self, breaks: collections.abc.Sequence[typing.SupportsFloat | typing.SupportsIndex], starts: collections.abc.Sequence[typing.SupportsFloat | typing.SupportsIndex], ends: collections.abc.Sequence[typing.SupportsFloat | typing.SupportsIndex] | None = None) -> None:
        """
        Break times, the ceiling at the start and at the end of each interval (ends=None: a step ceiling).
        """
    def at(self, t: typing.Annotated[numpy.typing.ArrayLike, numpy.float64]) -> numpy.typing.NDArray[numpy.float64]:
        """
        The ceiling at every element of t.
        """
    @property
    def breaks(self) -> list[float]:
        """
        Break times (s).
        """
    @property
    def ends(self) -> list[float]:
        """
        Value at the end of each interval (m).
        """
    @property
    def starts(self) -> list[float]:
        """
        Value at the start of each interval (m).
        """
class LocusCheck:
    """
    The locus check of a smooth plan: MaxRadius along the whole POI path, the ceilings R(t) obeys between check points, and how much lower than the paper's piecewise-linear R(t) it is.
    """
    @property
    def arc_lengths(self) -> list[float]:
        """
        s_j of the check points (m).
        """
    @property
    def ceiling(self) -> Ceiling:
        """
        The bound R(t) obeys: the lower bound of MaxRadius between check points minus the tracking margin.
        """
    @property
    def lowering(self) -> list[float]:
        """
        Paper R(t_j) - smooth R(t_j) per check point (m).
        """
    @property
    def max_lowering(self) -> float:
        """
        Its largest value (m).
        """
    @property
    def max_lowering_time(self) -> float:
        """
        Where (s).
        """
    @property
    def max_radii(self) -> list[float]:
        """
        MaxRadius at the check points (m).
        """
    @property
    def min_clearance(self) -> float:
        """
        min_j MaxRadius - smooth R (m).
        """
    @property
    def paper_max_violation(self) -> float:
        """
        By how much at most (m).
        """
    @property
    def paper_violations(self) -> int:
        """
        Check points where the paper's piecewise-linear R(t) exceeds MaxRadius.
        """
    @property
    def rounds(self) -> int:
        """
        Refinement rounds.
        """
    @property
    def slope_bounds(self) -> list[float]:
        """
        Per interval: the MaxRadius slope assumed (m per m).
        """
    @property
    def times(self) -> list[float]:
        """
        t_j of the check points (s).
        """
    @property
    def volumes_computed(self) -> int:
        """
        VVs the check computed.
        """
class Discretization:
    """
    VV samples along the POI path (section IV.B).
    """
    def volume(self, k: typing.SupportsInt | typing.SupportsIndex) -> VisibilityVolume:
        """
        A copy of VV k.
        """
    @property
    def arc_lengths(self) -> list[float]:
        """
        s_k along the path (m).
        """
    @property
    def depths(self) -> list[int]:
        """
        0 for initial samples, d for one inserted at halving d.
        """
    @property
    def metric(self) -> list[float]:
        """
        d(alpha_k, alpha_k+1) of eq. (56) (m^3), size n - 1.
        """
    @property
    def num_volumes(self) -> int:
        """
        VVs held (none for a plan read from JSON).
        """
    @property
    def points(self) -> typing.Annotated[numpy.typing.NDArray[numpy.float64], "[m, 3]"]:
        """
        g(t_k), (n, 3).
        """
    @property
    def times(self) -> list[float]:
        """
        t_k = s_k / v_g (s).
        """
    @property
    def volumes_computed(self) -> int:
        """
        VVs computed by this call.
        """
class VisibilityOrbitPlan(OrbitPlan):
    """
    An orbit plan with what it was made from: samples and VVs, VPs, MaxRadius, Algorithm 1's result.
    """
    @staticmethod
    def from_json(text: str) -> VisibilityOrbitPlan:
        """
        A plan from its JSON text.
        """
    def to_json(self) -> str:
        """
        The plan as JSON (without VVs).
        """
    def volume(self, k: typing.SupportsInt | typing.SupportsIndex) -> VisibilityVolume:
        """
        A copy of the VV of sample k (VVs are not stored in JSON).
        """
    @property
    def arc_lengths(self) -> list[float]:
        """
        s_k of the samples (m).
        """
    @property
    def check(self) -> LocusCheck:
        """
        The locus check (a LocusCheck; empty for the paper's locus).
        """
    @property
    def depths(self) -> list[int]:
        """
        Refinement depth of each sample.
        """
    @property
    def discretization(self) -> Discretization:
        """
        The VV samples (a Discretization).
        """
    @property
    def failing_samples(self) -> list[int]:
        """
        Samples that break Lemma 6.
        """
    @property
    def max_radii(self) -> list[float]:
        """
        MaxRadius of each VP (m), line 1 of Algorithm 1.
        """
    @property
    def metric(self) -> list[float]:
        """
        XOR volume (56) between neighbouring VVs (m^3).
        """
    @property
    def min_feasible_radius(self) -> float:
        """
        r_min (1 + v_g/v)^2 (m), Lemma 6.
        """
    @property
    def num_volumes(self) -> int:
        """
        VVs held (none for a plan read from JSON).
        """
    @property
    def orbits(self) -> CircularOrbits:
        """
        Algorithm 1's result (a CircularOrbits).
        """
    @property
    def planning(self) -> Planning:
        ...
    @property
    def polygons(self) -> list[list[Polygon]]:
        """
        VPs at h_UAV, one list of Polygon per sample.
        """
    @property
    def radius_rates(self) -> list[float]:
        """
        dR/dt per sample segment of Algorithm 1's piecewise-linear R(t) (m/s).
        """
    @property
    def sensor(self) -> Sensor:
        ...
    @property
    def uav(self) -> Uav:
        ...
    @property
    def volumes_computed(self) -> int:
        """
        VVs computed by this plan.
        """
class OrbitPlanner:
    """
    Section IV on one environment: an Embree scene built once, VV caches shared by every call (spacings and plans reuse VVs; one per grid resolution), the XOR metric (56) in the POI frame, VPs at world z = h_UAV.
    """
    def __init__(self, env: Environment, sensor: Sensor, cache_dir: typing.Any = None) -> None:
        """
        cache_dir (str or os.PathLike, created when missing): keep every VV on disk there, keyed by the environment fingerprint, the POI position, d_max, the altitude band and the resolution, so a later planner with the same inputs reads them instead of ray casting. None: no disk cache.
        """
    def adaptive(self, poi: PoiPath, planning: Planning, progress: typing.Any = None) -> Discretization:
        """
        Adaptive discretization (IV.B): initial spacing, halving while the metric exceeds the cutoff. progress(done, total) is called as VVs are computed.
        """
    def fixed(self, poi: PoiPath, spacing: typing.SupportsFloat | typing.SupportsIndex, resolution_deg: typing.SupportsFloat | typing.SupportsIndex = 1.0, progress: typing.Any = None, max_volumes: typing.SupportsInt | typing.SupportsIndex = 20000) -> Discretization:
        """
        VVs every `spacing` m from each edge start plus every node, and the metric between neighbours; VistrackError before any work when that is more than max_volumes VVs.
        """
    def plan(self, poi: PoiPath, uav: Uav, planning: Planning, progress: typing.Any = None) -> VisibilityOrbitPlan:
        """
        Adaptive VVs, VPs at h_UAV, MaxRadius and Algorithm 1: a VisibilityOrbitPlan.
        """
    @property
    def cached_volumes(self) -> int:
        """
        VVs held in the caches.
        """
    @property
    def disk_hits(self) -> int:
        """
        VVs read from the disk cache so far (0 without cache_dir).
        """
    @property
    def disk_misses(self) -> int:
        """
        VVs computed and written to the disk cache so far (0 without cache_dir).
        """
    @property
    def scene(self) -> VisibilityScene:
        """
        The planner's Embree scene (for line-of-sight queries on the same city).
        """
class OrbitState:
    """
    The reference orbit at one instant (Definitions 1-2): centre g, its velocity g_dot, radius R and dR/dt.
    """
    def __init__(self, *, center: typing.Annotated[numpy.typing.ArrayLike, numpy.float64, "[2, 1]"] = ..., center_velocity: typing.Annotated[numpy.typing.ArrayLike, numpy.float64, "[2, 1]"] = ..., radius: typing.SupportsFloat | typing.SupportsIndex = 1.0, radius_rate: typing.SupportsFloat | typing.SupportsIndex = 0.0, radius_acceleration: typing.SupportsFloat | typing.SupportsIndex = 0.0) -> None:
        """
        center g (m), center_velocity g_dot (m/s), radius R (m), radius_rate dR/dt (m/s), radius_acceleration d2R/dt2 (m/s^2; 0 on the paper's piecewise-linear locus).
        """
    def validate(self) -> None:
        """
        Raise VistrackError naming the first field out of range.
        """
    @property
    def center(self) -> typing.Annotated[numpy.typing.NDArray[numpy.float64], "[2, 1]"]:
        """
        g, (2,)
        """
    @center.setter
    def center(self, arg0: typing.Annotated[numpy.typing.ArrayLike, numpy.float64, "[2, 1]"]) -> None:
        ...
    @property
    def center_velocity(self) -> typing.Annotated[numpy.typing.NDArray[numpy.float64], "[2, 1]"]:
        """
        g_dot, (2,)
        """
    @center_velocity.setter
    def center_velocity(self, arg0: typing.Annotated[numpy.typing.ArrayLike, numpy.float64, "[2, 1]"]) -> None:
        ...
    @property
    def radius(self) -> float:
        """
        R, m
        """
    @radius.setter
    def radius(self, arg0: typing.SupportsFloat | typing.SupportsIndex) -> None:
        ...
    @property
    def radius_acceleration(self) -> float:
        """
        d2R/dt2, m/s^2
        """
    @radius_acceleration.setter
    def radius_acceleration(self, arg0: typing.SupportsFloat | typing.SupportsIndex) -> None:
        ...
    @property
    def radius_rate(self) -> float:
        """
        dR/dt, m/s
        """
    @radius_rate.setter
    def radius_rate(self, arg0: typing.SupportsFloat | typing.SupportsIndex) -> None:
        ...
class GuidanceGains:
    """
    Gains of the vector field and steering law: speed v, beta, k_psi, direction ('ccw' or 'cw'), max_turn_rate = v / r_min.
    """
    @staticmethod
    def from_parameters(uav: Uav, control: Control) -> GuidanceGains:
        """
        Gains from a Uav and a Control (max_turn_rate = speed / min_turn_radius).
        """
    def __init__(self, *, speed: typing.SupportsFloat | typing.SupportsIndex = 20.0, beta: typing.SupportsFloat | typing.SupportsIndex = 0.025, k_psi: typing.SupportsFloat | typing.SupportsIndex = 20.0, direction: str = 'ccw', max_turn_rate: typing.SupportsFloat | typing.SupportsIndex = 0.4) -> None:
        """
        Validated gains.
        """
    @property
    def beta(self) -> float:
        """
        beta of a_1 (59)
        """
    @beta.setter
    def beta(self, arg0: typing.SupportsFloat | typing.SupportsIndex) -> None:
        ...
    @property
    def direction(self) -> str:
        """
        'ccw' or 'cw'
        """
    @direction.setter
    def direction(self, arg0: str) -> None:
        ...
    @property
    def k_psi(self) -> float:
        """
        heading gain of (86)
        """
    @k_psi.setter
    def k_psi(self, arg0: typing.SupportsFloat | typing.SupportsIndex) -> None:
        ...
    @property
    def max_turn_rate(self) -> float:
        """
        u_psi,max = v / r_min, rad/s
        """
    @max_turn_rate.setter
    def max_turn_rate(self, arg0: typing.SupportsFloat | typing.SupportsIndex) -> None:
        ...
    @property
    def speed(self) -> float:
        """
        v, m/s
        """
    @speed.setter
    def speed(self, arg0: typing.SupportsFloat | typing.SupportsIndex) -> None:
        ...
class VectorField:
    """
    The guidance vector field (74) at one point.
    """
    @property
    def attraction(self) -> float:
        """
        Phi' (70), m/s
        """
    @property
    def attraction_rate(self) -> float:
        """
        dPhi'/dt along the field (83)
        """
    @property
    def e_r(self) -> typing.Annotated[numpy.typing.NDArray[numpy.float64], "[2, 1]"]:
        """
        radial unit vector
        """
    @property
    def e_theta(self) -> typing.Annotated[numpy.typing.NDArray[numpy.float64], "[2, 1]"]:
        """
        tangential unit vector
        """
    @property
    def heading(self) -> float:
        """
        desired heading psi_d (77), rad
        """
    @property
    def heading_rate(self) -> float:
        """
        dpsi_d/dt along the field (85), rad/s
        """
    @property
    def polar_rate(self) -> float:
        """
        theta_dot along the field (84)
        """
    @property
    def r(self) -> float:
        """
        distance to the POI, m
        """
    @property
    def radial_error(self) -> float:
        """
        r - R, m
        """
    @property
    def theta(self) -> float:
        """
        polar angle about the POI, rad
        """
    @property
    def u(self) -> typing.Annotated[numpy.typing.NDArray[numpy.float64], "[2, 1]"]:
        """
        u in x, y (75), |u| = v
        """
    @property
    def u_r(self) -> float:
        """
        radial component of u, m/s
        """
    @property
    def u_theta(self) -> float:
        """
        circulation component of u, m/s
        """
class Steering:
    """
    The steering law (86) at one configuration.
    """
    @property
    def command(self) -> float:
        """
        u_psi clamped to +-max_turn_rate, rad/s
        """
    @property
    def feed_forward(self) -> float:
        """
        dpsi_d/dt (85)
        """
    @property
    def field(self) -> VectorField:
        """
        the vector field at the UAV
        """
    @property
    def heading_error(self) -> float:
        """
        psi - psi_d wrapped to (-pi, pi]
        """
    @property
    def lyapunov(self) -> float:
        """
        u_lyap, the last term of (86)
        """
    @property
    def proportional(self) -> float:
        """
        k_psi (psi_d - psi)
        """
    @property
    def saturated(self) -> bool:
        """
        whether the clamp was active
        """
    @property
    def unsaturated(self) -> float:
        """
        sum of the three terms, rad/s
        """
class OdeStatistics:
    """
    Work done by the integrator.
    """
    def __repr__(self) -> str:
        ...
    @property
    def accepted_steps(self) -> int:
        """
        accepted steps
        """
    @property
    def rejected_steps(self) -> int:
        """
        rejected trial steps
        """
    @property
    def rhs_evaluations(self) -> int:
        """
        right-hand side evaluations
        """
class OdeResult:
    """
    Solution of solve_ode.
    """
    @property
    def event_index(self) -> list[int]:
        """
        which event each crossing belongs to
        """
    @property
    def event_t(self) -> typing.Annotated[numpy.typing.NDArray[numpy.float64], "[m, 1]"]:
        """
        crossing times, in time order
        """
    @property
    def event_y(self) -> typing.Annotated[numpy.typing.NDArray[numpy.float64], "[m, n]"]:
        """
        states at the crossings (k, dim)
        """
    @property
    def statistics(self) -> OdeStatistics:
        """
        work done
        """
    @property
    def t(self) -> typing.Annotated[numpy.typing.NDArray[numpy.float64], "[m, 1]"]:
        """
        output times (n,)
        """
    @property
    def terminated(self) -> bool:
        """
        stopped by a terminal event
        """
    @property
    def y(self) -> typing.Annotated[numpy.typing.NDArray[numpy.float64], "[m, n]"]:
        """
        states (n, dim)
        """
class SimulationResult:
    """
    Closed-loop trajectory and its errors (section VI).
    """
    def to_csv(self) -> str:
        """
        The trajectory as CSV text (header t,x,y,psi,psi_d,psi_d_rate,radial_error,heading_error,u_psi,u_psi_unsaturated,poi_x,poi_y,poi_z,orbit_radius[,visible]), as vistrack_sim writes it.
        """
    @property
    def bank(self) -> numpy.typing.NDArray[numpy.float64]:
        """
        bank (n,), rad: the roll model's state, or the coordinated bank of u_psi (dubins)
        """
    @property
    def control(self) -> numpy.typing.NDArray[numpy.float64]:
        """
        turn rate u_psi commanded by (86) (clamped to +-v/r_min), rad/s; the Dubins vehicle flies it at once
        """
    @property
    def control_unsaturated(self) -> numpy.typing.NDArray[numpy.float64]:
        """
        the steering law (86) before the clamp, rad/s
        """
    @property
    def desired_heading(self) -> numpy.typing.NDArray[numpy.float64]:
        """
        psi_d (77) at each sample, rad
        """
    @property
    def desired_heading_rate(self) -> numpy.typing.NDArray[numpy.float64]:
        """
        dpsi_d/dt along the field (85), rad/s
        """
    @property
    def heading_error(self) -> numpy.typing.NDArray[numpy.float64]:
        """
        psi - psi_d wrapped to (-pi, pi], rad
        """
    @property
    def orbit_radius(self) -> numpy.typing.NDArray[numpy.float64]:
        """
        R(t), m
        """
    @property
    def poi(self) -> typing.Annotated[numpy.typing.NDArray[numpy.float64], "[m, 3]"]:
        """
        (n, 3) POI position g(t)
        """
    @property
    def radial_error(self) -> numpy.typing.NDArray[numpy.float64]:
        """
        r - R, m
        """
    @property
    def restart_times(self) -> numpy.typing.NDArray[numpy.float64]:
        """
        segment boundaries where the integrator restarted, s
        """
    @property
    def state(self) -> typing.Annotated[numpy.typing.NDArray[numpy.float64], "[m, 3]"]:
        """
        (n, 3): x, y, psi (psi as integrated, unwrapped)
        """
    @property
    def statistics(self) -> OdeStatistics:
        """
        integrator work (all segments)
        """
    @property
    def t(self) -> numpy.typing.NDArray[numpy.float64]:
        """
        output times (n,), s
        """
    @property
    def turn_rate(self) -> numpy.typing.NDArray[numpy.float64]:
        """
        turn rate flown: u_psi (dubins) or g tan(phi) / v (roll), rad/s
        """
    @property
    def visibility_fraction(self) -> float | None:
        """
        fraction of samples with line of sight, or None
        """
    @property
    def visible(self) -> typing.Any:
        """
        line of sight UAV -> POI at each sample (bool array), or None when not evaluated
        """
class TuningResult:
    """
    Grid search of max |dpsi_d/dt + u_lyap| (section V.D).
    """
    @property
    def angles(self) -> numpy.typing.NDArray[numpy.float64]:
        """
        grid angles, rad
        """
    @property
    def at_heading_error(self) -> float:
        """
        heading error of the maximum, rad
        """
    @property
    def at_r(self) -> float:
        """
        distance to the POI of the maximum, m
        """
    @property
    def at_theta(self) -> float:
        """
        polar angle of the maximum from the POI's motion, rad
        """
    @property
    def map(self) -> numpy.typing.NDArray[numpy.float64]:
        """
        (num_radii, num_angles): max over heading errors at each grid point, rad/s
        """
    @property
    def max_turn_rate(self) -> float:
        """
        max |dpsi_d/dt + u_lyap|, rad/s
        """
    @property
    def radii(self) -> numpy.typing.NDArray[numpy.float64]:
        """
        grid radii, m
        """
def check_closed_mesh(vertices: typing.Annotated[numpy.typing.ArrayLike, numpy.float64, "[m, 3]"], faces: typing.Annotated[numpy.typing.ArrayLike, numpy.int32, "[m, 3]"]) -> MeshCheck:
    """
    Check with CGAL that a triangle mesh is closed, 2-manifold, free of self-intersections, bounds a volume and is outward oriented.
    """
def check_work(poi: PoiPath, planning: Planning) -> WorkEstimate:
    """
    estimate_work, and VistrackError naming planning.resolution_deg or planning.spacing when the initial VVs would hold more than limits.MAX_WORK_BYTES, or planning.max_volumes when the worst case exceeds it (what the planner does before computing any VV); returns the estimate.
    """
def circular_orbits(times: collections.abc.Sequence[typing.SupportsFloat | typing.SupportsIndex], max_radii: collections.abc.Sequence[typing.SupportsFloat | typing.SupportsIndex], uav: Uav, poi_speed: typing.SupportsFloat | typing.SupportsIndex, rate_margin: typing.SupportsFloat | typing.SupportsIndex = 0.0) -> CircularOrbits:
    """
    Algorithm 1 (lines 2-18): lower radii so that |dR/dt| <= (1 - rate_margin)(v - v_g) (Lemma 5 for rate_margin = 0), each limited radius built from its neighbour's, then check R_k >= r_min (1 + v_g/v)^2 (Lemma 6). VistrackError when the UAV is not faster than the POI.
    """
def constant_radius_plan(poi: PoiPath, radius: typing.SupportsFloat | typing.SupportsIndex, uav: Uav) -> OrbitPlan:
    """
    Baseline plan: orbits of one radius along the whole POI path.
    """
def epsilon_max() -> float:
    """
    Maximum of atan^2(x) / (1 + x^2), about 0.31483 (98).
    """
def estimate_work(poi: PoiPath, planning: Planning) -> WorkEstimate:
    """
    Worst case of plan_orbits / OrbitPlanner.plan on this path: VVs (every initial interval halved down to min_spacing or max_depth) and their memory; the planner refuses a worst case beyond planning.max_volumes before computing any VV.
    """
def grid_xor_volume(a: VisibilityVolume, b: VisibilityVolume) -> float:
    """
    The XOR volume of two VVs on one direction grid, each about its own POI: per grid corner, trapezoid rule.
    """
def lambda_max() -> float:
    """
    Maximum of atan(x) / (1 + x^2), about 0.41195 (106).
    """
def lemma6_curvature_bound(radius: typing.SupportsFloat | typing.SupportsIndex, speed: typing.SupportsFloat | typing.SupportsIndex, poi_speed: typing.SupportsFloat | typing.SupportsIndex) -> float:
    """
    (v_g + v)^2 / (R v^2), the maximum curvature on an orbit (Lemma 6).
    """
def lemma7_min_gain(speed: typing.SupportsFloat | typing.SupportsIndex, beta: typing.SupportsFloat | typing.SupportsIndex) -> float:
    """
    The lower bound (87) on k_psi: v beta 4 / pi^2 eps_max.
    """
def lyapunov_term(field: VectorField, orbit: OrbitState, beta: typing.SupportsFloat | typing.SupportsIndex, heading_error: typing.SupportsFloat | typing.SupportsIndex) -> float:
    """
    u_lyap of (86) for the field at the UAV and heading error psi - psi_d.
    """
def max_inscribed_radius(polygons: collections.abc.Sequence[Polygon], center: typing.Annotated[numpy.typing.ArrayLike, numpy.float64, "[2, 1]"]) -> float:
    """
    Radius of the largest circle centred at `center` inside the visibility polygon: the distance to the nearest boundary (holes included) of the polygon containing the centre, 0 when none contains it.
    """
def max_orbit_curvature(radius: typing.SupportsFloat | typing.SupportsIndex, uav_speed: typing.SupportsFloat | typing.SupportsIndex, poi_speed: typing.SupportsFloat | typing.SupportsIndex) -> float:
    """
    Lemma 6: (1 + v_g/v)^2 / R, the largest curvature (31) over angles and admissible dR/dt.
    """
def mesh_volume(vertices: typing.Annotated[numpy.typing.ArrayLike, numpy.float64, "[m, 3]"], faces: typing.Annotated[numpy.typing.ArrayLike, numpy.int32, "[m, 3]"]) -> float:
    """
    Volume of a closed, consistently oriented triangle mesh.
    """
def mesh_xor_volume(vertices_a: typing.Annotated[numpy.typing.ArrayLike, numpy.float64, "[m, 3]"], faces_a: typing.Annotated[numpy.typing.ArrayLike, numpy.int32, "[m, 3]"], vertices_b: typing.Annotated[numpy.typing.ArrayLike, numpy.float64, "[m, 3]"], faces_b: typing.Annotated[numpy.typing.ArrayLike, numpy.int32, "[m, 3]"], time_limit: typing.SupportsFloat | typing.SupportsIndex = 120.0, perturbation: typing.SupportsFloat | typing.SupportsIndex | None = None, check_self_intersection: bool = True) -> float:
    """
    vol(A) + vol(B) - 2 vol(A n B) of two closed triangle meshes ((n, 3) float vertices, (m, 3) int
    faces) by CGAL corefinement with exact predicates on copies; perturbation (rad, None: 0) rotates b
    as in xor_volume. VistrackError when a mesh is not
    closed, self-intersects, does not bound a volume, or time_limit (s) is exceeded.
    """
def min_feasible_radius(uav: Uav, poi_speed: typing.SupportsFloat | typing.SupportsIndex) -> float:
    """
    r_min (1 + v_g/v)^2: the smallest orbit radius Lemma 6 allows (at most 4 r_min, Corollary 1).
    """
def one_minus_cos_over_x(x: typing.SupportsFloat | typing.SupportsIndex) -> float:
    """
    (1 - cos x) / x, 0 at x = 0, accurate near 0.
    """
def orbit_configuration(theta0: typing.SupportsFloat | typing.SupportsIndex, orbit: OrbitState, speed: typing.SupportsFloat | typing.SupportsIndex, direction: str = 'ccw') -> typing.Annotated[numpy.typing.NDArray[numpy.float64], "[3, 1]"]:
    """
    Initial configuration (x, y, psi) on the orbit, (38)-(40).
    """
def orbit_curvature(radius: typing.SupportsFloat | typing.SupportsIndex, radius_rate: typing.SupportsFloat | typing.SupportsIndex, relative_angle: typing.SupportsFloat | typing.SupportsIndex, uav_speed: typing.SupportsFloat | typing.SupportsIndex, poi_speed: typing.SupportsFloat | typing.SupportsIndex, direction: str = 'ccw') -> float:
    """
    Curvature (31) of the path that stays on the orbit at a = theta - gamma, with theta' from (13) for the circulation 'ccw' or 'cw'; inf when (g'.e_r + R')^2 >= v^2 (Lemma 5).
    """
def orbit_polar_rate(theta: typing.SupportsFloat | typing.SupportsIndex, orbit: OrbitState, speed: typing.SupportsFloat | typing.SupportsIndex, direction: str = 'ccw') -> float:
    """
    theta_dot of (13) for a vehicle remaining on the orbit.
    """
def orbit_signed_curvature(theta: typing.SupportsFloat | typing.SupportsIndex, orbit: OrbitState, speed: typing.SupportsFloat | typing.SupportsIndex, direction: str = 'ccw') -> float:
    """
    Signed path curvature (31) of a vehicle remaining on the orbit at polar angle theta (Theorem 1: steering with v * this keeps it there).
    """
def orbit_state(plan: OrbitPlan, segment_start: typing.SupportsFloat | typing.SupportsIndex, t: typing.SupportsFloat | typing.SupportsIndex) -> OrbitState:
    """
    The reference orbit (g, g_dot, R, dR/dt, d2R/dt2) at t on the segment that starts at segment_start (one of segment_boundaries(plan)): what the closed loop steers around, for an outside vehicle model (vistrack.fdm) with steering().
    """
def plan_on_volumes(poi: PoiPath, uav: Uav, planning: Planning, arc_lengths: collections.abc.Sequence[typing.SupportsFloat | typing.SupportsIndex], volumes: collections.abc.Sequence[VisibilityVolume]) -> VisibilityOrbitPlan:
    """
    The plan on VVs computed elsewhere (e.g. saved VV files), placed at the given increasing arc lengths of the POI path: metric (56) in the POI frame, VPs at h_UAV, MaxRadius and Algorithm 1, nothing inserted.
    """
def plan_orbits(env: Environment, poi: PoiPath, uav: Uav, sensor: Sensor, planning: Planning, progress: typing.Any = None, cache_dir: typing.Any = None) -> VisibilityOrbitPlan:
    """
    Section IV end to end: adaptive VVs along the POI path (IV.B), VPs at h_UAV, MaxRadius, then Algorithm 1 (IV.C). cache_dir: as for OrbitPlanner. Returns a VisibilityOrbitPlan (an OrbitPlan); infeasible plans say which sample fails and why. VistrackError when the UAV is not faster than the POI.
    """
def plane_visibility_polygon(vv: VisibilityVolume, altitude: typing.SupportsFloat | typing.SupportsIndex) -> list[Polygon]:
    """
    VP of a VV at world altitude z by walking the mesh edges that cross the plane (what the orbit planner uses); the same polygons as vv.slice(z), which uses CGAL's slicer.
    """
def radial_error_rate(field: VectorField, orbit: OrbitState, heading_error: typing.SupportsFloat | typing.SupportsIndex) -> float:
    """
    d(r - R)/dt of (93) for the Dubins vehicle with the given heading error.
    """
def radial_xor_volume(a: VisibilityVolume, b: VisibilityVolume) -> float:
    """
    The XOR volume of two star VVs' meshes, each about its own POI, exact per direction (faces
    overlapped, |r_a^3 - r_b^3| / 3 integrated in closed form between planes). VistrackError unless
    shares_radial_mesh(a, b).
    """
def sample_vector_field(points: typing.Annotated[numpy.typing.ArrayLike, numpy.float64, "[m, 2]"], orbit: OrbitState, gains: GuidanceGains) -> tuple[typing.Annotated[numpy.typing.NDArray[numpy.float64], "[m, 2]"], typing.Annotated[numpy.typing.NDArray[numpy.float64], "[m, 1]"], typing.Annotated[numpy.typing.NDArray[numpy.float64], "[m, 1]"]]:
    """
    The field at many points (n, 2): returns (u (n, 2), psi_d (n,), dpsi_d/dt (n,)).
    """
def segment_boundaries(plan: OrbitPlan) -> list[float]:
    """
    Times where dR/dt or the POI velocity may jump: plan samples and path nodes.
    """
def shares_direction_grid(a: VisibilityVolume, b: VisibilityVolume) -> bool:
    """
    True when both VVs carry intervals on the same direction grid (the grid path applies).
    """
def shares_radial_mesh(a: VisibilityVolume, b: VisibilityVolume) -> bool:
    """
    True when both VVs are star VVs (POI in the band) on the same direction grid, with the record of
    how their meshes cover the sphere of grid corners (the radial path applies; rows may differ).
    """
def simulate(plan: OrbitPlan, uav: Uav, x0: typing.Annotated[numpy.typing.ArrayLike, numpy.float64, "[3, 1]"], control: Control, env: typing.Any = None, options: SimulationOptions = ..., *, line_of_sight: collections.abc.Callable | None = None, fixed_step: typing.SupportsFloat | typing.SupportsIndex = 0.0) -> SimulationResult:
    """
    Closed loop of section VI: the Dubins vehicle (1) from x0 = (x, y, psi) steered by (86) around the plan's time-varying orbit, Dormand-Prince 5(4) restarted at each segment boundary (options.rtol/atol/max_step; fixed_step > 0 for fixed steps), sampled every options.output_step. With env (an Environment or a VisibilityScene: Embree occlusion rays from the UAV at world z = uav.altitude to the POI, lifted onto the surface where its path z is underground) or a line_of_sight(from (n, 3), to (n, 3)) -> bool array callable (UAV at z = uav.altitude, POI at its path z), also the line of sight at every sample and the visibility fraction. Releases the GIL.
    """
def sinc(x: typing.SupportsFloat | typing.SupportsIndex) -> float:
    """
    sin(x) / x, 1 at x = 0, accurate near 0.
    """
def slice_mesh(vertices: typing.Annotated[numpy.typing.ArrayLike, numpy.float64, "[m, 3]"], faces: typing.Annotated[numpy.typing.ArrayLike, numpy.int32, "[m, 3]"], altitude: typing.SupportsFloat | typing.SupportsIndex) -> list[Polygon]:
    """
    Polygons (with holes) where the plane z = altitude cuts a closed mesh (CGAL Polygon_mesh_slicer).
    """
def smooth_radius(ceiling: Ceiling, limits: SmoothRadiusLimits, knot_spacing: typing.SupportsFloat | typing.SupportsIndex = 0.0, passes: typing.SupportsInt | typing.SupportsIndex = 2, smoothing: typing.SupportsFloat | typing.SupportsIndex = 0.3) -> RadiusProfile:
    """
    The C1 quadratic spline on uniform knots (knot_spacing; <= 0: picked from the d2R/dt2 bound) under the ceiling that obeys `limits` with the largest integral of R(t) less the d2R/dt2 penalty (smoothing / 2) (top / A^2) integral of (d2R/dt2)^2 (top: the ceiling's largest value, A: the d2R/dt2 bound there; smoothing 0: the largest integral, a banded linear program): a log-barrier interior point method, re-solved passes - 1 times with the d2R/dt2 budget of the radii reached. A RadiusProfile.
    """
def smooth_radius_violation(profile: RadiusProfile, limits: SmoothRadiusLimits) -> str:
    """
    Why a smooth RadiusProfile breaks `limits` (|dR/dt| at a knot, |d2R/dt2| on a segment against the bound at its smallest R), or '' when it keeps them all.
    """
def solve_ode(fun: collections.abc.Callable[[float, typing.Annotated[numpy.typing.NDArray[numpy.float64], "[m, 1]"]], typing.Annotated[numpy.typing.ArrayLike, numpy.float64, "[m, 1]"]], t_span: tuple[typing.SupportsFloat | typing.SupportsIndex, typing.SupportsFloat | typing.SupportsIndex], y0: typing.Annotated[numpy.typing.ArrayLike, numpy.float64, "[m, 1]"], *, rtol: typing.SupportsFloat | typing.SupportsIndex = 1e-06, atol: typing.SupportsFloat | typing.SupportsIndex = 1e-08, max_step: typing.SupportsFloat | typing.SupportsIndex = ..., first_step: typing.SupportsFloat | typing.SupportsIndex = 0.0, fixed_step: typing.SupportsFloat | typing.SupportsIndex = 0.0, t_eval: collections.abc.Sequence[typing.SupportsFloat | typing.SupportsIndex] = [], events: collections.abc.Sequence[typing.Any] = []) -> OdeResult:
    """
    Dormand-Prince 5(4) for dy/dt = fun(t, y) over t_span = (t0, t1), like scipy.integrate.solve_ivp(method='RK45'): adaptive steps (rtol, atol, max_step, first_step; 0 = automatic), or fixed_step > 0 for fixed steps. Output at t_eval (dense output) or at every step. events: callables event(t, y) with optional attributes direction (+1, -1, 0) and terminal (bool or count), located on the dense output.
    """
def steering(q: typing.Annotated[numpy.typing.ArrayLike, numpy.float64, "[3, 1]"], orbit: OrbitState, gains: GuidanceGains) -> Steering:
    """
    The steering law (86) at configuration q = (x, y, psi), clamped to +-max_turn_rate (2).
    """
def tune_turn_rate(radius: typing.SupportsFloat | typing.SupportsIndex, radius_rate: typing.SupportsFloat | typing.SupportsIndex, speed: typing.SupportsFloat | typing.SupportsIndex, poi_speed: typing.SupportsFloat | typing.SupportsIndex, beta: typing.SupportsFloat | typing.SupportsIndex, *, direction: str = 'ccw', tau: typing.SupportsFloat | typing.SupportsIndex = 1.0, r_max_factor: typing.SupportsFloat | typing.SupportsIndex = 4.0, num_radii: typing.SupportsInt | typing.SupportsIndex = 200, num_angles: typing.SupportsInt | typing.SupportsIndex = 360, num_heading_errors: typing.SupportsInt | typing.SupportsIndex = 73) -> TuningResult:
    """
    Largest |dpsi_d/dt + u_lyap| (85), (106) over r in [tau R, r_max_factor R], all polar angles and heading errors, for orbit radius R, dR/dt, UAV speed v, POI speed v_g and beta (Fig. 9). Compare with v / r_min.
    """
def vector_field(xi: typing.Annotated[numpy.typing.ArrayLike, numpy.float64, "[2, 1]"], orbit: OrbitState, gains: GuidanceGains, heading_hint: typing.SupportsFloat | typing.SupportsIndex = 0.0) -> VectorField:
    """
    The constant-speed guidance vector field (74) at position xi (2,): desired heading (77) and its rate along the field (85). heading_hint orients the frame at the exact centre.
    """
def visibility_volume(scene: VisibilityScene, g: typing.Annotated[numpy.typing.ArrayLike, numpy.float64, "[m, 1]"], d_max: typing.SupportsFloat | typing.SupportsIndex, altitude_band: tuple[typing.SupportsFloat | typing.SupportsIndex, typing.SupportsFloat | typing.SupportsIndex] | None = None, resolution_deg: typing.SupportsFloat | typing.SupportsIndex = 1.0, with_mesh: bool = True) -> VisibilityVolume:
    """
    Visibility volume of POI g (3,) within d_max, inside the altitude band (h_lo, h_hi) of world z when given, on a grid of about resolution_deg degrees; with_mesh=False leaves the mesh out (the same intervals and volume, less work).
    """
def visibility_volume_cost(scene: VisibilityScene, g: typing.Annotated[numpy.typing.ArrayLike, numpy.float64, "[m, 1]"], d_max: typing.SupportsFloat | typing.SupportsIndex, altitude_band: tuple[typing.SupportsFloat | typing.SupportsIndex, typing.SupportsFloat | typing.SupportsIndex] | None = None, resolution_deg: typing.SupportsFloat | typing.SupportsIndex = 1.0, parallel: bool = True, check_predicted: bool = False, with_mesh: bool = True) -> tuple[VisibilityVolume, VolumeCost]:
    """
    visibility_volume and where its time and rays went: (vv, VolumeCost); parallel=False keeps it on the calling thread (as in a batch); check_predicted=True also traces the refining rays it predicts (VolumeCost.predicted_misses, predicted_error); with_mesh as in visibility_volume.
    """
def visibility_volumes(scene: VisibilityScene, pois: typing.Annotated[numpy.typing.ArrayLike, numpy.float64, "[m, 3]"], d_max: typing.SupportsFloat | typing.SupportsIndex, altitude_band: tuple[typing.SupportsFloat | typing.SupportsIndex, typing.SupportsFloat | typing.SupportsIndex] | None = None, resolution_deg: typing.SupportsFloat | typing.SupportsIndex = 1.0, with_mesh: bool = True) -> list[VisibilityVolume]:
    """
    VVs for every row of pois (n, 3), in parallel over the points; with_mesh as in visibility_volume.
    """
def visible_disk_radius(scene: VisibilityScene, poi: typing.Annotated[numpy.typing.ArrayLike, numpy.float64, "[3, 1]"], altitude: typing.SupportsFloat | typing.SupportsIndex, sensor: Sensor, azimuths: typing.SupportsInt | typing.SupportsIndex = 360, rings: typing.SupportsInt | typing.SupportsIndex = 8) -> float:
    """
    MaxRadius by line of sight (the locus check's probe): the largest disk at world z = altitude centred above the POI (placed on the surface) every point of which sees it, by occlusion rays along `azimuths` directions on `rings` circles and then by bisection.
    """
def volume_bytes(resolution_deg: typing.SupportsFloat | typing.SupportsIndex, with_mesh: bool = True) -> float:
    """
    Memory of one VV on a grid of resolution_deg degrees, estimated from above (bytes; ~4.7 MB at 1 degree); with_mesh=False: its intervals only (~1 MB).
    """
def wrap_to_pi(angle: typing.SupportsFloat | typing.SupportsIndex) -> float:
    """
    Angle wrapped to (-pi, pi]; VistrackError when not finite.
    """
def xor_volume(a: VisibilityVolume, b: VisibilityVolume, frame: str = 'poi', method: str = 'auto', time_limit: typing.SupportsFloat | typing.SupportsIndex = 120.0, perturbation: typing.SupportsFloat | typing.SupportsIndex | None = None) -> float:
    """
    Volume (m^3) of the symmetric difference of two VVs, the metric d of eq. (56).
    
    frame: "poi" translates each VV by minus its POI first (open terrain gives 0), "world" compares
    them in place. method: "radial" is the exact XOR of the two meshes computed per direction
    (star VVs on one direction grid: what "mesh" gives, without CGAL); "grid" is
    the per-direction integral sum(corner_weight * |A xor B| measured in r^2 dr) over the grid corners'
    intervals of a shared direction grid (trapezoid rule); both need frame "poi" or equal POIs. "mesh" is CGAL corefinement
    of the closed meshes; "auto" takes radial, else grid, else mesh, as they apply.
    time_limit (s) aborts the mesh path with VistrackError. perturbation (rad): rotation of b's mesh
    about the axis (1,2,3) before the Boolean; default 1e-6 in the POI frame (identical sphere faces
    make CGAL pathologically slow), 0 in the world frame.
    """
__version__: str = '0.1.0'
