"""Paper 1's checks on a run through the RTI (the ROS run of :mod:`.ros` and the chain of :mod:`.chain`):
what a run recorded at every grant, and whether the robots behaved as the paper's scenario wants."""

from __future__ import annotations

from dataclasses import dataclass, field
from typing import Any, Optional

from hlacore.federates.robot_world import World
from hlacore.federates.robot_world.world import Pose

from . import scenario as paper1

__all__ = ["HALF", "WALL_FACE", "Result", "check", "held_back"]

HALF = 0.33 / 2  #: the robots' half size
WALL_FACE = 7.0 - 0.1  #: x of the wall's face


@dataclass
class Result:
    """What a run recorded, and its checks."""

    times: list[float] = field(default_factory=list)
    poses: list[dict[str, Pose]] = field(default_factory=list)
    stall_steps: dict[str, int] = field(default_factory=dict)
    late_cycles: int = 0
    sent: int = 0
    checks: dict[str, bool] = field(default_factory=dict)
    world: Optional[World] = None  #: the world at the end of the run

    @property
    def ok(self) -> bool:
        """All checks passed."""
        return bool(self.checks) and all(self.checks.values())

    def summary(self) -> dict[str, Any]:
        """The JSON-able summary printed by the command."""
        final = self.poses[-1]["avatar"]
        return {"checks": self.checks, "ok": self.ok, "grants": len(self.times), "end": self.times[-1],
                "avatar_x": final.x, "wall_gap": WALL_FACE - (final.x + HALF), "stall_steps": self.stall_steps,
                "late_cycles": self.late_cycles, "sent": self.sent,
                "obstacles_y": {n: self.poses[-1][n].y for n in paper1.OBSTACLES}}


def held_back(poses: list[dict[str, Pose]]) -> list[tuple[float, float]]:
    """Where the avatar stood still on its way (in the first 150 grants, once it had moved): an obstacle
    held it back. What the ``held_back`` check looks for, and what the plots mark."""
    xs = [p["avatar"].x for p in poses[:150]]
    return [(poses[i]["avatar"].x, poses[i]["avatar"].y) for i in range(1, len(xs)) if xs[i] == xs[i - 1] > 0]


def check(result: Result) -> dict[str, bool]:
    """Paper 1's checks on the poses at every grant: no robot ever blocked, the avatar and an obstacle never
    overlap, every obstacle crossed, the avatar was held back by an obstacle at some point, and it ends
    past the obstacles, stopped, its front less than the controller's stop distance from the wall."""
    avatar = [p["avatar"] for p in result.poses]
    apart = True
    for name in paper1.OBSTACLES:
        for a, o in zip(avatar, (p[name] for p in result.poses)):
            if abs(a.x - o.x) < 2 * HALF and abs(a.y - o.y) <= 2 * HALF:
                apart = False
    xs = [a.x for a in avatar]
    held = bool(held_back(result.poses))
    gap = WALL_FACE - (avatar[-1].x + HALF)
    return {
        "no_stall": all(v == 0 for v in result.stall_steps.values()),
        "no_overlap": apart,
        "obstacles_crossed": all(result.poses[-1][n].y > 2.0 for n in paper1.OBSTACLES),
        "held_back": held,
        "stopped_before_wall": avatar[-1].x > 5.0 and 0.0 < gap <= paper1.Controller().stop_below
        and xs[-1] == xs[-20],
    }
