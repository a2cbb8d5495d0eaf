"""The transports of the pure-Python Federate Protocol client (hlacore.fedpro): "tcp", "tls", "websocket" and
"websocketsecure". The WebSocket client (hlacore.fedpro.websocket) against a WebSocket server written here (a
thread on a loopback port doing the server's side of the upgrade, then frames the test writes and reads): the
upgrade and its refusals, masked binary frames out, fragments, pings, lengths of 7, 16 and 64 bits, close, and
the frames a client must refuse. TLS against a TLS server here with a throwaway certificate from the `openssl`
command: bytes already decrypted are read without waiting for the socket. Sessions over each transport resume
on a new connection of the same kind; RTIambassador takes the transport and HLAplainTextPassword credentials.
Every wait is bounded; every server and connection is closed after its test."""

from __future__ import annotations

import base64
import concurrent.futures
import dataclasses
import hashlib
import os
import pathlib
import queue
import re
import select
import socket
import ssl
import struct
import subprocess
import threading
import time
from concurrent.futures import ThreadPoolExecutor
from typing import Any, Callable, Iterator, List, Optional, Tuple, TypeVar

import pytest

from hlacore import fedpro
from hlacore.fedpro import messages
from hlacore.fedpro._proto import RTIambassador_pb2
from hlacore.fedpro.session import (HEADER_SIZE, NO_SEQUENCE, Header, MessageType, NewSessionReason, ResumeStatus,
                                    Session, Transport, decode_header, default_port, encode_message)
from hlacore.fedpro.websocket import (Opcode, WebSocketError, WebSocketStream, accept_key, encode_frame, mask,
                                      wait_readable)

WAIT = 5.0  # the longest any step waits for the other side
SESSION_ID = 0x0123_4567_89AB_CDEF
T = TypeVar("T")

RTI: Any = RTIambassador_pb2


def u32(*values: int) -> bytes:
    return struct.pack(f">{len(values)}I", *values)


def result(future: "concurrent.futures.Future[T]") -> T:
    return future.result(timeout=WAIT)


# ---- the server's side, written here ----

@dataclasses.dataclass
class Frame:
    fin: bool
    opcode: int
    mask_key: Optional[bytes]  # None: not masked
    payload: bytes  # unmasked
    length_code: int  # the 7-bit length field: the size, or 126 (16 bits follow) or 127 (64 bits)


def upgraded(key: str) -> bytes:
    """The right answer to an upgrade with `key`; the accept computed here, not by the client's code."""
    accept = base64.b64encode(hashlib.sha1((key + "258EAFA5-E914-47DA-95CA-C5AB0DC85B11").encode()).digest())
    return (b"HTTP/1.1 101 Switching Protocols\r\nUpgrade: websocket\r\nConnection: Upgrade\r\n"
            b"Sec-WebSocket-Accept: " + accept + b"\r\n\r\n")


