"""Tests for hlacore.omt, the PyHLA- and JCERTI-compatible encoders."""

from __future__ import annotations

import math
import pickle
import struct

import pytest

import hlacore.omt as omt

INTEGER_TYPES = [
    (omt.HLAinteger16BE, ">h"),
    (omt.HLAinteger16LE, "<h"),
    (omt.HLAinteger32BE, ">i"),
    (omt.HLAinteger32LE, "<i"),
    (omt.HLAinteger64BE, ">q"),
    (omt.HLAinteger64LE, "<q"),
    (omt.Unsignedinteger16BE, ">H"),
    (omt.Unsignedinteger32BE, ">I"),
    (omt.Unsignedinteger64BE, ">Q"),
]
FLOAT_TYPES = [
    (omt.HLAfloat32BE, ">f"),
    (omt.HLAfloat32LE, "<f"),
    (omt.HLAfloat64BE, ">d"),
    (omt.HLAfloat64LE, "<d"),
]


def _limits(fmt: str) -> tuple[int, int]:
    """Return the (min, max) integer range of a struct integer format."""
    bits = 8 * struct.calcsize(fmt)
    if fmt[1].isupper():
        return 0, (1 << bits) - 1
    return -(1 << (bits - 1)), (1 << (bits - 1)) - 1


# --------------------------------------------------------------------------
# basic integer and float types
# --------------------------------------------------------------------------

@pytest.mark.parametrize("hla_type,fmt", INTEGER_TYPES,
                         ids=[t.name for t, _ in INTEGER_TYPES])
def test_integer_round_trip_and_layout(hla_type, fmt):
    """Integers round-trip at both range limits and match struct's layout."""
    low, high = _limits(fmt)
    for value in (0, 1, 42, low, high, low + 1, high - 1, -1 if low else 7):
        data = hla_type.pack(value)
        assert data == struct.pack(fmt, value)
        assert hla_type.unpack(data) == (value, struct.calcsize(fmt))
    assert hla_type.octetBoundary == struct.calcsize(fmt)


@pytest.mark.parametrize("hla_type,fmt", INTEGER_TYPES,
                         ids=[t.name for t, _ in INTEGER_TYPES])
def test_integer_out_of_range_raises_value_error(hla_type, fmt):
    """Values outside the type's range raise ValueError naming the type."""
    low, high = _limits(fmt)
    for value in (low - 1, high + 1):
        with pytest.raises(ValueError, match=hla_type.name + ".*out of range"):
            hla_type.pack(value)


def test_negative_integers_exact_bytes():
    """Negative integers use two's complement in the declared byte order."""
    assert omt.HLAinteger16BE.pack(-2) == b"\xff\xfe"
    assert omt.HLAinteger16LE.pack(-2) == b"\xfe\xff"
    assert omt.HLAinteger32BE.pack(-1) == b"\xff\xff\xff\xff"
    assert omt.HLAinteger64LE.unpack(b"\xfe" + b"\xff" * 7) == (-2, 8)


def test_integer_exact_bytes():
    """Known integers encode to the documented big/little-endian bytes."""
    assert omt.HLAinteger32BE.pack(1) == b"\x00\x00\x00\x01"
    assert omt.HLAinteger32LE.pack(1) == b"\x01\x00\x00\x00"
    assert omt.HLAinteger64BE.pack(258) == b"\x00" * 6 + b"\x01\x02"
    assert omt.Unsignedinteger16BE.pack(0xABCD) == b"\xab\xcd"


def test_unsigned_rejects_negative():
    """Unsigned types refuse negative values with ValueError."""
    with pytest.raises(ValueError, match="Unsignedinteger32BE"):
        omt.Unsignedinteger32BE.pack(-1)


def test_integer_wrong_type_raises_type_error():
    """Non-integers (str, float) given to an integer type raise TypeError."""
    with pytest.raises(TypeError, match="HLAinteger32BE"):
        omt.HLAinteger32BE.pack("1")
    with pytest.raises(TypeError, match="HLAinteger32BE"):
        omt.HLAinteger32BE.pack(1.5)


def test_integer_accepts_bool():
    """Booleans are ints and pack as 0/1."""
    assert omt.HLAinteger32BE.pack(True) == b"\x00\x00\x00\x01"


@pytest.mark.parametrize("hla_type,fmt", FLOAT_TYPES,
                         ids=[t.name for t, _ in FLOAT_TYPES])
def test_float_round_trip(hla_type, fmt):
    """Representable floats, signed zero and infinities round-trip exactly."""
    for value in (0.0, -0.0, 1.5, -2.25, 1024.125, math.inf, -math.inf):
        data = hla_type.pack(value)
        assert data == struct.pack(fmt, value)
        result, size = hla_type.unpack(data)
        assert size == struct.calcsize(fmt) == hla_type.octetBoundary
        assert result == value
        assert math.copysign(1.0, result) == math.copysign(1.0, value)


@pytest.mark.parametrize("hla_type,fmt", FLOAT_TYPES,
                         ids=[t.name for t, _ in FLOAT_TYPES])
def test_float_nan_round_trip(hla_type, fmt):
    """NaN survives a pack/unpack round trip."""
    result, _ = hla_type.unpack(hla_type.pack(math.nan))
    assert math.isnan(result)


def test_float_exact_bytes():
    """Floats use IEEE 754 layouts in the declared byte order."""
    assert omt.HLAfloat64BE.pack(1.5) == struct.pack(">d", 1.5)
    assert omt.HLAfloat64BE.pack(1.5) == b"\x3f\xf8" + b"\x00" * 6
    assert omt.HLAfloat32BE.pack(1.0) == b"\x3f\x80\x00\x00"
    assert omt.HLAfloat32LE.pack(1.0) == b"\x00\x00\x80\x3f"


