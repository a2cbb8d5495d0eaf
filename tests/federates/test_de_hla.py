"""The HLA-aware DE director against both gateways: NER vs TAR requests and grants, no firing past a grant,
reflections and interactions as events at their timestamps, blocking while another federate lags, the
publisher/subscriber actors, and the examples of docs/de.md."""

from __future__ import annotations

import re
import threading
from typing import Any, Callable, Iterator

import pytest

import hlacore.rti as rti
from hlacore import omt
from hlacore.federates.de import (
    Actor,
    Clock,
    HlaDirector,
    InteractionReceiver,
    ObjectPublisher,
    ObjectSubscriber,
    Received,
    Recorder,
    TimedSource,
)

from support import ROOT, Federate, barrier

Join = Callable[[str], Federate]
JoinDE = Callable[..., HlaDirector]
F64 = omt.HLAfloat64BE


@pytest.fixture
def join_de(federation: Join, gateway_address: str) -> Iterator[JoinDE]:
    """Joins HlaDirectors to TestFed (made by `federation`) and resigns them afterwards."""
    directors: list[HlaDirector] = []

    def join(name: str, **options: Any) -> HlaDirector:
        options.setdefault("grant_timeout", 10.0)
        director = HlaDirector.join(name, "TestFed", address=gateway_address, **options)
        directors.append(director)
        return director

    yield join
    for director in directors:
        try:
            director.resign()
        except rti.FederateNotExecutionMember:
            pass


class Probe(Actor):
    """Records (time, microstep, granted, token) for every token, from the HLA director it runs in."""

    def __init__(self, name: str = "probe") -> None:
        super().__init__(name)
        self.input = self.add_input("input")
        self.seen: list[tuple[float, int, float, Any]] = []

    def fire(self) -> None:
        director = self.director_or_raise()
        assert isinstance(director, HlaDirector)
        for token in self.input.tokens:
            self.seen.append((director.now, director.microstep, director.granted, token))

    def never_past_grant(self) -> bool:
        return all(time <= granted for time, _, granted, _ in self.seen)


@pytest.mark.parametrize(
    "mode, grants, sent",
    [
        ("NER", [0.5, 1.7, 2.3, 3.0], [0.6, 2.4]),  # own events, the message at 1.7, then until
        ("TAR", [1.0, 2.0, 3.0], [1.1, 3.1]),  # grid points; an update carries the grant + lookahead
    ],
)
def test_ner_and_tar_requests_grants_and_firing_times(
    federation: Join, join_de: JoinDE, mode: str, grants: list[float], sent: list[float]
) -> None:
    """Local events at 0.5 and 2.3, a reflection stamped 1.7: NER is granted at each event time (the message's
    included), TAR at each grid point; every event fires at its own time, never past the grant."""
    director = join_de("de", mode=mode, step=1.0, lookahead=0.1)
    source = TimedSource("source", [(0.5, 10.0), (2.3, 20.0)])
    publisher = ObjectPublisher("publisher", "robot", {"location": F64}, instance_name="de-robot")
    subscriber = ObjectSubscriber("subscriber", "robot", {"battery": F64})
    probe = Probe()
    source.output.connect(probe.input, publisher.ports["location"])
    subscriber.ports["battery"].connect(probe.input)
    director.add(source, publisher, subscriber, probe)
    director.initialize()

    peer = federation("peer")
    robot = peer.rtia.getObjectClassHandle("robot")
    battery = peer.rtia.getAttributeHandle("battery", robot)
    peer.rtia.publishObjectClass(robot, [battery])
    peer.enable_time(lookahead=1.0, constrained=False)
    barrier(director.rtia)
    obj = peer.rtia.registerObjectInstance(robot, "peer-robot")
    peer.rtia.updateAttributeValues(obj, {battery: F64.pack(42.0)}, "peer", 1.7)
    assert peer.rtia.advance_to(10.0, timeout=5.0) == 10.0  # not constrained: granted at once

    director.run(until=3.0)
    assert director.grants == grants
    assert [(t, m, v) for t, m, _, v in probe.seen] == [(0.5, 0, 10.0), (1.7, 0, 42.0), (2.3, 0, 20.0)]
    assert probe.never_past_grant()
    assert publisher.sent == pytest.approx(sent)
    assert director.now == 3.0 and director.rtia.queryFederateTime() == 3.0


