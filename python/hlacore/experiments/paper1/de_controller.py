"""Paper 1's controller as a DE-engine federate: the Ptolemy model of ros-ptolemy-hla-iess2015 (Fig. 6) on
:mod:`hlacore.federates.de`, commanding the robots through the RTI (and, in paper 1's chain, the ROS bridge
and a stageros-style node).

    python -m hlacore.experiments.paper1.de_controller --rtig HOST:PORT [--duration 30] [--out FILE.json]

The model: an :class:`~hlacore.federates.de.HlaDirector` (regulating and constrained, lookahead 0.1 s,
event-driven NER: each reflected state is granted at its own timestamp), an ``ObjectSubscriber`` of the ``WorldRobot``
``pose`` and ``ranges``, the paper's "Control" actor (:class:`AvatarControl`, the go / slow / stop rule of
:class:`~.scenario.Controller`) and the obstacles' driver (:class:`ObstacleDrivers`, :class:`~.scenario.ObstacleDriver`;
in the paper a Python ROS node drove them, here the DE model does, so that the whole scenario is in lockstep),
both feeding an ``InteractionSender`` of ``cmd_vel``. Each reflected state is an event at its timestamp; the
actors answer it at the same tag, and the commands go out stamped that time plus the lookahead.

The federate waits until it has discovered every robot (the world's publisher is then joined and
regulating) before it runs, prints ``paper1_de ready``, runs to ``--duration`` and writes what it did.
"""

from __future__ import annotations

import argparse
import json
import sys
import time as _time
from dataclasses import dataclass, field
from typing import Any, Optional, Sequence

import hlacore.rti as rti
from hlacore.federates.de import Actor, HlaDirector, InteractionSender, ObjectSubscriber

from hlacore.federates.robot_world import codec

from . import scenario as paper1

ROBOTS = ("avatar",) + paper1.OBSTACLES


class _CommandActor(Actor):
    """An actor that answers robot states (``Received`` records on ``state``) with ``cmd_vel`` tokens on
    ``robot``, ``linear`` and ``angular`` (one token on each per command, so the sender pairs them)."""

    def __init__(self, name: str) -> None:
        super().__init__(name)
        self.state = self.add_input("state")
        self.robot = self.add_output("robot")
        self.linear = self.add_output("linear")
        self.angular = self.add_output("angular")
        #: (time, robot, linear) of every command sent
        self.commands: list[tuple[float, str, float]] = []

    def command(self, robot: str, linear: float) -> None:
        """Send ``cmd_vel(robot, linear, 0)`` at the current tag."""
        self.robot.send(robot)
        self.linear.send(linear)
        self.angular.send(0.0)
        self.commands.append((self.now, robot, linear))


class AvatarControl(_CommandActor):
    """The paper's "Control" Python actor: each avatar state's nearest beam → go / slow / stop."""

    def __init__(self, name: str = "control", controller: Optional[paper1.Controller] = None,
                 avatar: str = "avatar") -> None:
        super().__init__(name)
        self.controller = controller or paper1.Controller()
        self.avatar = avatar
        #: (time, sensed distance, commanded speed) per avatar state
        self.log: list[tuple[float, float, float]] = []

    def fire(self) -> None:
        """Command the avatar's speed from the nearest beam of each of its states, and log it."""
        for record in self.state.tokens:
            ranges = record.values.get("ranges")
            if record.source != self.avatar or not ranges:
                continue
            distance = min(ranges)
            speed = self.controller(distance)
            self.command(self.avatar, speed)
            self.log.append((self.now, distance, speed))


class ObstacleDrivers(_CommandActor):
    """The obstacles' driver: each obstacle state's y → cross at 0.3 m/s until 5 m travelled, then stop."""

    def __init__(self, name: str = "obstacles", driver: Optional[paper1.ObstacleDriver] = None,
                 obstacles: Sequence[str] = paper1.OBSTACLES) -> None:
        super().__init__(name)
        self.driver = driver or paper1.ObstacleDriver()
        self.obstacles = tuple(obstacles)

    def fire(self) -> None:
        """Command each obstacle's speed from the y of its state."""
        for record in self.state.tokens:
            pose = record.values.get("pose")
            if record.source in self.obstacles and pose is not None:
                self.command(record.source, self.driver(record.source, float(pose[1])))


class _Discoveries(rti.FederateAmbassador):
    """The director's delegate: the names of the robots discovered so far."""

    def __init__(self) -> None:
        self.names: set[str] = set()

    def discoverObjectInstance(self, obj: Any, cls: Any, name: str) -> None:
        """Note the discovered robot's name."""
        self.names.add(str(name))


