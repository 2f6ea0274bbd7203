"""vistrack's autopilot for a JSBSim aircraft: a bank command in, four surface commands out.

Successive loop closure as in Beard and McLain, *Small Unmanned Aircraft* (2012), ch. 6:

- roll: aileron = kp (phi_c - phi) - kd p + ki integral(phi_c - phi);
- altitude through pitch: theta_c = theta_trim + alpha_trim (1 / cos phi - 1) (the extra angle of
  attack a bank needs) + kp (h_c - h) + ki integral(h_c - h), within +-max_pitch of trim;
  elevator = elevator_trim - kp (theta_c - theta) + kd (q - q_turn), q_turn = g/V sin(phi) tan(phi) the
  pitch rate of a steady level turn (JSBSim's elevator +1 is nose down);
- airspeed through throttle: throttle = throttle_trim + kp (V_c - V) + ki integral(V_c - V), in [0, 1];
- turn coordination: rudder = k_beta beta (sideslip to zero).

Integrators stop while their output saturates (anti-windup).
"""

from __future__ import annotations

import math

from .._core.flight import coordinated_bank
from .aircraft import GRAVITY, Aircraft
from .model import AircraftState
from .trim import Trim


def _clamp(value: float, low: float, high: float) -> float:
    return low if value < low else high if value > high else value


class Autopilot:
    """The inner loops of one aircraft, from a trim; ``step`` once per autopilot period."""

    def __init__(self, aircraft: Aircraft, trim: Trim, altitude: float, airspeed: float):
        self.gains = aircraft.gains
        self.max_bank = math.radians(aircraft.envelope.max_bank_deg)
        self.max_pitch = math.radians(aircraft.gains.max_pitch_deg)
        self.trim = trim
        self.altitude = altitude
        self.airspeed = airspeed
        self._roll_i = 0.0
        self._altitude_i = 0.0
        self._speed_i = 0.0

    def bank_command(self, turn_rate: float, alpha: float) -> float:
        """The Euler bank (rad, + right wing down) of the coordinated turn at ``turn_rate`` (rad/s, + to the
        left, counter-clockwise) at the commanded airspeed: the lift's bank mu = atan(v r / g), the body's
        phi = atan(tan(mu) / cos(alpha)) (level flight, no sideslip), within the bank limit."""
        mu = coordinated_bank(self.airspeed, turn_rate)
        phi = math.atan(math.tan(mu) / max(math.cos(alpha), 0.5))
        return -_clamp(phi, -self.max_bank, self.max_bank)

    def step(self, s: AircraftState, bank_command: float, dt: float) -> tuple[float, float, float, float]:
        """(aileron, elevator, rudder, throttle) for state ``s`` and the bank command (rad)."""
        g = self.gains
        trim = self.trim
        roll_error = bank_command - s.phi
        aileron = g.roll_kp * roll_error - g.roll_kd * s.p + g.roll_ki * self._roll_i
        if -1.0 < aileron < 1.0:
            self._roll_i += roll_error * dt
        aileron = _clamp(aileron, -1.0, 1.0)

        altitude_error = self.altitude - s.altitude
        cos_phi = max(math.cos(s.phi), 0.3)
        max_pitch = self.max_pitch
        feed_forward = trim.alpha * (1.0 / cos_phi - 1.0)
        theta_c = g.altitude_kp * altitude_error + g.altitude_ki * self._altitude_i + feed_forward
        if -max_pitch < theta_c < max_pitch:
            self._altitude_i += altitude_error * dt
        theta_c = trim.theta + _clamp(theta_c, -max_pitch, max_pitch)
        q_turn = GRAVITY / max(s.airspeed, 1.0) * math.sin(s.phi) * math.tan(s.phi) * (cos_phi > 0.3)
        elevator = trim.elevator - g.pitch_kp * (theta_c - s.theta) + g.pitch_kd * (s.q - q_turn)
        elevator = _clamp(elevator, -1.0, 1.0)

        speed_error = self.airspeed - s.airspeed
        throttle = trim.throttle + g.speed_kp * speed_error + g.speed_ki * self._speed_i
        if 0.0 < throttle < 1.0:
            self._speed_i += speed_error * dt
        throttle = _clamp(throttle, 0.0, 1.0)

        rudder = _clamp(g.yaw_k_beta * s.beta, -1.0, 1.0)
        return aileron, elevator, rudder, throttle
