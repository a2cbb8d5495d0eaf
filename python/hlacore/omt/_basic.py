"""The basic data types: IEEE 1516.2's integers, floats, octets, booleans and strings, and the MIM's names
that FOMs use without defining them."""

from __future__ import annotations

import struct
from typing import Any, Generic, TypeVar

from ._base import HLAdataType
from ._bytes import _COUNT, Buffer, _as_int, _check_buffer, _counted, _need

_V = TypeVar("_V")  # a decoded value

_FLOAT32_MAX = struct.unpack(">f", b"\x7f\x7f\xff\xff")[0]


class _StructType(HLAdataType, Generic[_V]):
    """A number that one ``struct`` code encodes (``order``: ``>`` or ``<``)."""

    def __init__(self, name: str, order: str, code: str) -> None:
        self.name = name
        self._order = order
        self._code = code
        self._struct = struct.Struct(order + code)
        self.octetBoundary = self._struct.size
        self.fixed_size = self._struct.size

    def unpack(self, buffer: Buffer, offset: int = 0) -> tuple[_V, int]:
        """Decode a number at ``offset``; return ``(value, size)``."""
        offset = _check_buffer(self.name, buffer, offset)
        size = self._struct.size
        _need(self.name, buffer, offset, size)
        return self._struct.unpack_from(buffer, offset)[0], size


class _IntegerType(_StructType[int]):
    """Fixed-size two's complement or unsigned integer."""

    def __init__(self, name: str, order: str, code: str) -> None:
        super().__init__(name, order, code)
        size = self._struct.size
        if code.isupper():
            self._min, self._max = 0, (1 << (8 * size)) - 1
        else:
            self._min = -(1 << (8 * size - 1))
            self._max = (1 << (8 * size - 1)) - 1

    def pack(self, value: Any) -> bytes:
        """Encode an integer; ``ValueError`` if it does not fit the type."""
        number = _as_int(self.name, value)
        if not self._min <= number <= self._max:
            raise ValueError(
                f"{self.name}: value {number} out of range "
                f"[{self._min}, {self._max}]")
        return self._struct.pack(number)


class _FloatType(_StructType[float]):
    """IEEE 754 binary32 or binary64 number."""

    def __init__(self, name: str, order: str, code: str) -> None:
        super().__init__(name, order, code)
        self._max = _FLOAT32_MAX if code == "f" else 1.7976931348623157e308

    def pack(self, value: Any) -> bytes:
        """Encode a float; ``ValueError`` if too large for a float32."""
        if isinstance(value, (str, bytes, bytearray)):
            raise TypeError(
                f"{self.name}: expected a number, got {type(value).__name__}")
        try:
            return self._struct.pack(value)
        except struct.error:
            raise TypeError(
                f"{self.name}: expected a number, got "
                f"{type(value).__name__}") from None
        except OverflowError:
            raise ValueError(
                f"{self.name}: value {value!r} out of range (largest finite "
                f"magnitude is {self._max!r})") from None


class _OctetType(HLAdataType):
    """A single byte, packed from and unpacked to a 1-byte ``bytes``
    (``HLAoctet``, ``HLAbyte``; ``HLAASCIIchar`` also packs a
    one-character ASCII ``str``)."""

    octetBoundary = 1
    fixed_size = 1

    def __init__(self, name: str = "HLAoctet", text: bool = False) -> None:
        self.name = name
        self._text = text

    def pack(self, value: Any) -> bytes:
        """Encode a 1-byte ``bytes`` (or an int 0..255) as one octet."""
        if isinstance(value, (bytes, bytearray, memoryview)):
            data = bytes(value)
            if len(data) != 1:
                raise ValueError(
                    f"{self.name}: expected exactly 1 byte, got {len(data)}")
            return data
        if self._text and isinstance(value, str):
            if len(value) != 1 or not value.isascii():
                raise ValueError(
                    f"{self.name}: expected one ASCII character, got "
                    f"{value!r}")
            return value.encode("ascii")
        number = _as_int(self.name, value)
        if not 0 <= number <= 255:
            raise ValueError(
                f"{self.name}: value {number} out of range [0, 255]")
        return bytes((number,))

    def unpack(self, buffer: Buffer, offset: int = 0) -> tuple[bytes, int]:
        """Decode one octet at ``offset``; return ``(bytes_of_len_1, 1)``."""
        offset = _check_buffer(self.name, buffer, offset)
        _need(self.name, buffer, offset, 1)
        return bytes(buffer[offset:offset + 1]), 1


