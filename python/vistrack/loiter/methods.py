"""``vt.loiter.Plan.to_mission``: the compiled class gains its mission export here, in Python (the
compiled module imports no Python). The annotations are objects, not text, so that the generated
stubs of ``vistrack._core`` name the types (scripts/stubs.sh)."""

from typing import Optional, Sequence, Union

from .._core.loiter import Plan
from ..georeference import Georeference
from ..mission.model import Mission
from .to_mission import loiter_plan_mission


def to_mission(self: Plan, georeference: Union[Georeference, Sequence[float]], altitude: float, *,
               speed: Optional[float] = None, max_step_deg: float = 30.0, acceptance_radius: Optional[float] = None,
               return_to_launch: bool = False, firmware: str = "ardupilot", altitude_mode: str = "relative") -> Mission:
    return loiter_plan_mission(self, georeference, altitude, speed=speed, max_step_deg=max_step_deg,
                               acceptance_radius=acceptance_radius, return_to_launch=return_to_launch,
                               firmware=firmware, altitude_mode=altitude_mode)


to_mission.__doc__ = loiter_plan_mission.__doc__
Plan.to_mission = to_mission  # type: ignore[method-assign]
