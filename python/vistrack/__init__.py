"""vistrack: occlusion-aware tracking of a moving ground target by a Dubins UAV.

The C++ core lives in ``vistrack._core``; this package re-exports it and adds scenario files,
the command line, plotting and pipelines.
"""

from __future__ import annotations

from importlib.metadata import PackageNotFoundError, version as _version

from . import _core
from . import dubins
from ._core import (
    plane_visibility_polygon,
    OrbitPlanner,
    plan_orbits,
    CircularOrbits,
    Discretization,
    VisibilityOrbitPlan,
    circular_orbits,
    grid_xor_volume,
    max_orbit_curvature,
    mesh_xor_volume,
    min_feasible_radius,
    orbit_curvature,
    shares_direction_grid,
    xor_volume,
    Control,
    DirectionGrid,
    Environment,
    MeshCheck,
    OrbitPlan,
    Planning,
    PoiPath,
    Polygon,
    RoadNetwork,
    Sensor,
    SimulationOptions,
    Uav,
    VisibilityScene,
    VisibilityVolume,
    VistrackError,
    check_closed_mesh,
    constant_radius_plan,
    max_inscribed_radius,
    mesh_volume,
    slice_mesh,
)
from .visibility import visibility_scene, visibility_volume, visibility_volumes

try:
    __version__ = _version("vistrack")
except PackageNotFoundError:  # running from a build tree
    __version__ = _core.__version__

__all__ = [
    "plane_visibility_polygon",
    "OrbitPlanner",
    "plan_orbits",
    "CircularOrbits",
    "Discretization",
    "VisibilityOrbitPlan",
    "circular_orbits",
    "grid_xor_volume",
    "max_orbit_curvature",
    "mesh_xor_volume",
    "min_feasible_radius",
    "orbit_curvature",
    "shares_direction_grid",
    "xor_volume",
    "Control",
    "DirectionGrid",
    "Environment",
    "MeshCheck",
    "OrbitPlan",
    "Planning",
    "PoiPath",
    "Polygon",
    "RoadNetwork",
    "Sensor",
    "SimulationOptions",
    "Uav",
    "VisibilityScene",
    "VisibilityVolume",
    "VistrackError",
    "check_closed_mesh",
    "constant_radius_plan",
    "dubins",
    "max_inscribed_radius",
    "mesh_volume",
    "slice_mesh",
    "visibility_scene",
    "visibility_volume",
    "visibility_volumes",
    "__version__",
]