class Conn:
    """The server's side of one accepted connection (TLS already, when the server has a context): raw bytes,
    WebSocket frames, and whole Federate Protocol messages (in binary frames over a WebSocket)."""

    def __init__(self, sock: socket.socket, websocket: bool) -> None:
        self.sock = sock
        self.websocket = websocket
        self.payload = b""  # client payload decoded from frames and not read yet
        self.next = 1  # the RTI's numbers; NewSessionStatus is 0
        self.last_received = 0
        sock.settimeout(WAIT)

    def exact(self, size: int) -> bytes:
        data = b""
        while len(data) < size:
            chunk = self.sock.recv(size - len(data))
            assert chunk, "the client closed the connection"
            data += chunk
        return data

    def read_frame(self) -> Frame:
        first, second = self.exact(2)
        size = second & 0x7F
        if size == 126:
            size = struct.unpack(">H", self.exact(2))[0]
        elif size == 127:
            size = struct.unpack(">Q", self.exact(8))[0]
        key = self.exact(4) if second & 0x80 else None
        payload = self.exact(size)
        return Frame(bool(first & 0x80), first & 0x0F, key, mask(payload, key) if key else payload, second & 0x7F)

    def write_frame(self, opcode: int, payload: bytes = b"", fin: bool = True) -> None:
        self.sock.sendall(encode_frame(opcode, payload, fin=fin))

    def read(self, size: int) -> bytes:
        if not self.websocket:
            return self.exact(size)
        while len(self.payload) < size:
            frame = self.read_frame()
            assert frame.opcode in (Opcode.BINARY, Opcode.CONTINUATION) and frame.mask_key is not None, frame
            self.payload += frame.payload
        data, self.payload = self.payload[:size], self.payload[size:]
        return data

    def send(self, data: bytes) -> None:
        if self.websocket:
            self.write_frame(Opcode.BINARY, data)
        else:
            self.sock.sendall(data)

    def read_message(self) -> Tuple[Header, bytes]:
        header = decode_header(self.read(HEADER_SIZE))
        payload = self.read(header.payload_size)
        if header.sequence != NO_SEQUENCE and header.type != MessageType.NEW_SESSION:
            self.last_received = header.sequence
        return header, payload

    def message(self, message_type: MessageType, payload: bytes = b"") -> bytes:
        """The RTI's next message, numbered, not sent."""
        sequence, self.next = self.next, self.next + 1
        return encode_message(message_type, sequence, SESSION_ID, self.last_received, payload)

    def open_session(self) -> None:
        """Reads NewSession and answers NewSessionStatus OK."""
        header, payload = self.read_message()
        assert header.type == MessageType.NEW_SESSION and payload == u32(1)
        self.send(encode_message(MessageType.NEW_SESSION_STATUS, 0, SESSION_ID, 0, u32(NewSessionReason.OK)))

    def answer_call(self) -> Tuple[int, bytes]:
        """Reads an HlaCallRequest: (its number, its request)."""
        header, payload = self.read_message()
        assert header.type == MessageType.HLA_CALL_REQUEST, header
        return header.sequence, payload

    def silent(self, seconds: float = 0.3) -> bool:
        """Whether nothing (not even the end of the stream) comes for `seconds`."""
        ready, _, _ = select.select([self.sock], [], [], seconds)
        return not ready


class Server:
    """A server on a loopback port whose thread accepts connections: each one TLS when `tls` is given, then,
    for a WebSocket, upgraded with `answer(key)` (by default the right 101); they wait in order for
    :meth:`next`. The heads of the upgrade requests are in `requests`."""

    def __init__(self, tls: Optional[ssl.SSLContext] = None, websocket: bool = False,
                 answer: Callable[[str], bytes] = upgraded) -> None:
        self.listener = socket.create_server(("127.0.0.1", 0))
        self.port: int = self.listener.getsockname()[1]
        self.tls, self.websocket, self.answer = tls, websocket, answer
        self.requests: List[str] = []
        self.errors: List[BaseException] = []
        self._accepted: "queue.Queue[Conn]" = queue.Queue()
        self._open: List[socket.socket] = []
        self._stop = threading.Event()
        self._thread = threading.Thread(target=self._run, name="test-server", daemon=True)
        self._thread.start()

    def next(self) -> Conn:
        """The next connection, ready; AssertionError when none came within WAIT."""
        try:
            return self._accepted.get(timeout=WAIT)
        except queue.Empty:
            raise AssertionError(f"no connection within {WAIT} s; errors: {self.errors}") from None

    def close(self) -> None:
        self._stop.set()
        self._thread.join(WAIT)
        for sock in self._open:
            sock.close()
        self.listener.close()

    def _run(self) -> None:
        while not self._stop.is_set():
            ready, _, _ = select.select([self.listener], [], [], 0.05)
            if not ready:
                continue
            sock, _ = self.listener.accept()
            self._open.append(sock)
            try:
                sock.settimeout(WAIT)
                if self.tls is not None:
                    sock = self.tls.wrap_socket(sock, server_side=True)
                    self._open.append(sock)
                conn = Conn(sock, self.websocket)
                if self.websocket:
                    self._upgrade(conn)
                self._accepted.put(conn)
            except (OSError, AssertionError) as e:  # a client that gave up on a certificate, ...
                self.errors.append(e)
                sock.close()

    def _upgrade(self, conn: Conn) -> None:
        head = b""
        while b"\r\n\r\n" not in head:
            chunk = conn.sock.recv(4096)
            assert chunk, "the client closed the connection during the upgrade"
            head += chunk
        request = head.decode("latin-1")
        self.requests.append(request)
        key = re.search(r"(?im)^Sec-WebSocket-Key:\s*(\S+)", request)
        conn.sock.sendall(self.answer(key.group(1) if key else ""))


