"""vistrack: occlusion-aware tracking of a moving ground target by a Dubins UAV.

The C++ core lives in ``vistrack._core``; this package re-exports it and adds scenario files,
the command line, plotting and pipelines.
"""

from __future__ import annotations

from importlib.metadata import PackageNotFoundError, version as _version

from . import _core
from ._core import (
    Control,
    Environment,
    GuidanceGains,
    OdeResult,
    OdeStatistics,
    OrbitPlan,
    OrbitState,
    Planning,
    PoiPath,
    Polygon,
    Sensor,
    SimulationOptions,
    SimulationResult,
    Steering,
    TuningResult,
    Uav,
    VectorField,
    VistrackError,
    constant_radius_plan,
    epsilon_max,
    lambda_max,
    lemma6_curvature_bound,
    lemma7_min_gain,
    lyapunov_term,
    max_inscribed_radius,
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

try:
    __version__ = _version("vistrack")
except PackageNotFoundError:  # running from a build tree
    __version__ = _core.__version__

__all__ = [
    "Control",
    "Environment",
    "GuidanceGains",
    "OdeResult",
    "OdeStatistics",
    "OrbitPlan",
    "OrbitState",
    "Planning",
    "PoiPath",
    "Polygon",
    "Sensor",
    "SimulationOptions",
    "SimulationResult",
    "Steering",
    "TuningResult",
    "Uav",
    "VectorField",
    "VistrackError",
    "constant_radius_plan",
    "epsilon_max",
    "lambda_max",
    "lemma6_curvature_bound",
    "lemma7_min_gain",
    "lyapunov_term",
    "max_inscribed_radius",
    "one_minus_cos_over_x",
    "orbit_configuration",
    "orbit_polar_rate",
    "orbit_signed_curvature",
    "radial_error_rate",
    "sample_vector_field",
    "segment_boundaries",
    "simulate",
    "sinc",
    "solve_ode",
    "steering",
    "tune_turn_rate",
    "vector_field",
    "__version__",
]
