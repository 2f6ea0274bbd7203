"""Loiter planning over areas of interest (AOIs) and camera coverage.

Wilhelm, Clem, Eberhart, *Direct Entry Minimal Path UAV Loitering Path Planning* (Aerospace,
2017): the Fly-Through loiter of common autopilots, the Tangential (TLPP) and the Least-Distance
(LDLPP) planners, as exact paths of lines and arcs (C++ ``vistrack._core.loiter``), and the
paper's coverage metric: a conic 74-degree camera on a +-25 degree roll gimbal; an AOI counts as
covered at a time step when at least 75 % of its disk lies in the footprint.

- ``planning``: plans, coverage and their metrics (the API below); every default is section
  4.1's, from the bound C++ structs ``Parameters``, ``CoverageOptions`` and ``Camera``
- ``scenario``: a scenario's settings, seeded random scenarios; ``files``: its YAML, plans as CSV
- ``flying``: a plan flown through the flight layer in wind, and scored
- ``study``: every method on a scenario, random studies at scale (old address: ``vistrack.loiter_study``)
- ``to_mission``: a plan as an autopilot mission; ``methods`` attaches it as ``Plan.to_mission``
- ``city``, ``city_coverage`` (beyond the paper): loiter circles inside each AOI's visibility
  polygon over a city, coverage with line of sight (a scenario's ``city`` block)

>>> import vistrack as vt
>>> plan = vt.loiter.plan([(300, 200), (600, 500)], method="ldlpp")
>>> cov = vt.loiter.coverage(plan)
>>> plan.flight_time, plan.transit_time, cov.time, cov.area
"""

from __future__ import annotations

from . import methods as _methods  # noqa: F401  (attaches Plan.to_mission)
from .files import (
    load_scenario,
)
from .flying import (
    flown_samples,
    fly,
    fly_and_score,
    loiter_coverage_fraction,
    path_pieces,
)
from .planning import (
    ALL_METHODS,
    AREA_SIZE,
    BEYOND_PAPER_METHODS,
    EXACT_ORDER_LIMIT,
    METHOD_NAMES,
    METHODS,
    OBJECTIVES,
    ORDERS,
    PLAN_METHODS,
    Camera,
    Coverage,
    CoverageOptions,
    FlightTrajectory,
    Footprint,
    Parameters,
    Plan,
    Samples,
    Segment,
    Wind,
    bank_angle,
    best_order,
    coverage,
    coverage_by_role,
    ellipse_disk_area,
    entry_angle,
    entry_distance,
    loiter_circles,
    metrics,
    order_length,
    plan,
    plan_in_order,
    segment_records,
    turn_angle,
    turn_rates_from_headings,
)
from .scenario import (
    Scenario,
    random_aois,
    random_scenario,
)

__all__ = [
    "ALL_METHODS",
    "AREA_SIZE",
    "BEYOND_PAPER_METHODS",
    "EXACT_ORDER_LIMIT",
    "METHODS",
    "METHOD_NAMES",
    "OBJECTIVES",
    "ORDERS",
    "PLAN_METHODS",
    "Camera",
    "Coverage",
    "CoverageOptions",
    "FlightTrajectory",
    "Footprint",
    "Parameters",
    "Plan",
    "Samples",
    "Scenario",
    "Segment",
    "Wind",
    "bank_angle",
    "best_order",
    "coverage",
    "coverage_by_role",
    "ellipse_disk_area",
    "entry_angle",
    "entry_distance",
    "flown_samples",
    "fly",
    "fly_and_score",
    "load_scenario",
    "loiter_circles",
    "loiter_coverage_fraction",
    "metrics",
    "order_length",
    "path_pieces",
    "plan",
    "plan_in_order",
    "random_aois",
    "random_scenario",
    "segment_records",
    "turn_angle",
    "turn_rates_from_headings",
]
