"""Tests for hlacore.omt.HLAuse: the data types of IEEE 1516-2000 and
1516-2010 OMT/FOM XML files, defined in the hlacore.omt module."""

from __future__ import annotations

import math
import struct
import xml.etree.ElementTree as ElementTree
from typing import Any

import pytest

import hlacore.omt as omt

from support import ROOT, TESTS

DATA = TESTS / "data" / "omt"
ROBOT = DATA / "robot-2010.xml"
PYHLA = DATA / "pyhla-2000.xml"


@pytest.fixture
def fom():
    """hlacore.omt, restored after the test: HLAuse defines module names."""
    names = dict(vars(omt))
    fom_types = dict(omt._fom_types)
    yield omt
    for name in set(vars(omt)) - set(names):
        delattr(omt, name)
    vars(omt).update(names)
    omt._fom_types.clear()
    omt._fom_types.update(fom_types)


def _write(tmp_path, data_types, name="test.xml", namespace=""):
    """Write a 1516-2010 layout FOM whose dataTypes element holds
    ``data_types``; return its path."""
    xmlns = f' xmlns="{namespace}"' if namespace else ""
    path = tmp_path / name
    path.write_text(f"<?xml version='1.0'?>\n<objectModel{xmlns}><dataTypes>"
                    f"{data_types}</dataTypes></objectModel>\n")
    return path


def _round_trip(datatype, value):
    """Pack ``value``, unpack it (also at an offset) and check that the
    same value and size come back and that repacking gives the same bytes."""
    data = datatype.pack(value)
    back, size = datatype.unpack(data)
    assert size == len(data), datatype.name
    assert back == value, datatype.name
    assert datatype.pack(back) == data, datatype.name
    assert datatype.unpack(b"\xa5" * 5 + data + b"\x5a", 5) == (back, size)
    if datatype.fixed_size is not None:
        assert datatype.fixed_size == size, datatype.name
    return data


def _chars(text):
    """A fixed array of HLAASCIIchar as unpack returns it."""
    return tuple(bytes((c,)) for c in text.encode("ascii"))


def _robot_values(fom):
    """Values of every type of robot-2010.xml, each as unpack returns it."""
    mode = fom.DriveModeEnum8
    pose2d = {"x": 1.5, "y": -2.25, "theta": math.pi / 2}
    waypoint = {"sequence": 65535, "pose": pose2d, "tolerance": 0.125}
    wheel_commands = [
        {"mode": mode.Stopped},
        {"mode": mode.Differential, "differential": {"left": 3.0, "right": -3.0}},
        {"mode": mode.SkidSteer, "differential": {"left": 0.5, "right": 0.25}},
        {"mode": mode.Ackermann, "ackermann": {"speed": 1.25, "steering": -0.5}},
        {"mode": mode.Omnidirectional, "velocity": (0.5, -0.5, 0.25)},
        {"mode": mode.Teleoperated, "wheelSpeeds": (1.0, 2.0, -1.5, 0.0)},
        {"mode": mode.Docking, "wheelSpeeds": ()},
    ]
    status = {
        "id": 4_000_000_000, "name": "Robotin\u00f6 \u65e5", "frame": _chars("base_lnk"),
        "pose": {"position": {"x": 1.0, "y": 2.0, "z": 0.0},
                 "orientation": (1.0, 0.0, 0.0, 0.0)},
        "covariance": ((0.01, 0.0, 0.0), (0.0, 0.01, 0.0), (0.0, 0.0, 0.05)),
        "twist": {"linear": (0.5, 0.0, 0.0), "angular": (0.0, 0.0, 0.25)},
        "mode": mode.Ackermann, "bumper": fom.BumperStateEnum32.Fault,
        "stalled": True, "firmware": b"v2.1.0", "diagnostics": b"\x00\xffok"}
    return {
        "HLAoctet": [b"\x00", b"\xff"],
        "HLAinteger32BE": [-(2**31), 2**31 - 1],
        "HLAfloat64BE": [0.1, -1e300],
        "RobotUnsignedInteger8": [0, 255],
        "RobotUnsignedInteger16LE": [0, 65535],
        "RobotCounter32BE": [0, 2**32 - 1],
        "RobotFloat32LE": [1.5, -0.0, math.inf],
        "Meters": [12.5],
        "Radians": [-math.pi],
        "RadiansPerSecond": [6.25],
        "RangeMeters": [0.5, math.inf],
        "RobotId": [7, 2**32 - 1],
        "SequenceNumber": [1, 65535],
        "Microseconds": [-1, 2**62],
        "HLAboolean": [True, False],
        "DriveModeEnum8": list(mode),
        "SensorKindEnum16": list(fom.SensorKindEnum16),
        "BumperStateEnum32": list(fom.BumperStateEnum32),
        "HLAASCIIstring": [b"", b"lidar"],
        "Vector3f": [(1.0, -2.0, 0.5)],
        "Quaternion": [(0.5, 0.5, -0.5, 0.5)],
        "PoseCovariance": [status["covariance"]],
        "FrameId": [_chars("map     ")],
        "LidarRanges": [(), (0.25, 1.5, math.inf, 30.0), (1.0,) * 2048],
        "WheelSpeeds": [(), (1.0, -1.0)],
        "WaypointList": [(waypoint,), (waypoint, dict(waypoint, sequence=2))],
        "Pose2D": [pose2d],
        "Position3D": [{"x": 0.0, "y": 1.0, "z": -1.0}],
        "Pose3D": [status["pose"]],
        "Twist": [status["twist"]],
        "DifferentialCommand": [{"left": 1.0, "right": 2.0}],
        "AckermannCommand": [{"speed": 0.75, "steering": 0.125}],
        "Waypoint": [waypoint],
        "LidarScan": [{"robot": 3, "sensor": fom.SensorKindEnum16.Lidar2D,
                       "stamp": 123_456_789, "angleMin": -math.pi,
                       "angleIncrement": 0.5, "ranges": (1.0, 2.0, 3.0)},
                      {"robot": 3, "sensor": fom.SensorKindEnum16.Sonar, "stamp": 0,
                       "angleMin": 0.0, "angleIncrement": 0.0, "ranges": ()}],
        "RobotStatus": [status],
        "DriveRequest": [{"robot": 9, "command": command, "issued": 5}
                         for command in wheel_commands],
        "MissionPlan": [{"robot": 1, "waypoints": (waypoint,) * 3}],
        "WheelCommand": wheel_commands,
    }


