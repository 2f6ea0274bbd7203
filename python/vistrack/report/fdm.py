"""The 6-DOF flights (``vistrack.fdm``) in a planner's report folder: metrics.json's ``fdm`` block
beside the kinematic keys, the figure of the 6-DOF flight beside the kinematic one and its table."""

from __future__ import annotations

from pathlib import Path
from typing import Any, Sequence

import numpy as np

from ..fdm import FdmTrajectory
from ..plotting.fdm import figure_fdm
from .document import Block, Heading, Picture, Table


def fdm_block(aircraft: str, trajectories: Sequence[FdmTrajectory], flights: list[dict[str, Any]]) -> dict[str, Any]:
    """metrics.json's ``fdm``: the aircraft, the largest altitude and airspeed errors over its flights, and
    ``flights`` mirroring the kinematic ``flights`` list."""
    return {"aircraft": aircraft,
            "altitude_error_max_m": max(t.altitude_error_max for t in trajectories),
            "airspeed_error_max_m_s": max(t.airspeed_error_max for t in trajectories),
            "real_time_factor": float(sum(t.t[-1] - t.t[0] for t in trajectories)
                                      / sum(t.seconds for t in trajectories)),
            "flights": flights}


def fdm_figure(out: Path, kinematic: tuple[Any, Any, Any, Any], kinematic_label: str, six: FdmTrajectory, title: str,
               reference: np.ndarray, reference_label: str) -> Picture:
    """fdm.png: the 6-DOF flight beside the kinematic one (t, x, y, bank), as a report picture."""
    k = (np.asarray(kinematic[0]), np.asarray(kinematic[1]), np.asarray(kinematic[2]), np.asarray(kinematic[3]))
    figure_fdm(k, kinematic_label, six, out / "fdm.png", title=title, reference=reference,
               reference_label=reference_label)
    return Picture("fdm.png", "6-DOF flight (JSBSim) beside the kinematic one",
                   f"The same guidance flown by vistrack's autopilot on {six.aircraft} in JSBSim, trimmed level at "
                   f"{six.speed:g} m/s and {six.altitude_command:g} m: ground tracks, altitude, airspeed and bank.")


def fdm_blocks(block: dict[str, Any], rows: list[list[str]], header: list[str]) -> list[Block]:
    """The report's 6-DOF section: a line on the aircraft and its errors, and the planner's score table."""
    return [Heading(f"6-DOF flights on {block['aircraft']} (JSBSim, vistrack's autopilot)"),
            f"Altitude within {block['altitude_error_max_m']:.2f} m and airspeed within "
            f"{block['airspeed_error_max_m_s']:.2f} m/s of the commands after trim; "
            f"{block['real_time_factor']:.0f} x real time.",
            Table(header, rows)]
