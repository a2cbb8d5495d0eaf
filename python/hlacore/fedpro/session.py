"""The Federate Protocol's session layer (IEEE 1516.1-2025, HLA 4), the federate's side.

Every message starts with a 24-byte big-endian header (:class:`Header`): the size of the whole message, its
sequence number, the session id, the number of the last message received from the peer, and its type
(:class:`MessageType`). The federate's first message, NewSession, is its number 0 and the RTI's answer,
NewSessionStatus, the RTI's number 0; after them each side numbers what it sends from 1 up, in a 31-bit space
that wraps (:data:`NO_SEQUENCE` means "none").

:class:`Session` is one session: the handshake, one reader thread, calls matched to their responses by
sequence number (from any number of threads), a queue of the RTI's callbacks, heartbeats, termination, and the
resume after a dropped connection. Everything the federate sends is kept until a header from the RTI says it
arrived, so that a resume on a new connection sends again exactly what the RTI had not received; what the RTI
sends again that the federate had is recognised by its number and ignored.

The session runs over any of the protocol's transports, named as the standard's and Pitch's clients name them
(``connect.protocol``): ``"tcp"``, ``"tls"`` (TCP with TLS), ``"websocket"`` (RFC 6455 over TCP) and
``"websocketsecure"`` (the same over TLS), on ports 15164, 15165, 80 and 443 by default. A resume dials again
the same way: a new TLS handshake, a new WebSocket upgrade.

The codec (:func:`encode_header`, :func:`decode_header`, :func:`encode_message`) has no sockets: tests build
an RTI's side with it.
"""

from __future__ import annotations

import collections
import enum
import errno
import select
import socket
import ssl
import struct
import threading
import time
from dataclasses import dataclass
from typing import Deque, Dict, Optional, Protocol, Set, Tuple

from .websocket import WebSocketStream, wait_readable

#: The size of a message's header, in bytes.
HEADER_SIZE = 24
#: The protocol version NewSession asks for.
PROTOCOL_VERSION = 1
#: "No sequence number": outside the 31-bit space of sequence numbers.
NO_SEQUENCE = 0x80000000
#: The sequence numbers are 0 to SEQUENCE_MASK, and wrap.
SEQUENCE_MASK = 0x7FFFFFFF
#: The largest message :func:`decode_header` accepts by default (header included), as the RTI's default limit.
MAX_MESSAGE_SIZE = 64 << 20
#: The callbacks' bytes a session queues for a federate that does not evoke them before it stops reading.
MAX_QUEUED_BYTES = 64 << 20
#: The Federate Protocol's TCP port when an address names none.
DEFAULT_PORT = 15164
#: The transports a session runs over (``connect.protocol`` in the standard's and Pitch's clients), each with
#: the port it dials when none is given.
DEFAULT_PORTS: Dict[str, int] = {"tcp": DEFAULT_PORT, "tls": 15165, "websocket": 80, "websocketsecure": 443}

_HEADER = struct.Struct(">IIQII")
_U32 = struct.Struct(">I")
_U32X2 = struct.Struct(">II")
_SLICE = 0.1  # waits are cut into slices this long, so that Ctrl-C and a stop request are seen
_FRAME_SLACK = 64 << 10  # a WebSocket frame may hold a whole message and the start of the next
_TLS_CHUNK = 1 << 16  # TLS writes go out this much at a time


class MessageType(enum.IntEnum):
    """The type of a message, the last field of its header."""

    NEW_SESSION = 1
    NEW_SESSION_STATUS = 2
    HEARTBEAT = 3
    HEARTBEAT_RESPONSE = 4
    TERMINATE_SESSION = 5
    SESSION_TERMINATED = 6
    RESUME_REQUEST = 10
    RESUME_STATUS = 11
    HLA_CALL_REQUEST = 20
    HLA_CALL_RESPONSE = 21
    HLA_CALLBACK_REQUEST = 22
    HLA_CALLBACK_RESPONSE = 23


class NewSessionReason(enum.IntEnum):
    """The reason a NewSessionStatus gives: OK, or why the RTI opened no session."""

    OK = 0
    UNSUPPORTED_VERSION = 1
    OUT_OF_RESOURCES = 2
    OTHER = 99


class ResumeStatus(enum.IntEnum):
    """The status a ResumeStatus gives: OK, or why the RTI does not resume the session."""

    OK = 0
    INVALID_SESSION = 1
    NOT_ENOUGH_BUFFERED = 2
    OTHER = 99


class SessionError(Exception):
    """Base class of the session layer's errors."""


class BadMessage(SessionError):
    """A message breaks the protocol: a header whose size is under 24 bytes or over the limit, an unknown type,
    another session's id, a message the federate never receives, or a payload too short for its fields."""


