"""The robot-world throughput body: N robots with a 3-beam sonar each, in a walled arena, driving and
turning (seeded commands, re-sent every 0.1 s), stepped with dt = 0.01 s. A round is `steps` world steps;
its rate is robot-steps per second (N x steps / seconds)."""

from __future__ import annotations

import math
import random

from hlacore.federates.robot_world import World, load_world

DT = 0.01


def arena(robots: int) -> str:
    """A .world text: a square arena sized for `robots` robots 1 m apart, plus a few boxes."""
    side = max(2, math.ceil(math.sqrt(robots)))
    half = side / 2 + 0.5
    lines = [
        "define sonar ranger ( sensor( pose [0 0 0 -30] range [0.02 3.0] fov 15 samples 1 )",
        "                      sensor( pose [0 0 0   0] range [0.02 3.0] fov 15 samples 1 )",
        "                      sensor( pose [0 0 0  30] range [0.02 3.0] fov 15 samples 1 ) )",
        'define bot position ( size [0.33 0.33 0.4] drive "diff" sonar(pose [0.165 0 0 0]) )',
        f"model( pose [0 {half} 0 0] size [{2 * half} 0.1 0.5] )",
        f"model( pose [0 {-half} 0 0] size [{2 * half} 0.1 0.5] )",
        f"model( pose [{half} 0 0 0] size [0.1 {2 * half} 0.5] )",
        f"model( pose [{-half} 0 0 0] size [0.1 {2 * half} 0.5] )",
    ]
    for i in range(robots):
        x, y = -side / 2 + 0.5 + i % side, -side / 2 + 0.5 + i // side
        lines.append(f'bot( pose [{x:.3f} {y:.3f} 0 {(37 * i) % 360}] name "r{i}" )')
    return "\n".join(lines)


class WorldRun:
    """One world of `robots` robots; `round()` runs `steps` steps with fresh commands every 10 steps."""

    def __init__(self, robots: int, steps: int, seed: int = 1) -> None:
        self.world = World(load_world(arena(robots)), dt=DT, watchdog=0.2)
        self.robots = robots
        self.steps = steps
        self.rng = random.Random(seed)

    def round(self) -> None:
        world = self.world
        for k in range(self.steps):
            if k % 10 == 0:
                for robot in world.robots:
                    world.command(robot.name, self.rng.uniform(0.0, 0.6), self.rng.uniform(-1.0, 1.0))
            world.step()
