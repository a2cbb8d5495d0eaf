"""Federation management: create, destroy, join, resign with each action, and their errors."""

import pytest

import hlacore.rti as rti

from support import ROBOT_FED, Federate, share_robot_location, tick_until


def test_create_twice_raises_already_exists(gateway_address):
    """A second createFederationExecution of the same name raises FederationExecutionAlreadyExists."""
    rtia = rti.RTIAmbassador(gateway_address)
    rtia.createFederationExecution("Twice", ROBOT_FED)
    with pytest.raises(rti.FederationExecutionAlreadyExists):
        rtia.createFederationExecution("Twice", ROBOT_FED)
    rtia.destroyFederationExecution("Twice")


def test_destroy_unknown_and_join_unknown_raise_does_not_exist(gateway_address):
    """Destroying or joining a federation that does not exist raises FederationExecutionDoesNotExist."""
    rtia = rti.RTIAmbassador(gateway_address)
    with pytest.raises(rti.FederationExecutionDoesNotExist):
        rtia.destroyFederationExecution("Nowhere")
    with pytest.raises(rti.FederationExecutionDoesNotExist):
        rtia.joinFederationExecution("me", "Nowhere", rti.FederateAmbassador())


def test_destroy_with_joined_federates_raises(federation):
    """Destroy is refused while federates are joined, and works once they resigned."""
    fed = federation("a")
    other = rti.RTIAmbassador(fed.rtia.address)
    with pytest.raises(rti.FederatesCurrentlyJoined):
        other.destroyFederationExecution("TestFed")


def test_join_twice_and_duplicate_name_raise_already_member(federation, gateway_address):
    """One ambassador joins once; a federate name is unique in a federation."""
    fed = federation("a")
    with pytest.raises(rti.FederateAlreadyExecutionMember):
        fed.rtia.joinFederationExecution("b", "TestFed", rti.FederateAmbassador())
    with pytest.raises(rti.FederateAlreadyExecutionMember):
        Federate(gateway_address, "a")


def test_federate_handles_are_distinct(federation):
    """Each joined federate gets its own FederateHandle."""
    a, b = federation("a"), federation("b")
    assert isinstance(a.handle, rti.FederateHandle)
    assert a.handle != b.handle


def test_create_with_missing_file_raises_could_not_open(gateway_address, tmp_path):
    """A FED file found neither by the client nor by the gateway raises CouldNotOpenFED."""
    rtia = rti.RTIAmbassador(gateway_address)
    with pytest.raises(rti.CouldNotOpenFED, match="missing.fed"):
        rtia.createFederationExecution("F", str(tmp_path / "missing.fed"))


@pytest.mark.parametrize(
    "text, position",
    [
        ("(FED (Federation F) (FEDversion v1.3)\n (objects (class A (attribute x reliable tso)))", "2:42"),
        ("(FED (Federation F)\n(FEDversion v1.3)\n(objects (clas A)))", "3:11"),
        ("(FED (Federation F) (FEDversion v1.3) (objects (class A (attribute x reliable receive))", "1:88"),
    ],
)
def test_malformed_fed_raises_error_reading_fed_with_position(gateway_address, tmp_path, text, position):
    """createFederationExecution on a malformed file raises ErrorReadingFED starting FILE:LINE:COL."""
    path = tmp_path / "broken.fed"
    path.write_text(text)
    rtia = rti.RTIAmbassador(gateway_address)
    with pytest.raises(rti.ErrorReadingFED) as error:
        rtia.createFederationExecution("F", str(path))
    assert str(error.value).startswith(f"{path}:{position}: ")
    assert isinstance(error.value, rti.RTIexception)
    with pytest.raises(rti.FederationExecutionDoesNotExist):
        rtia.destroyFederationExecution("F")


def test_resign_delete_objects_removes_them_for_others(federation):
    """ResignAction.DeleteObjects: subscribers get removeObjectInstance for the resigner's objects."""
    owner, watcher = federation("owner"), federation("watcher")
    robot, _location = share_robot_location(owner, watcher)
    obj = owner.rtia.registerObjectInstance(robot, "r")
    tick_until(lambda: watcher.amb.named("discoverObjectInstance"), watcher.rtia)
    owner.rtia.resignFederationExecution(rti.ResignAction.DeleteObjects)
    tick_until(lambda: watcher.amb.named("removeObjectInstance"), watcher.rtia)
    assert watcher.amb.named("removeObjectInstance")[0][0] == obj