def _pyhla_values(fom):
    """Values of every type of pyhla-2000.xml, each as unpack returns it."""
    kind = fom.ShapeKind
    return {
        "UnsignedShort": [0, 65535],
        "HLAinteger32BE": [-5],
        "AngleDegrees": [90.0],
        "Altitude": [1234.5],
        "ShapeKind": list(kind),
        "Vector": [(1.0, 2.0, 3.0)],
        "SampleList": [(), (1, 2, 65535)],
        "Location": [{"heading": 45.0, "altitude": 100.0, "offset": (0.0, 0.5, -0.5)}],
        "Size": [{"width": 2.0, "height": 1.0}],
        "Shape": [{"kind": kind.Circle, "radius": 2.5},
                  {"kind": kind.Square, "size": {"width": 1.0, "height": 1.0}},
                  {"kind": kind.Rectangle, "size": {"width": 3.0, "height": 1.0}},
                  {"kind": kind.Point},
                  {"kind": kind.Unknown, "description": b"a blob"}],
    }


# --------------------------------------------------------------------------
# the two FOMs: every type round-trips
# --------------------------------------------------------------------------

@pytest.mark.parametrize("path,values", [(ROBOT, _robot_values), (PYHLA, _pyhla_values)],
                         ids=["robot-2010", "pyhla-2000"])
def test_every_type_round_trips(fom, path, values):
    """Every name HLAuse returns round-trips; none is skipped."""
    types = fom.HLAuse(path)
    samples = values(fom)
    assert list(types) == list(samples)  # every type, in declaration order
    for name, datatype in types.items():
        assert isinstance(datatype, omt.HLAdataType), name
        assert samples[name], name
        for value in samples[name]:
            _round_trip(datatype, value)


def test_names_are_defined_in_the_module(fom):
    """HLAuse defines the types as hlacore.omt attributes and returns them."""
    types = fom.HLAuse(ROBOT)
    assert fom.Pose2D is types["Pose2D"]
    assert fom.Pose2D.pack({"x": 1.0, "y": 2.0, "theta": 0.0}) == struct.pack(">3d", 1, 2, 0)
    assert [name for name, _ in fom.Waypoint.fields] == ["sequence", "pose", "tolerance"]
    assert fom.WaypointList.elementType is fom.Waypoint  # a forward use, resolved
    assert fom.Meters is omt.HLAfloat64BE  # simpleData: an alias
    assert fom.RobotId is fom.RobotCounter32BE
    assert fom.LidarRanges.cardinality == 2048  # [0..2048]
    assert fom.WaypointList.cardinality == 64
    assert fom.PoseCovariance.cardinality == 3
    assert fom.PoseCovariance.elementType.cardinality == 3


