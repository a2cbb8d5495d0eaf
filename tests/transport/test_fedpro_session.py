"""The pure-Python Federate Protocol client (hlacore.fedpro): the session layer's 24-byte header codec, and
:class:`hlacore.fedpro.Session` and :class:`hlacore.fedpro.RTIambassador` against an RTI's side written here
with the same codec on a loopback socket, which a test drives message by message: the new session handshake,
calls matched to responses, callbacks queued and answered, heartbeats, a dropped connection resumed (what the
RTI lacks sent again exactly once, what it sends again ignored), a resume that fails, termination. Every wait
is bounded."""

from __future__ import annotations

import concurrent.futures
import select
import socket
import struct
import threading
import time
from concurrent.futures import ThreadPoolExecutor
from typing import Any, Callable, Iterator, List, Optional, Tuple, TypeVar

import pytest

from hlacore import fedpro
from hlacore.fedpro import messages
from hlacore.fedpro._proto import FederateAmbassador_pb2, RTIambassador_pb2
from hlacore.fedpro.session import (HEADER_SIZE, NO_SEQUENCE, SEQUENCE_MASK, BadMessage, CallTimeout, Header,
                                    MessageType, NewSessionReason, ResumeStatus, Session, SessionLost,
                                    SessionRefused, after, decode_header, encode_header, encode_message,
                                    next_sequence, split_address)

from support import wait_until

WAIT = 5.0  # the longest any step waits for the other side
SESSION_ID = 0x0123_4567_89AB_CDEF
T = TypeVar("T")

RTI: Any = RTIambassador_pb2
FED: Any = FederateAmbassador_pb2


def u32(*values: int) -> bytes:
    return struct.pack(f">{len(values)}I", *values)


# ---- the header codec ----

@pytest.mark.parametrize("header", [
    Header(24, 0, 0, NO_SEQUENCE, MessageType.NEW_SESSION),
    Header(28, 1, SESSION_ID, 0, MessageType.HLA_CALL_REQUEST),
    Header(0xFFFFFFFF, SEQUENCE_MASK, 0xFFFF_FFFF_FFFF_FFFF, SEQUENCE_MASK, MessageType.HLA_CALLBACK_RESPONSE),
])
def test_a_header_round_trips(header: Header) -> None:
    """encode_header gives 24 big-endian bytes in the standard's order; decode_header reads them back."""
    data = encode_header(header)
    assert len(data) == HEADER_SIZE
    assert struct.unpack(">IIQII", data) == (header.size, header.sequence, header.session_id,
                                             header.last_received, int(header.type))
    assert decode_header(data, max_size=0xFFFFFFFF) == header


def test_a_message_is_its_header_then_its_payload() -> None:
    """encode_message counts the header in the size; the payload follows it unchanged."""
    data = encode_message(MessageType.HLA_CALL_RESPONSE, 7, SESSION_ID, 3, b"\x00\x00\x00\x05abc")
    header = decode_header(data)
    assert header == Header(31, 7, SESSION_ID, 3, MessageType.HLA_CALL_RESPONSE)
    assert header.payload_size == 7 and data[HEADER_SIZE:] == b"\x00\x00\x00\x05abc"


@pytest.mark.parametrize("data, max_size, message", [
    (encode_message(MessageType.HEARTBEAT, 1, 1, 0)[:23], 1 << 20, "a header is 24 bytes, not 23"),
    (struct.pack(">IIQII", 23, 1, 1, 0, 3), 1 << 20, "a message of 23 bytes, under its header's 24"),
    (struct.pack(">IIQII", 0, 1, 1, 0, 3), 1 << 20, "a message of 0 bytes, under"),
    (struct.pack(">IIQII", 1025, 1, 1, 0, 20), 1024, "a message of 1025 bytes, over the limit of 1024"),
    (struct.pack(">IIQII", 24, 1, 1, 0, 7), 1 << 20, "unknown message type 7"),
    (struct.pack(">IIQII", 24, 1, 1, 0, 0), 1 << 20, "unknown message type 0"),
    (struct.pack(">IIQII", 24, 1, 1, 0, 999), 1 << 20, "unknown message type 999"),
])
def test_decode_refuses_a_bad_header(data: bytes, max_size: int, message: str) -> None:
    """A size under 24 or over the limit, an unknown type and a short header are BadMessage, a SessionError."""
    with pytest.raises(BadMessage, match=message) as caught:
        decode_header(data, max_size)
    assert isinstance(caught.value, fedpro.SessionError)


