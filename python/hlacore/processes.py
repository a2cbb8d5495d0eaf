"""Running a federation's processes from code: the toolkit of the tests, the benchmarks and their peers.

The conductor side starts an ``rtig`` on a free port (:class:`Rtig`) and Python peers (:func:`python_peer`),
reads the peers' reports (one JSON object per line on stdout) with a deadline, so that a stuck peer fails
the caller instead of hanging it, and stops everything by pid. The peer side reports with :func:`say`,
ticks with a deadline (:func:`tick_until`) and meets the others at a synchronization point
(:class:`SyncAmbassador`, :func:`synchronize`).
"""

from __future__ import annotations

import json
import os
import pathlib
import re
import selectors
import shutil
import signal
import subprocess
import sys
import tempfile
import time
from typing import IO, Any, Callable, NamedTuple, Optional, Sequence

from hlacore import rti

__all__ = ["Child", "ProcessInfo", "Rtig", "SyncAmbassador", "descendants", "linger", "process_info", "python_peer",
           "round_trip", "rtig_beside_python", "say", "serve", "still_running", "synchronize", "tick_until"]


class Child:
    """A child process whose stdout is read as lines with deadlines; stderr goes to a file shown in errors.

    Usable as a context manager: leaving it kills the process if it still runs and releases its pipes.
    """

    def __init__(self, argv: Sequence[str], env: Optional[dict[str, str]] = None,
                 stderr_path: Optional[pathlib.Path] = None, cwd: Optional[str] = None) -> None:
        self._stderr: IO[bytes] = open(stderr_path, "w+b") if stderr_path else tempfile.TemporaryFile()
        self.proc = subprocess.Popen(list(argv), stdin=subprocess.DEVNULL, stdout=subprocess.PIPE,
                                     stderr=self._stderr, bufsize=0, env=env, cwd=cwd)
        self._pending = b""

    @property
    def pid(self) -> int:
        """The process id."""
        return self.proc.pid

    def stderr(self) -> str:
        """What the process wrote on stderr so far (its last 4000 characters)."""
        self._stderr.flush()
        self._stderr.seek(0)
        return self._stderr.read().decode(errors="replace")[-4000:]

    def read_line(self, timeout: float) -> str:
        """The next line of stdout, without its newline; RuntimeError when the process ends or `timeout`
        seconds pass first."""
        assert self.proc.stdout is not None
        deadline = time.monotonic() + timeout
        with selectors.DefaultSelector() as sel:
            sel.register(self.proc.stdout, selectors.EVENT_READ)
            while b"\n" not in self._pending:
                left = deadline - time.monotonic()
                if left <= 0 or not sel.select(left):
                    raise RuntimeError(f"no line from {self._name()} within {timeout} s; stderr: {self.stderr()}")
                chunk = os.read(self.proc.stdout.fileno(), 65536)
                if not chunk:
                    raise RuntimeError(f"{self._name()} exited ({self.proc.wait()}); stderr: {self.stderr()}")
                self._pending += chunk
        line, _, self._pending = self._pending.partition(b"\n")
        return line.decode(errors="replace")

    def read_json(self, timeout: float = 30.0) -> dict[str, Any]:
        """The next report; RuntimeError for a report with an "error" field."""
        result: dict[str, Any] = json.loads(self.read_line(timeout))
        if "error" in result:
            raise RuntimeError(f"{self._name()} reported {result}; stderr: {self.stderr()}")
        return result

    def poll(self) -> Optional[int]:
        """The exit status, or None while the process runs."""
        return self.proc.poll()

    def send_signal(self, sig: int) -> None:
        """Send ``sig`` to the process unless it has exited."""
        if self.proc.poll() is None:
            self.proc.send_signal(sig)

    def wait(self, timeout: float) -> int:
        """The exit status; on timeout the process is killed and RuntimeError raised."""
        try:
            return self.proc.wait(timeout=timeout)
        except subprocess.TimeoutExpired:
            self.kill()
            raise RuntimeError(f"{self._name()} did not exit within {timeout} s") from None

    def terminate(self, timeout: float = 10.0) -> int:
        """SIGTERM, then SIGKILL after `timeout` seconds; returns the exit status."""
        self.send_signal(signal.SIGTERM)
        try:
            return self.proc.wait(timeout=timeout)
        except subprocess.TimeoutExpired:
            self.kill()
            return self.proc.returncode

    def kill(self) -> None:
        """SIGKILL unless it has exited, and reap the process."""
        if self.proc.poll() is None:
            self.proc.kill()
        self.proc.wait()

    def close(self) -> None:
        """Kill if still running and release the pipes (idempotent)."""
        self.kill()
        if self.proc.stdout:
            self.proc.stdout.close()
        self._stderr.close()

    def __enter__(self) -> "Child":
        return self

    def __exit__(self, *exc: object) -> None:
        self.close()

    def _name(self) -> str:
        return f"pid {self.proc.pid} ({' '.join(map(str, self.proc.args))[:200]})"  # type: ignore[arg-type]


