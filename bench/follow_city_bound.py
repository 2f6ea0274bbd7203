"""How well could any follower keep the vehicle in sight on a Charlotte road run? An estimate by
dynamic programming with the vehicle's whole future known, beside the city orbit's and the baseline's
numbers (docs/following.md).

The UAV is the runs' roll model (vistrack.flight.RollModel: airspeed v, bank towards its command with
the roll time constant and rate limit, turning at g tan(bank) / v) in the file's wind. Each second it
commands one of five banks (0, +-half and +-the full atan(v^2 / (g r_min))). Its state is its position
relative to the vehicle (a 15 m grid, +-450 m), its heading (10-degree grid) and its bank (the five
levels). A second scores when the vehicle is in line of sight (one Embree ray per grid point from the
flight altitude to the vehicle 0.5 m above the surface, as the runs are scored) and in the file's camera
at that bank. Backward induction, the value interpolated linearly between grid points, gives the best
fraction of seconds scored; then the aircraft is flown from the runs' start (exact roll model in 0.02 s
steps, continuous state), each second's command the one whose next state has the most value, and scored
every 0.1 s with a ray and the library's camera. That flight exists for this aircraft; it knows the
future, which a follower does not: read its fraction as what foresight could reach, and a goal far
below it as not limited by the aircraft, the camera or the city.

    VISTRACK_BUILD_DIR=build/dev python3 bench/follow_city_bound.py [FILE ...]

Default files: examples/follow_{straight,wind,stop,truck}_city.yaml; 1-5 minutes per file on one core.
Charlotte geometry (c) OpenStreetMap contributors (ODbL).
"""

from __future__ import annotations

import argparse
import math
import os
import sys
import time
from dataclasses import dataclass
from pathlib import Path
from typing import Any

import numpy as np

REPO = Path(__file__).resolve().parents[1]
if os.environ.get("VISTRACK_BUILD_DIR"):
    sys.path.insert(0, str(REPO / "tests" / "python"))
    import conftest  # noqa: F401  (imports vistrack from python/ with the build tree's _core)

from vistrack import VisibilityScene
from vistrack.flight import RollModel
from vistrack.follow import DownwardCamera, FollowScenario
from vistrack.follow.simulation import camera_sees

FILES = [REPO / "examples" / f"follow_{name}_city.yaml" for name in ("straight", "wind", "stop", "truck")]
SPACING, HALF = 15.0, 450.0  # m: the relative-position grid
HEADING_STEP = math.radians(10.0)
VEHICLE_HEIGHT = 0.5
DT = 0.02  # s: the roll model's integration step (the runs' flight step)


def camera_table(camera: DownwardCamera, altitude: float, rel: np.ndarray, heading: np.ndarray,
                 bank: float) -> np.ndarray:
    """Whether the camera sees the vehicle from each relative position (UAV - vehicle, (m, 2)) at
    each heading (h,), banked ``bank``: (h, m), camera_sees vectorised (checked against it)."""
    left = np.stack([-np.sin(heading), np.cos(heading)], axis=1)
    r_left = -(left @ rel.T)  # the vehicle from the UAV, along the body's left axis
    distance = np.sqrt(np.sum(rel ** 2, axis=1) + altitude ** 2)[None, :]
    half = 0.5 * camera.fov
    if camera.mount == "pan_tilt":
        down = math.cos(bank) * altitude - math.sin(bank) * r_left  # r . (the body's down axis)
        return np.arccos(np.clip(down / distance, -1.0, 1.0)) <= camera.max_gimbal + half
    if camera.mount == "fixed":
        roll = np.full_like(r_left, bank)
    else:
        roll = bank - np.clip(bank + np.arctan2(r_left, altitude), -camera.max_gimbal, camera.max_gimbal)
    return np.cos(roll) * altitude - np.sin(roll) * r_left >= math.cos(half) * distance