def test_the_limit_itself_is_accepted() -> None:
    """A message exactly at the size limit is accepted."""
    assert decode_header(struct.pack(">IIQII", 1024, 1, 1, 0, 20), 1024).size == 1024


def test_sequence_numbers_wrap_in_31_bits() -> None:
    """after() and next_sequence() wrap at 2^31; "none" (0x80000000) is not a sequence number."""
    assert next_sequence(SEQUENCE_MASK) == 0 and next_sequence(0) == 1
    assert after(0, SEQUENCE_MASK) and after(5, 4) and not after(4, 5) and not after(4, 4)
    assert after(3, SEQUENCE_MASK - 2) and not after(SEQUENCE_MASK - 2, 3)
    assert NO_SEQUENCE == SEQUENCE_MASK + 1


def test_addresses_split_into_host_and_port() -> None:
    """Addresses: host:port, a bare host (port 15164), [IPv6]:port and :port (loopback)."""
    assert split_address("rti.example:1234") == ("rti.example", 1234)
    assert split_address("rti.example") == ("rti.example", 15164)
    assert split_address("[::1]:99") == ("::1", 99)
    assert split_address(":77") == ("127.0.0.1", 77)


# ---- an RTI's side, driven by the test ----

class Peer:
    """The RTI's side of one session on a loopback listener: numbers its messages from 1, records every
    message it reads (on any connection), and answers only as the test says."""

    def __init__(self) -> None:
        self.listener = socket.create_server(("127.0.0.1", 0))
        self.port = self.listener.getsockname()[1]
        self.conn: Optional[socket.socket] = None
        self.old: List[socket.socket] = []
        self.next = 1
        self.last_received = 0  # the federate's NewSession is its 0
        self.received: List[Tuple[Header, bytes]] = []

    def accept(self) -> socket.socket:
        """The next connection from the client (the old one, if any, stays open until close())."""
        ready, _, _ = select.select([self.listener], [], [], WAIT)
        assert ready, "the client did not connect"
        conn, _ = self.listener.accept()
        if self.conn is not None:
            self.old.append(self.conn)
        self.conn = conn
        return conn

    def read(self, timeout: float = WAIT) -> Tuple[Header, bytes]:
        """The next message on the current connection; AssertionError when none comes within `timeout`."""
        assert self.conn is not None
        header = decode_header(self._exact(HEADER_SIZE, timeout))
        payload = self._exact(header.payload_size, timeout)
        self.received.append((header, payload))
        if header.type not in (MessageType.NEW_SESSION, MessageType.RESUME_REQUEST):
            assert header.session_id == SESSION_ID
            if after(header.sequence, self.last_received):
                self.last_received = header.sequence
        return header, payload

    def nothing_comes(self, seconds: float = 0.3) -> bool:
        """Whether the current connection stays silent for `seconds`."""
        assert self.conn is not None
        ready, _, _ = select.select([self.conn], [], [], seconds)
        return not ready

    def _exact(self, size: int, timeout: float) -> bytes:
        assert self.conn is not None
        data = b""
        deadline = time.monotonic() + timeout
        while len(data) < size:
            ready, _, _ = select.select([self.conn], [], [], max(deadline - time.monotonic(), 0))
            assert ready, f"nothing from the client within {timeout} s"
            chunk = self.conn.recv(size - len(data))
            assert chunk, "the client closed the connection"
            data += chunk
        return data

    def send(self, message_type: MessageType, payload: bytes = b"", *, sequence: Optional[int] = None) -> int:
        """Sends a message numbered next (or `sequence`), stamped with the last number received; its number."""
        assert self.conn is not None
        if sequence is None:
            sequence, self.next = self.next, next_sequence(self.next)
        self.conn.sendall(encode_message(message_type, sequence, SESSION_ID, self.last_received, payload))
        return sequence

    def open_session(self) -> Tuple[Header, bytes]:
        """Accepts a connection, reads NewSession and answers NewSessionStatus OK (the RTI's number 0)."""
        self.accept()
        header, payload = self.read()
        assert self.conn is not None
        self.conn.sendall(encode_message(MessageType.NEW_SESSION_STATUS, 0, SESSION_ID, 0,
                                         u32(NewSessionReason.OK)))
        return header, payload

    def resume(self, status: int = ResumeStatus.OK, received: Optional[int] = None) -> Tuple[int, int]:
        """Accepts the client's new connection, reads its ResumeRequest and answers ResumeStatus(`status`,
        `received` or the last number read); (last RTI number the client has, oldest it keeps)."""
        self.accept()
        header, payload = self.read()
        assert header.type == MessageType.RESUME_REQUEST and header.session_id == SESSION_ID
        assert header.sequence == NO_SEQUENCE
        last, oldest = struct.unpack(">II", payload)
        assert header.last_received == last
        answer = u32(status, self.last_received if received is None else received)
        self.send(MessageType.RESUME_STATUS, answer)  # the RTI numbers it: the client must not count it
        return last, oldest

    def drop(self) -> None:
        """Closes the current connection abruptly (a reset)."""
        assert self.conn is not None
        self.conn.setsockopt(socket.SOL_SOCKET, socket.SO_LINGER, struct.pack("ii", 1, 0))
        self.conn.close()
        self.conn = None

    def close(self) -> None:
        for conn in self.old + ([self.conn] if self.conn else []):
            conn.close()
        self.old, self.conn = [], None
        self.listener.close()