def test_float_accepts_int():
    """Integers are accepted by float types."""
    assert omt.HLAfloat64BE.unpack(omt.HLAfloat64BE.pack(3)) == (3.0, 8)


def test_float32_overflow_raises_value_error():
    """A finite value too large for binary32 raises ValueError."""
    with pytest.raises(ValueError, match="HLAfloat32BE.*out of range"):
        omt.HLAfloat32BE.pack(1e300)


def test_float_wrong_type_raises_type_error():
    """Strings and None are rejected by float types with TypeError."""
    with pytest.raises(TypeError, match="HLAfloat64LE"):
        omt.HLAfloat64LE.pack("1.0")
    with pytest.raises(TypeError, match="HLAfloat64LE"):
        omt.HLAfloat64LE.pack(None)


# --------------------------------------------------------------------------
# offsets and short buffers
# --------------------------------------------------------------------------

def test_unpack_with_offset():
    """unpack reads at the given offset and reports only the consumed size."""
    data = b"\xaa\xbb\xcc" + omt.HLAinteger32BE.pack(-7) + b"\xdd"
    assert omt.HLAinteger32BE.unpack(data, 3) == (-7, 4)
    shifted = b"\x00" + struct.pack("<d", 2.5)
    assert omt.HLAfloat64LE.unpack(shifted, 1) == (2.5, 8)
    assert omt.HLAoctet.unpack(data, 7) == (b"\xdd", 1)


def test_unpack_accepts_bytearray_and_memoryview():
    """unpack works on bytearray and memoryview buffers."""
    data = omt.HLAinteger16BE.pack(300)
    assert omt.HLAinteger16BE.unpack(bytearray(data)) == (300, 2)
    assert omt.HLAinteger16BE.unpack(memoryview(data)) == (300, 2)
    ascii_data = omt.HLAASCIIstring.pack("abc")
    assert omt.HLAASCIIstring.unpack(memoryview(ascii_data)) == (b"abc", 7)


FIXED_SIZE_TYPES = ([t for t, _ in INTEGER_TYPES + FLOAT_TYPES]
                    + [omt.HLAoctet, omt.HLAboolean])


@pytest.mark.parametrize("hla_type", FIXED_SIZE_TYPES, ids=lambda t: t.name)
def test_short_buffer_raises_value_error(hla_type):
    """Every fixed-size basic type reports needed vs available bytes."""
    size = hla_type.octetBoundary
    with pytest.raises(ValueError) as info:
        hla_type.unpack(b"\x00" * (size - 1))
    message = str(info.value)
    assert hla_type.name in message
    assert f"need {size} bytes" in message
    assert f"only {size - 1} available" in message


def test_short_buffer_because_of_offset():
    """A buffer long enough overall but short after the offset is rejected."""
    with pytest.raises(ValueError, match="need 4 bytes at offset 2, only 2"):
        omt.HLAinteger32BE.unpack(b"\x00\x00\x00\x01", 2)
    with pytest.raises(ValueError, match="only 0 available"):
        omt.HLAinteger32BE.unpack(b"\x00\x00\x00\x01", 10)


def test_negative_offset_rejected():
    """A negative offset is a ValueError rather than Python-style indexing."""
    with pytest.raises(ValueError, match="negative offset"):
        omt.HLAinteger32BE.unpack(b"\x00" * 8, -4)


def test_unpack_rejects_str_buffer():
    """Passing a str buffer (Python 2 habit) raises TypeError."""
    with pytest.raises(TypeError, match="buffer must be bytes"):
        omt.HLAinteger32BE.unpack("\x00\x00\x00\x01")


# --------------------------------------------------------------------------
# HLAoctet, HLAboolean, strings
# --------------------------------------------------------------------------

def test_octet_round_trip():
    """HLAoctet packs a 1-byte bytes and unpacks (bytes, 1)."""
    assert omt.HLAoctet.pack(b"\x7f") == b"\x7f"
    assert omt.HLAoctet.unpack(b"\xff") == (b"\xff", 1)
    assert omt.HLAoctet.pack(200) == b"\xc8"
    assert omt.HLAoctet.octetBoundary == 1


def test_octet_rejects_wrong_length_and_range():
    """HLAoctet refuses multi-byte values and ints outside 0..255."""
    with pytest.raises(ValueError, match="exactly 1 byte"):
        omt.HLAoctet.pack(b"ab")
    with pytest.raises(ValueError, match="out of range"):
        omt.HLAoctet.pack(256)


def test_boolean_round_trip_and_layout():
    """HLAboolean is a big-endian HLAinteger32 0/1 decoding to bool."""
    assert omt.HLAboolean.pack(True) == b"\x00\x00\x00\x01"
    assert omt.HLAboolean.pack(False) == b"\x00\x00\x00\x00"
    assert omt.HLAboolean.unpack(b"\x00\x00\x00\x01") == (True, 4)
    assert omt.HLAboolean.unpack(b"\x00\x00\x00\x00") == (False, 4)
    assert omt.HLAboolean.unpack(b"\x00\x00\x00\x02")[0] is True
    assert omt.HLAboolean.octetBoundary == 4


def test_boolean_rejects_other_values():
    """HLAboolean.pack refuses values other than bools and 0/1."""
    with pytest.raises(ValueError, match="HLAboolean"):
        omt.HLAboolean.pack(2)
    with pytest.raises(TypeError, match="HLAboolean"):
        omt.HLAboolean.pack("true")


