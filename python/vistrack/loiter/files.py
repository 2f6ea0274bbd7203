"""Loiter files: the scenario YAML (examples/loiter_*.yaml) and a plan sampled as CSV."""

from __future__ import annotations

from pathlib import Path
from typing import Any, Mapping

import numpy as np

from .. import schema
from .._core import Uav
from ..io.documents import read_yaml_mapping
from ..scenario_blocks import (
    Rename,
    camera_block,
    city_block,
    georeference_block,
    origin_to_georeference,
    uav_block,
    upgrade,
)
from .planning import Camera, Coverage, CoverageOptions, Parameters, Plan, segment_roles
from .scenario import Scenario

__all__ = ["RENAMES", "load_scenario", "read_loiter_scenario", "vehicle_and_camera", "write_loiter_samples_csv"]

# Spellings from before the one scenario schema, still read.
RENAMES = (Rename("origin", "georeference", origin_to_georeference), Rename("turn_radius", "uav.min_turn_radius"),
           Rename("speed", "uav.speed"), Rename("camera.altitude", "uav.altitude"),
           Rename("camera.levelled", "camera.mount",
                  lambda value: "levelled" if schema.boolean("camera.levelled", value) else "roll"))


def read_loiter_scenario(path: str | Path) -> Scenario:
    """A loiter scenario file (examples/loiter_*.yaml); every bad value names its key."""
    data = upgrade(read_yaml_mapping(path, "scenario"), RENAMES)
    allowed = {"name", "aois", "start", "end", "uav", "aoi_radius", "turns", "camera", "threshold", "dt", "paper",
               "georeference", "city", "off_centre"}
    schema.reject_unknown(data, allowed)

    raw_aois = data.get("aois")
    if not isinstance(raw_aois, list) or not raw_aois:
        raise schema.fail("aois", raw_aois, "must be a non-empty list of [x, y] AOI centres")
    aois = np.array([schema.pair(f"aois[{i}]", a) for i, a in enumerate(raw_aois)], dtype=float)
    defaults, coverage_defaults = Parameters(), CoverageOptions()
    uav, camera = vehicle_and_camera(data)
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
        name=schema.output_name("name", data["name"]) if "name" in data else Path(path).stem,
        start=schema.pair("start", data.get("start", [0.0, 0.0])),
        end=schema.pair("end", data.get("end", [0.0, 0.0])),
        turn_radius=uav.min_turn_radius,
        speed=uav.speed,
        aoi_radius=schema.positive("aoi_radius", data.get("aoi_radius", defaults.aoi_radius)),
        turns=schema.integer("turns", data.get("turns", defaults.turns), 1, 1000),
        camera=camera,
        threshold=schema.number("threshold", data.get("threshold", coverage_defaults.threshold), low=0.0, high=1.0,
                                low_open=True),
        dt=schema.positive("dt", data.get("dt", coverage_defaults.dt)),
        paper=paper_numbers,
        origin=georeference_block(data),
        dynamics=str(uav.dynamics),
        roll_time_constant=uav.roll_time_constant,
        max_roll_rate_deg_s=uav.max_roll_rate_deg_s,
        city=city_block(data, Path(path).parent),
        off_centre=schema.boolean("off_centre", data.get("off_centre", True)),
    )
    # The planner's own checks (overlapping circles, R < r, start inside a circle) name the key.
    scenario.plan("tlpp")
    return scenario


def vehicle_and_camera(data: Mapping[str, Any]) -> tuple[Uav, Camera]:
    """The ``uav`` and ``camera`` blocks of a loiter file or sweep base, over section 4.1's defaults
    (the bound ``Parameters`` and ``Camera``); the camera's height above the AOIs' ground plane is
    the flight altitude."""
    defaults, camera_defaults = Parameters(), Camera()
    uav = uav_block(data, Uav(speed=defaults.speed, min_turn_radius=defaults.turn_radius,
                              altitude=camera_defaults.altitude)).uav
    mount = camera_block(data, camera_defaults.fov_deg, camera_defaults.max_gimbal_deg)
    return uav, Camera(mount.fov_deg, mount.max_gimbal_deg, uav.altitude, mount.mount == "levelled")


def write_loiter_samples_csv(path: str | Path, plan: Plan, coverage: Coverage, dt: float,
                             threshold: float = CoverageOptions().threshold) -> Path:
    """The plan sampled every dt (as the coverage was): t, x, y, psi, turn rate, segment role, the AOI
    most in view, the gimbal angle and the AOIs covered at that step."""
    samples = plan.sample_states(dt, False)
    roles = segment_roles(plan)[np.asarray(samples.segment)]
    # Each bound property is a new array: read each once, not once per row.
    t, poses, turn_rate = np.asarray(samples.t), np.asarray(samples.poses), np.asarray(samples.turn_rate)
    pointed, gimbal = np.asarray(coverage.pointed), np.asarray(coverage.gimbal)
    covered = [";".join(str(i) for i in np.flatnonzero(row >= threshold)) for row in coverage.fraction]
    file = Path(path)
    file.parent.mkdir(parents=True, exist_ok=True)
    with open(file, "w", encoding="utf-8") as out:
        out.write("t,x,y,psi,turn_rate,role,pointed_aoi,gimbal_rad,covered_aois\n")
        for k in range(poses.shape[0]):
            x, y, psi = poses[k]
            out.write(f"{t[k]:.6f},{x:.6f},{y:.6f},{psi:.9f},{turn_rate[k]:.9f},{roles[k]},"
                      f"{pointed[k]},{gimbal[k]:.6f},{covered[k]}\n")
    return file


def load_scenario(path: str | Path) -> Scenario:
    """Read a loiter scenario YAML file (see examples/loiter_*.yaml)."""
    return read_loiter_scenario(Path(path))

