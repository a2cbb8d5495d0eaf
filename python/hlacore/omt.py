"""Encoding helpers for HLA attribute and parameter values.

This module is a pure-Python replacement for PyHLA's ``hla.omt``: a PyHLA
federate ports by changing ``import hla.omt as fom`` into
``import hlacore.omt as fom``.  It provides

* the IEEE 1516.2 basic data types (``HLAinteger32BE``, ``HLAfloat64LE``,
  ``HLAASCIIstring`` ...) as objects with ``pack(value) -> bytes``,
  ``unpack(buffer, offset=0) -> (value, size)`` and ``octetBoundary``;
* the composite type constructors ``HLAfixedArray``, ``HLAvariableArray``,
  ``HLAfixedRecord`` and ``HLAenumerated`` that pad elements and fields to
  their octet boundary (relative to the start of the composite) as the
  IEEE 1516.2 encoding rules require;
* ``HLAboolean`` and ``HLAunicodeString``, which PyHLA lacked;
* the helpers used by Ptolemy II through JCERTI's ``EncodingHelpers``
  (``pack_string``/``unpack_string``, ``pack_int``/``unpack_int`` ...):
  big-endian numbers, booleans as 4-byte integers and strings as UTF-8
  bytes followed by one NUL byte.

Error policy: every ``unpack`` raises ``ValueError`` naming the type and the
number of bytes needed versus available when the buffer is too short, and
never returns a truncated value.  Packing a value that does not fit the
type (an integer out of range, a float too large for ``float32``, a
non-ASCII ``HLAASCIIstring``) raises ``ValueError`` as well; a value of the
wrong kind (a ``str`` for an integer type) raises ``TypeError``.
"""

from __future__ import annotations

import operator
import struct
from collections.abc import Iterable, Mapping, Sequence
from typing import Any, Generic, NoReturn, Protocol, TypeVar, Union

__all__ = [
    "HLAdataType",
    "HLAoctet",
    "HLAinteger16BE",
    "HLAinteger16LE",
    "HLAinteger32BE",
    "HLAinteger32LE",
    "HLAinteger64BE",
    "HLAinteger64LE",
    "HLAfloat32BE",
    "HLAfloat32LE",
    "HLAfloat64BE",
    "HLAfloat64LE",
    "Unsignedinteger16BE",
    "Unsignedinteger32BE",
    "Unsignedinteger64BE",
    "HLAASCIIstring",
    "HLAunicodeString",
    "HLAboolean",
    "HLAfixedArray",
    "HLAvariableArray",
    "HLAfixedRecord",
    "HLAenumerated",
    "HLAenumerator",
    "pack_string",
    "unpack_string",
    "pack_short",
    "unpack_short",
    "pack_int",
    "unpack_int",
    "pack_long",
    "unpack_long",
    "pack_float",
    "unpack_float",
    "pack_double",
    "unpack_double",
    "pack_boolean",
    "unpack_boolean",
]

#: Anything ``unpack`` accepts as its buffer.
Buffer = Union[bytes, bytearray, memoryview]

_V = TypeVar("_V")  # a decoded value
_V_co = TypeVar("_V_co", covariant=True)
_V_contra = TypeVar("_V_contra", contravariant=True)

_COUNT = struct.Struct(">i")  # HLAinteger32BE element/character count
_FLOAT32_MAX = struct.unpack(">f", b"\x7f\x7f\xff\xff")[0]


# --------------------------------------------------------------------------
# internal helpers
# --------------------------------------------------------------------------

def _check_buffer(type_name: str, buffer: Any, offset: Any) -> int:
    """Validate an ``unpack`` buffer/offset pair and return the offset."""
    if not isinstance(buffer, (bytes, bytearray, memoryview)):
        raise TypeError(
            f"{type_name}.unpack: buffer must be bytes, bytearray or "
            f"memoryview, not {type(buffer).__name__}")
    try:
        position: int = operator.index(offset)
    except TypeError:
        raise TypeError(
            f"{type_name}.unpack: offset must be an integer, not "
            f"{type(offset).__name__}") from None
    if position < 0:
        raise ValueError(f"{type_name}.unpack: negative offset {position}")
    return position