def test_resign_no_action_while_owning_raises_owns_attributes(federation):
    """ResignAction.NoAction is refused while the federate owns attributes; it stays joined."""
    owner = federation("owner")
    robot = owner.rtia.getObjectClassHandle("robot")
    location = owner.rtia.getAttributeHandle("location", robot)
    owner.rtia.publishObjectClass(robot, [location])
    obj = owner.rtia.registerObjectInstance(robot)
    with pytest.raises(rti.FederateOwnsAttributes):
        owner.rtia.resignFederationExecution(rti.ResignAction.NoAction)
    owner.rtia.updateAttributeValues(obj, {location: b"still joined"}, "")


def test_resign_release_attributes_keeps_the_object(federation, gateway_address):
    """ResignAction.ReleaseAttributes leaves the object in the federation for late joiners."""
    owner = federation("owner")
    robot = owner.rtia.getObjectClassHandle("robot")
    location = owner.rtia.getAttributeHandle("location", robot)
    owner.rtia.publishObjectClass(robot, [location])
    owner.rtia.registerObjectInstance(robot, "kept")
    owner.rtia.resignFederationExecution(rti.ResignAction.ReleaseAttributes)
    late = federation("late")
    late.rtia.subscribeObjectClassAttributes(robot, [location])
    tick_until(lambda: late.amb.named("discoverObjectInstance"), late.rtia)
    assert late.amb.named("discoverObjectInstance")[0][2] == "kept"


def test_invalid_resign_action_raises(federation):
    """An action outside ResignAction raises InvalidResignAction."""
    fed = federation("a")
    with pytest.raises(rti.InvalidResignAction):
        fed.rtia.resignFederationExecution(7)


def test_services_before_join_raise_not_execution_member(gateway_address):
    """Services that need a federation raise FederateNotExecutionMember before join."""
    rtia = rti.RTIAmbassador(gateway_address)
    with pytest.raises(rti.FederateNotExecutionMember):
        rtia.getObjectClassHandle("robot")
    with pytest.raises(rti.FederateNotExecutionMember):
        rtia.resignFederationExecution(rti.ResignAction.NoAction)
    with pytest.raises(rti.FederateNotExecutionMember):
        rtia.registerFederationSynchronizationPoint("x", "")
    assert rtia.tick() is False


def test_rejoin_after_resign(federation, gateway_address):
    """An ambassador that resigned may join again."""
    fed = federation("a")
    fed.rtia.resignFederationExecution(rti.ResignAction.NoAction)
    handle = fed.rtia.joinFederationExecution("a", "TestFed", fed.amb)
    assert handle != fed.handle


def test_connect_to_nothing_names_the_address(monkeypatch):
    """RTIAmbassador() with nothing listening raises RTIinternalError naming the address."""
    import socket

    with socket.socket() as s:
        s.bind(("127.0.0.1", 0))
        port = s.getsockname()[1]
    with pytest.raises(rti.RTIinternalError, match=f"127.0.0.1:{port}"):
        rti.RTIAmbassador(f"127.0.0.1:{port}")
    monkeypatch.setenv("HLACORE_RTIG", f"127.0.0.1:{port}")
    with pytest.raises(rti.RTIInternalError, match=f"127.0.0.1:{port}"):
        rti.RTIAmbassador()


def test_address_from_environment(inprocess_gateway, monkeypatch):
    """$HLACORE_RTIG names the gateway when no address is given."""
    monkeypatch.setenv("HLACORE_RTIG", inprocess_gateway.address)
    assert rti.RTIAmbassador().address == inprocess_gateway.address


def test_malformed_address_raises():
    """An address that is not HOST:PORT raises RTIinternalError."""
    with pytest.raises(rti.RTIinternalError, match="HOST:PORT"):
        rti.RTIAmbassador("nowhere")
