"""hlacore-rtia (docs/certi.md): CERTI's federate protocol served over hlacore's client, driven by a federate of
ours that speaks that protocol (tests/support/certi.py), in both byte orders, started as CERTI's libRTI starts
it (a socket pair) and as JCERTI does (a TCP port), against the rtig under test."""

from __future__ import annotations

import math
import pathlib
import subprocess
import sys
import threading
from typing import Iterator, Optional

import pytest

import hlacore.rti as rti
from hlacore.status import status
from support import DATA, ROBOT_FED, RtigProcess, rtia_executable
from support.certi import CertiError, CertiFederate, Message, encode

ORDERS = [pytest.param(True, id="big-endian"), pytest.param(False, id="little-endian")]


class Certi:
    """Starts CertiFederates against one rtig, each with its rtia's stderr in tmp_path; ends them all."""

    def __init__(self, server: RtigProcess, tmp_path: pathlib.Path) -> None:
        host, port = server.address.rsplit(":", 1)
        self.env = {"CERTI_HOST": host, "CERTI_TCP_PORT": port, "HLACORE_RTIG": ""}  # CERTI's variables name it
        self.address = server.address
        self.tmp_path = tmp_path
        self.started: list[CertiFederate] = []

    def federate(self, big_endian: bool, via: str = "socketpair", open: bool = True,
                 env: Optional[dict[str, str]] = None) -> CertiFederate:
        f = CertiFederate(rtia_executable(), big_endian, {**self.env, **(env or {})}, via=via,
                          stderr=self.tmp_path / f"rtia-{len(self.started)}.log")
        self.started.append(f)
        if open:
            f.open()
        return f

    def joined(self, big_endian: bool, name: str, via: str = "socketpair") -> CertiFederate:
        f = self.federate(big_endian, via)
        f.call("JOIN_FEDERATION_EXECUTION", federation="TestFed", federate_name=name)
        return f

    def close(self) -> None:
        for f in self.started:
            f.__exit__()
        assert all(f.proc.returncode is not None for f in self.started)  # no rtia left behind


@pytest.fixture
def certi(rtig: RtigProcess, tmp_path: pathlib.Path) -> Iterator[Certi]:
    c = Certi(rtig, tmp_path)
    try:
        yield c
    finally:
        c.close()


def handles(f: CertiFederate) -> dict[str, int]:
    robot = f.call("GET_OBJECT_CLASS_HANDLE", name="robot").object_class
    command = f.call("GET_INTERACTION_CLASS_HANDLE", name="command").interaction_class
    return {"robot": robot, "location": f.call("GET_ATTRIBUTE_HANDLE", object_class=robot, name="location").attribute,
            "command": command, "value": f.call("GET_PARAMETER_HANDLE", interaction_class=command, name="value").parameter}


def of_type(kind: str):  # type: ignore[no-untyped-def]
    return lambda seen: any(m.type == kind for m in seen)


@pytest.mark.parametrize("big_endian", ORDERS)
def test_the_opening_handshake_and_a_wrong_version(certi: Certi, big_endian: bool) -> None:
    f = certi.federate(big_endian, open=False)
    with pytest.raises(CertiError) as refused:
        f.call("JOIN_FEDERATION_EXECUTION", federation="TestFed", federate_name="early")
    assert refused.value.name == "RTIinternalError" and "OPEN_CONNEXION" in refused.value.reason
    with pytest.raises(CertiError) as wrong:
        f.call("OPEN_CONNEXION", version_major=2, version_minor=0)
    assert wrong.value.name == "RTIinternalError" and "speaks 1.0" in wrong.value.reason
    answer = f.open()
    assert (answer.version_major, answer.version_minor) == (1, 0)
    assert f.close() == 0