def fly_second(model: RollModel, speed: float, wind: np.ndarray, position: np.ndarray, heading: float, bank: float,
               command: float) -> tuple[np.ndarray, float, float, list[tuple[np.ndarray, float, float]]]:
    """The roll model's second with the bank command held (0.02 s steps): the final position, heading and
    bank, and the state every 0.1 s from the start (for scoring)."""
    position, trace = np.array(position, dtype=float), []
    for sub in range(round(1.0 / DT)):
        if sub % 5 == 0:
            trace.append((position.copy(), heading, bank))
        position += (speed * np.array([math.cos(heading), math.sin(heading)]) + wind) * DT
        heading += model.turn_rate(bank) * DT
        bank = model.step(bank, command, DT)
    return position, heading, bank, trace


def one_second(model: RollModel, speed: float, bank: float, command: float) -> tuple[np.ndarray, float, float]:
    """fly_second from heading 0 in still air: displacement (2,), heading change, final bank."""
    position, heading, bank, _ = fly_second(model, speed, np.zeros(2), np.zeros(2), 0.0, bank, command)
    return position, heading, bank


def score_trace(scene: VisibilityScene, camera: DownwardCamera, uav: Any, vehicle: Any, t: float,
                trace: list[tuple[np.ndarray, float, float]], altitude: float) -> int:
    """How many of the trace's 0.1 s states see the vehicle: a ray from the flight altitude to the vehicle
    0.5 m above the surface, and camera_sees at the state's heading and bank."""
    target = np.asarray(vehicle.sample(t + 0.1 * np.arange(len(trace))))
    ground = np.asarray(scene.poi_on_surface(np.column_stack([target, np.full(len(trace), VEHICLE_HEIGHT)])))
    sky = np.array([[p[0], p[1], altitude] for p, _, _ in trace])
    sight = np.asarray(scene.line_of_sight(sky, ground), dtype=bool)
    return sum(bool(s) and bool(camera_sees(camera, np.array([p[0], p[1], uav.altitude]), h, b,
                                            np.array([g[0], g[1], 0.0])))
               for (p, h, b), s, g in zip(trace, sight, target))


def stencil(shape: tuple[int, int], heading: np.ndarray, points: np.ndarray,
            n_side: int) -> tuple[np.ndarray, np.ndarray]:
    """Where a value (h, m) on the grid is read at fractional heading indices ``heading`` (p,) and
    positions (p, 2): flat indices and weights (8, p), linear in heading, bilinear in position; weight 0
    outside the grid."""
    u = (points[:, 0] + HALF) / SPACING
    w = (points[:, 1] + HALF) / SPACING
    inside = (u >= 0) & (u <= n_side - 1) & (w >= 0) & (w <= n_side - 1)
    u, w = np.clip(u, 0, n_side - 1 - 1e-9), np.clip(w, 0, n_side - 1 - 1e-9)
    i, j = np.floor(u).astype(int), np.floor(w).astype(int)
    fu, fw = u - i, w - j
    h0 = np.floor(heading).astype(int)
    fh = heading - h0
    cell = i * n_side + j
    index, weight = [], []
    for dh, wh in ((0, 1.0 - fh), (1, fh)):
        row = ((h0 + dh) % shape[0]) * shape[1]
        for offset, wc in ((0, (1 - fu) * (1 - fw)), (n_side, fu * (1 - fw)), (1, (1 - fu) * fw),
                           (n_side + 1, fu * fw)):
            index.append(row + cell + offset)
            weight.append(np.where(inside, wh * wc, 0.0))
    return np.array(index), np.array(weight)


def interpolate(value: np.ndarray, heading: np.ndarray, points: np.ndarray, n_side: int) -> np.ndarray:
    """value (h, m) on the grid at fractional heading indices ``heading`` (p,) and positions (p, 2)
    (the stencil's reading), 0 outside the grid."""
    index, weight = stencil(value.shape, heading, points, n_side)
    return np.sum(value.reshape(-1)[index] * weight, axis=0)


