"""Large values (docs/robustness.md, case 3). A value too large for the gateway's frame limit raises ValueLengthExceeded
at the call, before anything is sent, with the limit computed so that what the gateway forwards (a
reflection is a few bytes longer than the update) always fits; a client that sends one anyway is dropped
with the reason; camera-size updates reach a subscriber that ticks slowly, through flow control. Against
the real rtig (`--max-frame` makes the limit small enough to test quickly)."""

from __future__ import annotations

import hashlib
import pathlib
import re
import time
from typing import Any

import pytest

import hlacore
import hlacore.rti as rti
from hlacore.processes import python_peer

from support import PEERS, ROBOT_FED, release_rtig, running_rtig, tick_until, vm_rss, wait_until
from support.federations import legit_federation
from support.wire import (T, boolean, closed_and_dropped, frame, handles, joined_raw_client, optional_time, string, u32,
                          u64)

PEER = PEERS / "large_values_peer.py"
MIB = 1 << 20
LIMIT = MIB


class Reflections(rti.FederateAmbassador):
    def __init__(self) -> None:
        self.values: list[bytes] = []

    def reflectAttributeValues(self, obj: Any, attributes: dict[Any, bytes], *rest: Any) -> None:
        self.values.append(next(iter(attributes.values())))


def largest_accepted(rtia: rti.RTIAmbassador, obj: Any, location: Any) -> int:
    """The largest value updateAttributeValues accepts, by bisection (each accepted one is sent)."""
    low, high = 0, LIMIT  # low is accepted, high refused
    while high - low > 1:
        middle = (low + high) // 2
        try:
            rtia.updateAttributeValues(obj, {location: bytes(middle)}, "")
            low = middle
        except rti.ValueLengthExceeded:
            high = middle
    return low


def test_a_value_over_the_frame_limit_raises_at_the_call(tmp_path: pathlib.Path) -> None:
    """Against `rtig --max-frame 1 MiB`: the largest accepted update is reflected in a frame of exactly the
    limit; one byte more raises ValueLengthExceeded (the sender stays joined and usable, nothing reaches the
    subscriber); an interaction the same."""
    with running_rtig(tmp_path, "--max-frame", str(LIMIT)) as server, legit_federation(server.address) as legit:
        robot, _, location = legit.handles()
        with joined_raw_client(server.address, "watcher") as (watcher, _):
            watcher.send(frame("SubscribeObjectClass", u32(robot) + handles([location]) + boolean(True)))
            watcher.ping()
            alice = legit.alice.rtia
            obj = alice.registerObjectInstance(legit.robot, "big")
            largest = largest_accepted(alice, obj, legit.location)
            with pytest.raises(rti.ValueLengthExceeded, match=rf"over its frame limit of {LIMIT} bytes"):
                alice.updateAttributeValues(obj, {legit.location: bytes(largest + 1)}, "")
            with pytest.raises(rti.ValueLengthExceeded):  # the tag counts too
                alice.updateAttributeValues(obj, {legit.location: bytes(largest)}, "t")
            alice.updateAttributeValues(obj, {legit.location: b"after"}, "")  # still joined, still usable
            lengths = []
            while True:
                code, payload = watcher.recv_frame(timeout=10)
                if code != T["ReflectAttributes"]:
                    continue
                lengths.append(2 + len(payload))
                if b"after" in payload:
                    break
            with pytest.raises(rti.ValueLengthExceeded):
                alice.sendInteraction(legit.command, {legit.value: bytes(LIMIT)}, "")
        print(f"\nframe limit {LIMIT}: largest value accepted {largest} bytes, its reflection's frame "
              f"{max(lengths)} bytes")
        assert max(lengths) == LIMIT  # the largest accepted update is forwarded at exactly the limit
        assert LIMIT - 64 < largest < LIMIT
        legit.check_working()
        assert not re.search(r"protocol error|not reading", server.log()), server.log()  # the watcher's own close only


