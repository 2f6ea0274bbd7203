"""The 6-DOF flight beside the kinematic one: ground track, altitude, airspeed and bank against time
(any product's report; ``vistrack.fdm``)."""

from __future__ import annotations

from pathlib import Path
from typing import Any, Optional

import numpy as np

from ..fdm import FdmTrajectory
from .common import pyplot, save_figure


def figure_fdm(kinematic: tuple[np.ndarray, np.ndarray, np.ndarray, np.ndarray], kinematic_label: str,
               six_dof: FdmTrajectory, path: str | Path, title: str = "",
               reference: Optional[np.ndarray] = None, reference_label: str = "") -> Path:
    """Four panels: the two ground tracks (with an optional reference polyline (n, 2): the POI path, the
    route), the 6-DOF altitude and airspeed against their commands, and both banks.
    ``kinematic`` = (t, x, y, bank) of the kinematic flight."""
    plt = pyplot()
    fig, axes = plt.subplots(2, 2, figsize=(12, 9), constrained_layout=True)
    t, x, y, bank = (np.asarray(a, dtype=float) for a in kinematic)
    ax = axes[0, 0]
    if reference is not None and len(reference):
        ref = np.asarray(reference)
        ax.plot(ref[:, 0], ref[:, 1], color="0.4", ls="--", lw=1.0, label=reference_label or "reference")
    ax.plot(x, y, color="tab:blue", lw=1.2, label=kinematic_label)
    ax.plot(six_dof.x, six_dof.y, color="tab:red", lw=1.0, label=f"6-DOF ({six_dof.aircraft}, JSBSim)")
    ax.set_aspect("equal", adjustable="datalim")
    ax.set_xlabel("x (m)")
    ax.set_ylabel("y (m)")
    ax.set_title("ground track")
    ax.legend(loc="best", fontsize=8)

    _held(axes[0, 1], six_dof.t, six_dof.altitude, six_dof.altitude_command, "command", "altitude (m)",
          f"altitude: largest error {six_dof.altitude_error_max:.2f} m")
    _held(axes[1, 0], six_dof.t, six_dof.airspeed, six_dof.speed, "command (the kinematic vehicle's)",
          "true airspeed (m/s)", f"airspeed: largest error {six_dof.airspeed_error_max:.2f} m/s")

    ax = axes[1, 1]
    ax.plot(t, np.degrees(bank), color="tab:blue", lw=1.0, label=kinematic_label)
    ax.plot(six_dof.t, np.degrees(six_dof.bank), color="tab:red", lw=1.0, label="6-DOF")
    ax.plot(six_dof.t, np.degrees(six_dof.bank_command), color="tab:red", ls=":", lw=0.8, label="6-DOF command")
    ax.set_xlabel("t (s)")
    ax.set_ylabel("bank (deg, + turning left)")
    ax.set_title("bank")
    ax.legend(loc="best", fontsize=8)
    limit = max(5.0, float(np.max(np.abs(np.degrees(six_dof.bank)))) * 1.1)
    ax.set_ylim(-min(limit, 90.0), min(limit, 90.0))
    if title:
        fig.suptitle(title)
    return save_figure(fig, path)


def _held(ax: Any, t: np.ndarray, value: np.ndarray, command: float, command_label: str, ylabel: str,
          title: str) -> None:
    """One panel: a quantity the autopilot holds, against its command."""
    ax.plot(t, value, color="tab:red", lw=1.0, label="6-DOF")
    ax.axhline(command, color="k", ls="--", lw=0.8, label=command_label)
    ax.set_xlabel("t (s)")
    ax.set_ylabel(ylabel)
    ax.set_title(title)
    ax.legend(loc="best", fontsize=8)
