"""Flow control (docs/robustness.md, cases 1 and 4): a constrained federate that keeps ticking but does not advance
while an untimed publisher floods it with 1 KiB updates (the ROS bridge's pattern). The gateway holds the updates
for it (HLA 1.3: receive-order messages wait until it advances) up to its --client-budget, then stops reading the
publisher, whose calls block; nobody is dropped, and when the federate advances it receives every update in order.
Against the optimized rtig (its memory is measured), federates in their own processes; the test process is a
bystander in another federation measuring its round trips."""

from __future__ import annotations

import pathlib
import re
import threading
import time
from typing import Any

import pytest

import hlacore
import hlacore.rti as rti
from hlacore.status import status
from hlacore.processes import python_peer

from support import PEERS, ROBOT_FED, Recorder, release_rtig, running_rtig, vm_rss
from support.federations import legit_federation
from support.wire import boolean, frame, handles, raw_client, u32, u64

PEER = PEERS / "flow_peer.py"
MIB = 1 << 20


def bystander_round_trip(pub: rti.RTIAmbassador, sub: rti.RTIAmbassador, amb: Recorder, obj: Any,
                         location: Any) -> float:
    """One update from `pub` until `sub` reflects it, in seconds."""
    started = time.monotonic()
    before = len(amb.calls)
    pub.updateAttributeValues(obj, {location: b"x"}, "")
    while len(amb.calls) == before:
        sub.tick(0.05, 0.05)
        assert time.monotonic() - started < 30, "the bystander's update never arrived"
    return time.monotonic() - started


@pytest.mark.slow
@pytest.mark.parametrize("order, seconds, budget", [("receive", 60.0, 16 * MIB), ("timestamp", 20.0, 16 * MIB)])
def test_a_federate_that_does_not_advance_holds_back_its_publisher_within_the_budget(
        tmp_path: pathlib.Path, order: str, seconds: float, budget: int) -> None:
    executable = release_rtig()
    assert executable, "the optimized rtig is installed beside Python by ./scripts/test.sh"
    with running_rtig(tmp_path, "--client-budget", str(budget), executable=executable) as server:
        rti.RTIAmbassador(server.address).createFederationExecution("TestFed", ROBOT_FED)
        rti.RTIAmbassador(server.address).createFederationExecution("Other", ROBOT_FED)
        pub, sub, amb = rti.RTIAmbassador(server.address), rti.RTIAmbassador(server.address), Recorder()
        pub.joinFederationExecution("bystander-pub", "Other", rti.FederateAmbassador())
        sub.joinFederationExecution("bystander-sub", "Other", amb)
        robot = pub.getObjectClassHandle("robot")
        location = pub.getAttributeHandle("location", robot)
        pub.publishObjectClass(robot, [location])
        sub.subscribeObjectClassAttributes(robot, [location])
        obj = pub.registerObjectInstance(robot)
        baseline = vm_rss(server.proc.pid)
        with python_peer(PEER, "paused", server.address, seconds, order) as paused:
            assert paused.read_json(30) == {"ready": True}  # subscribed and constrained before anything is sent
            publisher = python_peer(PEER, "publisher", server.address, seconds, order)
            assert publisher.read_json(30) == {"ready": True}
            # The paused federate stops pausing a little before `seconds` from now (it started first).
            peak, peak_after, worst, trips = baseline, baseline, 0.0, 0
            start = time.monotonic()
            while time.monotonic() < start + seconds + 2:
                if time.monotonic() < start + seconds - 1:
                    peak = max(peak, vm_rss(server.proc.pid))
                else:
                    peak_after = max(peak_after, vm_rss(server.proc.pid))
                worst = max(worst, bystander_round_trip(pub, sub, amb, obj, location))
                trips += 1
                time.sleep(0.05)
            with publisher:
                sent = publisher.read_json(seconds + 60)
                assert publisher.wait(30) == 0, publisher.stderr()  # resigned, not killed on the way out
            received = paused.read_json(seconds + 120)
            assert paused.wait(30) == 0, paused.stderr()
        log = server.log()
    print(f"\n{order} order, {seconds:.0f} s, budget {budget // MIB} MiB: rtig VmRSS {baseline / MIB:.1f} MiB before, "
          f"peak {peak / MIB:.1f} MiB (+{(peak - baseline) / MIB:.1f}) while paused, {peak_after / MIB:.1f} MiB "
          f"(+{(peak_after - baseline) / MIB:.1f}) as it advanced; publisher sent {sent['sent']} updates, "
          f"its slowest call {sent['slowest_call']} s; the paused federate received {received['received']} "
          f"({received['before_advance']} before advancing), in order: {received['in_order']}; bystander: "
          f"{trips} round trips, worst {worst * 1000:.1f} ms")
    assert received["received"] == sent["sent"] and received["in_order"], (sent, received)
    assert received["before_advance"] == 0  # held, as HLA 1.3 says, until it advanced
    assert sent["slowest_call"] > 1  # the publisher was held back rather than buffered without bound
    assert peak - baseline < budget + 8 * MIB, "rtig held more than the client's budget"
    assert not re.search(r"dropped .*\(federate", log), log  # no federate dropped (a closing idle client may log)


# ---- fairness (case 4): what one client's requests make the gateway produce is bounded ----