def _need(type_name: str, buffer: Buffer, offset: int, needed: int) -> None:
    """Raise ``ValueError`` unless ``needed`` bytes are available at offset."""
    available = len(buffer) - offset
    if available < needed:
        raise ValueError(
            f"{type_name}: need {needed} bytes at offset {offset}, "
            f"only {max(available, 0)} available")


def _counted(type_name: str, buffer: Any, offset: Any,
             unit: int) -> tuple[int, int]:
    """Read the HLAinteger32BE count at ``offset`` of a count-prefixed
    value whose elements take ``unit`` bytes; check that it is not negative
    and that the elements are there; return ``(start, count)``."""
    offset = _check_buffer(type_name, buffer, offset)
    _need(type_name, buffer, offset, 4)
    count: int = _COUNT.unpack_from(buffer, offset)[0]
    if count < 0:
        raise ValueError(f"{type_name}: negative length {count}")
    start = offset + 4
    _need(type_name, buffer, start, unit * count)
    return start, count


def _padding(position: int, boundary: int) -> int:
    """Number of pad bytes to bring ``position`` to a multiple of boundary."""
    return -position % boundary


def _pack_padded(parts: list[bytes], position: int, datatype: HLAdataType,
                 value: Any) -> int:
    """Append the pad bytes that bring ``position`` (in the composite) to
    ``datatype``'s octet boundary, then ``value`` packed, to ``parts``;
    return the position after it."""
    pad = _padding(position, datatype.octetBoundary)
    data = datatype.pack(value)
    if pad:
        parts.append(b"\x00" * pad)
    parts.append(data)
    return position + pad + len(data)


def _as_int(type_name: str, value: Any) -> int:
    """Convert ``value`` to ``int`` via ``__index__``, else ``TypeError``."""
    try:
        return operator.index(value)
    except TypeError:
        raise TypeError(
            f"{type_name}: expected an integer, got "
            f"{type(value).__name__}") from None


def _rethrow(context: str, exc: Exception) -> NoReturn:
    """Re-raise ``exc`` as its KeyError/TypeError/ValueError base class
    with ``context`` (e.g. ``Record.field``) prepended to the message."""
    message = exc.args[0] if len(exc.args) == 1 else str(exc)
    for base in (KeyError, TypeError, ValueError):
        if isinstance(exc, base):
            raise base(f"{context}: {message}") from exc
    raise exc


# --------------------------------------------------------------------------
# base class
# --------------------------------------------------------------------------

class HLAdataType:
    """Base class of every encoding type in this module.

    Subclasses provide ``pack(value) -> bytes`` and
    ``unpack(buffer, offset=0) -> (value, size)`` where ``size`` is the
    number of bytes consumed from ``offset`` on, and set ``name`` and
    ``octetBoundary`` (the alignment, in bytes, of an encoded value).
    """

    name: str
    octetBoundary: int
    #: Encoded size in bytes when it does not depend on the value, else None.
    fixed_size: int | None = None

    def pack(self, value: Any) -> bytes:
        """Encode ``value`` and return the bytes."""
        raise NotImplementedError

    def unpack(self, buffer: Buffer, offset: int = 0) -> tuple[Any, int]:
        """Decode one value at ``offset``; return ``(value, size)``."""
        raise NotImplementedError

    def __repr__(self) -> str:
        """Return ``<hlacore.omt Kind 'name'>``."""
        return f"<hlacore.omt {type(self).__name__} {self.name!r}>"


# --------------------------------------------------------------------------
# basic data types
# --------------------------------------------------------------------------

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
    """A single byte, packed from and unpacked to a 1-byte ``bytes``."""

    octetBoundary = 1
    fixed_size = 1

    def __init__(self) -> None:
        self.name = "HLAoctet"

    def pack(self, value: Any) -> bytes:
        """Encode a 1-byte ``bytes`` (or an int 0..255) as one octet."""
        if isinstance(value, (bytes, bytearray, memoryview)):
            data = bytes(value)
            if len(data) != 1:
                raise ValueError(
                    f"HLAoctet: expected exactly 1 byte, got {len(data)}")
            return data
        number = _as_int(self.name, value)
        if not 0 <= number <= 255:
            raise ValueError(f"HLAoctet: value {number} out of range [0, 255]")
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


