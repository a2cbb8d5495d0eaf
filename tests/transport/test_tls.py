"""Optional TLS (docs/networking.md): `rtig --tls-cert FILE --tls-key FILE` makes every connection TLS, and
`RTIAmbassador(address, tls=...)` (or $HLACORE_TLS) verifies the gateway's certificate and the host it
connected to. Against the real rtig and the in-process gateway, on loopback, with certificates the `openssl`
command makes for the test (docs/networking.md)."""

from __future__ import annotations

import dataclasses
import json
import os
import pathlib
import socket
import subprocess
import sys
import time
from typing import Any, Iterator, Optional

import pytest

import hlacore
import hlacore.rti as rti
from hlacore.link import Link
from hlacore.status import status

from support import ROBOT_FED, RtigProcess, make_certificate, rtig_executable, running_rtig, status_client, wait_for_log
from support.federations import FEDERATION, VALUE, check_federation, run_federation
from support.wire import closed_and_dropped, raw_client


@dataclasses.dataclass
class Certificates:
    cert: pathlib.Path  # self-signed, for IP 127.0.0.1 only
    key: pathlib.Path
    other_cert: pathlib.Path  # an unrelated self-signed certificate, also for 127.0.0.1
    other_key: pathlib.Path


@pytest.fixture
def certs(tmp_path: pathlib.Path) -> Certificates:
    cert, key = make_certificate(tmp_path, "gateway", "IP:127.0.0.1")
    other_cert, other_key = make_certificate(tmp_path, "other", "IP:127.0.0.1")
    return Certificates(cert, key, other_cert, other_key)


@pytest.fixture
def tls_rtig(tmp_path: pathlib.Path, certs: Certificates) -> Iterator[RtigProcess]:
    with running_rtig(tmp_path, "--tls-cert", str(certs.cert), "--tls-key", str(certs.key),
                      "--frame-timeout", "1") as server:
        yield server


@pytest.fixture(autouse=True)
def no_tls_from_the_environment(monkeypatch: pytest.MonkeyPatch) -> None:
    monkeypatch.delenv("HLACORE_TLS", raising=False)


# ---- a federation over TLS ----


def test_a_federation_over_tls_with_rtig(tls_rtig: RtigProcess, certs: Certificates) -> None:
    result = run_federation(tls_rtig.address, tls=certs.cert)
    check_federation(result)
    # No datagrams under TLS: the best-effort interactions came over the encrypted stream.
    for side in ("alice_datagrams", "bob_datagrams"):
        assert result[side]["path"] is False
        assert "under TLS" in result[side]["reason"]
        assert result[side]["sent"] == result[side]["received"] == 0
    assert "dropped" not in tls_rtig.log()


def test_a_federation_over_tls_with_the_in_process_gateway(certs: Certificates,
                                                           monkeypatch: pytest.MonkeyPatch) -> None:
    with hlacore.Gateway(port=0, tls_cert=certs.cert, tls_key=certs.key) as gw:
        monkeypatch.setenv("HLACORE_TLS", str(certs.cert))  # the environment, as PyHLA scripts take it
        check_federation(run_federation(gw.address, tls=None))
        report = gw.status()  # trusts its own certificate
        assert report["datagrams"]["port"] is None


def test_a_plain_federation_still_uses_datagrams(rtig: RtigProcess) -> None:
    """The same federation without TLS: best effort as datagrams (what TLS turns off)."""
    result = run_federation(rtig.address, tls=None)
    check_federation(result)
    assert result["alice_datagrams"]["path"] and result["alice_datagrams"]["sent"] == 5


def test_an_8_mib_update_over_tls_arrives_whole(tls_rtig: RtigProcess, certs: Certificates) -> None:
    """Partial TLS writes both ways: the client's into the gateway, the gateway's out to the subscriber."""
    value = os.urandom(8 << 20)
    check_federation(run_federation(tls_rtig.address, tls=str(certs.cert), value=value), value)


# ---- what crosses the network ----