def python_peer(script: os.PathLike[str] | str, *args: object, env: Optional[dict[str, str]] = None,
                prefix: Sequence[str] = ()) -> Child:
    """The Python script `script` under this interpreter, unbuffered, with `env` added to the environment;
    `prefix` as for :class:`Rtig`."""
    full_env = dict(os.environ, PYTHONUNBUFFERED="1", **(env or {}))
    return Child([*prefix, sys.executable, str(script), *map(str, args)], env=full_env)


def rtig_beside_python() -> str:
    """The rtig that ``pip install`` put beside this interpreter, else the one on PATH."""
    beside = pathlib.Path(sys.executable).parent / "rtig"
    if beside.exists():
        return str(beside)
    found = shutil.which("rtig")
    if not found:
        raise RuntimeError(f"rtig is not installed ({beside} is missing): pip install hlacore")
    return found


class Rtig:
    """``rtig --port 0`` with extra arguments, stopped by SIGTERM to its pid; its log (stderr) goes to
    `log_path` or a temporary file. As a context manager it raises when rtig exits with a failure.
    `prefix` runs it through another command that executes it in place (``ip netns exec NAMESPACE``)."""

    def __init__(self, *args: str, executable: Optional[str] = None,
                 log_path: Optional[pathlib.Path] = None, prefix: Sequence[str] = ()) -> None:
        self.child = Child([*prefix, executable or rtig_beside_python(), "--port", "0", *args], stderr_path=log_path)
        self.log_path = log_path
        try:
            line = self.child.read_line(timeout=10.0)
        except RuntimeError:
            self.child.close()
            raise
        match = re.fullmatch(r"rtig listening on (\S+):(\d+)(?: and (unix:[^,]+))?(?:, the Federate Protocol on (\S+)(?: \((\w+)\))?)?",
                             line)
        if not match:
            self.child.close()
            raise RuntimeError(f"unexpected rtig readiness line {line!r}")
        self.host, self.port = match.group(1), int(match.group(2))
        self.address = f"{self.host}:{self.port}"
        self.unix_address: Optional[str] = match.group(3)  # with --unix PATH: "unix:PATH"
        self.fedpro_address: Optional[str] = match.group(4)  # with --fedpro HOST:PORT: "host:port"
        # With --fedpro: its transport ("tcp", "tls", "websocket", "websocketsecure").
        self.fedpro_protocol: Optional[str] = (match.group(5) or "tcp") if match.group(4) else None
        self._final_log: Optional[str] = None

    @property
    def proc(self) -> subprocess.Popen[bytes]:
        """The rtig process."""
        return self.child.proc

    def log(self) -> str:
        """rtig's log so far (all of it with a `log_path`, its last 4000 characters otherwise)."""
        if self._final_log is not None:
            return self._final_log
        if self.log_path is not None:  # rtig writes it through its own descriptor: nothing to flush here
            return self.log_path.read_text(errors="replace")
        return self.child.stderr()

    def stop(self) -> int:
        """SIGTERM (SIGKILL after 10 s), and the exit status; idempotent."""
        status = self.child.terminate()
        if self._final_log is None:
            self._final_log = self.log()
        self.child.close()
        return status

    def __enter__(self) -> "Rtig":
        return self

    def __exit__(self, *exc: object) -> None:
        status = self.stop()
        if status != 0 and exc[0] is None:
            raise RuntimeError(f"rtig exited with {status}; log: {self.log()[-4000:]}")


# ---- the peer side ----