#: One octet; ``pack`` takes a 1-byte ``bytes``, ``unpack`` returns one.
HLAoctet = _OctetType()
#: 16-bit signed integer, big-endian.
HLAinteger16BE = _IntegerType("HLAinteger16BE", ">", "h")
#: 16-bit signed integer, little-endian.
HLAinteger16LE = _IntegerType("HLAinteger16LE", "<", "h")
#: 32-bit signed integer, big-endian.
HLAinteger32BE = _IntegerType("HLAinteger32BE", ">", "i")
#: 32-bit signed integer, little-endian.
HLAinteger32LE = _IntegerType("HLAinteger32LE", "<", "i")
#: 64-bit signed integer, big-endian.
HLAinteger64BE = _IntegerType("HLAinteger64BE", ">", "q")
#: 64-bit signed integer, little-endian.
HLAinteger64LE = _IntegerType("HLAinteger64LE", "<", "q")
#: IEEE 754 binary32, big-endian.
HLAfloat32BE = _FloatType("HLAfloat32BE", ">", "f")
#: IEEE 754 binary32, little-endian.
HLAfloat32LE = _FloatType("HLAfloat32LE", "<", "f")
#: IEEE 754 binary64, big-endian.
HLAfloat64BE = _FloatType("HLAfloat64BE", ">", "d")
#: IEEE 754 binary64, little-endian.
HLAfloat64LE = _FloatType("HLAfloat64LE", "<", "d")
#: 16-bit unsigned integer, big-endian (RPR FOM extra).
Unsignedinteger16BE = _IntegerType(
    "Unsignedinteger16BE", ">", "H")
#: 32-bit unsigned integer, big-endian (RPR FOM extra).
Unsignedinteger32BE = _IntegerType(
    "Unsignedinteger32BE", ">", "I")
#: 64-bit unsigned integer, big-endian (RPR FOM extra).
Unsignedinteger64BE = _IntegerType(
    "Unsignedinteger64BE", ">", "Q")
#: Length-prefixed ASCII string; ``unpack`` returns ``bytes`` like PyHLA.
HLAASCIIstring = _ASCIIStringType()
#: Count-prefixed UTF-16BE string (IEEE 1516.2); ``unpack`` returns ``str``.
HLAunicodeString = _UnicodeStringType()
#: Boolean as HLAinteger32BE 0/1; ``unpack`` returns ``bool``.
HLAboolean = _BooleanType()


def _numeric_code(element: HLAdataType) -> tuple[str, str] | None:
    """Return ``(byte_order, struct_code)`` for plain numeric basic types."""
    if isinstance(element, _StructType):
        return element._order, element._code
    return None


# --------------------------------------------------------------------------
# composite data types
# --------------------------------------------------------------------------

class _ArrayBase(HLAdataType):
    """Shared element encoding of fixed and variable arrays."""

    elementType: HLAdataType

    def _pack_elements(self, values: Sequence[Any], start: int) -> list[bytes]:
        """Pack ``values`` as padded elements; ``start`` = position in
        the composite where the first element may begin."""
        parts: list[bytes] = []
        position = start
        for index, value in enumerate(values):
            try:
                position = _pack_padded(parts, position, self.elementType,
                                        value)
            except (ValueError, TypeError, KeyError) as exc:
                _rethrow(f"{self.name}[{index}]", exc)
        return parts

    def _pack_fast(self, values: Sequence[Any]) -> bytes | None:
        """Pack numeric elements with one ``struct`` call, or return None."""
        code = _numeric_code(self.elementType)
        if code is None:
            return None
        try:
            return struct.pack(f"{code[0]}{len(values)}{code[1]}", *values)
        except (struct.error, OverflowError, TypeError):
            return None  # let the element-wise path report the exact error

    def _unpack_elements(self, buffer: Buffer, offset: int, start: int,
                         count: int) -> tuple[tuple[Any, ...], int]:
        """Unpack ``count`` padded elements beginning at composite position
        ``start``; return ``(values, end_position)``."""
        element = self.elementType
        size = element.fixed_size
        code = _numeric_code(element)
        if size is not None and count:
            # Basic fixed-size types never need padding between elements
            # (size is a multiple of the boundary), so the total is exact.
            pad = _padding(start, element.octetBoundary)
            stride = size + _padding(size, element.octetBoundary)
            needed = pad + stride * (count - 1) + size
            _need(self.name, buffer, offset + start, needed)
            if code is not None:
                fmt = f"{code[0]}{count}{code[1]}"
                values = struct.unpack_from(fmt, buffer, offset + start + pad)
                return values, start + needed
        result: list[Any] = []
        position = start
        boundary = element.octetBoundary
        for index in range(count):
            position += _padding(position, boundary)
            try:
                value, used = element.unpack(buffer, offset + position)
            except (ValueError, TypeError) as exc:
                _rethrow(f"{self.name}[{index}]", exc)
            result.append(value)
            position += used
        return tuple(result), position


