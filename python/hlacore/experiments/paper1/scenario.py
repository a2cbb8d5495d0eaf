"""Paper 1's scenario (ros-ptolemy-hla-iess2015) in the robot world alone: an avatar with a distance
sensor drives toward a wall while three obstacle robots cross its way from its right to its left; a
go / slow / stop controller keeps it clear of them and stops it before the wall.

The paper gives no speeds, distances or thresholds; the ones here are ours (docs/robot-world.md).
"""

from __future__ import annotations

from dataclasses import dataclass, field
from typing import Optional

from hlacore.federates.robot_world.world import Pose, World
from hlacore.federates.robot_world.worldfile import WorldSpec, load_world

#: The world (Stage syntax). The avatar faces +x; the obstacles start on its right (y < 0) heading +y.
WORLD = """
# paper 1: avatar + 3 crossing obstacles + wall
resolution 0.02
interval_sim 100
define sonar ranger ( sensor( pose [0 0 0 0] range [0.02 3.0] fov 60 samples 13 ) )
define bot position ( size [0.33 0.33 0.40] drive "diff" gui_nose 1 )
define wall model ( size [0.2 6.0 0.5] color "gray30" obstacle_return 1 ranger_return 1 )
window ( size [ 600 400 ] scale 40 )
bot( pose [ 0.0  0.0 0   0] name "avatar"    color "black" sonar(pose [0.165 0 0 0]) )
bot( pose [ 2.0 -1.2 0  90] name "obstacle1" color "red" )
bot( pose [ 3.5 -1.8 0  90] name "obstacle2" color "orange" )
bot( pose [ 5.0 -2.4 0  90] name "obstacle3" color "magenta" )
wall( pose [ 7.0 0.0 0 0] )
"""

OBSTACLES = ("obstacle1", "obstacle2", "obstacle3")


@dataclass
class Controller:
    """The paper's "Control" script: go, slow or stop by the sensed distance (the nearest beam)."""

    go: float = 0.5  # m/s
    slow: float = 0.15
    slow_below: float = 1.2  # m
    stop_below: float = 0.5

    def __call__(self, distance: float) -> float:
        """The avatar's linear velocity for a sensed distance."""
        if distance <= self.stop_below:
            return 0.0
        if distance <= self.slow_below:
            return self.slow
        return self.go


@dataclass
class ObstacleDriver:
    """The obstacles' driver: each crosses at ``speed`` until it has travelled ``travel`` m from where it
    was first seen (y grows: they cross from the avatar's right to its left), then stops."""

    speed: float = 0.3  # m/s
    travel: float = 5.0  # m
    starts: dict[str, float] = field(default_factory=dict)  # obstacle -> first y seen

    def __call__(self, name: str, y: float) -> float:
        """The obstacle's linear velocity at lateral position ``y``."""
        start = self.starts.setdefault(name, y)
        return self.speed if y - start < self.travel else 0.0


@dataclass
class Trace:
    """What a run recorded at every control cycle."""

    times: list[float] = field(default_factory=list)
    poses: list[dict[str, Pose]] = field(default_factory=list)
    distance: list[float] = field(default_factory=list)
    avatar_speed: list[float] = field(default_factory=list)
    touching: list[bool] = field(default_factory=list)  # per physics step: the avatar touches something
    stalled: list[bool] = field(default_factory=list)  # per physics step: some robot is stalled


def world_spec() -> WorldSpec:
    """The scenario's world."""
    return load_world(WORLD)


def run(duration: float = 30.0, period: float = 0.1, dt: float = 0.01, obstacle_speed: float = 0.3,
        obstacle_travel: float = 5.0, controller: Optional[Controller] = None) -> tuple[World, Trace]:
    """Run the scenario for ``duration`` s with a controller cycle of ``period``; return the world and trace.

    Obstacles drive at ``obstacle_speed`` until they have travelled ``obstacle_travel`` m, then stop;
    every command is re-sent each cycle (the watchdog is 0.2 s)."""
    control = controller or Controller()
    drive = ObstacleDriver(obstacle_speed, obstacle_travel)
    world = World(world_spec(), dt=dt, watchdog=0.2)
    trace = Trace()
    per_cycle = round(period / dt)
    for _cycle in range(round(duration / period)):
        avatar = world.robot("avatar")
        distance = min(avatar.ranges)
        speed = control(distance)
        world.command("avatar", speed, 0.0)
        for name in OBSTACLES:
            world.command(name, drive(name, world.robot(name).pose.y), 0.0)
        for _ in range(per_cycle):
            world.step()
            trace.touching.append(world.touching("avatar"))
            trace.stalled.append(any(r.stall for r in world.robots))
        trace.times.append(world.time)
        trace.poses.append(world.poses())
        trace.distance.append(distance)
        trace.avatar_speed.append(speed)
    return world, trace


def write_outputs(world: World, trace: Trace, directory: str) -> list[str]:
    """Write the run's trace (CSV), a final snapshot (PNG) and, when matplotlib is installed, the
    trajectory plot; returns the files written."""
    import csv
    import pathlib

    from hlacore.federates.robot_world import render

    out = pathlib.Path(directory)
    out.mkdir(parents=True, exist_ok=True)
    names = [r.name for r in world.robots]
    with open(out / "paper1-trace.csv", "w", newline="") as f:
        writer = csv.writer(f)
        writer.writerow(["time", "distance", "avatar_speed"] + [f"{n}_{c}" for n in names for c in "xy"])
        for t, d, v, poses in zip(trace.times, trace.distance, trace.avatar_speed, trace.poses):
            writer.writerow([repr(t), repr(d), repr(v)] + [repr(c) for n in names for c in (poses[n].x, poses[n].y)])
    written = [str(out / "paper1-trace.csv")]
    tracks = render.trajectories(trace.poses)
    written.append(str(render.write_labelled_snapshot(world, out / "paper1-snapshot.png",
                                                      "paper 1: the world at the end, with each robot's trail",
                                                      trails=tracks)))
    title = "paper 1: avatar, crossing obstacles, wall"
    try:
        written.append(str(render.plot_trajectories(world, trace.poses, out / "paper1-trajectories.png",
                                                    title=title)))
        written.append(str(render.animate_trajectories(world, trace.poses, out / "paper1-trajectories.gif",
                                                       title=title)))
    except ImportError as exc:
        print(f"no trajectory plot: {exc}")
    return written


def main(argv: Optional[list[str]] = None) -> int:
    """``python -m hlacore.experiments.paper1.scenario [OUTDIR]``: run the scenario, print its checks,
    write the trace and pictures (default directory: paper1-out)."""
    import sys

    args = sys.argv[1:] if argv is None else argv
    world, trace = run()
    avatar = world.robot("avatar").pose
    print(f"collisions: {sum(trace.touching)} steps touching, stalls: {sum(trace.stalled)} steps")
    print(f"avatar stopped at x = {avatar.x:.3f} m, front {6.9 - avatar.x - 0.165:.3f} m from the wall")
    for path in write_outputs(world, trace, args[0] if args else "paper1-out"):
        print(f"wrote {path}")
    return 0 if not any(trace.touching) and not any(trace.stalled) else 1


if __name__ == "__main__":
    raise SystemExit(main())
