"""The array types, ``HLAfixedArray`` and ``HLAvariableArray``: elements padded to their octet boundary,
numeric elements packed and unpacked with one ``struct`` call."""

from __future__ import annotations

import operator
import struct
from collections.abc import Iterable, Sequence
from typing import Any

from ._base import HLAdataType, _Composite, _pack_padded
from ._basic import _StructType
from ._bytes import _COUNT, _ERRORS, Buffer, _check_buffer, _need, _padding, _rethrow
from ._encoding import HLAencoding


def _numeric_code(element: HLAdataType) -> tuple[str, str] | None:
    """Return ``(byte_order, struct_code)`` for plain numeric basic types."""
    if isinstance(element, HLAencoding):
        element = element.encoding
    if isinstance(element, _StructType):
        return element._order, element._code
    return None


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