class SessionRefused(SessionError):
    """The RTI answered NewSession with a NewSessionStatus other than OK; ``reason`` is its code."""

    def __init__(self, reason: int) -> None:
        try:
            said = NewSessionReason(reason).name.lower().replace("_", " ")
        except ValueError:
            said = f"reason {reason}"
        super().__init__(f"the RTI opened no session: {said}")
        self.reason = reason


class SessionLost(SessionError):
    """The session is over: it could not be resumed (the RTI refused, or no connection within the resume
    timeout), the RTI ended it or broke the protocol, or it was terminated or closed here. Every call waiting
    on it and every later one raises this."""


class CallTimeout(SessionError, TimeoutError):
    """No response came within the timeout given. The session goes on; a response that comes later is dropped."""


def _type_name(value: int) -> str:
    try:
        return MessageType(value).name
    except ValueError:
        return str(value)


@dataclass(frozen=True)
class Header:
    """A message's header. ``size`` counts the whole message, the header's 24 bytes included."""

    size: int
    sequence: int
    session_id: int
    last_received: int
    type: MessageType

    @property
    def payload_size(self) -> int:
        """The size of the payload that follows the header."""
        return self.size - HEADER_SIZE


def encode_header(header: Header) -> bytes:
    """The 24 big-endian bytes of `header`. ``struct.error`` for a field out of its range."""
    return _HEADER.pack(header.size, header.sequence, header.session_id, header.last_received, int(header.type))


def decode_header(data: bytes, max_size: int = MAX_MESSAGE_SIZE) -> Header:
    """The header at the start of `data` (24 bytes at least). :class:`BadMessage` for fewer bytes, a size under
    the header's 24 or over `max_size`, or an unknown message type."""
    if len(data) < HEADER_SIZE:
        raise BadMessage(f"a header is {HEADER_SIZE} bytes, not {len(data)}")
    size, sequence, session_id, last_received, kind = _HEADER.unpack_from(data)
    if size < HEADER_SIZE:
        raise BadMessage(f"a message of {size} bytes, under its header's {HEADER_SIZE}")
    if size > max_size:
        raise BadMessage(f"a message of {size} bytes, over the limit of {max_size}")
    try:
        message_type = MessageType(kind)
    except ValueError:
        raise BadMessage(f"unknown message type {kind}") from None
    return Header(size, sequence, session_id, last_received, message_type)


def encode_message(message_type: MessageType, sequence: int, session_id: int, last_received: int,
                   payload: bytes = b"") -> bytes:
    """A whole message: its header, then `payload`."""
    header = Header(HEADER_SIZE + len(payload), sequence, session_id, last_received, message_type)
    return encode_header(header) + payload


def valid_sequence(number: int) -> bool:
    """Whether `number` is a sequence number (0 to :data:`SEQUENCE_MASK`), not :data:`NO_SEQUENCE`."""
    return 0 <= number <= SEQUENCE_MASK


def next_sequence(number: int) -> int:
    """The sequence number after `number`, wrapping to 0 after :data:`SEQUENCE_MASK`."""
    return (number + 1) & SEQUENCE_MASK


def after(a: int, b: int) -> bool:
    """Whether sequence number `a` comes after `b` in the wrapping space (less than half of it ahead)."""
    distance = (a - b) & SEQUENCE_MASK
    return 0 < distance < 0x40000000


def split_address(address: str, default_port: int = DEFAULT_PORT) -> Tuple[str, int]:
    """``"host:port"`` (``"[::1]:port"`` for IPv6, ``"host"`` for the default port) as ``(host, port)``."""
    host, port = address, default_port
    if address.startswith("["):
        end = address.find("]")
        if end < 0:
            raise ValueError(f"bad address {address!r}: no closing ']'")
        host, rest = address[1:end], address[end + 1:]
        if rest:
            if not rest.startswith(":"):
                raise ValueError(f"bad address {address!r}")
            port = int(rest[1:])
    elif address.count(":") == 1:
        host, _, number = address.partition(":")
        port = int(number)
    return host or "127.0.0.1", port


class Stream(Protocol):
    """What the session layer reads and writes: a connected socket, or a stream over one that behaves as it
    does (a :class:`TlsStream`, a WebSocket stream). ``recv`` returns ``b""`` at the end of the stream and may
    raise ``BlockingIOError`` when what came holds nothing to return yet: wait (a poll, after ``pending()``
    when the stream has one) and call again."""

    def recv(self, size: int, /) -> bytes:
        """Up to `size` bytes."""

    def sendall(self, data: bytes, /) -> None:
        """Writes all of `data`."""

    def shutdown(self, how: int, /) -> None:
        """Shuts the connection down (``socket.SHUT_RDWR``, ...), waking a blocked read."""

    def close(self) -> None:
        """Closes the connection."""

    def fileno(self) -> int:
        """The connection's file descriptor."""

    def settimeout(self, timeout: Optional[float], /) -> None:
        """How long a write may wait for the peer (None: no limit)."""


