"""Declaration and object management: publish/subscribe, discovery, reflection, interactions, deletion,
attribute value update requests and the relevance advisories."""

import pytest

import hlacore.rti as rti

from support import barrier, settle, tick_until


@pytest.fixture
def pair(federation):
    """A publisher and a subscriber federate, with the robot class and its handles."""
    pub, sub = federation("publisher"), federation("subscriber")
    r = pub.rtia
    robot = r.getObjectClassHandle("robot")
    turtle = r.getObjectClassHandle("robot.turtlebot")
    h = {name: r.getAttributeHandle(name, robot) for name in ("location", "battery", "compass")}
    h["sonar"] = r.getAttributeHandle("sonar", turtle)
    return pub, sub, robot, turtle, h


@pytest.fixture
def registered(pair):
    """`pair` after the publisher published robot.location, the subscriber subscribed to it (a round trip
    later) and the publisher registered a robot, which the subscriber will discover: (pub, sub, h, object)."""
    pub, sub, robot, _turtle, h = pair
    pub.rtia.publishObjectClass(robot, [h["location"]])
    sub.rtia.subscribeObjectClassAttributes(robot, [h["location"]])
    barrier(sub.rtia)
    return pub, sub, h, pub.rtia.registerObjectInstance(robot)


def test_seed_fom_handles_follow_certi_numbering(federation):
    """ObjectRoot=1, RTIprivate=2, robot=3; privilegeToDelete=1 inherited; location is the 8th attribute."""
    r = federation("a").rtia
    assert [int(r.getObjectClassHandle(n)) for n in ("ObjectRoot", "RTIprivate", "robot")] == [1, 2, 3]
    robot = r.getObjectClassHandle("ObjectRoot.robot")
    assert int(r.getAttributeHandle("privilegeToDelete", robot)) == 1
    assert int(r.getAttributeHandle("location", robot)) == 8
    assert r.getObjectClassName(robot) == "robot"
    assert r.getAttributeName(r.getAttributeHandle("battery", robot), robot) == "battery"
    turtle = r.getObjectClassHandle("turtlebot")
    assert r.getObjectClassName(turtle) == "robot.turtlebot"
    assert r.getAttributeHandle("location", turtle) == r.getAttributeHandle("location", robot)


def test_lookups_of_unknown_names_and_handles_raise_typed_errors(federation):
    """Unknown names raise NameNotFound; handles of nothing raise the *NotDefined exceptions."""
    r = federation("a").rtia
    robot = r.getObjectClassHandle("robot")
    command = r.getInteractionClassHandle("command")
    with pytest.raises(rti.NameNotFound):
        r.getObjectClassHandle("submarine")
    with pytest.raises(rti.NameNotFound):
        r.getAttributeHandle("depth", robot)
    with pytest.raises(rti.NameNotFound):
        r.getInteractionClassHandle("fire")
    with pytest.raises(rti.NameNotFound):
        r.getParameterHandle("volume", command)
    privilege = r.getAttributeHandle("privilegeToDelete", robot)
    location = r.getAttributeHandle("location", robot)
    ic_root = r.getInteractionClassHandle("InteractionRoot")
    with pytest.raises(rti.AttributeNotDefined):
        r.getAttributeName(r.getAttributeHandle("sonar", r.getObjectClassHandle("turtlebot")), robot)
    with pytest.raises(rti.InteractionParameterNotDefined):
        r.getParameterName(r.getParameterHandle("name", command), ic_root)
    with pytest.raises(rti.ObjectNotKnown):
        r.getObjectInstanceHandle("nobody")
    assert privilege != location


def test_wrong_handle_types_raise_type_error(federation):
    """Handles are not interchangeable: passing the wrong kind raises TypeError."""
    r = federation("a").rtia
    robot = r.getObjectClassHandle("robot")
    location = r.getAttributeHandle("location", robot)
    command = r.getInteractionClassHandle("command")
    with pytest.raises(TypeError):
        r.publishObjectClass(location, [location])
    with pytest.raises(TypeError):
        r.publishObjectClass(robot, [robot])
    with pytest.raises(TypeError):
        r.publishInteractionClass(robot)
    with pytest.raises(TypeError):
        r.subscribeObjectClassAttributes(robot, [3])
    with pytest.raises(TypeError):
        r.getAttributeHandle("location", command)
    with pytest.raises(TypeError):
        r.publishObjectClass(3, [location])


