"""A loiter scenario: AOI centres, start and end, vehicle, camera and coverage settings; seeded
random scenarios (section 4.1's area and vehicle)."""

from __future__ import annotations

from dataclasses import dataclass, field

import numpy as np

from .._core import Uav, VistrackError
from ..georeference import Georeference
from ..scenario_blocks import DEFAULT_DYNAMICS, City
from .planning import AREA_SIZE, Camera, Coverage, CoverageOptions, Parameters, Plan, Point, coverage, plan

__all__ = ["Scenario", "random_aois", "random_scenario"]

_PLAN, _COVERAGE, _VEHICLE = Parameters(), CoverageOptions(), Uav()  # the defaults: the bound C++ structs'


@dataclass
class Scenario:
    """A loiter mission: AOI centres, start and end, vehicle, camera and coverage settings.

    ``paper`` holds the paper's Table 1 numbers for the scenario of the same size, when the file
    gives them (``{"fly_through": {"flight_time_min": ..., "coverage_m2": ...}, ...}``).
    """

    aois: np.ndarray
    name: str = "scenario"
    start: tuple[float, float] = (0.0, 0.0)
    end: tuple[float, float] = (0.0, 0.0)
    turn_radius: float = _PLAN.turn_radius
    speed: float = _PLAN.speed
    aoi_radius: float = _PLAN.aoi_radius
    turns: int = _PLAN.turns
    camera: Camera = field(default_factory=Camera)
    threshold: float = _COVERAGE.threshold
    dt: float = _COVERAGE.dt
    paper: dict[str, dict[str, float]] = field(default_factory=dict)
    origin: Georeference | None = None  # where local (0, 0) lies on the Earth (mission export)
    dynamics: str = DEFAULT_DYNAMICS    # the flown vehicle's model (uav.dynamics)
    roll_time_constant: float = _VEHICLE.roll_time_constant   # s, the roll model's
    max_roll_rate_deg_s: float = _VEHICLE.max_roll_rate_deg_s
    aircraft: str | None = None  # uav.dynamics: jsbsim: the wind flights also flown on this 6-DOF aircraft
    city: City | None = None  # beyond the paper: loiter circles inside visibility polygons (loiter.city)
    off_centre: bool = True  # with a city: an AOI without a circle about it may loiter on one off it

    def uav(self) -> Uav:
        """The vehicle that flies the plans: the scenario's speed, turn radius, camera altitude and model."""
        return Uav(speed=self.speed, min_turn_radius=self.turn_radius, altitude=self.camera.altitude,
                   dynamics=self.dynamics, roll_time_constant=self.roll_time_constant,
                   max_roll_rate_deg_s=self.max_roll_rate_deg_s)

    def plan(self, method: str, order: str = "given", objective: str = "time") -> Plan:
        return plan(self.aois, method, self.start, self.end, self.turn_radius, self.speed, self.aoi_radius,
                    self.turns, order, objective=objective, camera=self.camera, threshold=self.threshold, dt=self.dt)

    def coverage(self, plan_or_samples: Plan | np.ndarray) -> Coverage:
        return coverage(plan_or_samples, self.aois, self.camera, self.threshold, self.dt, speed=self.speed,
                        aoi_radius=self.aoi_radius)


def random_aois(count: int, rng: np.random.Generator, size: float = AREA_SIZE, separation: float = 160.0,
                clearance: float = 80.0, start: Point = (0.0, 0.0), end: Point = (0.0, 0.0),
                attempts: int = 100000) -> np.ndarray:
    """``count`` AOI centres uniform in [0, size]^2, at least ``separation`` apart and ``clearance``
    from the start and end (defaults: LDLPP can fly every order, 2 D_Entry = 159.3 m and
    D_Entry = 79.7 m at R = r = 46 m)."""
    if count < 1:
        raise VistrackError(f"count = {count}: at least one AOI")
    anchors = [np.asarray(start, dtype=float), np.asarray(end, dtype=float)]
    chosen: list[np.ndarray] = []
    for _ in range(attempts):
        c = rng.uniform(0.0, size, 2)
        if all(np.hypot(*(c - a)) >= clearance for a in anchors) and all(
                np.hypot(*(c - o)) >= separation for o in chosen):
            chosen.append(c)
            if len(chosen) == count:
                return np.array(chosen)
    raise VistrackError(f"count = {count}: could not place that many AOIs {separation} m apart in "
                        f"{size} x {size} m")


def random_scenario(count: int, seed: int, **settings: object) -> Scenario:
    """A seeded random scenario of ``count`` AOIs (section 4.1's area and vehicle)."""
    rng = np.random.default_rng(seed)
    return Scenario(aois=random_aois(count, rng), name=f"random-{count}-{seed}", **settings)  # type: ignore[arg-type]
