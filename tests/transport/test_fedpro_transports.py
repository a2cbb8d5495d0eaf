"""The Federate Protocol's door over each of its transports (TCP, TLS, WebSocket, WebSocket over TLS) and behind
the gateway's secret: a timestamped lockstep through each, its connection cut under it and resumed (a fresh TLS
and WebSocket handshake each time); connect asking for the secret as HLAplainTextPassword credentials; what the
door refuses to open, and bad handshakes closing only their own connection."""

from __future__ import annotations

import pathlib
import socket
import ssl
import subprocess
from typing import Optional

import pytest

import hlacore.rti as rti13
from hlacore import fedpro
from hlacore.fedpro.session import split_address
from hlacore.fedpro._proto import datatypes_pb2
from hlacore.link import Link

from support import make_certificate, rtig_executable, secret_file
from support.fedpro import Calls, Pair
from support.fedpro import door as fedpro_door
from support.rti1516e import VEHICLES

SECURE = ("tls", "websocketsecure")


def trusting(cert: pathlib.Path) -> ssl.SSLContext:
    """A client context that trusts the door's self-signed certificate (and checks the host it names)."""
    return ssl.create_default_context(cafile=str(cert))


@pytest.mark.parametrize("protocol", ["tcp", "tls", "websocket", "websocketsecure"])
def test_a_lockstep_over_each_transport_resumes_after_a_cut(tmp_path: pathlib.Path, protocol: str) -> None:
    cert, key = make_certificate(tmp_path, "door", "IP:127.0.0.1")
    # The native federate comes through the Unix socket, which has no TLS even when the gateway has it.
    tls = ["--tls-cert", str(cert), "--tls-key", str(key)] if protocol in SECURE else []
    with fedpro_door(tmp_path, *tls, "--unix", str(tmp_path / "gateway.sock"), address=f"{protocol}://127.0.0.1:0") as server:
        assert server.fedpro_protocol == protocol
        with Link(("127.0.0.1", 0), split_address(server.fedpro_address)) as link:
            amb = Calls()
            context = trusting(cert) if protocol in SECURE else None
            rtia = fedpro.RTIambassador(link.address, protocol=protocol, ssl_context=context, resume_timeout=10.0)
            rtia.connect(amb)
            rtia.createFederationExecutionWithModules(federationName="Road", fomModules=[VEHICLES])
            rtia.joinFederationExecution(federateName="remote", federateType="fedpro", federationName="Road")
            pair = Pair(rtia, amb, str(server.unix_address))
            try:
                def cut(step: int) -> None:
                    if step in (40, 80):
                        assert link.cut() == 1

                pair.lockstep(rtia, amb, 120, cut)
                assert rtia.session.resumes == 2
            finally:
                pair.other.close()
                rtia.resignFederationExecution(resignAction="CANCEL_THEN_DELETE_THEN_DIVEST")
                rtia.destroyFederationExecution(federationName="Road")
                rtia.close()


def test_connect_asks_for_the_gateways_secret_as_a_password(tmp_path: pathlib.Path) -> None:
    """With --secret-file, connect needs HLAplainTextPassword credentials holding the secret: without credentials,
    with HLAnoCredentials or a wrong password it is Unauthorized, with credentials it cannot read InvalidCredentials,
    and the session stays open for another try. The door's federates reach the gateway through their own socket,
    proving the secret; a federate of hlacore's own protocol still needs it."""
    secret = secret_file(tmp_path, "correct horse battery staple ☃")
    unauthorized = fedpro.rti_exception("Unauthorized")
    with fedpro_door(tmp_path, "--secret-file", str(secret)) as server:
        rtia = fedpro.RTIambassador(server.fedpro_address)
        try:
            amb = Calls()
            for credentials in (None, datatypes_pb2.Credentials(type="HLAnoCredentials"), fedpro.plain_text_password("wrong")):
                with pytest.raises(unauthorized):
                    rtia.connect(amb) if credentials is None else rtia.connect(amb, credentials=credentials)
            for credentials in (datatypes_pb2.Credentials(type="HLAplainTextPassword", data=b"\x00\x00\x00\x09ab"),
                                datatypes_pb2.Credentials(type="Kerberos", data=b"ticket")):
                with pytest.raises(fedpro.rti_exception("InvalidCredentials")):
                    rtia.connect(amb, credentials=credentials)
            rtia.connect(amb, credentials=fedpro.plain_text_password("correct horse battery staple ☃"))
            rtia.createFederationExecutionWithModules(federationName="Road", fomModules=[VEHICLES])
            rtia.joinFederationExecution(federateName="inside", federateType="fedpro", federationName="Road")
            assert rtia.getFederateName(federate=rtia.getFederateHandle(federateName="inside")) == "inside"
            with pytest.raises(rti13.AuthenticationFailed):
                rti13.RTIAmbassador(server.address)
            rtia.resignFederationExecution(resignAction="NO_ACTION")
            rtia.destroyFederationExecution(federationName="Road")
        finally:
            rtia.close()


