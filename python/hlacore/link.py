"""An emulated network link in user space: a relay that adds delay, jitter, a bandwidth limit and, for
datagrams, loss, per direction, between federates and a gateway (docs/networking.md).

Kernels without the ``netem`` queueing discipline cannot shape traffic, so the relay does it: a client
connects to the relay's address as if it were the gateway's, and each byte it sends is delivered to the
target after the serialization time of the link (``rate``) plus the one-way ``delay``, ± ``jitter`` (uniform);
the reply direction has its own figures. A TCP stream keeps its order, so jitter there never reorders
(a segment waits for the one before it, as on a real path); datagrams (``udp=True``) may be lost or
reordered. Each direction buffers at most ``buffer`` bytes, beyond which the relay stops reading, so a sender
faster than the link is slowed by TCP as it would be by a router's queue.

From the command line, to rehearse a lab network (Wi-Fi to a robot, say) on one machine::

    python -m hlacore.link 127.0.0.1:60500 127.0.0.1:60400 --delay 5 --jitter 2 --rate 10
    python -m hlacore.link 127.0.0.1:60500 127.0.0.1:60400 --up delay=20,rate=1 --down delay=5

and point the federates at 127.0.0.1:60500. From Python, :class:`Link` runs the same relay on a thread.
"""

from __future__ import annotations

import argparse
import asyncio
import collections
import dataclasses
import random
import socket
import sys
import threading
import time
from typing import Any, Optional

__all__ = ["Direction", "Link", "main"]

SEGMENT = 1448  # a stream is cut into segments of a TCP payload's size, so a rate limit paces it smoothly


@dataclasses.dataclass(frozen=True)
class Direction:
    """The figures of one direction of the link."""

    delay: float = 0.0  #: one-way delay, seconds
    jitter: float = 0.0  #: ± seconds around the delay, uniform
    rate: float = 0.0  #: bits per second, 0 for no limit
    loss: float = 0.0  #: probability that a datagram is lost (streams lose nothing)

    def __post_init__(self) -> None:
        for name in ("delay", "jitter", "rate"):
            value = getattr(self, name)
            if not (value >= 0 and value != float("inf")):
                raise ValueError(f"{name} must be a finite number >= 0, not {value}")
        if not 0 <= self.loss <= 1:
            raise ValueError(f"loss must be between 0 and 1, not {self.loss}")

    @classmethod
    def parse(cls, spec: str, base: Optional["Direction"] = None) -> "Direction":
        """``"delay=5,jitter=2,rate=10,loss=1"``: milliseconds, Mbit/s and percent, over `base`'s figures."""
        figures = dataclasses.asdict(base or cls())
        scale = {"delay": 1e-3, "jitter": 1e-3, "rate": 1e6, "loss": 1e-2}
        for item in filter(None, spec.split(",")):
            name, _, value = item.partition("=")
            if name.strip() not in scale:
                raise ValueError(f"unknown link figure {name.strip()!r} (delay, jitter, rate, loss)")
            figures[name.strip()] = float(value) * scale[name.strip()]
        return cls(**figures)


class _Shaper:
    """When each packet of one direction arrives at the far end."""

    def __init__(self, figures: Direction, rng: random.Random, in_order: bool) -> None:
        self.figures, self.rng, self.in_order = figures, rng, in_order
        self.line_free = 0.0  # when the link has sent everything before
        self.last_due = 0.0

    def due(self, size: int) -> Optional[float]:
        """The arrival time of `size` bytes sent now, on the loop's clock; None when lost."""
        f = self.figures
        if f.loss and self.rng.random() < f.loss:
            return None
        start = max(time.monotonic(), self.line_free)
        self.line_free = start + (size * 8 / f.rate if f.rate else 0.0)
        due = self.line_free + max(0.0, f.delay + self.rng.uniform(-f.jitter, f.jitter))
        if self.in_order:
            due = max(due, self.last_due)
            self.last_due = due
        return due


