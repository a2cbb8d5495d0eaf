"""The scripted federations that several test modules run: two well-behaved federates beside hostile
clients (`Legit`), a best-effort pair (`Pair`), a federation over TLS or any transport (`run_federation`), and
the handles of tests/data/ddm.fed (`Fom`)."""

from __future__ import annotations

import contextlib
import time
from dataclasses import dataclass, field
from typing import Any, Iterator

from hlacore import rti

from support import DATA, ROBOT_FED, Federate, joined_federation, share_robot_location, tick_until

# ---- two well-behaved federates beside hostile ones ----


@dataclass
class Legit:
    address: str
    creator: rti.RTIAmbassador
    alice: Federate
    bob: Federate
    robot: Any
    battery: Any
    location: Any
    command: Any
    value: Any
    probes: int = 0
    objects: list[Any] = field(default_factory=list)

    def check_working(self) -> None:
        """alice registers, updates and sends; bob discovers, reflects and receives."""
        self.probes += 1
        n = self.probes
        alice, bob = self.alice, self.bob
        obj = alice.rtia.registerObjectInstance(self.robot, f"probe-{n}")
        self.objects.append(obj)
        tick_until(lambda: any(a[2] == f"probe-{n}" for a in bob.amb.named("discoverObjectInstance")), alice.rtia, bob.rtia)
        alice.rtia.updateAttributeValues(obj, {self.battery: b"battery-%d" % n}, "probe")
        tick_until(
            lambda: any(a[0] == obj and a[1].get(self.battery) == b"battery-%d" % n for a in bob.amb.named("reflectAttributeValues")),
            alice.rtia,
            bob.rtia,
        )
        alice.rtia.sendInteraction(self.command, {self.value: b"command-%d" % n}, "probe")
        tick_until(
            lambda: any(a[1].get(self.value) == b"command-%d" % n for a in bob.amb.named("receiveInteraction")),
            alice.rtia,
            bob.rtia,
        )

    def handles(self) -> tuple[int, int, int]:
        return int(self.robot), int(self.battery), int(self.location)


@contextlib.contextmanager
def legit_federation(address: str) -> Iterator[Legit]:
    """Creates TestFed with alice (publishes robot battery+location and command) and bob (subscribes to
    robot battery and to command); resigns them and destroys TestFed afterwards."""
    creator = rti.RTIAmbassador(address)
    creator.createFederationExecution("TestFed", ROBOT_FED)
    alice = Federate(address, "alice")
    bob = Federate(address, "bob")
    robot = alice.rtia.getObjectClassHandle("robot")
    battery = alice.rtia.getAttributeHandle("battery", robot)
    location = alice.rtia.getAttributeHandle("location", robot)
    command = alice.rtia.getInteractionClassHandle("command")
    value = alice.rtia.getParameterHandle("value", command)
    alice.rtia.publishObjectClass(robot, [battery, location])
    alice.rtia.publishInteractionClass(command)
    bob.rtia.subscribeObjectClassAttributes(robot, [battery])
    bob.rtia.subscribeInteractionClass(command)
    legit = Legit(address, creator, alice, bob, robot, battery, location, command, value)
    legit.check_working()
    try:
        yield legit
    finally:
        for fed in (alice, bob):
            try:
                fed.rtia.resignFederationExecution(rti.ResignAction.DeleteObjectsAndReleaseAttributes)
            except rti.FederateNotExecutionMember:
                pass
        creator.destroyFederationExecution("TestFed")


# ---- alice and bob, with best-effort and reliable classes (datagrams) ----


class Catcher(rti.FederateAmbassador):
    def __init__(self) -> None:
        self.interactions: list[tuple[Any, dict[Any, bytes], Any]] = []  # class, parameters, transport
        self.reflections: list[tuple[dict[Any, bytes], Any]] = []  # values, transport
        self.discovered: list[str] = []

    def discoverObjectInstance(self, obj: Any, cls: Any, name: str) -> None:
        self.discovered.append(name)

    def receiveInteraction(self, cls: Any, parameters: dict[Any, bytes], tag: str, order: Any = None,
                           transport: Any = None, *rest: Any) -> None:
        self.interactions.append((cls, parameters, transport))

    def reflectAttributeValues(self, obj: Any, attributes: dict[Any, bytes], tag: str, order: Any = None,
                               transport: Any = None, *rest: Any) -> None:
        self.reflections.append((attributes, transport))


