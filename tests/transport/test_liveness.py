"""A frozen gateway (docs/robustness.md, case 2): with `rtig` stopped (SIGSTOP, as a frozen host or a partition looks to
its clients), every blocking call of a federate in another process ends with GatewayNotResponding within the
client's timeout plus a second, Ctrl-C ends any of them with KeyboardInterrupt at once, and a send the gateway
does not take leaves the other Python threads running. docs/robustness.md lists the figures."""

from __future__ import annotations

import pathlib
import signal
import time
from typing import Iterator

import pytest

import hlacore.rti as rti
from hlacore.processes import Child, python_peer

from support import PEERS, ROBOT_FED, RtigProcess, running_rtig

PEER = PEERS / "frozen_gateway.py"
CALLS = ["RTIAmbassador", "createFederationExecution", "joinFederationExecution", "registerObjectInstance",
         "queryLBTS", "resignFederationExecution", "tick", "advance_to", "updateAttributeValues", "sendInteraction"]


@pytest.fixture
def stoppable_rtig(tmp_path: pathlib.Path) -> Iterator[RtigProcess]:
    """An rtig with TestFed, continued before it is stopped for good whatever the test did to it."""
    with running_rtig(tmp_path) as server:
        rti.RTIAmbassador(server.address).createFederationExecution("TestFed", ROBOT_FED)
        try:
            yield server
        finally:
            server.proc.send_signal(signal.SIGCONT)


# The peer's federate as it is by default, and busy polling its longest (test_busy_poll.py): a spin takes a
# signal without interrupting a poll, and the sleep after it is cut in slices for Ctrl-C to be seen.
BUSY_POLL = pytest.mark.parametrize("busy_poll_us", ["0", "100000"])


def frozen_peer(server: RtigProcess, mode: str, timeout: float, busy_poll_us: str = "0") -> Child:
    """The peer, set up while the gateway runs; returns once the gateway is stopped."""
    peer = python_peer(PEER, server.address, server.proc.pid, mode, timeout, env={"HLACORE_BUSY_POLL_US": busy_poll_us})
    assert peer.read_json(60) == {"ready": True}
    server.proc.send_signal(signal.SIGSTOP)
    return peer


@pytest.mark.slow
@BUSY_POLL
def test_every_blocking_call_raises_gateway_not_responding_within_its_timeout(stoppable_rtig: RtigProcess,
                                                                             busy_poll_us: str) -> None:
    timeout = 1.0
    with frozen_peer(stoppable_rtig, "timeout", timeout, busy_poll_us) as peer:
        reports = [peer.read_json(60) for _ in CALLS]
        assert peer.read_json(10) == {"done": True}
    print("\ncall                        raised                 after (s)")
    for r in reports:
        print(f"{r['call']:<28}{r['raised']:<23}{r['after']}")
    assert [r["call"] for r in reports] == CALLS
    for r in reports:
        assert r["raised"] == "GatewayNotResponding", r
        assert r["after"] <= timeout + 1.0, r


@BUSY_POLL
def test_ctrl_c_interrupts_every_blocking_call(stoppable_rtig: RtigProcess, busy_poll_us: str) -> None:
    """SIGINT 0.3 s into each call (the timeout is 30 s; busy polling, 0.05 s: within the wait's first spin):
    KeyboardInterrupt within half a second."""
    with frozen_peer(stoppable_rtig, "interrupt", 30.0, busy_poll_us) as peer:
        print("\ncall                        interrupted after (s)")
        for name in CALLS:
            assert peer.read_json(60) == {"calling": name}
            time.sleep(0.3 if busy_poll_us == "0" else 0.05)
            sent = time.monotonic()
            peer.send_signal(signal.SIGINT)
            report = peer.read_json(10)
            seen = time.monotonic() - sent
            print(f"{name:<28}{seen:.3f}")
            assert report["call"] == name and report["raised"] == "KeyboardInterrupt", report
            assert seen < 0.5, (name, seen)
        assert peer.read_json(10) == {"done": True}


def test_other_threads_run_while_a_send_is_blocked(stoppable_rtig: RtigProcess) -> None:
    """A 16 MiB update to a stopped gateway blocks in the socket with the GIL released: a thread sleeping
    10 ms at a time keeps counting until the send fails with GatewayNotResponding."""
    timeout = 2.0
    with frozen_peer(stoppable_rtig, "thread", timeout) as peer:
        report = peer.read_json(60)
        assert peer.read_json(10) == {"done": True}
    print(f"\nblocked update: {report}")
    assert report["raised"] == "GatewayNotResponding", report
    # At 10 ms a count, a free thread counts about 100 a second; a thread held by the GIL counts nothing.
    assert report["counted"] >= 50 * report["after"], report


@pytest.mark.slow
def test_a_resumed_gateway_resigns_the_federates_that_gave_up(stoppable_rtig: RtigProcess) -> None:
    """After the peer's calls failed, their connections are closed: once continued, rtig resigns those
    federates and the federation takes a new one under a name they held."""
    with frozen_peer(stoppable_rtig, "timeout", 1.0) as peer:
        for _ in CALLS:
            peer.read_json(60)
        stoppable_rtig.proc.send_signal(signal.SIGCONT)
        rtia = rti.RTIAmbassador(stoppable_rtig.address)
        deadline = time.monotonic() + 10
        while True:
            try:
                rtia.joinFederationExecution("registrant", "TestFed", rti.FederateAmbassador())
                break
            except rti.FederateAlreadyExecutionMember:
                assert time.monotonic() < deadline, "the gateway kept the federate that gave up"
                time.sleep(0.05)
        rtia.resignFederationExecution(rti.ResignAction.NoAction)