@pytest.mark.parametrize("via", ["socketpair", "tcp"])
def test_two_federates_in_each_byte_order_exchange_updates_and_interactions(certi: Certi, via: str) -> None:
    """One federate big-endian, the other little-endian: create, join, publish, subscribe, register, discover,
    an update and an interaction in receive order, then timestamped ones delivered at the grant, resign, destroy."""
    a = certi.federate(True, via)
    a.call("CREATE_FEDERATION_EXECUTION", federation="TestFed", fed=ROBOT_FED)
    a_handle = a.call("JOIN_FEDERATION_EXECUTION", federation="TestFed", federate_name="a").federate
    assert a_handle >= 1
    b = certi.joined(False, "b", via)
    h = handles(a)
    assert handles(b) == h
    # created through the rtia: CERTI's reading of the time rules (docs/time-management.md)
    assert status(certi.address)["federations"][0]["time_semantics"] == "certi"
    a.call("PUBLISH_OBJECT_CLASS", object_class=h["robot"], handles=[h["location"]])
    a.call("PUBLISH_INTERACTION_CLASS", interaction_class=h["command"])
    b.call("SUBSCRIBE_OBJECT_CLASS_ATTRIBUTES", object_class=h["robot"], handles=[h["location"]], flag=True)
    b.call("SUBSCRIBE_INTERACTION_CLASS", interaction_class=h["command"])
    obj = a.call("REGISTER_OBJECT_INSTANCE", object_class=h["robot"], name="r1").object
    assert a.call("GET_OBJECT_INSTANCE_NAME", object=obj).name == "r1"
    seen = b.tick_until(of_type("DISCOVER_OBJECT_INSTANCE"))
    discovered = next(m for m in seen if m.type == "DISCOVER_OBJECT_INSTANCE")
    assert (discovered.object, discovered.object_class, discovered.name) == (obj, h["robot"], "r1")

    a.call("UPDATE_ATTRIBUTE_VALUES", object=obj, handles=[h["location"]], values=[b"x=1\x00y=2"], tag="moved")
    a.call("SEND_INTERACTION", interaction_class=h["command"], handles=[h["value"]], values=[b"go"], tag="now")
    seen = b.tick_until(lambda s: of_type("REFLECT_ATTRIBUTE_VALUES")(s) and of_type("RECEIVE_INTERACTION")(s))
    reflect = next(m for m in seen if m.type == "REFLECT_ATTRIBUTE_VALUES")
    assert (reflect.object, reflect.handles, reflect.values, reflect.tag, reflect.date) == \
        (obj, [h["location"]], [b"x=1\x00y=2"], "moved", None)
    interaction = next(m for m in seen if m.type == "RECEIVE_INTERACTION")
    assert (interaction.interaction_class, interaction.values, interaction.tag) == (h["command"], [b"go"], "now")

    # Timestamp order: a regulating (lookahead 1), b constrained; b's grant at 5 brings a's update at 3.
    a.call("ENABLE_TIME_REGULATION", date=0.0, lookahead=1.0)
    a.tick_until(of_type("TIME_REGULATION_ENABLED"))
    b.call("ENABLE_TIME_CONSTRAINED")
    b.tick_until(of_type("TIME_CONSTRAINED_ENABLED"))
    sent = a.call("UPDATE_ATTRIBUTE_VALUES", object=obj, handles=[h["location"]], values=[b"at 3"], tag="ts", date=3.0)
    assert sent.date == 3.0 and sent.retraction is not None and sent.retraction[0] == a_handle
    a.call("TIME_ADVANCE_REQUEST", date=10.0)
    b.call("TIME_ADVANCE_REQUEST", date=5.0)
    seen = b.tick_until(of_type("TIME_ADVANCE_GRANT"))
    timed = [m for m in seen if m.type == "REFLECT_ATTRIBUTE_VALUES"]
    assert [(m.values, m.date, m.tag) for m in timed] == [([b"at 3"], 3.0, "ts")]
    assert seen[-1].type == "TIME_ADVANCE_GRANT" and seen[-1].date == 5.0
    assert b.call("QUERY_FEDERATE_TIME").date == 5.0
    assert a.call("QUERY_LOOKAHEAD").lookahead == 1.0

    a.call("DELETE_OBJECT_INSTANCE", object=obj, tag="bye")
    b.call("ENABLE_ASYNCHRONOUS_DELIVERY")  # receive order reaches a constrained federate between its advances
    removed = next(m for m in b.tick_until(of_type("REMOVE_OBJECT_INSTANCE")) if m.type == "REMOVE_OBJECT_INSTANCE")
    assert (removed.object, removed.tag) == (obj, "bye")
    b.call("RESIGN_FEDERATION_EXECUTION", resign_action=3)
    a.call("RESIGN_FEDERATION_EXECUTION", resign_action=3)
    a.call("DESTROY_FEDERATION_EXECUTION", federation="TestFed")
    assert a.close() == 0 and b.close() == 0