def test_standard_names_keep_the_module_types(fom):
    """A FOM re-declaring a standard type keeps the module's: HLAboolean
    stays a bool although the 2010 MIM makes it an enumeration."""
    standard = {name: getattr(omt, name) for name in (
        "HLAoctet", "HLAinteger32BE", "HLAfloat64BE", "HLAboolean", "HLAASCIIstring")}
    types = fom.HLAuse(ROBOT)
    for name, datatype in standard.items():
        assert types[name] is datatype and getattr(fom, name) is datatype
    assert fom.HLAboolean.unpack(b"\x00\x00\x00\x01") == (True, 4)
    assert fom.HLAuse(PYHLA)["HLAinteger32BE"] is standard["HLAinteger32BE"]


def test_custom_basic_data(fom):
    """basicData: size, endian; unsigned and float from the name or the
    interpretation."""
    fom.HLAuse(ROBOT)
    assert fom.RobotUnsignedInteger8.pack(200) == b"\xc8"
    assert fom.RobotUnsignedInteger16LE.pack(0x0102) == b"\x02\x01"
    assert fom.RobotCounter32BE.pack(2**32 - 1) == b"\xff\xff\xff\xff"
    assert fom.RobotFloat32LE.pack(1.0) == b"\x00\x00\x80\x3f"
    with pytest.raises(ValueError, match="RobotUnsignedInteger8.*out of range"):
        fom.RobotUnsignedInteger8.pack(-1)
    fom.HLAuse(PYHLA)
    assert fom.UnsignedShort.pack(65535) == b"\xff\xff"


def test_enumerations(fom):
    """Enumerators are attributes, print like PyHLA's and unpack as such."""
    fom.HLAuse(ROBOT)
    docking = fom.DriveModeEnum8.Docking
    assert docking == 11
    assert str(docking) == "DriveModeEnum8.Docking"
    assert repr(docking) == "<DriveModeEnum8.Docking=11>"
    assert fom.DriveModeEnum8.unpack(b"\x0b") == (docking, 1)
    assert fom.SensorKindEnum16.pack("Sonar") == b"\x00\x03"
    assert [e.name for e in fom.BumperStateEnum32] == ["Released", "Pressed", "Fault"]


RPR_EMITTER = """
<enumeratedDataTypes><enumeratedData><name>EmitterTypeEnum16</name><representation>HLAinteger16BE</representation>
  <enumerator><name>Other</name><value>0</value></enumerator>
  <enumerator><name>AN_APG_63</name><value>32805</value></enumerator>
  <enumerator><name>AN_APG_66</name><value>32806</value></enumerator></enumeratedData></enumeratedDataTypes>
"""


def test_an_enumerator_beyond_a_signed_representation_reads_as_its_bit_pattern(fom, tmp_path):
    """As the RPR FOM 2.0's EmitterTypeEnum16 (32805 in an HLAinteger16BE), read as tools in the field read it:
    the representation's bit pattern, 0x8025 on the wire, said once for the type; a value beyond the width
    stays an error."""
    with pytest.warns(UserWarning, match=r"EmitterTypeEnum16: .*bit pattern: 32805 as -32731, 32806 as -32730") as caught:
        fom.HLAuse(_write(tmp_path, RPR_EMITTER))
    assert len(caught) == 1
    emitter = fom.EmitterTypeEnum16
    assert emitter.AN_APG_63 == -32731 and emitter.pack("AN_APG_63") == b"\x80\x25"
    assert emitter.unpack(b"\x80\x26") == (emitter.AN_APG_66, 2)
    with pytest.raises(ValueError, match="out of range"):
        omt.HLAenumerated("Wide", omt.HLAinteger16BE, {"Big": 65536}).pack("Big")


# --------------------------------------------------------------------------
# byte layouts written out by hand from IEEE 1516.2's rules
# --------------------------------------------------------------------------