def test_ascii_string_layout_and_round_trip():
    """HLAASCIIstring is a 4-byte BE length + bytes; unpack gives bytes."""
    data = omt.HLAASCIIstring.pack("UFO")
    assert data == b"\x00\x00\x00\x03UFO"
    assert omt.HLAASCIIstring.unpack(data) == (b"UFO", 7)
    assert omt.HLAASCIIstring.pack(b"\x01\xff") == b"\x00\x00\x00\x02\x01\xff"
    assert omt.HLAASCIIstring.pack("") == b"\x00\x00\x00\x00"
    assert omt.HLAASCIIstring.unpack(b"\x00\x00\x00\x00") == (b"", 4)
    assert omt.HLAASCIIstring.octetBoundary == 4


def test_ascii_string_rejects_non_ascii():
    """A str with non-ASCII characters raises ValueError."""
    with pytest.raises(ValueError, match="HLAASCIIstring.*non-ASCII"):
        omt.HLAASCIIstring.pack("caf\u00e9")


def test_ascii_string_short_buffers():
    """Truncated length prefix or data raise ValueError, never truncate."""
    with pytest.raises(ValueError, match="need 4 bytes"):
        omt.HLAASCIIstring.unpack(b"\x00\x00")
    with pytest.raises(ValueError, match="need 5 bytes at offset 4, only 3"):
        omt.HLAASCIIstring.unpack(b"\x00\x00\x00\x05abc")
    with pytest.raises(ValueError, match="negative length"):
        omt.HLAASCIIstring.unpack(b"\xff\xff\xff\xff")


def test_ascii_string_with_offset():
    """HLAASCIIstring.unpack honours the offset."""
    data = b"xy" + omt.HLAASCIIstring.pack("go") + b"zz"
    assert omt.HLAASCIIstring.unpack(data, 2) == (b"go", 6)


def test_unicode_string_layout_and_round_trip():
    """HLAunicodeString counts UTF-16 code units and stores UTF-16BE."""
    assert omt.HLAunicodeString.pack("A") == b"\x00\x00\x00\x01\x00A"
    for text in ("", "hello", "caf\u00e9", "\u65e5\u672c", "\U0001f680 go"):
        data = omt.HLAunicodeString.pack(text)
        assert omt.HLAunicodeString.unpack(data) == (text, len(data))
    # A character outside the BMP is a surrogate pair: two code units.
    assert omt.HLAunicodeString.pack("\U0001f680")[:4] == b"\x00\x00\x00\x02"


def test_unicode_string_errors():
    """Short data and invalid UTF-16 raise ValueError; non-str TypeError."""
    with pytest.raises(ValueError, match="HLAunicodeString: need 4 bytes"):
        omt.HLAunicodeString.unpack(b"\x00\x00\x00\x02\x00A")
    with pytest.raises(ValueError, match="invalid UTF-16"):
        omt.HLAunicodeString.unpack(b"\x00\x00\x00\x01\xd8\x00")
    with pytest.raises(TypeError):
        omt.HLAunicodeString.pack(b"bytes")


# --------------------------------------------------------------------------
# composite types
# --------------------------------------------------------------------------

def test_fixed_array_numeric():
    """A fixed array of integers is the concatenation of its elements."""
    vector = omt.HLAfixedArray("Vector", omt.HLAfloat64BE, 3)
    data = vector.pack([1.0, -2.0, 0.5])
    assert data == struct.pack(">3d", 1.0, -2.0, 0.5)
    assert vector.unpack(data) == ((1.0, -2.0, 0.5), 24)
    assert vector.octetBoundary == 8


def test_fixed_array_wrong_length_and_element_error():
    """Wrong element count and bad elements raise ValueError with context."""
    pair = omt.HLAfixedArray("Pair", omt.HLAinteger16BE, 2)
    with pytest.raises(ValueError, match="Pair: expected 2 elements, got 3"):
        pair.pack([1, 2, 3])
    with pytest.raises(ValueError, match=r"Pair\[1\]: HLAinteger16BE"):
        pair.pack([1, 70000])
    with pytest.raises(ValueError, match="Pair: need 4 bytes"):
        pair.unpack(b"\x00\x01\x00")


def test_fixed_array_of_octets():
    """An HLAoctet array packs from bytes and unpacks to 1-byte bytes."""
    mac = omt.HLAfixedArray("Mac", omt.HLAoctet, 3)
    assert mac.pack(b"abc") == b"abc"
    assert mac.unpack(b"abcd") == ((b"a", b"b", b"c"), 3)


def test_fixed_array_pads_elements():
    """Elements of a record type are padded to the record's boundary."""
    item = omt.HLAfixedRecord("Item", [("n", omt.HLAinteger32BE),
                                       ("flag", omt.HLAoctet)])
    array = omt.HLAfixedArray("Items", item, 2)
    values = [{"n": 1, "flag": b"\x01"}, {"n": 2, "flag": b"\x02"}]
    data = array.pack(values)
    assert data == (b"\x00\x00\x00\x01\x01" + b"\x00" * 3
                    + b"\x00\x00\x00\x02\x02")
    assert array.unpack(data) == (tuple(values), 13)
    assert array.fixed_size == 13


def test_variable_array_layout_and_round_trip():
    """A variable array is an HLAinteger32BE count followed by elements."""
    numbers = omt.HLAvariableArray("Numbers", omt.HLAinteger16BE)
    data = numbers.pack([1, -1, 3])
    assert data == b"\x00\x00\x00\x03" + struct.pack(">3h", 1, -1, 3)
    assert numbers.unpack(data) == ((1, -1, 3), 10)
    assert numbers.pack([]) == b"\x00\x00\x00\x00"
    assert numbers.unpack(b"\x00\x00\x00\x00") == ((), 4)
    assert numbers.octetBoundary == 4


def test_variable_array_pads_after_count():
    """Eight-byte elements start at offset 8, after 4 pad bytes."""
    doubles = omt.HLAvariableArray("Doubles", omt.HLAfloat64BE)
    data = doubles.pack([1.5])
    assert data == b"\x00\x00\x00\x01" + b"\x00" * 4 + struct.pack(">d", 1.5)
    assert doubles.unpack(data) == ((1.5,), 16)
    assert doubles.unpack(b"\xee" + data, 1) == ((1.5,), 16)
    assert doubles.octetBoundary == 8


