"""Child processes of a scenario command: started with this Python, their output read line by line for
bounded waits, and ended by pid (SIGTERM, then SIGKILL if they linger) — never by name."""

from __future__ import annotations

import os
import queue
import signal
import subprocess
import sys
import threading
import time
from typing import Any, Optional, Sequence

__all__ = ["Child", "Children", "stop_process"]


def stop_process(proc: "subprocess.Popen[Any]", sig: int = signal.SIGTERM, timeout: float = 15.0) -> int:
    """Send ``sig`` to ``proc`` by pid, wait up to ``timeout`` s, SIGKILL it by pid if it lingers; returns
    its exit status."""
    if proc.poll() is None:
        proc.send_signal(sig)
        try:
            proc.wait(timeout)
        except subprocess.TimeoutExpired:
            proc.kill()
            proc.wait()
    return int(proc.returncode)


class Child:
    """One child process and the lines it printed (stdout and stderr merged)."""

    def __init__(self, name: str, args: Sequence[str], env: Optional[dict[str, str]] = None,
                 prefix: Sequence[str] = ()) -> None:
        self.name = name
        self.proc: subprocess.Popen[str] = subprocess.Popen(
            [*prefix, sys.executable, *args], stdout=subprocess.PIPE, stderr=subprocess.STDOUT,
            stdin=subprocess.DEVNULL, text=True, env=env)
        self.seen: list[str] = []
        self._lines: "queue.Queue[Optional[str]]" = queue.Queue()
        self._reader = threading.Thread(target=self._read, name=f"{name}-stdout", daemon=True)
        self._reader.start()

    def _read(self) -> None:
        assert self.proc.stdout is not None
        for line in self.proc.stdout:
            self._lines.put(line.rstrip("\n"))
        self._lines.put(None)  # end of output

    def wait_for(self, prefix: str, timeout: float) -> str:
        """The first line starting with ``prefix``, within ``timeout`` s; RuntimeError with the output
        otherwise (the child ended, or it took too long)."""
        deadline = time.monotonic() + timeout
        while True:
            try:
                line = self._lines.get(timeout=max(0.0, min(0.2, deadline - time.monotonic())))
            except queue.Empty:
                if time.monotonic() > deadline:
                    raise RuntimeError(self.report(f"no {prefix!r} within {timeout} s")) from None
                continue
            if line is None:
                self._lines.put(None)
                raise RuntimeError(self.report(f"ended (status {self.proc.wait()}) before {prefix!r}"))
            self.seen.append(line)
            if line.startswith(prefix):
                return line

    def wait(self, timeout: float) -> int:
        """Wait for the child to exit (RuntimeError after ``timeout`` s); returns its status."""
        try:
            return self.proc.wait(timeout)
        except subprocess.TimeoutExpired:
            raise RuntimeError(self.report(f"still running after {timeout} s")) from None

    def stop(self, timeout: float = 15.0) -> int:
        """SIGTERM by pid, wait, SIGKILL by pid if it lingers; returns the exit status."""
        stop_process(self.proc, timeout=timeout)
        self._reader.join(5.0)
        while not self._lines.empty():
            line = self._lines.get()
            if line is not None:
                self.seen.append(line)
        if self.proc.stdout is not None and not self._reader.is_alive():
            self.proc.stdout.close()
        return self.proc.returncode

    def report(self, what: str) -> str:
        """``what``, with the child's name and its output so far."""
        tail = "\n".join(self.seen[-40:])
        return f"{self.name} (pid {self.proc.pid}) {what}; its output:\n{tail}"


class Children:
    """Children started in a ``with`` block, each stopped by pid when it ends (in reverse order)."""

    def __init__(self, env: Optional[dict[str, str]] = None) -> None:
        self.env = env
        self.children: list[Child] = []

    def start(self, name: str, args: Sequence[str], prefix: Sequence[str] = (),
              env: Optional[dict[str, str]] = None) -> Child:
        """Start ``python args...``, through ``prefix`` (a command that runs it in place, such as ``ip netns
        exec HOST``) and with ``env`` added to the environment."""
        child = Child(name, args, {**(self.env if self.env is not None else os.environ), **(env or {})}, prefix)
        self.children.append(child)
        return child

    def __enter__(self) -> "Children":
        return self

    def __exit__(self, *exc: object) -> None:
        for child in reversed(self.children):
            child.stop()