class _Counters:
    def __init__(self) -> None:
        self.bytes = 0
        self.packets = 0
        self.lost = 0


class Link:
    """The relay on a thread of its own: listens on `listen` (host, port; port 0 picks one) and forwards to
    `target`, ``up`` being the direction towards the target. TCP by default; ``udp=True`` relays datagrams
    (each client address gets its own socket towards the target, so replies find it). ``dump`` names a
    file that receives every relayed byte, tagged with its direction (to check what crossed the link).

    ::

        with Link(("127.0.0.1", 0), ("127.0.0.1", 60400), up=Direction(delay=0.005)) as link:
            rtia = hlacore.rti.RTIAmbassador(link.address)
    """

    def __init__(self, listen: tuple[str, int], target: tuple[str, int], up: Direction = Direction(),
                 down: Direction = Direction(), udp: bool = False, buffer: int = 256 << 10,
                 seed: Optional[int] = None, dump: Optional[str] = None) -> None:
        self.target, self.udp, self.buffer = target, udp, buffer
        rng = random.Random(seed)
        self._figures = {"up": up, "down": down}
        self._rng = rng
        self.counters = {"up": _Counters(), "down": _Counters()}
        self._dump = open(dump, "wb") if dump else None
        self._loop = asyncio.new_event_loop()
        self._ready = threading.Event()
        self._error: Optional[BaseException] = None
        self._server: Any = None
        self._open: set[Any] = set()  # the stream writers and datagram transports to close at the end
        self._streams: set[tuple[asyncio.StreamWriter, asyncio.StreamWriter]] = set()  # the connections relayed now
        self._listen = listen
        self._thread = threading.Thread(target=self._run, name="hlacore-link", daemon=True)
        self._thread.start()
        self._ready.wait(10)
        if self._error:
            raise self._error
        if not self._ready.is_set():
            raise RuntimeError("the link did not start within 10 s")

    @property
    def address(self) -> str:
        """``"host:port"`` of the relay, to give the federates instead of the gateway's."""
        return f"{self.host}:{self.port}"

    def close(self) -> None:
        """Stop relaying and close every connection; idempotent."""
        if self._loop.is_running():
            try:
                asyncio.run_coroutine_threadsafe(self._shutdown(), self._loop).result(10)
            finally:
                self._loop.call_soon_threadsafe(self._loop.stop)
        self._thread.join(10)
        if self._dump:
            self._dump.close()
            self._dump = None

    def cut(self) -> int:
        """Break every TCP connection relayed now, as a failed link would: both ends see a reset and what the
        link held in flight is lost. Later connections are relayed as before. Returns how many were cut."""
        async def cut() -> int:
            pairs = list(self._streams)
            for pair in pairs:
                for writer in pair:
                    writer.transport.abort()
            return len(pairs)

        return asyncio.run_coroutine_threadsafe(cut(), self._loop).result(10)

    def __enter__(self) -> "Link":
        return self

    def __exit__(self, *exc: object) -> None:
        self.close()

    # ---- inside the loop ----

    def _run(self) -> None:
        asyncio.set_event_loop(self._loop)
        try:
            self._loop.run_until_complete(self._start())
        except BaseException as e:  # reported to the constructor
            self._error = e
            self._ready.set()
            return
        self._ready.set()
        try:
            self._loop.run_forever()
        finally:
            tasks = asyncio.all_tasks(self._loop)
            for task in tasks:
                task.cancel()
            self._loop.run_until_complete(asyncio.gather(*tasks, return_exceptions=True))
            for _ in range(3):  # the closed transports' last callbacks (connection_lost) run before the loop ends
                self._loop.run_until_complete(asyncio.sleep(0))
            self._loop.close()

    async def _shutdown(self) -> None:
        self._server.close()
        for item in list(self._open):
            item.close()

    async def _start(self) -> None:
        host, port = self._listen
        if self.udp:
            transport, _ = await self._loop.create_datagram_endpoint(lambda: _DatagramFront(self), local_addr=(host, port))
            self._server = transport
            self.host, self.port = transport.get_extra_info("sockname")[:2]
        else:
            self._server = await asyncio.start_server(self._relay_stream, host, port)
            self.host, self.port = self._server.sockets[0].getsockname()[:2]

    def _record(self, direction: str, data: bytes) -> None:
        counters = self.counters[direction]
        counters.bytes += len(data)
        counters.packets += 1
        if self._dump:
            self._dump.write(b"%s %d\n" % (direction.encode(), len(data)) + data + b"\n")

    async def _relay_stream(self, client_reader: asyncio.StreamReader, client_writer: asyncio.StreamWriter) -> None:
        try:
            target_reader, target_writer = await asyncio.open_connection(*self.target)
        except OSError:
            client_writer.close()
            return
        for w in (client_writer, target_writer):
            w.get_extra_info("socket").setsockopt(socket.IPPROTO_TCP, socket.TCP_NODELAY, 1)
            self._open.add(w)
        pair = (client_writer, target_writer)
        self._streams.add(pair)
        try:
            await asyncio.gather(self._pump(client_reader, target_writer, "up"),
                                 self._pump(target_reader, client_writer, "down"), return_exceptions=True)
        finally:
            self._streams.discard(pair)
            for w in (client_writer, target_writer):
                self._open.discard(w)
                w.close()

    async def _pump(self, reader: asyncio.StreamReader, writer: asyncio.StreamWriter, direction: str) -> None:
        """One direction of a stream: read, stamp each segment with its arrival time, write it then."""
        shaper = _Shaper(self._figures[direction], self._rng, in_order=True)
        queue: collections.deque[tuple[float, bytes]] = collections.deque()
        queued = 0
        changed = asyncio.Event()
        done = False

        async def deliver() -> None:
            nonlocal queued
            while queue or not done:
                if not queue:
                    changed.clear()
                    await changed.wait()
                    continue
                due, segment = queue[0]
                wait = due - time.monotonic()
                if wait > 0:
                    await asyncio.sleep(wait)
                queue.popleft()
                queued -= len(segment)
                changed.set()
                writer.write(segment)
                await writer.drain()
            if writer.can_write_eof():
                writer.write_eof()

        delivering = asyncio.ensure_future(deliver())
        try:
            while True:
                while queued >= self.buffer:  # the link's queue is full: stop reading, as a router drops
                    changed.clear()           # nothing on a TCP path but the sender's window closes
                    await changed.wait()
                data = await reader.read(65536)
                if not data:
                    break
                self._record(direction, data)
                for i in range(0, len(data), SEGMENT):
                    segment = data[i:i + SEGMENT]
                    due = shaper.due(len(segment))
                    assert due is not None  # streams lose nothing
                    queue.append((due, segment))
                    queued += len(segment)
                changed.set()
        except (ConnectionError, OSError):
            pass
        finally:
            done = True
            changed.set()
        try:
            await delivering
        except (ConnectionError, OSError):
            pass