def test_variable_array_of_strings():
    """Strings in a variable array are each padded to 4 bytes."""
    names = omt.HLAvariableArray("Names", omt.HLAASCIIstring)
    data = names.pack(["a", "bcd", ""])
    assert data == (b"\x00\x00\x00\x03" + b"\x00\x00\x00\x01a\x00\x00\x00"
                    + b"\x00\x00\x00\x03bcd\x00" + b"\x00\x00\x00\x00")
    assert names.unpack(data) == ((b"a", b"bcd", b""), len(data))


def test_variable_array_errors():
    """Short data, negative counts and too many elements raise ValueError."""
    numbers = omt.HLAvariableArray("Numbers", omt.HLAinteger32BE, 2)
    with pytest.raises(ValueError, match="Numbers: need 8 bytes at offset 4"):
        numbers.unpack(b"\x00\x00\x00\x02\x00\x00\x00\x01")
    with pytest.raises(ValueError, match="exceed the cardinality 2"):
        numbers.pack([1, 2, 3])
    with pytest.raises(ValueError, match="exceed the cardinality 2"):
        numbers.unpack(b"\x00\x00\x00\x03" + b"\x00" * 12)
    with pytest.raises(ValueError, match="negative element count"):
        numbers.unpack(b"\xff\xff\xff\xff")
    strings = omt.HLAvariableArray("Strings", omt.HLAASCIIstring)
    with pytest.raises(ValueError, match=r"Strings\[1\]: HLAASCIIstring"):
        strings.unpack(b"\x00\x00\x00\x02" + b"\x00" * 4 + b"\x00\x00")


def test_variable_array_fast_path_falls_back_for_errors():
    """Bad numeric elements are reported with their index."""
    numbers = omt.HLAvariableArray("Numbers", omt.HLAinteger32BE)
    with pytest.raises(ValueError, match=r"Numbers\[2\]: .*out of range"):
        numbers.pack([1, 2, 1 << 40])
    with pytest.raises(TypeError, match=r"Numbers\[0\]"):
        numbers.pack(["x"])


def test_fixed_record_padding_and_round_trip():
    """Fields are aligned to their boundary relative to the record start."""
    record = omt.HLAfixedRecord("Rec", [
        ("tag", omt.HLAoctet),
        ("value", omt.HLAfloat64BE),
        ("label", omt.HLAASCIIstring),
        ("count", omt.HLAinteger16BE),
    ])
    value = {"tag": b"x", "value": 1.5, "label": b"hi", "count": -2}
    data = record.pack(value)
    assert data == (b"x" + b"\x00" * 7 + struct.pack(">d", 1.5)
                    + b"\x00\x00\x00\x02hi" + b"\xff\xfe")
    assert record.unpack(data) == (value, 24)
    assert list(record.unpack(data)[0]) == ["tag", "value", "label", "count"]
    assert record.octetBoundary == 8


def test_fixed_record_padding_is_relative_to_record_start():
    """Unpacking at an odd offset uses padding relative to the record."""
    record = omt.HLAfixedRecord("R", [("a", omt.HLAoctet),
                                      ("b", omt.HLAinteger32BE)])
    data = record.pack({"a": b"\x01", "b": 7})
    assert data == b"\x01\x00\x00\x00\x00\x00\x00\x07"
    assert record.unpack(b"\xff" + data, 1) == ({"a": b"\x01", "b": 7}, 8)


def test_nested_record():
    """A record inside a record is aligned to the inner record's boundary."""
    point = omt.HLAfixedRecord("Point", [("x", omt.HLAfloat32BE),
                                         ("y", omt.HLAfloat32BE)])
    tagged = omt.HLAfixedRecord("Tagged", [("id", omt.HLAinteger16BE),
                                           ("at", point)])
    value = {"id": 5, "at": {"x": 1.0, "y": -1.0}}
    data = tagged.pack(value)
    assert data == b"\x00\x05\x00\x00" + struct.pack(">ff", 1.0, -1.0)
    assert tagged.unpack(data) == (value, 12)


def test_fixed_record_errors():
    """Missing fields, bad values and short data raise with the field name."""
    record = omt.HLAfixedRecord("R", [("a", omt.HLAinteger32BE),
                                      ("b", omt.HLAinteger16BE)])
    with pytest.raises(KeyError, match="missing field 'b'"):
        record.pack({"a": 1})
    with pytest.raises(ValueError, match=r"R\.b: HLAinteger16BE.*range"):
        record.pack({"a": 1, "b": 1 << 16})
    with pytest.raises(ValueError, match=r"R\.b: HLAinteger16BE: need 2"):
        record.unpack(b"\x00\x00\x00\x01\x00")
    with pytest.raises(TypeError, match="mapping"):
        record.pack([1, 2])


def test_fixed_record_ignores_extra_keys():
    """Extra keys in the value mapping are ignored, as in PyHLA."""
    record = omt.HLAfixedRecord("R", [("a", omt.HLAoctet)])
    assert record.pack({"a": b"z", "other": 1}) == b"z"


def test_enumerated_attribute_access_and_pack():
    """Enumerators are int attributes that pack with the representation."""
    enum = omt.HLAenumerated("Enum", omt.HLAinteger32BE,
                             {"Little": 0, "Big": 1, "Yellow": 64})
    assert isinstance(enum.Yellow, int)
    assert enum.Yellow == 64
    assert repr(enum.Yellow) == "<Enum.Yellow=64>"
    assert str(enum.Little) == "Enum.Little"
    assert f"{enum.Big}" == "Enum.Big"
    assert enum["Big"] is enum.Big
    assert enum.pack(enum.Yellow) == b"\x00\x00\x00\x40"
    assert enum.pack(1) == enum.pack("Big") == b"\x00\x00\x00\x01"
    assert enum.octetBoundary == 4
    assert [e.name for e in enum] == ["Little", "Big", "Yellow"]
    assert [str(e) for e in enum] == ["Enum.Little", "Enum.Big", "Enum.Yellow"]