def created(certi: Certi, big_endian: bool, name: str) -> CertiFederate:
    f = certi.federate(big_endian)
    f.call("CREATE_FEDERATION_EXECUTION", federation="TestFed", fed=ROBOT_FED)
    f.call("JOIN_FEDERATION_EXECUTION", federation="TestFed", federate_name=name)
    return f


@pytest.mark.parametrize("big_endian", ORDERS)
def test_a_1000_step_lockstep_with_a_python_federate(certi: Certi, rtig: RtigProcess, big_endian: bool) -> None:
    """A CERTI federate and an hlacore Python federate, both regulating and constrained with lookahead 1, each
    updating its robot's location at t + 1 and asking to advance there: 1 000 steps, each grant preceded by
    the other's update of that step."""
    steps = 1000
    c = created(certi, big_endian, "certi")
    h = handles(c)
    c.call("PUBLISH_OBJECT_CLASS", object_class=h["robot"], handles=[h["location"]])
    c.call("SUBSCRIBE_OBJECT_CLASS_ATTRIBUTES", object_class=h["robot"], handles=[h["location"]], flag=True)
    mine = c.call("REGISTER_OBJECT_INSTANCE", object_class=h["robot"], name="certi").object
    report: dict[str, object] = {}
    ready, go = threading.Event(), threading.Event()  # both enabled before either steps

    def python_federate() -> None:
        class Amb(rti.FederateAmbassador):
            def __init__(self) -> None:
                self.values: set[bytes] = set()

            def reflectAttributeValues(self, obj, attributes, *rest):  # type: ignore[no-untyped-def]
                self.values.update(attributes.values())

        amb = Amb()
        p = rti.RTIAmbassador(rtig.address)
        p.joinFederationExecution("python", "TestFed", amb)
        robot = p.getObjectClassHandle("robot")
        location = p.getAttributeHandle("location", robot)
        p.publishObjectClass(robot, [location])
        p.subscribeObjectClassAttributes(robot, [location])
        obj = p.registerObjectInstance(robot, "python")
        base = p.enable_time_management(1.0)
        report["base"] = base
        ready.set()
        assert go.wait(30)
        late = 0
        for t in range(1, steps + 1):
            p.updateAttributeValues(obj, {location: str(t).encode()}, "", base + t)
            p.advance_to(base + t, timeout=30.0)
            late += str(t).encode() not in amb.values
        report.update(late=late)
        p.resignFederationExecution(rti.ResignAction.DeleteObjectsAndReleaseAttributes)

    peer = threading.Thread(target=python_federate)
    peer.start()
    try:
        assert ready.wait(30)
        c.call("ENABLE_TIME_REGULATION", date=0.0, lookahead=1.0)
        base = c.tick_until(of_type("TIME_REGULATION_ENABLED"))[-1].date
        c.call("ENABLE_TIME_CONSTRAINED")
        c.tick_until(of_type("TIME_CONSTRAINED_ENABLED"))
        go.set()
        assert base == report["base"]
        late = 0
        for t in range(1, steps + 1):
            c.call("UPDATE_ATTRIBUTE_VALUES", object=mine, handles=[h["location"]], values=[str(t).encode()], tag="",
                   date=base + t)
            c.call("TIME_ADVANCE_REQUEST", date=base + t)
            seen = c.tick_until(of_type("TIME_ADVANCE_GRANT"))
            assert seen[-1].date == base + t
            late += not any(m.type == "REFLECT_ATTRIBUTE_VALUES" and m.values == [str(t).encode()] for m in seen)
    finally:
        peer.join(timeout=120)
    assert not peer.is_alive()
    assert report["late"] == 0 and late == 0
    c.call("RESIGN_FEDERATION_EXECUTION", resign_action=3)
    assert c.close() == 0