def test_register_requires_published_class_and_unique_name(pair):
    """registerObjectInstance needs a published class; object names are unique in the federation."""
    pub, sub, robot, turtle, h = pair
    with pytest.raises(rti.ObjectClassNotPublished):
        pub.rtia.registerObjectInstance(robot)
    pub.rtia.publishObjectClass(robot, [h["location"]])
    sub.rtia.publishObjectClass(robot, [h["location"]])
    obj = pub.rtia.registerObjectInstance(robot, "unique")
    with pytest.raises(rti.ObjectAlreadyRegistered):
        sub.rtia.registerObjectInstance(robot, "unique")
    assert pub.rtia.getObjectInstanceName(obj) == "unique"
    assert pub.rtia.getObjectInstanceHandle("unique") == obj
    assert pub.rtia.getObjectClass(obj) == robot
    anonymous = pub.rtia.registerObjectInstance(robot)
    assert pub.rtia.getObjectInstanceName(anonymous) not in ("", "unique")


def test_reflect_only_subscribed_attributes_with_exact_bytes(pair):
    """Only subscribed attributes are reflected, with the exact bytes, tag, order and transport."""
    pub, sub, robot, turtle, h = pair
    pub.rtia.publishObjectClass(robot, [h["location"], h["battery"], h["compass"]])
    sub.rtia.subscribeObjectClassAttributes(robot, [h["location"], h["battery"]])
    barrier(sub.rtia)
    obj = pub.rtia.registerObjectInstance(robot, "r")
    payload = bytes(range(256)) * 4
    pub.rtia.updateAttributeValues(obj, {h["location"]: payload, h["compass"]: b"N", h["battery"]: "98%"}, "t1")
    pub.rtia.updateAttributeValues(obj, {h["compass"]: b"S"}, "only compass")
    tick_until(lambda: sub.amb.named("reflectAttributeValues"), sub.rtia)
    settle(sub.rtia)
    assert sub.amb.named("discoverObjectInstance") == [(obj, robot, "r")]
    [(o, values, tag, order, transport)] = sub.amb.named("reflectAttributeValues")
    assert o == obj and tag == "t1"
    assert values == {h["location"]: payload, h["battery"]: b"98%"}
    assert sub.rtia.getOrderingName(order) == "Receive"
    assert sub.rtia.getTransportationName(transport) == "HLAreliable"


def test_values_of_every_accepted_type_arrive_as_the_bytes_they_held_at_the_call(registered):
    """bytes (sent from where they are), str (UTF-8, surrogateescape), bytearray and memoryview (copied at the
    call: changing them afterwards changes nothing sent) each arrive as the bytes they held; anything else
    is a TypeError at the call."""
    pub, sub, h, obj = registered
    mutable = bytearray(b"before")
    values = [b"\x00bytes\xff", "caf\u00e9 \udcff", mutable, memoryview(b"viewed")]
    for value in values:
        pub.rtia.updateAttributeValues(obj, {h["location"]: value}, "")
    mutable[:] = b"after!"
    with pytest.raises(TypeError, match="bytes or str"):
        pub.rtia.updateAttributeValues(obj, {h["location"]: 42}, "")
    tick_until(lambda: len(sub.amb.named("reflectAttributeValues")) == len(values), sub.rtia)
    got = [args[1][h["location"]] for args in sub.amb.named("reflectAttributeValues")]
    assert got == [b"\x00bytes\xff", "caf\u00e9 \udcff".encode("utf-8", "surrogateescape"), b"before", b"viewed"]


def test_subclass_instance_discovered_as_subscribed_superclass(pair):
    """A turtlebot is discovered as robot by a robot subscriber, and its subclass attribute is not reflected."""
    pub, sub, robot, turtle, h = pair
    pub.rtia.publishObjectClass(turtle, [h["location"], h["sonar"]])
    sub.rtia.subscribeObjectClassAttributes(robot, [h["location"]])
    barrier(sub.rtia)
    obj = pub.rtia.registerObjectInstance(turtle, "t")
    pub.rtia.updateAttributeValues(obj, {h["location"]: b"here", h["sonar"]: b"ping"}, "")
    tick_until(lambda: sub.amb.named("reflectAttributeValues"), sub.rtia)
    assert sub.amb.named("discoverObjectInstance") == [(obj, robot, "t")]
    assert sub.rtia.getObjectClass(obj) == robot
    assert sub.amb.named("reflectAttributeValues")[0][1] == {h["location"]: b"here"}