@pytest.fixture
def pool() -> Iterator[ThreadPoolExecutor]:
    """Threads for the client's blocking calls while the test plays the RTI."""
    with ThreadPoolExecutor(max_workers=4) as executor:
        yield executor


@pytest.fixture
def peer() -> Iterator[Peer]:
    """An RTI's side on a loopback port, closed after the test."""
    p = Peer()
    yield p
    p.close()


def opened(peer: Peer, pool: ThreadPoolExecutor, **options: Any) -> Session:
    """A session of the client with `peer`, the handshake done."""
    future = pool.submit(Session.connect, "127.0.0.1", peer.port, timeout=WAIT, **options)
    peer.open_session()
    return future.result(timeout=WAIT)


@pytest.fixture
def session(peer: Peer, pool: ThreadPoolExecutor) -> Iterator[Session]:
    """A client session with the peer, the handshake done; closed after the test."""
    s = opened(peer, pool)
    yield s
    s.close()


def result(future: "concurrent.futures.Future[T]") -> T:
    return future.result(timeout=WAIT)


# ---- the session ----

def test_the_handshake_opens_a_session_with_the_rtis_id(peer: Peer, pool: ThreadPoolExecutor) -> None:
    """NewSession is the federate's number 0 with session id 0 and protocol version 1; the session takes
    its id from NewSessionStatus; the first message after is number 1 and says it has the RTI's 0."""
    future = pool.submit(Session.connect, "127.0.0.1", peer.port, timeout=WAIT)
    header, payload = peer.open_session()
    assert (header.type, header.sequence, header.session_id, header.last_received) == \
        (MessageType.NEW_SESSION, 0, 0, NO_SEQUENCE)
    assert payload == u32(1)
    s = result(future)
    try:
        assert s.session_id == SESSION_ID and s.lost is None
        s.answer_callback(0, b"")  # any message: its numbering
        header, _ = peer.read()
        assert (header.sequence, header.last_received, header.session_id) == (1, 0, SESSION_ID)
    finally:
        s.close()


def test_a_refused_new_session_is_session_refused(peer: Peer, pool: ThreadPoolExecutor) -> None:
    """A NewSessionStatus other than OK is SessionRefused, carrying the reason."""
    future = pool.submit(Session.connect, "127.0.0.1", peer.port, timeout=WAIT)
    peer.accept()
    peer.read()
    assert peer.conn is not None
    refusal = u32(NewSessionReason.UNSUPPORTED_VERSION)
    peer.conn.sendall(encode_message(MessageType.NEW_SESSION_STATUS, 0, 0, 0, refusal))
    with pytest.raises(SessionRefused, match="unsupported version") as caught:
        result(future)
    assert caught.value.reason == 1


