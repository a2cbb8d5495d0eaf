"""Paper 1's scenario through the RTI: the world federate and a controller federate (the paper's Ptolemy
"Control" script in plain Python) in lockstep. The controller reflects the avatar's ranges and the robots'
poses, and sends cmd_vel to the avatar (go / slow / stop) and to the obstacles, stamped its time plus
lookahead. Compared with :func:`paper1.run` the loop has one more lookahead of delay: the controller at
``T`` reads the state of ``T - L`` and its command acts from ``T + L``.
"""

from __future__ import annotations

import time
from dataclasses import dataclass, field
from typing import Any, Optional

import hlacore.rti as rti

from hlacore.federates.robot_world import codec
from hlacore.federates.robot_world.federate import WorldFederate
from hlacore.federates.robot_world.world import World

from . import scenario as paper1


class _Reflections(rti.FederateAmbassador):
    def __init__(self) -> None:
        self.names: dict[Any, str] = {}
        self.attributes: dict[Any, str] = {}
        self.latest: dict[str, dict[str, Any]] = {}  # robot -> attribute -> value

    def discoverObjectInstance(self, obj: Any, cls: Any, name: str) -> None:
        """Note the discovered robot's name."""
        self.names[obj] = str(name)

    def reflectAttributeValues(self, obj: Any, attributes: dict[Any, bytes], tag: Any, order: Any,
                               transport: Any, t: Optional[float] = None, retraction: Any = None) -> None:
        """Decode the pose, ranges and stall flag reflected and keep them as the robot's latest."""
        kinds = {"pose": codec.POSE, "ranges": codec.RANGES, "stall": codec.STALL}
        values = self.latest.setdefault(self.names.get(obj, str(obj)), {})
        for handle, data in attributes.items():
            name = self.attributes.get(handle)
            if name in kinds:
                values[name] = codec.unpack(kinds[name], data)


@dataclass
class ControllerFederate:
    """The paper's controller as a federate of the robot world's federation (regulating and constrained)."""

    rtia: rti.RTIAmbassador
    amb: _Reflections
    lookahead: float
    controller: paper1.Controller = field(default_factory=paper1.Controller)
    obstacle_speed: float = 0.3
    obstacle_travel: float = 5.0
    starts: dict[str, float] = field(default_factory=dict)  # obstacle -> initial y
    speeds: list[float] = field(default_factory=list)  # the avatar speed sent each cycle
    _cmd: Any = None
    _params: dict[str, Any] = field(default_factory=dict)

    @classmethod
    def join(cls, address: str, lookahead: float, timeout: float = 10.0) -> "ControllerFederate":
        """Join the RobotWorld federation (it must exist), subscribe, publish cmd_vel and enable time."""
        rtia = rti.RTIAmbassador(address)
        amb = _Reflections()
        rtia.joinFederationExecution("control", codec.FEDERATION, amb)
        robot = rtia.getObjectClassHandle(codec.OBJECT_CLASS)
        amb.attributes = {rtia.getAttributeHandle(n, robot): n for n in codec.ATTRIBUTES}
        rtia.subscribeObjectClassAttributes(robot, list(amb.attributes))
        fed = cls(rtia, amb, lookahead)
        fed._cmd = rtia.getInteractionClassHandle(codec.INTERACTION)
        fed._params = {n: rtia.getParameterHandle(n, fed._cmd) for n in codec.PARAMETERS}
        rtia.publishInteractionClass(fed._cmd)
        rtia.enable_time_management(lookahead, timeout)
        return fed

    def send(self, robot: str, linear: float, stamp: float) -> None:
        """cmd_vel(robot, linear, 0) stamped ``stamp``."""
        p = self._params
        self.rtia.sendInteraction(self._cmd, {p["robot"]: codec.NAME.pack(robot),
                                              p["linear"]: codec.SPEED.pack(linear),
                                              p["angular"]: codec.SPEED.pack(0.0)}, "control", stamp)

    def control(self) -> None:
        """One cycle at the current grant: commands from the latest reflected state, stamped time + lookahead."""
        now = float(self.rtia.queryFederateTime())
        avatar = self.amb.latest.get("avatar", {})
        speed = self.controller(min(avatar["ranges"])) if "ranges" in avatar else 0.0
        self.speeds.append(speed)
        self.send("avatar", speed, now + self.lookahead)
        drive = paper1.ObstacleDriver(self.obstacle_speed, self.obstacle_travel, self.starts)
        for name in paper1.OBSTACLES:
            pose = self.amb.latest.get(name, {}).get("pose")
            if pose is not None:
                self.send(name, drive(name, pose[1]), now + self.lookahead)

    def resign(self) -> None:
        """Resign from the federation."""
        self.rtia.resignFederationExecution(rti.ResignAction.DeleteObjectsAndReleaseAttributes)


def run(address: str, duration: float = 30.0, period: float = 0.1, dt: float = 0.01,
        cycle_timeout: float = 10.0) -> tuple[WorldFederate, ControllerFederate, list[bool]]:
    """Create RobotWorld on the gateway at ``address`` if needed, join the world and the controller, run
    them in lockstep on this thread for ``duration`` s, and return both federates (still joined: resign
    them) and, per grant, whether any robot was stalled. Each cycle gives up after ``cycle_timeout`` s."""
    world = WorldFederate.join(World(paper1.world_spec(), dt=dt, watchdog=0.2), address, period=period,
                               lookahead=period)
    try:
        control = ControllerFederate.join(address, lookahead=period)
    except BaseException:
        world.resign()
        raise
    stalls = []
    for k in range(round(duration / period)):
        control.control()
        control.rtia.timeAdvanceRequest((k + 1) * period)
        world.request()
        deadline = time.monotonic() + cycle_timeout
        world_done = control_done = False
        while not (world_done and control_done):
            if time.monotonic() > deadline:
                raise TimeoutError(f"cycle {k} was not granted within {cycle_timeout} s")
            world_done = world_done or world.poll()
            control_done = control_done or control.rtia.deliver_until_granted()
            if not (world_done and control_done):
                control.rtia.tick(0.001, 0.01)
        stalls.append(any(r.stall for r in world.world.robots))
    return world, control, stalls
