"""The wire protocol spoken by hand (cpp/rti/wire/messages.hpp, codec.hpp), as a hostile or a careful client speaks it:
the field codecs, frames, a raw client socket, and the gateway's log line when it drops one."""

from __future__ import annotations

import contextlib
import re
import socket
import struct
import time
from dataclasses import dataclass
from typing import Any, Iterator, Optional

from hlacore import _core

from support import PROTOCOL_VERSION, RtigProcess, wait_for_log


MAGIC = 0x484C4143
VERSION = PROTOCOL_VERSION
MAX_FRAME = 64 << 20
MESSAGE_TYPES = _core._message_names()  # the list of cpp/rti/wire/message_list.hpp, in code order
T = {name: code for code, name in enumerate(MESSAGE_TYPES, start=1)}


def u8(v: int) -> bytes:
    return struct.pack("<B", v)


def u16(v: int) -> bytes:
    return struct.pack("<H", v)


def u32(v: int) -> bytes:
    return struct.pack("<I", v)


def u64(v: int) -> bytes:
    return struct.pack("<Q", v)


def f64(v: float) -> bytes:
    return struct.pack("<d", v)


def boolean(v: bool) -> bytes:
    return u8(1 if v else 0)


def optional_time(t: Optional[float]) -> bytes:
    return boolean(False) if t is None else boolean(True) + f64(t)


def string(s: str | bytes) -> bytes:
    data = s.encode() if isinstance(s, str) else s
    return u32(len(data)) + data


def handles(hs: list[int]) -> bytes:
    return u32(len(hs)) + b"".join(u32(h) for h in hs)


def frame(message: str | int, payload: bytes = b"") -> bytes:
    code = T[message] if isinstance(message, str) else message
    return u32(2 + len(payload)) + u16(code) + payload


def hello(magic: int = MAGIC, version: int = VERSION) -> bytes:
    return frame("Hello", u32(magic) + u16(version))


class Cursor:
    """Reads the fields of a received payload."""

    def __init__(self, data: bytes) -> None:
        self.data, self.pos = data, 0

    def take(self, fmt: str) -> Any:
        (value,) = struct.unpack_from(fmt, self.data, self.pos)
        self.pos += struct.calcsize(fmt)
        return value

    def string(self) -> bytes:
        n = self.take("<I")
        value = self.data[self.pos : self.pos + n]
        self.pos += n
        return value


# The gateway's answers to requests (HLACORE_ANSWERS): a Reply (a request without a result, or any refusal) or
# the result of the request; FederationJoined and ObjectRegistered carry a handle after the request id.
ANSWERS = ("Reply", "FederationJoined", "ObjectRegistered", "AttributesReleased", "StatusReport", "TimeQueried")
WITH_HANDLE = ("FederationJoined", "ObjectRegistered")


@dataclass
class Answer:
    kind: str  # its message's name
    request: int
    error: int = 0
    message: str = ""
    handle: int = 0


