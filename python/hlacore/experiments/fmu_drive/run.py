"""The run: the controller FMU and the robot world as two federates of one federation, and the same loop run
without HLA twice, as the references: with the federation's delays (it must give the same path) and with none
(the path the controller's designer expects: the difference is what the loop's delay costs).

Timing (docs/fmu.md, "Time"): the world publishes its pose at each grant G stamped G + h (less the FMU's margin); the FMU, granted t,
holds the pose of t - h (its start values, the robot's initial pose, before any), steps, and sends the command
stamped t + h, which the world applies from t + h: two steps of delay around the loop.
"""

from __future__ import annotations

import math
import pathlib
import threading
from dataclasses import dataclass, field
from typing import Any, Optional

from hlacore.federates.robot_world import FEDERATION, FOM_PATH, Pose, World, WorldFederate, WorldSpec, load_world
from hlacore.fmu import FmuFederate, FmuModel
from hlacore.fmu.build import build_fmu
from hlacore.fmu.federate import LOOKAHEAD_MARGIN

SOURCES = pathlib.Path(__file__).resolve().parent / "controller"
ROBOT = "fmubot"
IDEAL = "without delay"  #: the name of the undelayed loop's path in the plot
STEP = 0.1  #: the FMU's step, the world's period and both lookaheads (s)
WAYPOINTS = [(2.0, 0.0), (2.0, 2.0), (0.0, 2.0), (0.0, 0.0)]  #: the controller's defaults (modelDescription.xml)
TOLERANCE = 0.1  #: a waypoint is reached within this distance (m), as the controller decides
BOX = (1.0, 1.0, 0.5)  #: a box inside the square: centre x, y and side (m)
WORLD = f"""
resolution 0.02
interval_sim 100
define bot position ( size [0.33 0.33 0.40] drive "diff" )
define box model ( size [{BOX[2]} {BOX[2]} 0.5] color "black" obstacle_return 1 ranger_return 1 )
bot( pose [ 0 0 0 0 ] name "{ROBOT}" color "red" )
box( pose [ {BOX[0]} {BOX[1]} 0 0 ] name "box" )
"""


def world_spec(*others: str) -> WorldSpec:
    """The world: the robot at the origin facing +x, a box in the middle of the waypoints' square; ``others``:
    robots of these names at the same place, to draw other paths there."""
    return load_world(WORLD + "".join(f'bot( pose [ 0 0 0 0 ] name "{name}" color "blue" )\n' for name in others))


@dataclass
class Path:
    """A run's poses at each step's time, and the commands in force over each step."""

    times: list[float] = field(default_factory=list)
    poses: list[Pose] = field(default_factory=list)
    commands: list[tuple[float, float]] = field(default_factory=list)

    def reached(self) -> list[Optional[float]]:
        """For each waypoint in order, the first time at or after the previous one's that the robot was within
        :data:`TOLERANCE` of it (None: never)."""
        out: list[Optional[float]] = []
        start = 0
        for wx, wy in WAYPOINTS:
            hit = next((i for i in range(start, len(self.poses))
                        if math.hypot(self.poses[i].x - wx, self.poses[i].y - wy) < TOLERANCE), None)
            out.append(None if hit is None else self.times[hit])
            if hit is None:
                break
            start = hit
        return out + [None] * (len(WAYPOINTS) - len(out))

    def distance(self, other: "Path") -> float:
        """The largest distance between the two paths' positions at the same steps."""
        return max(math.hypot(a.x - b.x, a.y - b.y) for a, b in zip(self.poses, other.poses))


@dataclass
class Result:
    """The federated run, the two references, and whether the world ever stalled the robot."""

    federated: Path
    delayed: Path
    ideal: Path
    stalled: bool
    steps: int

    def summary(self) -> dict[str, Any]:
        """The figures of the run, as the command prints them in JSON."""
        end = self.federated.poses[-1]
        return {"steps": self.steps, "step": STEP, "reached": self.federated.reached(),
                "ideal_reached": self.ideal.reached(), "vs_same_loop": self.federated.distance(self.delayed),
                "vs_ideal": self.federated.distance(self.ideal), "stalled": self.stalled,
                "end": [end.x, end.y, end.theta]}


def controller_fmu(into: pathlib.Path) -> pathlib.Path:
    """The controller's .fmu, compiled from ``controller/`` into ``into`` (once per set of sources)."""
    into.mkdir(parents=True, exist_ok=True)
    return build_fmu(SOURCES, into)


def federated(fmu: pathlib.Path, address: str, steps: int, timeout: float = 30.0) -> tuple[Path, bool]:
    """The FMU federate and the world federate (this process, two threads) for ``steps`` steps; the robot's
    path as the world saw it at each grant, the commands as the FMU sent them, and whether it ever stalled."""
    path, stalled = Path(), False
    with FmuFederate(fmu, FEDERATION, step_size=STEP, name="controller", address=address, fed_file=str(FOM_PATH), mapping=SOURCES / "mapping.toml", timeout=timeout) as fmu_fed:
        fmu_fed.join()  # first, so that it hears the world's first pose
        # the FMU's lookahead too: a pose of G stamped G + lookahead is safely before the FMU's grant G + h
        world = WorldFederate.join(World(world_spec()), address, period=STEP, lookahead=STEP * (1 - LOOKAHEAD_MARGIN))
        failure: list[BaseException] = []

        def run_fmu() -> None:
            try:
                fmu_fed.run(steps * STEP)
            except BaseException as error:  # re-raised by this thread
                failure.append(error)

        runner = threading.Thread(target=run_fmu, name="fmu")
        runner.start()
        try:
            for _ in range(steps):
                world.advance(timeout)
                stalled = stalled or world.world.robot(ROBOT).stall
        finally:
            world.resign()
            runner.join(timeout)
        if failure:
            raise failure[0]
    for time, poses in world.history:
        path.times.append(time)
        path.poses.append(poses[ROBOT])
    path.commands = [(values["v"], values["w"]) for _, values in fmu_fed.trajectory[1:]]
    return path, stalled


def same_loop(fmu: pathlib.Path, steps: int, delay: int) -> Path:
    """The loop without HLA: the same FMU stepped by FMPy and the same world stepped directly. At step k the
    FMU holds the pose of step k - ``delay`` + 1 (the first pose before that) and its command applies from
    step k + ``delay`` - 1: ``delay`` 2 is the federation's timing, 1 an ideal loop without delay."""
    world, path = World(world_spec()), Path()
    instance = FmuModel(fmu).instantiate(0.0)
    try:
        path.times.append(world.time)
        path.poses.append(world.robot(ROBOT).pose)
        for k in range(steps):
            pose = path.poses[max(0, k - delay + 1)]
            instance.set({"x": pose.x, "y": pose.y, "theta": pose.theta})
            out = instance.do_step(k * STEP, STEP, ["v", "w"])
            path.commands.append((out["v"], out["w"]))
            world.schedule((k + delay - 1) * STEP, ROBOT, out["v"], out["w"])
            world.advance_to((k + 1) * STEP)
            path.times.append(world.time)
            path.poses.append(world.robot(ROBOT).pose)
    finally:
        instance.close()
    return path


def run(address: str, steps: int, workdir: pathlib.Path) -> Result:
    """The experiment: build the FMU into ``workdir``, run it federated, then the two references."""
    fmu = controller_fmu(workdir)
    path, stalled = federated(fmu, address, steps)
    return Result(path, same_loop(fmu, steps, delay=2), same_loop(fmu, steps, delay=1), stalled, steps)
