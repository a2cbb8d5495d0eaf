"""The simulated device: a process that answers the command protocol on the master side of a pty.

:func:`spawn_simulated_device` opens a pty (``os.openpty``), starts the device process (:func:`main`) on the
master side and returns a :class:`SimulatedDevice` whose
:attr:`~SimulatedDevice.path` (``/dev/pts/N``) a :class:`~.driver.TxRxDriver` opens like a serial port.
The device moves a :class:`~.kinematics.Body` and sleeps ``simulated seconds * time_scale`` of wall time
per move (0: no sleeping, for tests; 1: the paper's real 2 s per cell).

The process ends on end of stream (the other side closed), after ``--idle-timeout`` seconds without a
command, or on SIGTERM.
"""

from __future__ import annotations

import argparse
import math
import os
import select
import subprocess
import sys
import time
import tty
from dataclasses import dataclass
from typing import Callable, Optional, Sequence

from .kinematics import Body, Calibration
from .navigation import Scenario
from .protocol import COMMANDS, DRIVE, format_reply, parse_drive

__all__ = ["DeviceServer", "SimulatedDevice", "spawn_simulated_device", "main"]


# Run through -c, not -m: the package imports this module, and runpy warns when re-running it as __main__.
_ENTRY = "import sys; from hlacore.federates.robot_driver.device import main; sys.exit(main())"


class DeviceServer:
    """Executes protocol commands on a :class:`Body`; :meth:`handle` maps one request line to its reply."""

    def __init__(self, body: Body, time_scale: float = 0.0, sleep: Callable[[float], None] = time.sleep) -> None:
        self.body = body
        self.time_scale = time_scale
        self._sleep = sleep

    def handle(self, line: bytes) -> bytes:
        """The reply to one request line (without its newline)."""
        command = line.decode("ascii", "replace").strip()
        body = self.body
        if command.split(" ", 1)[0] == DRIVE:
            try:
                linear, angular, nominal = parse_drive(command.split()[1:])
            except ValueError as error:
                return format_reply(error=str(error))
            seconds = body.drive_velocity(linear, angular, nominal)
            if self.time_scale > 0:
                self._sleep(seconds * self.time_scale)
            return format_reply((seconds,))
        if command not in COMMANDS:
            return format_reply(error=f"unknown command {command!r}")
        if command == "readSensors":
            return format_reply((body.range(0.0), body.range(90.0), body.range(-90.0)))
        if command == "readPosition":
            return format_reply((body.x, body.y, math.degrees(body.heading)))
        if command == "goFront":
            seconds = body.drive(+1, 2.0)
        elif command == "goBack":
            seconds = body.drive(-1, 2.0)
        elif command == "turnLeft":
            seconds = body.turn(+1, 1.0)
        else:
            seconds = body.turn(-1, 1.0)
        if self.time_scale > 0:
            self._sleep(seconds * self.time_scale)
        return format_reply((seconds,))

    def serve(self, fd: int, idle_timeout: float) -> None:
        """Answer requests on ``fd`` until end of stream or ``idle_timeout`` seconds without input."""
        pending = b""
        while True:
            ready, _, _ = select.select([fd], [], [], idle_timeout)
            if not ready:
                return
            try:
                chunk = os.read(fd, 4096)
            except OSError:  # EIO: the slave side is closed
                return
            if not chunk:
                return
            pending += chunk
            while b"\n" in pending:
                line, pending = pending.split(b"\n", 1)
                if line.strip():
                    reply = self.handle(line)
                    os.write(fd, reply)


@dataclass
class SimulatedDevice:
    """A running simulated device: its process and the pty path to open (keep it; :meth:`close` it)."""

    process: subprocess.Popen[bytes]
    path: str
    _slave_fd: int

    def close(self) -> int:
        """Close our side of the pty, end the process by pid (SIGTERM, then SIGKILL) and return its status."""
        if self._slave_fd >= 0:
            os.close(self._slave_fd)
            self._slave_fd = -1
        if self.process.poll() is None:
            self.process.terminate()
            try:
                self.process.wait(timeout=5)
            except subprocess.TimeoutExpired:
                self.process.kill()
                self.process.wait()
        return int(self.process.returncode)

    def __enter__(self) -> "SimulatedDevice":
        return self

    def __exit__(self, *exc: object) -> None:
        self.close()


def spawn_simulated_device(
    scenario: Scenario,
    calibration: Calibration = Calibration(),
    time_scale: float = 0.0,
    heading_deg: float = 90.0,
    idle_timeout: float = 120.0,
    open_floor: bool = False,
) -> SimulatedDevice:
    """Start the device process on a new pty; returns it with the slave path for the driver."""
    master, slave = os.openpty()
    tty.setraw(slave)  # no echo, no line editing, no CR/LF translation: a byte stream like a serial line
    try:
        args = [
            sys.executable, "-c", _ENTRY, "--fd", str(master),
            "--world", scenario.to_text(), "--time-scale", repr(time_scale), "--heading", repr(heading_deg),
            "--motor-time-error", repr(calibration.motor_time_error), "--friction", repr(calibration.friction),
            "--wheel-bias", repr(calibration.wheel_bias), "--idle-timeout", repr(idle_timeout),
            "--defective-wheel", repr(calibration.defective_wheel),
        ] + (["--open-floor"] if open_floor else [])
        process = subprocess.Popen(args, pass_fds=(master,), stdin=subprocess.DEVNULL)
    except BaseException:
        os.close(slave)
        raise
    finally:
        os.close(master)
    return SimulatedDevice(process, os.ttyname(slave), slave)


def main(argv: Optional[Sequence[str]] = None) -> int:
    """Serve the protocol on an inherited file descriptor (the pty master)."""
    parser = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    parser.add_argument("--fd", type=int, required=True, help="file descriptor of the byte stream")
    parser.add_argument("--world", required=True, help="the scenario in its text form")
    parser.add_argument("--time-scale", type=float, default=0.0, help="wall seconds per simulated second")
    parser.add_argument("--heading", type=float, default=90.0, help="initial heading, degrees")
    parser.add_argument("--motor-time-error", type=float, default=0.0)
    parser.add_argument("--friction", type=float, default=0.0)
    parser.add_argument("--wheel-bias", type=float, default=0.0)
    parser.add_argument("--defective-wheel", type=float, default=0.0, help="fraction of speed the right wheel loses")
    parser.add_argument("--open-floor", action="store_true", help="no wall or border stops the body")
    parser.add_argument("--idle-timeout", type=float, default=120.0, help="exit after this long without input")
    args = parser.parse_args(argv)
    calibration = Calibration(args.motor_time_error, args.friction, args.wheel_bias, args.defective_wheel)
    body = Body(Scenario.parse(args.world), calibration, args.heading, open_floor=args.open_floor)
    try:
        DeviceServer(body, args.time_scale).serve(args.fd, args.idle_timeout)
    except KeyboardInterrupt:
        pass
    return 0


if __name__ == "__main__":
    sys.exit(main())
