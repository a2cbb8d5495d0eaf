"""Access control (docs/networking.md): a gateway with a secret (`rtig --secret-file`) lets in only clients that prove
they know it, by challenge-response before anything else; without it or with a wrong one the client gets
AuthenticationFailed and no federation data; the secret never crosses the network. Against the real rtig,
on loopback and bound to a test host's address in a network namespace."""

from __future__ import annotations

import hashlib
import hmac
import os
import pathlib
import subprocess
import sys
from typing import Iterator

import pytest

import hlacore
import hlacore.rti as rti
from hlacore.link import Link
from hlacore.status import status

from support import ROBOT_FED, RtigProcess, rtig_executable, running_rtig, secret_file, status_client, wait_for_log
from support.nethosts import NetHosts
from support.wire import Answer, RawClient, T, boolean, frame, hello, raw_client, string, u32, u64

SECRET = "correct horse battery staple"


@pytest.fixture
def secret(tmp_path: pathlib.Path) -> pathlib.Path:
    return secret_file(tmp_path, SECRET)


@pytest.fixture
def guarded(tmp_path: pathlib.Path, secret: pathlib.Path) -> Iterator[RtigProcess]:
    with running_rtig(tmp_path, "--secret-file", str(secret)) as server:
        yield server


def test_the_right_secret_lets_a_federate_in(guarded: RtigProcess, secret: pathlib.Path) -> None:
    rtia = rti.RTIAmbassador(guarded.address, secret_file=secret)
    rtia.createFederationExecution("TestFed", ROBOT_FED)
    rtia.joinFederationExecution("trusted", "TestFed", rti.FederateAmbassador())
    rtia.resignFederationExecution(rti.ResignAction.NoAction)
    rtia.destroyFederationExecution("TestFed")


def test_the_secret_may_come_from_the_environment(guarded: RtigProcess, secret: pathlib.Path,
                                                  monkeypatch: pytest.MonkeyPatch) -> None:
    """$HLACORE_SECRET_FILE: PyHLA scripts run unchanged against a guarded gateway, and so does the status."""
    monkeypatch.setenv("HLACORE_SECRET_FILE", str(secret))
    rti.RTIAmbassador(guarded.address).createFederationExecution("TestFed", ROBOT_FED)
    report = status(guarded.address)
    assert [f["name"] for f in report["federations"]] == ["TestFed"]


def test_no_secret_is_refused_before_anything_is_sent(guarded: RtigProcess, monkeypatch: pytest.MonkeyPatch) -> None:
    monkeypatch.delenv("HLACORE_SECRET_FILE", raising=False)
    with pytest.raises(rti.AuthenticationFailed, match="asks for a secret and none was given"):
        rti.RTIAmbassador(guarded.address)
    with pytest.raises(rti.RTIinternalError):  # PyHLA code catching RTIinternalError still catches it
        rti.RTIAmbassador(guarded.address)


def test_a_wrong_secret_is_refused_and_logged(guarded: RtigProcess, tmp_path: pathlib.Path) -> None:
    wrong = secret_file(tmp_path, "incorrect horse", "wrong")
    with pytest.raises(rti.AuthenticationFailed, match="refused this client: the gateway refused the secret"):
        rti.RTIAmbassador(guarded.address, secret_file=wrong)
    wait_for_log(guarded, r"rtig: dropped \S+: authentication failed: wrong secret")  # logged as it closes


def test_a_client_that_skips_the_proof_gets_nothing(guarded: RtigProcess, secret: pathlib.Path) -> None:
    """A raw client that asks for the status (or anything else) instead of answering the challenge is dropped
    with nothing but the Welcome read; the federations beside it are untouched."""
    rti.RTIAmbassador(guarded.address, secret_file=secret).createFederationExecution("TestFed", ROBOT_FED)
    with raw_client(guarded.address) as sneaky:
        sneaky.send(hello())
        code, welcome = sneaky.recv_frame()
        assert code == T["Welcome"] and len(welcome) > 32  # the challenge
        sneaky.send(frame("QueryStatus", u32(1) + u64(0) + boolean(True)), tolerate_drop=True)
        sneaky.send(frame("DestroyFederation", u32(2) + string("TestFed") + string("")), tolerate_drop=True)
        sneaky.wait_eof()
        assert sneaky.buffer == b""
    wait_for_log(guarded, "QueryStatus sent before authenticating")
    rtia = rti.RTIAmbassador(guarded.address, secret_file=secret)
    rtia.destroyFederationExecution("TestFed")  # it was still there


def test_rtig_refuses_a_secret_file_others_may_read(tmp_path: pathlib.Path) -> None:
    loose = secret_file(tmp_path, SECRET)
    loose.chmod(0o644)
    result = subprocess.run([rtig_executable(), "--port", "0", "--secret-file", str(loose)], capture_output=True,
                            text=True, timeout=30)
    assert result.returncode == 2
    assert f"the secret file '{loose}' may be read by other users: chmod 600" in result.stderr
    with pytest.raises(RuntimeError, match="may be read by other users"):
        hlacore.Gateway(port=0, secret_file=loose)