def captured_federation(tmp_path: pathlib.Path, address: str, tls: Any, name: str) -> bytes:
    host, port = address.rsplit(":", 1)
    dump = tmp_path / f"{name}.dump"
    with Link(("127.0.0.1", 0), (host, int(port)), dump=str(dump)) as link:
        check_federation(run_federation(link.address, tls=tls))
    return dump.read_bytes()


def test_through_a_link_the_traffic_is_encrypted(tmp_path: pathlib.Path, certs: Certificates) -> None:
    """A relay that records every byte between the federates and the gateway: under TLS the capture holds
    neither the federation's name, the FED file's name nor an attribute value; without TLS it holds all
    three (the capture is real)."""
    secrets = (FEDERATION.encode(), b"robot.fed", VALUE)
    with running_rtig(tmp_path, "--tls-cert", str(certs.cert), "--tls-key", str(certs.key)) as server:
        encrypted = captured_federation(tmp_path, server.address, certs.cert, "tls")
    with running_rtig(tmp_path, "--max-datagram", "0") as server:
        plain = captured_federation(tmp_path, server.address, None, "plain")
    print(f"\ncaptured {len(encrypted)} bytes with TLS, {len(plain)} without")
    for secret in secrets:
        assert secret in plain, secret
        assert secret not in encrypted, secret
    assert len(encrypted) > len(VALUE)


# ---- refusals ----


def test_an_untrusted_certificate_is_refused(tls_rtig: RtigProcess, certs: Certificates) -> None:
    start = time.monotonic()
    with pytest.raises(rti.AuthenticationFailed, match="the gateway's certificate is not trusted: self-signed certificate"):
        rti.RTIAmbassador(tls_rtig.address, tls=certs.other_cert)
    with pytest.raises(rti.RTIinternalError, match="not trusted"):  # PyHLA's catch still catches it
        rti.RTIAmbassador(tls_rtig.address, tls=True)  # the system's CA store knows no test certificate
    assert time.monotonic() - start < 5
    line = wait_for_log(tls_rtig, r"rtig: dropped \S+: TLS handshake failed[^\n]*")
    assert "the client refused it (tlsv1 alert unknown ca)" in line, line
    rti.RTIAmbassador(tls_rtig.address, tls=certs.cert)  # the gateway serves on


def test_a_certificate_for_another_host_is_refused(tls_rtig: RtigProcess, certs: Certificates) -> None:
    """The certificate names IP 127.0.0.1 only: connecting by "localhost" is refused even though the chain is
    trusted."""
    with pytest.raises(rti.AuthenticationFailed, match=r"certificate at localhost:\d+ is not for 'localhost' "
                                                       r"\(hostname mismatch\)"):
        rti.RTIAmbassador(f"localhost:{tls_rtig.port}", tls=certs.cert)
    line = wait_for_log(tls_rtig, r"rtig: dropped \S+: TLS handshake failed[^\n]*")
    assert "the client refused it (sslv3 alert bad certificate)" in line, line


def refused_at_once(server: RtigProcess, who: str, error: type[Exception], message: str, tls: Any = None) -> str:
    """A client whose TLS does not match the gateway's is refused with `error` (matching `message`) well within its
    3 s timeout, and the gateway drops its connection; returns the gateway's log line of that drop (the only one)."""
    start = time.monotonic()
    with pytest.raises(error, match=message) as caught:
        rti.RTIAmbassador(server.address, tls=tls, timeout=3)
    elapsed = time.monotonic() - start
    print(f"\n{who}, after {elapsed:.2f} s: {caught.value}")
    assert elapsed < 3
    line = wait_for_log(server, r"rtig: dropped \S+: [^\n]*")
    assert server.log().count("rtig: dropped") == 1
    return line


def test_a_client_without_tls_at_a_gateway_with_it(tls_rtig: RtigProcess, certs: Certificates) -> None:
    served = rti.RTIAmbassador(tls_rtig.address, tls=certs.cert)
    served.createFederationExecution(FEDERATION, ROBOT_FED)
    line = refused_at_once(tls_rtig, "plain client at a TLS gateway", rti.RTIinternalError,
                           r"give RTIAmbassador\(tls=\.\.\.\) or \$HLACORE_TLS")
    assert "TLS handshake failed" in line and "a client without TLS?" in line, line
    served.destroyFederationExecution(FEDERATION)  # the others are served on