class RawClient:
    """A federate-side socket that speaks (or abuses) the wire protocol by hand."""

    def __init__(self, address: str, rcvbuf: Optional[int] = None) -> None:
        host, port = address.rsplit(":", 1)
        self.sock = socket.socket(socket.AF_INET, socket.SOCK_STREAM)
        if rcvbuf is not None:  # before connect, so that the kernel does not grow it
            self.sock.setsockopt(socket.SOL_SOCKET, socket.SO_RCVBUF, rcvbuf)
        self.sock.settimeout(5)
        self.sock.connect((host, int(port)))
        self.local = "%s:%d" % self.sock.getsockname()
        self.buffer = b""
        self.request = 0
        self.skipped: list[tuple[int, bytes]] = []  # frames call() read past while waiting for its answer

    def close(self) -> None:
        self.sock.close()

    def send(self, data: bytes, tolerate_drop: bool = False) -> None:
        try:
            self.sock.sendall(data)
        except (BrokenPipeError, ConnectionResetError):
            if not tolerate_drop:
                raise

    def recv_frame(self, timeout: float = 5.0) -> tuple[int, bytes]:
        deadline = time.monotonic() + timeout
        while True:
            if len(self.buffer) >= 6:
                (length,) = struct.unpack_from("<I", self.buffer)
                if len(self.buffer) >= 4 + length:
                    (code,) = struct.unpack_from("<H", self.buffer, 4)
                    payload = self.buffer[6 : 4 + length]
                    self.buffer = self.buffer[4 + length :]
                    return code, payload
            left = deadline - time.monotonic()
            if left <= 0:
                raise AssertionError("no complete frame from the gateway within %.1f s" % timeout)
            self.sock.settimeout(left)
            chunk = self.sock.recv(65536)
            if not chunk:
                raise AssertionError("the gateway closed the connection")
            self.buffer += chunk

    def handshake(self) -> tuple[int, bytes, int]:
        """Hello, then the Welcome (with no challenge): returns (version, server name, frame limit); keeps the
        datagram token and limit, and the nonce of federation proofs (empty unless a federation has a secret)."""
        self.send(hello())
        code, payload = self.recv_frame()
        assert code == T["Welcome"]
        c = Cursor(payload)
        version, server, max_frame, challenge = c.take("<H"), c.string(), c.take("<I"), c.string()
        self.datagram_token, self.max_datagram = c.take("<Q"), c.take("<I")
        self.nonce = c.string()
        assert c.pos == len(payload) and challenge == b""
        return version, server, max_frame

    def call(self, message: str, payload_after_request: bytes) -> Answer:
        """Send a request-carrying message and read frames until its answer."""
        self.request += 1
        request = self.request
        self.send(frame(message, u32(request) + payload_after_request))
        while True:
            code, payload = self.recv_frame()
            kind = MESSAGE_TYPES[code - 1]
            if kind not in ANSWERS:
                self.skipped.append((code, payload))
                continue
            c = Cursor(payload)
            answer = Answer(kind, c.take("<I"))
            if kind == "Reply":
                answer.error, answer.message = c.take("<H"), c.string().decode()
            elif kind in WITH_HANDLE:
                answer.handle = c.take("<I")
            if answer.request == request:
                return answer

    def join(self, federate: str, federation: str = "TestFed") -> int:
        self.handshake()
        reply = self.call("JoinFederation", string(federate) + string(federation) + string("") + string("") + string(""))
        assert reply.error == 0, reply.message
        return reply.handle

    def ping(self) -> None:
        """A round trip (an error Reply) proving that everything sent before was handled."""
        reply = self.call("DestroyFederation", string("no-such-federation") + string(""))
        assert reply.error != 0

    def frames_until(self, message: str, timeout: float = 5.0) -> tuple[list[tuple[int, bytes]], bytes]:
        """Read frames until one of type `message`: returns (the frames before it, its payload)."""
        before = []
        while True:
            code, payload = self.recv_frame(timeout)
            if code == T[message]:
                return before, payload
            before.append((code, payload))

    def wait_eof(self, timeout: float = 5.0) -> None:
        """Read (and discard) until the gateway's close shows: EOF or a reset."""
        deadline = time.monotonic() + timeout
        while True:
            left = deadline - time.monotonic()
            if left <= 0:
                raise AssertionError("the gateway did not close the connection within %.1f s" % timeout)
            self.sock.settimeout(left)
            try:
                chunk = self.sock.recv(1 << 16)
            except ConnectionResetError:
                return
            except socket.timeout:
                continue
            if not chunk:
                return


@contextlib.contextmanager
def raw_client(address: str, rcvbuf: Optional[int] = None) -> Iterator[RawClient]:
    client = RawClient(address, rcvbuf)
    try:
        yield client
    finally:
        client.close()


def dropped_line(server: RtigProcess, client: RawClient, timeout: float = 5.0) -> str:
    """The log line of the gateway dropping `client` (found by its address)."""
    return wait_for_log(server, rf"rtig: dropped {re.escape(client.local)}\b[^\n]*", timeout)


def closed_and_dropped(server: RtigProcess, client: RawClient) -> str:
    """Once `client` has misbehaved: the gateway closes its connection, and the log line of dropping it."""
    client.wait_eof()
    return dropped_line(server, client)


@contextlib.contextmanager
def joined_raw_client(address: str, federate: str) -> Iterator[tuple[RawClient, int]]:
    """A raw client joined to TestFed as `federate`: (the client, its federate handle)."""
    with raw_client(address) as client:
        yield client, client.join(federate)


def send_interaction(client: RawClient, command: int, value: int, data: bytes, ts: Optional[float], serial: int) -> bytes:
    """A SendInteraction frame: interaction class `command` with `data` as its parameter `value`, tag "raw",
    timestamp `ts` (None: receive order) and the sender's message `serial`."""
    return frame(
        "SendInteraction",
        u32(command) + u32(1) + u32(value) + string(data) + string("raw") + optional_time(ts) + u64(serial),
    )
