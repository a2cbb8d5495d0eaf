"""Child processes of a benchmark: the rtig server and the Python peers. Each is started here and ended
by its pid here; their stdout is read line by line with a deadline so that a stuck peer fails the run
instead of hanging it."""

from __future__ import annotations

import json
import os
import pathlib
import re
import selectors
import signal
import subprocess
import sys
import tempfile
import time
from typing import Any, Optional

PEERS = pathlib.Path(__file__).parent / "peers"


class Child:
    """A process whose stdout is parsed as lines; stderr goes to a temporary file shown on failure."""

    def __init__(self, argv: list[str], env: Optional[dict[str, str]] = None) -> None:
        self._stderr = tempfile.TemporaryFile()
        self.proc = subprocess.Popen(
            argv, stdin=subprocess.DEVNULL, stdout=subprocess.PIPE, stderr=self._stderr, bufsize=0, env=env
        )
        self._pending = b""

    def stderr(self) -> str:
        self._stderr.seek(0)
        return self._stderr.read().decode(errors="replace")[-4000:]

    def read_line(self, timeout: float) -> str:
        """The next line of stdout; RuntimeError when the process exits or `timeout` seconds pass first."""
        assert self.proc.stdout is not None
        deadline = time.monotonic() + timeout
        with selectors.DefaultSelector() as sel:
            sel.register(self.proc.stdout, selectors.EVENT_READ)
            while b"\n" not in self._pending:
                left = deadline - time.monotonic()
                if left <= 0 or not sel.select(left):
                    raise RuntimeError(f"no line from {self.proc.args!r} within {timeout} s; stderr: {self.stderr()}")
                chunk = os.read(self.proc.stdout.fileno(), 65536)
                if not chunk:
                    raise RuntimeError(f"{self.proc.args!r} exited ({self.proc.wait()}); stderr: {self.stderr()}")
                self._pending += chunk
        line, _, self._pending = self._pending.partition(b"\n")
        return line.decode()

    def read_json(self, timeout: float = 30.0) -> dict[str, Any]:
        result: dict[str, Any] = json.loads(self.read_line(timeout))
        if "error" in result:
            raise RuntimeError(f"{self.proc.args!r} reported {result}; stderr: {self.stderr()}")
        return result

    def wait(self, timeout: float) -> int:
        """Wait for a clean exit; on timeout, kill by pid and raise."""
        try:
            return self.proc.wait(timeout=timeout)
        except subprocess.TimeoutExpired:
            self.kill()
            raise RuntimeError(f"{self.proc.args!r} did not exit within {timeout} s") from None

    def terminate(self, timeout: float = 10.0) -> int:
        if self.proc.poll() is None:
            self.proc.send_signal(signal.SIGTERM)
        try:
            return self.proc.wait(timeout=timeout)
        except subprocess.TimeoutExpired:
            self.kill()
            return self.proc.returncode

    def kill(self) -> None:
        if self.proc.poll() is None:
            self.proc.kill()
        self.proc.wait()

    def close(self) -> None:
        """Kill if still running and release the pipes (idempotent)."""
        self.kill()
        if self.proc.stdout:
            self.proc.stdout.close()
        self._stderr.close()


def python_peer(script: str, *args: object) -> Child:
    """bench/peers/<script> under this interpreter."""
    env = dict(os.environ, PYTHONUNBUFFERED="1")
    return Child([sys.executable, str(PEERS / script), *map(str, args)], env=env)


def close_all(children: list[Child]) -> None:
    for child in children:
        child.close()


def installed_rtig() -> str:
    """The Release rtig that `pip install .` put beside this interpreter ($HLACORE_BENCH_RTIG overrides)."""
    explicit = os.environ.get("HLACORE_BENCH_RTIG")
    if explicit:
        return explicit
    beside = pathlib.Path(sys.executable).parent / "rtig"
    if not beside.exists():
        raise RuntimeError(f"{beside} is missing: run ./scripts/bench.sh (it pip-installs hlacore)")
    return str(beside)


class RtigServer:
    """`rtig --port 0`, stopped by SIGTERM to its pid; `address` is "host:port"."""

    def __init__(self, executable: Optional[str] = None) -> None:
        self.child = Child([executable or installed_rtig(), "--port", "0"])
        line = self.child.read_line(timeout=10.0)
        match = re.fullmatch(r"rtig listening on (\S+):(\d+)", line)
        if not match:
            self.child.close()
            raise RuntimeError(f"unexpected rtig line {line!r}")
        self.address = f"{match.group(1)}:{match.group(2)}"
        self.log = ""

    def stop(self) -> int:
        status = self.child.terminate()
        self.log = self.child.stderr()
        self.child.close()
        return status

    def __enter__(self) -> "RtigServer":
        return self

    def __exit__(self, *exc: object) -> None:
        status = self.stop()
        if status != 0 and exc[0] is None:
            raise RuntimeError(f"rtig exited with {status}; stderr: {self.log}")