def test_late_subscriber_discovers_existing_instances(pair, federation):
    """Objects registered before a federate joined and subscribed are discovered by it."""
    pub, sub, robot, turtle, h = pair
    pub.rtia.publishObjectClass(robot, [h["location"]])
    objs = {pub.rtia.registerObjectInstance(robot, f"r{i}") for i in range(3)}
    late = federation("late")
    late.rtia.subscribeObjectClassAttributes(robot, [h["location"]])
    barrier(late.rtia)
    tick_until(lambda: len(late.amb.named("discoverObjectInstance")) == 3, late.rtia)
    assert {args[0] for args in late.amb.named("discoverObjectInstance")} == objs


def test_update_errors(registered):
    """Updating an unknown object, an undefined attribute or one not owned raises the typed exception."""
    pub, sub, h, obj = registered
    with pytest.raises(rti.AttributeNotOwned):
        pub.rtia.updateAttributeValues(obj, {h["battery"]: b"x"}, "")
    with pytest.raises(rti.AttributeNotDefined):
        pub.rtia.updateAttributeValues(obj, {h["sonar"]: b"x"}, "")
    tick_until(lambda: sub.amb.named("discoverObjectInstance"), sub.rtia)
    with pytest.raises(rti.AttributeNotOwned):
        sub.rtia.updateAttributeValues(obj, {h["location"]: b"x"}, "")
    with pytest.raises(TypeError):
        pub.rtia.updateAttributeValues(obj, {h["location"]: 3.0}, "")
    with pytest.raises(TypeError):
        pub.rtia.updateAttributeValues(obj, 5, "")
    with pytest.raises(TypeError):
        pub.rtia.updateAttributeValues(obj, {h["location"]: b"x"}, 3)
    pub.rtia.deleteObjectInstance(obj, "gone")
    with pytest.raises(rti.ObjectNotKnown):
        pub.rtia.updateAttributeValues(obj, {h["location"]: b"x"}, "")


def test_delete_requires_privilege_and_reaches_subscribers(registered):
    """Only the registrant may delete; subscribers get removeObjectInstance with the tag."""
    pub, sub, _h, obj = registered
    tick_until(lambda: sub.amb.named("discoverObjectInstance"), sub.rtia)
    with pytest.raises(rti.DeletePrivilegeNotHeld):
        sub.rtia.deleteObjectInstance(obj, "")
    pub.rtia.deleteObjectInstance(obj, "bye")
    tick_until(lambda: sub.amb.named("removeObjectInstance"), sub.rtia)
    assert sub.amb.named("removeObjectInstance") == [(obj, "bye")]
    with pytest.raises(rti.ObjectNotKnown):
        sub.rtia.getObjectInstanceName(obj)


def test_local_delete_forgets_and_rediscovers(pair):
    """localDeleteObjectInstance forgets an object; the next update discovers it again."""
    pub, sub, robot, turtle, h = pair
    pub.rtia.publishObjectClass(robot, [h["location"]])
    sub.rtia.subscribeObjectClassAttributes(robot, [h["location"]])
    barrier(sub.rtia)
    obj = pub.rtia.registerObjectInstance(robot, "again")
    tick_until(lambda: sub.amb.named("discoverObjectInstance"), sub.rtia)
    with pytest.raises(rti.FederateOwnsAttributes):
        pub.rtia.localDeleteObjectInstance(obj)
    sub.rtia.localDeleteObjectInstance(obj)
    barrier(sub.rtia)
    with pytest.raises(rti.ObjectNotKnown):
        sub.rtia.getObjectInstanceName(obj)
    pub.rtia.updateAttributeValues(obj, {h["location"]: b"1"}, "")
    tick_until(lambda: sub.amb.named("reflectAttributeValues"), sub.rtia)
    assert len(sub.amb.named("discoverObjectInstance")) == 2
    assert sub.rtia.getObjectInstanceName(obj) == "again"