def refused(*args: str) -> str:
    """rtig's complaint when it will not start with `args`."""
    run = subprocess.run([rtig_executable(), "--port", "0", *args], capture_output=True, text=True, timeout=30)
    assert run.returncode != 0, run.stdout
    return run.stderr


def test_the_door_refuses_what_it_cannot_guard(tmp_path: pathlib.Path) -> None:
    secret = secret_file(tmp_path, "s3cret")
    cert, key = make_certificate(tmp_path, "door", "IP:127.0.0.1")
    assert "beyond this machine, needs the gateway's secret" in refused("--fedpro", "0.0.0.0:0")
    assert "over tls:// or websocketsecure:// only" in refused("--secret-file", str(secret), "--fedpro", "ws://0.0.0.0:0")
    assert "needs the gateway's certificate" in refused("--fedpro", "tls://127.0.0.1:0")
    assert "'gopher' is not a transport" in refused("--fedpro", "gopher://127.0.0.1:0")
    assert "is not [PROTOCOL://]HOST:PORT" in refused("--tls-cert", str(cert), "--tls-key", str(key), "--fedpro", "wss://127.0.0.1:x")


def exchange(address: str, data: bytes, tls: Optional[ssl.SSLContext] = None) -> bytes:
    """What the door answers to `data` on a fresh connection, until it closes it (at most 5 s)."""
    raw = socket.create_connection(split_address(address), timeout=5)
    sock = tls.wrap_socket(raw, server_hostname="127.0.0.1") if tls else raw
    with sock:
        sock.sendall(data)
        got = b""
        while chunk := sock.recv(65536):
            got += chunk
        return got


UPGRADE = (b"GET / HTTP/1.1\r\nHost: 127.0.0.1\r\nUpgrade: websocket\r\nConnection: Upgrade\r\n"
           b"Sec-WebSocket-Key: dGhlIHNhbXBsZSBub25jZQ==\r\nSec-WebSocket-Version: 13\r\n\r\n")


def test_bad_handshakes_close_only_their_connection(tmp_path: pathlib.Path) -> None:
    """A request that is not a WebSocket upgrade gets status 400 saying why; a text frame after the upgrade, or an
    unmasked frame, closes the connection; a session opened meanwhile goes on."""
    with fedpro_door(tmp_path, address="websocket://127.0.0.1:0") as server:
        rtia = fedpro.RTIambassador(server.fedpro_address, protocol="websocket")
        try:
            rtia.connect(Calls())
            answer = exchange(server.fedpro_address, b"GET /index.html HTTP/1.1\r\nHost: 127.0.0.1\r\n\r\n")
            assert answer.startswith(b"HTTP/1.1 400 ") and b"does not ask to upgrade to websocket" in answer
            answer = exchange(server.fedpro_address, UPGRADE.replace(b"Version: 13", b"Version: 8"))
            assert answer.startswith(b"HTTP/1.1 400 ") and b"version other than 13" in answer
            # The RFC's example key, and its accept value; then an empty text frame, refused by closing (frames with
            # no payload: nothing left unread, which would make the close a reset that loses the answer).
            answer = exchange(server.fedpro_address, UPGRADE + b"\x81\x80\x00\x00\x00\x00")
            assert answer.startswith(b"HTTP/1.1 101 ") and b"Sec-WebSocket-Accept: s3pPLMBiTxaQ9kYGzzhZRbK+xOo=" in answer
            assert answer.endswith(b"\r\n\r\n"), "nothing after the answer: the connection closed"
            assert exchange(server.fedpro_address, UPGRADE + b"\x82\x00").endswith(b"\r\n\r\n")  # unmasked
            assert rtia.listFederationExecutions() is None  # still served
        finally:
            rtia.close()


def test_a_tls_door_closes_a_plain_connection_and_goes_on(tmp_path: pathlib.Path) -> None:
    cert, key = make_certificate(tmp_path, "door", "IP:127.0.0.1")
    with fedpro_door(tmp_path, "--tls-cert", str(cert), "--tls-key", str(key), address="tls://127.0.0.1:0") as server:
        rtia = fedpro.RTIambassador(server.fedpro_address, protocol="tls", ssl_context=trusting(cert))
        try:
            rtia.connect(Calls())
            with pytest.raises((fedpro.SessionError, OSError)):
                fedpro.RTIambassador(server.fedpro_address, connect_timeout=3.0)  # plain TCP to TLS
            with pytest.raises(ssl.SSLCertVerificationError):
                fedpro.RTIambassador(server.fedpro_address, protocol="tls")  # the system's CAs do not know it
            assert rtia.listFederationExecutions() is None
        finally:
            rtia.close()
