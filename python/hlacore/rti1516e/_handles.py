"""IEEE 1516-2010's handle types: each built empty (an invalid handle, as ``FederateHandle()`` is), valid
ones come from the RTI; they hash, compare within their kind and answer ``isValid()``; ``encode()`` gives
their bytes and ``RTIambassador.decode<Kind>Handle`` takes them back. Each wraps the core's typed handle."""

from __future__ import annotations

from typing import Any, Iterable, List, Set, Type, TypeVar

from .. import _core
from . import _exceptions as x

H = TypeVar("H", bound="Handle")


class Handle:
    """What every handle type shares (not itself a handle type)."""

    __slots__ = ("_core",)
    _invalid: Type[x.Exception] = x.RTIinternalError  # raised when an invalid handle is given to a service

    def __init__(self, *args: Any, **kwargs: Any) -> None:
        self._core: Any = None  # arguments are ignored, as the standard's default constructor takes none

    @classmethod
    def wrap(cls: Type[H], core: Any) -> H:
        """The handle of this kind for the core's handle `core`."""
        h = cls.__new__(cls)
        h._core = core
        return h

    def isValid(self) -> bool:
        """Whether the RTI gave this handle (one built empty is not)."""
        return self._core is not None

    def _key(self) -> Any:
        return -1 if self._core is None else int(self._core)

    def encode(self) -> bytearray:
        """The handle's bytes (4, big-endian; empty for an invalid handle)."""
        return bytearray() if self._core is None else bytearray(int(self._core).to_bytes(4, "big"))

    def __hash__(self) -> int:
        return hash((type(self).__name__, self._key()))

    def __eq__(self, other: object) -> bool:
        return type(other) is type(self) and self._key() == other._key()  # type: ignore[attr-defined]

    def __ne__(self, other: object) -> bool:
        return not self == other

    def __lt__(self, other: Handle) -> bool:
        return bool(self._key() < self._same(other)._key())

    def __le__(self, other: Handle) -> bool:
        return bool(self._key() <= self._same(other)._key())

    def __gt__(self, other: Handle) -> bool:
        return bool(self._key() > self._same(other)._key())

    def __ge__(self, other: Handle) -> bool:
        return bool(self._key() >= self._same(other)._key())

    def _same(self, other: Handle) -> Handle:
        if type(other) is not type(self):
            raise TypeError(f"cannot order a {type(self).__name__} and a {type(other).__name__}")
        return other

    def __repr__(self) -> str:
        return f"rti1516e::{type(self).__name__}({'Invalid' if self._core is None else self._key()})"

    __str__ = __repr__

    def __reduce__(self) -> Any:
        raise TypeError(f"a {type(self).__name__} is sent as encode()'s bytes, not pickled")


# The handle kinds: a docstring, and the exception a service raises for one built empty.
class FederateHandle(Handle): """A joined federate."""; __slots__ = (); _invalid = x.InvalidFederateHandle
class ObjectClassHandle(Handle): """An object class of the FOM."""; __slots__ = (); _invalid = x.ObjectClassNotDefined
class ObjectInstanceHandle(Handle): """An object instance."""; __slots__ = (); _invalid = x.ObjectInstanceNotKnown
class InteractionClassHandle(Handle): """An interaction class of the FOM."""; __slots__ = (); _invalid = x.InteractionClassNotDefined
class AttributeHandle(Handle): """An attribute of an object class."""; __slots__ = (); _invalid = x.AttributeNotDefined
class ParameterHandle(Handle): """A parameter of an interaction class."""; __slots__ = (); _invalid = x.InteractionParameterNotDefined
class DimensionHandle(Handle): """A dimension of the FOM (for regions)."""; __slots__ = (); _invalid = x.InvalidDimensionHandle
class RegionHandle(Handle): """A region (data distribution management)."""; __slots__ = (); _invalid = x.InvalidRegion


class MessageRetractionHandle(Handle):
    """A timestamped message its sender may retract: its sender's handle and serial number."""
    __slots__ = ()
    _invalid = x.InvalidMessageRetractionHandle

    def _key(self) -> Any:
        return (-1, -1) if self._core is None else (int(self._core.sendingFederate), int(self._core.serial))

    def encode(self) -> bytearray:
        """The sender's handle (4 bytes) and the serial number (8), big-endian; empty when invalid."""
        if self._core is None:
            return bytearray()
        sender, serial = self._key()
        return bytearray(sender.to_bytes(4, "big") + serial.to_bytes(8, "big"))

    def __repr__(self) -> str:
        return f"rti1516e::MessageRetractionHandle({'Invalid' if self._core is None else '%d:%d' % self._key()})"

    __str__ = __repr__


def core(cls: Type[Handle], h: object) -> Any:
    """The core's handle inside `h`, which must be a valid handle of kind `cls`."""
    if type(h) is not cls:
        raise TypeError(f"a {cls.__name__} was expected, not {type(h).__name__}")
    inner = h._core  # type: ignore[attr-defined]
    if inner is None:
        raise cls._invalid(f"{cls._invalid.__name__}: an invalid {cls.__name__} (built empty, not given by the RTI)")
    return inner


def cores(cls: Type[Handle], handles: Iterable[object]) -> List[Any]:
    """The core's handles of an iterable of handles of kind `cls`."""
    if isinstance(handles, (str, bytes)) or not hasattr(handles, "__iter__"):
        raise TypeError(f"a set of {cls.__name__} was expected, not {type(handles).__name__}")
    return [core(cls, h) for h in handles]


def wrap_set(cls: Type[H], handles: Iterable[Any]) -> Set[H]:
    """A set of handles of kind `cls` for the core's handles."""
    return {cls.wrap(h) for h in handles}


def decode(cls: Type[H], data: Any, core_type: Any) -> H:
    """The handle `encode()` gave `data` for: 4 bytes, big-endian."""
    raw = bytes(data)
    if len(raw) != 4:
        raise x.CouldNotDecode(f"CouldNotDecode: a {cls.__name__} is 4 bytes, not {len(raw)}")
    return cls.wrap(core_type._from_int(int.from_bytes(raw, "big")))


CORE_TYPES = {
    FederateHandle: _core.FederateHandle, ObjectClassHandle: _core.ObjectClassHandle,
    ObjectInstanceHandle: _core.ObjectHandle, InteractionClassHandle: _core.InteractionClassHandle,
    AttributeHandle: _core.AttributeHandle, ParameterHandle: _core.ParameterHandle,
    DimensionHandle: _core.DimensionHandle, RegionHandle: _core.RegionHandle,
}
