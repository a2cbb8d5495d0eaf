"""The Tx/Rx driver: sends protocol requests to the device and reads the replies, over a serial port or a pty.

``TxRxDriver.open(path)`` picks the transport: ``"pty"`` opens the path as a raw file descriptor (a pty,
or any tty already configured), ``"serial"`` uses pyserial (``pip install pyserial``) at ``baudrate``,
``"auto"`` takes pyserial when it is installed and the raw descriptor otherwise.
"""

from __future__ import annotations

import os
import select
import time
from typing import Any, Protocol

from .protocol import Reply, encode_drive, encode_request, parse_reply

__all__ = ["Transport", "FdTransport", "SerialTransport", "TxRxDriver", "Pose", "Ranges"]

Pose = tuple[float, float, float]
Ranges = tuple[float, float, float]


class Transport(Protocol):
    """A byte stream to the device."""

    def write(self, data: bytes) -> None:
        """Send ``data``."""

    def read_line(self, timeout: float) -> bytes:
        """One line without its newline; TimeoutError after ``timeout`` seconds."""

    def close(self) -> None:
        """Release the stream."""


class FdTransport:
    """A tty or pty opened as a file descriptor (``O_RDWR | O_NOCTTY``)."""

    def __init__(self, path: str) -> None:
        self.fd = os.open(path, os.O_RDWR | os.O_NOCTTY)
        self._pending = b""

    def write(self, data: bytes) -> None:
        """Write all of ``data``."""
        view = memoryview(data)
        while view:
            view = view[os.write(self.fd, view):]

    def read_line(self, timeout: float) -> bytes:
        """The next line without its newline; TimeoutError after ``timeout`` seconds, ConnectionError
        when the device closes the stream."""
        deadline = time.monotonic() + timeout
        while b"\n" not in self._pending:
            remaining = deadline - time.monotonic()
            if remaining <= 0:
                raise TimeoutError(f"no reply from the device within {timeout} s")
            ready, _, _ = select.select([self.fd], [], [], remaining)
            if ready:
                chunk = os.read(self.fd, 4096)
                if not chunk:
                    raise ConnectionError("the device closed the stream")
                self._pending += chunk
        line, self._pending = self._pending.split(b"\n", 1)
        return line

    def close(self) -> None:
        """Close the file descriptor (idempotent)."""
        if self.fd >= 0:
            os.close(self.fd)
            self.fd = -1


class SerialTransport:
    """A serial port through pyserial (an optional dependency)."""

    def __init__(self, path: str, baudrate: int = 115200) -> None:
        try:
            import serial  # type: ignore[import-untyped, import-not-found, unused-ignore]
        except ImportError:
            raise RuntimeError(
                "the serial transport needs pyserial (pip install pyserial); "
                "for a pty or a configured tty use transport='pty'"
            ) from None
        self.port: Any = serial.Serial(path, baudrate=baudrate, timeout=0.1)

    def write(self, data: bytes) -> None:
        """Write ``data`` and flush it to the port."""
        self.port.write(data)
        self.port.flush()

    def read_line(self, timeout: float) -> bytes:
        """The next line without its newline; TimeoutError after ``timeout`` seconds."""
        deadline = time.monotonic() + timeout
        line = b""
        while not line.endswith(b"\n"):
            if time.monotonic() > deadline:
                raise TimeoutError(f"no reply from the device within {timeout} s")
            line += self.port.readline()
        return line[:-1]

    def close(self) -> None:
        """Close the serial port."""
        self.port.close()


class TxRxDriver:
    """The robot's commands as methods; each sends one request and waits for its reply.

    ``timeout`` bounds each wait (a move replies once the motors stopped: allow for the time scale).
    """

    def __init__(self, transport: Transport, timeout: float = 30.0) -> None:
        self.transport = transport
        self.timeout = timeout

    @classmethod
    def open(cls, path: str, transport: str = "auto", baudrate: int = 115200, timeout: float = 30.0) -> "TxRxDriver":
        """Open the device at ``path`` with ``transport`` ``"auto"``, ``"pty"`` or ``"serial"``."""
        if transport not in ("auto", "pty", "serial"):
            raise ValueError(f"transport must be auto, pty or serial, not {transport!r}")
        chosen: Transport
        if transport == "serial":
            chosen = SerialTransport(path, baudrate)
        elif transport == "auto" and _has_pyserial():
            chosen = SerialTransport(path, baudrate)
        else:
            chosen = FdTransport(path)
        return cls(chosen, timeout)

    def request(self, command: str) -> Reply:
        """Send ``command`` and return its reply; ProtocolError on ``err``."""
        self.transport.write(encode_request(command))
        return parse_reply(self.transport.read_line(self.timeout))

    def go_front(self) -> float:
        """``goFront``; returns the simulated seconds the motors ran."""
        return self.request("goFront").fields[0]

    def go_back(self) -> float:
        """``goBack``; returns the simulated seconds the motors ran."""
        return self.request("goBack").fields[0]

    def turn_left(self) -> float:
        """``turnLeft``; returns the simulated seconds the motors ran."""
        return self.request("turnLeft").fields[0]

    def turn_right(self) -> float:
        """``turnRight``; returns the simulated seconds the motors ran."""
        return self.request("turnRight").fields[0]

    def command(self, name: str) -> float:
        """Any motor command by its protocol name; returns the simulated seconds."""
        return self.request(name).fields[0]

    def drive(self, linear: float, angular: float, seconds: float) -> float:
        """``drive``: motors at ``linear`` m/s and ``angular`` rad/s for ``seconds``; returns the simulated
        seconds the motors ran (ValueError before sending for non-finite numbers or a bad duration)."""
        self.transport.write(encode_drive(linear, angular, seconds))
        return parse_reply(self.transport.read_line(self.timeout)).fields[0]

    def read_sensors(self) -> Ranges:
        """``readSensors``: front, left and right distances in metres."""
        front, left, right = self.request("readSensors").fields
        return front, left, right

    def read_position(self) -> Pose:
        """``readPosition``: x, y (metres) and heading (degrees)."""
        x, y, heading = self.request("readPosition").fields
        return x, y, heading

    def close(self) -> None:
        """Close the transport."""
        self.transport.close()


def _has_pyserial() -> bool:
    try:
        import serial  # type: ignore[import-untyped, import-not-found, unused-ignore]  # noqa: F401
    except ImportError:
        return False
    return True
