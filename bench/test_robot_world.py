"""Robot-world throughput: robot-steps per second for 4 and 50 robots (docs/robot-world.md)."""

from __future__ import annotations

import pytest

from .robot_world import WorldRun

ROUNDS = 5
STEPS = {4: 5_000, 50: 400}  # world steps per round: about 20,000 robot-steps each

pytestmark = pytest.mark.benchmark(group="robot world (one round = steps x robots)")


@pytest.mark.parametrize("robots", sorted(STEPS))
def test_robot_steps_per_second(measure, robots: int) -> None:
    run = WorldRun(robots, STEPS[robots])
    measure(f"world.robot_steps.{robots}", run.round, ROUNDS, per_round=robots * STEPS[robots])