def test_wheel_command_layout(fom):
    """Discriminant (1 octet), pad to the alternative's boundary, value."""
    fom.HLAuse(ROBOT)
    wheel = fom.WheelCommand
    assert wheel.octetBoundary == 8
    assert wheel.pack({"mode": "Stopped"}) == b"\x00"
    assert wheel.pack({"mode": "SkidSteer", "differential": {"left": 1.0, "right": -2.0}}) == (
        b"\x02" + b"\x00" * 7
        + b"\x3f\xf0\x00\x00\x00\x00\x00\x00"      # left, HLAfloat64BE
        + b"\xc0\x00\x00\x00\x00\x00\x00\x00")     # right
    assert wheel.pack({"mode": 3, "ackermann": {"speed": 1.0, "steering": 1.0}}) == (
        b"\x03" + b"\x00" * 3
        + b"\x00\x00\x80\x3f"                      # speed, RobotFloat32LE
        + b"\x3f\x80\x00\x00")                     # steering, HLAfloat32BE
    assert wheel.pack({"mode": "Teleoperated", "wheelSpeeds": [1.0, 2.0]}) == (
        b"\x0a" + b"\x00" * 3
        + b"\x00\x00\x00\x02"                      # HLAinteger32BE count
        + b"\x00\x00\x80\x3f" + b"\x00\x00\x00\x40")


def test_padded_record_layouts(fom):
    """Fields start at their boundary relative to the record's start; a
    variant inside a record is aligned to the variant's boundary."""
    fom.HLAuse(ROBOT)
    waypoint = fom.Waypoint.pack({"sequence": 0x0102, "tolerance": 0.5,
                                  "pose": {"x": 1.0, "y": 2.0, "theta": 0.0}})
    assert waypoint == (b"\x02\x01" + b"\x00" * 6             # RobotUnsignedInteger16LE
                        + b"\x3f\xf0" + b"\x00" * 6           # x = 1.0
                        + b"\x40\x00" + b"\x00" * 6           # y = 2.0
                        + b"\x00" * 8                         # theta = 0.0
                        + b"\x3f\x00\x00\x00")                # tolerance, HLAfloat32BE
    request = fom.DriveRequest.pack({"robot": 5, "issued": 6, "command": {"mode": "Stopped"}})
    assert request == (b"\x00\x00\x00\x05" + b"\x00" * 4      # robot, pad to 8
                       + b"\x00" + b"\x00" * 7                # variant: Stopped; pad to 8
                       + b"\x00" * 7 + b"\x06")               # issued, HLAinteger64BE
    fom.HLAuse(PYHLA)
    assert fom.Location.pack({"heading": 1.0, "altitude": 1.0, "offset": [0, 0, 0]}) == (
        b"\x3f\x80\x00\x00" + b"\x00" * 4                   # heading, pad to 8
        + b"\x00\x00\x00\x00\x00\x00\xf0\x3f"               # altitude, HLAfloat64LE
        + b"\x00" * 12)
    assert fom.Shape.pack({"kind": "Circle", "radius": 1.0}) == (
        b"\x00\x00\x00\x01" + b"\x00" * 4 + b"\x3f\xf0" + b"\x00" * 6)
    assert fom.Shape.pack({"kind": "Point"}) == b"\x00\x00\x00\x04"
    assert fom.Shape.pack({"kind": "Unknown", "description": "ab"}) == (
        b"\x00\x00\x00\x00" + b"\x00\x00\x00\x02ab")


def test_variant_alternatives_from_the_file(fom):
    """Ranges follow the enumeration's declaration order; HLAother takes the
    rest; unpack returns the enumerator and PyHLA's value shape."""
    fom.HLAuse(ROBOT)
    mode = fom.DriveModeEnum8
    wheel = fom.WheelCommand
    value, size = wheel.unpack(wheel.pack({"mode": "SkidSteer", "differential": {
        "left": 0.0, "right": 0.0}}))
    assert value["mode"] is mode.SkidSteer and set(value) == {"mode", "differential"}
    assert wheel.unpack(b"\x0b\x00\x00\x00\x00\x00\x00\x00") == (
        {"mode": mode.Docking, "wheelSpeeds": ()}, 8)
    assert wheel.unpack(b"\x00") == ({"mode": mode.Stopped}, 1)


# --------------------------------------------------------------------------
# both layouts, with and without namespace
# --------------------------------------------------------------------------

