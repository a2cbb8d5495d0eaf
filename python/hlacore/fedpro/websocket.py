"""A WebSocket client (RFC 6455) as a byte stream: the Federate Protocol's "websocket" and "websocketsecure"
transports.

The Federate Protocol over a WebSocket is the same byte stream as over TCP, carried in binary frames: the
federate sends each of its writes as one binary frame, masked as a client's frames must be, and reads the
payloads of the RTI's binary frames (and their continuations) one after the other, whatever their boundaries.
:class:`WebSocketStream` does that over a connected socket (or a TLS stream) and looks enough like a socket for
the session layer (its ``Stream``): ``recv``, ``sendall``, ``shutdown``, ``close``, ``fileno``, ``settimeout``,
and ``pending`` for the bytes it holds already.

It answers a ping with a pong, ignores a pong, answers a close once and then ends the stream. A text frame, a
masked frame from the server, a reserved bit or opcode, a control frame fragmented or over 125 bytes, a frame
over the size limit and a continuation out of place are :class:`WebSocketError`: the connection is broken.
"""

from __future__ import annotations

import base64
import enum
import errno
import hashlib
import os
import select
import struct
import threading
import time
from typing import TYPE_CHECKING, Dict, List, Optional, Tuple, Union

if TYPE_CHECKING:  # the session layer imports this module
    from .session import Stream

#: RFC 6455's GUID: the server proves it speaks WebSocket by answering SHA-1 of the client's key and this.
ACCEPT_GUID = "258EAFA5-E914-47DA-95CA-C5AB0DC85B11"
#: The largest frame accepted by default: any Federate Protocol message at its default size limit, and more.
MAX_FRAME = (64 << 20) + (64 << 10)

_U16 = struct.Struct(">H")
_U64 = struct.Struct(">Q")
_MAX_HEAD = 16 << 10  # the longest answer to the upgrade accepted, up to its blank line
_CHUNK = 1 << 16  # read from the connection this much at a time
_SLICE = 0.1  # waits are cut into slices this long


class Opcode(enum.IntEnum):
    """The type of a frame (RFC 6455, 5.2)."""

    CONTINUATION = 0
    TEXT = 1
    BINARY = 2
    CLOSE = 8
    PING = 9
    PONG = 10


class WebSocketError(ConnectionError):
    """The server refused the WebSocket upgrade (the message says its status line), answered it wrongly, or
    broke RFC 6455 on the connection."""


def accept_key(key: str) -> str:
    """The ``Sec-WebSocket-Accept`` a server answers to the ``Sec-WebSocket-Key`` `key`: base64 of the SHA-1
    of `key` and :data:`ACCEPT_GUID`."""
    return base64.b64encode(hashlib.sha1((key + ACCEPT_GUID).encode("ascii")).digest()).decode("ascii")


