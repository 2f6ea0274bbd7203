"""Camera coverage over a city: the paper's rule (an AOI is covered at a time step when at least
``threshold`` of its disk is in the footprint), counting only the disk points the camera sees
through the buildings (Embree occlusion rays from the aircraft).

The footprint and the gimbal's pointing are the paper's (:func:`vistrack.loiter.coverage`: the
same ellipse ``Camera.footprint`` at the tilt that coverage chose); each AOI disk is sampled by
``rays`` points on a sunflower spiral, each on the surface there (the street, or a roof: the AOI is
what one sees of that disk from above), and a point counts when it is inside the footprint and the
segment from the aircraft to it is clear.
"""

from __future__ import annotations

import math
from dataclasses import dataclass

import numpy as np

from .._core import PoiMotion, VisibilityScene
from .planning import Camera, Coverage, Plan, coverage

__all__ = ["CityCoverage", "city_coverage", "disk_points"]


@dataclass
class CityCoverage:
    """Per time step and AOI the share of the disk in the footprint (``in_footprint``) and in it
    and seen (``seen``); covered seconds with and without line of sight."""

    dt: float
    threshold: float
    in_footprint: np.ndarray  # (steps, AOIs)
    seen: np.ndarray  # (steps, AOIs)
    paper: Coverage  # the open-ground coverage of the same plan and camera

    @property
    def time_per_aoi(self) -> np.ndarray:
        """Covered seconds per AOI, counting only what the camera sees."""
        return np.count_nonzero(self.seen >= self.threshold, axis=0) * self.dt

    @property
    def time(self) -> float:
        return float(self.time_per_aoi.sum())

    @property
    def open_time(self) -> float:
        """Covered seconds as if the buildings hid nothing (the same sampled disks)."""
        return float(np.count_nonzero(self.in_footprint >= self.threshold) * self.dt)

    def record(self) -> dict[str, object]:
        return {"covered_s": self.time, "covered_per_aoi_s": [float(t) for t in self.time_per_aoi],
                "covered_ignoring_buildings_s": self.open_time, "paper_covered_s": float(self.paper.time)}


def disk_points(center: np.ndarray, radius: float, count: int) -> np.ndarray:
    """``count`` points spread evenly over the disk (a sunflower spiral), (count, 2)."""
    k = np.arange(count) + 0.5
    r = radius * np.sqrt(k / count)
    theta = k * math.pi * (3.0 - math.sqrt(5.0))
    return np.asarray(center)[None, :2] + np.column_stack([r * np.cos(theta), r * np.sin(theta)])


def city_coverage(p: Plan, scene: VisibilityScene, camera: Camera, altitude: float, threshold: float, dt: float,
                  rays: int = 48, height: float = PoiMotion().height,
                  targets: np.ndarray | None = None) -> CityCoverage:
    """Coverage of the AOIs ``targets`` (n, 2; default the plan's circle centres) as disks of the
    plan's loiter radius, their points ``height`` above the surface, by the camera at world z =
    ``altitude``, every ``dt`` s, with line of sight through ``scene``."""
    aois = np.asarray(p.aois if targets is None else targets, dtype=float)
    paper = coverage(p, aois, camera=camera, threshold=threshold, dt=dt)
    poses = np.asarray(p.sample_states(dt, False).poses)
    tilt = np.asarray(paper.tilt)
    disks = np.stack([disk_points(c, p.aoi_radius, rays) for c in aois])  # (AOIs, rays, 2)
    flat = disks.reshape(-1, 2)
    heights = np.asarray(scene.poi_on_surface(np.column_stack([flat, np.full(len(flat), height)])))[:, 2]
    inside = np.zeros((len(poses), flat.shape[0]), dtype=bool)
    for k, pose in enumerate(poses):
        fp = camera.footprint(tuple(pose), float(tilt[k]))
        along = np.asarray(fp.along)
        d = flat - np.asarray(fp.center)
        a = d @ along
        b = d @ np.array([-along[1], along[0]])
        inside[k] = (a / fp.semi_along) ** 2 + (b / fp.semi_across) ** 2 <= 1.0
    steps, points = np.nonzero(inside)
    uav = np.column_stack([poses[steps, :2], np.full(steps.size, altitude)])
    targets = np.column_stack([flat[points], heights[points]])
    clear = np.asarray(scene.line_of_sight(uav, targets), dtype=bool) if steps.size else np.zeros(0, bool)
    seen = np.zeros_like(inside)
    seen[steps[clear], points[clear]] = True
    shape = (len(poses), len(aois), rays)
    return CityCoverage(dt, threshold, inside.reshape(shape).mean(axis=2), seen.reshape(shape).mean(axis=2), paper)