ELEMENT_LAYOUT = """
<simpleDataTypes><simpleData><name>Level</name><representation>HLAinteger16LE</representation>
</simpleData></simpleDataTypes>
<enumeratedDataTypes><enumeratedData><name>Color</name><representation>HLAoctet</representation>
  <enumerator><name>Red</name><value>1</value><value>101</value></enumerator>
  <enumerator><name>Green</name><value>2</value></enumerator></enumeratedData></enumeratedDataTypes>
<arrayDataTypes><arrayData><name>Grid</name><dataType>Level</dataType>
  <cardinality>[0..2],2</cardinality><encoding>HLAvariableArray</encoding></arrayData></arrayDataTypes>
<variantRecordDataTypes><variantRecordData><name>Light</name><discriminant>color</discriminant>
  <dataType>Color</dataType>
  <alternative><enumerator>Red</enumerator><name>level</name><dataType>Level</dataType></alternative>
  <alternative><enumerator>Green</enumerator></alternative>
  <encoding>HLAvariantRecord</encoding></variantRecordData></variantRecordDataTypes>
"""


@pytest.mark.parametrize("namespace", ["", "http://standards.ieee.org/IEEE1516-2010"],
                         ids=["no-namespace", "namespace"])
def test_element_layout(fom, tmp_path, namespace):
    """The 2010 layout reads with or without its namespace; an enumerator
    with two values decodes both; nested variable arrays; a valueless
    alternative with no name."""
    types = fom.HLAuse(_write(tmp_path, ELEMENT_LAYOUT, namespace=namespace))
    assert list(types) == ["Level", "Color", "Grid", "Light"]
    assert fom.Color.unpack(b"\x65") == (fom.Color.Red, 1)
    grid = [[1, 2], [3, -4]]
    data = fom.Grid.pack(grid)
    assert data == (b"\x00\x00\x00\x02" + b"\x00\x00\x00\x02\x01\x00\x02\x00"
                    + b"\x00\x00\x00\x02\x03\x00\xfc\xff")
    assert fom.Grid.unpack(data) == (((1, 2), (3, -4)), 20)
    with pytest.raises(ValueError, match=r"Grid: 3 elements exceed the cardinality 2"):
        fom.Grid.pack([[], [], []])
    with pytest.raises(ValueError, match=r"Grid\[0\]: Grid \(dimension 2\): 3 elements"):
        fom.Grid.pack([[1, 2, 3]])
    assert fom.Light.pack({"color": "Red", "level": -2}) == b"\x01\x00\xfe\xff"
    assert fom.Light.unpack(b"\x02") == ({"color": fom.Color.Green}, 1)


def test_attribute_layout_with_namespace(fom, tmp_path):
    """The 2000 attribute layout also reads inside a namespace."""
    path = tmp_path / "ns2000.xml"
    path.write_text(
        '<objectModel xmlns="urn:x-test"><dataTypes><arrayDataTypes>'
        '<arrayData name="Pair" dataType="HLAinteger32LE" cardinality="[2..2]"'
        ' encoding="HLAfixedArray"/></arrayDataTypes></dataTypes></objectModel>')
    assert fom.HLAuse(path)["Pair"].pack([1, 2]) == b"\x01\x00\x00\x00\x02\x00\x00\x00"


# --------------------------------------------------------------------------
# references across files and to undefined names
# --------------------------------------------------------------------------

def test_unresolved_reference_fails_when_used(fom, tmp_path):
    """A name nobody defines loads, and fails when used, naming it, the
    type that uses it and the file; defining it later makes it work."""
    path = _write(tmp_path, """<fixedRecordDataTypes><fixedRecordData><name>Reading</name>
        <field><name>value</name><dataType>HLAfloat32BE</dataType></field>
        <field><name>unit</name><dataType>UnitCode</dataType></field>
        </fixedRecordData></fixedRecordDataTypes>""", name="sensors.xml")
    types = fom.HLAuse(path)
    with pytest.raises(KeyError) as info:
        types["Reading"].pack({"value": 1.0, "unit": 3})
    message = str(info.value)
    assert "'UnitCode'" in message and "Reading.unit" in message and "sensors.xml" in message
    with pytest.raises(KeyError, match="UnitCode"):
        types["Reading"].unpack(b"\x00" * 8)
    # A second module defines it: the first one's types now work.
    fom.HLAuse(_write(tmp_path, """<simpleDataTypes><simpleData><name>UnitCode</name>
        <representation>HLAinteger16BE</representation></simpleData></simpleDataTypes>""",
                      name="units.xml"))
    data = types["Reading"].pack({"value": 1.0, "unit": 3})
    assert data == b"\x3f\x80\x00\x00\x00\x03"
    assert types["Reading"].unpack(data) == ({"value": 1.0, "unit": 3}, 6)