class HLAfixedArray(_ArrayBase):
    """Array of exactly ``cardinality`` elements of ``elementType``.

    Each element is padded to the element's octet boundary; ``pack`` takes
    a sequence, ``unpack`` returns ``(tuple, size)``.
    """

    def __init__(self, name: str, elementType: HLAdataType,
                 cardinality: int) -> None:
        """Create the type; ``cardinality`` is the exact element count."""
        self.name = name
        self.elementType = elementType
        self.cardinality = operator.index(cardinality)
        if self.cardinality < 0:
            raise ValueError(f"{name}: negative cardinality {cardinality}")
        self.octetBoundary = elementType.octetBoundary
        size = elementType.fixed_size
        if self.cardinality == 0:
            self.fixed_size = 0
        elif size is None:
            self.fixed_size = None
        else:
            stride = size + _padding(size, elementType.octetBoundary)
            self.fixed_size = stride * (self.cardinality - 1) + size

    def pack(self, value: Iterable[Any]) -> bytes:
        """Encode a sequence of exactly ``cardinality`` elements."""
        values = value if isinstance(value, Sequence) else list(value)
        if len(values) != self.cardinality:
            raise ValueError(
                f"{self.name}: expected {self.cardinality} elements, "
                f"got {len(values)}")
        fast = self._pack_fast(values)
        if fast is not None:
            return fast
        return b"".join(self._pack_elements(values, 0))

    def unpack(self, buffer: Buffer, offset: int = 0
               ) -> tuple[tuple[Any, ...], int]:
        """Decode ``cardinality`` elements; return ``(tuple, size)``."""
        offset = _check_buffer(self.name, buffer, offset)
        return self._unpack_elements(buffer, offset, 0, self.cardinality)


class HLAvariableArray(_ArrayBase):
    """Array with an HLAinteger32BE element count prefix.

    Elements follow the count, each padded to the element's octet boundary
    (relative to the start of the array, count included).  ``cardinality``
    is ``None`` (dynamic) or the maximum number of elements, enforced by
    ``pack`` and ``unpack``.
    """

    def __init__(self, name: str, elementType: HLAdataType,
                 cardinality: int | None = None) -> None:
        """Create the type; ``cardinality`` is an optional upper bound."""
        self.name = name
        self.elementType = elementType
        self.cardinality = (None if cardinality is None
                            else operator.index(cardinality))
        self.octetBoundary = max(4, elementType.octetBoundary)

    def _check_count(self, count: int) -> None:
        """Reject element counts that are negative or above cardinality."""
        if count < 0:
            raise ValueError(f"{self.name}: negative element count {count}")
        if self.cardinality is not None and count > self.cardinality:
            raise ValueError(
                f"{self.name}: {count} elements exceed the cardinality "
                f"{self.cardinality}")

    def pack(self, value: Iterable[Any]) -> bytes:
        """Encode a sequence as count + padded elements."""
        values = value if isinstance(value, Sequence) else list(value)
        self._check_count(len(values))
        header = _COUNT.pack(len(values))
        if not values:
            return header
        pad = b"\x00" * _padding(4, self.elementType.octetBoundary)
        fast = self._pack_fast(values)
        if fast is not None:
            return header + pad + fast
        return b"".join([header, *self._pack_elements(values, 4)])

    def unpack(self, buffer: Buffer, offset: int = 0
               ) -> tuple[tuple[Any, ...], int]:
        """Decode count + elements; return ``(tuple, size)``."""
        offset = _check_buffer(self.name, buffer, offset)
        _need(self.name, buffer, offset, 4)
        count = _COUNT.unpack_from(buffer, offset)[0]
        self._check_count(count)
        return self._unpack_elements(buffer, offset, 4, count)


