"""Federate Protocol sessions that survive, and the door's answers to bad input: a FedPro federate's connection cut
mid-lockstep (the link emulator's cut: both ends reset, what was in flight lost) resumes with every update and
grant delivered once; a session not resumed in time ends as a resigned federate; malformed or misplaced messages
close their connection and nobody else notices."""

from __future__ import annotations

import pathlib
import socket
import struct
import time
from typing import Any, Iterator

import pytest

from hlacore import fedpro
from hlacore.fedpro.session import split_address
from hlacore.fedpro import MessageType, encode_message
from hlacore.link import Link
from hlacore.status import status

from support import wait_until
from support.fedpro import Calls, Pair
from support.fedpro import door as fedpro_door
from support.rti1516e import VEHICLES, Federate


@pytest.fixture
def door(tmp_path: pathlib.Path) -> Iterator[Any]:
    with fedpro_door(tmp_path, "--fedpro-resume-timeout", "2") as server:
        yield server


STEPS = 600
CUTS = (150, 300, 450)


def test_a_lockstep_survives_connections_cut_under_it(door: Any) -> None:
    with Link(("127.0.0.1", 0), split_address(door.fedpro_address)) as link:
        amb = Calls()
        rtia = fedpro.RTIambassador(link.address, resume_timeout=10.0)
        rtia.connect(amb)
        rtia.createFederationExecutionWithModules(federationName="Road", fomModules=[VEHICLES])
        rtia.joinFederationExecution(federateName="remote", federateType="fedpro", federationName="Road")
        pair = Pair(rtia, amb, door.address)
        other = pair.other
        try:
            def cut(step: int) -> None:
                if step in CUTS:  # the request and the other federate's update in flight, or not yet sent
                    assert link.cut() == 1

            pair.lockstep(rtia, amb, STEPS, cut)
            assert rtia.session.resumes == len(CUTS)
        finally:
            other.close()
            rtia.resignFederationExecution(resignAction="CANCEL_THEN_DELETE_THEN_DIVEST")
            rtia.destroyFederationExecution(federationName="Road")
            rtia.close()


def test_a_session_not_resumed_in_time_ends_as_a_resigned_federate(door: Any) -> None:
    other = Federate(door.address)
    link = Link(("127.0.0.1", 0), split_address(door.fedpro_address))
    rtia = fedpro.RTIambassador(link.address, resume_timeout=0.5)
    try:
        rtia.connect(Calls())
        rtia.createFederationExecutionWithModules(federationName="Road", fomModules=[VEHICLES])
        rtia.joinFederationExecution(federateName="gone", federateType="fedpro", federationName="Road")
        other.rtia.joinFederationExecution("stays", "1516e", "Road")
        vehicle = rtia.getObjectClassHandle(objectClassName="Vehicle")
        rtia.publishObjectClassAttributes(objectClass=vehicle,
                                          attributes=[rtia.getAttributeHandle(objectClass=vehicle, attributeName="speed")])
        o_vehicle = other.rtia.getObjectClassHandle("Vehicle")
        other.rtia.subscribeObjectClassAttributes(o_vehicle, [other.rtia.getAttributeHandle(o_vehicle, "speed")])
        rtia.registerObjectInstance(objectClass=vehicle)
        other.until(lambda: bool(other.amb.named("discoverObjectInstance")))
        [session] = status(door.address)["fedpro"]["sessions"]
        assert (session["federation"], session["federate"], session["state"]) == ("Road", "gone", "connected")
        link.close()  # the link is gone for good: the client cannot resume
        started = time.monotonic()
        # The status report (and the monitor) show the session dropped, then ended: after the door's resume
        # timeout (2 s) its federate resigns, deleting its object.
        wait_until(lambda: status(door.address)["fedpro"]["sessions"][0]["state"] == "dropped")
        other.until(lambda: bool(other.amb.named("removeObjectInstance")), seconds=15)
        assert time.monotonic() - started >= 1.5
        with pytest.raises(Exception):
            other.rtia.getFederateHandle("gone")
        wait_until(lambda: status(door.address)["fedpro"]["sessions"][0]["state"] == "ended")
        [session] = status(door.address)["fedpro"]["sessions"]
        assert (session["federate"], session["reason"]) == ("gone", "not resumed within 2 s")
    finally:
        rtia.close(timeout=1.0)
        other.close()
        link.close()


def handshake(address: str) -> tuple[socket.socket, int]:
    sock = socket.create_connection(split_address(address), timeout=5)
    sock.sendall(encode_message(MessageType.NEW_SESSION, 0, 0, 0x80000000, struct.pack(">I", 1)))
    header = fedpro.decode_header(recv_exact(sock, 24))
    assert header.type == MessageType.NEW_SESSION_STATUS
    assert recv_exact(sock, header.size - 24) == struct.pack(">I", 0)
    return sock, header.session_id


