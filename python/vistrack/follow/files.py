"""Follow files: vehicle tracks ``t,x,y``, road paths, follow trajectories as CSV."""

from __future__ import annotations

from pathlib import Path
from typing import Any

import numpy as np

from ..io.tables import numeric_rows

__all__ = ["read_road_path", "read_vehicle_track", "write_follow_trajectory", "write_follow_updates"]


def read_vehicle_track(path: str | Path, key: str = "vehicle.track") -> tuple[np.ndarray, np.ndarray]:
    """A ground vehicle's track: one ``t,x,y`` per line (s, m; a header line allowed). Returns the
    times (n,) and positions (n, 2); GroundVehicle checks that the times increase and are finite."""
    rows = numeric_rows(path, key, (3,))
    return rows[:, 0].copy(), rows[:, 1:3].copy()


def read_road_path(path: str | Path, key: str = "road") -> np.ndarray:
    """A road polyline, one ``x,y`` or ``x,y,z`` per line (the data's POI paths): (n, 2)."""
    return numeric_rows(path, key, (2, 3))[:, :2].copy()


def write_follow_trajectory(result: Any, path: str | Path) -> Path:
    """A follow run as CSV, one sample per line, full precision: t, the UAV (x, y, psi, turn rate,
    bank), the vehicle, the offset point, the desired position, the waypoint flown to, the mode,
    the tracking error, the along-track lag, the camera's view (0/1) and, when evaluated, the
    line of sight (0/1). ``result``: a vistrack.follow.FollowResult."""
    run = result.run
    columns = {
        "t": np.asarray(run.t), "x": result.state[:, 0], "y": result.state[:, 1], "psi": result.state[:, 2],
        "turn_rate": np.asarray(run.turn_rate), "bank": np.asarray(run.bank),
        "vehicle_x": result.vehicle[:, 0], "vehicle_y": result.vehicle[:, 1],
        "offset_x": result.offset_point[:, 0], "offset_y": result.offset_point[:, 1],
        "desired_x": result.desired[:, 0], "desired_y": result.desired[:, 1],
        "target_x": np.asarray(run.target)[:, 0], "target_y": np.asarray(run.target)[:, 1],
        "tracking_error": np.asarray(run.tracking_error), "along_track_lag": np.asarray(run.along_track_lag),
        "in_view": result.in_view.astype(int),
    }
    if result.line_of_sight is not None:
        columns["line_of_sight"] = result.line_of_sight.astype(int)
    mode = result.mode
    names = list(columns)
    lines = [",".join([*names[:16], "mode", *names[16:]])]
    values = list(columns.values())
    for i in range(len(mode)):
        cells = [repr(float(v[i])) for v in values[:16]] + [str(mode[i])] + [str(int(v[i])) for v in values[16:]]
        lines.append(",".join(cells))
    file = Path(path)
    file.write_text("\n".join(lines) + "\n", encoding="utf-8")
    return file


UPDATE_COLUMNS = ("t", "mode", "speed_ratio", "period_s", "period_distance_m", "amplitude_m", "phase", "capturing",
                  "offset_x", "offset_y", "waypoint_x", "waypoint_y")


def write_follow_updates(result: Any, path: str | Path) -> Path:
    """The planner's updates (1 Hz) as CSV, one per line: t, the mode, the speed ratio sigma and
    the sinusoid's effective period T (s), period distance D and amplitude A (m; blank outside the
    sinusoid: T as flown, after the curvature floor), its phase, whether the update held a pattern's
    entry point, the offset point and the waypoint issued. ``result``: a FollowResult."""
    lines = [",".join(UPDATE_COLUMNS)]
    for tick in result.run.ticks:
        sinusoid = tick.mode == "sinusoid"
        shape = [repr(float(v)) if sinusoid else "" for v in (tick.period, tick.period_distance, tick.amplitude,
                                                              tick.phase)]
        lines.append(",".join([repr(float(tick.t)), tick.mode, repr(float(tick.speed_ratio)), *shape,
                               str(int(tick.capturing)), *(repr(float(v)) for v in tick.offset_point),
                               *(repr(float(v)) for v in tick.waypoint)]))
    file = Path(path)
    file.write_text("\n".join(lines) + "\n", encoding="utf-8")
    return file