@pytest.mark.parametrize("mode", ["NER", "TAR"])
def test_director_blocks_while_a_regulating_federate_lags(federation: Join, join_de: JoinDE, mode: str) -> None:
    """A regulating peer stays at 0 with lookahead 1, so LBTS is 1: the director fires nothing at or past the
    time it cannot be granted, until the peer advances."""
    director = join_de("de", mode=mode, step=1.0, lookahead=0.1)
    source = TimedSource("source", [(0.5, "a"), (1.5, "b")])
    probe = Probe()
    source.output.connect(probe.input)
    director.add(source, probe)
    director.initialize()
    peer = federation("peer")
    peer.enable_time(lookahead=1.0, constrained=True)
    assert director.rtia.queryLBTS() == 1.0

    director.grant_timeout = 0.3
    if mode == "NER":
        director.step()  # NER(0.5) is granted: 0.5 < LBTS
        director.step()  # the probe at 0.5
        assert [t for t, *_ in probe.seen] == [0.5]
    with pytest.raises(TimeoutError):
        director.run(until=2.0)  # NER(1.5) or TAR(1.0): not below LBTS 1
    assert director.pending_request == (1.5 if mode == "NER" else 1.0)
    assert director.grants == ([0.5] if mode == "NER" else [])
    assert [t for t, *_ in probe.seen] == ([0.5] if mode == "NER" else [])
    assert director.now == (0.5 if mode == "NER" else 0.0)

    peer.rtia.timeAdvanceRequest(5.0)  # its bound becomes 6: the pending request is granted
    director.grant_timeout = 10.0
    director.run(until=2.0)
    assert director.grants == ([0.5, 1.5, 2.0] if mode == "NER" else [1.0, 2.0])
    assert [t for t, *_ in probe.seen] == [0.5, 1.5]
    assert probe.never_past_grant()


def test_two_directors_in_lockstep_exchange_timestamped_updates(join_de: JoinDE) -> None:
    """An NER director publishes its clock at t + lookahead; a TAR director (step 1) fires each reflection at
    its timestamp, after the grid point that covers it. Each runs in its own thread and blocks on the other."""
    sender = join_de("sender", mode="NER", lookahead=0.5)
    receiver = join_de("receiver", mode="TAR", step=1.0, lookahead=0.5)
    clock = Clock("clock", period=1.0, cycles=5)
    publisher = ObjectPublisher("publisher", "robot", {"location": omt.HLAinteger32BE}, instance_name="bot")
    clock.output.connect(publisher.ports["location"])
    sender.add(clock, publisher)
    subscriber = ObjectSubscriber("subscriber", "robot", {"location": omt.HLAinteger32BE}, instance_name="bot")
    probe, received = Probe(), Recorder("received")
    subscriber.ports["location"].connect(probe.input)
    subscriber.received.connect(received.input)
    receiver.add(subscriber, probe, received)
    receiver.initialize()
    sender.initialize()
    barrier(receiver.rtia)

    errors: list[BaseException] = []

    def run(director: HlaDirector) -> None:
        try:
            director.run(until=6.0)
        except BaseException as e:  # reported by the main thread
            errors.append(e)

    threads = [threading.Thread(target=run, args=(d,)) for d in (sender, receiver)]
    for thread in threads:
        thread.start()
    for thread in threads:
        thread.join(30)
    assert not errors, errors
    assert not any(t.is_alive() for t in threads)

    assert publisher.sent == [0.5, 1.5, 2.5, 3.5, 4.5]
    assert sender.grants == [1.0, 2.0, 3.0, 4.0, 6.0]
    assert receiver.grants == [1.0, 2.0, 3.0, 4.0, 5.0, 6.0]
    assert [(t, v, g) for t, _, g, v in probe.seen] == [(k + 0.5, k, k + 1.0) for k in range(5)]
    records: list[Received] = received.values
    assert [(r.source, r.timestamp, r.time, r.values) for r in records] == [
        ("bot", k + 0.5, k + 0.5, {"location": k}) for k in range(5)
    ]
    assert {r.tag for r in records} == {"publisher"}


