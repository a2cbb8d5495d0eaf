"""The IEEE 1516-2010 C++ API's time types and encoding helpers (tests/cpp/rti1516e/encoding.cpp, built by
./scripts/test.sh as rti1516e_encoding): every check the program makes passes, and every value it encodes
has the bytes hlacore.omt's encoder gives the same value, which also decodes them whole — the C++ helpers
pad as the Python ones do."""

from __future__ import annotations

import subprocess
from typing import Any

import pytest

from hlacore import omt
from support import rti1516e_program

CASES = ["roundtrip", "time_float_arithmetic", "time_integer_arithmetic", "time_encoding", "time_wrong_length",
         "time_wrong_type", "time_overflow", "time_factories", "time_text", "basic_external_memory",
         "decode_errors", "composites", "opaque_data", "hashes"]

_RECORD = omt.HLAfixedRecord("Padded", [("a", omt.HLAoctet), ("b", omt.HLAinteger32BE), ("c", omt.HLAoctet),
                                        ("d", omt.HLAfloat64BE)])
_RECORD_VALUE = {"a": 1, "b": 7, "c": 2, "d": 0.5}
_VARIANT = omt.HLAvariantRecord("Variant", ("kind", omt.HLAinteger32BE),
                                [([1], "f", omt.HLAfloat64BE), ([2], "s", omt.HLAASCIIstring)])

# What the program prints, by name: the hlacore.omt type and the value it encoded.
EXPECTED: dict[str, tuple[omt.HLAdataType, Any]] = {
    "HLAASCIIchar": (omt.HLAASCIIchar, "A"),
    "HLAASCIIstring": (omt.HLAASCIIstring, "hello"),
    "HLAboolean_true": (omt.HLAboolean, True),
    "HLAboolean_false": (omt.HLAboolean, False),
    "HLAbyte": (omt.HLAbyte, 0xAB),
    "HLAoctet": (omt.HLAoctet, 0x7F),
    "HLAfloat32BE": (omt.HLAfloat32BE, 1.5),
    "HLAfloat32LE": (omt.HLAfloat32LE, -2.25),
    "HLAfloat64BE": (omt.HLAfloat64BE, 3.141592653589793),
    "HLAfloat64LE": (omt.HLAfloat64LE, -0.1),
    "HLAinteger16BE": (omt.HLAinteger16BE, -2),
    "HLAinteger16LE": (omt.HLAinteger16LE, 0x1234),
    "HLAinteger32BE": (omt.HLAinteger32BE, -123456),
    "HLAinteger32LE": (omt.HLAinteger32LE, 0x01020304),
    "HLAinteger64BE": (omt.HLAinteger64BE, -1234567890123),
    "HLAinteger64LE": (omt.HLAinteger64LE, 0x0102030405060708),
    "HLAoctetPairBE": (omt.HLAoctetPairBE, 0x1234),  # C++: OctetPair(0x12, 0x34), first the high octet
    "HLAoctetPairLE": (omt.HLAoctetPairLE, 0x1234),
    "HLAunicodeChar": (omt.HLAunicodeChar, "\u00e9"),
    "HLAunicodeString": (omt.HLAunicodeString, "h\u00e9\U0001d11e"),
    "HLAopaqueData": (omt.HLAopaqueData, b"\x01\x02\x03"),
    "fixed_int16x3": (omt.HLAfixedArray("Shorts", omt.HLAinteger16BE, 3), [1, 2, 3]),
    "fixed_stringx2": (omt.HLAfixedArray("Strings", omt.HLAASCIIstring, 2), ["ab", "c"]),
    "variable_float64": (omt.HLAvariableArray("Doubles", omt.HLAfloat64BE), [1.0, 2.0]),
    "variable_float64_empty": (omt.HLAvariableArray("Doubles", omt.HLAfloat64BE), []),
    "variable_octet": (omt.HLAvariableArray("Octets", omt.HLAoctet), [b"x", b"y", b"z"]),
    "record_padded": (_RECORD, _RECORD_VALUE),
    "record_nested": (omt.HLAfixedRecord("Nested", [("s", omt.HLAinteger16BE),
                                                    ("longs", omt.HLAvariableArray("Longs", omt.HLAinteger64BE)),
                                                    ("r", _RECORD)]),
                      {"s": -1, "longs": [5], "r": _RECORD_VALUE}),
    "variant_float": (_VARIANT, {"kind": 1, "f": 2.5}),
    "variant_string": (_VARIANT, {"kind": 2, "s": "hi"}),
    "variant_octet_int32": (omt.HLAvariantRecord("Small", ("d", omt.HLAoctet), [([3], "v", omt.HLAinteger32BE)]),
                            {"d": 3, "v": -1}),
    "HLAfloat64Time": (omt.HLAfloat64BE, 1.5),
    "HLAfloat64Interval": (omt.HLAfloat64BE, 0.25),
    "HLAinteger64Time": (omt.HLAinteger64BE, 42),
    "HLAinteger64Interval": (omt.HLAinteger64BE, -3),
}


@pytest.fixture(scope="module")
def output() -> subprocess.CompletedProcess[str]:
    """One run of the program."""
    return subprocess.run([rti1516e_program("rti1516e_encoding")], capture_output=True, text=True, timeout=60)


def encodings(run: subprocess.CompletedProcess[str]) -> dict[str, bytes]:
    """The program's "name hex" lines, as bytes by name."""
    pairs = [line.split(" ") for line in run.stdout.splitlines()
             if not line.startswith(("ok ", "FAIL ", "# "))]
    return {name: bytes.fromhex(digits) for name, digits in pairs}


def test_every_check_passes(output: subprocess.CompletedProcess[str]) -> None:
    assert output.returncode == 0, output.stdout + output.stderr
    assert [line for line in output.stdout.splitlines() if line.startswith("ok ")] == [f"ok {c}" for c in CASES]


def test_every_printed_value_has_its_python_twin(output: subprocess.CompletedProcess[str]) -> None:
    assert sorted(encodings(output)) == sorted(EXPECTED)


@pytest.mark.parametrize("name", EXPECTED)
def test_encoding_is_omts(output: subprocess.CompletedProcess[str], name: str) -> None:
    datatype, value = EXPECTED[name]
    assert encodings(output)[name].hex() == datatype.pack(value).hex()


@pytest.mark.parametrize("name", EXPECTED)
def test_omt_decodes_the_cpp_bytes_whole(output: subprocess.CompletedProcess[str], name: str) -> None:
    datatype, _ = EXPECTED[name]
    data = encodings(output)[name]
    _, size = datatype.unpack(data)
    assert size == len(data)