def test_an_update_whose_reflection_would_not_fit_drops_its_raw_sender(tmp_path: pathlib.Path) -> None:
    """A client that skips the check: an update of the limit less 5 bytes would be reflected over it, so the
    gateway refuses it (protocol error) instead of forwarding what its subscribers could not read."""
    with running_rtig(tmp_path, "--max-frame", str(LIMIT)) as server, legit_federation(server.address) as legit:
        robot, battery, _ = legit.handles()
        with joined_raw_client(server.address, "careless") as (careless, handle):
            careless.send(frame("PublishObjectClass", u32(robot) + handles([battery])))
            reply = careless.call("RegisterObject", u32(robot) + string("careless-object"))
            assert reply.error == 0, reply.message
            head = u32(reply.handle) + u32(1) + u32(battery)
            tail = string("") + optional_time(None) + u64(1)
            value = bytes(LIMIT - 5 - 2 - len(head) - 4 - len(tail))
            update = frame("UpdateAttributes", head + string(value) + tail)
            assert len(update) - 4 == LIMIT - 5
            careless.send(update, tolerate_drop=True)
            line = closed_and_dropped(server, careless)
        assert (f"(federate {handle} of 'TestFed'): protocol error: UpdateAttributes of {LIMIT - 5} bytes would be "
                f"forwarded over the frame limit of {LIMIT} bytes") in line, line
        legit.check_working()


def test_the_in_process_gateway_takes_the_frame_limit() -> None:
    with hlacore.Gateway(port=0, max_frame=LIMIT) as gw, legit_federation(gw.address) as legit:
        obj = legit.alice.rtia.registerObjectInstance(legit.robot, "big")
        with pytest.raises(rti.ValueLengthExceeded, match=f"frame limit of {LIMIT} bytes"):
            legit.alice.rtia.updateAttributeValues(obj, {legit.location: bytes(LIMIT)}, "")


@pytest.mark.slow
def test_camera_size_updates_reach_a_subscriber_that_ticks_slowly(tmp_path: pathlib.Path) -> None:
    """Eight updates of about 20 MiB (camera frames) from a publisher process to a subscriber that ticks every
    0.3 s: flow control holds the publisher back while the subscriber takes them; nobody is dropped and every
    frame arrives intact, in order. Against the optimized rtig with its defaults (64 MiB budget and frame
    limit); its memory is measured. The buffers it keeps for the next frame while frames come (reused rather
    than mapped afresh: docs/performance.md) are given back once they stop, the subscriber still joined. Each
    frame is 64 KiB smaller than the one before: the first ones freed raise glibc's mmap threshold, so the rtig
    gets the later ones from its heap, which only its trim gives back, once nothing holds them (not even a
    splice still to be written to the subscriber)."""
    count, mib, shrink = 8, 20, 64 << 10
    executable = release_rtig()
    assert executable, "the optimized rtig is installed beside Python by ./scripts/test.sh"
    with running_rtig(tmp_path, executable=executable) as server:
        rti.RTIAmbassador(server.address).createFederationExecution("TestFed", ROBOT_FED)
        sub, amb = rti.RTIAmbassador(server.address), Reflections()
        sub.joinFederationExecution("viewer", "TestFed", amb)
        robot = sub.getObjectClassHandle("robot")
        sub.subscribeObjectClassAttributes(robot, [sub.getAttributeHandle("location", robot)])
        baseline = peak = vm_rss(server.proc.pid)
        started = time.monotonic()
        with python_peer(PEER, server.address, count, mib, shrink) as publisher:
            first = None
            while len(amb.values) < count:
                assert time.monotonic() - started < 120, f"{len(amb.values)} of {count} frames in 120 s"
                time.sleep(0.3)
                sub.tick(0.0, 0.0)  # what has arrived, nothing more
                peak = max(peak, vm_rss(server.proc.pid))
                if amb.values and first is None:
                    first = time.monotonic() - started
            report = publisher.read_json(60)
            assert publisher.wait(30) == 0
        took = time.monotonic() - started
        wait_until(lambda: vm_rss(server.proc.pid) - baseline < 4 * MIB, timeout=10)
        settled = vm_rss(server.proc.pid)
        sub.resignFederationExecution(rti.ResignAction.NoAction)
        log = server.log()
    print(f"\n{count} x {mib} MiB to a subscriber ticking every 0.3 s: first after {first:.1f} s, all after "
          f"{took:.1f} s; publisher's slowest call {report['slowest_call']} s; rtig VmRSS {baseline / MIB:.1f} MiB "
          f"before, peak {peak / MIB:.1f} MiB, {settled / MIB:.1f} MiB once the frames stopped")
    assert [len(v) for v in amb.values] == [(mib << 20) - k * shrink for k in range(count)]
    assert all(v[0] == k and v[-1] == k and v.count(bytes([k])) == len(v) for k, v in enumerate(amb.values))
    assert not re.search(r"dropped", log), log


