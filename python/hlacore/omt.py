"""Encoding helpers for HLA attribute and parameter values.

This module is a pure-Python replacement for PyHLA's ``hla.omt``: a PyHLA
federate ports by changing ``import hla.omt as fom`` into
``import hlacore.omt as fom``.  It provides

* the IEEE 1516.2 basic data types (``HLAinteger32BE``, ``HLAfloat64LE``,
  ``HLAASCIIstring`` ...) as objects with ``pack(value) -> bytes``,
  ``unpack(buffer, offset=0) -> (value, size)`` and ``octetBoundary``;
* the standard names of the IEEE 1516.2 MIM that FOMs reference without
  defining them: ``HLAbyte`` and ``HLAASCIIchar`` (one octet),
  ``HLAunicodeChar``, ``HLAoctetPairBE`` and ``HLAoctetPairLE`` (16 bits)
  and ``HLAopaqueData`` (count-prefixed bytes);
* the composite type constructors ``HLAfixedArray``, ``HLAvariableArray``,
  ``HLAfixedRecord``, ``HLAvariantRecord`` and ``HLAenumerated`` that pad
  elements and fields to their octet boundary (relative to the start of
  the composite) as the IEEE 1516.2 encoding rules require;
* ``HLAencoding(name)``, PyHLA's forward reference to a data type defined
  later in this module's namespace;
* ``HLAuse(filename)``, which reads the data types of an IEEE 1516-2000 or
  1516-2010 OMT/FOM XML file and defines them in this module, as PyHLA's
  does (``fom.HLAuse("robot.xml"); fom.Pose.pack(...)``);
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
wrong kind (a ``str`` for an integer type) raises ``TypeError``; a missing
record field raises ``KeyError``.  A composite type prefixes the message
with where the error is (``Record.field``, ``Array[3]``).  A forward
reference that names no data type raises ``KeyError`` when used, and a
type whose encoding this module does not implement (a FOM's
``RPRnullTerminatedArray``, say) raises ``NotImplementedError`` when
packed or unpacked.
"""

from __future__ import annotations

import operator
import os
import re
import struct
import xml.etree.ElementTree as ElementTree
from collections.abc import Callable, Iterable, Mapping, Sequence
from typing import (Any, Generic, NamedTuple, NoReturn, Protocol, TypeVar,
                    Union, overload)

