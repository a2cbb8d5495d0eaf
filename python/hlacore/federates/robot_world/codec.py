"""The encodings of the robot world's FOM (``hlacore/foms/robot_world.fed``), with hlacore.omt types."""

from __future__ import annotations

import pathlib

from hlacore import omt

#: The FED file of the robot world.
FOM_PATH = pathlib.Path(__file__).resolve().parent.parent.parent / "foms" / "robot_world.fed"
FEDERATION = "RobotWorld"
OBJECT_CLASS = "WorldRobot"
ATTRIBUTES = ("name", "pose", "odometry", "ranges", "stall")
INTERACTION = "cmd_vel"
PARAMETERS = ("robot", "linear", "angular")

NAME = omt.HLAASCIIstring
POSE = omt.HLAfixedArray("Pose", omt.HLAfloat64BE, 3)
ODOMETRY = omt.HLAfixedArray("Odometry", omt.HLAfloat64BE, 5)
RANGES = omt.HLAvariableArray("Ranges", omt.HLAfloat64BE)
STALL = omt.HLAboolean
SPEED = omt.HLAfloat64BE


def unpack(kind: omt.HLAdataType, data: bytes) -> object:
    """Decode a whole value, checking that nothing is left over."""
    value, size = kind.unpack(data)
    if size != len(data):
        raise ValueError(f"{kind.name}: {len(data) - size} bytes left over")
    return value


def unpack_name(data: bytes) -> str:
    """Decode an HLAASCIIstring robot name."""
    value = unpack(NAME, data)
    return value.decode("ascii") if isinstance(value, (bytes, bytearray)) else str(value)