def test_enumerated_unpack_returns_enumerator():
    """unpack returns the enumerator object, honouring the offset."""
    enum = omt.HLAenumerated("Color", omt.HLAinteger16LE,
                             {"Red": 1, "Green": 2})
    value, size = enum.unpack(b"\x00\x02\x00", 1)
    assert value is enum.Green
    assert size == 2


def test_enumerated_errors():
    """Unknown names, values and encodings raise ValueError/AttributeError."""
    enum = omt.HLAenumerated("Enum", omt.HLAinteger32BE, {"A": 0, "B": 1})
    with pytest.raises(AttributeError, match="no enumerator 'C'"):
        enum.C  # noqa: B018
    with pytest.raises(ValueError, match="unknown enumerator 'C'"):
        enum.pack("C")
    with pytest.raises(ValueError, match="Enum: 5 is not an enumerator"):
        enum.pack(5)
    with pytest.raises(ValueError, match="Enum: 7 is not an enumerator"):
        enum.unpack(b"\x00\x00\x00\x07")
    with pytest.raises(ValueError, match="Enum: HLAinteger32BE: need 4"):
        enum.unpack(b"\x00")
    with pytest.raises(ValueError, match="out of range"):
        omt.HLAenumerated("Bad", omt.HLAinteger16BE, {"Huge": 1 << 20})


def test_enumerated_in_record_and_pickle():
    """Enumerators work as record fields and survive pickling."""
    enum = omt.HLAenumerated("Kind", omt.HLAinteger32BE, {"X": 3})
    record = omt.HLAfixedRecord("R", [("kind", enum), ("ok", omt.HLAboolean)])
    data = record.pack({"kind": enum.X, "ok": True})
    assert data == b"\x00\x00\x00\x03\x00\x00\x00\x01"
    assert record.unpack(data) == ({"kind": 3, "ok": True}, 8)
    copy = pickle.loads(pickle.dumps(enum.X))
    assert copy == 3 and repr(copy) == "<Kind.X=3>" and str(copy) == "Kind.X"


# --------------------------------------------------------------------------
# Ptolemy II / JCERTI helpers
# --------------------------------------------------------------------------

def test_pack_string_layout():
    """pack_string appends exactly one NUL to the UTF-8 bytes."""
    assert omt.pack_string("go") == b"go\x00"
    assert omt.pack_string("") == b"\x00"
    assert omt.pack_string("caf\u00e9") == b"caf\xc3\xa9\x00"


def test_string_round_trip():
    """pack_string/unpack_string round-trip ASCII, empty and non-ASCII text."""
    for text in ("", "go", "battery 42 ", "caf\u00e9 \u65e5\u672c \U0001f680"):
        assert omt.unpack_string(omt.pack_string(text)) == text


def test_unpack_string_drops_only_one_nul_and_keeps_spaces():
    """Only one trailing NUL is removed; trailing spaces are preserved."""
    assert omt.unpack_string(b"42 \x00") == "42 "
    assert omt.unpack_string(b"a\x00\x00") == "a\x00"
    assert omt.unpack_string(b"no-nul") == "no-nul"
    assert omt.unpack_string(b"") == ""
    assert omt.unpack_string(bytearray(b"x\x00")) == "x"


def test_unpack_string_invalid_utf8():
    """Invalid UTF-8 raises a ValueError (UnicodeDecodeError)."""
    with pytest.raises(ValueError):
        omt.unpack_string(b"\xff\x00")


@pytest.mark.parametrize("pack,unpack,fmt,values", [
    (omt.pack_short, omt.unpack_short, ">h", (0, -1, 32767, -32768)),
    (omt.pack_int, omt.unpack_int, ">i", (0, 1, -1, 2**31 - 1, -2**31)),
    (omt.pack_long, omt.unpack_long, ">q", (0, -1, 2**63 - 1, -2**63)),
    (omt.pack_float, omt.unpack_float, ">f", (0.0, 1.5, -2.25, math.inf)),
    (omt.pack_double, omt.unpack_double, ">d", (0.0, 0.1, -1e300, -math.inf)),
], ids=["short", "int", "long", "float", "double"])
def test_ptolemy_numbers_round_trip(pack, unpack, fmt, values):
    """JCERTI-style numbers are big-endian and round-trip exactly."""
    for value in values:
        data = pack(value)
        assert data == struct.pack(fmt, value)
        assert unpack(data) == value


def test_ptolemy_nan_round_trip():
    """NaN round-trips through pack_float and pack_double."""
    assert math.isnan(omt.unpack_float(omt.pack_float(math.nan)))
    assert math.isnan(omt.unpack_double(omt.pack_double(math.nan)))


def test_ptolemy_boolean():
    """Booleans are 4-byte big-endian ints; non-zero decodes as True."""
    assert omt.pack_boolean(True) == b"\x00\x00\x00\x01"
    assert omt.pack_boolean(False) == b"\x00\x00\x00\x00"
    assert omt.unpack_boolean(b"\x00\x00\x00\x01") is True
    assert omt.unpack_boolean(b"\x00\x00\x00\x00") is False
    assert omt.unpack_boolean(b"\xff\xff\xff\xff") is True