def test_no_answer_to_new_session_times_out(peer: Peer) -> None:
    """The handshake is bounded by its timeout."""
    start = time.monotonic()
    with pytest.raises(TimeoutError):
        Session.connect("127.0.0.1", peer.port, timeout=0.3)
    assert time.monotonic() - start < 2


def test_a_call_gets_its_response(peer: Peer, session: Session, pool: ThreadPoolExecutor) -> None:
    """HlaCallRequest carries the request; the HlaCallResponse naming its number returns its payload; the
    RTI's header confirming the request lets the session forget it."""
    call = pool.submit(session.call, b"request bytes", WAIT)
    header, payload = peer.read()
    assert (header.type, header.sequence, header.last_received) == (MessageType.HLA_CALL_REQUEST, 1, 0)
    assert payload == b"request bytes"
    assert session.kept_messages == 1
    peer.send(MessageType.HLA_CALL_RESPONSE, u32(1) + b"response bytes")
    assert result(call) == b"response bytes"
    wait_until(lambda: session.kept_messages == 0 and session.kept_bytes == 0, WAIT)


def test_calls_from_several_threads_get_their_own_responses(
        peer: Peer, session: Session, pool: ThreadPoolExecutor) -> None:
    """Responses are matched by the request's sequence number, whatever order they come in."""
    calls = {}
    for text in (b"first", b"second", b"third"):
        calls[text] = pool.submit(session.call, text, WAIT)
    requests = {}
    for _ in calls:
        header, payload = peer.read()
        requests[payload] = header.sequence
    assert sorted(requests.values()) == [1, 2, 3]
    for text in (b"third", b"first", b"second"):
        peer.send(MessageType.HLA_CALL_RESPONSE, u32(requests[text]) + b"answer to " + text)
    for text, future in calls.items():
        assert result(future) == b"answer to " + text


def test_a_call_times_out_and_the_session_goes_on(peer: Peer, session: Session) -> None:
    """CallTimeout (a TimeoutError) after the timeout; the late response is dropped; the next call works."""
    start = time.monotonic()
    with pytest.raises(CallTimeout) as caught:
        session.call(b"slow", timeout=0.3)
    assert isinstance(caught.value, TimeoutError) and time.monotonic() - start < 2
    first, _ = peer.read()
    peer.send(MessageType.HLA_CALL_RESPONSE, u32(first.sequence) + b"too late")
    done = threading.Event()
    answered: List[bytes] = []

    def second() -> None:
        answered.append(session.call(b"fast", WAIT))
        done.set()

    threading.Thread(target=second, daemon=True).start()
    header, _ = peer.read()
    peer.send(MessageType.HLA_CALL_RESPONSE, u32(header.sequence) + b"in time")
    assert done.wait(WAIT) and answered == [b"in time"]


def test_a_callback_is_queued_and_answered(peer: Peer, session: Session) -> None:
    """HlaCallbackRequests queue up in order; answer_callback sends HlaCallbackResponse naming the number."""
    assert session.next_callback(0) is None
    peer.send(MessageType.HLA_CALLBACK_REQUEST, b"callback one")
    peer.send(MessageType.HLA_CALLBACK_REQUEST, b"callback two")
    assert session.next_callback(WAIT) == (1, b"callback one")
    assert session.next_callback(WAIT) == (2, b"callback two")
    assert session.next_callback(0.05) is None
    session.answer_callback(1, b"done")
    header, payload = peer.read()
    assert (header.type, header.sequence, header.last_received) == (MessageType.HLA_CALLBACK_RESPONSE, 1, 2)
    assert payload == u32(1) + b"done"


