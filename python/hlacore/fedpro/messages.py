"""Building the Federate Protocol's protobuf messages from plain Python values, and reading them back.

:func:`build` makes a message of a given type from a value, and :func:`fill` sets a message's fields from
keyword-like pairs; :class:`hlacore.fedpro.RTIambassador` builds every call with them. What a value may be,
for a field of message type:

* a message of that type, as it is (a handle an earlier call returned, ...);
* a dict of its fields by name, a tuple of its fields in their order (``(handle, b"value")`` for an
  ``AttributeHandleValue``);
* for a message of one field, that field's value: ``bytes`` for a handle (its ``data``), a list for a set
  (``attributes=[h1, h2]`` for an ``AttributeHandleSet``), a dict or a list of pairs for a map
  (``attributeValues={h.data: b"..."}`` or ``[(h, b"...")]`` for an ``AttributeHandleValueMap``), one
  element alone for a list of one;
* a ``str`` or path for a ``FomModule``: the file's content with its name (:func:`fom_module`), or a URL when
  the string has ``://``;
* a ``float`` (or ``int``) for a ``LogicalTime`` or ``LogicalTimeInterval``: HLAfloat64Time's encoding
  (:func:`float64_time`; for HLAinteger64Time pass :func:`integer64_time`).

Scalar fields take their Python value; an enum field also takes its value's name (``"DELETE_OBJECTS"``), a
``bytes`` field also a ``str`` (UTF-8). Repeated fields take any iterable.
"""

from __future__ import annotations

import os
import pathlib
import struct
from typing import Any, Dict, Iterable, Mapping, Optional, Union

from ._proto import FederateAmbassador_pb2, RTIambassador_pb2, datatypes_pb2

# The generated modules are reached through Any: mypy then needs no stubs for them (protoc's Python output
# defines its classes at run time).
_DATATYPES: Any = datatypes_pb2
_MODULES: Any = (datatypes_pb2, RTIambassador_pb2, FederateAmbassador_pb2)

#: Every message type of the three .proto files, by its full name (``rti1516_2025.fedpro.FomModule``).
MESSAGE_CLASSES: Dict[str, Any] = {
    descriptor.full_name: getattr(module, name)
    for module in _MODULES for name, descriptor in module.DESCRIPTOR.message_types_by_name.items()}

_FLOAT64 = struct.Struct(">d")
_INT64 = struct.Struct(">q")
_U32 = struct.Struct(">I")
_TIME_TYPES = ("rti1516_2025.fedpro.LogicalTime", "rti1516_2025.fedpro.LogicalTimeInterval")
_FOM_MODULE = "rti1516_2025.fedpro.FomModule"

PathLike = Union[str, "os.PathLike[str]"]

#: The type of the credentials :func:`plain_text_password` makes, as the standard names it.
PLAIN_TEXT_PASSWORD = "HLAplainTextPassword"


def is_repeated(field: Any) -> bool:
    """Whether the field descriptor `field` is a repeated field (across protobuf versions)."""
    repeated = getattr(field, "is_repeated", None)
    if repeated is not None:
        return bool(repeated)
    return bool(field.label == field.LABEL_REPEATED)


def message_class(descriptor: Any) -> Any:
    """The generated class of the message type `descriptor` describes."""
    return MESSAGE_CLASSES[descriptor.full_name]


def float64_time(t: float) -> Any:
    """A ``LogicalTime`` holding `t` as HLAfloat64Time: the 8-byte big-endian IEEE 754 double."""
    return _DATATYPES.LogicalTime(data=_FLOAT64.pack(t))


def float64_interval(t: float) -> Any:
    """A ``LogicalTimeInterval`` holding `t` as HLAfloat64Interval (an 8-byte big-endian double)."""
    return _DATATYPES.LogicalTimeInterval(data=_FLOAT64.pack(t))


def integer64_time(t: int) -> Any:
    """A ``LogicalTime`` holding `t` as HLAinteger64Time: an 8-byte big-endian signed integer."""
    return _DATATYPES.LogicalTime(data=_INT64.pack(t))


def integer64_interval(t: int) -> Any:
    """A ``LogicalTimeInterval`` holding `t` as HLAinteger64Interval (an 8-byte big-endian integer)."""
    return _DATATYPES.LogicalTimeInterval(data=_INT64.pack(t))


def _time_data(msg: Any) -> bytes:
    data = msg if isinstance(msg, (bytes, bytearray)) else getattr(msg, "data", None)
    if data is None:  # a TimeQueryReturn, a TimeAdvanceGrant, ...: its time
        for name in ("logicalTime", "time"):
            inner = getattr(msg, name, None)
            if inner is not None and hasattr(inner, "data"):
                data = inner.data
                break
    if not isinstance(data, (bytes, bytearray)) or len(data) != 8:
        raise ValueError(f"not an 8-byte logical time: {msg!r}")
    return bytes(data)


def time_value(msg: Any) -> float:
    """The HLAfloat64Time in `msg`: a ``LogicalTime`` or ``LogicalTimeInterval``, a message holding one in
    its ``time`` or ``logicalTime`` field (a ``TimeAdvanceGrant``, a ``TimeQueryReturn``), or the 8 bytes.
    ``ValueError`` when it is not 8 bytes long."""
    value: float = _FLOAT64.unpack(_time_data(msg))[0]
    return value


def integer_time_value(msg: Any) -> int:
    """The HLAinteger64Time in `msg`, found as :func:`time_value` finds a float time."""
    value: int = _INT64.unpack(_time_data(msg))[0]
    return value