@pytest.mark.parametrize("unpack,size", [
    (omt.unpack_short, 2), (omt.unpack_int, 4), (omt.unpack_long, 8),
    (omt.unpack_float, 4), (omt.unpack_double, 8), (omt.unpack_boolean, 4),
], ids=["short", "int", "long", "float", "double", "boolean"])
def test_ptolemy_unpack_requires_exact_length(unpack, size):
    """Too short or too long buffers raise ValueError naming the function."""
    for wrong in (size - 1, size + 1):
        with pytest.raises(ValueError) as info:
            unpack(b"\x00" * wrong)
        assert unpack.__name__ in str(info.value)
        assert f"expected exactly {size} bytes, got {wrong}" in str(info.value)


def test_ptolemy_out_of_range():
    """Out-of-range numbers raise ValueError instead of wrapping."""
    with pytest.raises(ValueError, match="out of range"):
        omt.pack_int(2**31)
    with pytest.raises(ValueError, match="out of range"):
        omt.pack_short(-32769)
    with pytest.raises(ValueError, match="out of range"):
        omt.pack_long(2**63)
    with pytest.raises(ValueError, match="out of range"):
        omt.pack_float(1e39)


def test_public_names_have_docstrings():
    """Every name in __all__ exists and is documented."""
    for name in omt.__all__:
        obj = getattr(omt, name)
        assert (obj.__doc__ or "").strip(), name


def test_public_methods_have_docstrings():
    """Every public method and property of the public classes is documented
    (the API reference is generated from the docstrings)."""
    for name in omt.__all__:
        cls = getattr(omt, name)
        if not isinstance(cls, type):
            continue
        for attribute, member in vars(cls).items():
            if attribute.startswith("_") and attribute not in (
                    "__init__", "__new__", "__repr__", "__str__"):
                continue
            if callable(member) or isinstance(member, property):
                assert (member.__doc__ or "").strip(), f"{name}.{attribute}"


# --------------------------------------------------------------------------
# the MIM's standard names
# --------------------------------------------------------------------------

# Each type: [(value, what it packs to)], [(buffer, what it unpacks to)],
# its octet boundary, and the calls it refuses:
# [(method, argument, exception, message)].
MIM_TYPES = [
    # HLAbyte and HLAASCIIchar are one octet; HLAASCIIchar also packs an
    # ASCII character.
    (omt.HLAbyte, [(b"\x80", b"\x80")], [(b"\x07", (b"\x07", 1))], 1,
     [("pack", "A", TypeError, "HLAbyte")]),
    (omt.HLAASCIIchar, [("A", b"A"), (65, b"A")], [(b"Az", (b"A", 1))], 1,
     [("pack", "\u00e9", ValueError, "HLAASCIIchar: expected one ASCII"),
      ("pack", "AB", ValueError, "HLAASCIIchar: expected one ASCII")]),
    # HLAoctetPairBE/LE are 16-bit unsigned; HLAunicodeChar a UTF-16BE code
    # unit unpacked to a one-character str.
    (omt.HLAoctetPairBE, [(0x1234, b"\x12\x34")], [], 2, []),
    (omt.HLAoctetPairLE, [(0x1234, b"\x34\x12")], [(b"\xff\xff", (0xFFFF, 2))],
     2, []),
    (omt.HLAunicodeChar, [("\u00e9", b"\x00\xe9"), (0x65E5, b"\x65\xe5")],
     [(b"\x65\xe5", ("\u65e5", 2))], 2,
     [("pack", "\U0001f680", ValueError, "HLAunicodeChar.*Basic Multilingual"),
      ("unpack", b"\x00", ValueError, "HLAunicodeChar: need 2 bytes")]),
    # HLAopaqueData is an HLAinteger32BE count and the bytes.
    (omt.HLAopaqueData, [(b"\x00\xff", b"\x00\x00\x00\x02\x00\xff"),
                         (bytearray(), b"\x00\x00\x00\x00")],
     [(b"\x00\x00\x00\x01zq", (b"z", 5))], 4,
     [("pack", "text", TypeError, "HLAopaqueData: expected bytes"),
      ("unpack", b"\x00\x00\x00\x03ab", ValueError, "HLAopaqueData: need 3 bytes")]),
]


@pytest.mark.parametrize("datatype, packs, unpacks, boundary, refused", MIM_TYPES,
                         ids=[row[0].name for row in MIM_TYPES])
def test_mim_types(datatype, packs, unpacks, boundary, refused):
    """The MIM's standard simple types and HLAopaqueData: layout, octet
    boundary, errors naming the type."""
    for value, encoded in packs:
        assert datatype.pack(value) == encoded
    for buffer, decoded in unpacks:
        assert datatype.unpack(buffer) == decoded
    assert datatype.octetBoundary == boundary
    for method, argument, error, message in refused:
        with pytest.raises(error, match=message):
            getattr(datatype, method)(argument)


def test_enumerated_with_octet_representation():
    """An enumeration represented by HLAoctet unpacks to its enumerators."""
    enum = omt.HLAenumerated("Small", omt.HLAoctet, {"A": 1, "B": 200})
    assert enum.pack("B") == b"\xc8"
    assert enum.unpack(b"\xc8") == (enum.B, 1)


# --------------------------------------------------------------------------
# HLAvariantRecord
# --------------------------------------------------------------------------

MODE = omt.HLAenumerated("Mode", omt.HLAinteger32BE, {
    "Off": 0, "Slow": 1, "Fast": 2, "Reverse": 3, "Turbo": 7, "Test": 9})
SPEEDS = omt.HLAfixedRecord("Speeds", [("left", omt.HLAfloat64BE),
                                       ("right", omt.HLAfloat64BE)])