@pytest.fixture
def pool() -> Iterator[ThreadPoolExecutor]:
    """Threads for the client's blocking calls while the test plays the server."""
    with ThreadPoolExecutor(max_workers=4) as executor:
        yield executor


@pytest.fixture
def servers() -> Iterator[Callable[..., Server]]:
    """Makes servers (Server's arguments); all are closed after the test."""
    made: List[Server] = []

    def make(**options: Any) -> Server:
        made.append(Server(**options))
        return made[-1]

    yield make
    for server in made:
        server.close()


@pytest.fixture
def closing() -> Iterator[Callable[[T], T]]:
    """Registers a client stream or session to close after the test; returns it."""
    opened: List[Any] = []

    def register(thing: T) -> T:
        opened.append(thing)
        return thing

    yield register
    for thing in opened:
        thing.close()


# ---- a throwaway certificate ----

@dataclasses.dataclass
class Certificate:
    cert: pathlib.Path  # self-signed, for 127.0.0.1 and localhost
    key: pathlib.Path

    def client(self) -> ssl.SSLContext:
        """A client's context that trusts this certificate only."""
        context = ssl.create_default_context()
        context.load_verify_locations(cafile=str(self.cert))
        return context

    def server(self) -> ssl.SSLContext:
        context = ssl.SSLContext(ssl.PROTOCOL_TLS_SERVER)
        context.load_cert_chain(str(self.cert), str(self.key))
        return context


@pytest.fixture(scope="module")
def certificate(tmp_path_factory: pytest.TempPathFactory) -> Certificate:
    directory = tmp_path_factory.mktemp("tls")
    cert, key = directory / "rti.pem", directory / "rti.key"
    subprocess.run(["openssl", "req", "-x509", "-newkey", "rsa:2048", "-nodes", "-subj", "/CN=localhost",
                    "-addext", "subjectAltName=IP:127.0.0.1,DNS:localhost", "-days", "1",
                    "-keyout", str(key), "-out", str(cert)], check=True, capture_output=True, timeout=60,
                   stdin=subprocess.DEVNULL)
    return Certificate(cert, key)


# ---- the client's side ----

def ws_connect(server: Server, closing: Callable[[Any], Any], path: str = "/fedpro",
               max_frame: int = 1 << 20, send_buffer: Optional[int] = None) -> WebSocketStream:
    sock = closing(socket.create_connection(("127.0.0.1", server.port), timeout=WAIT))
    if send_buffer is not None:
        sock.setsockopt(socket.SOL_SOCKET, socket.SO_SNDBUF, send_buffer)
    return WebSocketStream.connect(sock, "127.0.0.1", server.port, path=path, timeout=WAIT, max_frame=max_frame)


def receive(stream: Any, size: int) -> bytes:
    """`size` bytes from a client stream, waiting as the session does; fewer when the stream ends."""
    data = b""
    deadline = time.monotonic() + WAIT
    while len(data) < size:
        remaining = deadline - time.monotonic()
        assert remaining > 0, f"{len(data)} bytes of {size} within {WAIT} s"
        if not wait_readable(stream, min(remaining, 0.1)):
            continue
        try:
            chunk = stream.recv(size - len(data))
        except BlockingIOError:
            continue
        if not chunk:
            break
        data += chunk
    return data


