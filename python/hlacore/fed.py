"""HLA 1.3 ``.fed`` files: the Federation Object Model as frozen dataclasses, and a linter.

The parsing itself is done by the C++ core (the same parser the gateway uses), so the handles here are the
handles of a running federation: CERTI's numbering, where a subclass repeats its parent's attribute
(or parameter) handles and numbers its own after them.

``python -m hlacore.fed FILE...`` checks files and reports errors as ``FILE:LINE:COL: message``.
"""

from __future__ import annotations

import os
import sys
from collections.abc import Sequence
from dataclasses import dataclass, field
from functools import cached_property
from typing import Any, ClassVar, Generic, Literal, TypeVar

from . import _core

ErrorReadingFED = _core.ErrorReadingFED
CouldNotOpenFED = _core.CouldNotOpenFED

__all__ = [
    "Attribute",
    "CouldNotOpenFED",
    "Dimension",
    "ErrorReadingFED",
    "Fom",
    "InteractionClass",
    "MAX_FED_BYTES",
    "ObjectClass",
    "Parameter",
    "RoutingSpace",
    "main",
    "parse",
    "parse_text",
]

Transport = Literal["reliable", "best_effort"]
Order = Literal["timestamp", "receive"]

MAX_FED_BYTES = 256 << 20
"""The largest ``.fed`` text the parser reads (the C++ ``kMaxFedBytes``, 256 MiB): a longer one raises
ErrorReadingFED at ``1:1`` (and the gateway refuses such a file in its ``--fom-path`` the same way)."""

# Root classes whose name CERTI does not prepend to their children's names.
OBJECT_ROOTS = ("ObjectRoot", "HLAobjectRoot")
INTERACTION_ROOTS = ("InteractionRoot", "HLAinteractionRoot")


@dataclass(frozen=True)
class _Handled:
    """What every element of the FOM has: its handle and its name."""

    handle: int
    name: str


_N = TypeVar("_N", bound=_Handled)


def _check_key(key: object, what: str) -> None:
    if isinstance(key, bool) or not isinstance(key, (int, str)):
        raise TypeError(f"{what} is looked up by handle (int) or name (str), not {type(key).__name__}")


class _Lookup(Generic[_N]):
    """The items of one list by handle and by name (the first declared wins a name), so that a lookup in a
    class of 40 000 attributes is a dict access, not a scan."""

    __slots__ = ("by_handle", "by_name")

    def __init__(self, items: Sequence[_N]) -> None:
        self.by_handle = {item.handle: item for item in items}
        self.by_name = {item.name: item for item in reversed(items)}

    def find(self, key: int | str, what: str) -> _N:
        """The item whose handle (int) or name (str) is ``key``; KeyError naming ``what`` otherwise."""
        _check_key(key, what)
        found = self.by_handle.get(key) if isinstance(key, int) else self.by_name.get(key)
        if found is None:
            raise KeyError(f"no {what} {key!r}")
        return found


class _Members(Generic[_N]):
    """What object classes, interaction classes and routing spaces share: a list of members (attributes,
    parameters, dimensions: the field named by ``_MEMBERS``) looked up by handle or name."""

    _MEMBERS: ClassVar[str]

    @cached_property
    def _members(self) -> _Lookup[_N]:
        # Built on first use: most classes of a large FOM are never looked into by name.
        return _Lookup(getattr(self, self._MEMBERS))

    def _member(self, key: int | str, what: str) -> _N:
        return self._members.find(key, what)


@dataclass(frozen=True)
class Attribute(_Handled):
    """An attribute of an object class; ``space`` is the routing space name, None without one."""

    transport: Transport
    order: Order
    space: str | None = None


@dataclass(frozen=True)
class _Class(_Handled):
    """What object and interaction classes share: their place in the class tree."""

    qualified_name: str
    parent: int | None
    children: tuple[int, ...]


@dataclass(frozen=True)
class ObjectClass(_Class, _Members[Attribute]):
    """An object class. ``attributes`` holds the inherited attributes first (with the parent's handles)."""

    _MEMBERS = "attributes"
    attributes: tuple[Attribute, ...]

    def attribute(self, name_or_handle: int | str) -> Attribute:
        """The attribute with this handle or name; KeyError if the class has none."""
        return self._member(name_or_handle, f"attribute of class {self.qualified_name!r} with name/handle")


@dataclass(frozen=True)
class Parameter(_Handled):
    """A parameter of an interaction class."""


