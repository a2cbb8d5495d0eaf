"""The floors every figure is divided by: a raw TCP loopback exchange between two processes, in Python
sockets (timed by pytest-benchmark like the hlacore figures) and in C++ (bench/tcp_floor.cpp, which
times itself and prints its samples)."""

from __future__ import annotations

import json
import socket
import subprocess

from .procs import start_peer

RECORD = 48  # bytes per message of the stream floor: about one hlacore update frame with 8 bytes of data


class _SocketPeer:
    """A bench/peers/echo.py process and this process's TCP connection to it."""

    def __init__(self, *args: object) -> None:
        self.peer = start_peer("echo.py", *args)
        try:
            port = self.peer.read_json(timeout=30.0)["port"]
            self.sock = socket.create_connection(("127.0.0.1", port))
        except BaseException:
            self.peer.close()
            raise
        self.sock.setsockopt(socket.IPPROTO_TCP, socket.TCP_NODELAY, 1)

    def close(self) -> None:
        """Close the connection; the peer exits on end of file (killed by pid if it does not)."""
        self.sock.close()
        try:
            self.peer.wait(timeout=10.0)
        finally:
            self.peer.close()


class PyEcho(_SocketPeer):
    """Round trips of `size` bytes to a Python echo process."""

    def __init__(self, size: int) -> None:
        super().__init__("echo", size)
        self.size = size
        self.payload = bytes(size)
        self.view = memoryview(bytearray(size))

    def round_trip(self) -> None:
        self.sock.sendall(self.payload)
        got = 0
        while got < self.size:
            n = self.sock.recv_into(self.view[got:])
            if n == 0:
                raise ConnectionError("echo peer closed")
            got += n


class PySink(_SocketPeer):
    """Bursts of RECORD-byte messages, one send() each (as the hlacore client sends one frame per update),
    to a Python process that counts them and reports each complete burst."""

    def __init__(self, burst: int, record: int = RECORD) -> None:
        super().__init__("sink", record, burst)
        self.burst_size = burst
        self.record = record
        self.sent = 0

    def burst(self) -> None:
        send, record = self.sock.sendall, bytes(self.record)
        for _ in range(self.burst_size):
            send(record)
        self.sent += self.burst_size
        got = self.peer.read_json(timeout=60.0)
        assert got == {"received": self.sent}, (got, self.sent)


def cpp_rtt_ns(binary: str, size: int, count: int, mode: str = "rtt", unix: bool = False,
               spin: bool = False) -> list[int]:
    """`count` round trips of `size` bytes timed by the C++ program, in nanoseconds. `mode` "rtt": to an echo;
    "rtt-relay": through a third process that passes each message on (four hops, as through a gateway);
    "barrier": to a server that answers this process and a second client once both have sent (as the rtig
    grants two federates). `unix`: over Unix socket pairs instead of TCP loopback; `spin`: every process polls
    its socket (yielding between tries, as hlacore's busy polling does) instead of sleeping in recv."""
    options = [*(["--unix"] if unix else []), *(["--spin"] if spin else [])]
    out = subprocess.run([binary, *options, mode, str(size), str(count)],
                         check=True, capture_output=True, text=True, timeout=120).stdout
    samples: list[int] = json.loads(out)["rtt_ns"]
    return samples


def cpp_stream_rate(binary: str, count: int, record: int = RECORD, mode: str = "stream", unix: bool = False) -> float:
    """Messages per second of `count` sends of `record` bytes, timed by the C++ program until all were read;
    mode "relay": through a third process that forwards them (tcp_floor.cpp); `unix`: over a Unix socket pair."""
    out = subprocess.run([binary, *(["--unix"] if unix else []), mode, str(record), str(count)], check=True,
                         capture_output=True, text=True, timeout=120).stdout
    result = json.loads(out)
    return float(result["count"] / result["seconds"])
