"""``_FOMReader``: builds the data types of one OMT file from their elements, in any declaration order."""

from __future__ import annotations

import re
import xml.etree.ElementTree as ElementTree
from collections.abc import Callable
from typing import Any, NamedTuple

from ._arrays import HLAfixedArray, HLAvariableArray
from ._base import HLAdataType
from ._basic import _FloatType, _IntegerType
from ._encoding import HLAencoding
from ._enumerated import HLAenumerated
from ._namespace import _lookup_type, _standard_type
from ._record import HLAfixedRecord
from ._unsupported import _UnsupportedType
from ._variant import HLAvariantRecord
from ._xml import _alternative_items, _cardinality, _children, _integer, _text, _texts


class _Definition(NamedTuple):
    """A data type element of an OMT file."""

    kind: str
    element: ElementTree.Element


class _FOMError(ValueError):
    """A malformed data type definition; the message names file and type."""


class _Reference(HLAencoding):
    """A reference made by :func:`HLAuse`: resolved by ``resolver`` (a type
    of the same file), or else looked up in the package on first use; the
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
