"""What the services of hlacore.rti1516e share: exceptions translated at every service, the checks of the
values they take, and the FOM modules read at creation and at join."""

from __future__ import annotations

import functools
import os
from typing import Any, Callable, Dict, Mapping, Tuple, TypeVar

from .. import _core
from . import _exceptions as x
from ._handles import core

F = TypeVar("F", bound=Callable[..., Any])

def translating(method: F) -> F:
    """`method`, raising IEEE 1516-2010's exception for each of the core's."""
    @functools.wraps(method)
    def call(*args: Any, **kwargs: Any) -> Any:
        try:
            return method(*args, **kwargs)
        except _core.RTIexception as error:
            raise x.translate(error) from None
    return call  # type: ignore[return-value]


def services(cls: Any) -> Any:
    """Every public method of `cls` raises IEEE 1516-2010's exceptions for the core's."""
    for name, value in list(vars(cls).items()):
        if callable(value) and not name.startswith("_"):
            setattr(cls, name, translating(value))
    return cls


def not_served(service: str, why: str) -> x.Exception:
    """The RTIinternalError of a service hlacore does not serve yet, saying why."""
    return x.RTIinternalError(f"RTIinternalError: hlacore does not serve {service} yet: {why}")


def values_of(handle_type: type, values: Mapping[Any, Any]) -> Dict[Any, bytes]:
    """A map of handles of kind `handle_type` to bytes-like values, as the core's handles to bytes."""
    if not hasattr(values, "items"):
        raise TypeError(f"a dict of {handle_type.__name__} to bytes was expected, not {type(values).__name__}")
    out = {}
    for h, v in values.items():
        if isinstance(v, str) or v is None:
            raise TypeError(f"the value of {h!r} must be bytes-like, not {type(v).__name__}")
        out[core(handle_type, h)] = bytes(v)
    return out


def tag_of(tag: Any) -> bytes:
    """A user-supplied tag: bytes-like, not str."""
    if isinstance(tag, str) or tag is None:
        raise TypeError(f"a tag is bytes-like, not {type(tag).__name__}")
    return bytes(tag)


def legal_name(name: Any) -> str:
    """An object instance name a federate may reserve (IllegalName for the RTI's, beginning with HLA)."""
    if isinstance(name, bytes):
        name = name.decode("latin-1")
    if not isinstance(name, str):
        raise TypeError(f"an object instance name is a str, not {type(name).__name__}")
    if not name or name.startswith("HLA"):
        raise x.IllegalName(f"IllegalName: {name!r} (names beginning with HLA are the RTI's)")
    return name


def module_text(module: Any) -> Tuple[str, str]:
    """A FOM module given as a path or file: URL: (its name, its text; "" when this process cannot read it)."""
    if isinstance(module, bytes):
        module = module.decode("utf-8", "surrogateescape")
    if not isinstance(module, str):
        raise TypeError(f"a FOM module is given by its path or URL, not {type(module).__name__}")
    path = module[len("file://"):] if module.startswith("file://") else module[len("file:"):] \
        if module.startswith("file:") else module
    if not os.path.isfile(path):
        return module, ""
    try:
        with open(path, "r", encoding="utf-8", errors="surrogateescape") as f:
            return module, f.read()
    except OSError as error:
        raise x.CouldNotOpenFDD(f"CouldNotOpenFDD: cannot read {module!r}: {error.strerror}") from None


def added_modules(modules: Any) -> str:
    """The FOM modules a federate adds at join (paths or file: URLs), read here and checked on their own, as a
    bundle ("" for none): CouldNotOpenFDD for one this process cannot read (the gateway does not look them up),
    ErrorReadingFDD (FILE:LINE:COL) for one that does not read."""
    names = [modules] if isinstance(modules, (str, bytes)) else list(modules)
    if not names:
        return ""
    read = [module_text(m) for m in names]
    unread = [n for n, text in read if not text]
    if unread:
        raise x.CouldNotOpenFDD(f"CouldNotOpenFDD: cannot open {unread[0]!r}")
    pairs = [(text, n) for n, text in read]
    _core.parse_fom_modules(pairs)  # errors at the caller, ErrorReadingFED as ErrorReadingFDD
    return _core.fom_bundle(pairs).decode("utf-8", "surrogateescape")