def test_a_callback_comes_between_a_call_and_its_response(
        peer: Peer, session: Session, pool: ThreadPoolExecutor) -> None:
    """A callback interleaved before a call's response is queued; the call still gets its response."""
    call = pool.submit(session.call, b"request", WAIT)
    header, _ = peer.read()
    peer.send(MessageType.HLA_CALLBACK_REQUEST, b"meanwhile")
    peer.send(MessageType.HLA_CALL_RESPONSE, u32(header.sequence) + b"response")
    assert result(call) == b"response"
    assert session.next_callback(WAIT) == (1, b"meanwhile")


def test_a_heartbeat_is_answered(peer: Peer, session: Session, pool: ThreadPoolExecutor) -> None:
    """Heartbeat is numbered like any message; the HeartbeatResponse naming it ends heartbeat() with the round trip."""
    beat = pool.submit(session.heartbeat, WAIT)
    header, payload = peer.read()
    assert (header.type, header.sequence, payload) == (MessageType.HEARTBEAT, 1, b"")
    peer.send(MessageType.HEARTBEAT_RESPONSE, u32(header.sequence))
    assert 0 <= result(beat) < WAIT


def test_a_heartbeat_without_response_times_out(session: Session) -> None:
    """A heartbeat the RTI does not answer is CallTimeout after its timeout."""
    with pytest.raises(CallTimeout):
        session.heartbeat(0.2)


def test_a_dropped_connection_resumes_and_resends_the_unconfirmed_call_once(
        peer: Peer, session: Session, pool: ThreadPoolExecutor) -> None:
    """After a drop the client dials again and sends ResumeRequest(last RTI number, oldest kept); the RTI
    says it received none of the call: the client sends it again, once, and the call gets its response."""
    call = pool.submit(session.call, b"the call", WAIT)
    header, _ = peer.read()
    assert header.sequence == 1
    session.drop_connection()
    last, oldest = peer.resume(received=0)  # as if the RTI had lost it
    assert (last, oldest) == (0, 1)
    again, payload = peer.read()
    assert (again.type, again.sequence, payload) == (MessageType.HLA_CALL_REQUEST, 1, b"the call")
    assert peer.nothing_comes(0.3), "the call was sent again more than once"
    assert [h.sequence for h, _ in peer.received if h.type == MessageType.HLA_CALL_REQUEST] == [1, 1]
    peer.send(MessageType.HLA_CALL_RESPONSE, u32(1) + b"answered")
    assert result(call) == b"answered"
    assert session.resumes == 1 and session.lost is None
    wait_until(lambda: session.kept_messages == 0, WAIT)


def test_a_resume_sends_nothing_the_rti_has_and_ignores_what_it_sends_again(
        peer: Peer, session: Session, pool: ThreadPoolExecutor) -> None:
    """The RTI drops the connection after confirming the call; on resume it sends again a callback the client
    had: the client resends nothing, queues the callback once, and the call's response still arrives."""
    call = pool.submit(session.call, b"the call", WAIT)
    peer.read()
    peer.send(MessageType.HLA_CALLBACK_REQUEST, b"callback")  # its header confirms the call
    wait_until(lambda: session.pending_callbacks == 1 and session.kept_messages == 0, WAIT)
    peer.drop()
    last, oldest = peer.resume()
    assert (last, oldest) == (1, 2)  # has the RTI's 1; keeps nothing, so "from 2 on"
    peer.send(MessageType.HLA_CALLBACK_REQUEST, b"callback", sequence=1)  # a repeat
    peer.send(MessageType.HLA_CALL_RESPONSE, u32(1) + b"answered")
    assert result(call) == b"answered"
    assert session.next_callback(WAIT) == (1, b"callback")
    assert session.next_callback(0.2) is None
    assert peer.nothing_comes(0.3)
    session.answer_callback(1, b"ok")  # numbered on after the resume
    header, _ = peer.read()
    assert (header.sequence, header.last_received) == (2, 3)  # the ResumeStatus (the RTI's 2) is not counted


def test_calls_made_while_dropped_go_out_on_resume(
        peer: Peer, session: Session, pool: ThreadPoolExecutor) -> None:
    """A call made after the RTI dropped the connection (before or after the client noticed) is kept and sent
    once the session resumes."""
    peer.drop()
    call = pool.submit(session.call, b"during the drop", WAIT)
    peer.resume()
    header, payload = peer.read()
    assert (header.sequence, payload) == (1, b"during the drop")
    peer.send(MessageType.HLA_CALL_RESPONSE, u32(1) + b"after")
    assert result(call) == b"after"