def test_request_attribute_value_updates_reach_owners(pair):
    """requestObject/ClassAttributeValueUpdate lead to provideAttributeValueUpdate at the owner."""
    pub, sub, robot, turtle, h = pair
    pub.rtia.publishObjectClass(robot, [h["location"], h["battery"]])
    pub.rtia.publishObjectClass(turtle, [h["location"]])
    sub.rtia.subscribeObjectClassAttributes(robot, [h["location"], h["battery"]])
    barrier(sub.rtia)
    r1 = pub.rtia.registerObjectInstance(robot)
    t1 = pub.rtia.registerObjectInstance(turtle)
    tick_until(lambda: len(sub.amb.named("discoverObjectInstance")) == 2, sub.rtia)
    sub.rtia.requestObjectAttributeValueUpdate(r1, [h["battery"]])
    tick_until(lambda: pub.amb.named("provideAttributeValueUpdate"), pub.rtia)
    assert pub.amb.named("provideAttributeValueUpdate") == [(r1, (h["battery"],))]
    sub.rtia.requestClassAttributeValueUpdate(robot, [h["location"]])
    tick_until(lambda: len(pub.amb.named("provideAttributeValueUpdate")) == 3, pub.rtia)
    assert set(pub.amb.named("provideAttributeValueUpdate")[1:]) == {(r1, (h["location"],)), (t1, (h["location"],))}


def test_interactions_round_trip_and_subclass_received_as_superclass(pair):
    """sendInteraction reaches subscribers with exact bytes; a subclass arrives as the subscribed class."""
    pub, sub, robot, turtle, h = pair
    r = pub.rtia
    command, urgent = r.getInteractionClassHandle("command"), r.getInteractionClassHandle("command.urgent_command")
    name, value = r.getParameterHandle("name", command), r.getParameterHandle("value", command)
    priority = r.getParameterHandle("priority", urgent)
    assert r.getParameterHandle("name", urgent) == name
    with pytest.raises(rti.InteractionClassNotPublished):
        r.sendInteraction(command, {name: b"x"}, "")
    r.publishInteractionClass(command)
    r.publishInteractionClass(urgent)
    sub.rtia.subscribeInteractionClass(command)
    barrier(sub.rtia)
    r.sendInteraction(command, {name: b"go", value: b"\x00\x01"}, "c1")
    r.sendInteraction(urgent, {name: b"stop", priority: b"9"}, "c2")
    with pytest.raises(rti.InteractionParameterNotDefined):
        r.sendInteraction(command, {priority: b"9"}, "")
    tick_until(lambda: len(sub.amb.named("receiveInteraction")) == 2, sub.rtia)
    first, second = sub.amb.named("receiveInteraction")
    assert first[:3] == (command, {name: b"go", value: b"\x00\x01"}, "c1")
    assert second[:3] == (command, {name: b"stop"}, "c2")
    assert sub.rtia.getTransportationName(first[4]) == "HLAreliable"


def test_unsubscribe_stops_delivery(pair):
    """After unsubscribing, updates and interactions are no longer delivered."""
    pub, sub, robot, turtle, h = pair
    command = pub.rtia.getInteractionClassHandle("command")
    pub.rtia.publishObjectClass(robot, [h["location"]])
    pub.rtia.publishInteractionClass(command)
    sub.rtia.subscribeObjectClassAttributes(robot, [h["location"]])
    sub.rtia.subscribeInteractionClass(command)
    barrier(sub.rtia)
    obj = pub.rtia.registerObjectInstance(robot)
    tick_until(lambda: sub.amb.named("discoverObjectInstance"), sub.rtia)
    sub.rtia.unsubscribeObjectClass(robot)
    sub.rtia.unsubscribeInteractionClass(command)
    barrier(sub.rtia)
    with pytest.raises(rti.ObjectClassNotSubscribed):
        sub.rtia.unsubscribeObjectClass(robot)
    with pytest.raises(rti.InteractionClassNotSubscribed):
        sub.rtia.unsubscribeInteractionClass(command)
    pub.rtia.updateAttributeValues(obj, {h["location"]: b"x"}, "")
    pub.rtia.sendInteraction(command, {}, "")
    settle(sub.rtia, pub.rtia)
    assert not sub.amb.named("reflectAttributeValues")
    assert not sub.amb.named("receiveInteraction")


