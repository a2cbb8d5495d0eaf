"""The reference model: the robot's controller on an ideal body, with an ideal sonar, computed (as the
testbench's reference model is: correct by design, paper 2's Ptolemy instance).

A robot alone on a copy of the mirror's lane (same box, same sonar) in a standalone :class:`World`: every
cycle it reads its own sonar and its exact pose, the controller decides, and the world carries the command
out exactly for one cycle. No RTI, no delay: the trajectory the software means to produce.
"""

from __future__ import annotations

from typing import Optional

from hlacore.federates.robot_driver.avoid import AvoidParams, make_controller
from hlacore.federates.robot_world import World

from .scenario import REFERENCE, world_spec

Pose = tuple[float, float, float]


def reference_trajectory(cycles: int, corrected: bool = False, params: Optional[AvoidParams] = None,
                         dt: float = 0.01) -> list[tuple[float, Pose]]:
    """``(time, pose)`` at the start of every cycle ``k = 1 .. cycles + 1`` (time ``k * cycle``), the
    robot standing still during the first cycle as the real robot does (it acts from its first grant)."""
    params = params or AvoidParams()
    controller = make_controller(corrected, params)
    world = World(world_spec((REFERENCE,)), dt=dt, watchdog=None)
    robot = world.robot(REFERENCE)
    world.advance_to(params.cycle)
    out: list[tuple[float, Pose]] = []
    for k in range(1, cycles + 2):
        p = robot.pose
        out.append((world.time, (p.x, p.y, p.theta)))
        if k > cycles:
            break
        world.command(REFERENCE, *controller.decide((p.x, p.y, p.theta), min(robot.ranges)))
        world.advance_to((k + 1) * params.cycle)
    return out