class _BooleanType(HLAdataType):
    """``HLAboolean``: an HLAinteger32BE holding 0 (false) or 1 (true)."""

    octetBoundary = 4
    fixed_size = 4

    def __init__(self) -> None:
        self.name = "HLAboolean"

    def pack(self, value: Any) -> bytes:
        """Encode ``True``/``False`` (or 1/0) as a 4-byte big-endian int."""
        if value is True or value is False:
            return _COUNT.pack(int(value))
        if isinstance(value, (str, bytes, bytearray)):
            raise TypeError(
                f"HLAboolean: expected a bool, got {type(value).__name__}")
        if value == 1:
            return _COUNT.pack(1)
        if value == 0:
            return _COUNT.pack(0)
        raise ValueError(f"HLAboolean: expected True/False or 1/0, "
                         f"got {value!r}")

    def unpack(self, buffer: Buffer, offset: int = 0) -> tuple[bool, int]:
        """Decode a boolean at ``offset``; any non-zero value is ``True``."""
        offset = _check_buffer(self.name, buffer, offset)
        _need(self.name, buffer, offset, 4)
        return _COUNT.unpack_from(buffer, offset)[0] != 0, 4


class _ASCIIStringType(HLAdataType):
    """``HLAASCIIstring``: HLAinteger32BE length followed by the bytes."""

    octetBoundary = 4

    def __init__(self) -> None:
        self.name = "HLAASCIIstring"

    def pack(self, value: Any) -> bytes:
        """Encode a ``str`` (ASCII only) or ``bytes`` with a length prefix."""
        if isinstance(value, str):
            try:
                data = value.encode("ascii")
            except UnicodeEncodeError as exc:
                bad = exc.object[exc.start]
                raise ValueError(
                    f"HLAASCIIstring: non-ASCII character {bad!r} "
                    f"at index {exc.start}") from None
        elif isinstance(value, (bytes, bytearray, memoryview)):
            data = bytes(value)
        else:
            raise TypeError(
                f"HLAASCIIstring: expected str or bytes, got "
                f"{type(value).__name__}")
        return _COUNT.pack(len(data)) + data

    def unpack(self, buffer: Buffer, offset: int = 0) -> tuple[bytes, int]:
        """Decode at ``offset``; return ``(bytes, 4 + length)`` like PyHLA."""
        start, length = _counted(self.name, buffer, offset, 1)
        return bytes(buffer[start:start + length]), 4 + length


