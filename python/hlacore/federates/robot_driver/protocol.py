"""The robot's command protocol over a byte stream (serial port or pty): one ASCII line each way.

Request: the command name and ``\\n``. Reply: ``ok`` and fields separated by spaces, or ``err`` and a
message, then ``\\n``. Numbers are decimal (``repr`` of a float).

===============  ==========================================  ===================================
command          effect                                      reply fields
===============  ==========================================  ===================================
``goFront``      motors forward for one cell (nominal 2 s)   simulated seconds the motors ran
``goBack``       motors backward for one cell (nominal 2 s)  simulated seconds the motors ran
``turnLeft``     rotate 90 degrees counter-clockwise (1 s)   simulated seconds the motors ran
``turnRight``    rotate 90 degrees clockwise (1 s)           simulated seconds the motors ran
``readSensors``  read the three range sensors                front, left, right distances (m)
``readPosition`` read the position tracker                   x (m), y (m), heading (degrees)
``drive V W S``  motors at V m/s and W rad/s for S seconds   simulated seconds the motors ran
===============  ==========================================  ===================================

``drive`` is the one command with arguments (decimal numbers; S between 0 and :data:`MAX_DRIVE_SECONDS`):
the velocity form a ROS robot is driven with, for controllers that steer continuously. A move replies once the motors stopped. Heading 0 faces the first coordinate's growth, 90 the second's.
"""

from __future__ import annotations

import math
from dataclasses import dataclass

__all__ = ["COMMANDS", "MOVES", "DRIVE", "MAX_DRIVE_SECONDS", "encode_drive", "parse_drive", "Reply", "ProtocolError", "encode_request", "parse_reply", "format_reply"]

#: Commands that run the motors.
MOVES = ("goFront", "goBack", "turnLeft", "turnRight")
#: Every command the device understands.
COMMANDS = MOVES + ("readSensors", "readPosition")
#: The velocity command: ``drive LINEAR ANGULAR SECONDS``.
DRIVE = "drive"
#: The longest ``drive`` accepted, seconds (a bound on one blocking request).
MAX_DRIVE_SECONDS = 60.0


class ProtocolError(RuntimeError):
    """The device replied ``err``, or something that is not a reply."""


@dataclass(frozen=True)
class Reply:
    """A decoded ``ok`` reply: its numeric fields."""

    fields: tuple[float, ...]


def encode_request(command: str) -> bytes:
    """The bytes of a request; raises ValueError for an unknown command."""
    if command not in COMMANDS:
        raise ValueError(f"unknown command {command!r}; the protocol has {', '.join(COMMANDS)}")
    return command.encode("ascii") + b"\n"


def encode_drive(linear: float, angular: float, seconds: float) -> bytes:
    """The bytes of a ``drive`` request; raises ValueError for a non-finite number or a bad duration."""
    return DRIVE.encode("ascii") + b" " + " ".join(repr(v) for v in _drive_values(linear, angular, seconds)).encode(
        "ascii") + b"\n"


def parse_drive(words: list[str]) -> tuple[float, float, float]:
    """The arguments of a ``drive`` request split into words (without the name); ValueError when they are
    not three finite numbers with a duration in ``[0, MAX_DRIVE_SECONDS]``."""
    if len(words) != 3:
        raise ValueError(f"drive takes linear, angular and seconds, got {len(words)} arguments")
    try:
        linear, angular, seconds = (float(w) for w in words)
    except ValueError:
        raise ValueError(f"drive arguments are not numbers: {' '.join(words)!r}") from None
    return _drive_values(linear, angular, seconds)


def _drive_values(linear: float, angular: float, seconds: float) -> tuple[float, float, float]:
    values = (float(linear), float(angular), float(seconds))
    if not all(math.isfinite(v) for v in values):
        raise ValueError(f"drive arguments must be finite, got {values}")
    if not 0.0 <= values[2] <= MAX_DRIVE_SECONDS:
        raise ValueError(f"drive duration must be within [0, {MAX_DRIVE_SECONDS}] s, got {values[2]}")
    return values


def format_reply(fields: tuple[float, ...] = (), error: str = "") -> bytes:
    """The bytes of a reply: ``err message`` when ``error`` is set, else ``ok`` and the fields."""
    if error:
        return f"err {error}\n".encode("ascii", "replace")
    return (" ".join(["ok", *(repr(float(f)) for f in fields)]) + "\n").encode("ascii")


def parse_reply(line: bytes) -> Reply:
    """Decode one reply line; raises :class:`ProtocolError` for ``err`` or garbage."""
    words = line.decode("ascii", "replace").split()
    if not words or words[0] not in ("ok", "err"):
        raise ProtocolError(f"not a reply: {line!r}")
    if words[0] == "err":
        raise ProtocolError("device error: " + " ".join(words[1:]))
    try:
        return Reply(tuple(float(w) for w in words[1:]))
    except ValueError:
        raise ProtocolError(f"bad number in reply {line!r}") from None
