"""The stand-in for a type whose encoding hlacore.omt does not implement: it loads, and fails when used."""

from __future__ import annotations

from collections.abc import Iterable
from typing import Any, NoReturn

from ._base import HLAdataType, _Composite
from ._bytes import Buffer


class _UnsupportedType(_Composite):
    """A type :func:`HLAuse` read whose encoding ``hlacore.omt`` does
    not implement: it loads (so the rest of the FOM does) and raises
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