def test_a_client_with_tls_at_a_gateway_without_it(rtig: RtigProcess, certs: Certificates) -> None:
    served = rti.RTIAmbassador(rtig.address)
    line = refused_at_once(rtig, "TLS client at a plain gateway", rti.AuthenticationFailed,
                           r"the gateway at \S+ does not speak TLS", tls=certs.cert)
    assert "began a TLS handshake and this gateway has no TLS" in line, line
    served.createFederationExecution(FEDERATION, ROBOT_FED)
    served.destroyFederationExecution(FEDERATION)


def test_a_silent_or_garbled_handshake_is_dropped_and_harms_nobody(tls_rtig: RtigProcess, certs: Certificates) -> None:
    """A client that opens TCP and says nothing is dropped by the frame timeout (1 s here); one that sends garbage
    instead of a ClientHello at once; a federate beside them keeps working."""
    member = rti.RTIAmbassador(tls_rtig.address, tls=certs.cert)
    member.createFederationExecution(FEDERATION, ROBOT_FED)
    with raw_client(tls_rtig.address) as silent, raw_client(tls_rtig.address) as garbled:
        start = time.monotonic()
        garbled.send(b"GET / HTTP/1.0\r\n\r\n" + bytes(range(256)), tolerate_drop=True)
        line = closed_and_dropped(tls_rtig, garbled)
        assert "TLS handshake failed" in line, line
        member.joinFederationExecution("member", FEDERATION, rti.FederateAmbassador())  # not held up
        line = closed_and_dropped(tls_rtig, silent)
        elapsed = time.monotonic() - start
        assert "no TLS handshake within the frame timeout" in line, line
        assert 0.9 <= elapsed < 5, elapsed
    member.resignFederationExecution(rti.ResignAction.NoAction)
    member.destroyFederationExecution(FEDERATION)


def test_a_half_done_handshake_does_not_hold_the_reactor(tls_rtig: RtigProcess, certs: Certificates) -> None:
    """A client that sends the start of a real ClientHello and stops: the gateway serves others meanwhile."""
    with socket.create_connection(("127.0.0.1", tls_rtig.port)) as raw:
        raw.sendall(bytes([0x16, 0x03, 0x01, 0x02, 0x00, 0x01, 0x00, 0x01, 0xfc, 0x03, 0x03]))
        start = time.monotonic()
        for _ in range(3):
            rti.RTIAmbassador(tls_rtig.address, tls=certs.cert).createFederationExecution(FEDERATION, ROBOT_FED)
            rti.RTIAmbassador(tls_rtig.address, tls=certs.cert).destroyFederationExecution(FEDERATION)
        assert time.monotonic() - start < 1
        wait_for_log(tls_rtig, r"rtig: dropped \S+: no TLS handshake within the frame timeout")


# ---- options ----


def test_the_options(tmp_path: pathlib.Path, certs: Certificates) -> None:
    rtig = rtig_executable()

    def refused(*args: str) -> str:
        result = subprocess.run([rtig, "--port", "0", *args], capture_output=True, text=True, timeout=30)
        assert result.returncode != 0
        return result.stderr

    assert "--tls-cert and --tls-key go together" in refused("--tls-cert", str(certs.cert))
    certs.key.chmod(0o644)
    assert "the TLS key file" in refused("--tls-cert", str(certs.cert), "--tls-key", str(certs.key))
    assert "may be read by other users" in refused("--tls-cert", str(certs.cert), "--tls-key", str(certs.key))
    certs.key.chmod(0o600)
    assert "does not belong to the certificate" in refused("--tls-cert", str(certs.other_cert), "--tls-key", str(certs.key))
    assert "cannot read the TLS certificate" in refused("--tls-cert", str(tmp_path / "none"), "--tls-key", str(certs.key))
    help_text = subprocess.run([rtig, "--help"], capture_output=True, text=True, timeout=30).stdout
    assert "--tls-cert FILE" in help_text and "No datagrams are then offered" in " ".join(help_text.split())
    with pytest.raises(ValueError, match="go together"):
        hlacore.Gateway(port=0, tls_cert=certs.cert)
    with pytest.raises(RuntimeError, match="does not belong to the certificate"):
        hlacore.Gateway(port=0, tls_cert=certs.other_cert, tls_key=certs.key)
    with pytest.raises(rti.AuthenticationFailed, match="cannot read the TLS CA file"):
        rti.RTIAmbassador("127.0.0.1:9", tls=tmp_path / "none.pem")