def transitions(moves: dict[tuple[int, int], Any], rel: np.ndarray, headings: np.ndarray, drift: np.ndarray,
                n_side: int) -> list[tuple[int, int, np.ndarray, np.ndarray]]:
    """For each (bank, command): the bank, the bank after, and the stencil of the next state of every
    (heading, grid point): the command's second (``moves``: displacement, turn, final bank level) plus
    ``drift`` (the wind minus the vehicle's way), relative to the vehicle then."""
    cos_h, sin_h = np.cos(headings)[:, None], np.sin(headings)[:, None]
    out = []
    for (b0, _command), ((dx, dy), turn, b1) in moves.items():
        tx = rel[None, :, 0] + cos_h * dx - sin_h * dy + drift[0]
        ty = rel[None, :, 1] + sin_h * dx + cos_h * dy + drift[1]
        turned = np.broadcast_to((np.arange(len(headings)) + turn / HEADING_STEP)[:, None], tx.shape)
        index, weight = stencil((len(headings), len(rel)), turned.ravel(), np.column_stack([tx.ravel(), ty.ravel()]),
                                n_side)
        out.append((b0, b1, index, weight))
    return out


def add_best_next(now: np.ndarray, later: np.ndarray, steps: list[tuple[int, int, np.ndarray, np.ndarray]]) -> None:
    """One step of backward induction: now[bank] += the most value of ``later`` over the commands
    (``steps``: transitions())."""
    best = np.zeros_like(now)  # values are counts, >= 0
    for b0, b1, index, weight in steps:
        after = np.sum(later[b1].reshape(-1)[index] * weight, axis=0)
        np.maximum(best[b0], after.reshape(best.shape[1:]), out=best[b0])
    now += best


def state_value(value: np.ndarray, banks: np.ndarray, bank: float, heading: float, rel: np.ndarray,
                n_side: int) -> float:
    """value (bank level, heading, grid) at a continuous bank, heading and relative position (2,)."""
    level = float(np.interp(bank, banks, np.arange(len(banks))))
    lo = int(min(math.floor(level), len(banks) - 2))
    out = 0.0
    for index, weight in ((lo, 1.0 - (level - lo)), (lo + 1, level - lo)):
        out += weight * float(interpolate(value[index], np.array([(heading % (2 * math.pi)) / HEADING_STEP]),
                                          rel[None, :], n_side)[0])
    return out


@dataclass
class Programme:
    """The dynamic programme's pieces for one scenario: the bank levels, the relative grid, the camera
    table, the roll model's second for each (bank, command) and the flight altitude (world z)."""

    model: RollModel
    banks: np.ndarray
    rel: np.ndarray
    n_side: int
    headings: np.ndarray
    cams: np.ndarray  # (bank, heading, grid point)
    moves: dict[tuple[int, int], Any]
    altitude: float

    @classmethod
    def of(cls, scenario: FollowScenario, scene: VisibilityScene) -> "Programme":
        uav, camera = scenario.uav, scenario.camera
        model = RollModel(uav)
        full = math.atan(uav.speed ** 2 / (9.80665 * uav.min_turn_radius))
        banks = np.array([-1.0, -0.5, 0.0, 0.5, 1.0]) * full
        axis = np.arange(-HALF, HALF + 1e-9, SPACING)
        gx, gy = np.meshgrid(axis, axis, indexing="ij")
        rel = np.column_stack([gx.ravel(), gy.ravel()])
        headings = np.arange(round(2.0 * math.pi / HEADING_STEP)) * HEADING_STEP
        cams = np.stack([camera_table(camera, uav.altitude, rel, headings, b) for b in banks])
        rng = np.random.default_rng(1)
        for _ in range(300):  # the vectorised camera against the library's
            b, h, m = rng.integers(len(banks)), rng.integers(len(headings)), rng.integers(len(rel))
            if bool(cams[b, h, m]) != bool(camera_sees(camera, np.array([rel[m, 0], rel[m, 1], uav.altitude]),
                                                       headings[h], banks[b], np.zeros(3))):
                raise RuntimeError("the camera table disagrees with camera_sees")
        # Each (bank, command): the second's displacement (rotated by the heading later), turn and final bank.
        moves = {}
        for b0, bank in enumerate(banks):
            for c, command in enumerate(banks):
                shift, turn, final = one_second(model, uav.speed, bank, command)
                moves[b0, c] = (shift, turn, int(np.argmin(np.abs(banks - final))))
        return cls(model, banks, rel, len(axis), headings, cams, moves, scene.ground_level + uav.altitude)

    def scored(self, scene: VisibilityScene, at: np.ndarray) -> np.ndarray:
        """(bank, heading, grid point): 1 where a ray from the grid point reaches the vehicle at ``at``
        (0.5 m above the surface) and the camera sees it."""
        ground = np.asarray(scene.poi_on_surface(np.array([[at[0], at[1], VEHICLE_HEIGHT]])))[0]
        sky = np.column_stack([self.rel + at, np.full(len(self.rel), self.altitude)])
        sight = np.asarray(scene.line_of_sight(sky, np.repeat(ground[None, :], len(self.rel), axis=0)), dtype=bool)
        return (self.cams & sight[None, None, :]).astype(float)


