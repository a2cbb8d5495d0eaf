"""Handles are typed: hashable, ordered within a kind, never interchangeable, never built by hand."""

import pytest

import hlacore

import hlacore.rti as rti


def test_handles_are_hashable_ordered_and_typed(federation):
    """Handles of one kind compare and hash by value; kinds never compare equal or order."""
    r = federation("a").rtia
    robot = r.getObjectClassHandle("robot")
    location = r.getAttributeHandle("location", robot)
    battery = r.getAttributeHandle("battery", robot)
    assert r.getObjectClassHandle("ObjectRoot.robot") == robot
    assert hash(r.getObjectClassHandle("robot")) == hash(robot)
    assert {location: 1}[r.getAttributeHandle("location", robot)] == 1
    assert battery < location and sorted([location, battery]) == [battery, location]
    assert repr(robot) == "<rti.ObjectClassHandle=3>"
    assert int(robot) == 3
    same_number = r.getAttributeHandle("battery", robot)
    assert int(same_number) == 3
    assert robot != same_number
    with pytest.raises(TypeError):
        robot < same_number  # noqa: B015


def test_an_integer_or_the_wrong_kind_of_handle_gets_a_typed_error_naming_its_source(federation):
    """A PyHLA script passing an int, or a handle of another kind, learns what was expected and where to
    get it, instead of pybind11's signature dump; comparing with an int stays False, not an error."""
    r = federation("a").rtia
    robot = r.getObjectClassHandle("robot")
    location = r.getAttributeHandle("location", robot)
    with pytest.raises(TypeError) as raised:
        r.getObjectClassName(4)
    assert str(raised.value) == ("expected ObjectClassHandle, got int 4: hlacore's handles are typed, not "
                                 "integers (docs/pyhla.md); get one from getObjectClassHandle(name)")
    with pytest.raises(TypeError, match=r"^expected ObjectClassHandle, got hlacore._core.AttributeHandle "
                                        r"<rti.AttributeHandle=\d+>; get one from getObjectClassHandle"):
        r.getAttributeHandle("location", location)
    with pytest.raises(TypeError, match=r"^expected AttributeHandle, got int 1: .*getAttributeHandle\(name, "):
        r.publishObjectClass(robot, [1])  # inside a list
    with pytest.raises(TypeError, match=r"^expected ObjectHandle, got int 3: .*registerObjectInstance"):
        r.updateAttributeValues(3, {location: b""}, "tag")
    assert robot != 3 and not (robot == 3) and location not in [1, 2, 3, 8]
    assert {robot: "robot"}.get(3) is None


def test_handles_cannot_be_constructed():
    """Handles come from the RTI only."""
    for cls in (rti.ObjectClassHandle, rti.AttributeHandle, rti.ObjectHandle, rti.FederateHandle):
        with pytest.raises(TypeError):
            cls(3)


def test_transportation_and_ordering_handles_work_before_join():
    """getTransportationHandle/getOrderingHandle and their names need no federation (as in PyHLA's test)."""
    with hlacore.Gateway(port=0) as gw:
        r = rti.RTIAmbassador(gw.address)
        reliable = r.getTransportationHandle("HLAreliable")
        assert r.getTransportationName(reliable) == "HLAreliable"
        assert r.getTransportationName(r.getTransportationHandle("HLAbestEffort")) == "HLAbestEffort"
        assert r.getOrderingName(r.getOrderingHandle("Timestamp")) == "Timestamp"
        assert r.getOrderingName(r.getOrderingHandle("Receive")) == "Receive"
        with pytest.raises(rti.NameNotFound):
            r.getTransportationHandle("carrier pigeon")
        with pytest.raises(TypeError):
            r.getOrderingName(reliable)


def test_every_hla_exception_derives_from_rtiexception():
    """The HLA 1.3 exception list is exported under one base, with PyHLA's aliases."""
    assert issubclass(rti.ObjectNotKnown, rti.RTIexception)
    assert rti.RTIInternalError is rti.RTIinternalError
    assert rti.Exception is rti.RTIexception
    names = [n for n in rti.__all__ if isinstance(getattr(rti, n), type) and issubclass(getattr(rti, n), rti.RTIexception)]
    assert len(names) >= 80
