"""asyncio forms of the blocking conveniences: wait on the connection's socket, never poll.

::

    fed = hlacore.aio.AsyncAmbassador(rtia)     # rtia: a joined hlacore.rti.RTIAmbassador
    granted = await fed.advance_to(10.0)        # timeAdvanceRequest(10.0), callbacks delivered meanwhile

The event loop watches the socket with ``loop.add_reader``; when it is readable the ambassador reads
what is there without blocking and delivers the callbacks on the loop's thread. Use one ambassador
from one event loop.
"""

from __future__ import annotations

import asyncio
from typing import Any, Optional

from . import _core
from .rti import RTIAmbassador


class AsyncAmbassador:
    """Wraps a :class:`hlacore.rti.RTIAmbassador`; other attributes are forwarded to it."""

    def __init__(self, rtia: RTIAmbassador) -> None:
        self.rtia = rtia

    def __getattr__(self, name: str) -> Any:
        return getattr(self.rtia, name)

    async def advance_to(self, time: float) -> float:
        """``timeAdvanceRequest(time)``, then wait for the grant; returns the grant time."""
        self.rtia.timeAdvanceRequest(time)
        return await self.await_grant()

    async def next_event(self, time: float) -> float:
        """``nextEventRequest(time)``, then wait for the grant; returns the grant time."""
        self.rtia.nextEventRequest(time)
        return await self.await_grant()

    async def await_grant(self) -> float:
        """Wait for the pending time advance's grant, delivering callbacks; returns the new time."""
        if not self.rtia._time_advance_pending():
            raise _core.TimeAdvanceWasNotInProgress("no time advance is pending")
        while not self.rtia.deliver_until_granted():
            await self._readable()
        return float(self.rtia.queryFederateTime())

    async def tick(self, timeout: Optional[float] = None) -> bool:
        """Wait until callbacks arrive (or ``timeout`` seconds pass), deliver them; True if any were."""
        self.rtia._poll()
        if not self.rtia._has_callbacks():
            try:
                await asyncio.wait_for(self._readable(), timeout)
            except asyncio.TimeoutError:
                return False
            self.rtia._poll()
        delivered = bool(self.rtia._has_callbacks())
        self.rtia.tick()
        return delivered

    async def _readable(self) -> None:
        loop = asyncio.get_running_loop()
        ready = loop.create_future()
        # The stream, and the datagrams of best-effort messages when they travel apart (docs/networking.md).
        fds = [fd for fd in (self.rtia.fileno(), self.rtia._datagram_fileno()) if fd >= 0]
        def wake() -> None:
            if not ready.done():
                ready.set_result(None)

        for fd in fds:
            loop.add_reader(fd, wake)
        try:
            await ready
        finally:
            for fd in fds:
                loop.remove_reader(fd)