def say(**fields: Any) -> None:
    """One JSON line on stdout, flushed: how a peer reports to whoever started it."""
    print(json.dumps(fields), flush=True)


def tick_until(rtia: rti.RTIAmbassador, predicate: Callable[[], bool], timeout: float = 30.0) -> None:
    """Tick until predicate() holds; after `timeout` seconds report {"error": "timeout"} and exit 3."""
    deadline = time.monotonic() + timeout
    while not predicate():
        if time.monotonic() > deadline:
            say(error="timeout")
            sys.exit(3)
        rtia.tick(0.05, 0.1)


def round_trip(rtia: rti.RTIAmbassador) -> None:
    """Return once the gateway has handled everything this federate sent before (it asks to destroy a
    federation that does not exist). The gateway handles each connection's messages in order but
    connections in any order: a federate that subscribes makes this round trip before another sends."""
    try:
        rtia.destroyFederationExecution("hlacore-round-trip")
    except rti.FederationExecutionDoesNotExist:
        pass


def serve(rtia: rti.RTIAmbassador, seconds: float) -> None:
    """Tick (delivering callbacks) until the gateway goes away, for at most `seconds`."""
    deadline = time.monotonic() + seconds
    while time.monotonic() < deadline:
        try:
            rtia.tick(0.05, 0.1)
        except rti.RTIinternalError:
            return  # the connection to the gateway ended


def linger(seconds: float) -> None:
    """Do nothing (never tick) until killed; exit by ourselves after `seconds` as a safety net."""
    deadline = time.monotonic() + seconds
    while time.monotonic() < deadline:
        time.sleep(0.2)


class SyncAmbassador(rti.FederateAmbassador):
    """Keeps the announced and synchronized labels, for :func:`synchronize`."""

    def __init__(self) -> None:
        self.announced: set[str] = set()
        self.synchronized: set[str] = set()

    def announceSynchronizationPoint(self, label: str, tag: str) -> None:
        """Note the announced label."""
        self.announced.add(label)

    def federationSynchronized(self, label: str) -> None:
        """Note the label the federation is synchronized on."""
        self.synchronized.add(label)


def synchronize(rtia: rti.RTIAmbassador, amb: SyncAmbassador, label: str = "start", timeout: float = 60.0) -> None:
    """Wait for `label` to be announced, achieve it, and wait until the federation is synchronized on it."""
    tick_until(rtia, lambda: label in amb.announced, timeout)
    rtia.synchronizationPointAchieved(label)
    tick_until(rtia, lambda: label in amb.synchronized, timeout)


# ---- the process tree, from /proc (Linux) ----


class ProcessInfo(NamedTuple):
    """A live process: its pid, its start time (clock ticks after boot: with the pid, it names the process
    even after the pid is reused) and its command line."""

    pid: int
    start: int
    command: str


def process_info(pid: int) -> Optional[ProcessInfo]:
    """The process `pid`, or None when it is gone (a zombie counts as gone: only its parent's wait is
    missing)."""
    try:
        stat = pathlib.Path(f"/proc/{pid}/stat").read_text()
        command = pathlib.Path(f"/proc/{pid}/cmdline").read_bytes().replace(b"\0", b" ").decode(errors="replace")
    except OSError:
        return None
    fields = stat[stat.rindex(")") + 2:].split()
    return None if fields[0] == "Z" else ProcessInfo(pid, int(fields[19]), command)


def descendants(root: int) -> list[ProcessInfo]:
    """Every live descendant of process `root` (children, theirs, and so on)."""
    children: dict[int, list[int]] = {}
    for entry in pathlib.Path("/proc").iterdir():
        if entry.name.isdigit():
            try:
                stat = (entry / "stat").read_text()
            except OSError:
                continue
            children.setdefault(int(stat[stat.rindex(")") + 2:].split()[1]), []).append(int(entry.name))
    found, todo = [], list(children.get(root, []))
    while todo:
        pid = todo.pop()
        info = process_info(pid)
        if info:
            found.append(info)
        todo.extend(children.get(pid, []))
    return found


def still_running(process: ProcessInfo) -> bool:
    """Whether `process` (the same one, not a reuse of its pid) is alive."""
    now = process_info(process.pid)
    return now is not None and now.start == process.start