def test_pipelined_status_queries_that_are_never_read_cannot_grow_the_gateway(tmp_path: pathlib.Path) -> None:
    """A client that never joined pipelines 2.3 MiB of status queries (100 000) and reads none of the
    answers: once its own queue is over its budget the gateway stops reading it, so rtig's memory stays
    within the budget and the federation beside it keeps working."""
    executable = release_rtig()
    assert executable, "the optimized rtig is installed beside Python by ./scripts/test.sh"
    budget = 4 * MIB
    with running_rtig(tmp_path, "--client-budget", str(budget), executable=executable) as server, \
            legit_federation(server.address) as legit:
        baseline = vm_rss(server.proc.pid)
        with raw_client(server.address, rcvbuf=4096) as hostile:
            hostile.handshake()
            queries = b"".join(frame("QueryStatus", u32(i) + u64(0) + boolean(True)) for i in range(100_000))
            # Its sends block once the gateway stops reading it: from a thread, ended by closing the socket.
            sender = threading.Thread(target=_send_ignoring_close, args=(hostile.sock, queries), daemon=True)
            sender.start()
            peak, worst = baseline, 0.0
            for _ in range(20):
                started = time.monotonic()
                legit.check_working()
                worst = max(worst, time.monotonic() - started)
                peak = max(peak, vm_rss(server.proc.pid))
                time.sleep(0.05)
            # Its own unread replies are not spilled to disk (it is held back instead): nothing to read back.
            spilled = status(server.address)["spill"]["used"]
        sender.join(10)
        print(f"\nstatus flood: rtig VmRSS {baseline / MIB:.1f} MiB before, peak {peak / MIB:.1f} MiB "
              f"(+{(peak - baseline) / MIB:.1f}, budget {budget // MIB} MiB); legit federation's worst check "
              f"{worst * 1000:.0f} ms")
        assert peak - baseline < budget + 8 * MIB
        assert spilled == 0 and "spilled" not in server.log(), server.log()
        legit.check_working()
        assert "protocol error" not in server.log()  # held back for its queue, not dropped for a bad frame


def _send_ignoring_close(sock: Any, data: bytes) -> None:
    try:
        sock.sendall(data)
    except OSError:
        pass  # the test closed the socket


def test_a_burst_of_class_update_requests_does_not_drop_the_owner(tmp_path: pathlib.Path) -> None:
    """A federate asks 200 times for the attributes of every robot while another owns 1 000 of them
    (200 000 provideAttributeValueUpdate callbacks, more than the 1 MiB budget holds): the requester is held
    back while the owner takes them, the owner is not dropped and gets every one."""
    with running_rtig(tmp_path, "--client-budget", str(MIB)) as server, legit_federation(server.address) as legit:
        alice, bob = legit.alice, legit.bob
        for i in range(1000):
            alice.rtia.registerObjectInstance(legit.robot, f"owned-{i}")
        requests = 200
        for _ in range(requests):
            bob.rtia.requestClassAttributeValueUpdate(legit.robot, [legit.battery])
        expected = requests * (1000 + len(legit.objects))
        deadline = time.monotonic() + 120
        while len(alice.amb.named("provideAttributeValueUpdate")) < expected:
            alice.rtia.tick(0.05, 0.5)
            assert time.monotonic() < deadline, len(alice.amb.named("provideAttributeValueUpdate"))
        print(f"\nclass update burst: the owner got {expected} provideAttributeValueUpdate")
        assert "dropped" not in server.log(), server.log()
        legit.check_working()


# ---- the knobs of the in-process gateway ----


def test_the_in_process_gateway_takes_the_same_flow_control_knobs(capfd: pytest.CaptureFixture[str]) -> None:
    """hlacore.Gateway(client_budget=..., stall_timeout=..., disk_budget=0) are rtig's --client-budget,
    --stall-timeout and --disk-budget: without spilling, a subscriber that never reads holds back its
    publisher, then is dropped with its budget in the reason."""
    budget = 1 << 16
    with hlacore.Gateway(port=0, client_budget=budget, stall_timeout=1.0, disk_budget=0) as gw, \
            legit_federation(gw.address) as legit:
        robot, _, location = legit.handles()
        with raw_client(gw.address, rcvbuf=4096) as sloth:
            sloth.join("sloth")
            sloth.send(frame("SubscribeObjectClass", u32(robot) + handles([location]) + boolean(True)))
            sloth.ping()  # subscribed; from here on it never reads
            alice = legit.alice.rtia
            obj = alice.registerObjectInstance(legit.robot, "heavy")
            for _ in range(120):  # 7.5 MiB: beyond the budget and what the kernel buffers hold
                alice.updateAttributeValues(obj, {legit.location: bytes(64 << 10)}, "heavy")
            # The sends may all be in the kernel's buffers already: wait for the drop without reading a byte
            # (reading until EOF would make the sloth a reader).
            deadline = time.monotonic() + 30
            while any(f["name"] == "sloth" for f in gw.status()["federations"][0]["federates"]):
                assert time.monotonic() < deadline, "the sloth was not dropped"
                time.sleep(0.1)
            sloth.wait_eof(timeout=10)
        legit.check_working()
    err = capfd.readouterr().err
    assert re.search(rf"dropped {re.escape(sloth.local)}\b.*not reading: \d+ bytes queued, none taken for \d+ s "
                     rf"\(budget {budget}\)", err), err


@pytest.mark.parametrize("knobs", [{"client_budget": 1000}, {"stall_timeout": -1.0},
                                   {"stall_timeout": float("inf")}, {"stall_timeout": float("nan")},
                                   {"max_frame": 1000}, {"max_frame": 1 << 31},
                                   {"max_datagram": 100}, {"max_datagram": 70000}])
def test_the_in_process_gateway_refuses_knobs_out_of_range(knobs: dict[str, Any]) -> None:
    with pytest.raises(ValueError, match=next(iter(knobs))):
        hlacore.Gateway(port=0, **knobs)