def test_synchronization_points_and_a_save_and_restore(certi: Certi) -> None:
    a = created(certi, True, "a")
    b = certi.joined(False, "b")
    a.call("REGISTER_FEDERATION_SYNCHRONIZATION_POINT", label="ready", tag="go", handles=[])
    a_seen = a.tick_until(lambda s: of_type("SYNCHRONIZATION_POINT_REGISTRATION_SUCCEEDED")(s)
                          and of_type("ANNOUNCE_SYNCHRONIZATION_POINT")(s))
    announced = next(m for m in a_seen if m.type == "ANNOUNCE_SYNCHRONIZATION_POINT")
    assert (announced.label, announced.tag) == ("ready", "go")
    b.tick_until(of_type("ANNOUNCE_SYNCHRONIZATION_POINT"))
    for f in (a, b):
        f.call("SYNCHRONIZATION_POINT_ACHIEVED", label="ready")
    for f in (a, b):
        done = f.tick_until(of_type("FEDERATION_SYNCHRONIZED"))
        assert done[-1].label == "ready"

    a.call("REQUEST_FEDERATION_SAVE", label="s1")
    for f in (a, b):
        assert f.tick_until(of_type("INITIATE_FEDERATE_SAVE"))[-1].label == "s1"
        f.call("FEDERATE_SAVE_BEGUN")
        f.call("FEDERATE_SAVE_COMPLETE")
    for f in (a, b):
        f.tick_until(of_type("FEDERATION_SAVED"))

    a.call("REQUEST_FEDERATION_RESTORE", label="s1")
    assert a.tick_until(of_type("REQUEST_FEDERATION_RESTORE_SUCCEEDED"))[-1].label == "s1"
    for f in (a, b):
        seen = f.tick_until(of_type("INITIATE_FEDERATE_RESTORE"))
        assert seen[-1].label == "s1" and seen[-1].federate >= 1
        f.call("FEDERATE_RESTORE_COMPLETE")
    for f in (a, b):
        f.tick_until(of_type("FEDERATION_RESTORED"))
    a.call("REQUEST_FEDERATION_RESTORE", label="never saved")
    failed = a.tick_until(of_type("REQUEST_FEDERATION_RESTORE_FAILED"))[-1]
    assert failed.label == "never saved" and failed.tag == failed.fields["reason"] and "no save" in failed.tag


def test_exceptions_come_back_by_certi_name(certi: Certi) -> None:
    a = created(certi, False, "a")
    with pytest.raises(CertiError) as e:
        a.call("GET_OBJECT_CLASS_HANDLE", name="no such class")
    assert e.value.name == "NameNotFound"
    with pytest.raises(CertiError) as e:
        a.call("CREATE_FEDERATION_EXECUTION", federation="TestFed", fed=ROBOT_FED)
    assert e.value.name == "FederationExecutionAlreadyExists"
    with pytest.raises(CertiError) as e:
        a.call("UPDATE_ATTRIBUTE_VALUES", object=12345, handles=[1], values=[b"v"])
    assert e.value.name == "ObjectNotKnown"
    assert a.call("GET_TRANSPORTATION_HANDLE", name="HLAbestEffort").transport == 2
    assert a.call("GET_ORDERING_NAME", order=2).name == "Timestamp"
    with pytest.raises(CertiError) as e:
        a.call("GET_TRANSPORTATION_HANDLE", name="fast")
    assert e.value.name == "NameNotFound"
    with pytest.raises(CertiError) as e:
        a.call("GET_ORDERING_NAME", order=9)
    assert e.value.name == "InvalidOrderingHandle"
    with pytest.raises(CertiError) as e:
        a.call("DDM_CREATE_REGION", space=1, extent_count=1)
    assert e.value.name == "RTIinternalError" and "DDM" in e.value.reason
    with pytest.raises(CertiError) as e:
        a.call("RESIGN_FEDERATION_EXECUTION", resign_action=9)
    assert e.value.name == "InvalidResignAction"
    with pytest.raises(CertiError) as e:
        a.call("RESIGN_FEDERATION_EXECUTION", resign_action=257)  # not 1 once cut to a byte
    assert e.value.name == "InvalidResignAction"
    other = certi.federate(True)
    with pytest.raises(CertiError) as e:
        other.call("JOIN_FEDERATION_EXECUTION", federation="Nowhere", federate_name="x")
    assert e.value.name == "FederationExecutionDoesNotExist"
    with pytest.raises(CertiError) as e:
        other.call("CREATE_FEDERATION_EXECUTION", federation="Other", fed="missing.fed")
    assert e.value.name == "CouldNotOpenFED"


