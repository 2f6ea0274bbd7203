"""vistrack: occlusion-aware tracking of a moving ground target by a Dubins UAV.

The C++ core lives in ``vistrack._core``; this package re-exports it by area and adds scenario
files (``scenario``), file formats (``io``), the pipeline from map to report (``pipeline``,
``report``), metrics, plotting and the command line (``cli``, ``commands``; the library never
imports them).
"""

from __future__ import annotations

from importlib.metadata import PackageNotFoundError, version as _version

from . import _core, dubins
from ._core import (  # geometry and parameters
    Control,
    Planning,
    PoiMotion,
    Polygon,
    Sensor,
    SimulationOptions,
    Uav,
    VistrackError,
    wrap_to_pi,
)
from ._core import Environment, PoiPath, RoadNetwork  # environment
from ._core import (  # visibility and volumes
    DirectionGrid,
    MeshCheck,
    VisibilityScene,
    VisibilityVolume,
    check_closed_mesh,
    grid_xor_volume,
    mesh_volume,
    mesh_xor_volume,
    plane_visibility_polygon,
    radial_xor_volume,
    shares_direction_grid,
    shares_radial_mesh,
    slice_mesh,
    xor_volume,
)
from ._core import (  # orbits (section IV)
    CircularOrbits,
    Discretization,
    OrbitPlan,
    OrbitPlanner,
    VisibilityOrbitPlan,
    circular_orbits,
    constant_radius_plan,
    max_inscribed_radius,
    max_orbit_curvature,
    min_feasible_radius,
    orbit_curvature,
    plan_on_volumes,
    plan_orbits,
)
from ._core import (  # guidance, integrator and closed loop (sections V-VI)
    GuidanceGains,
    OdeResult,
    OdeStatistics,
    OrbitState,
    SimulationResult,
    Steering,
    TuningResult,
    VectorField,
    epsilon_max,
    lambda_max,
    lemma6_curvature_bound,
    lemma7_min_gain,
    lyapunov_term,
    one_minus_cos_over_x,
    orbit_configuration,
    orbit_polar_rate,
    orbit_signed_curvature,
    radial_error_rate,
    sample_vector_field,
    segment_boundaries,
    simulate,
    sinc,
    solve_ode,
    steering,
    tune_turn_rate,
    vector_field,
)
from .pipeline import RunResult, run
from .scenario import Scenario
from .visibility import polygon_agreement, visibility_scene, visibility_volume, visibility_volumes

try:
    __version__ = _version("vistrack")
except PackageNotFoundError:  # running from a build tree
    __version__ = _core.__version__

__all__ = [
    "CircularOrbits", "Control", "DirectionGrid", "Discretization", "Environment", "GuidanceGains",
    "MeshCheck", "OdeResult", "OdeStatistics", "OrbitPlan", "OrbitPlanner", "OrbitState", "Planning",
    "PoiMotion", "PoiPath", "Polygon", "RoadNetwork", "RunResult", "Scenario", "Sensor", "SimulationOptions",
    "SimulationResult", "Steering", "TuningResult", "Uav", "VectorField", "VisibilityOrbitPlan",
    "VisibilityScene", "VisibilityVolume", "VistrackError", "__version__", "check_closed_mesh",
    "circular_orbits", "constant_radius_plan", "dubins", "epsilon_max", "grid_xor_volume",
    "lambda_max", "lemma6_curvature_bound", "lemma7_min_gain", "lyapunov_term",
    "max_inscribed_radius", "max_orbit_curvature", "mesh_volume", "mesh_xor_volume",
    "min_feasible_radius", "one_minus_cos_over_x", "orbit_configuration", "orbit_curvature",
    "orbit_polar_rate", "orbit_signed_curvature", "plan_on_volumes", "plan_orbits", "plane_visibility_polygon",
    "radial_error_rate", "radial_xor_volume", "run", "sample_vector_field", "segment_boundaries",
    "shares_direction_grid", "shares_radial_mesh",
    "simulate", "sinc", "slice_mesh", "solve_ode", "steering", "tune_turn_rate", "vector_field",
    "polygon_agreement", "visibility_scene", "visibility_volume", "visibility_volumes", "wrap_to_pi",
    "xor_volume",
]