# ---- the WebSocket client ----

def test_the_accept_key_is_rfc_6455s() -> None:
    """The example of RFC 6455, 1.3."""
    assert accept_key("dGhlIHNhbXBsZSBub25jZQ==") == "s3pPLMBiTxaQ9kYGzzhZRbK+xOo="


def test_the_upgrade_then_masked_binary_frames_out_and_binary_in(
        servers: Callable[..., Server], closing: Callable[[Any], Any]) -> None:
    """GET path with Host, Upgrade, Connection, a fresh 16-byte key and version 13; then each write is one
    binary frame, final, masked with a fresh key; the server's binary frames are read back."""
    server = servers(websocket=True)
    client = ws_connect(server, closing)
    conn = server.next()
    lines = server.requests[0].split("\r\n")
    assert lines[0] == "GET /fedpro HTTP/1.1"
    headers = {name.lower(): value.strip() for name, _, value in (line.partition(":") for line in lines[1:] if line)}
    assert headers["host"] == f"127.0.0.1:{server.port}"
    assert headers["upgrade"].lower() == "websocket" and headers["connection"].lower() == "upgrade"
    assert headers["sec-websocket-version"] == "13"
    assert len(base64.b64decode(headers["sec-websocket-key"], validate=True)) == 16

    client.sendall(b"hello")
    client.sendall(b"hello")
    first, second = conn.read_frame(), conn.read_frame()
    for frame in (first, second):
        assert (frame.fin, frame.opcode, frame.payload) == (True, Opcode.BINARY, b"hello")
        assert frame.mask_key is not None
    assert first.mask_key != second.mask_key

    conn.write_frame(Opcode.BINARY, b"world")
    assert receive(client, 5) == b"world"


def test_a_second_upgrade_has_a_new_key(servers: Callable[..., Server], closing: Callable[[Any], Any]) -> None:
    server = servers(websocket=True)
    ws_connect(server, closing)
    ws_connect(server, closing)
    keys = [re.search(r"(?im)^Sec-WebSocket-Key:\s*(\S+)", request).group(1)  # type: ignore[union-attr]
            for request in server.requests]
    assert len(keys) == 2 and keys[0] != keys[1]


@pytest.mark.parametrize("size, code", [(0, 0), (125, 125), (126, 126), (65535, 126), (65536, 127), (70000, 127)])
def test_lengths_of_7_16_and_64_bits_both_ways(servers: Callable[..., Server], closing: Callable[[Any], Any],
                                               size: int, code: int) -> None:
    server = servers(websocket=True)
    client = ws_connect(server, closing)
    conn = server.next()
    data = os.urandom(size)
    client.sendall(data)
    frame = conn.read_frame()
    assert (frame.length_code, frame.payload) == (code, data)
    conn.write_frame(Opcode.BINARY, data)
    conn.write_frame(Opcode.BINARY, b"end")
    assert receive(client, size + 3) == data + b"end"


def test_fragments_make_one_stream_and_pings_between_them_are_answered(
        servers: Callable[..., Server], closing: Callable[[Any], Any]) -> None:
    """Continuation frames continue the binary message; a ping between fragments gets a pong with its
    payload, a pong is ignored; what the session reads is the payloads in order."""
    server = servers(websocket=True)
    client = ws_connect(server, closing)
    conn = server.next()
    conn.write_frame(Opcode.BINARY, b"abc", fin=False)
    conn.write_frame(Opcode.PING, b"are you there")
    conn.write_frame(Opcode.CONTINUATION, b"def", fin=False)
    conn.write_frame(Opcode.PONG, b"unasked")
    conn.write_frame(Opcode.CONTINUATION, b"ghi", fin=True)
    conn.write_frame(Opcode.PING, b"")
    conn.write_frame(Opcode.BINARY, b"jkl")
    assert receive(client, 12) == b"abcdefghijkl"
    pongs = [conn.read_frame(), conn.read_frame()]
    assert [(f.opcode, f.fin, f.payload) for f in pongs] == [(Opcode.PONG, True, b"are you there"),
                                                             (Opcode.PONG, True, b"")]
    assert all(f.mask_key is not None for f in pongs)
    assert conn.silent()