class _Closed(Exception):
    """The connection ended (end of stream, an error, or the session stopping)."""


def _readable(sock: Stream, timeout: float) -> bool:
    """Whether `sock` has something to read (or has ended) within `timeout` seconds: at once when its TLS or
    WebSocket layer holds bytes already (a poll on the socket would wait for bytes read off it already)."""
    return wait_readable(sock, timeout)


def _read_exact(sock: Stream, size: int, stop: threading.Event, deadline: Optional[float] = None) -> bytes:
    """`size` bytes from `sock`, waiting in slices so that `stop` is seen; :class:`_Closed` at the end of the
    stream, on an error, on `stop`, and past `deadline` (a ``time.monotonic()`` value)."""
    chunks = []
    while size > 0:
        if stop.is_set():
            raise _Closed("stopped")
        if deadline is not None and time.monotonic() >= deadline:
            raise _Closed("timed out")
        try:
            if not _readable(sock, _SLICE):
                continue
            chunk = sock.recv(min(size, 1 << 20))
        except BlockingIOError:  # part of a TLS record or of a WebSocket frame, or a ping: wait for more
            continue
        except (OSError, ValueError) as e:  # ValueError: the socket was closed under us
            raise _Closed(str(e)) from None
        if not chunk:
            raise _Closed("end of stream")
        chunks.append(chunk)
        size -= len(chunk)
    return b"".join(chunks)


def _read_message(sock: Stream, max_size: int, stop: threading.Event,
                  deadline: Optional[float] = None) -> Tuple[Header, bytes]:
    header = decode_header(_read_exact(sock, HEADER_SIZE, stop, deadline), max_size)
    return header, _read_exact(sock, header.payload_size, stop, deadline)


def _u32(payload: bytes, index: int, what: MessageType) -> int:
    if len(payload) < 4 * (index + 1):
        raise BadMessage(f"a {what.name} of {len(payload)} bytes, too short for its numbers")
    value: int = _U32.unpack_from(payload, 4 * index)[0]
    return value


def _dial(address: Tuple[str, int], timeout: float) -> socket.socket:
    sock = socket.create_connection(address, timeout=max(timeout, 0.001))
    try:
        sock.setsockopt(socket.IPPROTO_TCP, socket.TCP_NODELAY, 1)
    except OSError:
        pass
    return sock


def _shutdown(sock: Stream) -> None:
    try:
        sock.shutdown(socket.SHUT_RDWR)
    except OSError:
        pass


def default_port(protocol: str) -> int:
    """The port the transport `protocol` dials when none is given (:data:`DEFAULT_PORTS`); ``ValueError``
    naming the transports for another name."""
    try:
        return DEFAULT_PORTS[protocol]
    except (KeyError, TypeError):
        raise ValueError(f"unknown Federate Protocol transport {protocol!r}: one of "
                         f"{', '.join(DEFAULT_PORTS)}") from None