def test_tick_delivers_one_callback_at_a_time_as_certi_does(certi: Certi) -> None:
    """multiple=False: one callback, the answer saying more are pending; TICK_REQUEST_STOP ends a tick early; a
    tick from within a callback is refused (ConcurrentAccessAttempted) and the outer tick goes on; a callback
    may call services."""
    a = created(certi, True, "a")
    for label in ("p1", "p2", "p3"):
        a.call("REGISTER_FEDERATION_SYNCHRONIZATION_POINT", label=label, tag="", handles=[])
    a.call("QUERY_LBTS")  # answered by the gateway after the six callbacks, on the same connection
    got, more = a.tick(0.0, math.inf, multiple=False)
    assert len(got) == 1 and more

    def nested(m: Message) -> str:
        with pytest.raises(CertiError) as e:
            a.tick()
        assert e.value.name == "ConcurrentAccessAttempted"
        assert a.call("QUERY_FEDERATE_TIME").date == 0.0  # a service from within a callback
        return "stop"

    got, more = a.tick(0.0, math.inf, on_callback=nested)
    assert len(got) == 1 and more
    rest, more = a.tick(1.0, 1.0)
    assert rest and not more


@pytest.mark.parametrize("frame, why", [
    (b"\x07\x00\x00\x00\x10" + bytes(11), "byte-order flag 7"),
    (b"\x00\xff\xff\xff\x7f", "a frame length of"),
    (encode(Message("QUERY_LBTS"), False)[:5] + (999).to_bytes(4, "little") + bytes(7), "unknown message type 999"),
    (encode(Message("GET_OBJECT_CLASS_HANDLE", fields={"name": "robot"}), False)[:-3], "closed the connection within"),
], ids=["byte order", "length", "type", "truncated"])
def test_a_malformed_frame_ends_that_rtia_with_one_line_and_the_federation_goes_on(
        certi: Certi, rtig: RtigProcess, frame: bytes, why: str) -> None:
    a = created(certi, False, "a")
    b = certi.joined(True, "b")
    b.send_raw(frame)
    if why.startswith("closed"):
        b.sock.shutdown(2)
    assert b.wait() == 1
    log = b.stderr()
    assert why in log and log.count("\n") == 1, log
    assert "leaves as a dead federate" in log
    a.call("REGISTER_FEDERATION_SYNCHRONIZATION_POINT", label="after", tag="", handles=[])
    a.tick_until(of_type("ANNOUNCE_SYNCHRONIZATION_POINT"))  # synchronized without b: it is gone
    a.call("SYNCHRONIZATION_POINT_ACHIEVED", label="after")
    a.tick_until(of_type("FEDERATION_SYNCHRONIZED"))
    assert "dropped" in rtig.log()