def recv_exact(sock: socket.socket, n: int) -> bytes:
    data = b""
    while len(data) < n:
        chunk = sock.recv(n - len(data))
        if not chunk:
            break
        data += chunk
    return data


def closed(sock: socket.socket) -> bool:
    """Whether the peer closed the connection (within 5 s)."""
    sock.settimeout(5)
    try:
        while sock.recv(4096):
            pass
        return True
    except ConnectionResetError:
        return True
    except socket.timeout:
        return False


BAD_FIRST = [
    ("a size under the header's", struct.pack(">IIQII", 20, 1, 0, 0, 20)),
    ("an unknown type", struct.pack(">IIQII", 24, 1, 0, 0, 99)),
    ("a call before any session", encode_message(MessageType.HLA_CALL_REQUEST, 1, 0, 0, b"")),
    ("a size over the limit", struct.pack(">IIQII", 0x7FFFFFFF, 1, 0, 0, 20)),
]


@pytest.mark.parametrize("what, message", BAD_FIRST, ids=[what for what, _ in BAD_FIRST])
def test_bad_first_messages_close_their_connection_only(door: Any, what: str, message: bytes) -> None:
    bystander = fedpro.RTIambassador(door.fedpro_address)
    try:
        bystander.connect(Calls())
        sock = socket.create_connection(split_address(door.fedpro_address), timeout=5)
        sock.sendall(message)
        assert closed(sock), what
        sock.close()
        # The door still serves the session that was there, and new ones.
        assert bystander.listFederationExecutions() is None
        fedpro.RTIambassador(door.fedpro_address).close()
    finally:
        bystander.close()


def test_bad_messages_in_a_session_end_it(door: Any) -> None:
    sock, session = handshake(door.fedpro_address)
    # A call that does not parse as a CallRequest is answered with RTIinternalError ...
    sock.sendall(encode_message(MessageType.HLA_CALL_REQUEST, 1, session, 0, b"\xff\xff\xff"))
    header = fedpro.decode_header(recv_exact(sock, 24))
    payload = recv_exact(sock, header.size - 24)
    assert header.type == MessageType.HLA_CALL_RESPONSE and payload[:4] == struct.pack(">I", 1)
    from hlacore.fedpro._proto import RTIambassador_pb2
    response = RTIambassador_pb2.CallResponse.FromString(payload[4:])
    assert response.exceptionData.exceptionName == "RTIinternalError"
    # ... a message of another session ends the session.
    sock.sendall(encode_message(MessageType.HEARTBEAT, 2, session + 1, 1))
    assert closed(sock)
    sock.close()
    # A resume of it now is refused: the session is gone.
    resume = socket.create_connection(split_address(door.fedpro_address), timeout=5)
    resume.sendall(encode_message(MessageType.RESUME_REQUEST, 0, session, 1, struct.pack(">II", 1, 1)))
    header = fedpro.decode_header(recv_exact(resume, 24))
    assert header.type == MessageType.RESUME_STATUS
    assert struct.unpack(">I", recv_exact(resume, header.size - 24)[:4])[0] == 1  # invalid session
    resume.close()


def test_a_resume_reports_the_last_hla_message_received_not_a_heartbeat(door: Any) -> None:
    """A federate keeps only its HLA messages to send again (Pitch's client cannot rewind to a heartbeat's
    number): the resume names the last call the door received, though a heartbeat came after it."""
    sock, session = handshake(door.fedpro_address)
    from hlacore.fedpro._proto import RTIambassador_pb2
    call = RTIambassador_pb2.CallRequest(listFederationExecutionsRequest={}).SerializeToString()
    sock.sendall(encode_message(MessageType.HLA_CALL_REQUEST, 1, session, 0, call))
    header = fedpro.decode_header(recv_exact(sock, 24))
    recv_exact(sock, header.size - 24)
    sock.sendall(encode_message(MessageType.HEARTBEAT, 2, session, header.sequence))
    header = fedpro.decode_header(recv_exact(sock, 24))
    assert header.type == MessageType.HEARTBEAT_RESPONSE and recv_exact(sock, 4) == struct.pack(">I", 2)
    sock.close()  # dropped: the session waits for a resume
    resume = socket.create_connection(split_address(door.fedpro_address), timeout=5)
    resume.sendall(encode_message(MessageType.RESUME_REQUEST, 0, session, header.sequence, struct.pack(">II", 1, 1)))
    header = fedpro.decode_header(recv_exact(resume, 24))
    assert header.type == MessageType.RESUME_STATUS
    assert struct.unpack(">II", recv_exact(resume, header.size - 24)) == (0, 1)  # ok, the call (1), not the heartbeat
    resume.sendall(encode_message(MessageType.TERMINATE_SESSION, 3, session, header.sequence))
    header = fedpro.decode_header(recv_exact(resume, 24))
    assert header.type == MessageType.SESSION_TERMINATED
    resume.close()