def test_a_session_that_cannot_resume_is_lost(peer: Peer, pool: ThreadPoolExecutor) -> None:
    """No RTI to dial within resume_timeout: the waiting call, later calls and the callback queue raise
    SessionLost."""
    s = opened(peer, pool, resume_timeout=0.5)
    try:
        call = pool.submit(s.call, b"pending", WAIT)
        peer.read()
        peer.listener.close()
        peer.drop()
        with pytest.raises(SessionLost, match="could not be resumed within 0.5 s"):
            result(call)
        with pytest.raises(SessionLost):
            s.call(b"later", WAIT)
        with pytest.raises(SessionLost):
            s.next_callback(0)
    finally:
        s.close()


def test_a_refused_resume_loses_the_session(peer: Peer, session: Session) -> None:
    """A ResumeStatus other than OK loses the session; later calls raise SessionLost."""
    session.drop_connection()
    peer.resume(status=ResumeStatus.INVALID_SESSION, received=NO_SEQUENCE)
    wait_until(lambda: session.lost is not None, WAIT)
    assert "refused to resume the session: invalid session" in str(session.lost)
    with pytest.raises(SessionLost):
        session.heartbeat(WAIT)


def test_a_bad_message_loses_the_session(peer: Peer, session: Session, pool: ThreadPoolExecutor) -> None:
    """An unknown message type from the RTI loses the session, and the waiting call raises SessionLost."""
    call = pool.submit(session.call, b"request", WAIT)
    peer.read()
    assert peer.conn is not None
    peer.conn.sendall(struct.pack(">IIQII", 24, 1, SESSION_ID, 1, 77))
    with pytest.raises(SessionLost, match="unknown message type 77"):
        result(call)


def test_terminate_ends_the_session(peer: Peer, session: Session, pool: ThreadPoolExecutor) -> None:
    """TerminateSession, then the RTI's SessionTerminated: terminate() returns, the session is over."""
    ending = pool.submit(session.terminate, WAIT)
    header, payload = peer.read()
    assert (header.type, header.sequence, payload) == (MessageType.TERMINATE_SESSION, 1, b"")
    peer.send(MessageType.SESSION_TERMINATED)
    assert result(ending) is None
    assert session.lost == "the session was terminated"
    with pytest.raises(SessionLost):
        session.call(b"after the end", WAIT)
    assert not peer.nothing_comes(WAIT)  # the client closed its end:
    assert peer.conn is not None and peer.conn.recv(1) == b""


def test_terminate_without_answer_raises_and_closes(session: Session) -> None:
    """No SessionTerminated within the timeout: SessionLost, and the session is closed all the same."""
    with pytest.raises(SessionLost, match="no SessionTerminated within 0.2 s"):
        session.terminate(0.2)
    assert session.lost is not None


# ---- the RTI ambassador ----

def serve(peer: Peer, answer: Callable[[Any], Any]) -> Tuple[Any, Header]:
    """Reads one HlaCallRequest, answers with the CallResponse `answer` makes from the CallRequest; both
    messages are returned (the request parsed)."""
    header, payload = peer.read()
    assert header.type == MessageType.HLA_CALL_REQUEST
    request = RTI.CallRequest.FromString(payload)
    peer.send(MessageType.HLA_CALL_RESPONSE, u32(header.sequence) + answer(request).SerializeToString())
    return request, header


@pytest.fixture
def rtia(peer: Peer, session: Session) -> Iterator[fedpro.RTIambassador]:
    """An RTIambassador over the test's session."""
    yield fedpro.RTIambassador(session, timeout=WAIT)