@pytest.mark.parametrize("when", ["within a tick", "within a call"])
def test_a_federate_that_vanishes_is_dropped_and_others_go_on(certi: Certi, rtig: RtigProcess, when: str) -> None:
    a = created(certi, False, "a")
    b = certi.joined(True, "b")
    if when == "within a tick":
        b.send(Message("TICK_REQUEST", fields={"flag": True, "min_tick": 60.0, "max_tick": 60.0}))
    else:
        b.send(Message("QUERY_LBTS"))  # the federate dies before it reads the answer
    b.sock.close()
    assert b.wait() == 1
    assert ("hung up during its tick" if when == "within a tick" else "leaves as a dead federate") in b.stderr()
    a.call("RESIGN_FEDERATION_EXECUTION", resign_action=3)
    a.call("DESTROY_FEDERATION_EXECUTION", federation="TestFed")  # b is no longer joined
    assert "dropped" in rtig.log()


def test_the_installed_rtia_is_named_by_hlacore_config() -> None:
    found = subprocess.run([sys.executable, "-m", "hlacore.config", "--rtia"], capture_output=True, text=True,
                           timeout=30)
    assert found.returncode == 0, found.stderr
    rtia = found.stdout.strip()
    assert pathlib.Path(rtia).name == "hlacore-rtia" and pathlib.Path(rtia).is_file()
    usage = subprocess.run([rtia, "--help"], capture_output=True, text=True, timeout=30)
    assert usage.returncode == 0 and "-f FD" in usage.stdout and "-p PORT" in usage.stdout
    wrong = subprocess.run([rtia], capture_output=True, text=True, timeout=30)
    assert wrong.returncode == 2 and "usage: hlacore-rtia" in wrong.stderr


def test_jcertis_1516_create_and_join_with_an_xml_fom_module(certi: Certi, tmp_path: pathlib.Path) -> None:
    """JCERTI's IEEE 1516-2010 ambassador creates from FOM modules named by URL (one, or several merged), joins
    by federate type (also adding a module), and reserves object instance names."""
    module = tmp_path / "robots.xml"
    module.write_text("""<objectModel><objects><objectClass><name>HLAobjectRoot</name><objectClass><name>robot</name>
<attribute><name>location</name><transportation>HLAreliable</transportation><order>TimeStamp</order></attribute>
</objectClass></objectClass></objects></objectModel>""")
    f = certi.federate(True)
    f.call("CREATE_FEDERATION_EXECUTION_V4", federation="Evolved", rti_version=3, values=[f"file:{module}".encode()])
    assert status(certi.address)["federations"][0]["fed"] == str(module)
    joined = f.call("JOIN_FEDERATION_EXECUTION_V4", name=None, federate_type="ptolemy", rti_version=3,
                    federation="Evolved", values=[])
    assert joined.federate >= 1
    robot = f.call("GET_OBJECT_CLASS_HANDLE", name="HLAobjectRoot.robot").object_class
    assert f.call("GET_ATTRIBUTE_HANDLE", object_class=robot, name="location").attribute >= 1
    names = [m["name"] for m in status(certi.address)["federations"][0]["federates"]]
    assert len(names) == 1 and names[0].startswith("ptolemy-")
    # JCERTI's 1516e update writes a stray count after its last field: ignored, as CERTI ignores it
    f.call("PUBLISH_OBJECT_CLASS", object_class=robot, handles=[1])
    obj = f.call("REGISTER_OBJECT_INSTANCE", object_class=robot, name="r").object
    update = encode(Message("UPDATE_ATTRIBUTE_VALUES", tag="", fields={"object": obj, "handles": [1], "values": [b"v"]}), True)
    f.send_raw(update[:1] + (len(update) + 4).to_bytes(4, "big") + update[5:] + (1).to_bytes(4, "big"))
    answer = f.receive()
    assert answer.type == "UPDATE_ATTRIBUTE_VALUES" and not answer.exception, answer.reason
    for name in ("r", "HLAobject_9", "r2"):  # held by the object, the RTI's, free
        f.call("RESERVE_OBJECT_INSTANCE_NAME", name=name)
    reserved = f.tick_until(lambda s: len([m for m in s if m.type.startswith("RESERVE_OBJECT_INSTANCE_NAME_")]) == 3)
    assert [(m.type[len("RESERVE_OBJECT_INSTANCE_NAME_"):], m.name) for m in reserved if m.type.startswith("RESERVE")] == [
        ("FAILED", "r"), ("FAILED", "HLAobject_9"), ("SUCCEEDED", "r2")]
    cars = tmp_path / "cars.xml"
    cars.write_text("""<objectModel><objects><objectClass><name>HLAobjectRoot</name><objectClass><name>robot</name>
<objectClass><name>car</name></objectClass></objectClass></objectClass></objects></objectModel>""")
    # Another JCERTI federate joins adding the Cars module: the first finds its class once its rtia has read what
    # the gateway sent (a tick), the classes it knew unchanged.
    g = certi.federate(True)
    g.call("JOIN_FEDERATION_EXECUTION_V4", name="adder", federate_type="ptolemy", rti_version=3, federation="Evolved",
           values=[f"file:{cars}".encode()])
    car = g.call("GET_OBJECT_CLASS_HANDLE", name="HLAobjectRoot.robot.car").object_class
    f.tick(0.2, 0.5)
    assert f.call("GET_OBJECT_CLASS_HANDLE", name="HLAobjectRoot.robot.car").object_class == car
    assert f.call("GET_OBJECT_CLASS_HANDLE", name="HLAobjectRoot.robot").object_class == robot
    g.call("RESIGN_FEDERATION_EXECUTION", resign_action=3)
    assert g.close() == 0
    f.call("CREATE_FEDERATION_EXECUTION_V4", federation="Two", rti_version=3,
           values=[f"file://{module}".encode(), str(cars).encode()])
    assert [fed["fed"] for fed in status(certi.address)["federations"] if fed["name"] == "Two"] == [f"{module}, {cars}"]
    with pytest.raises(CertiError, match="CouldNotOpenFED.*missing.xml"):
        f.call("CREATE_FEDERATION_EXECUTION_V4", federation="Three", rti_version=3,
               values=[str(module).encode(), b"missing.xml"])
    f.call("RESIGN_FEDERATION_EXECUTION", resign_action=3)
    assert f.close() == 0