def test_a_close_is_answered_once_then_the_stream_ends(
        servers: Callable[..., Server], closing: Callable[[Any], Any]) -> None:
    """The payload before the close is read; the client answers the close with its status code, once; then
    recv returns b"" and a write is refused."""
    server = servers(websocket=True)
    client = ws_connect(server, closing)
    conn = server.next()
    conn.write_frame(Opcode.BINARY, b"last")
    conn.write_frame(Opcode.CLOSE, struct.pack(">H", 1000) + b"bye")
    conn.write_frame(Opcode.CLOSE, struct.pack(">H", 1001))
    conn.write_frame(Opcode.BINARY, b"after the close")
    assert receive(client, 100) == b"last"
    assert client.recv(10) == b""
    answer = conn.read_frame()
    assert (answer.opcode, answer.payload) == (Opcode.CLOSE, struct.pack(">H", 1000)) and answer.mask_key
    assert conn.silent()
    with pytest.raises(WebSocketError, match="closed"):
        client.sendall(b"more")


@pytest.mark.parametrize("frame, message", [
    (encode_frame(Opcode.BINARY, b"masked", mask_key=b"abcd"), "masked frame from the server"),
    (encode_frame(Opcode.TEXT, b"{}"), "text frame"),
    (encode_frame(Opcode.CONTINUATION, b"orphan"), "continuation frame with no fragmented message"),
    (encode_frame(Opcode.BINARY, b"a", fin=False) + encode_frame(Opcode.BINARY, b"b"), "new binary message"),
    (bytes([0xC2, 0x00]), "reserved bits"),
    (encode_frame(3, b""), "reserved opcode"),
    (encode_frame(Opcode.PING, b"x" * 126), "control frame"),
    (encode_frame(Opcode.PING, b"x", fin=False), "control frame"),
    (encode_frame(Opcode.BINARY, bytes(4096)), "a frame of 4096 bytes, over the limit of 1024"),
    (bytes([0x82, 127]) + struct.pack(">Q", 1 << 63), "most significant bit"),
])
def test_a_frame_a_client_must_refuse_breaks_the_stream(
        servers: Callable[..., Server], closing: Callable[[Any], Any], frame: bytes, message: str) -> None:
    """WebSocketError (a ConnectionError: the session drops the connection), and again on the next read."""
    server = servers(websocket=True)
    client = ws_connect(server, closing, max_frame=1024)
    conn = server.next()
    conn.sock.sendall(frame)
    with pytest.raises(WebSocketError, match=message) as caught:
        receive(client, 100)
    assert isinstance(caught.value, ConnectionError)
    with pytest.raises(WebSocketError):
        client.recv(1)


def wrong_accept(key: str) -> bytes:
    return upgraded(base64.b64encode(b"another key, 16").decode())