def test_the_status_over_tls(tls_rtig: RtigProcess, certs: Certificates, monkeypatch: pytest.MonkeyPatch) -> None:
    rti.RTIAmbassador(tls_rtig.address, tls=certs.cert).createFederationExecution(FEDERATION, ROBOT_FED)
    rtig = status_client()
    shown = subprocess.run([rtig, "--tls-ca", str(certs.cert), "--status", tls_rtig.address], capture_output=True,
                           text=True, timeout=30)
    assert shown.returncode == 0, shown.stderr
    assert [f["name"] for f in json.loads(shown.stdout)["federations"]] == [FEDERATION]
    refused = subprocess.run([rtig, "--status", tls_rtig.address], capture_output=True, text=True, timeout=30)
    assert refused.returncode == 1 and "HLACORE_TLS" in refused.stderr
    by_env = subprocess.run([rtig, "--status", tls_rtig.address], capture_output=True, text=True, timeout=30,
                            env=dict(os.environ, HLACORE_TLS=str(certs.cert)))
    assert by_env.returncode == 0, by_env.stderr
    table = subprocess.run([sys.executable, "-m", "hlacore.status", "--tls-ca", str(certs.cert), tls_rtig.address],
                           capture_output=True, text=True, timeout=30)
    assert table.returncode == 0 and f"federation {FEDERATION}" in table.stdout, table.stderr
    assert f"at {tls_rtig.address} (TLS): " in table.stdout
    report = status(tls_rtig.address, tls=certs.cert)
    assert report["tls"] is True and [f["name"] for f in report["federations"]] == [FEDERATION]
    monkeypatch.setenv("HLACORE_TLS", str(certs.cert))
    assert status(tls_rtig.address)["datagrams"]["port"] is None


def test_the_shared_secret_works_inside_tls(tmp_path: pathlib.Path, certs: Certificates) -> None:
    secret = tmp_path / "secret"
    secret.write_text("inside the tunnel\n")
    secret.chmod(0o600)
    wrong = tmp_path / "wrong"
    wrong.write_text("guess\n")
    wrong.chmod(0o600)
    with running_rtig(tmp_path, "--tls-cert", str(certs.cert), "--tls-key", str(certs.key),
                      "--secret-file", str(secret), "--federation-secret", f"{FEDERATION}={secret}") as server:
        with pytest.raises(rti.AuthenticationFailed, match="refused the secret"):
            rti.RTIAmbassador(server.address, tls=certs.cert, secret_file=wrong)
        member = rti.RTIAmbassador(server.address, tls=certs.cert, secret_file=secret, federation_secret_file=secret)
        member.createFederationExecution(FEDERATION, ROBOT_FED)
        member.joinFederationExecution("member", FEDERATION, rti.FederateAmbassador())
        member.resignFederationExecution(rti.ResignAction.NoAction)
        member.destroyFederationExecution(FEDERATION)


def test_asyncio_over_tls(tls_rtig: RtigProcess, certs: Certificates) -> None:
    """hlacore.aio waits on fileno(): what the TLS session decrypted is never left waiting inside it."""
    import asyncio

    import hlacore.aio

    async def main() -> Optional[float]:
        rtia = rti.RTIAmbassador(tls_rtig.address, tls=certs.cert)
        rtia.create_or_join("robot", FEDERATION, ROBOT_FED, rti.FederateAmbassador())
        t = rtia.enable_time_management(1.0, timeout=5.0)
        amb = hlacore.aio.AsyncAmbassador(rtia)
        for step in range(1, 21):
            t = await asyncio.wait_for(amb.advance_to(float(step)), 5)
        rtia.resignFederationExecution(rti.ResignAction.NoAction)
        rtia.destroyFederationExecution(FEDERATION)
        return t

    assert asyncio.run(main()) == 20.0
