"""A live web view of a running gateway: federations, federates, times, grants and traffic (docs/monitor.md).

``python -m hlacore.monitor [HOST:PORT]`` serves the page on http://127.0.0.1:8470/ by default; from Python,
``hlacore.Gateway.monitor()`` or :class:`Monitor`. The monitor is one client of the gateway that asks for its
status report every ``interval`` seconds, whatever the number of pages open, and pushes each view to every
page over a WebSocket. It only reads: it never joins a federation.

The server side is aiohttp: one well-kept package that serves HTTP and WebSockets from an asyncio loop, with
no separate ASGI server to run. The page is plain HTML, CSS and JavaScript shipped in the package (no front-end
build); its chart is drawn on a canvas.
"""

from __future__ import annotations

import asyncio
import concurrent.futures
import json
import os
import pathlib
import threading
import time
from types import TracebackType
from typing import Any, Optional

from aiohttp import WSMsgType, web

from .. import _core
from ..rti import _client_settings
from .state import HOLD_SECONDS, MonitorState

__all__ = ["Monitor", "DEFAULT_PORT"]

#: The port ``python -m hlacore.monitor`` serves on unless told otherwise.
DEFAULT_PORT = 8470
_STATIC = pathlib.Path(__file__).with_name("static")


class Monitor:
    """Serves the live view of the gateway at ``address`` (as :class:`hlacore.rti.RTIAmbassador` takes it) on
    ``http://host:port/`` (``port`` 0 picks a free one; :attr:`url` tells).

    :meth:`start` serves from a background thread (also what ``hlacore.Gateway.monitor()`` and
    ``python -m hlacore.monitor`` do) until :meth:`close`. ``interval`` is the seconds between two status queries (at most 1, so
    that the page moves at least once a second); ``hold_seconds`` how long a time advance request must wait
    for its federate to count as held back. ``secret_file`` and ``tls`` are those of the gateway's clients.
    """

    def __init__(self, address: Optional[str] = None, *, host: str = "127.0.0.1", port: int = DEFAULT_PORT,
                 interval: float = 0.5, hold_seconds: float = HOLD_SECONDS,
                 secret_file: Optional[str | os.PathLike[str]] = None,
                 tls: Optional[bool | str | os.PathLike[str]] = None) -> None:
        if not 0.05 <= interval <= 1.0:
            raise ValueError(f"interval must be between 0.05 and 1 second, not {interval}")
        if hold_seconds <= 0:
            raise ValueError(f"hold_seconds must be positive, not {hold_seconds}")
        self._settings = _client_settings(address=address, secret_file=secret_file, tls=tls, datagrams=False)
        self.gateway_host, self.gateway_port = self._settings.host, self._settings.port
        self.host = host
        self.port = port
        self.interval = interval
        self.state = MonitorState(hold_seconds=hold_seconds)
        self._subscribers: set[_Subscriber] = set()
        self._client: Any = None
        self._queries = concurrent.futures.ThreadPoolExecutor(1, thread_name_prefix="hlacore-monitor-query")
        self._loop: Optional[asyncio.AbstractEventLoop] = None
        self._stop: Optional[asyncio.Event] = None
        self._thread: Optional[threading.Thread] = None
        self._ready = threading.Event()
        self._failure: Optional[BaseException] = None

    @property
    def url(self) -> str:
        """Where the page is: ``http://host:port/`` (the real port once started)."""
        return f"http://{self.host}:{self.port}/"

    # ---- running ----
    def start(self, timeout: float = 10.0) -> "Monitor":
        """Serve from a background thread; returns once the page is served (raises what stopped it)."""
        if self._thread is not None:
            raise RuntimeError("the monitor is already started")
        self._thread = threading.Thread(target=lambda: asyncio.run(self._serve()), name="hlacore-monitor",
                                        daemon=True)
        self._thread.start()
        if not self._ready.wait(timeout):
            raise TimeoutError(f"the monitor did not start within {timeout} s")
        if self._failure is not None:
            raise self._failure
        return self

    def close(self) -> None:
        """Stop serving and close the gateway connection; idempotent."""
        loop, stop = self._loop, self._stop
        if loop is not None and stop is not None and not loop.is_closed():
            try:
                loop.call_soon_threadsafe(stop.set)
            except RuntimeError:  # the loop ended meanwhile
                pass
        if self._thread is not None and self._thread is not threading.current_thread():
            self._thread.join(10)
        self._queries.shutdown(wait=True)
        self._client = None

    def __enter__(self) -> "Monitor":
        return self.start() if self._thread is None else self

    def __exit__(self, exc_type: Optional[type[BaseException]], exc: Optional[BaseException],
                 tb: Optional[TracebackType]) -> None:
        self.close()

    # ---- the server ----
    async def _serve(self) -> None:
        self._loop = asyncio.get_running_loop()
        self._stop = asyncio.Event()
        app = web.Application()
        app.router.add_get("/", self._page)
        app.router.add_get("/view.json", self._view)
        app.router.add_get("/ws", self._websocket)
        app.router.add_static("/static/", _STATIC)
        runner = web.AppRunner(app, access_log=None, handle_signals=False)
        try:
            await runner.setup()
            await web.TCPSite(runner, self.host, self.port).start()
            self.port = int(runner.addresses[0][1])  # the one picked for port 0
        except BaseException as e:  # the address is in use, say: start() raises it
            self._failure = e
            self._ready.set()
            await runner.cleanup()
            return
        self._ready.set()
        poller = asyncio.create_task(self._poll())
        try:
            await self._stop.wait()
        finally:
            poller.cancel()
            for subscriber in list(self._subscribers):
                await subscriber.close()
            await runner.cleanup()

    async def _page(self, request: web.Request) -> web.FileResponse:
        return web.FileResponse(_STATIC / "index.html")

    async def _view(self, request: web.Request) -> web.Response:
        """The latest view as JSON (what the page receives; for scripts and curl)."""
        return web.json_response(self.state.latest or {})

    async def _websocket(self, request: web.Request) -> web.WebSocketResponse:
        socket = web.WebSocketResponse(heartbeat=20.0)
        await socket.prepare(request)
        await socket.send_str(json.dumps(self.state.hello()))
        subscriber = _Subscriber(socket)
        self._subscribers.add(subscriber)
        try:
            async for message in socket:  # read-only: what a page sends is ignored
                if message.type == WSMsgType.ERROR:
                    break
        finally:
            self._subscribers.discard(subscriber)
            await subscriber.close()
        return socket

    # ---- the gateway ----
    async def _poll(self) -> None:
        loop = asyncio.get_running_loop()
        while True:
            started = loop.time()
            try:
                text = await loop.run_in_executor(self._queries, self._query)
                view = self.state.update(json.loads(text), time.time(), time.monotonic())
            except Exception as e:  # the gateway is down or refuses us: say so on the page, try again
                self._client = None
                view = self.state.unreachable(f"{type(e).__name__}: {e}", time.time())
            message = json.dumps(view)
            for subscriber in self._subscribers:
                subscriber.offer(message)
            await asyncio.sleep(max(0.0, self.interval - (loop.time() - started)))

    def _query(self) -> str:
        """One status query, on the query thread (the call releases the GIL while it waits)."""
        if self._client is None:
            self._client = _core.RTIAmbassadorBase(self._settings)
        return str(self._client._status(self.state.last_event, instances=False))


class _Subscriber:
    """One open page: it is sent the latest view only, so a slow browser costs one pending message at most."""

    def __init__(self, socket: web.WebSocketResponse) -> None:
        self._socket = socket
        self._latest: Optional[str] = None
        self._wake = asyncio.Event()
        self._task = asyncio.create_task(self._send())

    def offer(self, message: str) -> None:
        """Make ``message`` the next one sent, replacing one not sent yet."""
        self._latest = message
        self._wake.set()

    async def _send(self) -> None:
        while True:
            await self._wake.wait()
            self._wake.clear()
            message, self._latest = self._latest, None
            if message is not None:
                try:
                    await self._socket.send_str(message)
                except (ConnectionError, RuntimeError):
                    return

    async def close(self) -> None:
        """Stop sending and close the web socket."""
        self._task.cancel()
        if not self._socket.closed:
            await self._socket.close()