def test_unsupported_encoding_loads_and_fails_loudly(fom, tmp_path):
    """A non-standard encoding loads, keeps its element's boundary, and
    raises NotImplementedError naming the type and the encoding."""
    types = fom.HLAuse(_write(tmp_path, """
        <basicDataRepresentations><basicData><name>Int24</name><size>24</size>
          <interpretation>Integer</interpretation><endian>Big</endian></basicData>
        </basicDataRepresentations>
        <arrayDataTypes><arrayData><name>Marking</name><dataType>HLAASCIIchar</dataType>
          <cardinality>Dynamic</cardinality><encoding>RPRnullTerminatedArray</encoding></arrayData>
        </arrayDataTypes>
        <fixedRecordDataTypes><fixedRecordData><name>Entity</name>
          <field><name>id</name><dataType>HLAinteger16BE</dataType></field>
          <field><name>marking</name><dataType>Marking</dataType></field></fixedRecordData>
        </fixedRecordDataTypes>"""))
    marking = types["Marking"]
    assert marking.octetBoundary == 1 and marking.fixed_size is None
    with pytest.raises(NotImplementedError,
                       match="Marking: cannot pack: arrayData encoding "
                             "'RPRnullTerminatedArray' is not supported"):
        marking.pack(b"abc")
    with pytest.raises(NotImplementedError, match="Marking: cannot unpack"):
        marking.unpack(b"abc\x00")
    with pytest.raises(NotImplementedError, match=r"Entity\.marking: Marking: cannot pack"):
        types["Entity"].pack({"id": 1, "marking": b"x"})
    with pytest.raises(NotImplementedError, match="Int24: cannot pack: basicData "
                                                  "encoding '24-bit integer'"):
        types["Int24"].pack(1)


def test_recursive_type_loads_and_fails_when_used(fom, tmp_path):
    """A type that contains itself loads; using it fails clearly."""
    types = fom.HLAuse(_write(tmp_path, """
        <arrayDataTypes><arrayData><name>Nodes</name><dataType>Node</dataType>
          <cardinality>Dynamic</cardinality><encoding>HLAvariableArray</encoding></arrayData>
        </arrayDataTypes>
        <fixedRecordDataTypes><fixedRecordData><name>Node</name>
          <field><name>children</name><dataType>Nodes</dataType></field></fixedRecordData>
          <fixedRecordData><name>Leaf</name>
          <field><name>value</name><dataType>HLAinteger32BE</dataType></field></fixedRecordData>
        </fixedRecordDataTypes>"""))
    with pytest.raises(NotImplementedError, match="recursive data type"):
        types["Node"].pack({"children": []})
    assert types["Leaf"].pack({"value": 1}) == b"\x00\x00\x00\x01"


def test_name_clashes_and_reloading(fom, tmp_path):
    """A type named like a module attribute is returned but not set; a
    second HLAuse replaces the first one's names."""
    first = fom.HLAuse(_write(tmp_path, """<simpleDataTypes>
        <simpleData><name>pack_int</name><representation>HLAoctet</representation></simpleData>
        <simpleData><name>Speed</name><representation>HLAfloat32BE</representation></simpleData>
        </simpleDataTypes>
        <arrayDataTypes><arrayData><name>Packs</name><dataType>pack_int</dataType>
          <cardinality>2</cardinality><encoding>HLAfixedArray</encoding></arrayData>
        </arrayDataTypes>""", name="a.xml"))
    assert first["pack_int"] is omt.HLAoctet
    assert callable(fom.pack_int) and fom.pack_int(1) == b"\x00\x00\x00\x01"
    assert first["Packs"].pack(b"ab") == b"ab"
    assert fom.Speed is omt.HLAfloat32BE
    fom.HLAuse(_write(tmp_path, """<simpleDataTypes>
        <simpleData><name>Speed</name><representation>HLAfloat64BE</representation></simpleData>
        </simpleDataTypes>""", name="b.xml"))
    assert fom.Speed is omt.HLAfloat64BE


# --------------------------------------------------------------------------
# files that cannot be used
# --------------------------------------------------------------------------

def test_missing_file(fom, tmp_path):
    """A file that is not there raises OSError naming it."""
    missing = tmp_path / "nowhere.xml"
    with pytest.raises(OSError, match="nowhere.xml"):
        fom.HLAuse(missing)