def _motor(others=True):
    """A variant record listing its enumerators in every accepted form."""
    alternatives = [
        (["Off"], None, None),                       # no value
        ([1, MODE.Fast], "speeds", SPEEDS),           # value and enumerator
        (slice("Reverse", "Turbo"), "throttle", omt.HLAoctet),
        (["Test"], "NA", "NA"),                       # the OMT's NA
    ]
    if others:
        alternatives.append(([None], "code", omt.HLAinteger16BE))
    return omt.HLAvariantRecord("Motor", ("mode", MODE), alternatives)


def test_variant_record_layout_by_hand():
    """Discriminant, pad to the alternative's boundary, then the value."""
    motor = _motor()
    data = motor.pack({"mode": MODE.Slow, "speeds": {"left": 1.5, "right": -2.0}})
    assert data == (b"\x00\x00\x00\x01" + b"\x00" * 4
                    + b"\x3f\xf8\x00\x00\x00\x00\x00\x00"
                    + b"\xc0\x00\x00\x00\x00\x00\x00\x00")
    assert motor.unpack(data) == (
        {"mode": MODE.Slow, "speeds": {"left": 1.5, "right": -2.0}}, 24)
    assert motor.pack({"mode": "Turbo", "throttle": 9}) == b"\x00\x00\x00\x07\x09"
    assert motor.pack({"mode": "Off"}) == b"\x00\x00\x00\x00"
    assert motor.pack({"mode": MODE.Test}) == b"\x00\x00\x00\x09"
    assert motor.octetBoundary == 8
    assert motor.fixed_size is None


def test_variant_record_unpack_returns_the_enumerator():
    """unpack gives {discriminant: enumerator, alternative: value}, PyHLA's
    shape, with only the discriminant when the alternative has no value."""
    motor = _motor()
    value, size = motor.unpack(b"\xee" + motor.pack({"mode": 2, "speeds": {
        "left": 0.0, "right": 0.0}}), 1)
    assert value["mode"] is MODE.Fast and size == 24
    assert motor.unpack(b"\x00\x00\x00\x00") == ({"mode": MODE.Off}, 4)
    assert motor.unpack(b"\x00\x00\x00\x03\x05") == (
        {"mode": MODE.Reverse, "throttle": b"\x05"}, 5)


def test_variant_record_matches_enumerators_by_name_and_value():
    """Alternatives given by value match a discriminant given by name and
    vice versa (PyHLA compared ints with names and never matched)."""
    motor = _motor()
    expected = motor.pack({"mode": MODE.Fast, "speeds": {"left": 1, "right": 2}})
    for mode in ("Fast", 2, MODE.Fast):
        assert motor.pack({"mode": mode, "speeds": {"left": 1, "right": 2}}) == expected
    assert motor.pack({"mode": "Slow", "speeds": {"left": 1, "right": 2}})[3] == 1


def test_variant_record_other_alternative():
    """HLAother takes every enumerator no alternative lists; None itself
    works as well as a list holding None."""
    motor = _motor()
    assert motor.pack({"mode": 1, "speeds": {"left": 0, "right": 0}})  # listed
    # every enumerator is listed, so build one where HLAother is used
    record = omt.HLAvariantRecord("R", ("mode", MODE), [
        ("Off", None, None), (None, "code", omt.HLAinteger16BE)])
    data = record.pack({"mode": "Turbo", "code": -3})
    assert data == b"\x00\x00\x00\x07\xff\xfd"
    assert record.unpack(data) == ({"mode": MODE.Turbo, "code": -3}, 6)


def test_variant_record_integer_discriminant():
    """An integer discriminant type works with integer enumerators."""
    record = omt.HLAvariantRecord("ByNumber", ("tag", omt.HLAoctet), [
        ([1, 2], "small", omt.HLAinteger16BE), ([None], "big", omt.HLAfloat32BE)])
    assert record.pack({"tag": 2, "small": 5}) == b"\x02\x00\x00\x05"
    assert record.unpack(b"\x02\x00\x00\x05") == ({"tag": b"\x02", "small": 5}, 4)
    assert record.pack({"tag": 9, "big": 1.0}) == b"\x09\x00\x00\x00\x3f\x80\x00\x00"
    with pytest.raises(ValueError, match="needs an enumerated discriminant"):
        omt.HLAvariantRecord("Bad", ("tag", omt.HLAoctet), [(["A"], "a", omt.HLAoctet)])


def test_variant_record_errors():
    """Clear, typed errors with the record and field in the message."""
    motor = _motor(others=False)
    with pytest.raises(ValueError,
                       match=r"Motor: no alternative for mode = 5 and no HLAother"):
        motor.pack({"mode": 5})
    with pytest.raises(ValueError, match=r"Motor\.mode: unknown enumerator 'Warp'"):
        motor.pack({"mode": "Warp"})
    with pytest.raises(KeyError, match="Motor: missing discriminant 'mode'"):
        motor.pack({"speeds": {}})
    with pytest.raises(KeyError, match=r"Motor: missing field 'speeds' \(the "
                                       r"alternative for mode = Mode\.Slow\)"):
        motor.pack({"mode": 1})
    with pytest.raises(KeyError, match=r"Motor\.speeds: Speeds: missing field 'right'"):
        motor.pack({"mode": 1, "speeds": {"left": 1.0}})
    with pytest.raises(ValueError, match=r"Motor\.throttle: HLAoctet.*out of range"):
        motor.pack({"mode": "Turbo", "throttle": 300})
    with pytest.raises(TypeError, match="Motor: expected a mapping"):
        motor.pack([1])
    with pytest.raises(ValueError, match=r"Motor\.mode: Mode: 5 is not an enumerator"):
        motor.unpack(b"\x00\x00\x00\x05")
    with pytest.raises(ValueError, match=r"Motor\.speeds: Speeds\.left: HLAfloat64BE: need 8"):
        motor.unpack(b"\x00\x00\x00\x01" + b"\x00" * 8)


