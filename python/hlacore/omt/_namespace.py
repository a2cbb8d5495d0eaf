"""The namespace of ``hlacore.omt``, where ``HLAencoding`` looks names up and ``HLAuse`` defines the
types of a FOM: the package binds its own namespace here once it has imported everything."""

from __future__ import annotations

from typing import Any

from ._base import HLAdataType

#: Data types defined by :func:`HLAuse`, by name, including those whose name
#: is taken by another attribute of the package.
_fom_types: dict[str, HLAdataType] = {}

_names: dict[str, Any] = {}  # the package's namespace (vars(hlacore.omt)), once bound
_module_names: frozenset[str] = frozenset()  # its own names: HLAuse never replaces them


def _bind(names: dict[str, Any]) -> None:
    """Make ``names`` (the package's ``globals()``, all its own names
    defined) the namespace that the functions below read and write."""
    global _names, _module_names
    _names = names
    _module_names = frozenset(names)


def _lookup_type(name: str) -> HLAdataType | None:
    """The data type the package calls ``name`` (its own, one set by hand,
    or one :func:`HLAuse` defined), or None."""
    found = _names.get(name)
    if isinstance(found, HLAdataType):
        return found
    return _fom_types.get(name)


def _standard_type(name: str) -> HLAdataType | None:
    """The package's own data type called ``name`` (one :func:`HLAuse`
    never replaces), or None."""
    if name in _module_names:
        found = _names.get(name)
        if isinstance(found, HLAdataType):
            return found
    return None


def _constructor(name: str) -> Any:
    """What the package calls ``name`` (a type constructor, if anything)."""
    return _names.get(name)


def _define(name: str, datatype: HLAdataType) -> None:
    """Record a data type :func:`HLAuse` read, and make it an attribute of
    the package unless ``name`` is one of the package's own."""
    _fom_types[name] = datatype
    if name not in _module_names:
        _names[name] = datatype
