"""An HLA federate that drives a robot of the RobotWorld federation: forward at SPEED m/s until its range
sensor reads STOP metres or less, then a stop command. With the ROS bridge in between (docs/own-robot.md),
the robot is a ROS node: a real one, or docs/own-robot/my_robot.py.

    python docs/own-robot/drive.py NAME [--rtig HOST:PORT] [--speed 0.3] [--stop 0.5] [--timeout 60]

Exits 0 after printing where the robot stopped; 1 when it did not get there within the timeout."""

from __future__ import annotations

import argparse
import sys
import time

import hlacore.rti as rti
from hlacore.federates.robot_world import codec


class Watcher(rti.FederateAmbassador):
    """Keeps the latest odometry and nearest range of the robot called `name`."""

    def __init__(self, name: str) -> None:
        self.name = name
        self.objects: dict[rti.ObjectHandle, str] = {}  # instances are registered under the robot's name
        self.odometry: tuple[float, ...] | None = None  # x, y, heading, linear, angular
        self.nearest: float | None = None
        self.attributes: dict[str, rti.AttributeHandle] = {}

    def discoverObjectInstance(self, obj, objectClass, name):
        self.objects[obj] = name

    def reflectAttributeValues(self, obj, attributes, tag, order, transport, time=None, retraction=None):
        if self.objects.get(obj) != self.name:
            return
        if self.attributes["odometry"] in attributes:
            self.odometry = codec.unpack(codec.ODOMETRY, attributes[self.attributes["odometry"]])
        if self.attributes["ranges"] in attributes:
            beams = codec.unpack(codec.RANGES, attributes[self.attributes["ranges"]])
            self.nearest = min(beams) if beams else None


def main() -> int:
    parser = argparse.ArgumentParser(description=__doc__.split("\n\n")[0])
    parser.add_argument("name")
    parser.add_argument("--rtig", default=None, help="the gateway (default $HLACORE_RTIG or 127.0.0.1:60400)")
    parser.add_argument("--speed", type=float, default=0.3)
    parser.add_argument("--stop", type=float, default=0.5)
    parser.add_argument("--timeout", type=float, default=60.0)
    args = parser.parse_args()

    rtia = rti.RTIAmbassador(args.rtig) if args.rtig else rti.RTIAmbassador()
    watcher = Watcher(args.name)
    rtia.create_or_join(f"drive-{args.name}", codec.FEDERATION, str(codec.FOM_PATH), watcher)
    robot_class = rtia.getObjectClassHandle(codec.OBJECT_CLASS)
    watcher.attributes = {a: rtia.getAttributeHandle(a, robot_class) for a in ("odometry", "ranges")}
    rtia.subscribeObjectClassAttributes(robot_class, list(watcher.attributes.values()))
    cmd_vel = rtia.getInteractionClassHandle(codec.INTERACTION)
    parameters = {p: rtia.getParameterHandle(p, cmd_vel) for p in codec.PARAMETERS}
    rtia.publishInteractionClass(cmd_vel)

    def command(linear: float) -> None:
        rtia.sendInteraction(cmd_vel, {parameters["robot"]: codec.NAME.pack(args.name),
                                       parameters["linear"]: codec.SPEED.pack(linear),
                                       parameters["angular"]: codec.SPEED.pack(0.0)}, "drive")

    deadline = time.monotonic() + args.timeout
    try:
        while watcher.nearest is None or watcher.nearest > args.stop:
            if time.monotonic() > deadline:
                print(f"drive: {args.name} did not come within {args.stop} m of an obstacle in {args.timeout} s "
                      f"(odometry {watcher.odometry}, nearest {watcher.nearest})", file=sys.stderr)
                return 1
            command(args.speed)  # a robot's driver usually stops when commands stop coming: keep sending
            rtia.tick(0.1, 0.1)
        command(0.0)
        assert watcher.odometry is not None
        print(f"drive: {args.name} stopped {watcher.nearest:.2f} m from the obstacle, "
              f"at x={watcher.odometry[0]:.2f} m", flush=True)
        return 0
    finally:
        rtia.resignFederationExecution(rti.ResignAction.DeleteObjectsAndReleaseAttributes)


if __name__ == "__main__":
    sys.exit(main())