class HLAfixedRecord(HLAdataType):
    """Record of named fields, each padded to its type's octet boundary
    relative to the start of the record.

    ``pack`` takes a mapping ``{fieldName: value}`` (extra keys are
    ignored, a missing field raises ``KeyError``); ``unpack`` returns
    ``(dict, size)`` with the fields in declaration order.
    """

    def __init__(self, name: str,
                 fields: Sequence[tuple[str, HLAdataType]]) -> None:
        """Create the type from ``[(fieldName, type), ...]``."""
        self.name = name
        self.fields: list[tuple[str, HLAdataType]] = [
            (field_name, field_type) for field_name, field_type in fields]
        self.octetBoundary = max(
            (field_type.octetBoundary for _, field_type in self.fields),
            default=1)
        position = 0
        for _, field_type in self.fields:
            if field_type.fixed_size is None:
                self.fixed_size = None
                break
            position += _padding(position, field_type.octetBoundary)
            position += field_type.fixed_size
        else:
            self.fixed_size = position

    def pack(self, value: Mapping[str, Any]) -> bytes:
        """Encode a mapping of field names to values."""
        if not isinstance(value, Mapping):
            raise TypeError(
                f"{self.name}: expected a mapping of field values, got "
                f"{type(value).__name__}")
        parts: list[bytes] = []
        position = 0
        for field_name, field_type in self.fields:
            try:
                field_value = value[field_name]
            except KeyError:
                raise KeyError(
                    f"{self.name}: missing field {field_name!r}") from None
            try:
                position = _pack_padded(parts, position, field_type,
                                        field_value)
            except (ValueError, TypeError, KeyError) as exc:
                _rethrow(f"{self.name}.{field_name}", exc)
        return b"".join(parts)

    def unpack(self, buffer: Buffer, offset: int = 0
               ) -> tuple[dict[str, Any], int]:
        """Decode all fields; return ``(dict, size)``."""
        offset = _check_buffer(self.name, buffer, offset)
        result: dict[str, Any] = {}
        position = 0
        for field_name, field_type in self.fields:
            position += _padding(position, field_type.octetBoundary)
            try:
                result[field_name], used = field_type.unpack(
                    buffer, offset + position)
            except (ValueError, TypeError) as exc:
                _rethrow(f"{self.name}.{field_name}", exc)
            position += used
        return result, position


class HLAenumerator(int):
    """One value of an :class:`HLAenumerated` type: an ``int`` that knows
    its name (``str()``) and its type (``repr()`` gives ``Type.Name``)."""

    name: str
    enumeration: str

    def __new__(cls, enumeration: str, name: str, value: int
                ) -> HLAenumerator:
        """Create the enumerator ``enumeration.name`` equal to ``value``."""
        self = super().__new__(cls, value)
        self.name = name
        self.enumeration = enumeration
        return self

    def __repr__(self) -> str:
        """Return ``Enumeration.Name``."""
        return f"{self.enumeration}.{self.name}"

    def __str__(self) -> str:
        """Return the enumerator name."""
        return self.name

    def __reduce__(self) -> tuple[Any, ...]:
        """Pickle support."""
        return (HLAenumerator, (self.enumeration, self.name, int(self)))