@pytest.mark.parametrize("answer, message", [
    (wrong_accept, "wrong Sec-WebSocket-Accept"),
    (lambda key: b"HTTP/1.1 403 Forbidden\r\nContent-Length: 0\r\n\r\n",
     "refused the WebSocket upgrade: 'HTTP/1.1 403 Forbidden'"),
    (lambda key: b"HTTP/1.1 200 OK\r\nContent-Length: 0\r\n\r\n", "'HTTP/1.1 200 OK'"),
    (lambda key: upgraded(key).replace(b"Upgrade: websocket\r\n", b""), "without 'Upgrade: websocket'"),
    (lambda key: upgraded(key).replace(b"Connection: Upgrade\r\n", b"Connection: keep-alive\r\n"),
     "without 'Connection: Upgrade'"),
    (lambda key: upgraded(key)[:-2] + b"Sec-WebSocket-Extensions: permessage-deflate\r\n\r\n",
     "sec-websocket-extensions"),
    (lambda key: b"SSH-2.0-OpenSSH_9.2\r\n\r\n", "refused the WebSocket upgrade"),
])
def test_a_wrong_answer_to_the_upgrade_is_a_clear_error(
        servers: Callable[..., Server], closing: Callable[[Any], Any], answer: Callable[[str], bytes],
        message: str) -> None:
    server = servers(websocket=True, answer=answer)
    with pytest.raises(WebSocketError, match=re.escape(message)) as caught:
        ws_connect(server, closing)
    assert isinstance(caught.value, ConnectionError)
    assert f"ws://127.0.0.1:{server.port}/fedpro" in str(caught.value)


def test_no_answer_to_the_upgrade_times_out(servers: Callable[..., Server]) -> None:
    server = servers(websocket=True, answer=lambda key: b"HTTP/1.1 101 Switching")  # and never the rest
    start = time.monotonic()
    with pytest.raises(TimeoutError), socket.create_connection(("127.0.0.1", server.port), timeout=WAIT) as sock:
        WebSocketStream.connect(sock, "127.0.0.1", server.port, timeout=0.3)
    assert time.monotonic() - start < 2


def test_pongs_and_writes_from_two_threads_never_interleave(
        servers: Callable[..., Server], closing: Callable[[Any], Any], pool: ThreadPoolExecutor) -> None:
    """A writer sends frames larger than the socket's buffers while the reader answers pings that come during
    them: every frame reaches the server whole, none cut by a pong."""
    server = servers(websocket=True)
    client = ws_connect(server, closing, send_buffer=8192)  # a frame's write waits for the server, part-way
    conn = server.next()
    payloads = [bytes([i]) * (256 << 10) for i in range(8)]
    writer = pool.submit(lambda: [client.sendall(p) for p in payloads])
    reader = pool.submit(receive, client, 3)
    conn.write_frame(Opcode.PING, b"ping 0")
    binary: List[bytes] = []
    pongs: List[bytes] = []
    while len(binary) < len(payloads) or len(pongs) < len(payloads):
        frame = conn.read_frame()
        if frame.opcode == Opcode.BINARY:
            binary.append(frame.payload)
            if len(binary) < len(payloads):  # the next ping comes while the writer is in the next frame
                conn.write_frame(Opcode.PING, b"ping %d" % len(binary))
            else:
                conn.write_frame(Opcode.BINARY, b"end")
        else:
            assert frame.opcode == Opcode.PONG, frame.opcode
            pongs.append(frame.payload)
    assert result(reader) == b"end"
    result(writer)
    assert binary == payloads
    assert pongs == [b"ping %d" % i for i in range(len(payloads))]


# ---- transports ----

def test_the_transports_and_their_default_ports() -> None:
    assert fedpro.DEFAULT_PORTS == {"tcp": 15164, "tls": 15165, "websocket": 80, "websocketsecure": 443}
    assert [default_port(p) for p in fedpro.DEFAULT_PORTS] == [15164, 15165, 80, 443]


def test_an_unknown_protocol_names_the_four() -> None:
    for call in (lambda: Session.connect("127.0.0.1", 1, protocol="quic"),
                 lambda: fedpro.RTIambassador("127.0.0.1:1", protocol="udp"),
                 lambda: fedpro.RTIambassador(protocol="WebSocket")):
        with pytest.raises(ValueError, match="one of tcp, tls, websocket, websocketsecure"):
            call()
    with pytest.raises(ValueError, match="no TLS"):
        Session.connect("127.0.0.1", 1, protocol="websocket", ssl_context=ssl.create_default_context())