def test_malformed_xml(fom, tmp_path):
    """Malformed XML raises ValueError naming the file and the position."""
    path = tmp_path / "broken.xml"
    path.write_text("<objectModel><dataTypes></objectModel>")
    with pytest.raises(ValueError, match=r"broken\.xml: malformed XML: mismatched tag: line 1"):
        fom.HLAuse(path)
    path.write_text("<html><body/></html>")
    with pytest.raises(ValueError, match=r"broken\.xml: not an HLA object model"):
        fom.HLAuse(path)


@pytest.mark.parametrize("data_types,message", [
    ("<arrayDataTypes><arrayData><name>A</name><dataType>HLAoctet</dataType>"
     "<cardinality>Dynamic</cardinality><encoding>HLAfixedArray</encoding></arrayData>"
     "</arrayDataTypes>",
     r"bad\.xml: arrayData 'A': HLAfixedArray needs a fixed cardinality, got 'Dynamic'"),
    ("<arrayDataTypes><arrayData><name>A</name><dataType>HLAoctet</dataType>"
     "<cardinality>many</cardinality><encoding>HLAvariableArray</encoding></arrayData>"
     "</arrayDataTypes>",
     r"bad\.xml: arrayData 'A': cardinality 'many' is not Dynamic"),
    ("<simpleDataTypes><simpleData><representation>HLAoctet</representation>"
     "</simpleData></simpleDataTypes>",
     r"bad\.xml: a simpleData element has no name"),
    ("<fixedRecordDataTypes><fixedRecordData><name>R</name><field><name>f</name></field>"
     "</fixedRecordData></fixedRecordDataTypes>",
     r"bad\.xml: fixedRecordData 'R': R\.f: no dataType"),
    ("<enumeratedDataTypes><enumeratedData><name>E</name><representation>HLAoctet"
     "</representation><enumerator><name>A</name><value>x</value></enumerator>"
     "</enumeratedData></enumeratedDataTypes>",
     r"bad\.xml: enumeratedData 'E': invalid literal"),
    ("<enumeratedDataTypes><enumeratedData><name>E</name><representation>HLAoctet"
     "</representation><enumerator><name>A</name><value>1</value></enumerator>"
     "</enumeratedData></enumeratedDataTypes><variantRecordDataTypes><variantRecordData>"
     "<name>V</name><discriminant>d</discriminant><dataType>E</dataType><alternative>"
     "<enumerator>B</enumerator><name>b</name><dataType>HLAoctet</dataType></alternative>"
     "</variantRecordData></variantRecordDataTypes>",
     r"bad\.xml: variantRecordData 'V': V: 'B' is not an enumerator of E"),
], ids=["fixed-dynamic", "cardinality", "no-name", "no-datatype", "enumerator-value",
        "alternative-enumerator"])
def test_malformed_definitions(fom, tmp_path, data_types, message):
    """A malformed data type raises ValueError naming the file and the type."""
    with pytest.raises(ValueError, match=message):
        fom.HLAuse(_write(tmp_path, data_types, name="bad.xml"))


def test_unknown_discriminant_and_missing_fields(fom, tmp_path):
    """Values that do not fit the FOM's types raise typed errors with the
    path to the bad part."""
    fom.HLAuse(ROBOT)
    fom.HLAuse(_write(tmp_path, """
        <enumeratedDataTypes><enumeratedData><name>Axis</name>
          <representation>HLAinteger32BE</representation>
          <enumerator><name>X</name><value>0</value></enumerator>
          <enumerator><name>Y</name><value>1</value></enumerator>
          <enumerator><name>Z</name><value>2</value></enumerator></enumeratedData>
        </enumeratedDataTypes>
        <variantRecordDataTypes><variantRecordData><name>Coordinate</name>
          <discriminant>axis</discriminant><dataType>Axis</dataType>
          <alternative><enumerator>X,Y</enumerator><name>planar</name>
            <dataType>HLAfloat32BE</dataType></alternative>
          <encoding>HLAvariantRecord</encoding></variantRecordData></variantRecordDataTypes>"""))
    with pytest.raises(ValueError, match=r"Coordinate: no alternative for axis = Axis\.Z "
                                         r"and no HLAother alternative"):
        fom.Coordinate.pack({"axis": "Z"})
    with pytest.raises(ValueError, match=r"Coordinate: no alternative for axis = Axis\.Z"):
        fom.Coordinate.unpack(b"\x00\x00\x00\x02")
    with pytest.raises(ValueError, match=r"WheelCommand\.mode: DriveModeEnum8: 99 is not"):
        fom.WheelCommand.pack({"mode": 99, "wheelSpeeds": []})
    with pytest.raises(KeyError, match=r"DriveRequest: missing field 'issued'"):
        fom.DriveRequest.pack({"robot": 1, "command": {"mode": 0}})
    with pytest.raises(KeyError, match=r"DriveRequest\.command: WheelCommand: missing field "
                                       r"'ackermann' \(the alternative for mode = "
                                       r"DriveModeEnum8\.Ackermann\)"):
        fom.DriveRequest.pack({"robot": 1, "issued": 0, "command": {"mode": 3}})
    with pytest.raises(TypeError, match=r"MissionPlan\.waypoints: WaypointList\[1\]: "
                                        r"Waypoint\.pose: Pose2D\.theta: HLAfloat64BE"):
        fom.MissionPlan.pack({"robot": 1, "waypoints": [
            {"sequence": 0, "tolerance": 0, "pose": {"x": 0, "y": 0, "theta": 0}},
            {"sequence": 1, "tolerance": 0, "pose": {"x": 0, "y": 0, "theta": "north"}}]})
    with pytest.raises(ValueError, match=r"LidarRanges: 2049 elements exceed the cardinality"):
        fom.LidarRanges.pack([1.0] * 2049)