def test_a_service_is_sent_as_its_request_and_returns_its_result(
        peer: Peer, rtia: fedpro.RTIambassador, pool: ThreadPoolExecutor) -> None:
    """joinFederationExecution with a federate name sends joinFederationExecutionWithNameRequest and returns
    the response's one field, the JoinResult."""
    joined = pool.submit(rtia.joinFederationExecution, federateName="robot", federateType="robot type",
                         federationName="Fed")

    def answer(request: Any) -> Any:
        response = RTI.CallResponse()
        response.joinFederationExecutionWithNameResponse.result.federateHandle.data = b"\x07"
        response.joinFederationExecutionWithNameResponse.result.logicalTimeImplementationName = "HLAfloat64Time"
        return response

    request, _ = serve(peer, answer)
    assert request.WhichOneof("callRequest") == "joinFederationExecutionWithNameRequest"
    sent = request.joinFederationExecutionWithNameRequest
    assert (sent.federateName, sent.federateType, sent.federationName) == ("robot", "robot type", "Fed")
    joined_result = result(joined)
    assert joined_result.federateHandle.data == b"\x07"
    assert joined_result.logicalTimeImplementationName == "HLAfloat64Time"


def test_values_are_built_from_plain_python(
        peer: Peer, rtia: fedpro.RTIambassador, pool: ThreadPoolExecutor,
        tmp_path: Any) -> None:
    """Handles from bytes, maps from dicts, sets from lists, times from floats, FOM modules from paths, and
    an empty response is None."""
    fom = tmp_path / "tiny.xml"
    fom.write_bytes(b"<objectModel/>")
    created = pool.submit(rtia.createFederationExecution, federationName="Fed", fomModules=[str(fom)])
    request, _ = serve(peer, lambda r: _empty_response("createFederationExecutionWithModulesResponse"))
    module = request.createFederationExecutionWithModulesRequest.fomModules.fomModule[0].file
    assert (module.name, module.content) == ("tiny.xml", b"<objectModel/>")
    assert result(created) is None
    updated = pool.submit(rtia.updateAttributeValues, objectInstance=b"\x01", attributeValues={b"\x02": b"v"},
                          userSuppliedTag="tag", time=2.5)
    request, _ = serve(peer, lambda r: _empty_response("updateAttributeValuesWithTimeResponse"))
    sent = request.updateAttributeValuesWithTimeRequest
    assert sent.objectInstance.data == b"\x01" and sent.userSuppliedTag == b"tag"
    assert fedpro.handle_values(sent) == {b"\x02": b"v"}
    assert fedpro.time_value(sent.time) == 2.5 and sent.time.data == struct.pack(">d", 2.5)
    assert result(updated).retractionHandleIsValid is False  # the one field: a MessageRetractionReturn


def _empty_response(member: str) -> Any:
    response = RTI.CallResponse()
    getattr(response, member).SetInParent()
    return response


def test_an_exception_response_raises_its_named_class(
        peer: Peer, rtia: fedpro.RTIambassador, pool: ThreadPoolExecutor) -> None:
    """exceptionData raises the RTIexception subclass named after it, with its name and details."""
    created = pool.submit(rtia.createFederationExecution, federationName="Fed", fomModule="http://x/fom.xml")

    def answer(request: Any) -> Any:
        response = RTI.CallResponse()
        response.exceptionData.exceptionName = "FederationExecutionAlreadyExists"
        response.exceptionData.details = "Fed exists"
        return response

    serve(peer, answer)
    with pytest.raises(fedpro.rti_exception("FederationExecutionAlreadyExists"), match="Fed exists") as caught:
        result(created)
    assert isinstance(caught.value, fedpro.RTIexception)
    assert caught.value.name == "FederationExecutionAlreadyExists" and caught.value.details == "Fed exists"
    assert type(caught.value).__name__ == "FederationExecutionAlreadyExists"


def test_unknown_services_and_fields_are_refused_before_sending(peer: Peer, rtia: fedpro.RTIambassador) -> None:
    """A misspelt service (with the close matches), an unknown keyword and an unknown name fail before
    anything is sent."""
    with pytest.raises(AttributeError, match="did you mean joinFederationExecution"):
        rtia.joinFederationExecutin
    with pytest.raises(TypeError, match="takes no keywords"):
        rtia.joinFederationExecution(federationNam="Fed")
    with pytest.raises(ValueError, match="no HLA service"):
        rtia.call("nonsense")
    assert peer.nothing_comes(0.2)


