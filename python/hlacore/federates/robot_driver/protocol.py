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
===============  ==========================================  ===================================

A move replies once the motors stopped. Heading 0 faces the first coordinate's growth, 90 the second's.
"""

from __future__ import annotations

from dataclasses import dataclass

__all__ = ["COMMANDS", "MOVES", "Reply", "ProtocolError", "encode_request", "parse_reply", "format_reply"]

#: Commands that run the motors.
MOVES = ("goFront", "goBack", "turnLeft", "turnRight")
#: Every command the device understands.
COMMANDS = MOVES + ("readSensors", "readPosition")


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