class Pair:
    """alice publishes turtlebot.sonar (best effort) and location (reliable), and the reply (best effort)
    and command (reliable) interactions; bob subscribes to all of them."""

    def __init__(self, address: str, **options: Any) -> None:
        self.creator = rti.RTIAmbassador(address, **options)
        self.creator.createFederationExecution("TestFed", ROBOT_FED)
        self.alice, self.bob = rti.RTIAmbassador(address, **options), rti.RTIAmbassador(address, **options)
        self.alice_amb, self.bob_amb = Catcher(), Catcher()
        self.alice.joinFederationExecution("alice", "TestFed", self.alice_amb)
        self.bob.joinFederationExecution("bob", "TestFed", self.bob_amb)
        a = self.alice
        self.turtlebot = a.getObjectClassHandle("turtlebot")
        self.sonar = a.getAttributeHandle("sonar", self.turtlebot)
        self.location = a.getAttributeHandle("location", self.turtlebot)
        self.reply = a.getInteractionClassHandle("reply")
        self.value = a.getParameterHandle("value", self.reply)
        self.command = a.getInteractionClassHandle("command")
        self.name = a.getParameterHandle("name", self.command)
        a.publishObjectClass(self.turtlebot, [self.sonar, self.location])
        a.publishInteractionClass(self.reply)
        a.publishInteractionClass(self.command)
        self.bob.subscribeObjectClassAttributes(self.turtlebot, [self.sonar, self.location])
        self.bob.subscribeInteractionClass(self.reply)
        self.bob.subscribeInteractionClass(self.command)
        self.obj = a.registerObjectInstance(self.turtlebot, "t1")
        self.wait(lambda: self.bob_amb.discovered == ["t1"])

    def wait(self, done: Any, timeout: float = 10.0) -> None:
        deadline = time.monotonic() + timeout
        while not done():
            assert time.monotonic() < deadline, "timed out"
            self.bob.tick(0.01, 0.05)
            self.alice.tick(0.0, 0.01)

    def close(self) -> None:
        for fed in (self.alice, self.bob):
            fed.resignFederationExecution(rti.ResignAction.DeleteObjectsAndReleaseAttributes)
        self.creator.destroyFederationExecution("TestFed")


@contextlib.contextmanager
def pair(address: str, **options: Any) -> Iterator[Pair]:
    p = Pair(address, **options)
    try:
        yield p
    finally:
        p.close()


# ---- a federation of its own, over any transport (TLS, a Unix socket) ----

FEDERATION = "SecretLabFederation"
VALUE = b"attribute-value-only-the-federates-read"


def run_federation(address: str, tls: Any, value: bytes = VALUE) -> dict[str, Any]:
    """Two federates: join, publish/subscribe, an update reflected, a best-effort interaction received, a TSO
    advance; returns what the subscriber saw and the datagram status. Every connection with `tls`."""
    with joined_federation(address, FEDERATION, ROBOT_FED,
                           lambda address, name: Federate(address, name, FEDERATION, tls=tls), tls=tls) as join:
        alice, bob = join("alice"), join("bob")
        robot, location = share_robot_location(alice, bob)
        reply = alice.rtia.getInteractionClassHandle("reply")
        reply_value = alice.rtia.getParameterHandle("value", reply)
        alice.rtia.publishInteractionClass(reply)
        bob.rtia.subscribeInteractionClass(reply)
        obj = alice.rtia.registerObjectInstance(robot)
        alice.rtia.updateAttributeValues(obj, {location: value}, "tag")
        seen = bob.amb
        tick_until(lambda: bool(seen.named("reflectAttributeValues")), bob.rtia, timeout=30)
        for i in range(5):  # best effort (the FED's reply class), no timestamp
            alice.rtia.sendInteraction(reply, {reply_value: b"best-effort %d" % i}, "")
        tick_until(lambda: len(seen.named("receiveInteraction")) == 5, bob.rtia)
        t = alice.rtia.enable_time_management(1.0, timeout=5.0)
        granted = alice.rtia.advance_to(t + 2.0, timeout=5.0)
        return {"reflected": seen.named("reflectAttributeValues")[0][1], "granted": granted, "start": t,
                "interactions": [args[1] for args in seen.named("receiveInteraction")],
                "alice_datagrams": alice.rtia.datagram_status(), "bob_datagrams": bob.rtia.datagram_status()}


def check_federation(result: dict[str, Any], value: bytes = VALUE) -> None:
    assert list(result["reflected"].values()) == [value]
    assert result["granted"] == result["start"] + 2.0
    assert sorted(v for p in result["interactions"] for v in p.values()) == [b"best-effort %d" % i for i in range(5)]


# ---- tests/data/ddm.fed ----

DDM_FED = str(DATA / "ddm.fed")


@dataclass
class Fom:
    """The handles of ddm.fed."""

    geo: Any
    x: Any
    y: Any
    band: Any
    frequency: Any
    vehicle: Any
    truck: Any
    position: Any
    speed: Any
    channel: Any
    name: Any
    radio: Any
    text: Any
    alarm: Any
    level: Any
    broadcast: Any
    broadcast_text: Any


def fom_of(rtia: rti.RTIAmbassador) -> Fom:
    geo, band = rtia.getRoutingSpaceHandle("Geo"), rtia.getRoutingSpaceHandle("Band")
    vehicle, radio = rtia.getObjectClassHandle("vehicle"), rtia.getInteractionClassHandle("radio")
    alarm, broadcast = rtia.getInteractionClassHandle("alarm"), rtia.getInteractionClassHandle("broadcast")
    return Fom(
        geo, rtia.getDimensionHandle("X", geo), rtia.getDimensionHandle("Y", geo),
        band, rtia.getDimensionHandle("Frequency", band),
        vehicle, rtia.getObjectClassHandle("truck"),
        *(rtia.getAttributeHandle(n, vehicle) for n in ("position", "speed", "channel", "name")),
        radio, rtia.getParameterHandle("text", radio), alarm, rtia.getParameterHandle("level", alarm),
        broadcast, rtia.getParameterHandle("text", broadcast),
    )