@dataclass(frozen=True)
class InteractionClass(_Class, _Members[Parameter]):
    """An interaction class. ``parameters`` holds the inherited parameters first (with the parent's handles)."""

    _MEMBERS = "parameters"
    transport: Transport
    order: Order
    space: str | None
    parameters: tuple[Parameter, ...]

    def parameter(self, name_or_handle: int | str) -> Parameter:
        """The parameter with this handle or name; KeyError if the class has none."""
        return self._member(name_or_handle, f"parameter of interaction class {self.qualified_name!r} with name/handle")


@dataclass(frozen=True)
class Dimension(_Handled):
    """A dimension of a routing space."""


@dataclass(frozen=True)
class RoutingSpace(_Handled, _Members[Dimension]):
    """A routing space and its dimensions."""

    _MEMBERS = "dimensions"
    dimensions: tuple[Dimension, ...]

    def dimension(self, name_or_handle: int | str) -> Dimension:
        """The dimension with this handle or name; KeyError if the space has none."""
        return self._member(name_or_handle, f"dimension of space {self.name!r} with name/handle")


@dataclass(frozen=True)
class _ClassIndex:
    by_handle: dict[int, Any]
    by_qualified: dict[str, Any]
    by_leaf: dict[str, Any]

    @staticmethod
    def of(classes: Sequence[ObjectClass | InteractionClass]) -> _ClassIndex:
        # Built from the end so that the first declared class wins a shared leaf name.
        """Index ``classes`` by handle, qualified name and leaf name."""
        return _ClassIndex(
            {c.handle: c for c in classes},
            {c.qualified_name: c for c in reversed(classes)},
            {c.name: c for c in reversed(classes)},
        )

    def find(self, key: int | str, roots: tuple[str, ...], what: str) -> Any:
        """The class with handle ``key``, or named ``key``: qualified, qualified under one of ``roots``
        (``ObjectRoot.robot``), or by its leaf name; KeyError naming ``what`` otherwise."""
        _check_key(key, what)
        if isinstance(key, int):
            if key in self.by_handle:
                return self.by_handle[key]
            raise KeyError(f"no {what} with handle {key}")
        if key in self.by_qualified:
            return self.by_qualified[key]
        for root in roots:
            rest = key[len(root) + 1 :]
            if key.startswith(root + ".") and rest in self.by_qualified:
                return self.by_qualified[rest]
        if key in self.by_leaf:
            return self.by_leaf[key]
        raise KeyError(f"no {what} named {key!r}")

    def is_subclass(self, cls: int, ancestor: int) -> bool:
        """Whether the class with handle ``cls`` is the class ``ancestor`` or one of its subclasses."""
        c = self.by_handle.get(cls)
        while c is not None:
            if c.handle == ancestor:
                return True
            c = self.by_handle.get(c.parent) if c.parent is not None else None
        return False


@dataclass(frozen=True)
class Fom:
    """A parsed ``.fed`` file.

    Class lookups follow CERTI: the qualified name (``"robot.wheeled"``), the same preceded by a root class
    name (``"ObjectRoot.robot"``, ``"HLAobjectRoot.robot"``), or a bare leaf name (the first class declared
    with it). Names are case-sensitive.
    """

    federation_name: str
    fed_version: str
    source_name: str
    spaces: tuple[RoutingSpace, ...]
    object_classes: tuple[ObjectClass, ...]
    interaction_classes: tuple[InteractionClass, ...]
    _objects: _ClassIndex = field(init=False, repr=False, compare=False)
    _interactions: _ClassIndex = field(init=False, repr=False, compare=False)
    _spaces: _Lookup[RoutingSpace] = field(init=False, repr=False, compare=False)

    def __post_init__(self) -> None:
        object.__setattr__(self, "_objects", _ClassIndex.of(self.object_classes))
        object.__setattr__(self, "_interactions", _ClassIndex.of(self.interaction_classes))
        object.__setattr__(self, "_spaces", _Lookup(self.spaces))

    def object_class(self, name_or_handle: int | str) -> ObjectClass:
        """The object class with this handle or name (CERTI's name rules); KeyError if none."""
        result: ObjectClass = self._objects.find(name_or_handle, OBJECT_ROOTS, "object class")
        return result

    def interaction_class(self, name_or_handle: int | str) -> InteractionClass:
        """The interaction class with this handle or name (CERTI's name rules); KeyError if none."""
        result: InteractionClass = self._interactions.find(name_or_handle, INTERACTION_ROOTS, "interaction class")
        return result

    def space(self, name_or_handle: int | str) -> RoutingSpace:
        """The routing space with this handle or name; KeyError if none."""
        return self._spaces.find(name_or_handle, "routing space with name/handle")

    def is_object_subclass(self, cls: int | str, ancestor: int | str) -> bool:
        """True when object class ``cls`` is ``ancestor`` or one of its descendants."""
        return self._objects.is_subclass(self.object_class(cls).handle, self.object_class(ancestor).handle)

    def is_interaction_subclass(self, cls: int | str, ancestor: int | str) -> bool:
        """True when interaction class ``cls`` is ``ancestor`` or one of its descendants."""
        return self._interactions.is_subclass(
            self.interaction_class(cls).handle, self.interaction_class(ancestor).handle
        )


