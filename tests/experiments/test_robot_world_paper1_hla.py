"""Paper 1's scenario through the RTI, against both gateways: the world federate and a controller federate
in lockstep (commands stamped T + L, states reflected at G + L); the avatar never collides, passes the
obstacles once they have left its lane and stops before the wall."""

from __future__ import annotations


import pytest

from hlacore.experiments.paper1 import hla as paper1_hla
from hlacore.experiments.paper1 import scenario as paper1

HALF = 0.33 / 2
WALL_FACE = 7.0 - 0.1


def test_paper1_over_hla(world_federation: str) -> None:
    world, control, stalls = paper1_hla.run(world_federation, duration=30.0)
    try:
        assert len(world.history) == 301 and world.history[-1][0] == pytest.approx(30.0)
        # Stage semantics: any collision stalls the robot that moved into it, at that step
        assert not any(stalls) and [r.stall_steps for r in world.world.robots] == [0] * 4
        avatar = [poses["avatar"] for _, poses in world.history]
        for name in paper1.OBSTACLES:
            obstacle = [poses[name] for _, poses in world.history]
            # wherever the two boxes' x extents overlap, their y extents do not (they never touch)
            for a, o in zip(avatar, obstacle):
                if abs(a.x - o.x) < 2 * HALF:
                    assert abs(a.y - o.y) > 2 * HALF, (name, a, o)
            assert obstacle[-1].y > 2.0  # it crossed
        assert 0.0 in control.speeds[:150]  # it stopped for an obstacle
        final = avatar[-1]
        assert final.x > 5.0 and 0.0 < WALL_FACE - (final.x + HALF) <= paper1.Controller().stop_below
        assert control.speeds[-20:] == [0.0] * 20
        # the controller saw what the world published: the avatar's ranges at some G, reflected at G + L
        assert control.amb.latest["avatar"]["pose"] == pytest.approx(
            (world.history[-2][1]["avatar"].x, world.history[-2][1]["avatar"].y, 0.0))
    finally:
        control.resign()
        world.resign()