class HLAenumerated(HLAdataType):
    """Enumeration encoded with an integer ``representation`` type.

    Enumerators are attributes (``Enum.Little``) and items
    (``Enum["Little"]``) of the type and are :class:`HLAenumerator`
    (``int`` subclass) instances.  ``pack`` accepts an enumerator, its
    integer value or its name; ``unpack`` returns the enumerator and raises
    ``ValueError`` for a value that is not one of the enumerators.
    """

    def __init__(self, name: str, representation: HLAdataType,
                 enumerators: Mapping[str, int]) -> None:
        """Create the type from ``{enumeratorName: value}``."""
        self.name = name
        self.representation = representation
        self.octetBoundary = representation.octetBoundary
        self.fixed_size = representation.fixed_size
        self.enumerators: dict[str, HLAenumerator] = {}
        self._by_value: dict[int, HLAenumerator] = {}
        for enum_name, enum_value in enumerators.items():
            enumerator = HLAenumerator(name, enum_name,
                                       operator.index(enum_value))
            representation.pack(int(enumerator))  # validate the range early
            self.enumerators[enum_name] = enumerator
            self._by_value.setdefault(int(enumerator), enumerator)

    def __getattr__(self, attribute: str) -> HLAenumerator:
        """Return the enumerator called ``attribute``."""
        enumerators: dict[str, HLAenumerator] = self.__dict__.get(
            "enumerators", {})
        try:
            return enumerators[attribute]
        except KeyError:
            raise AttributeError(
                f"{self.__dict__.get('name', 'HLAenumerated')!s} has no "
                f"enumerator {attribute!r}") from None

    def __getitem__(self, enumerator_name: str) -> HLAenumerator:
        """Return the enumerator called ``enumerator_name``."""
        return self.enumerators[enumerator_name]

    def __iter__(self) -> Any:
        """Iterate over the enumerators in declaration order."""
        return iter(self.enumerators.values())

    def __len__(self) -> int:
        """Return the number of enumerators."""
        return len(self.enumerators)

    def pack(self, value: Any) -> bytes:
        """Encode an enumerator, its integer value or its name."""
        if isinstance(value, str):
            try:
                value = self.enumerators[value]
            except KeyError:
                raise ValueError(
                    f"{self.name}: unknown enumerator {value!r}") from None
        number = _as_int(self.name, value)
        if number not in self._by_value:
            raise ValueError(
                f"{self.name}: {number} is not an enumerator value")
        return self.representation.pack(number)

    def unpack(self, buffer: Buffer, offset: int = 0
               ) -> tuple[HLAenumerator, int]:
        """Decode an enumerator; return ``(enumerator, size)``."""
        try:
            number, used = self.representation.unpack(buffer, offset)
        except ValueError as exc:
            _rethrow(self.name, exc)
        try:
            return self._by_value[number], used
        except KeyError:
            raise ValueError(
                f"{self.name}: {number} is not an enumerator value") from None


# --------------------------------------------------------------------------
# Ptolemy II / JCERTI EncodingHelpers compatible helpers
# --------------------------------------------------------------------------

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
    def fixed_size(self) -> int | None: ...

    def pack(self, value: Any) -> bytes: ...

    def unpack(self, buffer: Buffer, offset: int = 0) -> tuple[_V_co, int]: ...


class _Pack(Protocol[_V_contra]):
    def __call__(self, value: _V_contra) -> bytes: ...


class _Unpack(Protocol[_V_co]):
    def __call__(self, data: Buffer) -> _V_co: ...


def _helpers(kind: str, datatype: _Fixed[_V], what: str,
             note: str = "") -> tuple[_Pack[_V], _Unpack[_V]]:
    """``pack_<kind>`` and ``unpack_<kind>``: ``datatype``'s encoding of
    ``what``, unpacked from exactly its size (as JCERTI does); ``note``
    ends the docstring of ``unpack_<kind>``."""
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
    return pack, unpack


pack_short, unpack_short = _helpers(
    "short", HLAinteger16BE, "a 16-bit signed integer, big-endian")
pack_int, unpack_int = _helpers(
    "int", HLAinteger32BE, "a 32-bit signed integer, big-endian")
pack_long, unpack_long = _helpers(
    "long", HLAinteger64BE, "a 64-bit signed integer, big-endian")
pack_float, unpack_float = _helpers(
    "float", HLAfloat32BE, "an IEEE 754 binary32, big-endian")
pack_double, unpack_double = _helpers(
    "double", HLAfloat64BE, "an IEEE 754 binary64, big-endian")
pack_boolean, unpack_boolean = _helpers(
    "boolean", HLAboolean, "a boolean, a big-endian 32-bit integer 0 or 1",
    "; non-zero is ``True`` (JCERTI)")