class TlsStream:
    """A TLS connection that the session's reader and writers share.

    OpenSSL allows one call at a time on a connection: a read in one thread during a write in another may
    crash. So every TLS call here takes a lock, and none waits while holding it: the socket is non-blocking,
    :meth:`recv` raises ``BlockingIOError`` when no whole record came (wait with :meth:`pending` and a poll),
    and :meth:`sendall` polls for room outside the lock.
    """

    def __init__(self, sock: ssl.SSLSocket, timeout: Optional[float] = None) -> None:
        """The stream over `sock`, its handshake done; a write waits up to `timeout` seconds for room."""
        self._sock = sock
        self._lock = threading.Lock()
        self._timeout = timeout
        sock.setblocking(False)

    def recv(self, size: int, /) -> bytes:
        """Up to `size` decrypted bytes; ``b""`` at the end of the stream; ``BlockingIOError`` when what came
        holds none yet."""
        with self._lock:
            try:
                return self._sock.recv(size)
            except (ssl.SSLWantReadError, ssl.SSLWantWriteError):
                raise BlockingIOError(errno.EAGAIN, "no whole TLS record yet") from None
            except ssl.SSLZeroReturnError:
                return b""

    def pending(self) -> int:
        """How many decrypted bytes wait in the TLS layer: a poll on the socket does not see them."""
        with self._lock:
            return self._sock.pending()

    def sendall(self, data: bytes, /) -> None:
        """Writes all of `data`; ``TimeoutError`` when the peer takes none of it for the timeout."""
        view = memoryview(data)
        deadline = None if self._timeout is None else time.monotonic() + self._timeout
        while view:
            chunk = view[:_TLS_CHUNK]  # after a want-read/write, OpenSSL needs the same bytes again
            with self._lock:
                try:
                    view = view[self._sock.send(chunk):]
                    continue
                except ssl.SSLWantWriteError:
                    writing = True
                except ssl.SSLWantReadError:
                    writing = False
            self._wait(writing, deadline)

    def _wait(self, writing: bool, deadline: Optional[float]) -> None:
        """Waits until the socket can be written (`writing`) or read, or `deadline` passes."""
        remaining = None if deadline is None else deadline - time.monotonic()
        if remaining is not None and remaining <= 0:
            raise TimeoutError(f"the TLS peer took nothing for {self._timeout} s")
        if hasattr(select, "poll"):
            poller = select.poll()
            poller.register(self._sock, select.POLLOUT if writing else select.POLLIN)
            poller.poll(None if remaining is None else remaining * 1000)
        else:
            select.select([] if writing else [self._sock], [self._sock] if writing else [], [], remaining)

    def shutdown(self, how: int, /) -> None:
        """Shuts the TCP connection down (no TLS close_notify), waking a blocked read."""
        # The socket's own shutdown: SSLSocket's would drop its TLS state under a reader still using it.
        socket.socket.shutdown(self._sock, how)

    def close(self) -> None:
        """Closes the connection."""
        with self._lock:
            self._sock.close()

    def fileno(self) -> int:
        """The connection's file descriptor (for poll and select)."""
        return self._sock.fileno()

    def settimeout(self, timeout: Optional[float], /) -> None:
        """How long a write may wait for room (None: no limit); reads never wait."""
        self._timeout = timeout


class Transport:
    """How a session reaches the RTI, the same for its first connection and for each resume's: a TCP
    connection, then, as `protocol` says (:data:`DEFAULT_PORTS`), a TLS handshake checking the RTI's
    certificate with `ssl_context` for `server_hostname` (by default the host dialed) and a WebSocket upgrade
    requesting `path`, whose frames may be `max_frame` bytes long at most."""

    def __init__(self, protocol: str = "tcp", *, ssl_context: Optional[ssl.SSLContext] = None,
                 server_hostname: Optional[str] = None, path: str = "/",
                 max_frame: int = MAX_MESSAGE_SIZE + _FRAME_SLACK) -> None:
        """``ValueError`` for an unknown `protocol`, or an `ssl_context` for one without TLS. TLS without a
        context uses ``ssl.create_default_context()``: the system's certificate authorities."""
        default_port(protocol)
        self.protocol = protocol
        #: Whether the connection is TLS.
        self.secure = protocol in ("tls", "websocketsecure")
        if ssl_context is not None and not self.secure:
            raise ValueError(f"an ssl_context for the transport {protocol!r}, which has no TLS: "
                             f"use 'tls' or 'websocketsecure'")
        if ssl_context is None and self.secure:
            ssl_context = ssl.create_default_context()
        self.ssl_context = ssl_context
        self.server_hostname = server_hostname
        self.path = path
        self.max_frame = max_frame

    def dial(self, address: Tuple[str, int], timeout: float) -> Stream:
        """A new connection to `address` (host, port) over this transport, ready for the session's first
        message, within `timeout` seconds: ``OSError`` otherwise (``ssl.SSLError`` when the TLS handshake
        fails, a ``ConnectionError`` when the WebSocket upgrade does)."""
        deadline = time.monotonic() + timeout
        sock = _dial(address, timeout)
        stream: Stream = sock
        try:
            if self.secure:
                assert self.ssl_context is not None
                sock.settimeout(max(deadline - time.monotonic(), 0.001))
                tls = self.ssl_context.wrap_socket(sock, server_hostname=self.server_hostname or address[0])
                stream = TlsStream(tls, timeout)
            if self.protocol.startswith("websocket"):
                stream = WebSocketStream.connect(stream, address[0], address[1], path=self.path,
                                                 secure=self.secure, timeout=max(deadline - time.monotonic(), 0.001),
                                                 max_frame=self.max_frame)
        except BaseException:
            stream.close()
            sock.close()
            raise
        return stream


