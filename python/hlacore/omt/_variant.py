"""``HLAvariantRecord``: a discriminant, then the value of the alternative it selects."""

from __future__ import annotations

import operator
from collections.abc import Iterable, Mapping
from typing import Any

from ._base import HLAdataType, _Composite, _pack_padded, _unpack_padded
from ._bytes import _ERRORS, Buffer, _as_int, _check_buffer, _rethrow
from ._encoding import _target
from ._enumerated import HLAenumerated, HLAenumerator


def _show(value: Any) -> str:
    """Render a discriminant value for an error message."""
    return str(value) if isinstance(value, HLAenumerator) else repr(value)


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
