"""The base classes: :class:`HLAdataType`, which every encoding type is, and ``_Composite``, a type built
from others whose layout is computed when first needed, with the padded packing of its members."""

from __future__ import annotations

from collections.abc import Iterable
from typing import Any, Generic, TypeVar, Union, overload

from ._bytes import _ERRORS, Buffer, _padding, _rethrow

_V = TypeVar("_V")  # the value of a layout attribute


class HLAdataType:
    """Base class of every encoding type of ``hlacore.omt``.

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

    def _pending(self) -> bool:
        """Whether this type's layout cannot be computed yet: an unresolved
        :class:`HLAencoding`, or a composite that contains one."""
        return False


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

    def _pending(self) -> bool:
        """Whether the layout is not computed yet (a component is pending)."""
        return self._layout_state != 2

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
        if not any(component._pending() for component in self._components()):
            self._layout()


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
