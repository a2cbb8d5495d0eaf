"""For the scenario runners that hold the robot world federate and a :class:`~.bridge.RosBridge` in one
process, with a ROS node in another: :func:`wait_wired` waits until the node has connected to the bridge's
topics, :class:`WorldThread` runs the world on a thread of its own while the bridge spins on the calling
thread."""

from __future__ import annotations

import subprocess
import threading
import time
from typing import TYPE_CHECKING, Any, Sequence

if TYPE_CHECKING:
    from hlacore.federates.robot_world import WorldFederate

    from .bridge import RosBridge

__all__ = ["WorldThread", "wait_wired"]


def wait_wired(bridge: RosBridge, topics: Sequence[str], node: subprocess.Popen[Any], timeout: float) -> bool:
    """Wait until each of ``topics`` has a ROS connection on ``bridge``: True; False as soon as ``node`` (the
    process that is to connect) has ended or ``timeout`` s have passed."""
    deadline = time.monotonic() + timeout
    while not all(bridge.connections().get(t, 0) > 0 for t in topics):
        if node.poll() is not None or time.monotonic() > deadline:
            return False
        time.sleep(0.05)
    return True


class WorldThread:
    """``world.run_until(until, timeout=timeout)`` on a thread named ``world``, started at once. What it
    raises goes to :meth:`fail`; :meth:`join` raises it on the calling thread."""

    def __init__(self, world: WorldFederate, until: float, timeout: float, bridge: RosBridge) -> None:
        self.failure: list[BaseException] = []  #: what went wrong (the first is raised by :meth:`join`)
        self._world = world
        self._until = until
        self._timeout = timeout
        self._bridge = bridge
        self._thread = threading.Thread(target=self._run, name="world")
        self._thread.start()

    def _run(self) -> None:
        try:
            self._world.run_until(self._until, timeout=self._timeout)
        except BaseException as exc:  # reported on the calling thread
            self.fail(exc)

    def fail(self, exc: BaseException) -> None:
        """Note ``exc`` for :meth:`join` and stop the bridge (its :meth:`~.RosBridge.spin` returns); safe from
        any thread."""
        self.failure.append(exc)
        self._bridge.stop()

    def join(self) -> None:
        """Wait up to ``timeout`` s for the world; raise the first failure, or TimeoutError if it still runs."""
        self._thread.join(self._timeout)
        if self.failure:
            raise self.failure[0]
        if self._thread.is_alive():
            raise TimeoutError("the world federate did not finish")
