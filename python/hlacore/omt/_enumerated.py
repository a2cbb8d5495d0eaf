"""``HLAenumerated`` and its values, ``HLAenumerator``: ints that know their name and print as PyHLA's."""

from __future__ import annotations

import operator
import warnings
from collections.abc import Iterable, Mapping
from typing import Any

from ._base import HLAdataType, _Composite
from ._bytes import _ERRORS, Buffer, _as_int, _rethrow


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
        representation = self.representation
        wrapped = {}
        for number in self._by_value:
            try:
                representation.pack(number)  # check the range
            except ValueError:
                wrapped[number] = self._bit_pattern(number)
        if wrapped:
            self._rewrap(wrapped)
        return representation.octetBoundary, representation.fixed_size

    def _bit_pattern(self, number: int) -> int:
        """``number``, beyond a signed representation's range but within its width, as the value of its bit
        pattern: tools in the field read the RPR FOM's ``EmitterTypeEnum16`` (32805 in an ``HLAinteger16BE``)
        so; anything else out of range is refused."""
        low = getattr(self.representation, "_min", 0)
        high = getattr(self.representation, "_max", 0)
        if low < 0 and high < number <= 2 * high + 1:
            return number - 2 * (high + 1)
        self.representation.pack(number)  # raises, naming the range
        raise AssertionError("unreachable")

    def _rewrap(self, wrapped: Mapping[int, int]) -> None:
        """The enumerators whose values are read as their bit pattern, said once for the type."""
        for name, enumerator in list(self.enumerators.items()):
            if int(enumerator) in wrapped:
                self.enumerators[name] = HLAenumerator(self.name, name, wrapped[int(enumerator)])
        self._by_value = {}
        for enumerator in self.enumerators.values():
            self._by_value.setdefault(int(enumerator), enumerator)
        shown = ", ".join(f"{n} as {w}" for n, w in wrapped.items())
        warnings.warn(f"{self.name}: enumerator values beyond {self.representation.name}'s range are read as its "
                      f"bit pattern: {shown}", stacklevel=2)

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