class _DatagramFront(asyncio.DatagramProtocol):
    """The listening side of a datagram link: one back socket per client address."""

    def __init__(self, link: Link) -> None:
        self.link = link
        self.transport: Any = None
        self.backs: dict[Any, Any] = {}
        self.up = _Shaper(link._figures["up"], link._rng, in_order=False)
        self.down = _Shaper(link._figures["down"], link._rng, in_order=False)

    def connection_made(self, transport: Any) -> None:
        """Keep the listening socket's transport."""
        self.transport = transport

    def datagram_received(self, data: bytes, addr: Any) -> None:
        """Forward a client's datagram upstream through its own back socket, delayed or dropped as the
        up direction's figures say."""
        self.link._record("up", data)
        back = self.backs.get(addr)
        if back is None:
            back = self.backs[addr] = asyncio.ensure_future(self._open_back(addr))
        due = self.up.due(len(data))
        if due is None:
            self.link.counters["up"].lost += 1
            return
        loop = asyncio.get_running_loop()
        loop.call_at(_loop_time(loop, due), lambda: self._send_up(back, data))

    def _send_up(self, back: Any, data: bytes) -> None:
        if not back.done():  # the client's first datagrams: its socket towards the target is being opened
            back.add_done_callback(lambda _: self._send_up(back, data))
        elif not back.cancelled() and back.exception() is None:
            back.result().sendto(data)

    async def _open_back(self, client: Any) -> Any:
        front = self

        class Back(asyncio.DatagramProtocol):
            def datagram_received(self, data: bytes, addr: Any) -> None:
                front.link._record("down", data)
                due = front.down.due(len(data))
                if due is None:
                    front.link.counters["down"].lost += 1
                    return
                loop = asyncio.get_running_loop()
                loop.call_at(_loop_time(loop, due), lambda: front.transport.sendto(data, client))

        transport, _ = await asyncio.get_running_loop().create_datagram_endpoint(Back, remote_addr=self.link.target)
        self.link._open.add(transport)
        return transport