def test_rtig_beyond_loopback_needs_a_secret() -> None:
    result = subprocess.run([rtig_executable(), "--port", "0", "--host", "0.0.0.0"], capture_output=True,
                            text=True, timeout=30)
    assert result.returncode == 2
    assert "needs --secret-file FILE" in result.stderr and "--no-secret" in result.stderr


def test_rtig_status_proves_the_secret_too(guarded: RtigProcess, secret: pathlib.Path) -> None:
    refused = subprocess.run([status_client(), "--status", guarded.address], capture_output=True, text=True,
                             timeout=30, env={k: v for k, v in os.environ.items() if k != "HLACORE_SECRET_FILE"})
    assert refused.returncode != 0 and "asks for a secret" in refused.stderr
    shown = subprocess.run([status_client(), "--secret-file", str(secret), "--status", guarded.address],
                           capture_output=True, text=True, timeout=30)
    assert shown.returncode == 0, shown.stderr
    assert '"federations"' in shown.stdout


def test_the_in_process_gateway_takes_a_secret(secret: pathlib.Path, monkeypatch: pytest.MonkeyPatch) -> None:
    monkeypatch.delenv("HLACORE_SECRET_FILE", raising=False)
    with hlacore.Gateway(port=0, secret_file=secret) as gw:
        with pytest.raises(rti.AuthenticationFailed):
            rti.RTIAmbassador(gw.address)
        rti.RTIAmbassador(gw.address, secret_file=secret).createFederationExecution("TestFed", ROBOT_FED)
        assert [f["name"] for f in gw.status()["federations"]] == ["TestFed"]  # the gateway knows its secret


def test_across_hosts_the_secret_never_crosses_the_link(nethosts: NetHosts, tmp_path: pathlib.Path,
                                                        secret: pathlib.Path) -> None:
    """The gateway bound to a test host's address; clients on another host reach it through a link that dumps
    every byte: the right secret works, none and a wrong one are refused before any federation data comes
    back, and the capture holds neither secret."""
    gw, robot = nethosts.add("gw"), nethosts.add("robot")
    wrong = secret_file(tmp_path, "incorrect horse", "wrong")
    dump = tmp_path / "link.dump"
    with RtigProcess(tmp_path, "--host", gw.address, "--secret-file", str(secret), prefix=gw.exec_prefix()) as server:
        rti.RTIAmbassador(server.address, secret_file=secret).createFederationExecution("TestFed", ROBOT_FED)
        with Link((robot.router, 0), (gw.address, server.port), dump=str(dump)) as link:
            probe = ("import hlacore.rti as rti, sys\n"
                     "try:\n"
                     "    r = rti.RTIAmbassador(sys.argv[1], secret_file=sys.argv[2] or None)\n"
                     "    r.joinFederationExecution('robot', 'TestFed', rti.FederateAmbassador())\n"
                     "    print('joined')\n"
                     "except rti.AuthenticationFailed as e:\n"
                     "    print('refused:', e)\n")
            outcomes = {}
            for name, path in (("none", ""), ("wrong", str(wrong)), ("right", str(secret))):
                result = subprocess.run([*robot.exec_prefix(), sys.executable, "-c", probe, link.address, path],
                                        capture_output=True, text=True, timeout=60,
                                        env={k: v for k, v in os.environ.items() if k != "HLACORE_SECRET_FILE"})
                outcomes[name] = result.stdout.strip() or result.stderr[-500:]
    captured = dump.read_bytes()
    print(f"\nacross hosts: {outcomes}; {len(captured)} bytes captured")
    assert outcomes["none"].startswith("refused: the gateway at") and "asks for a secret" in outcomes["none"]
    assert outcomes["wrong"].startswith("refused:") and "refused the secret" in outcomes["wrong"]
    assert outcomes["right"] == "joined"
    assert SECRET.encode() not in captured and b"incorrect horse" not in captured
    assert b"robot.fed" in captured  # the capture is real: the right client's join reply carries the FOM's name


# ---- a federation's own secret: creating, joining and destroying it (rtig --federation-secret NAME=FILE) ----

FEDERATION_SECRET = "the robot lab's own"


@pytest.fixture
def federation_secret(tmp_path: pathlib.Path) -> pathlib.Path:
    return secret_file(tmp_path, FEDERATION_SECRET, "lab")


@pytest.fixture
def lab_gateway(tmp_path: pathlib.Path, federation_secret: pathlib.Path) -> Iterator[RtigProcess]:
    """A loopback rtig without a connection secret where federation "Lab" has a secret of its own."""
    with running_rtig(tmp_path, "--federation-secret", f"Lab={federation_secret}") as server:
        yield server


