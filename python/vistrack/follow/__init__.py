"""Following a ground vehicle (../shared/seeds/ground_vehicle_following.txt).

The planner flies a sinusoid about the vehicle's path whose amplitude makes the UAV's average
progress equal the vehicle's (eqs. 5, 9-10: sigma = v_p / v_g = (2/pi) E(-A'^2), A' = 2 pi A / D,
D = v_g T), loiters (circle or the rose of Fig. 3) above a speed-ratio threshold with a
hysteresis band, follows an offset point (distance and angle, fixed to north or turning with the
vehicle), compensates a known wind by planning in the air mass (see cpp/include/vistrack/
follow.hpp for the derivation), and issues a waypoint every second (section V). The flight layer
flies the waypoints (the waypoint paper's feedback law (5) on a ``WaypointFollower``).

Example::

    import math, vistrack as vt
    A = vt.follow.sinusoid_amplitude(2.0, 300.0)           # m, for sigma = 2 and D = 300 m
    car = vt.follow.GroundVehicle.from_legs([vt.follow.VehicleLeg(-math.pi / 2, 10.0, 300.0)])
    res = vt.follow.simulate(car, vt.Uav(speed=21.0, min_turn_radius=50.0, altitude=200.0))
    res.metrics["camera_fraction"], res.mode, res.waypoints

``baseline(...)`` flies the tracking paper's vector field (74) at a constant radius about the same
offset point, for comparison; with a ``VisibilityScene`` both also report the line of sight
through the buildings.

- ``simulation``: the API above; ``scenario``: follow scenarios from YAML and the runs
  ``vistrack follow`` makes (old address: ``vistrack.follow_scenario``); ``files``: vehicle tracks, road paths,
  trajectories as CSV; ``to_mission``: a run's waypoints as an autopilot mission;
  ``city_horizon`` (beyond the paper, the default city follower): with a city, bank commands planned
  each second over a 24 s prediction of the vehicle by dynamic programming with rays through the city;
  ``city_orbit`` (``planner: orbit``): an orbit about the vehicle inside the visibility polygon of its
  predicted position; ``city_runs``: their shared result.
"""

from __future__ import annotations

from .scenario import CityRoad, FollowScenario, FollowStudy
from .simulation import (
    MODES,
    DownwardCamera,
    FollowFlight,
    FollowMetrics,
    FollowObservation,
    FollowParameters,
    FollowPlanner,
    FollowResult,
    FollowRun,
    FollowTick,
    GroundVehicle,
    LoiterShape,
    VehicleLeg,
    VehicleReportOptions,
    along_track_rate,
    arc_length,
    baseline,
    baseline_infeasibility,
    baseline_radius,
    camera_footprint,
    camera_reach,
    camera_sees,
    camera_threshold,
    coordinated_bank,
    default_uav,
    line_of_sight,
    phase_at_arc,
    simulate,
    sinusoid_amplitude,
    sinusoid_shape,
    sinusoid_slope,
    speed_ratio,
    threshold_warning,
)

__all__ = [
    "MODES", "CityRoad", "DownwardCamera", "FollowFlight", "FollowMetrics", "FollowObservation", "FollowParameters",
    "FollowPlanner", "FollowResult", "FollowRun", "FollowScenario", "FollowStudy", "FollowTick", "GroundVehicle",
    "LoiterShape", "VehicleLeg", "VehicleReportOptions", "along_track_rate", "arc_length", "baseline",
    "baseline_infeasibility", "baseline_radius", "camera_footprint", "camera_reach", "camera_sees", "camera_threshold",
    "coordinated_bank", "default_uav", "line_of_sight", "phase_at_arc", "simulate", "sinusoid_amplitude",
    "sinusoid_shape", "sinusoid_slope", "speed_ratio", "threshold_warning",
]
