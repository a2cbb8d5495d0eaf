"""``HLAencoding``, PyHLA's forward reference: a data type named now and looked up in ``hlacore.omt``
when first used."""

from __future__ import annotations

from collections.abc import Callable, Mapping
from typing import Any

from ._base import HLAdataType
from ._bytes import Buffer
from ._namespace import _constructor, _lookup_type


class HLAencoding(HLAdataType):
    """PyHLA's lazy reference to a data type: ``HLAencoding("Pose")`` is a
    data type that looks ``Pose`` up in ``hlacore.omt``'s namespace on first
    use (``pack``, ``unpack``, ``octetBoundary``), so a type may be
    referenced before it is defined::

        fom.Path = fom.HLAvariableArray("Path", fom.HLAencoding("Pose"))
        fom.Pose = fom.HLAfixedRecord("Pose", [("x", fom.HLAfloat64BE)])
        fom.Path.pack([{"x": 1.0}])

    With ``typeParameters``, ``representation`` names a type constructor
    of ``hlacore.omt`` (``"HLAfixedArray"`` ...) called on first use with the
    parameters: a tuple or list is passed as positional arguments, a
    mapping as keyword arguments (PyHLA passed the tuple as one argument,
    which its own constructors did not accept)::

        fom.HLAencoding("HLAfixedArray", ("Vector", fom.HLAfloat32BE, 3))

    The name is resolved once; the result is kept.  A name that is not a
    data type of ``hlacore.omt`` when first used raises ``KeyError`` naming
    it (and is looked up again on the next use); a chain of references
    that leads back to itself raises ``ValueError``.  Other attributes
    (``fields``, ``enumerators`` ...) are those of the resolved type.
    """

    def __init__(self, representation: str,
                 typeParameters: Any = None) -> None:
        """Refer to the data type (or constructor) named ``representation``."""
        if not isinstance(representation, str):
            raise TypeError(
                f"HLAencoding: representation must be a type name (str), "
                f"not {type(representation).__name__}")
        self.representation = representation
        self.typeParameters = typeParameters
        first = (typeParameters[0] if isinstance(typeParameters, (tuple, list))
                 and typeParameters else None)
        self.name = first if isinstance(first, str) else representation
        self._encoding: HLAdataType | None = None
        self._resolving = False

    def _resolve(self) -> HLAdataType:
        """Find or build the referenced data type."""
        if self.typeParameters is None:
            found = _lookup_type(self.representation)
            if found is None:
                raise KeyError(
                    f"HLAencoding: no data type named "
                    f"{self.representation!r} in hlacore.omt")
            return found
        constructor = _constructor(self.representation)
        if not (isinstance(constructor, type)
                and issubclass(constructor, HLAdataType)):
            raise KeyError(
                f"HLAencoding: no data type constructor named "
                f"{self.representation!r} in hlacore.omt")
        build: Callable[..., HLAdataType] = constructor
        parameters = self.typeParameters
        if isinstance(parameters, Mapping):
            return build(**parameters)
        if isinstance(parameters, (tuple, list)):
            return build(*parameters)
        return build(parameters)

    def _pending(self) -> bool:
        """Whether the reference is unresolved, or its target's layout is
        not computed yet."""
        return self._encoding is None or self._encoding._pending()

    @property
    def resolved(self) -> bool:
        """Whether the reference has been resolved."""
        return self._encoding is not None

    @property
    def encoding(self) -> HLAdataType:
        """The referenced data type, resolved on first access (following
        references to references)."""
        target = self._encoding
        if target is None:
            if self._resolving:
                raise ValueError(
                    f"HLAencoding {self.name!r}: circular reference (the "
                    f"name leads back to itself)")
            self._resolving = True
            try:
                target = self._resolve()
                if isinstance(target, HLAencoding):
                    target = target.encoding
            finally:
                self._resolving = False
            self._encoding = target
        return target

    @property
    def octetBoundary(self) -> int:
        """The referenced type's ``octetBoundary``."""
        return self.encoding.octetBoundary

    @octetBoundary.setter
    def octetBoundary(self, value: int) -> None:
        raise AttributeError(f"{self.name}: octetBoundary is read-only")

    @property
    def fixed_size(self) -> int | None:
        """The referenced type's ``fixed_size``."""
        return self.encoding.fixed_size

    @fixed_size.setter
    def fixed_size(self, value: int | None) -> None:
        raise AttributeError(f"{self.name}: fixed_size is read-only")

    def pack(self, value: Any) -> bytes:
        """Encode ``value`` with the referenced type."""
        return self.encoding.pack(value)

    def unpack(self, buffer: Buffer, offset: int = 0) -> tuple[Any, int]:
        """Decode with the referenced type; return ``(value, size)``."""
        return self.encoding.unpack(buffer, offset)

    def __getattr__(self, attribute: str) -> Any:
        """Return the attribute of the referenced type."""
        if attribute.startswith("_"):
            raise AttributeError(attribute)
        return getattr(self.encoding, attribute)


def _target(datatype: HLAdataType) -> HLAdataType:
    """The data type behind ``datatype``, resolving forward references."""
    return datatype.encoding if isinstance(datatype, HLAencoding) else datatype