def test_a_federation_with_its_own_secret_is_created_joined_and_destroyed_only_with_it(
        lab_gateway: RtigProcess, federation_secret: pathlib.Path, tmp_path: pathlib.Path,
        monkeypatch: pytest.MonkeyPatch) -> None:
    monkeypatch.delenv("HLACORE_FEDERATION_SECRET_FILE", raising=False)
    stranger = rti.RTIAmbassador(lab_gateway.address)
    wrong = rti.RTIAmbassador(lab_gateway.address, federation_secret_file=secret_file(tmp_path, "guess", "guess"))
    member = rti.RTIAmbassador(lab_gateway.address, federation_secret_file=federation_secret)
    with pytest.raises(rti.AuthenticationFailed, match="federation 'Lab' has a secret of its own and no secret "
                                                       r"was given \(RTIAmbassador\(federation_secret_file="):
        stranger.createFederationExecution("Lab", ROBOT_FED)
    with pytest.raises(rti.AuthenticationFailed, match="federation 'Lab' has a secret of its own and the secret is wrong"):
        wrong.createFederationExecution("Lab", ROBOT_FED)
    wait_for_log(lab_gateway, r"rtig: refused to create federation 'Lab' for \S+: the secret is wrong")
    member.createFederationExecution("Lab", ROBOT_FED)
    for outsider in (stranger, wrong):
        with pytest.raises(rti.AuthenticationFailed):
            outsider.joinFederationExecution("intruder", "Lab", rti.FederateAmbassador())
    wait_for_log(lab_gateway, r"rtig: refused to join federation 'Lab' for \S+: no secret was given")
    member.joinFederationExecution("robot", "Lab", rti.FederateAmbassador())
    member.resignFederationExecution(rti.ResignAction.NoAction)
    with pytest.raises(rti.AuthenticationFailed):
        stranger.destroyFederationExecution("Lab")
    # Other federations are open to every client the gateway lets in; the guarded one is still there.
    stranger.createFederationExecution("Open", ROBOT_FED)
    stranger.joinFederationExecution("visitor", "Open", rti.FederateAmbassador())
    assert sorted(f["name"] for f in status(lab_gateway.address)["federations"]) == ["Lab", "Open"]
    member.destroyFederationExecution("Lab")


def test_the_federation_secret_may_come_from_the_environment_and_the_in_process_gateway_takes_them(
        federation_secret: pathlib.Path, monkeypatch: pytest.MonkeyPatch) -> None:
    with hlacore.Gateway(port=0, federation_secrets={"Lab": federation_secret}) as gw:
        monkeypatch.delenv("HLACORE_FEDERATION_SECRET_FILE", raising=False)
        with pytest.raises(rti.AuthenticationFailed):
            rti.RTIAmbassador(gw.address).createFederationExecution("Lab", ROBOT_FED)
        monkeypatch.setenv("HLACORE_FEDERATION_SECRET_FILE", str(federation_secret))
        rtia = rti.RTIAmbassador(gw.address)  # as a PyHLA script gets it, unchanged
        rtia.createFederationExecution("Lab", ROBOT_FED)
        rtia.joinFederationExecution("robot", "Lab", rti.FederateAmbassador())


def test_a_federation_proof_is_bound_to_its_connection_action_and_federation(
        lab_gateway: RtigProcess, federation_secret: pathlib.Path) -> None:
    """A raw client computes the proof as docs/networking.md describes it: accepted over its own
    connection's nonce; the same bytes replayed on another connection, or given for another action, are
    refused."""
    rti.RTIAmbassador(lab_gateway.address, federation_secret_file=federation_secret).createFederationExecution(
        "Lab", ROBOT_FED)

    def proof(nonce: bytes, action: str, federation: str = "Lab") -> bytes:
        message = (b"hlacore federation authentication 1\n" + f"{len(action)}:{action}".encode()
                   + f"{len(federation)}:{federation}".encode() + nonce)
        return hmac.new(FEDERATION_SECRET.encode(), message, hashlib.sha256).digest()

    with raw_client(lab_gateway.address) as first, raw_client(lab_gateway.address) as second:
        first.handshake()
        second.handshake()
        assert len(first.nonce) == 32 and first.nonce != second.nonce
        def join(client: RawClient, name: str, signed: bytes) -> Answer:  # no FOM modules added
            return client.call("JoinFederation", string(name) + string("Lab") + string(signed) + string("") + string(""))

        joined = join(first, "first", proof(first.nonce, "join"))
        assert joined.error == 0, joined.message
        replayed = join(second, "second", proof(first.nonce, "join"))
        assert "the secret is wrong" in replayed.message
        other_action = join(second, "second", proof(second.nonce, "destroy"))
        assert "the secret is wrong" in other_action.message
        right = join(second, "second", proof(second.nonce, "join"))
        assert right.error == 0, right.message


@pytest.mark.parametrize("value, why", [
    ("Lab", "invalid --federation-secret 'Lab': takes NAME=FILE"),
    ("=file", "invalid --federation-secret '=file': takes NAME=FILE"),
    ("Lab=", "invalid --federation-secret 'Lab=': takes NAME=FILE"),
    ("Lab=/no/such/file", "cannot read the secret file '/no/such/file'"),
])
def test_rtig_refuses_a_malformed_federation_secret(value: str, why: str) -> None:
    result = subprocess.run([rtig_executable(), "--port", "0", "--federation-secret", value], capture_output=True,
                            text=True, timeout=30)
    assert result.returncode == 2 and why in result.stderr, result.stderr