def mask(payload: bytes, key: bytes) -> bytes:
    """`payload` XORed with the 4-byte `key` repeated (masking and unmasking are the same)."""
    if not payload:
        return b""
    repeated = (key * (len(payload) // 4 + 1))[:len(payload)]
    # One XOR of two big integers: a byte loop in Python would take seconds for a large message.
    return (int.from_bytes(payload, "big") ^ int.from_bytes(repeated, "big")).to_bytes(len(payload), "big")


def encode_frame(opcode: int, payload: bytes = b"", *, fin: bool = True, mask_key: Optional[bytes] = None) -> bytes:
    """One frame: its header (the 7-, 16- or 64-bit length as the payload's size needs), then `payload`, masked
    with `mask_key` (4 bytes) when given, as a client's frames must be and a server's must not."""
    first = (0x80 if fin else 0) | (opcode & 0x0F)
    masked = 0x80 if mask_key is not None else 0
    size = len(payload)
    if size < 126:
        head = bytes((first, masked | size))
    elif size < 1 << 16:
        head = bytes((first, masked | 126)) + _U16.pack(size)
    else:
        head = bytes((first, masked | 127)) + _U64.pack(size)
    if mask_key is None:
        return head + payload
    if len(mask_key) != 4:
        raise ValueError(f"a mask is 4 bytes, not {len(mask_key)}")
    return head + mask_key + mask(payload, mask_key)


def decode_frame_header(data: Union[bytes, bytearray]) -> Optional[Tuple[bool, int, bool, int, int]]:
    """The header at the start of `data` as ``(fin, opcode, masked, payload size, header size)`` (the header
    counts the mask, when there is one), or None while `data` holds only part of it. :class:`WebSocketError`
    for a reserved bit set or a 64-bit size with its top bit set."""
    if len(data) < 2:
        return None
    first, second = data[0], data[1]
    if first & 0x70:
        raise WebSocketError(f"a frame with reserved bits {first & 0x70:#x} set: no extension was agreed")
    size, header_size = second & 0x7F, 2
    if size == 126:
        if len(data) < 4:
            return None
        size, header_size = _U16.unpack_from(data, 2)[0], 4
    elif size == 127:
        if len(data) < 10:
            return None
        size, header_size = _U64.unpack_from(data, 2)[0], 10
        if size >> 63:
            raise WebSocketError("a frame size with its most significant bit set")
    masked = bool(second & 0x80)
    if masked:
        header_size += 4
        if len(data) < header_size:
            return None
    return bool(first & 0x80), first & 0x0F, masked, size, header_size


def wait_readable(stream: Stream, timeout: float) -> bool:
    """Whether `stream` has something to read (or has ended) within `timeout` seconds. True at once when a
    layer over the socket holds bytes it read already (its ``pending()``, as TLS and WebSocket streams have):
    the socket itself may have nothing more to say. poll where there is one: select refuses descriptors over
    FD_SETSIZE."""
    pending = getattr(stream, "pending", None)
    if pending is not None and pending() > 0:
        return True
    if hasattr(select, "poll"):
        poller = select.poll()
        poller.register(stream, select.POLLIN)
        return bool(poller.poll(timeout * 1000))
    readable, _, _ = select.select([stream], [], [], timeout)
    return bool(readable)


class WebSocketStream:
    """A WebSocket's binary messages as one byte stream, the client's side (RFC 6455).

    :meth:`connect` upgrades a connection; then :meth:`sendall` sends each write as one masked binary frame,
    and :meth:`recv` returns the payloads of the server's binary and continuation frames as they come,
    answering pings and a close on the way. :meth:`recv` is a non-blocking socket's: ``BlockingIOError`` when
    what it read holds no payload yet (a ping, part of a frame); :func:`wait_readable` waits for more.

    One thread reads; any number may write. Writes, and the pong or close the reader sends, go out whole, one
    at a time.
    """

    def __init__(self, inner: Stream, *, max_frame: int = MAX_FRAME, buffered: bytes = b"") -> None:
        """The stream over `inner`, a connection already upgraded (:meth:`connect` does it); `buffered` is what
        was read of it after the server's answer. Frames over `max_frame` bytes are refused."""
        self._inner = inner
        self._max_frame = max_frame
        self._write_lock = threading.Lock()
        self._raw = bytearray(buffered)  # read and not decoded: the start of a frame at most, after _decode
        self._data = bytearray()  # payload decoded and not returned yet
        self._remaining = 0  # payload bytes of the current data frame still to come
        self._in_message = False  # a fragmented message goes on: continuations expected
        self._eof = False
        self._close_sent = False
        self._failed: Optional[str] = None
        self._decode()

    @classmethod
    def connect(cls, inner: Stream, host: str, port: int, *, path: str = "/", secure: bool = False,
                timeout: float = 10.0, max_frame: int = MAX_FRAME) -> "WebSocketStream":
        """Upgrades the connection `inner` (to `host`:`port`, over TLS when `secure`) to a WebSocket: GET
        `path` with a fresh ``Sec-WebSocket-Key``, then the server's answer, within `timeout` seconds. The
        answer must be 101 with ``Upgrade: websocket``, ``Connection: Upgrade`` and the
        ``Sec-WebSocket-Accept`` of the key, and no extension or subprotocol (none is asked for).
        :class:`WebSocketError` otherwise (its message quotes a refusal's status line), ``TimeoutError`` when
        no whole answer came in time. `inner` stays the caller's to close on an error."""
        if not path.startswith("/") or not path.isascii() or not path.isprintable() or " " in path:
            raise ValueError(f"bad WebSocket path {path!r}: printable ASCII without spaces, from '/'")
        deadline = time.monotonic() + timeout
        key = base64.b64encode(os.urandom(16)).decode("ascii")
        name = f"[{host}]" if ":" in host else host
        authority = name if port == (443 if secure else 80) else f"{name}:{port}"
        where = f"{'wss' if secure else 'ws'}://{authority}{path}"
        request = (f"GET {path} HTTP/1.1\r\nHost: {authority}\r\nUpgrade: websocket\r\nConnection: Upgrade\r\n"
                   f"Sec-WebSocket-Key: {key}\r\nSec-WebSocket-Version: 13\r\n\r\n")
        inner.sendall(request.encode("ascii"))
        head = bytearray()
        while b"\r\n\r\n" not in head:
            if len(head) > _MAX_HEAD:
                raise WebSocketError(f"{where} answered the WebSocket upgrade with over {_MAX_HEAD} bytes of head")
            remaining = deadline - time.monotonic()
            if remaining <= 0:
                raise TimeoutError(f"no answer to the WebSocket upgrade from {where} within {timeout} s")
            if not wait_readable(inner, min(remaining, _SLICE)):
                continue
            try:
                chunk = inner.recv(4096)
            except BlockingIOError:
                continue
            if not chunk:
                raise WebSocketError(f"{where} closed the connection before answering the WebSocket upgrade")
            head += chunk
        end = head.index(b"\r\n\r\n")
        _check_answer(bytes(head[:end]).decode("latin-1"), key, where)
        return cls(inner, max_frame=max_frame, buffered=bytes(head[end + 4:]))

    # ---- what the session sees ----

    def recv(self, size: int, /) -> bytes:
        """Up to `size` bytes of the server's binary payloads; ``b""`` once the stream has ended (the server's
        close, or the connection's end). Reads the connection once at most when nothing is decoded yet:
        ``BlockingIOError`` when that brought no payload. :class:`WebSocketError` when the server broke
        RFC 6455."""
        if self._failed is not None:
            raise WebSocketError(self._failed)
        if not self._data and not self._eof:
            chunk = self._inner.recv(_CHUNK)  # BlockingIOError from a TLS stream passes through
            if chunk:
                self._raw += chunk
                self._decode()
            else:
                self._eof = True
        if self._data:
            taken = bytes(self._data[:size])
            del self._data[:size]
            return taken
        if self._eof:
            return b""
        raise BlockingIOError(errno.EAGAIN, "no WebSocket payload yet")

    def pending(self) -> int:
        """How many bytes :meth:`recv` can return without waiting for the socket (1 for the end of the stream
        when nothing else is left), counting a TLS layer's below: a poll on the socket would not see them."""
        if self._data or self._eof:
            return len(self._data) or 1
        inner = getattr(self._inner, "pending", None)
        return int(inner()) if inner is not None else 0

    def sendall(self, data: bytes, /) -> None:
        """Sends `data` as one binary frame, masked with a fresh key. :class:`WebSocketError` once the
        WebSocket is closing (it answered the server's close)."""
        self._send(Opcode.BINARY, bytes(data))

    def shutdown(self, how: int, /) -> None:
        """Shuts the connection down at once, without a close frame, as a dropped connection would (a blocked
        read wakes up)."""
        self._inner.shutdown(how)

    def close(self) -> None:
        """Closes the connection."""
        self._inner.close()

    def fileno(self) -> int:
        """The connection's file descriptor (for poll and select)."""
        return self._inner.fileno()

    def settimeout(self, timeout: Optional[float], /) -> None:
        """How long a write may wait for the server (None: no limit)."""
        self._inner.settimeout(timeout)

    # ---- frames ----

    def _send(self, opcode: Opcode, payload: bytes) -> None:
        frame = encode_frame(opcode, payload, mask_key=os.urandom(4))
        with self._write_lock:
            if self._close_sent:
                raise WebSocketError("the WebSocket is closed: it answered the server's close")
            if opcode == Opcode.CLOSE:
                self._close_sent = True
            self._inner.sendall(frame)

    def _decode(self) -> None:
        """Decodes the whole frames in _raw (a data frame's payload as far as it came): payloads into _data, the
        control frames answered."""
        try:
            self._decode_frames()
        except WebSocketError as e:
            self._failed = str(e)
            raise

    def _decode_frames(self) -> None:
        raw = self._raw
        while not self._eof:
            if self._remaining:
                take = min(self._remaining, len(raw))
                if not take:
                    return
                self._data += raw[:take]
                del raw[:take]
                self._remaining -= take
                continue
            header = decode_frame_header(raw)
            if header is None:
                return
            fin, opcode, masked, size, header_size = header
            if masked:
                raise WebSocketError("a masked frame from the server: only a client masks its frames")
            if size > self._max_frame:
                raise WebSocketError(f"a frame of {size} bytes, over the limit of {self._max_frame}")
            if opcode >= 8:
                if len(raw) < header_size + size:
                    return  # a control frame is taken whole (125 bytes at most)
                payload = bytes(raw[header_size:header_size + size])
                del raw[:header_size + size]
                self._control(fin, opcode, payload)
                continue
            if opcode == Opcode.TEXT:
                raise WebSocketError("a text frame: the Federate Protocol is sent in binary frames")
            if opcode == Opcode.CONTINUATION and not self._in_message:
                raise WebSocketError("a continuation frame with no fragmented message to continue")
            if opcode == Opcode.BINARY and self._in_message:
                raise WebSocketError("a new binary message before the fragmented one ended")
            if opcode not in (Opcode.CONTINUATION, Opcode.BINARY):
                raise WebSocketError(f"a frame of reserved opcode {opcode:#x}")
            del raw[:header_size]
            self._in_message = not fin
            self._remaining = size

    def _control(self, fin: bool, opcode: int, payload: bytes) -> None:
        if not fin or len(payload) > 125:
            raise WebSocketError(f"a control frame (opcode {opcode:#x}) fragmented or over 125 bytes")
        if opcode == Opcode.PING:
            self._send_quietly(Opcode.PONG, payload)
        elif opcode == Opcode.CLOSE:
            if len(payload) == 1:
                raise WebSocketError("a close frame of 1 byte: a status code is 2")
            self._eof = True
            self._raw.clear()  # nothing after a close counts
            if not self._close_sent:
                self._send_quietly(Opcode.CLOSE, payload[:2])  # the status code echoed, as RFC 6455 says
        elif opcode != Opcode.PONG:
            raise WebSocketError(f"a control frame of reserved opcode {opcode:#x}")

    def _send_quietly(self, opcode: Opcode, payload: bytes) -> None:
        """A pong or a close from the reader: when the connection is failing, the read sees it."""
        try:
            self._send(opcode, payload)
        except OSError:
            pass


def _check_answer(head: str, key: str, where: str) -> None:
    """Checks the server's answer to the upgrade (its status line and headers, `head`)."""
    lines = head.split("\r\n")
    status = lines[0]
    parts = status.split(" ", 2)
    if len(parts) < 2 or not parts[0].startswith("HTTP/") or parts[1] != "101":
        raise WebSocketError(f"{where} refused the WebSocket upgrade: {status!r}")
    headers: Dict[str, List[str]] = {}
    for line in lines[1:]:
        name, colon, value = line.partition(":")
        if not colon:
            raise WebSocketError(f"{where} answered the WebSocket upgrade with a bad header line {line!r}")
        headers.setdefault(name.strip().lower(), []).append(value.strip())

    def tokens(name: str) -> List[str]:
        return [token.strip().lower() for value in headers.get(name, []) for token in value.split(",")]

    if tokens("upgrade") != ["websocket"]:
        raise WebSocketError(f"{where} answered 101 without 'Upgrade: websocket' ({status!r})")
    if "upgrade" not in tokens("connection"):
        raise WebSocketError(f"{where} answered 101 without 'Connection: Upgrade' ({status!r})")
    expected = accept_key(key)
    accepts = headers.get("sec-websocket-accept", [])
    if accepts != [expected]:
        said = accepts[0] if accepts else "none"
        raise WebSocketError(f"{where} answered a wrong Sec-WebSocket-Accept: {said!r}, not {expected!r}")
    for name in ("sec-websocket-extensions", "sec-websocket-protocol"):
        if headers.get(name):
            raise WebSocketError(f"{where} answered {name} {headers[name][0]!r}, which was not asked for")
