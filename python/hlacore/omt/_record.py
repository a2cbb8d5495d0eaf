"""``HLAfixedRecord``: named fields, each padded to its type's octet boundary."""

from __future__ import annotations

from collections.abc import Iterable, Mapping, Sequence
from typing import Any

from ._base import HLAdataType, _Composite, _pack_padded, _unpack_padded
from ._bytes import Buffer, _check_buffer, _padding


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
