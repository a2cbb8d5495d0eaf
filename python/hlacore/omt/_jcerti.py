"""The helpers Ptolemy II uses through JCERTI's ``EncodingHelpers``: big-endian numbers, booleans as 4-byte
integers, strings as UTF-8 bytes and one NUL byte."""

from __future__ import annotations

from typing import Any, Protocol, TypeVar

from ._basic import HLAboolean, HLAfloat32BE, HLAfloat64BE, HLAinteger16BE, HLAinteger32BE, HLAinteger64BE
from ._bytes import Buffer

_V = TypeVar("_V")  # a decoded value
_V_co = TypeVar("_V_co", covariant=True)
_V_contra = TypeVar("_V_contra", contravariant=True)


def _exact(function: str, data: Any, size: int) -> None:
    """Require ``data`` to be a bytes-like object of exactly ``size`` bytes."""
    if not isinstance(data, (bytes, bytearray, memoryview)):
        raise TypeError(
            f"{function}: expected bytes, got {type(data).__name__}")
    if len(data) != size:
        raise ValueError(
            f"{function}: expected exactly {size} bytes, got {len(data)}")


def pack_string(value: str, encoding: str = "utf-8") -> bytes:
    """Encode ``value`` as JCERTI does: the encoded text plus one NUL byte."""
    if not isinstance(value, str):
        raise TypeError(
            f"pack_string: expected str, got {type(value).__name__}")
    return value.encode(encoding) + b"\x00"


def unpack_string(data: Buffer, encoding: str = "utf-8") -> str:
    """Decode a JCERTI string: drop one trailing NUL (if present) and decode.

    Other characters, including trailing spaces and embedded NULs, are kept.
    """
    if not isinstance(data, (bytes, bytearray, memoryview)):
        raise TypeError(
            f"unpack_string: expected bytes, got {type(data).__name__}")
    raw = bytes(data)
    if raw.endswith(b"\x00"):
        raw = raw[:-1]
    return raw.decode(encoding)


class _Fixed(Protocol[_V_co]):
    """A basic type of a fixed size whose ``unpack`` gives a ``_V_co``."""

    @property
    def fixed_size(self) -> int | None:
        """The encoded size in bytes."""

    def pack(self, value: Any) -> bytes:
        """Encode ``value``."""

    def unpack(self, buffer: Buffer, offset: int = 0) -> tuple[_V_co, int]:
        """Decode one value at ``offset``; return ``(value, size)``."""


class _Pack(Protocol[_V_contra]):
    def __call__(self, value: _V_contra) -> bytes: ...


class _Unpack(Protocol[_V_co]):
    def __call__(self, data: Buffer) -> _V_co: ...


def _helpers(kind: str, datatype: _Fixed[_V], value_type: type[_V],
             what: str, note: str = "") -> tuple[_Pack[_V], _Unpack[_V]]:
    """``pack_<kind>`` and ``unpack_<kind>``: ``datatype``'s encoding of
    ``what``, unpacked from exactly its size (as JCERTI does); ``note``
    ends the docstring of ``unpack_<kind>``.  Their annotations name
    ``value_type`` rather than the type variable, for the reference."""
    size = datatype.fixed_size
    assert size is not None, datatype

    def pack(value: _V) -> bytes:
        return datatype.pack(value)

    def unpack(data: Buffer) -> _V:
        _exact(unpack.__name__, data, size)
        return datatype.unpack(data)[0]

    pack.__doc__ = f"Encode {what} ({size} bytes)."
    unpack.__doc__ = f"Decode exactly {size} bytes as {what}{note}."
    for function, name in ((pack, f"pack_{kind}"), (unpack, f"unpack_{kind}")):
        function.__name__ = function.__qualname__ = name
    pack.__annotations__ = {"value": value_type, "return": bytes}
    unpack.__annotations__ = {"data": Buffer, "return": value_type}
    return pack, unpack


pack_short, unpack_short = _helpers(
    "short", HLAinteger16BE, int, "a 16-bit signed integer, big-endian")
pack_int, unpack_int = _helpers(
    "int", HLAinteger32BE, int, "a 32-bit signed integer, big-endian")
pack_long, unpack_long = _helpers(
    "long", HLAinteger64BE, int, "a 64-bit signed integer, big-endian")
pack_float, unpack_float = _helpers(
    "float", HLAfloat32BE, float, "an IEEE 754 binary32, big-endian")
pack_double, unpack_double = _helpers(
    "double", HLAfloat64BE, float, "an IEEE 754 binary64, big-endian")
pack_boolean, unpack_boolean = _helpers(
    "boolean", HLAboolean, bool,
    "a boolean, a big-endian 32-bit integer 0 or 1",
    "; non-zero is ``True`` (JCERTI)")
