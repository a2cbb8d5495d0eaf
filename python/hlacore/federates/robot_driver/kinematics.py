"""The simulated robot's body: a differential drive on the scenario's floor, with miscalibration.

Nominal calibration is the paper's: one cell (33 cm) in 2 s of motors forward, a 90 degree turn in 1 s.
A :class:`Calibration` describes how the real robot departs from it:

* ``motor_time_error``: the motors run ``(1 + e)`` times the nominal time (moves too long or too short);
* ``friction``: the wheels lose this fraction of their speed (moves and turns fall short);
* ``wheel_bias``: the right wheel is ``(1 + bias/2)`` and the left ``(1 - bias/2)`` times as fast, so a
  straight move curves (to the left for a positive bias);
* ``defective_wheel``: the right wheel loses this fraction of its speed (paper 2 §6.2's modified wheel):
  forward moves curve to the right and turns in place fall short.

Besides the protocol's unit moves, :meth:`Body.drive_velocity` runs the motors at a linear and an angular
velocity for a time (the wheels' speeds follow from them), as a ROS robot is driven by cmd_vel.

The body moves in small steps; it stops (stalls) where the next step would enter a wall cell or leave the
grid, as a real robot stopped by a wall. The range sensors measure the distance along a ray to the first
wall cell or the grid border.
"""

from __future__ import annotations

import math
from dataclasses import dataclass

from .navigation import CELL, Cell, Scenario

__all__ = ["Calibration", "CALIBRATED", "MISCALIBRATED", "Body", "LINEAR_SPEED", "TURN_RATE", "TRACK"]

#: Nominal forward speed, m/s (one cell in 2 s).
LINEAR_SPEED = CELL / 2.0
#: Nominal turn rate, rad/s (90 degrees in 1 s).
TURN_RATE = math.pi / 2
#: Distance between the wheels, m.
TRACK = 0.15
_DT = 0.02
_RANGE_STEP = 0.01


@dataclass(frozen=True)
class Calibration:
    """How far the robot is from the nominal calibration (all 0: calibrated)."""

    motor_time_error: float = 0.0
    friction: float = 0.0
    wheel_bias: float = 0.0
    defective_wheel: float = 0.0


CALIBRATED = Calibration()
#: The demo's miscalibrated robot: motors 8 % too long, 5 % friction, 6 % wheel imbalance.
MISCALIBRATED = Calibration(motor_time_error=0.08, friction=0.05, wheel_bias=0.06)


class Body:
    """Pose ``(x, y, heading)`` in metres and radians on ``scenario``'s floor, moved by motor commands."""

    def __init__(self, scenario: Scenario, calibration: Calibration = CALIBRATED, heading_deg: float = 90.0,
                 open_floor: bool = False) -> None:
        self.scenario = scenario
        #: No wall and no border stops the body (a lab floor whose obstacles are virtual ones).
        self.open_floor = open_floor
        self.calibration = calibration
        self.x = scenario.start[0] * CELL
        self.y = scenario.start[1] * CELL
        self.heading = math.radians(heading_deg)
        #: Simulated seconds the motors ran, in total.
        self.clock = 0.0

    @property
    def cell(self) -> Cell:
        """The cell the body's centre is in."""
        return (round(self.x / CELL), round(self.y / CELL))

    def _blocked(self, x: float, y: float) -> bool:
        if self.open_floor:
            return False
        return not self.scenario.free((round(x / CELL), round(y / CELL)))

    def drive(self, direction: int, nominal: float) -> float:
        """Both wheels ``direction`` (+1 forward, -1 back) for ``nominal`` seconds; returns the real time."""
        c = self.calibration
        duration = nominal * (1 + c.motor_time_error)
        speed = LINEAR_SPEED * (1 - c.friction)
        right, left = speed * (1 + c.wheel_bias / 2) * (1 - c.defective_wheel), speed * (1 - c.wheel_bias / 2)
        self._integrate(direction * (right + left) / 2, direction * (right - left) / TRACK, duration)
        return duration

    def turn(self, direction: int, nominal: float) -> float:
        """Rotate in place, ``direction`` +1 left (counter-clockwise), -1 right; returns the real time."""
        c = self.calibration
        duration = nominal * (1 + c.motor_time_error)
        if c.defective_wheel:
            return self.drive_velocity(0.0, direction * TURN_RATE, nominal)
        self._integrate(0.0, direction * TURN_RATE * (1 - c.friction), duration)
        return duration

    def drive_velocity(self, linear: float, angular: float, nominal: float) -> float:
        """Motors at ``linear`` m/s and ``angular`` rad/s (counter-clockwise) for ``nominal`` seconds, through
        the wheels and the calibration; returns the real time the motors ran."""
        c = self.calibration
        duration = nominal * (1 + c.motor_time_error)
        scale = 1 - c.friction
        right = (linear + angular * TRACK / 2) * scale * (1 + c.wheel_bias / 2) * (1 - c.defective_wheel)
        left = (linear - angular * TRACK / 2) * scale * (1 - c.wheel_bias / 2)
        self._integrate((right + left) / 2, (right - left) / TRACK, duration)
        return duration

    def _integrate(self, v: float, omega: float, duration: float) -> None:
        steps = max(1, math.ceil(duration / _DT))
        dt = duration / steps
        for _ in range(steps):
            heading = self.heading + omega * dt / 2
            x, y = self.x + v * dt * math.cos(heading), self.y + v * dt * math.sin(heading)
            if self._blocked(x, y):
                break
            self.x, self.y, self.heading = x, y, self.heading + omega * dt
        self.heading = math.atan2(math.sin(self.heading), math.cos(self.heading))
        self.clock += duration

    def range(self, relative_deg: float) -> float:
        """Distance (m) from the centre along ``heading + relative_deg`` to the first wall or the border."""
        angle = self.heading + math.radians(relative_deg)
        limit = CELL * (self.scenario.width + self.scenario.height)
        if self.open_floor:
            return round(limit, 3)
        distance = 0.0
        while distance < limit:
            distance += _RANGE_STEP
            if self._blocked(self.x + distance * math.cos(angle), self.y + distance * math.sin(angle)):
                return round(distance, 3)
        return round(limit, 3)