SHARED_FOMS = ROOT.parent / "shared" / "foms"
# In an order where every module finds the types it uses among those loaded before it.
SHARED_MODULES = ["space-fom/SISO_SpaceFOM_datatypes.xml", "space-fom/SISO_SpaceFOM_switches.xml",
                  "space-fom/SISO_SpaceFOM_environment.xml", "space-fom/SISO_SpaceFOM_management.xml",
                  "space-fom/SISO_SpaceFOM_management2.xml", "space-fom/SISO_SpaceFOM_entity.xml",
                  "trickhla/FixedRecordTest.xml", "trickhla/Encoders_Test_FOM.xml", "trickhla/Sine_FOM.xml"]


def _sample(t: Any) -> Any:
    """A value of data type `t` (not its zero where one is easy to get wrong)."""
    if isinstance(t, omt.HLAfixedRecord):
        return {name: _sample(field) for name, field in t.fields}
    if isinstance(t, omt.HLAvariantRecord):
        enumerators, name, alternative = next((a for a in t.alternatives if a[0] != (None,)), t.alternatives[0])
        chosen = enumerators[0]
        if chosen is None or isinstance(chosen, slice):  # HLAother or a range: an enumerator it covers
            chosen = next(iter(t.discriminantType.enumerators.values())) if chosen is None else chosen.start
        value = {t.discriminantName: chosen}
        if name is not None and alternative is not None:
            value[name] = _sample(alternative)
        return value
    if isinstance(t, omt.HLAenumerated):
        return list(t.enumerators.values())[-1]
    if isinstance(t, omt.HLAfixedArray):
        return [_sample(t.elementType)] * t.cardinality
    if isinstance(t, omt.HLAvariableArray):
        return [_sample(t.elementType)] * min(3, t.cardinality or 3)
    for value in (7, 1.5, True, "Ab", b"\x07", b"\x00\x01\x02"):
        try:
            t.pack(value)
        except (TypeError, ValueError):
            continue
        return value
    raise AssertionError(f"no sample value for {t.name}")


def test_every_data_type_of_the_shared_fom_modules_round_trips(fom: Any) -> None:
    """../shared/foms (the Space Reference FOM's six modules, TrickHLA's test FOMs) load unchanged, and each
    data type they declare encodes a value, decodes it whole and encodes the decoded value to the same bytes."""
    paths = [SHARED_FOMS / name for name in SHARED_MODULES]
    assert all(p.is_file() for p in paths), f"the FOM modules of ../shared/foms are missing under {SHARED_FOMS}"
    checked = 0
    for path in paths:
        for name, data_type in fom.HLAuse(path).items():
            value = _sample(data_type)
            data = data_type.pack(value)
            back, size = data_type.unpack(data)
            assert size == len(data) and data_type.pack(back) == data, (path.name, name, value, back)
            checked += 1
    assert checked == sum(_declared_types(p) for p in paths)


def _declared_types(path: Any) -> int:
    """How many data types a module declares (its dataTypes' elements of the six kinds)."""
    kinds = {"basicData", "simpleData", "enumeratedData", "arrayData", "fixedRecordData", "variantRecordData"}
    return sum(1 for e in ElementTree.parse(path).iter() if e.tag.rsplit("}", 1)[-1] in kinds)