@pytest.mark.parametrize("where", ["CERTI_FOM_PATH", "CERTI_HOME"])
def test_the_fed_file_is_found_as_certi_finds_it(certi: Certi, tmp_path: pathlib.Path, where: str) -> None:
    """A bare name: the federate's directory, then each directory of $CERTI_FOM_PATH, then
    $CERTI_HOME/share/federations; the rtia reads it and the gateway gets its text."""
    if where == "CERTI_FOM_PATH":
        env = {"CERTI_FOM_PATH": f"{tmp_path / 'nowhere'}:{DATA}"}
    else:
        (tmp_path / "share" / "federations").mkdir(parents=True)
        (tmp_path / "share" / "federations" / "robot.fed").write_text(pathlib.Path(ROBOT_FED).read_text())
        env = {"CERTI_HOME": str(tmp_path)}
    f = certi.federate(False, env=env)
    f.call("CREATE_FEDERATION_EXECUTION", federation="Found", fed="robot.fed")
    federation = status(certi.address)["federations"][0]
    assert federation["fed"].endswith("/robot.fed") and federation["fed"] != "robot.fed"
    f.call("DESTROY_FEDERATION_EXECUTION", federation="Found")
    assert f.close() == 0


@pytest.mark.parametrize("trace", ["1", "counts"])
def test_the_trace_names_each_message_or_counts_them(certi: Certi, trace: str) -> None:
    f = certi.federate(True, env={"HLACORE_RTIA_TRACE": trace})
    with pytest.raises(CertiError):
        f.call("GET_OBJECT_CLASS_HANDLE", name="robot")  # not joined
    assert f.close() == 0
    log = f.stderr()
    if trace == "1":
        assert "hlacore-rtia: <- OPEN_CONNEXION\nhlacore-rtia: -> OPEN_CONNEXION\n" in log
        assert "hlacore-rtia: -> GET_OBJECT_CLASS_HANDLE FederateNotExecutionMember: " in log
    else:
        assert log.strip() == "hlacore-rtia: received OPEN_CONNEXION 1 CLOSE_CONNEXION 1 GET_OBJECT_CLASS_HANDLE 1"