class _UnicodeStringType(HLAdataType):
    """``HLAunicodeString``: HLAinteger32BE count of UTF-16 code units,
    then the UTF-16BE data (IEEE 1516.2 form)."""

    octetBoundary = 4

    def __init__(self) -> None:
        self.name = "HLAunicodeString"

    def pack(self, value: Any) -> bytes:
        """Encode a ``str`` as count + UTF-16BE code units."""
        if not isinstance(value, str):
            raise TypeError(
                f"HLAunicodeString: expected str, got {type(value).__name__}")
        try:
            data = value.encode("utf-16-be")
        except UnicodeEncodeError as exc:
            raise ValueError(
                f"HLAunicodeString: cannot encode: {exc}") from None
        return _COUNT.pack(len(data) // 2) + data

    def unpack(self, buffer: Buffer, offset: int = 0) -> tuple[str, int]:
        """Decode at ``offset``; return ``(str, 4 + 2 * count)``."""
        start, count = _counted(self.name, buffer, offset, 2)
        try:
            text = bytes(buffer[start:start + 2 * count]).decode("utf-16-be")
        except UnicodeDecodeError as exc:
            raise ValueError(
                f"HLAunicodeString: invalid UTF-16: {exc}") from None
        return text, 4 + 2 * count


class _UnicodeCharType(HLAdataType):
    """``HLAunicodeChar``: one UTF-16 code unit, big-endian
    (``HLAoctetPairBE``); packs a one-character ``str`` of the Basic
    Multilingual Plane (or an int 0..65535), unpacks to a ``str``."""

    octetBoundary = 2
    fixed_size = 2
    _struct = struct.Struct(">H")

    def __init__(self) -> None:
        self.name = "HLAunicodeChar"

    def pack(self, value: Any) -> bytes:
        """Encode one character as its 16-bit code unit."""
        if isinstance(value, str):
            if len(value) != 1 or ord(value) > 0xFFFF:
                raise ValueError(
                    f"{self.name}: expected one character of the Basic "
                    f"Multilingual Plane, got {value!r}")
            return self._struct.pack(ord(value))
        number = _as_int(self.name, value)
        if not 0 <= number <= 0xFFFF:
            raise ValueError(
                f"{self.name}: value {number} out of range [0, 65535]")
        return self._struct.pack(number)

    def unpack(self, buffer: Buffer, offset: int = 0) -> tuple[str, int]:
        """Decode one code unit at ``offset``; return ``(str, 2)``."""
        offset = _check_buffer(self.name, buffer, offset)
        _need(self.name, buffer, offset, 2)
        return chr(self._struct.unpack_from(buffer, offset)[0]), 2


class _OpaqueDataType(HLAdataType):
    """``HLAopaqueData``: HLAinteger32BE byte count followed by the bytes."""

    octetBoundary = 4

    def __init__(self) -> None:
        self.name = "HLAopaqueData"

    def pack(self, value: Any) -> bytes:
        """Encode a ``bytes``-like value with a count prefix."""
        if not isinstance(value, (bytes, bytearray, memoryview)):
            raise TypeError(
                f"{self.name}: expected bytes, got {type(value).__name__}")
        data = bytes(value)
        return _COUNT.pack(len(data)) + data

    def unpack(self, buffer: Buffer, offset: int = 0) -> tuple[bytes, int]:
        """Decode at ``offset``; return ``(bytes, 4 + count)``."""
        start, length = _counted(self.name, buffer, offset, 1)
        return bytes(buffer[start:start + length]), 4 + length


_T = TypeVar("_T", bound=HLAdataType)


def _documented(datatype: _T, doc: str) -> _T:
    """``datatype`` with ``doc`` as its own docstring: ``inspect.getdoc`` and the API reference show it
    rather than its class's."""
    datatype.__doc__ = doc
    return datatype


_ENDIAN = {">": "big-endian", "<": "little-endian"}


def _integer(name: str, order: str, code: str, note: str = "") -> _IntegerType:
    """The integer type ``name``, documented by its size, signedness and byte order (then ``note``)."""
    kind = "unsigned" if code.isupper() else "signed"
    bits = 8 * struct.calcsize(order + code)
    return _documented(_IntegerType(name, order, code), f"{bits}-bit {kind} integer, {_ENDIAN[order]}{note}.")


def _float(name: str, order: str, code: str) -> _FloatType:
    """The float type ``name``, documented by its IEEE 754 format and byte order."""
    bits = 8 * struct.calcsize(order + code)
    return _documented(_FloatType(name, order, code), f"IEEE 754 binary{bits}, {_ENDIAN[order]}.")


HLAoctet = _documented(
    _OctetType(),
    "One octet; ``pack`` takes a 1-byte ``bytes``, ``unpack`` returns one.")
HLAbyte = _documented(
    _OctetType("HLAbyte"),
    "The MIM's ``HLAbyte``: one octet, like ``HLAoctet``.")
HLAASCIIchar = _documented(
    _OctetType("HLAASCIIchar", text=True),
    "The MIM's ``HLAASCIIchar``: one octet; ``pack`` also takes a one-character ASCII ``str``, ``unpack`` "
    "returns a 1-byte ``bytes``.")
HLAoctetPairBE = _documented(
    _IntegerType("HLAoctetPairBE", ">", "H"),
    "The MIM's ``HLAoctetPairBE``: 16 bits, big-endian, as an int 0..65535.")
HLAoctetPairLE = _documented(
    _IntegerType("HLAoctetPairLE", "<", "H"),
    "The MIM's ``HLAoctetPairLE``: 16 bits, little-endian, as an int 0..65535.")
HLAunicodeChar = _documented(
    _UnicodeCharType(),
    "The MIM's ``HLAunicodeChar``: one UTF-16BE code unit; ``pack`` takes a one-character ``str`` (or its "
    "code), ``unpack`` returns a ``str``.")
HLAinteger16BE = _integer("HLAinteger16BE", ">", "h")
HLAinteger16LE = _integer("HLAinteger16LE", "<", "h")
HLAinteger32BE = _integer("HLAinteger32BE", ">", "i")
HLAinteger32LE = _integer("HLAinteger32LE", "<", "i")
HLAinteger64BE = _integer("HLAinteger64BE", ">", "q")
HLAinteger64LE = _integer("HLAinteger64LE", "<", "q")
HLAfloat32BE = _float("HLAfloat32BE", ">", "f")
HLAfloat32LE = _float("HLAfloat32LE", "<", "f")
HLAfloat64BE = _float("HLAfloat64BE", ">", "d")
HLAfloat64LE = _float("HLAfloat64LE", "<", "d")
Unsignedinteger16BE = _integer("Unsignedinteger16BE", ">", "H", " (RPR FOM extra)")
Unsignedinteger32BE = _integer("Unsignedinteger32BE", ">", "I", " (RPR FOM extra)")
Unsignedinteger64BE = _integer("Unsignedinteger64BE", ">", "Q", " (RPR FOM extra)")
HLAASCIIstring = _documented(
    _ASCIIStringType(),
    "Length-prefixed ASCII string; ``unpack`` returns ``bytes`` like PyHLA.")
HLAunicodeString = _documented(
    _UnicodeStringType(),
    "Count-prefixed UTF-16BE string (IEEE 1516.2); ``unpack`` returns ``str``.")
HLAopaqueData = _documented(
    _OpaqueDataType(),
    "The MIM's ``HLAopaqueData``: HLAinteger32BE count + bytes; ``pack`` takes and ``unpack`` returns "
    "``bytes``.")
HLAboolean = _documented(
    _BooleanType(),
    "Boolean as HLAinteger32BE 0/1; ``unpack`` returns ``bool``. (The 1516-2010 MIM declares "
    "``HLAboolean`` as an enumeration of ``HLAfalse`` and ``HLAtrue``; the encoding is the same.)")
