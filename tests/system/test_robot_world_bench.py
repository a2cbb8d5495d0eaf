"""The robot-world throughput body of bench/ at a tiny size, for correctness only (no timing is asserted):
./scripts/bench.sh -k robot_steps runs it at full size."""

from __future__ import annotations

import pytest

from bench.robot_world import WorldRun, arena
from hlacore.federates.robot_world import load_world


@pytest.mark.parametrize("robots", [4, 50])
def test_arena_and_round(robots: int) -> None:
    spec = load_world(arena(robots))
    assert len(spec.robots) == robots and len(spec.blocks) == 4
    assert all(len(r.sensors) == 3 for r in spec.robots)
    run = WorldRun(robots, 20)
    before = run.world.poses()
    run.round()
    run.round()
    assert run.world.steps == 40
    after = run.world.poses()
    assert sum(before[n] != after[n] for n in before) >= robots // 2  # they drive
    assert all(len(r.ranges) == 3 for r in run.world.robots)