def test_variant_record_definition_errors():
    """Bad alternatives are rejected when the type is created."""
    with pytest.raises(ValueError, match="'Warp' is not an enumerator of Mode"):
        omt.HLAvariantRecord("V", ("mode", MODE), [(["Warp"], "a", omt.HLAoctet)])
    with pytest.raises(ValueError, match="5 is not a value of Mode"):
        omt.HLAvariantRecord("V", ("mode", MODE), [([5], "a", omt.HLAoctet)])
    with pytest.raises(ValueError, match="discriminant value 1 selects two"):
        omt.HLAvariantRecord("V", ("mode", MODE), [
            (["Slow"], "a", omt.HLAoctet), ([1], "b", omt.HLAoctet)])
    with pytest.raises(ValueError, match="two alternatives for HLAother"):
        omt.HLAvariantRecord("V", ("mode", MODE), [
            ([None], "a", omt.HLAoctet), (None, "b", omt.HLAoctet)])
    with pytest.raises(ValueError, match="empty range"):
        omt.HLAvariantRecord("V", ("mode", MODE), [
            (slice("Turbo", "Slow"), "a", omt.HLAoctet)])
    with pytest.raises(TypeError, match=r"V\.a: the alternative type must be"):
        omt.HLAvariantRecord("V", ("mode", MODE), [(["Slow"], "a", "HLAoctet")])


def test_variant_record_in_record_and_array():
    """A variant record is aligned to its octetBoundary inside composites."""
    motor = _motor()
    outer = omt.HLAfixedRecord("Outer", [("id", omt.HLAinteger16BE),
                                         ("motor", motor),
                                         ("tail", omt.HLAoctet)])
    value = {"id": 7, "motor": {"mode": MODE.Off}, "tail": b"!"}
    data = outer.pack(value)
    assert data == b"\x00\x07" + b"\x00" * 6 + b"\x00\x00\x00\x00" + b"!"
    assert outer.unpack(data) == (value, 13)
    many = omt.HLAvariableArray("Motors", motor)
    values = ({"mode": MODE.Off}, {"mode": MODE.Turbo, "throttle": b"\x01"})
    data = many.pack(values)
    assert data == (b"\x00\x00\x00\x02" + b"\x00" * 4 + b"\x00\x00\x00\x00"
                    + b"\x00" * 4 + b"\x00\x00\x00\x07\x01")
    assert many.unpack(data) == (values, len(data))


# --------------------------------------------------------------------------
# HLAencoding
# --------------------------------------------------------------------------

def test_encoding_forward_reference(monkeypatch):
    """A composite may use a type defined later in the module namespace."""
    path = omt.HLAvariableArray("Path", omt.HLAencoding("LaterPoint"))
    with pytest.raises(KeyError, match="no data type named 'LaterPoint'"):
        path.pack([{"x": 1.0}])
    point = omt.HLAfixedRecord("LaterPoint", [("x", omt.HLAfloat64BE)])
    monkeypatch.setattr(omt, "LaterPoint", point, raising=False)
    data = path.pack([{"x": 1.0}])
    assert data == b"\x00\x00\x00\x01" + b"\x00" * 4 + struct.pack(">d", 1.0)
    assert path.unpack(data) == (({"x": 1.0},), 16)
    assert path.octetBoundary == 8
    reference = path.elementType
    assert reference.resolved and reference.encoding is point
    assert reference.fields == point.fields  # attributes of the target


def test_encoding_unresolved_in_record_names_the_field():
    """An unresolved reference inside a record fails with its context."""
    record = omt.HLAfixedRecord("Rec", [("a", omt.HLAoctet),
                                        ("b", omt.HLAencoding("NoSuchType"))])
    with pytest.raises(KeyError, match=r"Rec\.b: HLAencoding: no data type "
                                       r"named 'NoSuchType'"):
        record.pack({"a": 1, "b": 2})
    with pytest.raises(KeyError, match="NoSuchType"):
        record.octetBoundary  # noqa: B018
    with pytest.raises(KeyError, match="NoSuchType"):
        omt.HLAencoding("NoSuchType").unpack(b"\x00")


def test_encoding_type_parameters():
    """With typeParameters the named constructor is called on first use."""
    vector = omt.HLAencoding("HLAfixedArray", ("Vector", omt.HLAfloat32BE, 3))
    assert vector.name == "Vector" and not vector.resolved
    assert vector.pack([1.0, 2.0, 3.0]) == struct.pack(">3f", 1.0, 2.0, 3.0)
    assert vector.cardinality == 3 and vector.fixed_size == 12
    named = omt.HLAencoding("HLAvariableArray", {
        "name": "Bytes", "elementType": omt.HLAoctet, "cardinality": 2})
    assert named.unpack(b"\x00\x00\x00\x01z") == ((b"z",), 5)
    with pytest.raises(KeyError, match="no data type constructor named 'pack_int'"):
        omt.HLAencoding("pack_int", (1,)).pack(1)


def test_encoding_cycles(monkeypatch):
    """A name that leads back to itself, or a type that contains itself,
    fails clearly instead of recursing forever."""
    monkeypatch.setattr(omt, "LoopA", omt.HLAencoding("LoopB"), raising=False)
    monkeypatch.setattr(omt, "LoopB", omt.HLAencoding("LoopA"), raising=False)
    with pytest.raises(ValueError, match="circular reference"):
        omt.LoopA.pack(1)
    tree = omt.HLAfixedRecord("Tree", [
        ("value", omt.HLAinteger32BE),
        ("children", omt.HLAvariableArray("Trees", omt.HLAencoding("Tree")))])
    monkeypatch.setattr(omt, "Tree", tree, raising=False)
    with pytest.raises(NotImplementedError, match="recursive data type"):
        tree.pack({"value": 1, "children": []})