class Session:
    """One Federate Protocol session with an RTI, the federate's side, over TCP, TLS or a WebSocket.

    Open it with :meth:`connect`. Then :meth:`call` sends an HLA call (a serialized ``CallRequest``) and waits
    for its response (a serialized ``CallResponse``); any number of threads may call at once, each response is
    matched to its request by sequence number. The RTI's callbacks (serialized ``CallbackRequest``) queue up
    until :meth:`next_callback` pops them; :meth:`answer_callback` sends each one's ``CallbackResponse``.

    One reader thread reads the connection. When the connection drops, that thread dials the RTI again (the
    same way: a new TLS handshake, a new WebSocket upgrade), for up to `resume_timeout` seconds, and resumes
    the session: the RTI says which of the federate's messages it has, the session sends the rest again, and
    the RTI sends again what the federate had not received. Calls made meanwhile are kept and sent on the new
    connection; a call waits through the resume. If no resume succeeds in time (or the RTI refuses it), the
    session is lost: the waiting calls and every later one raise :class:`SessionLost`.

    Memory stays bounded by what the RTI has not confirmed: a sent message is released as soon as a header
    from the RTI shows that it arrived.

    :meth:`terminate` ends the session with the RTI; :meth:`close` drops it without a word. A session is a
    context manager that terminates it (best effort) and closes it.
    """

    def __init__(self, sock: Stream, session_id: int, address: Tuple[str, int], *,
                 resume_timeout: float = 30.0, connect_timeout: float = 10.0,
                 max_message: int = MAX_MESSAGE_SIZE, write_timeout: float = 30.0,
                 transport: Optional[Transport] = None, max_queued: int = MAX_QUEUED_BYTES) -> None:
        """A session already opened on `sock` (its NewSessionStatus received), which a resume dials again over
        `transport` (None: plain TCP). :meth:`connect` makes one."""
        self._session_id = session_id
        self._address = address
        self._transport = transport if transport is not None else Transport()
        self._resume_timeout = resume_timeout
        self._connect_timeout = connect_timeout
        self._max_message = max_message
        self._write_timeout = write_timeout
        self._send_lock = threading.Lock()  # numbering and writing, so messages leave in their numbers' order
        self._lock = threading.Lock()  # the state below; taken after _send_lock when both are
        self._changed = threading.Condition(self._lock)
        self._sock: Optional[Stream] = sock  # None while the connection is dropped
        self._next = 1  # NewSession was 0
        self._last_received = 0  # NewSessionStatus was the RTI's 0
        self._kept: Deque[Tuple[int, MessageType, bytes]] = collections.deque()
        self._kept_bytes = 0
        self._pending: Dict[int, Optional[bytes]] = {}  # awaited sequence number -> its response, once here
        self._heartbeats: Set[int] = set()
        self._callbacks: Deque[Tuple[int, bytes]] = collections.deque()
        self._queued_bytes = 0  # of the callbacks' payloads
        self._max_queued = max_queued
        self._lost: Optional[str] = None  # why the session is over
        self._terminated = False  # SessionTerminated received
        self._resumes = 0
        self._stop = threading.Event()
        sock.settimeout(write_timeout)
        self._reader = threading.Thread(target=self._run, name=f"fedpro-session-{session_id:x}", daemon=True)
        self._reader.start()

    @classmethod
    def connect(cls, host: str, port: Optional[int] = None, *, protocol: str = "tcp",
                ssl_context: Optional[ssl.SSLContext] = None, server_hostname: Optional[str] = None,
                path: str = "/", timeout: float = 10.0, resume_timeout: float = 30.0,
                max_message: int = MAX_MESSAGE_SIZE, max_queued: int = MAX_QUEUED_BYTES) -> "Session":
        """Dials the RTI at `host`:`port` and opens a session: NewSession (protocol version 1), then the RTI's
        NewSessionStatus, within `timeout` seconds (also the timeout of each dial when resuming).

        While the callbacks waiting for :meth:`next_callback` hold more than `max_queued` bytes, the session stops
        reading from the RTI (unless a call or heartbeat awaits its answer): a federate that does not evoke leaves
        what comes to the RTI, which keeps it within its own budgets, rather than growing this process.

        `protocol` is the transport: ``"tcp"``, ``"tls"``, ``"websocket"`` or ``"websocketsecure"``; `port`
        None dials its default port (15164, 15165, 80, 443). Over TLS the RTI's certificate is checked with
        `ssl_context` (by default ``ssl.create_default_context()``, the system's certificate authorities) for
        `server_hostname` (by default `host`); a WebSocket requests `path`. Each resume dials the same way.

        :class:`SessionRefused` when the RTI opens none, :class:`BadMessage` for another answer,
        ``OSError`` (``ConnectionRefusedError``, ``TimeoutError``, ``ssl.SSLCertVerificationError``, a
        ``ConnectionError`` quoting the status line of a refused WebSocket upgrade, ...) when it cannot be
        reached or does not answer in time; ``ValueError`` for an unknown `protocol`."""
        transport = Transport(protocol, ssl_context=ssl_context, server_hostname=server_hostname, path=path,
                              max_frame=max_message + _FRAME_SLACK)
        if port is None:
            port = default_port(protocol)
        deadline = time.monotonic() + timeout
        sock = transport.dial((host, port), timeout)
        try:
            sock.sendall(encode_message(MessageType.NEW_SESSION, 0, 0, NO_SEQUENCE, _U32.pack(PROTOCOL_VERSION)))
            try:
                header, payload = _read_message(sock, max_message, threading.Event(), deadline)
            except _Closed as e:
                if time.monotonic() >= deadline:
                    raise TimeoutError(f"no NewSessionStatus from {host}:{port} within {timeout} s") from None
                raise ConnectionError(f"{host}:{port} closed the connection before NewSessionStatus ({e})") from None
            if header.type != MessageType.NEW_SESSION_STATUS:
                raise BadMessage(f"expected NewSessionStatus, got {header.type.name}")
            reason = _u32(payload, 0, header.type)
            if reason != NewSessionReason.OK:
                raise SessionRefused(reason)
        except BaseException:
            sock.close()
            raise
        return cls(sock, header.session_id, (host, port), resume_timeout=resume_timeout, connect_timeout=timeout,
                   max_message=max_message, transport=transport, max_queued=max_queued)

    # ---- what the federate sees ----

    @property
    def session_id(self) -> int:
        """The session's id, given by the RTI in its NewSessionStatus."""
        return self._session_id

    @property
    def lost(self) -> Optional[str]:
        """Why the session is over (lost, terminated or closed), or None while it goes on."""
        with self._lock:
            return self._lost

    @property
    def kept_messages(self) -> int:
        """How many sent messages are kept for a resume: those the RTI has not confirmed yet."""
        with self._lock:
            return len(self._kept)

    @property
    def kept_bytes(self) -> int:
        """The payload bytes of the kept messages (:attr:`kept_messages`)."""
        with self._lock:
            return self._kept_bytes

    @property
    def resumes(self) -> int:
        """How many times the session was resumed after a dropped connection."""
        with self._lock:
            return self._resumes

    @property
    def pending_callbacks(self) -> int:
        """How many received callbacks wait in the queue for :meth:`next_callback`."""
        with self._lock:
            return len(self._callbacks)

    @property
    def queued_bytes(self) -> int:
        """The bytes of the callbacks waiting in the queue (the session stops reading beyond `max_queued`)."""
        with self._lock:
            return self._queued_bytes

    def call(self, request: bytes, timeout: Optional[float] = 60.0) -> bytes:
        """Sends an HlaCallRequest with `request` (a serialized ``CallRequest``) and returns the payload of
        its HlaCallResponse (a serialized ``CallResponse``), waiting up to `timeout` seconds (None: no limit),
        through a resume if the connection drops. :class:`CallTimeout` when no response came in time,
        :class:`SessionLost` when the session is or becomes lost, ``ValueError`` for a request over the
        message size limit."""
        sequence = self._send(MessageType.HLA_CALL_REQUEST, request, awaited=True)
        return self._wait(sequence, timeout, "HLA call")

    def next_callback(self, timeout: Optional[float] = 0.0) -> Optional[Tuple[int, bytes]]:
        """The oldest received HlaCallbackRequest as ``(sequence number, serialized CallbackRequest)``,
        waiting up to `timeout` seconds for one (0: do not wait; None: no limit); None when none came.
        Answer each one with :meth:`answer_callback`. :class:`SessionLost` once the session is over."""
        deadline = None if timeout is None else time.monotonic() + timeout
        with self._changed:
            while True:
                if self._lost is not None:
                    raise SessionLost(self._lost)
                if self._callbacks:
                    callback = self._callbacks.popleft()
                    self._queued_bytes -= len(callback[1])
                    self._changed.notify_all()  # the reader may be waiting for room
                    return callback
                remaining = _SLICE if deadline is None else deadline - time.monotonic()
                if remaining <= 0:
                    return None
                self._changed.wait(min(remaining, _SLICE))

    def answer_callback(self, sequence: int, response: bytes) -> None:
        """Sends the HlaCallbackResponse to the callback numbered `sequence`: `response` is a serialized
        ``CallbackResponse``. Does not wait. :class:`SessionLost` once the session is over."""
        self._send(MessageType.HLA_CALLBACK_RESPONSE, _U32.pack(sequence) + response)

    def heartbeat(self, timeout: Optional[float] = 10.0) -> float:
        """Sends a Heartbeat and waits up to `timeout` seconds for its HeartbeatResponse; returns the round
        trip in seconds. A resume also answers a waiting heartbeat (the RTI is there). :class:`CallTimeout`,
        :class:`SessionLost` as :meth:`call`."""
        start = time.monotonic()
        sequence = self._send(MessageType.HEARTBEAT, b"", awaited=True, heartbeat=True)
        self._wait(sequence, timeout, "heartbeat")
        return time.monotonic() - start

    def terminate(self, timeout: float = 10.0) -> None:
        """Ends the session: sends TerminateSession, waits up to `timeout` seconds for SessionTerminated, then
        closes the connection. Nothing to do on a session already over. :class:`SessionLost` when no
        SessionTerminated came (the session is closed all the same)."""
        try:
            self._send(MessageType.TERMINATE_SESSION, b"")
        except SessionLost:
            self.close()
            return
        deadline = time.monotonic() + timeout
        with self._changed:
            while not self._terminated and self._lost is None and time.monotonic() < deadline:
                self._changed.wait(min(deadline - time.monotonic(), _SLICE))
            terminated, why = self._terminated, self._lost
        self.close()
        if not terminated:
            raise SessionLost(why or f"no SessionTerminated within {timeout} s")

    def close(self) -> None:
        """Closes the connection without telling the RTI (which ends the session when its resume timeout
        passes) and stops the reader thread. Waiting and later calls raise :class:`SessionLost`. Idempotent."""
        self._lose("the session was closed")
        self._stop.set()
        with self._lock:
            sock = self._sock
        if sock is not None:
            _shutdown(sock)
        if self._reader is not threading.current_thread():
            self._reader.join(timeout=5.0)

    def drop_connection(self) -> None:
        """Closes the connection abruptly, as a network failure would, for tests: the session resumes on a new
        connection as after a real drop."""
        with self._lock:
            sock = self._sock
        if sock is not None:
            _shutdown(sock)

    def __enter__(self) -> "Session":
        """The session itself."""
        return self

    def __exit__(self, *exc: object) -> None:
        """Terminates the session (best effort: a lost session is just closed) and closes it."""
        try:
            self.terminate()
        except SessionError:
            pass
        finally:
            self.close()

    # ---- sending ----

    def _send(self, message_type: MessageType, payload: bytes, *, awaited: bool = False,
              heartbeat: bool = False) -> int:
        """Numbers, keeps and writes a message; its sequence number. The write happens only while connected:
        a message sent while dropped goes out when the session resumes."""
        if HEADER_SIZE + len(payload) > self._max_message:
            raise ValueError(f"a message of {HEADER_SIZE + len(payload)} bytes, over the limit of "
                             f"{self._max_message}")
        with self._send_lock:
            with self._lock:
                if self._lost is not None:
                    raise SessionLost(self._lost)
                sequence = self._next
                self._next = next_sequence(sequence)
                if awaited:
                    self._pending[sequence] = None
                    self._changed.notify_all()  # a reader waiting for room reads again: the answer must come in
                if heartbeat:
                    self._heartbeats.add(sequence)
                self._kept.append((sequence, message_type, payload))
                self._kept_bytes += len(payload)
                sock, last = self._sock, self._last_received
            if sock is not None:
                self._write(sock, encode_message(message_type, sequence, self._session_id, last, payload))
        return sequence

    def _write(self, sock: Stream, data: bytes) -> None:
        """Writes `data`, under _send_lock. On a failure the connection is shut down: the reader sees the drop
        and resumes, and the message, kept, goes out again then."""
        try:
            sock.sendall(data)
        except OSError:
            _shutdown(sock)

    def _wait(self, sequence: int, timeout: Optional[float], what: str) -> bytes:
        deadline = None if timeout is None else time.monotonic() + timeout
        with self._changed:
            try:
                while True:
                    response = self._pending.get(sequence)
                    if response is not None:
                        return response
                    if self._lost is not None:
                        raise SessionLost(self._lost)
                    remaining = _SLICE if deadline is None else deadline - time.monotonic()
                    if remaining <= 0:
                        raise CallTimeout(f"no response to the {what} numbered {sequence} within {timeout} s")
                    self._changed.wait(min(remaining, _SLICE))
            finally:
                self._pending.pop(sequence, None)
                self._heartbeats.discard(sequence)

    # ---- the reader thread ----

    def _run(self) -> None:
        try:
            while not self._stop.is_set():
                with self._changed:
                    while self._queued_bytes > self._max_queued and not self._pending and not self._stop.is_set():
                        self._changed.wait(_SLICE)
                    sock = self._sock
                if sock is None:
                    if not self._resume():
                        return
                    continue
                try:
                    header, payload = _read_message(sock, self._max_message, self._stop)
                    self._receive(header, payload)
                except _Closed:
                    self._drop(sock)
                    continue
                except BadMessage as e:
                    self._lose(f"the RTI broke the protocol: {e}")
                    return
                if self._terminated:
                    return
        finally:
            self._lose("the session was closed")
            with self._send_lock:
                with self._lock:
                    sock, self._sock = self._sock, None
            if sock is not None:
                sock.close()

    def _drop(self, sock: Stream) -> None:
        """Forgets the connection `sock` after it ended (under _send_lock: no write is using it)."""
        _shutdown(sock)
        with self._send_lock:
            with self._lock:
                if self._sock is sock:
                    self._sock = None
        sock.close()

    def _receive(self, header: Header, payload: bytes) -> None:
        if header.session_id != self._session_id:
            raise BadMessage(f"a message of session {header.session_id:#x} in session {self._session_id:#x}")
        if not valid_sequence(header.sequence):
            raise BadMessage(f"sequence number {header.sequence:#x} out of range")
        if header.type not in (MessageType.HEARTBEAT_RESPONSE, MessageType.HLA_CALL_RESPONSE,
                               MessageType.HLA_CALLBACK_REQUEST, MessageType.SESSION_TERMINATED):
            raise BadMessage(f"a {header.type.name} within a session")
        answered = None
        if header.type in (MessageType.HEARTBEAT_RESPONSE, MessageType.HLA_CALL_RESPONSE):
            answered = _u32(payload, 0, header.type)
        with self._changed:
            if valid_sequence(header.last_received):
                self._release_through(header.last_received)
            if not after(header.sequence, self._last_received):
                return  # sent again after a resume: had it already
            self._last_received = header.sequence
            if header.type == MessageType.HLA_CALLBACK_REQUEST:
                self._callbacks.append((header.sequence, payload))
                self._queued_bytes += len(payload)
            elif header.type == MessageType.SESSION_TERMINATED:
                self._terminated = True
                if self._lost is None:
                    self._lost = "the session was terminated"
            elif answered is not None and answered in self._pending:  # else answered after its caller gave up
                self._pending[answered] = payload[4:]
            self._changed.notify_all()

    def _release_through(self, number: int) -> None:
        """Lets go of the kept messages up to `number`, which the RTI says it received (under _lock)."""
        while self._kept and not after(self._kept[0][0], number):
            _, _, payload = self._kept.popleft()
            self._kept_bytes -= len(payload)

    def _lose(self, reason: str) -> None:
        with self._changed:
            if self._lost is None:
                self._lost = reason
            self._changed.notify_all()

    def _resume(self) -> bool:
        """Dials the RTI again and resumes the session, retrying for up to the resume timeout; False (the
        session lost) when that fails or the session is stopping."""
        deadline = time.monotonic() + self._resume_timeout
        delay = 0.02
        why = "no connection"
        while not self._stop.is_set():
            remaining = deadline - time.monotonic()
            if remaining <= 0:
                self._lose(f"the connection dropped and the session could not be resumed within "
                           f"{self._resume_timeout} s ({why})")
                return False
            try:
                sock = self._transport.dial(self._address, min(remaining, self._connect_timeout))
            except OSError as e:
                why = str(e) or type(e).__name__
                self._stop.wait(min(delay, max(deadline - time.monotonic(), 0)))
                delay = min(delay * 2, 1.0)
                continue
            try:
                if self._resume_on(sock, min(deadline, time.monotonic() + self._connect_timeout)):
                    return True
            except SessionLost as e:
                sock.close()
                self._lose(str(e))
                return False
            except (_Closed, OSError, BadMessage) as e:
                why = str(e) or type(e).__name__
            sock.close()
        return False

    def _resume_on(self, sock: Stream, deadline: float) -> bool:
        """The resume handshake on the new connection `sock`; True when the session goes on, on it."""
        with self._lock:
            last = self._last_received
            oldest = self._kept[0][0] if self._kept else self._next
        sock.sendall(encode_message(MessageType.RESUME_REQUEST, NO_SEQUENCE, self._session_id, last,
                                    _U32X2.pack(last, oldest)))
        header, payload = _read_message(sock, self._max_message, self._stop, deadline)
        if header.type != MessageType.RESUME_STATUS:
            raise BadMessage(f"expected ResumeStatus, got {header.type.name}")
        status, received = _u32(payload, 0, header.type), _u32(payload, 1, header.type)
        if status != ResumeStatus.OK:
            try:
                said = ResumeStatus(status).name.lower().replace("_", " ")
            except ValueError:
                said = f"status {status}"
            raise SessionLost(f"the connection dropped and the RTI refused to resume the session: {said}")
        sock.settimeout(self._write_timeout)
        with self._send_lock:
            with self._changed:
                if valid_sequence(received):
                    self._release_through(received)
                resend = list(self._kept)
                self._sock = sock
                self._resumes += 1
                for sequence in list(self._heartbeats):  # the RTI is there: that is what they asked
                    if sequence in self._pending and self._pending[sequence] is None:
                        self._pending[sequence] = b""
                self._changed.notify_all()
                last = self._last_received
            for sequence, message_type, kept_payload in resend:
                self._write(sock, encode_message(message_type, sequence, self._session_id, last, kept_payload))
        return True