@dataclass
class Model:
    """The DE model of the controller federate, and what it recorded."""

    director: HlaDirector
    robots: ObjectSubscriber
    control: AvatarControl
    obstacles: ObstacleDrivers
    sender: InteractionSender
    received: list[tuple[float, str, list[float]]] = field(default_factory=list)  # (time, robot, pose)

    def summary(self) -> dict[str, Any]:
        """JSON-able: the grants, the avatar's control log, every command and every reflected pose."""
        return {"grants": len(self.director.grants), "end": self.director.now,
                "control": self.control.log, "commands": self.control.commands + self.obstacles.commands,
                "sent": len(self.sender.sent), "poses": self.received}


class _PoseLog(Actor):
    """Keeps every reflected pose (for the trace): a model actor like Ptolemy's recorders."""

    def __init__(self, model_log: list[tuple[float, str, list[float]]]) -> None:
        super().__init__("pose_log")
        self.state = self.add_input("state")
        self._log = model_log

    def fire(self) -> None:
        """Append each reflected pose to the model's log, with the time and the robot."""
        for record in self.state.tokens:
            pose = record.values.get("pose")
            if pose is not None:
                self._log.append((self.now, record.source, [float(v) for v in pose]))


def build(director: HlaDirector, controller: Optional[paper1.Controller] = None,
          driver: Optional[paper1.ObstacleDriver] = None) -> Model:
    """The model on ``director``: subscriber → Control and obstacle drivers → cmd_vel sender."""
    robots = ObjectSubscriber("robots", codec.OBJECT_CLASS, {"pose": codec.POSE, "ranges": codec.RANGES})
    control = AvatarControl(controller=controller)
    obstacles = ObstacleDrivers(driver=driver)
    sender = InteractionSender("cmd_vel", codec.INTERACTION, {"robot": codec.NAME, "linear": codec.SPEED,
                                                              "angular": codec.SPEED})
    model = Model(director, robots, control, obstacles, sender)
    log = _PoseLog(model.received)
    robots.received.connect(control.state, obstacles.state, log.state)
    for actor in (control, obstacles):
        actor.robot.connect(sender.ports["robot"])
        actor.linear.connect(sender.ports["linear"])
        actor.angular.connect(sender.ports["angular"])
    director.add(robots, control, obstacles, sender, log)
    return model


def join(address: Optional[str], period: float = 0.1, mode: str = "NER", grant_timeout: float = 60.0) -> Model:
    """Join ``RobotWorld`` (created from the robot world's FOM if missing) as ``control`` and build the
    model; time management is enabled by :meth:`HlaDirector.initialize`."""
    seen = _Discoveries()
    director = HlaDirector.join("control", codec.FEDERATION, str(codec.FOM_PATH), address=address, mode=mode,
                                step=period, lookahead=period, grant_timeout=grant_timeout, delegate=seen)
    model = build(director)
    model.director.initialize()
    return model


def await_robots(model: Model, robots: Sequence[str] = ROBOTS, timeout: float = 60.0) -> None:
    """Tick until every robot has been discovered (TimeoutError names the missing ones)."""
    seen: _Discoveries = model.director.ambassador.delegate  # type: ignore[assignment]
    deadline = _time.monotonic() + timeout
    while not set(robots) <= seen.names:
        if _time.monotonic() > deadline:
            raise TimeoutError(f"robots not discovered within {timeout} s: {sorted(set(robots) - seen.names)}")
        model.director.rtia.tick(0.01, 0.05)


def main(argv: Optional[Sequence[str]] = None) -> int:
    """The command (see the module docstring)."""
    parser = argparse.ArgumentParser(prog="python -m hlacore.experiments.paper1.de_controller",
                                     description=__doc__, formatter_class=argparse.RawDescriptionHelpFormatter)
    parser.add_argument("--rtig", default=None, help="gateway HOST:PORT (default $HLACORE_RTIG)")
    parser.add_argument("--duration", type=float, default=30.0)
    parser.add_argument("--period", type=float, default=0.1, help="the lookahead (the world's period)")
    parser.add_argument("--timeout", type=float, default=60.0, help="wall seconds for each wait")
    parser.add_argument("--out", help="write the summary (JSON) here")
    args = parser.parse_args(argv)
    model = join(args.rtig, args.period, grant_timeout=args.timeout)
    try:
        print("paper1_de joined", flush=True)
        await_robots(model, timeout=args.timeout)
        print("paper1_de ready", flush=True)
        model.director.run(until=args.duration)
        model.director.wrapup()
    finally:
        model.director.resign()
    summary = model.summary()
    if args.out:
        with open(args.out, "w") as f:
            json.dump(summary, f)
    print(f"paper1_de stopped at {model.director.now!r} ({summary['grants']} grants, {summary['sent']} cmd_vel)",
          flush=True)
    return 0


if __name__ == "__main__":
    sys.exit(main())