def test_interactions_fire_at_their_timestamps_and_receive_order_ones_at_the_current_time(
    federation: Join, join_de: JoinDE
) -> None:
    director = join_de("de", mode="NER", lookahead=0.1)
    commands = InteractionReceiver("commands", "command", {"name": None, "value": F64})
    replies = InteractionReceiver("replies", "reply", ["value"])
    local = TimedSource("local", [(1.0, "one"), (4.0, "four")])
    probe, log = Probe(), Recorder("log")
    for port in (commands.received, replies.received, local.output):
        port.connect(probe.input)
    commands.ports["value"].connect(log.input)
    director.add(commands, replies, local, probe, log)
    director.initialize()

    peer = federation("peer")
    command = peer.rtia.getInteractionClassHandle("command")
    reply = peer.rtia.getInteractionClassHandle("reply")
    name, value = (peer.rtia.getParameterHandle(p, command) for p in ("name", "value"))
    reply_value = peer.rtia.getParameterHandle("value", reply)
    peer.rtia.publishInteractionClass(command)
    peer.rtia.publishInteractionClass(reply)
    peer.enable_time(lookahead=1.0, constrained=False)
    barrier(director.rtia)
    peer.rtia.sendInteraction(command, {name: b"go", value: F64.pack(7.0)}, "peer", 2.5)
    peer.rtia.sendInteraction(reply, {reply_value: b"pong"}, "peer")
    assert peer.rtia.advance_to(10.0, timeout=5.0) == 10.0
    barrier(peer.rtia)

    director.run(until=5.0)
    assert director.grants == [1.0, 2.5, 4.0, 5.0]
    out = [(t, m, v if isinstance(v, str) else (v.source, v.timestamp, v.values)) for t, m, _, v in probe.seen]
    assert out == [
        (0.0, 0, ("reply", None, {"value": b"pong"})),  # receive order: at the time it arrived (0)
        (1.0, 0, "one"),
        (2.5, 0, ("command", 2.5, {"name": b"go", "value": 7.0})),
        (4.0, 0, "four"),
    ]
    assert [(r.time, r.value) for r in log.records] == [(2.5, 7.0)]
    assert probe.never_past_grant()


def test_publishers_of_one_instance_share_it_and_subscribers_filter_instances(
    federation: Join, join_de: JoinDE
) -> None:
    """Two publishers with one instance name register one object whose updates carry both attributes' times;
    a subscriber with an instance name ignores the other instances."""
    director = join_de("de", mode="NER", lookahead=0.25)
    location = ObjectPublisher("location", "robot", {"location": F64}, instance_name="shared")
    battery = ObjectPublisher("battery", "robot", {"battery": F64}, instance_name="shared")
    source = TimedSource("source", [(1.0, 1.0), (2.0, 2.0)])
    source.output.connect(location.ports["location"], battery.ports["battery"])
    only_r2 = ObjectSubscriber("only_r2", "robot", {"sensor1": F64}, instance_name="r2")
    seen = Recorder("seen")
    only_r2.ports["sensor1"].connect(seen.input)
    director.add(location, battery, source, only_r2, seen)
    director.initialize()
    assert location.object == battery.object is not None

    peer = federation("peer")
    robot = peer.rtia.getObjectClassHandle("robot")
    handles = {n: peer.rtia.getAttributeHandle(n, robot) for n in ("location", "battery", "sensor1")}
    peer.rtia.subscribeObjectClassAttributes(robot, [handles["location"], handles["battery"]])
    peer.rtia.publishObjectClass(robot, [handles["sensor1"]])
    peer.enable_time(lookahead=1.0, constrained=True)
    barrier(director.rtia)
    r1 = peer.rtia.registerObjectInstance(robot, "r1")
    r2 = peer.rtia.registerObjectInstance(robot, "r2")
    peer.rtia.updateAttributeValues(r1, {handles["sensor1"]: F64.pack(1.0)}, "", 1.5)
    peer.rtia.updateAttributeValues(r2, {handles["sensor1"]: F64.pack(2.0)}, "", 1.5)
    peer.rtia.timeAdvanceRequest(3.0)  # granted once the director is past 3 - its lookahead

    director.run(until=3.0)
    assert peer.rtia.await_grant(5.0) == 3.0
    assert [(r.time, r.value) for r in seen.records] == [(1.5, 2.0)]
    discovered = peer.amb.named("discoverObjectInstance")
    assert [(args[0], args[2]) for args in discovered] == [(location.object, "shared")]
    reflections = [(args[5], set(args[1])) for args in peer.amb.named("reflectAttributeValues")]
    assert reflections == [
        (1.25, {handles["location"]}),
        (1.25, {handles["battery"]}),
        (2.25, {handles["location"]}),
        (2.25, {handles["battery"]}),
    ]


def test_the_examples_in_docs_de_md_run() -> None:
    """Every python block of docs/de.md runs as written (they end in asserts)."""
    text = (ROOT / "docs" / "de.md").read_text()
    blocks = re.findall(r"```python\n(.*?)```", text, re.S)
    assert len(blocks) == 2
    for block in blocks:
        exec(compile(block, "docs/de.md", "exec"), {})
