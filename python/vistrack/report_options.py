"""What a report folder holds beyond report.md and how its media look: the options every
planner's report takes (a scenario's ``report`` section, the commands' flags) and their defaults,
which the figures use too."""

from __future__ import annotations

from dataclasses import dataclass
from typing import Any

from .schema import apply_checks, boolean, fail, integer, number

__all__ = ["DEFAULT_DURATION_S", "DEFAULT_FRAMES", "DEFAULT_VIEW", "DEFAULT_VOLUMES", "ReportOptions", "report_options"]

DEFAULT_FRAMES = 60  # frames of trajectory.gif
DEFAULT_DURATION_S = 8.0  # seconds it lasts
DEFAULT_VOLUMES = 8  # VVs under the volume slider of report.html
DEFAULT_VIEW = (32.0, -58.0)  # volume3d.png: elevation, azimuth in degrees


@dataclass
class ReportOptions:
    """What the report folder holds beyond report.md: the interactive report.html, the
    trajectory.gif animation (frames, seconds) and the viewpoint of volume3d.png."""

    html: bool = True
    animation: bool = True
    frames: int = DEFAULT_FRAMES
    duration: float = DEFAULT_DURATION_S  # seconds the GIF lasts
    volumes: int = DEFAULT_VOLUMES  # VVs under the slider of report.html
    view: tuple[float, float] = DEFAULT_VIEW  # volume3d.png: elevation, azimuth in degrees

    MAX_FRAMES = 1000

    def validate(self) -> None:
        integer("report.frames", self.frames, 2, self.MAX_FRAMES)
        number("report.duration", self.duration, low=0.0, high=3600.0, low_open=True)
        integer("report.volumes", self.volumes, 1, 100)


def report_options(section: dict[str, Any]) -> ReportOptions:
    """The ``report`` section of a scenario, every value checked and named by its key."""

    def view(key: str, value: Any) -> tuple[float, float]:
        if not isinstance(value, list) or len(value) != 2:
            raise fail(key, value, "must be [elevation, azimuth] in degrees")
        return (number(f"{key}[0]", value[0], low=-90.0, high=90.0), number(f"{key}[1]", value[1]))

    return apply_checks(ReportOptions(), section, "report", {
        "html": boolean, "animation": boolean, "frames": lambda k, v: integer(k, v, 2, ReportOptions.MAX_FRAMES),
        "duration": lambda k, v: number(k, v, low=0.0, high=3600.0, low_open=True),
        "volumes": lambda k, v: integer(k, v, 1, 100), "view": view})
