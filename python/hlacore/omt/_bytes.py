"""The byte-level checks every encoding shares: the buffer and offset ``unpack`` takes, the bytes a value
needs, count prefixes, padding, and the errors a composite re-raises with where they happened."""

from __future__ import annotations

import operator
import struct
from typing import Any, NoReturn, Union

#: Anything ``unpack`` accepts as its buffer.
Buffer = Union[bytes, bytearray, memoryview]

_COUNT = struct.Struct(">i")  # HLAinteger32BE element/character count

#: The errors a component's ``pack``/``unpack`` may raise that a composite
#: re-raises with its context (``Record.field``) prepended.
_ERRORS = (ValueError, TypeError, KeyError, NotImplementedError)


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