class Received(rti.FederateAmbassador):
    """Every reflection's and interaction's values, as {name: value} by the handles' names."""

    def __init__(self, names: dict[Any, str]) -> None:
        self.names = names
        self.reflections: list[dict[str, bytes]] = []
        self.interactions: list[dict[str, bytes]] = []

    def reflectAttributeValues(self, obj: Any, attributes: dict[Any, bytes], *rest: Any) -> None:
        self.reflections.append({self.names[h]: v for h, v in attributes.items()})

    def receiveInteraction(self, cls: Any, parameters: dict[Any, bytes], *rest: Any) -> None:
        self.interactions.append({self.names[h]: v for h, v in parameters.items()})


def digests(values: dict[str, bytes]) -> dict[str, str]:
    """Each value as its length and SHA-256: what a failure shows of megabytes."""
    return {name: f"{len(v)} bytes, sha256 {hashlib.sha256(v).hexdigest()[:16]}" for name, v in values.items()}


def test_large_values_reach_every_subscriber_intact_while_one_of_them_lags(tmp_path: pathlib.Path) -> None:
    """The gateway writes values from 256 KiB on to their receivers from the frame they came in (its
    splices, docs/performance.md), and reads the sender's next frames into other blocks meanwhile. Six
    updates, each with a 3 MiB, a 300 KiB and a small value, and six interactions with a 1 MiB parameter, all
    different, go to two subscribers; one of them reads nothing until all are sent, so the gateway still
    holds its part of the earlier frames while the later ones come. Both get every value intact, in order.
    Against the sanitizer build of the rtig."""
    count = 6
    with running_rtig(tmp_path) as server:
        pub = rti.RTIAmbassador(server.address)
        pub.createFederationExecution("TestFed", ROBOT_FED)
        pub.joinFederationExecution("camera", "TestFed", rti.FederateAmbassador())
        robot = pub.getObjectClassHandle("robot")
        attributes = {name: pub.getAttributeHandle(name, robot) for name in ("location", "sensor1", "sensor2")}
        command = pub.getInteractionClassHandle("urgent_command")
        parameters = {name: pub.getParameterHandle(name, command) for name in ("name", "value")}
        names = {h: name for name, h in {**attributes, **parameters}.items()}
        subscribers = []
        for name in ("prompt", "lagging"):
            sub, amb = rti.RTIAmbassador(server.address), Received(names)
            sub.joinFederationExecution(name, "TestFed", amb)
            sub.subscribeObjectClassAttributes(robot, list(attributes.values()))
            sub.subscribeInteractionClass(command)
            subscribers.append((sub, amb))
        (prompt, prompt_amb), (lagging, lagging_amb) = subscribers
        pub.publishObjectClass(robot, list(attributes.values()))
        pub.publishInteractionClass(command)
        obj = pub.registerObjectInstance(robot, "camera")

        def update(k: int) -> dict[str, bytes]:
            return {"location": bytes([k]) * (3 * MIB), "sensor1": b"small %d" % k,
                    "sensor2": bytes([100 + k]) * (300 << 10)}

        def interaction(k: int) -> dict[str, bytes]:
            return {"name": b"frame %d" % k, "value": bytes([200 + k]) * MIB}

        for k in range(count):
            pub.updateAttributeValues(obj, {attributes[n]: v for n, v in update(k).items()}, "")
            pub.sendInteraction(command, {parameters[n]: v for n, v in interaction(k).items()}, "")
            prompt.tick(0.0, 0.0)
        for sub, amb in subscribers:
            tick_until(lambda: len(amb.reflections) == count and len(amb.interactions) == count, sub, timeout=30)
            assert [digests(r) for r in amb.reflections] == [digests(update(k)) for k in range(count)]
            assert [digests(i) for i in amb.interactions] == [digests(interaction(k)) for k in range(count)]
        for rtia in (pub, prompt, lagging):
            rtia.resignFederationExecution(rti.ResignAction.DeleteObjectsAndReleaseAttributes)
        assert not re.search(r"dropped", server.log()), server.log()
