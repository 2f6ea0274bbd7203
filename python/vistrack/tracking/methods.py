"""``OrbitPlan.to_mission``: the compiled class gains its mission export here, in Python (the compiled
module imports no Python). The annotations are objects, not text, so that the generated stubs of
``vistrack._core`` name the types (scripts/stubs.sh)."""

from typing import Optional, Sequence, Union

from .._core import OrbitPlan
from ..georeference import Georeference
from ..mission.model import Mission
from .to_mission import orbit_plan_mission


def to_mission(self: OrbitPlan, georeference: Union[Georeference, Sequence[float]], altitude: Optional[float] = None,
               *, direction: str = "ccw", speed: Optional[float] = None, start: Optional[Sequence[float]] = None,
               end: str = "loiter", firmware: str = "ardupilot", altitude_mode: str = "relative") -> Mission:
    return orbit_plan_mission(self, georeference, altitude, direction=direction, speed=speed, start=start, end=end,
                              firmware=firmware, altitude_mode=altitude_mode)


to_mission.__doc__ = orbit_plan_mission.__doc__
OrbitPlan.to_mission = to_mission  # type: ignore[method-assign]