def test_decrypted_bytes_are_read_without_waiting_for_the_socket(
        servers: Callable[..., Server], closing: Callable[[Any], Any], certificate: Certificate) -> None:
    """Two messages in one TLS record: after the first is read the second waits in the TLS layer, where a poll
    on the socket does not see it; the stream says it has it."""
    server = servers(tls=certificate.server())
    stream = closing(Transport("tls", ssl_context=certificate.client()).dial(("127.0.0.1", server.port), WAIT))
    conn = server.next()
    first = encode_message(MessageType.NEW_SESSION_STATUS, 0, SESSION_ID, 0, u32(0))
    second = encode_message(MessageType.HLA_CALLBACK_REQUEST, 1, SESSION_ID, 0, b"callback")
    conn.sock.sendall(first + second)  # one write of a few bytes: one record
    assert receive(stream, len(first)) == first
    assert stream.pending() == len(second)
    assert select.select([stream.fileno()], [], [], 0.3)[0] == []
    assert wait_readable(stream, 0)
    assert receive(stream, len(second)) == second


def test_a_session_over_tls_reads_two_messages_of_one_record(
        servers: Callable[..., Server], closing: Callable[[Any], Any], certificate: Certificate,
        pool: ThreadPoolExecutor) -> None:
    """NewSessionStatus and a callback in one record, and the server then silent: the reader thread finds the
    callback in the TLS layer."""
    server = servers(tls=certificate.server())
    future = pool.submit(Session.connect, "127.0.0.1", server.port, protocol="tls",
                         ssl_context=certificate.client(), timeout=WAIT)
    conn = server.next()
    header, _ = conn.read_message()
    assert header.type == MessageType.NEW_SESSION
    conn.sock.sendall(encode_message(MessageType.NEW_SESSION_STATUS, 0, SESSION_ID, 0, u32(0))
                      + encode_message(MessageType.HLA_CALLBACK_REQUEST, 1, SESSION_ID, 0, b"callback"))
    session = closing(result(future))
    assert session.next_callback(WAIT) == (1, b"callback")


def test_a_certificate_not_trusted_or_for_another_name_is_refused(
        servers: Callable[..., Server], certificate: Certificate) -> None:
    server = servers(tls=certificate.server())
    with pytest.raises(ssl.SSLCertVerificationError):
        Session.connect("127.0.0.1", server.port, protocol="tls", timeout=WAIT)  # the system's authorities
    with pytest.raises(ssl.SSLCertVerificationError):
        Session.connect("127.0.0.1", server.port, protocol="tls", ssl_context=certificate.client(),
                        server_hostname="rti.example", timeout=WAIT)


@pytest.mark.parametrize("protocol", ["tcp", "tls", "websocket", "websocketsecure"])
def test_a_session_resumes_over_its_own_transport(
        servers: Callable[..., Server], closing: Callable[[Any], Any], certificate: Certificate,
        pool: ThreadPoolExecutor, protocol: str) -> None:
    """A call, the connection dropped, a resume on a new connection with a new TLS handshake and a new
    WebSocket upgrade, another call."""
    secure = protocol in ("tls", "websocketsecure")
    websocket = protocol.startswith("websocket")
    server = servers(tls=certificate.server() if secure else None, websocket=websocket)
    options = dict(ssl_context=certificate.client(), server_hostname="localhost") if secure else {}
    future = pool.submit(Session.connect, "127.0.0.1", server.port, protocol=protocol, path="/fedpro",
                         timeout=WAIT, resume_timeout=WAIT, **options)
    conn = server.next()
    conn.open_session()
    session = closing(result(future))

    call = pool.submit(session.call, b"first", WAIT)
    sequence, request = conn.answer_call()
    assert (sequence, request) == (1, b"first")
    conn.send(conn.message(MessageType.HLA_CALL_RESPONSE, u32(sequence) + b"first answer"))
    assert result(call) == b"first answer"

    session.drop_connection()
    again = server.next()
    header, payload = again.read_message()
    assert (header.type, header.session_id, payload) == (MessageType.RESUME_REQUEST, SESSION_ID, u32(1, 2))
    again.next, again.last_received = conn.next, conn.last_received
    again.send(encode_message(MessageType.RESUME_STATUS, NO_SEQUENCE, SESSION_ID, 1, u32(ResumeStatus.OK, 1)))
    call = pool.submit(session.call, b"second", WAIT)
    sequence, request = again.answer_call()
    assert (sequence, request) == (2, b"second")
    again.send(again.message(MessageType.HLA_CALL_RESPONSE, u32(sequence) + b"second answer"))
    assert result(call) == b"second answer"
    assert session.resumes == 1
    if websocket:
        assert [r.split("\r\n")[0] for r in server.requests] == ["GET /fedpro HTTP/1.1"] * 2