def test_a_lost_session_makes_calls_raise_not_connected(peer: Peer, pool: ThreadPoolExecutor) -> None:
    """Once the session is lost, a call raises NotConnected."""
    rtia = fedpro.RTIambassador(opened(peer, pool, resume_timeout=0.2), timeout=WAIT)
    try:
        peer.listener.close()
        peer.drop()
        wait_until(lambda: rtia.session.lost is not None, WAIT)
        with pytest.raises(fedpro.rti_exception("NotConnected")):
            rtia.queryLogicalTime()
    finally:
        rtia.close()


class Ambassador(fedpro.FederateAmbassador):
    """Takes reflections and grants; fails on discoveries."""

    def __init__(self) -> None:
        self.reflected: List[dict[bytes, bytes]] = []
        self.granted: List[float] = []
        self.lost: List[str] = []

    def reflectAttributeValues(self, msg: Any) -> None:
        self.reflected.append(fedpro.handle_values(msg))

    def timeAdvanceGrant(self, msg: Any) -> None:
        self.granted.append(fedpro.time_value(msg))

    def discoverObjectInstance(self, msg: Any) -> None:
        raise fedpro.rti_exception("FederateInternalError")("cannot discover")

    def connectionLost(self, msg: Any) -> None:
        self.lost.append(msg.faultDescription)


def callback(**member: Any) -> bytes:
    request = FED.CallbackRequest()
    (name, fields), = member.items()
    messages.fill(getattr(request, name), fields)
    getattr(request, name).SetInParent()
    return bytes(request.SerializeToString())


def test_evoked_callbacks_reach_the_ambassadors_methods_and_are_answered(
        peer: Peer, rtia: fedpro.RTIambassador, pool: ThreadPoolExecutor) -> None:
    """Each callback calls the method named after it with its message; the RTI gets callbackSucceeded, or
    callbackFailed with the exception when the method raised (which the evoke raises too), or when there is
    no method (NotImplementedError)."""
    ambassador = Ambassador()
    connected = pool.submit(rtia.connect, ambassador)
    request, _ = serve(peer, lambda r: _empty_response("connectResponse"))
    assert request.WhichOneof("callRequest") == "connectRequest"
    result(connected)
    peer.send(MessageType.HLA_CALLBACK_REQUEST, callback(reflectAttributeValues={
        "objectInstance": b"\x01", "attributeValues": [(b"\x02", b"value")]}))
    peer.send(MessageType.HLA_CALLBACK_REQUEST, callback(timeAdvanceGrant={"time": 4.0}))
    peer.send(MessageType.HLA_CALLBACK_REQUEST, callback(discoverObjectInstance={"objectInstance": b"\x01"}))
    peer.send(MessageType.HLA_CALLBACK_REQUEST, callback(turnInteractionsOn={"interactionClass": b"\x03"}))
    wait_until(lambda: rtia.session.pending_callbacks == 4, WAIT)

    assert rtia.evokeCallback(WAIT) is True  # more are waiting
    assert ambassador.reflected == [{b"\x02": b"value"}]
    with pytest.raises(fedpro.rti_exception("FederateInternalError"), match="cannot discover"):
        rtia.evokeMultipleCallbacks(0.0, WAIT)  # the grant, then the discovery, which raises
    assert ambassador.granted == [4.0]
    with pytest.raises(NotImplementedError, match="Ambassador has no method turnInteractionsOn"):
        rtia.evokeCallback(WAIT)
    assert rtia.evokeCallback(0.0) is False

    answers = []
    for _ in range(4):
        header, payload = peer.read()
        assert header.type == MessageType.HLA_CALLBACK_RESPONSE
        response = FED.CallbackResponse.FromString(payload[4:])
        answers.append((struct.unpack(">I", payload[:4])[0], response.WhichOneof("callbackResponse"),
                        response.callbackFailed.exceptionName))
    assert answers == [(2, "callbackSucceeded", ""), (3, "callbackSucceeded", ""),  # the RTI's 1: connect's
                       (4, "callbackFailed", "FederateInternalError"), (5, "callbackFailed", "FederateInternalError")]
