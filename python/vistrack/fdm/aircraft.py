"""The aircraft vistrack flies in JSBSim: each one's model, envelope and autopilot gains.

An aircraft is a YAML file in ``vistrack/fdm/aircraft/`` (``NAME/vistrack.yaml`` beside the JSBSim
model the project wrote, or ``NAME.yaml`` for a stock JSBSim aircraft). ``aircraft(name)`` reads it;
``Aircraft.check_plan(speed, turn_radius)`` refuses a plan the airframe cannot fly.
"""

from __future__ import annotations

import math
from dataclasses import dataclass
from pathlib import Path
from typing import Any

import yaml

from .._core import VistrackError
from .._core.loiter import STANDARD_GRAVITY

AIRCRAFT_DIR = Path(__file__).resolve().parent / "aircraft"
DEFAULT_AIRCRAFT = "aerosonde"
GRAVITY = STANDARD_GRAVITY  # m/s^2, the core's


@dataclass(frozen=True)
class Envelope:
    """What the airframe flies: speeds in m/s (true airspeed), the bank limit in degrees."""

    stall_speed: float
    min_airspeed: float
    cruise_speed: float
    max_airspeed: float
    max_bank_deg: float

    def min_turn_radius(self, speed: float) -> float:
        """The tightest coordinated turn at ``speed``: v^2 / (g tan(bank limit)), m."""
        return speed * speed / (GRAVITY * math.tan(math.radians(self.max_bank_deg)))


@dataclass(frozen=True)
class Gains:
    """The autopilot's loops (signs in JSBSim's conventions: elevator +1 nose down, aileron +1 right
    wing down, rudder +1 nose right, throttle 0..1)."""

    roll_kp: float
    roll_kd: float
    roll_ki: float
    pitch_kp: float
    pitch_kd: float
    altitude_kp: float
    altitude_ki: float
    max_pitch_deg: float
    speed_kp: float
    speed_ki: float
    yaw_k_beta: float


@dataclass(frozen=True)
class Rates:
    """Loop rates, Hz: the FDM's integration, the autopilot's inner loops, the planner's guidance."""

    fdm_hz: int
    autopilot_hz: int
    guidance_hz: int


@dataclass(frozen=True)
class Aircraft:
    """One aircraft: JSBSim model name, where its XML lives, envelope, control properties, trim
    method (``newton``: the project's trim on the model's accelerations; ``jsbsim``: JSBSim's),
    loop rates and autopilot gains."""

    name: str
    description: str
    model: str
    aircraft_path: Path | None  # None: the jsbsim package's own aircraft folder
    envelope: Envelope
    controls: dict[str, str]
    trim: str
    rates: Rates
    gains: Gains

    def check_plan(self, speed: float, turn_radius: float) -> None:
        """VistrackError naming the value and the limit when a plan's airspeed or turn radius lies
        outside the envelope."""
        env = self.envelope
        if not math.isfinite(speed):
            raise VistrackError(f"uav.speed = {speed!r}: must be a finite airspeed in [{env.min_airspeed:g}, "
                                f"{env.max_airspeed:g}] m/s for {self.name}")
        if speed < env.min_airspeed:
            raise VistrackError(f"uav.speed = {speed:g} m/s is below {self.name}'s lowest airspeed "
                                f"{env.min_airspeed:g} m/s (1.2-1.3 x its stall speed {env.stall_speed:g} m/s)")
        if speed > env.max_airspeed:
            raise VistrackError(f"uav.speed = {speed:g} m/s is above {self.name}'s highest airspeed "
                                f"{env.max_airspeed:g} m/s")
        tightest = env.min_turn_radius(speed)
        if not math.isfinite(turn_radius) or turn_radius < tightest:
            raise VistrackError(f"uav.min_turn_radius = {turn_radius:g} m is below {self.name}'s tightest turn at "
                                f"{speed:g} m/s: {tightest:.1f} m (bank limit {env.max_bank_deg:g} deg)")


def aircraft_names() -> list[str]:
    """Every aircraft vistrack knows, the default first."""
    names = {p.parent.name for p in AIRCRAFT_DIR.glob("*/vistrack.yaml")}
    names |= {p.stem for p in AIRCRAFT_DIR.glob("*.yaml")}
    return [DEFAULT_AIRCRAFT, *sorted(names - {DEFAULT_AIRCRAFT})]


def _section(data: dict[str, Any], key: str, name: str) -> dict[str, Any]:
    value = data.get(key)
    if not isinstance(value, dict):
        raise VistrackError(f"aircraft {name!r}: '{key}' must be a mapping, got {value!r}")
    return value


def aircraft(name: str = DEFAULT_AIRCRAFT) -> Aircraft:
    """The aircraft called ``name`` (see ``aircraft_names()``); VistrackError for an unknown name."""
    if not isinstance(name, str) or not name:
        raise VistrackError(f"aircraft = {name!r}: expected one of {aircraft_names()}")
    own = AIRCRAFT_DIR / name / "vistrack.yaml"
    stock = AIRCRAFT_DIR / f"{name}.yaml"
    path = own if own.is_file() else stock
    if not path.is_file():
        raise VistrackError(f"aircraft = {name!r} is unknown: expected one of {aircraft_names()}")
    data = yaml.safe_load(path.read_text())
    if not isinstance(data, dict):
        raise VistrackError(f"aircraft {name!r}: {path} is not a mapping")
    try:
        plane = _aircraft(name, data)
    except (KeyError, TypeError, ValueError) as error:
        raise VistrackError(f"aircraft {name!r}: {path}: missing or bad key {error}") from None
    r = plane.rates
    if not (0 < r.guidance_hz <= r.autopilot_hz <= r.fdm_hz and r.autopilot_hz % r.guidance_hz == 0
            and r.fdm_hz % r.autopilot_hz == 0):
        raise VistrackError(f"aircraft {name!r}: rates = {r}: guidance_hz must divide autopilot_hz, which must "
                            "divide fdm_hz")
    return plane


def _aircraft(name: str, data: dict[str, Any]) -> Aircraft:
    env, gains = _section(data, "envelope", name), _section(data, "gains", name)
    rates, controls = _section(data, "rates", name), _section(data, "controls", name)
    roll, pitch, alt = gains["roll"], gains["pitch"], gains["altitude"]
    return Aircraft(
        name=name, description=str(data.get("description", name)), model=str(data["model"]),
        aircraft_path=AIRCRAFT_DIR if data.get("packaged") else None,
        envelope=Envelope(**{k: float(v) for k, v in env.items()}),
        controls={k: str(v) for k, v in controls.items()}, trim=str(data["trim"]),
        rates=Rates(**{k: int(v) for k, v in rates.items()}),
        gains=Gains(roll_kp=roll["kp"], roll_kd=roll["kd"], roll_ki=roll["ki"], pitch_kp=pitch["kp"],
                    pitch_kd=pitch["kd"], altitude_kp=alt["kp"], altitude_ki=alt["ki"],
                    max_pitch_deg=alt["max_pitch_deg"], speed_kp=gains["speed"]["kp"],
                    speed_ki=gains["speed"]["ki"], yaw_k_beta=gains["yaw"]["k_beta"]))