def unicode_string(text: str) -> bytes:
    """`text` as HLAunicodeString: the 4-byte big-endian count of its UTF-16 code units, then each unit as 2
    big-endian bytes (a character beyond U+FFFF is two, a surrogate pair)."""
    units = text.encode("utf-16-be")
    return _U32.pack(len(units) // 2) + units


def plain_text_password(password: str) -> Any:
    """``Credentials`` of the standard's ``HLAplainTextPassword`` type holding `password` (its data is the
    password as HLAunicodeString, :func:`unicode_string`), for HLA connect:
    ``rtia.connect(amb, credentials=plain_text_password("secret"))``. The password goes as it is: send it over
    TLS, unless the network is trusted."""
    return _DATATYPES.Credentials(type=PLAIN_TEXT_PASSWORD, data=unicode_string(password))


def fom_module(path: PathLike, name: Optional[str] = None) -> Any:
    """A ``FomModule`` holding the file at `path` (its content, read now, and its file name, or `name`)."""
    p = pathlib.Path(path)
    return _DATATYPES.FomModule(file=_DATATYPES.FileFomModule(name=name or p.name, content=p.read_bytes()))


def handle_values(msg: Any) -> Dict[bytes, bytes]:
    """An ``AttributeHandleValueMap`` or ``ParameterHandleValueMap`` (or a callback holding one in its
    ``attributeValues`` or ``parameterValues`` field, such as ``ReflectAttributeValues``) as a dict from each
    handle's bytes to its value."""
    for holder in ("attributeValues", "parameterValues"):
        if msg.DESCRIPTOR.fields_by_name.get(holder) is not None:
            msg = getattr(msg, holder)
            break
    pairs = msg.attributeHandleValue if "attributeHandleValue" in msg.DESCRIPTOR.fields_by_name \
        else msg.parameterHandleValue
    result: Dict[bytes, bytes] = {}
    for pair in pairs:
        handle = pair.attributeHandle if pair.DESCRIPTOR.name == "AttributeHandleValue" else pair.parameterHandle
        result[bytes(handle.data)] = bytes(pair.value)
    return result


def _field_names(descriptor: Any) -> str:
    return ", ".join(field.name for field in descriptor.fields) or "none"


def fill(message: Any, fields: Mapping[str, Any]) -> Any:
    """Sets the fields of `message` from `fields` (field name to value, as the module's docstring says);
    returns `message`. ``TypeError`` for a field it does not have or a value that does not fit."""
    descriptor = message.DESCRIPTOR
    for name, value in fields.items():
        field = descriptor.fields_by_name.get(name)
        if field is None:
            raise TypeError(f"{descriptor.name} has no field {name!r}; its fields: {_field_names(descriptor)}")
        _set(message, field, value)
    return message


def _set(message: Any, field: Any, value: Any) -> None:
    where = f"{message.DESCRIPTOR.name}.{field.name}"
    if is_repeated(field):
        container = getattr(message, field.name)
        del container[:]
        for item in _items(value):
            if field.message_type is not None:
                container.add().CopyFrom(build(field.message_type, item, where))
            else:
                container.append(_scalar(field, item, where))
    elif field.message_type is not None:
        sub = getattr(message, field.name)
        sub.CopyFrom(build(field.message_type, value, where))
        sub.SetInParent()
    else:
        try:
            setattr(message, field.name, _scalar(field, value, where))
        except (TypeError, ValueError) as e:
            raise TypeError(f"{where}: {e}") from None


def _items(value: Any) -> Iterable[Any]:
    """The elements a repeated field gets from `value`: a dict's items, an iterable's elements, or `value`."""
    if isinstance(value, Mapping):
        return list(value.items())
    if isinstance(value, (str, bytes, bytearray, os.PathLike)) or hasattr(value, "DESCRIPTOR") \
            or not isinstance(value, Iterable):
        return [value]
    return list(value)


def _scalar(field: Any, value: Any, where: str) -> Any:
    if field.enum_type is not None and isinstance(value, str):
        number = field.enum_type.values_by_name.get(value)
        if number is None:
            names = ", ".join(field.enum_type.values_by_name)
            raise TypeError(f"{where}: {value!r} is not a {field.enum_type.name} ({names})")
        return number.number
    if field.type == field.TYPE_BYTES and isinstance(value, str):
        return value.encode()
    return value


def build(descriptor: Any, value: Any, where: str = "") -> Any:
    """A message of the type `descriptor` describes, made from `value` (the module's docstring lists what
    fits). ``TypeError`` when nothing does."""
    if hasattr(value, "DESCRIPTOR") and value.DESCRIPTOR.full_name == descriptor.full_name:
        return value
    cls = message_class(descriptor)
    if descriptor.full_name == _FOM_MODULE and isinstance(value, (str, os.PathLike)):
        if isinstance(value, str) and "://" in value:
            return cls(url=value)
        return fom_module(value)
    if descriptor.full_name in _TIME_TYPES and isinstance(value, (int, float)) and not isinstance(value, bool):
        return cls(data=_FLOAT64.pack(float(value)))
    fields = descriptor.fields
    if isinstance(value, Mapping) and value and all(isinstance(k, str) and k in descriptor.fields_by_name
                                                    for k in value):
        return fill(cls(), value)
    if isinstance(value, tuple) and len(fields) > 1 and len(value) == len(fields):
        return fill(cls(), {field.name: item for field, item in zip(fields, value)})
    if len(fields) == 1:
        message = cls()
        _set(message, fields[0], value)
        return message
    raise TypeError(f"{where + ': ' if where else ''}cannot make a {descriptor.name} from {value!r}: pass the "
                    f"message, a dict of its fields ({_field_names(descriptor)}) or a tuple of them in order")