def test_registration_and_interaction_advisories_follow_subscribers(pair):
    """start/stopRegistrationForObjectClass and turnInteractionsOn/Off follow real subscriber changes."""
    pub, sub, robot, turtle, h = pair
    command = pub.rtia.getInteractionClassHandle("command")
    pub.rtia.publishObjectClass(turtle, [h["location"]])
    pub.rtia.publishInteractionClass(command)
    settle(pub.rtia)
    assert not pub.amb.named("startRegistrationForObjectClass")
    sub.rtia.subscribeObjectClassAttributes(robot, [h["location"]])  # a superclass makes turtlebot relevant
    sub.rtia.subscribeInteractionClass(command)
    barrier(sub.rtia)
    tick_until(lambda: pub.amb.named("turnInteractionsOn"), pub.rtia)
    tick_until(lambda: pub.amb.named("startRegistrationForObjectClass"), pub.rtia)
    assert pub.amb.named("startRegistrationForObjectClass") == [(turtle,)]
    assert pub.amb.named("turnInteractionsOn") == [(command,)]
    sub.rtia.unsubscribeObjectClass(robot)
    sub.rtia.unsubscribeInteractionClass(command)
    tick_until(lambda: pub.amb.named("stopRegistrationForObjectClass") and pub.amb.named("turnInteractionsOff"),
               pub.rtia)
    assert pub.amb.named("stopRegistrationForObjectClass") == [(turtle,)]
    assert pub.amb.named("turnInteractionsOff") == [(command,)]


def test_disabled_advisory_switches_silence_advisories(pair):
    """With the relevance advisory switches off, no advisories are sent."""
    pub, sub, robot, turtle, h = pair
    command = pub.rtia.getInteractionClassHandle("command")
    pub.rtia.disableClassRelevanceAdvisorySwitch()
    pub.rtia.disableInteractionRelevanceAdvisorySwitch()
    pub.rtia.publishObjectClass(robot, [h["location"]])
    pub.rtia.publishInteractionClass(command)
    sub.rtia.subscribeObjectClassAttributes(robot, [h["location"]])
    sub.rtia.subscribeInteractionClass(command)
    barrier(sub.rtia)
    settle(pub.rtia, sub.rtia)
    assert not pub.amb.named("startRegistrationForObjectClass")
    assert not pub.amb.named("turnInteractionsOn")
    pub.rtia.enableClassRelevanceAdvisorySwitch()
    tick_until(lambda: pub.amb.named("startRegistrationForObjectClass"), pub.rtia)


def test_unpublish_errors_and_declaration_checks(pair):
    """Unpublishing what is not published, or publishing undefined attributes, raises the typed exception."""
    pub, sub, robot, turtle, h = pair
    command = pub.rtia.getInteractionClassHandle("command")
    with pytest.raises(rti.ObjectClassNotPublished):
        pub.rtia.unpublishObjectClass(robot)
    with pytest.raises(rti.InteractionClassNotPublished):
        pub.rtia.unpublishInteractionClass(command)
    with pytest.raises(rti.AttributeNotDefined):
        pub.rtia.publishObjectClass(robot, [h["sonar"]])
    pub.rtia.publishObjectClass(robot, [h["location"]])
    pub.rtia.unpublishObjectClass(robot)
    with pytest.raises(rti.ObjectClassNotPublished):
        pub.rtia.registerObjectInstance(robot)


def test_updates_from_another_thread_while_ticking(registered):
    """Sending calls are safe from another thread while the main thread ticks (ROS-bridge pattern)."""
    import threading

    pub, sub, h, obj = registered
    count = 500

    def sender():
        for i in range(count):
            pub.rtia.updateAttributeValues(obj, {h["location"]: i.to_bytes(4, "big")}, "")

    thread = threading.Thread(target=sender)
    thread.start()
    tick_until(lambda: len(sub.amb.named("reflectAttributeValues")) == count, sub.rtia, pub.rtia, timeout=20)
    thread.join()
    got = [int.from_bytes(args[1][h["location"]], "big") for args in sub.amb.named("reflectAttributeValues")]
    assert got == list(range(count))
