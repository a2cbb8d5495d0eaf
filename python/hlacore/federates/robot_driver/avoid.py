""""Go forward and avoid what the sonar sees" (testing-rtes-hla-2016 §6.2): two controllers, one decision per
control cycle from the robot's pose and the nearest sonar range, answered as a velocity pair held for the
cycle.

* :class:`OpenLoopAvoid` is the paper's first control: it goes forward; when the front range drops below
  ``detect`` it plays a timed side step (quarter turn left, ``sidestep`` metres, quarter turn right) and
  goes forward again. It never looks at its position, so a robot that does not do exactly what it is told
  (a defective wheel) drifts, and may meet the obstacle again.
* :class:`CorrectedAvoid` is the paper's third control: the same manoeuvre, but at every cycle it checks
  its pose (odometry) and steers back onto the line it should be on (heading and cross-track error), turns
  until the heading is reached, and side-steps by the distance actually travelled.

Both are pure Python (no RTI, no ROS): the robot driver federate, the ROS node of the third robot and the
reference model run the same code.
"""

from __future__ import annotations

import math
from dataclasses import dataclass, field
from typing import Optional

__all__ = ["AvoidParams", "OpenLoopAvoid", "CorrectedAvoid", "make_controller", "wrap"]

Pose = tuple[float, float, float]  # x, y (m), heading (rad)


def wrap(angle: float) -> float:
    """``angle`` in (-pi, pi]."""
    return math.atan2(math.sin(angle), math.cos(angle))


@dataclass(frozen=True)
class AvoidParams:
    """The controllers' figures (ours: the paper gives none)."""

    speed: float = 0.2  #: forward speed, m/s
    turn_rate: float = math.pi / 4  #: turning speed, rad/s (a quarter turn in 2 s)
    detect: float = 0.5  #: an obstacle is avoided when the front range is below this, m
    sidestep: float = 0.6  #: how far the robot moves to the left to pass the obstacle, m
    cycle: float = 0.5  #: the control cycle, s
    gain_heading: float = 1.0  #: corrected control: rad/s per rad of heading error
    gain_lateral: float = 2.0  #: corrected control: rad/s per m of cross-track error
    turn_gain: float = 0.7  #: corrected control: the part of a turn's heading error corrected per cycle
    heading_tolerance: float = math.radians(2.0)  #: corrected control: a turn is done within this


@dataclass
class _Base:
    params: AvoidParams = field(default_factory=AvoidParams)
    #: The mode of the last decision: ``forward``, ``turn-left``, ``sidestep`` or ``turn-right``.
    mode: str = "forward"
    #: How many avoidance manoeuvres began (a second one is the obstacle detected again).
    avoidances: int = 0


@dataclass
class OpenLoopAvoid(_Base):
    """Timed manoeuvres, no position feedback (see the module docstring)."""

    _plan: list[tuple[str, float, float]] = field(default_factory=list)

    def decide(self, pose: Pose, front: float) -> tuple[float, float]:
        """The (linear, angular) velocity for the next cycle; ``pose`` is not used (open loop)."""
        p = self.params
        if not self._plan and front < p.detect:
            self.avoidances += 1
            turns = max(1, round((math.pi / 2) / (p.turn_rate * p.cycle)))
            turn = (math.pi / 2) / (turns * p.cycle)
            steps = max(1, round(p.sidestep / (p.speed * p.cycle)))
            step = p.sidestep / (steps * p.cycle)
            self._plan = ([("turn-left", 0.0, turn)] * turns + [("sidestep", step, 0.0)] * steps
                          + [("turn-right", 0.0, -turn)] * turns)
        if self._plan:
            self.mode, linear, angular = self._plan.pop(0)
            return linear, angular
        self.mode = "forward"
        return p.speed, 0.0


@dataclass
class CorrectedAvoid(_Base):
    """Pose feedback at every cycle (see the module docstring). The first pose fixes the line to follow."""

    _lane: Optional[tuple[float, float, float]] = None  # a point of the line and its heading
    _target: float = 0.0  # the heading the current turn aims at
    _step_from: tuple[float, float] = (0.0, 0.0)  # where the side step began

    def decide(self, pose: Pose, front: float) -> tuple[float, float]:
        """The (linear, angular) velocity for the next cycle from the measured pose and front range."""
        p = self.params
        x, y, theta = pose
        if self._lane is None:
            self._lane = (x, y, theta)
        x0, y0, heading = self._lane
        for _ in range(4):  # a finished mode hands over within the same cycle
            if self.mode == "forward":
                if front < p.detect:
                    self.avoidances += 1
                    self.mode, self._target = "turn-left", wrap(heading + math.pi / 2)
                    continue
                return p.speed, self._steer(pose, (x0, y0), heading)
            if self.mode in ("turn-left", "turn-right"):
                error = wrap(self._target - theta)
                if abs(error) > p.heading_tolerance:
                    # less than the whole error per cycle: a command acting late (through ROS) must not overshoot
                    return 0.0, _clip(p.turn_gain * error / p.cycle, p.turn_rate)
                if self.mode == "turn-left":
                    self.mode, self._step_from = "sidestep", (x, y)
                    continue
                self.mode = "forward"
                continue
            # sidestep: along heading + 90 degrees from where it began, until ``sidestep`` metres are done
            across = wrap(heading + math.pi / 2)
            done = (x - self._step_from[0]) * math.cos(across) + (y - self._step_from[1]) * math.sin(across)
            left = p.sidestep - done
            if left <= 1e-3:
                self._lane = (x0 - p.sidestep * math.sin(heading), y0 + p.sidestep * math.cos(heading), heading)
                x0, y0 = self._lane[0], self._lane[1]
                self.mode, self._target = "turn-right", heading
                continue
            return min(p.speed, left / p.cycle), self._steer(pose, self._step_from, across)
        raise AssertionError("the corrected controller did not settle on a mode")  # pragma: no cover

    def _steer(self, pose: Pose, origin: tuple[float, float], heading: float) -> float:
        """Angular velocity back onto the line through ``origin`` along ``heading``."""
        p = self.params
        x, y, theta = pose
        cross = -(x - origin[0]) * math.sin(heading) + (y - origin[1]) * math.cos(heading)  # > 0: left of it
        return _clip(p.gain_heading * wrap(heading - theta) - p.gain_lateral * cross, p.turn_rate)


def make_controller(corrected: bool, params: Optional[AvoidParams] = None) -> "OpenLoopAvoid | CorrectedAvoid":
    """A fresh controller of either kind."""
    params = params or AvoidParams()
    return CorrectedAvoid(params) if corrected else OpenLoopAvoid(params)


def _clip(value: float, bound: float) -> float:
    return max(-bound, min(bound, value))