# ---- credentials ----

def test_plain_text_password_is_an_hla_unicode_string() -> None:
    credentials = fedpro.plain_text_password("ab€")
    assert credentials.type == "HLAplainTextPassword"
    assert credentials.data == bytes.fromhex("00000003 0061 0062 20AC")
    assert fedpro.unicode_string("") == bytes(4)
    assert fedpro.unicode_string("\U0001D11E") == bytes.fromhex("00000002 D834 DD1E")  # a surrogate pair


def test_connect_with_credentials_over_websocketsecure(
        servers: Callable[..., Server], certificate: Certificate, pool: ThreadPoolExecutor) -> None:
    """RTIambassador over "websocketsecure" sends connectWithCredentials with the password; an RTI that refuses
    it raises Unauthorized; with a configuration too it sends connectWithConfigurationAndCredentials."""
    server = servers(tls=certificate.server(), websocket=True)
    future = pool.submit(fedpro.RTIambassador, f"127.0.0.1:{server.port}", protocol="websocketsecure",
                         ssl_context=certificate.client(), server_hostname="localhost", path="/fedpro",
                         timeout=WAIT, connect_timeout=WAIT)
    conn = server.next()
    conn.open_session()
    rtia = result(future)
    try:
        call = pool.submit(rtia.connect, fedpro.NullFederateAmbassador(),
                           credentials=messages.plain_text_password("wrong"))
        sequence, payload = conn.answer_call()
        request = RTI.CallRequest.FromString(payload)
        assert request.WhichOneof("callRequest") == "connectWithCredentialsRequest"
        sent = request.connectWithCredentialsRequest.credentials
        assert (sent.type, sent.data) == ("HLAplainTextPassword", bytes.fromhex("00000005 0077 0072 006F 006E 0067"))
        refusal = RTI.CallResponse()
        refusal.exceptionData.exceptionName = "Unauthorized"
        refusal.exceptionData.details = "wrong password"
        conn.send(conn.message(MessageType.HLA_CALL_RESPONSE, u32(sequence) + refusal.SerializeToString()))
        with pytest.raises(fedpro.rti_exception("Unauthorized"), match="wrong password") as caught:
            result(call)
        assert type(caught.value).__name__ == "Unauthorized" and isinstance(caught.value, fedpro.RTIexception)

        call = pool.submit(rtia.connect, fedpro.NullFederateAmbassador(),
                           rtiConfiguration={"configurationName": "road"},
                           credentials=messages.plain_text_password("right"))
        sequence, payload = conn.answer_call()
        request = RTI.CallRequest.FromString(payload)
        assert request.WhichOneof("callRequest") == "connectWithConfigurationAndCredentialsRequest"
        sent_request = request.connectWithConfigurationAndCredentialsRequest
        assert sent_request.rtiConfiguration.configurationName == "road"
        assert sent_request.credentials.data == messages.unicode_string("right")
        accepted = RTI.CallResponse()
        accepted.connectWithConfigurationAndCredentialsResponse.configurationResult.configurationUsed = True
        conn.send(conn.message(MessageType.HLA_CALL_RESPONSE, u32(sequence) + accepted.SerializeToString()))
        assert result(call).configurationUsed
    finally:
        rtia.session.close()