def estimate(file: Path) -> dict[str, Any]:
    scenario = FollowScenario.load(file)
    env = scenario.city.load(scenario.origin)  # type: ignore[union-attr]
    scene = VisibilityScene(env)
    vehicle = scenario.city_vehicle(env)
    wind = np.array([scenario.wind.east, scenario.wind.north])
    ticks = np.arange(math.floor(vehicle.end_time - vehicle.start_time) + 1) + vehicle.start_time
    where = np.asarray(vehicle.sample(ticks))
    steps = len(ticks)
    pro = Programme.of(scenario, scene)
    values: list[np.ndarray] = [np.zeros(0, dtype=np.float32)] * steps
    started = time.perf_counter()
    for k in range(steps - 1, -1, -1):
        now = pro.scored(scene, where[k])
        if k + 1 < steps:
            drift = wind - (where[k + 1] - where[k])
            add_best_next(now, values[k + 1], transitions(pro.moves, pro.rel, pro.headings, drift, pro.n_side))
        values[k] = now.astype(np.float32)
    seconds = time.perf_counter() - started
    return {"value": float(values[0].max()) / steps, "seconds": seconds,
            **fly(values, scene, scenario, vehicle, pro, where, ticks, wind)}


def fly(values: list[np.ndarray], scene: VisibilityScene, scenario: FollowScenario, vehicle: Any, pro: Programme,
        where: np.ndarray, ticks: np.ndarray, wind: np.ndarray) -> dict[str, Any]:
    """From the runs' start (200 m ahead of the vehicle along its heading, level), each second the command
    whose next state has the most value; scored every 0.1 s (a ray and camera_sees)."""
    uav, camera = scenario.uav, scenario.camera
    heading0 = float(vehicle.heading(ticks[0]))
    position = where[0] + 200.0 * np.array([math.cos(heading0), math.sin(heading0)])
    heading, bank = heading0, 0.0
    seen, samples, commands = 0, 0, []
    for k in range(len(ticks)):
        best = (-1.0, 0, position, heading, bank, [])
        for c, command in enumerate(pro.banks):
            p, h, b, trace = fly_second(pro.model, uav.speed, wind, position, heading, bank, command)
            score = (state_value(values[k + 1], pro.banks, b, h, p - where[k + 1], pro.n_side)
                     if k + 1 < len(ticks) else 0.0)
            if score > best[0]:
                best = (score, c, p, h, b, trace)
        _, c, position, heading, bank, trace = best
        commands.append(c)
        seen += score_trace(scene, camera, uav, vehicle, ticks[k], trace, pro.altitude)
        samples += len(trace)
        if ticks[k] >= vehicle.end_time - 1e-9:
            break
    reversals = int(np.sum(np.diff(np.sign(np.array(commands) - 2)[np.array(commands) != 2]) != 0))
    return {"flown": seen / max(samples, 1), "commands": commands, "reversals": reversals}


def main() -> int:
    parser = argparse.ArgumentParser(description=__doc__, formatter_class=argparse.RawDescriptionHelpFormatter)
    parser.add_argument("files", nargs="*", type=Path, default=FILES)
    args = parser.parse_args()
    print("| file | value (best start, 1 s steps) | flown from the runs' start (0.1 s samples) | bank reversals |")
    print("|---|---|---|---|")
    for file in args.files:
        scenario = FollowScenario.load(file)
        if not scenario.city_available():
            print(f"| {file.name} | skipped: its city data is missing | | |")
            continue
        out = estimate(file)
        print(f"| {file.name} | {100 * out['value']:.1f} % | {100 * out['flown']:.1f} % | {out['reversals']} |"
              f"  ({out['seconds']:.0f} s)", flush=True)
    return 0


if __name__ == "__main__":
    sys.exit(main())