def _loop_time(loop: asyncio.AbstractEventLoop, monotonic_due: float) -> float:
    """A time.monotonic() instant on the loop's clock."""
    return loop.time() + (monotonic_due - time.monotonic())


def _address(text: str) -> tuple[str, int]:
    host, _, port = text.rpartition(":")
    if not host or not port.isdigit():
        raise argparse.ArgumentTypeError(f"expected HOST:PORT, not {text!r}")
    return host, int(port)


def main(argv: Optional[list[str]] = None) -> int:
    """``python -m hlacore.link LISTEN TARGET [figures]``: relay until Ctrl-C, then print the counters."""
    parser = argparse.ArgumentParser(prog="python -m hlacore.link", description=__doc__.split("\n\n")[0])
    parser.add_argument("listen", type=_address, help="HOST:PORT to listen on (port 0 picks one)")
    parser.add_argument("target", type=_address, help="HOST:PORT to relay to (the gateway)")
    parser.add_argument("--delay", type=float, default=0.0, help="one-way delay, ms, both directions")
    parser.add_argument("--jitter", type=float, default=0.0, help="± ms around the delay, uniform")
    parser.add_argument("--rate", type=float, default=0.0, help="Mbit/s each way (0: unlimited)")
    parser.add_argument("--loss", type=float, default=0.0, help="percent of datagrams lost (with --udp)")
    parser.add_argument("--up", default="", help="towards the target: delay=MS,jitter=MS,rate=MBIT,loss=PCT")
    parser.add_argument("--down", default="", help="back from the target, the same figures")
    parser.add_argument("--udp", action="store_true", help="relay datagrams instead of a TCP stream")
    parser.add_argument("--seed", type=int, help="seed of the jitter and loss draws")
    parser.add_argument("--dump", help="write every relayed byte to this file, tagged with its direction")
    args = parser.parse_args(argv)
    try:
        both = Direction(args.delay * 1e-3, args.jitter * 1e-3, args.rate * 1e6, args.loss * 1e-2)
        up, down = Direction.parse(args.up, both), Direction.parse(args.down, both)
    except ValueError as e:
        parser.error(str(e))
    with Link(args.listen, args.target, up, down, udp=args.udp, seed=args.seed, dump=args.dump) as link:
        print(f"link listening on {link.address} -> {args.target[0]}:{args.target[1]} (up {up}, down {down})",
              flush=True)
        try:
            while True:
                time.sleep(3600)
        except KeyboardInterrupt:
            pass
        for direction, c in link.counters.items():
            print(f"{direction}: {c.bytes} bytes in {c.packets} reads, {c.lost} datagrams lost", file=sys.stderr)
    return 0


if __name__ == "__main__":
    sys.exit(main())