def _from_core(data: dict[str, Any]) -> Fom:
    """Build the dataclasses from the plain data returned by ``_core.parse_fed``."""
    return Fom(
        federation_name=data["federation_name"],
        fed_version=data["fed_version"],
        source_name=data["source_name"],
        spaces=tuple(
            RoutingSpace(h, name, tuple(Dimension(dh, dn) for dh, dn in dims)) for h, name, dims in data["spaces"]
        ),
        object_classes=tuple(
            ObjectClass(h, name, qualified, parent, tuple(children), tuple(Attribute(*a) for a in attrs))
            for h, name, qualified, parent, children, attrs in data["object_classes"]
        ),
        interaction_classes=tuple(
            InteractionClass(
                h, name, qualified, parent, tuple(children), transport, order, space,
                tuple(Parameter(ph, pn) for ph, pn in params),
            )
            for h, name, qualified, parent, children, transport, order, space, params in data["interaction_classes"]
        ),
    )


def parse_text(text: str, name: str = "<string>") -> Fom:
    """Parse the text of a ``.fed`` file; ``name`` is used in error messages.

    Raises ErrorReadingFED (``str()`` is ``NAME:LINE:COL: message``; attributes ``file``, ``line``,
    ``column``) on the first error, and for a text longer than MAX_FED_BYTES in UTF-8. Time and memory are
    linear in the text's size (a 10 MB FED parses in a fraction of a second).
    """
    return _from_core(_core.parse_fed(text, name))


def parse(path: str | os.PathLike[str]) -> Fom:
    """Read and parse a ``.fed`` file.

    Raises CouldNotOpenFED when the file cannot be read, ErrorReadingFED when it is malformed or longer
    than MAX_FED_BYTES.
    """
    name = os.fspath(path)
    try:
        with open(name, "rb") as f:
            data = f.read(MAX_FED_BYTES + 1)  # enough for the parser to refuse a longer file
    except OSError as e:
        raise CouldNotOpenFED(f"{name}: cannot open FED file: {e.strerror or e}") from e
    # Undecodable bytes become U+FFFD: harmless in comments and strings, reported as an invalid
    # character anywhere else.
    return parse_text(data.decode("utf-8", errors="replace"), name)


_USAGE = "usage: python -m hlacore.fed FILE...\ncheck HLA 1.3 .fed files; errors are printed as FILE:LINE:COL: message"


def main(argv: Sequence[str] | None = None) -> int:
    """Lint each file named in ``argv``: 0 if all parse, 1 if any does not, 2 on a usage error."""
    args = list(sys.argv[1:] if argv is None else argv)
    files: list[str] = []
    options_done = False
    for arg in args:
        if options_done or not arg.startswith("-"):
            files.append(arg)
        elif arg == "--":
            options_done = True
        elif arg in ("-h", "--help"):
            print(_USAGE)
            return 0
        else:
            print(f"{_USAGE}\nerror: unknown option {arg}", file=sys.stderr)
            return 2
    if not files:
        print(f"{_USAGE}\nerror: no file given", file=sys.stderr)
        return 2
    status = 0
    for path in files:
        try:
            fom = parse(path)
        except (ErrorReadingFED, CouldNotOpenFED) as e:
            print(e, file=sys.stderr)
            status = 1
        else:
            print(
                f"{path}: ok ({len(fom.object_classes)} object classes, "
                f"{len(fom.interaction_classes)} interaction classes)"
            )
    return status


if __name__ == "__main__":
    sys.exit(main())