__all__ = [
    "HLAdataType",
    "HLAoctet",
    "HLAbyte",
    "HLAASCIIchar",
    "HLAunicodeChar",
    "HLAoctetPairBE",
    "HLAoctetPairLE",
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
    "HLAopaqueData",
    "HLAboolean",
    "HLAfixedArray",
    "HLAvariableArray",
    "HLAfixedRecord",
    "HLAvariantRecord",
    "HLAenumerated",
    "HLAenumerator",
    "HLAencoding",
    "HLAuse",
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

#: The errors a component's ``pack``/``unpack`` may raise that a composite
#: re-raises with its context (``Record.field``) prepended.
_ERRORS = (ValueError, TypeError, KeyError, NotImplementedError)


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


def _member(owner: str, member: str | int) -> str:
    """How an error names a composite's member: ``Record.field`` or
    ``Array[3]``."""
    if isinstance(member, int):
        return f"{owner}[{member}]"
    return f"{owner}.{member}"


def _pack_padded(owner: str, member: str | int, parts: list[bytes],
                 position: int, datatype: HLAdataType, value: Any) -> int:
    """Append the pad bytes that bring ``position`` (in the composite) to
    ``datatype``'s octet boundary, then ``value`` packed, to ``parts``;
    return the position after it; errors name the member (see
    :func:`_member`, called only then: formatting costs)."""
    try:
        pad = _padding(position, datatype.octetBoundary)
        data = datatype.pack(value)
    except _ERRORS as exc:
        _rethrow(_member(owner, member), exc)
    if pad:
        parts.append(b"\x00" * pad)
    parts.append(data)
    return position + pad + len(data)


def _unpack_padded(owner: str, member: str | int, datatype: HLAdataType,
                   buffer: Buffer, offset: int, position: int
                   ) -> tuple[Any, int]:
    """Decode a ``datatype`` value at ``position`` in the composite that
    starts at ``offset``, after the pad bytes to its octet boundary; return
    ``(value, position after it)``; errors name the member as
    :func:`_pack_padded`'s do."""
    try:
        position += _padding(position, datatype.octetBoundary)
        value, used = datatype.unpack(buffer, offset + position)
    except _ERRORS as exc:
        _rethrow(_member(owner, member), exc)
    return value, position + used


def _as_int(type_name: str, value: Any) -> int:
    """Convert ``value`` to ``int`` via ``__index__``, else ``TypeError``."""
    try:
        return operator.index(value)
    except TypeError:
        raise TypeError(
            f"{type_name}: expected an integer, got "
            f"{type(value).__name__}") from None


def _rethrow(context: str, exc: Exception) -> NoReturn:
    """Re-raise ``exc`` as its KeyError/TypeError/ValueError/
    NotImplementedError base class with ``context`` (e.g.
    ``Record.field``) prepended to the message."""
    message = exc.args[0] if len(exc.args) == 1 else str(exc)
    for base in _ERRORS:
        if isinstance(exc, base):
            raise base(f"{context}: {message}") from exc
    raise exc


def _show(value: Any) -> str:
    """Render a discriminant value for an error message."""
    return str(value) if isinstance(value, HLAenumerator) else repr(value)


# --------------------------------------------------------------------------
# base classes
# --------------------------------------------------------------------------

class HLAdataType:
    """Base class of every encoding type in this module.

    Subclasses provide ``pack(value) -> bytes`` and
    ``unpack(buffer, offset=0) -> (value, size)`` where ``size`` is the
    number of bytes consumed from ``offset`` on, and set ``name`` and
    ``octetBoundary`` (the alignment, in bytes, of an encoded value).
    """

    name: str
    #: Alignment, in bytes, of an encoded value: a composite pads each
    #: element or field to its type's octet boundary.
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


def _pending(datatype: HLAdataType) -> bool:
    """Whether ``datatype``'s layout cannot be computed yet: an unresolved
    :class:`HLAencoding`, or a composite that contains one."""
    if isinstance(datatype, HLAencoding):
        if datatype._encoding is None:
            return True
        datatype = datatype._encoding
    return isinstance(datatype, _Composite) and datatype._layout_state != 2


class _LayoutAttribute(Generic[_V]):
    """``octetBoundary`` or ``fixed_size`` of a :class:`_Composite`: computed
    on first access, then kept in the instance's ``__dict__``, where later
    accesses find it directly (this descriptor has no ``__set__``)."""

    def __init__(self, doc: str) -> None:
        self.__doc__ = doc
        self.attribute = ""

    def __set_name__(self, owner: type, name: str) -> None:
        self.attribute = name

    @overload
    def __get__(self, instance: None, owner: type) -> _LayoutAttribute[_V]: ...

    @overload
    def __get__(self, instance: _Composite, owner: type) -> _V: ...

    def __get__(self, instance: _Composite | None, owner: type) -> Any:
        if instance is None:
            return self
        instance._layout()
        return instance.__dict__[self.attribute]


class _Composite(HLAdataType):
    """A data type built from other data types, any of which may be a
    forward reference (:class:`HLAencoding`) resolved on first use.

    ``octetBoundary`` and ``fixed_size`` are computed by
    ``_compute_layout`` when first needed; the constructor computes them
    at once when no component is pending, so that a definition error
    surfaces where the type is created.
    """

    _layout_state = 0  # 0: not computed, 1: being computed, 2: done

    #: Alignment, in bytes, of an encoded value (computed on first use when
    #: the type refers to a type not yet defined).
    octetBoundary = _LayoutAttribute[int](
        "Alignment, in bytes, of an encoded value (computed on first use "
        "when the type refers to a type not yet defined).")
    #: Encoded size in bytes when it does not depend on the value, else None.
    fixed_size = _LayoutAttribute[Union[int, None]](
        "Encoded size in bytes when it does not depend on the value, else "
        "``None``.")

    def _components(self) -> Iterable[HLAdataType]:
        """The data types this one is built from."""
        return ()

    def _compute_layout(self) -> tuple[int, int | None]:
        """Return ``(octetBoundary, fixed_size)``; may check the definition."""
        raise NotImplementedError

    def _layout(self) -> None:
        """Compute the layout unless it is known; detect recursion."""
        if self._layout_state == 2:
            return
        if self._layout_state == 1:
            raise NotImplementedError(
                f"{self.name}: recursive data type (its encoding contains "
                f"itself), which hlacore.omt does not support")
        self._layout_state = 1
        try:
            boundary, size = self._compute_layout()
        except BaseException:
            self._layout_state = 0
            raise
        self.__dict__["octetBoundary"] = boundary
        self.__dict__["fixed_size"] = size
        self._layout_state = 2

    def _layout_if_ready(self) -> None:
        """Compute the layout now unless a component is pending."""
        if not any(_pending(component) for component in self._components()):
            self._layout()


class HLAencoding(HLAdataType):
    """PyHLA's lazy reference to a data type: ``HLAencoding("Pose")`` is a
    data type that looks ``Pose`` up in this module's namespace on first
    use (``pack``, ``unpack``, ``octetBoundary``), so a type may be
    referenced before it is defined::

        fom.Path = fom.HLAvariableArray("Path", fom.HLAencoding("Pose"))
        fom.Pose = fom.HLAfixedRecord("Pose", [("x", fom.HLAfloat64BE)])
        fom.Path.pack([{"x": 1.0}])

    With ``typeParameters``, ``representation`` names a type constructor
    of this module (``"HLAfixedArray"`` ...) called on first use with the
    parameters: a tuple or list is passed as positional arguments, a
    mapping as keyword arguments (PyHLA passed the tuple as one argument,
    which its own constructors did not accept)::

        fom.HLAencoding("HLAfixedArray", ("Vector", fom.HLAfloat32BE, 3))

    The name is resolved once; the result is kept.  A name that is not a
    data type of this module when first used raises ``KeyError`` naming
    it (and is looked up again on the next use); a chain of references
    that leads back to itself raises ``ValueError``.  Other attributes
    (``fields``, ``enumerators`` ...) are those of the resolved type.
    """

    def __init__(self, representation: str,
                 typeParameters: Any = None) -> None:
        """Refer to the data type (or constructor) named ``representation``."""
        if not isinstance(representation, str):
            raise TypeError(
                f"HLAencoding: representation must be a type name (str), "
                f"not {type(representation).__name__}")
        self.representation = representation
        self.typeParameters = typeParameters
        first = (typeParameters[0] if isinstance(typeParameters, (tuple, list))
                 and typeParameters else None)
        self.name = first if isinstance(first, str) else representation
        self._encoding: HLAdataType | None = None
        self._resolving = False

    def _resolve(self) -> HLAdataType:
        """Find or build the referenced data type."""
        if self.typeParameters is None:
            found = _lookup_type(self.representation)
            if found is None:
                raise KeyError(
                    f"HLAencoding: no data type named "
                    f"{self.representation!r} in hlacore.omt")
            return found
        constructor = globals().get(self.representation)
        if not (isinstance(constructor, type)
                and issubclass(constructor, HLAdataType)):
            raise KeyError(
                f"HLAencoding: no data type constructor named "
                f"{self.representation!r} in hlacore.omt")
        build: Callable[..., HLAdataType] = constructor
        parameters = self.typeParameters
        if isinstance(parameters, Mapping):
            return build(**parameters)
        if isinstance(parameters, (tuple, list)):
            return build(*parameters)
        return build(parameters)

    @property
    def resolved(self) -> bool:
        """Whether the reference has been resolved."""
        return self._encoding is not None

    @property
    def encoding(self) -> HLAdataType:
        """The referenced data type, resolved on first access (following
        references to references)."""
        target = self._encoding
        if target is None:
            if self._resolving:
                raise ValueError(
                    f"HLAencoding {self.name!r}: circular reference (the "
                    f"name leads back to itself)")
            self._resolving = True
            try:
                target = self._resolve()
                if isinstance(target, HLAencoding):
                    target = target.encoding
            finally:
                self._resolving = False
            self._encoding = target
        return target

    @property
    def octetBoundary(self) -> int:
        """The referenced type's ``octetBoundary``."""
        return self.encoding.octetBoundary

    @octetBoundary.setter
    def octetBoundary(self, value: int) -> None:
        raise AttributeError(f"{self.name}: octetBoundary is read-only")

    @property
    def fixed_size(self) -> int | None:
        """The referenced type's ``fixed_size``."""
        return self.encoding.fixed_size

    @fixed_size.setter
    def fixed_size(self, value: int | None) -> None:
        raise AttributeError(f"{self.name}: fixed_size is read-only")

    def pack(self, value: Any) -> bytes:
        """Encode ``value`` with the referenced type."""
        return self.encoding.pack(value)

    def unpack(self, buffer: Buffer, offset: int = 0) -> tuple[Any, int]:
        """Decode with the referenced type; return ``(value, size)``."""
        return self.encoding.unpack(buffer, offset)

    def __getattr__(self, attribute: str) -> Any:
        """Return the attribute of the referenced type."""
        if attribute.startswith("_"):
            raise AttributeError(attribute)
        return getattr(self.encoding, attribute)


class _Reference(HLAencoding):
    """A reference made by :func:`HLAuse`: resolved by ``resolver`` (a type
    of the same file), or else looked up in the module on first use; the
    error names the file and the type that used the name."""

    def __init__(self, name: str,
                 resolver: Callable[[], HLAdataType] | None,
                 context: str) -> None:
        super().__init__(name)
        self._resolver = resolver
        self._context = context

    def _resolve(self) -> HLAdataType:
        if self._resolver is not None:
            return self._resolver()
        found = _lookup_type(self.representation)
        if found is None:
            raise KeyError(
                f"data type {self.representation!r} ({self._context}) is not "
                f"defined in hlacore.omt")
        return found


def _target(datatype: HLAdataType) -> HLAdataType:
    """The data type behind ``datatype``, resolving forward references."""
    return datatype.encoding if isinstance(datatype, HLAencoding) else datatype


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


#: One octet; ``pack`` takes a 1-byte ``bytes``, ``unpack`` returns one.
HLAoctet = _OctetType()
#: The MIM's ``HLAbyte``: one octet, like ``HLAoctet``.
HLAbyte = _OctetType("HLAbyte")
#: The MIM's ``HLAASCIIchar``: one octet; ``pack`` also takes a
#: one-character ASCII ``str``, ``unpack`` returns a 1-byte ``bytes``.
HLAASCIIchar = _OctetType("HLAASCIIchar", text=True)
#: The MIM's ``HLAoctetPairBE``: 16 bits, big-endian, as an int 0..65535.
HLAoctetPairBE = _IntegerType("HLAoctetPairBE", ">", "H")
#: The MIM's ``HLAoctetPairLE``: 16 bits, little-endian, as an int 0..65535.
HLAoctetPairLE = _IntegerType("HLAoctetPairLE", "<", "H")
#: The MIM's ``HLAunicodeChar``: one UTF-16BE code unit; ``pack`` takes a
#: one-character ``str`` (or its code), ``unpack`` returns a ``str``.
HLAunicodeChar = _UnicodeCharType()
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
#: The MIM's ``HLAopaqueData``: HLAinteger32BE count + bytes; ``pack``
#: takes and ``unpack`` returns ``bytes``.
HLAopaqueData = _OpaqueDataType()
#: Boolean as HLAinteger32BE 0/1; ``unpack`` returns ``bool``.  (The
#: 1516-2010 MIM declares ``HLAboolean`` as an enumeration of ``HLAfalse``
#: and ``HLAtrue``; the encoding is the same.)
HLAboolean = _BooleanType()


def _numeric_code(element: HLAdataType) -> tuple[str, str] | None:
    """Return ``(byte_order, struct_code)`` for plain numeric basic types."""
    if isinstance(element, HLAencoding):
        element = element.encoding
    if isinstance(element, _StructType):
        return element._order, element._code
    return None


# --------------------------------------------------------------------------
# composite data types
# --------------------------------------------------------------------------

class _ArrayBase(_Composite):
    """Shared element encoding of fixed and variable arrays."""

    elementType: HLAdataType

    def _components(self) -> Iterable[HLAdataType]:
        return (self.elementType,)

    def _pack_elements(self, values: Sequence[Any], start: int) -> list[bytes]:
        """Pack ``values`` as padded elements; ``start`` = position in
        the composite where the first element may begin."""
        parts: list[bytes] = []
        position = start
        for index, value in enumerate(values):
            position = _pack_padded(self.name, index, parts, position,
                                    self.elementType, value)
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
            except _ERRORS as exc:
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
        self._layout_if_ready()

    def _compute_layout(self) -> tuple[int, int | None]:
        element = self.elementType
        size = element.fixed_size
        if self.cardinality == 0:
            return element.octetBoundary, 0
        if size is None:
            return element.octetBoundary, None
        stride = size + _padding(size, element.octetBoundary)
        return element.octetBoundary, stride * (self.cardinality - 1) + size

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
        self._layout_if_ready()

    def _compute_layout(self) -> tuple[int, int | None]:
        return max(4, self.elementType.octetBoundary), None

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


class HLAfixedRecord(_Composite):
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
        self._layout_if_ready()

    def _components(self) -> Iterable[HLAdataType]:
        return [field_type for _, field_type in self.fields]

    def _compute_layout(self) -> tuple[int, int | None]:
        boundary = max(
            (field_type.octetBoundary for _, field_type in self.fields),
            default=1)
        position = 0
        for _, field_type in self.fields:
            size = field_type.fixed_size
            if size is None:
                return boundary, None
            position += _padding(position, field_type.octetBoundary) + size
        return boundary, position

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
            position = _pack_padded(self.name, field_name, parts, position,
                                    field_type, field_value)
        return b"".join(parts)

    def unpack(self, buffer: Buffer, offset: int = 0
               ) -> tuple[dict[str, Any], int]:
        """Decode all fields; return ``(dict, size)``."""
        offset = _check_buffer(self.name, buffer, offset)
        result: dict[str, Any] = {}
        position = 0
        for field_name, field_type in self.fields:
            result[field_name], position = _unpack_padded(
                self.name, field_name, field_type, buffer, offset, position)
        return result, position


class HLAenumerator(int):
    """One value of an :class:`HLAenumerated` type: an ``int`` that knows
    its name and its type, printed as PyHLA prints it: ``str()`` gives
    ``Type.Name`` and ``repr()`` gives ``<Type.Name=value>``."""

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
        """Return ``<Enumeration.Name=value>``."""
        return f"<{self.enumeration}.{self.name}={int(self)}>"

    def __str__(self) -> str:
        """Return ``Enumeration.Name``."""
        return f"{self.enumeration}.{self.name}"

    def __reduce__(self) -> tuple[Any, ...]:
        """Pickle support."""
        return (HLAenumerator, (self.enumeration, self.name, int(self)))


class HLAenumerated(_Composite):
    """Enumeration encoded with an integer ``representation`` type.

    Enumerators are attributes (``Enum.Little``) and items
    (``Enum["Little"]``) of the type and are :class:`HLAenumerator`
    (``int`` subclass) instances.  ``pack`` accepts an enumerator, its
    integer value or its name; ``unpack`` returns the enumerator and raises
    ``ValueError`` for a value that is not one of the enumerators.  The
    representation may be ``HLAoctet``, whose bytes are read as an
    unsigned integer.
    """

    def __init__(self, name: str, representation: HLAdataType,
                 enumerators: Mapping[str, int]) -> None:
        """Create the type from ``{enumeratorName: value}``."""
        self.name = name
        self.representation = representation
        self.enumerators: dict[str, HLAenumerator] = {}
        self._by_value: dict[int, HLAenumerator] = {}
        for enum_name, enum_value in enumerators.items():
            enumerator = HLAenumerator(name, enum_name,
                                       operator.index(enum_value))
            self.enumerators[enum_name] = enumerator
            self._by_value.setdefault(int(enumerator), enumerator)
        self._layout_if_ready()

    def _components(self) -> Iterable[HLAdataType]:
        return (self.representation,)

    def _compute_layout(self) -> tuple[int, int | None]:
        for number in self._by_value:
            self.representation.pack(number)  # check the range
        representation = self.representation
        return representation.octetBoundary, representation.fixed_size

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
        try:
            return self.representation.pack(number)
        except _ERRORS as exc:
            _rethrow(self.name, exc)

    def unpack(self, buffer: Buffer, offset: int = 0
               ) -> tuple[HLAenumerator, int]:
        """Decode an enumerator; return ``(enumerator, size)``."""
        try:
            number, used = self.representation.unpack(buffer, offset)
        except _ERRORS as exc:
            _rethrow(self.name, exc)
        if isinstance(number, bytes) and len(number) == 1:
            number = number[0]
        try:
            return self._by_value[number], used
        except KeyError:
            raise ValueError(
                f"{self.name}: {number} is not an enumerator value") from None


class HLAvariantRecord(_Composite):
    """Discriminated union (IEEE 1516.2 variant record), with PyHLA's
    signature::

        HLAvariantRecord("WheelCommand", ("mode", DriveMode), [
            (["Stopped"], None, None),                 # no value
            (["Differential", "Skid"], "speeds", WheelSpeeds),
            ([DriveMode.Ackermann], "ackermann", Ackermann),
            ([None], "raw", RawSpeeds),                # HLAother
        ])

    ``discriminant`` is ``(discriminantName, discriminantType)``, where the
    type is normally an :class:`HLAenumerated` (an integer type also
    works, with integer enumerators).  Each alternative is
    ``(enumerators, alternativeName, alternativeType)``: ``enumerators``
    lists the discriminant values that select it, as enumerator names
    (``str``), integer values or :class:`HLAenumerator` objects, or
    ``slice(first, last)`` for the enumerators from ``first`` to ``last``
    inclusive in declaration order; ``None`` in the list (or ``None``
    instead of the list) is ``HLAother``, every value no other alternative
    lists.  An alternative whose name or type is ``None`` (or the OMT's
    ``"NA"``) carries no value.

    The encoding is the discriminant, then pad bytes up to the chosen
    alternative's octet boundary (counted from the start of the record),
    then the alternative's value; an alternative without a value ends
    the record after the discriminant.  ``octetBoundary`` is the largest
    of the discriminant's and every alternative's.

    ``pack`` takes ``{discriminantName: d, alternativeName: value}`` (``d``
    an enumerator, its value or its name; extra keys are ignored) and
    ``unpack`` returns ``({discriminantName: enumerator,
    alternativeName: value}, size)``, PyHLA's value shape.  A discriminant
    value that selects no alternative when there is no ``HLAother`` raises
    ``ValueError``; a missing discriminant or alternative value raises
    ``KeyError``.  Enumerators are matched by name or by value (PyHLA
    compared values with names and never matched).
    """

    def __init__(self, name: str, discriminant: tuple[str, HLAdataType],
                 alternatives: Iterable[tuple[Any, Any, Any]]) -> None:
        """Create the type from ``(discriminantName, discriminantType)``
        and ``[(enumerators, alternativeName, alternativeType), ...]``."""
        self.name = name
        discriminant_name, discriminant_type = discriminant
        if not isinstance(discriminant_type, HLAdataType):
            raise TypeError(
                f"{name}: the discriminant type must be a data type, not "
                f"{type(discriminant_type).__name__}")
        self.discriminantName: str = discriminant_name
        self.discriminantType: HLAdataType = discriminant_type
        self.alternatives: list[
            tuple[tuple[Any, ...], str | None, HLAdataType | None]] = []
        for enumerators, alternative_name, alternative_type in alternatives:
            if enumerators is None:
                items: tuple[Any, ...] = (None,)
            elif isinstance(enumerators, (str, int, slice)):
                items = (enumerators,)
            else:
                items = tuple(enumerators)
            if (alternative_name in (None, "", "NA")
                    or alternative_type is None
                    or (isinstance(alternative_type, str)
                        and alternative_type == "NA")):
                alternative_name, alternative_type = None, None
            elif not isinstance(alternative_type, HLAdataType):
                raise TypeError(
                    f"{name}.{alternative_name}: the alternative type must be "
                    f"a data type, not {type(alternative_type).__name__}")
            elif alternative_name == discriminant_name:
                raise ValueError(
                    f"{name}: alternative {alternative_name!r} has the "
                    f"discriminant's name")
            self.alternatives.append(
                (items, alternative_name, alternative_type))
        self._by_value: dict[int, int] = {}
        self._other: int | None = None
        self._enumeration: HLAenumerated | None = None
        self._layout_if_ready()

    def _components(self) -> Iterable[HLAdataType]:
        return [self.discriminantType] + [
            datatype for _, _, datatype in self.alternatives
            if datatype is not None]

    def _enumerator(self, item: Any, enumeration: HLAenumerated | None
                    ) -> int:
        """The discriminant value that an alternative's ``item`` names."""
        if isinstance(item, str):
            if enumeration is None:
                raise ValueError(
                    f"{self.name}: enumerator name {item!r} needs an "
                    f"enumerated discriminant; "
                    f"{_target(self.discriminantType).name} is not one")
            try:
                return enumeration.enumerators[item.strip()]
            except KeyError:
                raise ValueError(
                    f"{self.name}: {item!r} is not an enumerator of "
                    f"{enumeration.name}") from None
        try:
            number = operator.index(item)
        except TypeError:
            raise TypeError(
                f"{self.name}: alternative enumerators are names, integers, "
                f"slices or None, not {type(item).__name__}") from None
        if enumeration is None:
            return number
        found = enumeration._by_value.get(number)
        if found is None:
            raise ValueError(
                f"{self.name}: {number} is not a value of "
                f"{enumeration.name}")
        return found

    def _values(self, item: Any, enumeration: HLAenumerated | None
                ) -> list[int]:
        """The discriminant values an alternative's ``item`` selects."""
        if not isinstance(item, slice):
            return [int(self._enumerator(item, enumeration))]
        if (enumeration is None or item.start is None or item.stop is None
                or item.step is not None):
            raise ValueError(
                f"{self.name}: a range of enumerators needs an enumerated "
                f"discriminant and both ends, got {item!r}")
        order = list(enumeration.enumerators.values())
        first = self._enumerator(item.start, enumeration)
        last = self._enumerator(item.stop, enumeration)
        start = next(i for i, e in enumerate(order) if e is first)
        stop = next(i for i, e in enumerate(order) if e is last)
        if start > stop:
            raise ValueError(
                f"{self.name}: empty range of enumerators {item.start!r} to "
                f"{item.stop!r}")
        return [int(e) for e in order[start:stop + 1]]

    def _compute_layout(self) -> tuple[int, int | None]:
        discriminant = _target(self.discriminantType)
        enumeration = (discriminant if isinstance(discriminant, HLAenumerated)
                       else None)
        by_value: dict[int, int] = {}
        other: int | None = None
        for index, (items, _, _) in enumerate(self.alternatives):
            for item in items:
                if item is None:
                    if other is not None and other != index:
                        raise ValueError(
                            f"{self.name}: two alternatives for HLAother")
                    other = index
                    continue
                for number in self._values(item, enumeration):
                    if by_value.setdefault(number, index) != index:
                        raise ValueError(
                            f"{self.name}: discriminant value {number} "
                            f"selects two alternatives")
        boundary = max([discriminant.octetBoundary] + [
            datatype.octetBoundary for _, _, datatype in self.alternatives
            if datatype is not None])
        self._by_value, self._other = by_value, other
        self._enumeration = enumeration
        return boundary, None

    def _choose(self, discriminant: Any
                ) -> tuple[str | None, HLAdataType | None, str]:
        """The ``(name, type)`` of the alternative ``discriminant`` selects,
        and the discriminant as error messages show it."""
        context = f"{self.name}.{self.discriminantName}"
        if isinstance(discriminant, str):
            if self._enumeration is None:
                raise TypeError(
                    f"{context}: expected an integer, got str")
            try:
                number = int(self._enumeration.enumerators[discriminant])
            except KeyError:
                raise ValueError(f"{context}: unknown enumerator "
                                 f"{discriminant!r}") from None
        elif isinstance(discriminant, bytes) and len(discriminant) == 1:
            number = discriminant[0]
        else:
            number = _as_int(context, discriminant)
        shown = _show(discriminant if self._enumeration is None else
                      self._enumeration._by_value.get(number, discriminant))
        index = self._by_value.get(number, self._other)
        if index is None:
            raise ValueError(
                f"{self.name}: no alternative for {self.discriminantName} = "
                f"{shown} and no HLAother alternative")
        _, alternative_name, alternative_type = self.alternatives[index]
        return alternative_name, alternative_type, shown

    def pack(self, value: Mapping[str, Any]) -> bytes:
        """Encode ``{discriminantName: d, alternativeName: value}``."""
        if not isinstance(value, Mapping):
            raise TypeError(
                f"{self.name}: expected a mapping of field values, got "
                f"{type(value).__name__}")
        if self._layout_state != 2:
            self._layout()
        try:
            discriminant = value[self.discriminantName]
        except KeyError:
            raise KeyError(
                f"{self.name}: missing discriminant "
                f"{self.discriminantName!r}") from None
        alternative_name, alternative_type, shown = self._choose(discriminant)
        parts: list[bytes] = []
        position = _pack_padded(self.name, self.discriminantName, parts, 0,
                                self.discriminantType, discriminant)
        if alternative_type is not None:
            assert alternative_name is not None
            try:
                alternative_value = value[alternative_name]
            except KeyError:
                raise KeyError(
                    f"{self.name}: missing field {alternative_name!r} (the "
                    f"alternative for {self.discriminantName} = "
                    f"{shown})") from None
            _pack_padded(self.name, alternative_name, parts, position,
                         alternative_type, alternative_value)
        return b"".join(parts)

    def unpack(self, buffer: Buffer, offset: int = 0
               ) -> tuple[dict[str, Any], int]:
        """Decode the discriminant and its alternative; return
        ``({discriminantName: enumerator, alternativeName: value}, size)``."""
        offset = _check_buffer(self.name, buffer, offset)
        if self._layout_state != 2:
            self._layout()
        try:
            discriminant, position = self.discriminantType.unpack(
                buffer, offset)
        except _ERRORS as exc:
            _rethrow(f"{self.name}.{self.discriminantName}", exc)
        alternative_name, alternative_type, _ = self._choose(discriminant)
        result: dict[str, Any] = {self.discriminantName: discriminant}
        if alternative_type is not None:
            assert alternative_name is not None
            result[alternative_name], position = _unpack_padded(
                self.name, alternative_name, alternative_type, buffer, offset,
                position)
        return result, position


class _UnsupportedType(_Composite):
    """A type :func:`HLAuse` read whose encoding this module does not
    implement: it loads (so the rest of the FOM does) and raises
    ``NotImplementedError`` naming the type and the encoding when packed
    or unpacked.  Its octet boundary is the largest of its parts'."""

    def __init__(self, name: str, kind: str, encoding: str,
                 parts: Iterable[HLAdataType] = (), boundary: int = 1) -> None:
        self.name = name
        self.kind = kind
        self.encodingName = encoding
        self._parts = list(parts)
        self._minimum = boundary
        self._layout_if_ready()

    def _components(self) -> Iterable[HLAdataType]:
        return self._parts

    def _compute_layout(self) -> tuple[int, int | None]:
        return max([self._minimum]
                   + [part.octetBoundary for part in self._parts]), None

    def _refuse(self, action: str) -> NoReturn:
        raise NotImplementedError(
            f"{self.name}: cannot {action}: {self.kind} encoding "
            f"{self.encodingName!r} is not supported by hlacore.omt")

    def pack(self, value: Any) -> bytes:
        """Raise ``NotImplementedError``."""
        self._refuse("pack")

    def unpack(self, buffer: Buffer, offset: int = 0) -> tuple[Any, int]:
        """Raise ``NotImplementedError``."""
        self._refuse("unpack")


# --------------------------------------------------------------------------
# OMT / FOM XML files (HLAuse)
# --------------------------------------------------------------------------

#: Data types defined by :func:`HLAuse`, by name, including those whose name
#: is taken by another attribute of this module.
_fom_types: dict[str, HLAdataType] = {}

_KINDS = frozenset(("basicData", "simpleData", "enumeratedData", "arrayData",
                    "fixedRecordData", "variantRecordData"))
_RANGE = re.compile(r"\[\s*([^\].]+?)\s*\.\.\s*([^\]]+?)\s*\]")


def _lookup_type(name: str) -> HLAdataType | None:
    """The data type this module calls ``name`` (its own, one set by hand,
    or one :func:`HLAuse` defined), or None."""
    found = globals().get(name)
    if isinstance(found, HLAdataType):
        return found
    return _fom_types.get(name)


def _standard_type(name: str) -> HLAdataType | None:
    """The module's own data type called ``name`` (one :func:`HLAuse`
    never replaces), or None."""
    if name in _MODULE_NAMES:
        found = globals().get(name)
        if isinstance(found, HLAdataType):
            return found
    return None


def _local(tag: Any) -> str:
    """An element's tag without its XML namespace."""
    return tag.rsplit("}", 1)[-1] if isinstance(tag, str) else ""


def _texts(element: ElementTree.Element, key: str) -> list[str]:
    """The values of property ``key``: the attribute (1516-2000 layout) or
    the text of each child element of that name (1516-2010 layout)."""
    attribute = element.get(key)
    if attribute is not None:
        return [attribute.strip()]
    return [(child.text or "").strip() for child in element
            if _local(child.tag) == key]


def _text(element: ElementTree.Element, key: str) -> str | None:
    """The first non-empty value of property ``key``, or None."""
    for text in _texts(element, key):
        if text:
            return text
    return None


def _children(element: ElementTree.Element, kind: str
              ) -> list[ElementTree.Element]:
    """The child elements of ``element`` called ``kind``."""
    return [child for child in element if _local(child.tag) == kind]


def _integer(text: str) -> int:
    """Parse a decimal (or ``0x``-prefixed) integer."""
    try:
        return int(text)
    except ValueError:
        return int(text, 0)


def _cardinality(text: str) -> list[tuple[int, int | None]]:
    """The ``(lower, upper)`` bounds of each dimension of an arrayData
    cardinality (``Dynamic``, ``3``, ``[1..10]``, ``2,3``); ``upper`` is
    None when unbounded."""
    dimensions: list[tuple[int, int | None]] = []
    for part in text.split(","):
        part = part.strip()
        try:
            if part.lower() == "dynamic":
                dimensions.append((0, None))
                continue
            match = _RANGE.fullmatch(part)
            if match:
                low, high = match.groups()
                dimensions.append((
                    0 if low.lower() == "dynamic" else _integer(low),
                    None if high.lower() == "dynamic" else _integer(high)))
                continue
            dimensions.append((_integer(part), _integer(part)))
        except ValueError:
            raise ValueError(
                f"cardinality {text!r} is not Dynamic, a number or a range "
                f"[low..high]") from None
    return dimensions


def _enumerator_token(token: str) -> str | int:
    """An alternative's enumerator: an integer if it is one, else a name."""
    return int(token) if re.fullmatch(r"[+-]?\d+", token) else token


def _alternative_items(text: str) -> list[Any]:
    """Parse an alternative's enumerators: comma-separated names,
    ``HLAother`` (None) and ranges ``[A..C]`` (slices)."""
    items: list[Any] = []
    for token in text.split(","):
        token = token.strip()
        if not token:
            continue
        match = _RANGE.fullmatch(token)
        if token == "HLAother":
            items.append(None)
        elif match:
            items.append(slice(_enumerator_token(match.group(1)),
                               _enumerator_token(match.group(2))))
        else:
            items.append(_enumerator_token(token))
    return items


class _Definition(NamedTuple):
    """A data type element of an OMT file."""

    kind: str
    element: ElementTree.Element


class _FOMError(ValueError):
    """A malformed data type definition; the message names file and type."""


class _FOMReader:
    """Builds the data types of one OMT file, in any declaration order."""

    def __init__(self, filename: str,
                 definitions: dict[str, _Definition]) -> None:
        self.filename = filename
        self.definitions = definitions
        self.types: dict[str, HLAdataType] = {}
        self.building: set[str] = set()

    def type_of(self, name: str) -> HLAdataType:
        """The data type the file's ``name`` stands for, built on demand."""
        standard = _standard_type(name)
        if standard is not None:
            return standard
        built = self.types.get(name)
        if built is not None:
            return built
        if name in self.building:  # a type that contains itself
            return _Reference(name, lambda: self.types[name],
                              f"recursive use in {self.filename}")
        self.building.add(name)
        try:
            built = self._construct(name, self.definitions[name])
        finally:
            self.building.discard(name)
        self.types[name] = built
        return built

    def reference(self, name: str | None, user: str, role: str
                  ) -> HLAdataType:
        """The data type that ``user`` (``Type`` or ``Type.field``) names
        as its ``role``; a forward reference if nothing defines it yet."""
        if not name:
            raise ValueError(f"{user}: no {role}")
        if _standard_type(name) is not None or name in self.definitions:
            return self.type_of(name)
        found = _lookup_type(name)
        if found is not None:
            return found
        return _Reference(name, None, f"used by {user} in {self.filename}")

    def _construct(self, name: str, definition: _Definition) -> HLAdataType:
        """Build one definition; errors name the file and the type."""
        builders = {
            "basicData": self._basic,
            "simpleData": self._simple,
            "enumeratedData": self._enumerated,
            "arrayData": self._array,
            "fixedRecordData": self._fixed_record,
            "variantRecordData": self._variant_record,
        }
        try:
            return builders[definition.kind](name, definition.element)
        except _FOMError:
            raise
        except (ValueError, TypeError, KeyError) as exc:
            message = exc.args[0] if len(exc.args) == 1 else str(exc)
            raise _FOMError(f"{self.filename}: {definition.kind} {name!r}: "
                            f"{message}") from exc

    def _basic(self, name: str, element: ElementTree.Element) -> HLAdataType:
        size = _text(element, "size") or ""
        match = re.match(r"\d+", size)
        if not match:
            raise ValueError(f"size {size!r} is not a number of bits")
        bits = int(match.group())
        words = f"{name} {_text(element, 'interpretation') or ''}".lower()
        endian = (_text(element, "endian") or "Big").lower()
        order = "<" if endian.startswith("little") else ">"
        if "float" in words:
            code = {32: "f", 64: "d"}.get(bits)
            if code is not None:
                return _FloatType(name, order, code)
            what = "floating point number"
        else:
            code = {8: "b", 16: "h", 32: "i", 64: "q"}.get(bits)
            if code is not None:
                if "unsigned" in words:
                    code = code.upper()
                return _IntegerType(name, order, code)
            what = "integer"
        return _UnsupportedType(name, "basicData", f"{bits}-bit {what}")

    def _simple(self, name: str, element: ElementTree.Element
                ) -> HLAdataType:
        return self.reference(_text(element, "representation"), name,
                              "representation")

    def _enumerated(self, name: str, element: ElementTree.Element
                    ) -> HLAdataType:
        representation = self.reference(_text(element, "representation"),
                                         name, "representation")
        values: dict[str, int] = {}
        extra: list[tuple[str, int]] = []
        for child in _children(element, "enumerator"):
            enumerator = _text(child, "name")
            if not enumerator:
                raise ValueError("an enumerator has no name")
            numbers = [_integer(piece.strip())
                       for text in _texts(child, "values") + _texts(child,
                                                                    "value")
                       for piece in text.split(",") if piece.strip()]
            if not numbers:
                raise ValueError(f"enumerator {enumerator!r} has no value")
            values[enumerator] = numbers[0]
            extra.extend((enumerator, number) for number in numbers[1:])
        enumerated = HLAenumerated(name, representation, values)
        for enumerator, number in extra:  # further values decode to it
            enumerated._by_value.setdefault(
                number, enumerated.enumerators[enumerator])
            if enumerated._layout_state == 2:
                representation.pack(number)
        return enumerated

    def _array(self, name: str, element: ElementTree.Element) -> HLAdataType:
        element_type = self.reference(_text(element, "dataType"), name,
                                      "dataType")
        cardinality = _text(element, "cardinality") or "Dynamic"
        encoding = _text(element, "encoding") or (
            "HLAvariableArray" if ("dynamic" in cardinality.lower()
                                   or ".." in cardinality)
            else "HLAfixedArray")
        if encoding not in ("HLAfixedArray", "HLAvariableArray"):
            return _UnsupportedType(name, "arrayData", encoding,
                                    [element_type])
        dimensions = _cardinality(cardinality)
        datatype = element_type
        for index in range(len(dimensions) - 1, -1, -1):
            low, high = dimensions[index]
            dimension = (name if index == 0
                         else f"{name} (dimension {index + 1})")
            if encoding == "HLAvariableArray":
                datatype = HLAvariableArray(dimension, datatype, high)
            elif high is None or low != high:
                raise ValueError(
                    f"HLAfixedArray needs a fixed cardinality, got "
                    f"{cardinality!r}")
            else:
                datatype = HLAfixedArray(dimension, datatype, high)
        return datatype

    def _fixed_record(self, name: str, element: ElementTree.Element
                      ) -> HLAdataType:
        fields: list[tuple[str, HLAdataType]] = []
        for child in _children(element, "field"):
            field = _text(child, "name")
            if not field:
                raise ValueError("a field has no name")
            fields.append((field, self.reference(
                _text(child, "dataType"), f"{name}.{field}", "dataType")))
        encoding = _text(element, "encoding") or "HLAfixedRecord"
        if encoding != "HLAfixedRecord":
            return _UnsupportedType(name, "fixedRecordData", encoding,
                                    [datatype for _, datatype in fields])
        return HLAfixedRecord(name, fields)

    def _variant_record(self, name: str, element: ElementTree.Element
                        ) -> HLAdataType:
        discriminant = _text(element, "discriminant")
        if not discriminant:
            raise ValueError("no discriminant name")
        discriminant_type = self.reference(
            _text(element, "dataType"), f"{name}.{discriminant}", "dataType")
        alternatives: list[tuple[list[Any], str | None, HLAdataType | None]]
        alternatives = []
        for child in _children(element, "alternative"):
            items = _alternative_items(",".join(_texts(child, "enumerator")))
            if not items:
                raise ValueError("an alternative has no enumerator")
            alternative = _text(child, "name")
            type_name = _text(child, "dataType")
            if alternative in (None, "NA") or type_name in (None, "NA"):
                alternatives.append((items, None, None))
            else:
                assert alternative is not None
                alternatives.append((items, alternative, self.reference(
                    type_name, f"{name}.{alternative}", "dataType")))
        encoding = _text(element, "encoding") or "HLAvariantRecord"
        if encoding != "HLAvariantRecord":
            parts = [discriminant_type] + [
                datatype for _, _, datatype in alternatives
                if datatype is not None]
            return _UnsupportedType(name, "variantRecordData", encoding,
                                    parts)
        return HLAvariantRecord(name, (discriminant, discriminant_type),
                                alternatives)


def HLAuse(filename: str | os.PathLike[str]) -> dict[str, HLAdataType]:
    """Define the data types of an IEEE 1516 OMT/FOM XML file in this module.

    Returns ``{name: dataType}`` in declaration order and, as PyHLA's
    ``HLAuse`` does, sets each name as an attribute of ``hlacore.omt``::

        import hlacore.omt as fom
        fom.HLAuse("robot.xml")
        data = fom.Pose2D.pack({"x": 1.0, "y": 2.0, "theta": 0.5})

    Both layouts are read, with or without an XML namespace: 1516-2000's,
    whose properties are attributes
    (``<simpleData name="Meters" representation="HLAfloat64BE"/>``), and
    1516-2010's, whose properties are child elements
    (``<simpleData><name>Meters</name><representation>...``).  The data
    types become:

    * ``basicData``: an integer or a float of ``size`` bits (8, 16, 32 or
      64) in the ``endian`` byte order; a float when the name or the
      interpretation says "float", else an integer, signed unless the name
      or the interpretation says "unsigned";
    * ``simpleData``: its representation (the name is an alias of the same
      object);
    * ``enumeratedData``: an :class:`HLAenumerated`; an enumerator with
      several values takes the first, and the others decode to it;
    * ``arrayData``: an :class:`HLAfixedArray` or :class:`HLAvariableArray`
      of cardinality ``Dynamic``, a number or a range ``[1..10]`` (its upper
      bound is the maximum); a multi-dimensional cardinality ``2,3`` nests
      arrays, the first dimension outermost;
    * ``fixedRecordData``: an :class:`HLAfixedRecord` of its ``field``
      elements (1516-2010's record extension by ``include`` is ignored);
    * ``variantRecordData``: an :class:`HLAvariantRecord`; an alternative's
      enumerators are comma-separated names, ``HLAother`` and ranges
      ``[A..C]`` (in the enumeration's declaration order), and an
      alternative whose name or data type is ``NA`` carries no value.

    A type may be used before it is declared.  A name the file uses but
    does not define is looked up in this module (among its own types and
    those of earlier ``HLAuse`` calls) when first used, so FOM modules may
    be loaded in any order; a name still undefined then raises
    ``KeyError`` naming it and the type that uses it.  A type whose
    encoding is not a standard one (``RPRnullTerminatedArray`` ...), a
    ``basicData`` of another size, or a type that contains itself loads,
    and raises ``NotImplementedError`` naming the type and the encoding
    when packed or unpacked.

    ``HLAuse`` never replaces this module's own names: a FOM that declares
    a standard type (``HLAinteger32BE``, ``HLAASCIIstring``,
    ``HLAboolean`` ...) keeps this module's, and the returned dict maps the
    name to it.  Note that the 1516-2010 MIM declares ``HLAboolean`` as an
    enumeration of ``HLAfalse`` and ``HLAtrue``, whereas here it packs and
    unpacks ``bool`` (with the same bytes).  A type whose name is taken by
    another attribute of the module (``struct``, ``pack_string`` ...) is in
    the returned dict and serves the file's references but is not set as
    an attribute.  Names defined by an earlier ``HLAuse`` are replaced; a
    name defined twice in one file takes the later definition.  Type
    checkers do not know the attributes ``HLAuse`` sets: typed code should
    use the returned dict.

    Raises ``OSError`` (``FileNotFoundError`` ...) naming the file if it
    cannot be read, and ``ValueError`` naming the file if it is not
    well-formed XML, not an ``objectModel`` or has a malformed data type
    (no name, a fixed array without a fixed cardinality, an alternative
    naming an enumerator its discriminant lacks ...).
    """
    path = os.fspath(filename)
    try:
        root = ElementTree.parse(path).getroot()
    except ElementTree.ParseError as exc:
        raise ValueError(f"{path}: malformed XML: {exc}") from None
    if _local(root.tag) != "objectModel":
        raise ValueError(
            f"{path}: not an HLA object model (the root element is "
            f"<{_local(root.tag)}>, not <objectModel>)")
    definitions: dict[str, _Definition] = {}
    for element in root.iter():
        kind = _local(element.tag)
        if kind not in _KINDS:
            continue
        name = _text(element, "name")
        if not name:
            raise ValueError(f"{path}: a {kind} element has no name")
        definitions[name] = _Definition(kind, element)
    reader = _FOMReader(path, definitions)
    types = {name: reader.type_of(name) for name in definitions}
    for name, datatype in types.items():
        if _standard_type(name) is not None:
            continue
        _fom_types[name] = datatype
        if name not in _MODULE_NAMES:
            globals()[name] = datatype
    return types


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


#: Every name this module defines: :func:`HLAuse` never replaces them.
_MODULE_NAMES: frozenset[str] = frozenset(globals()) | {"_MODULE_NAMES"}
