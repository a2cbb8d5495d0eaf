"""The callback names are declared once (cpp/rti/wire/callbacks.hpp): the binding delivers those names,
Python reads them as hlacore._core.CALLBACKS, and FederateAmbassador's documentation lists exactly them."""

from __future__ import annotations

import re

import hlacore.rti as rti
from hlacore import _core

from support import ROOT

HEADER = ROOT / "cpp" / "rti" / "wire" / "callbacks.hpp"


def _declared_in_cpp() -> list[str]:
    block = HEADER.read_text().split("#define HLACORE_CALLBACKS(X)", 1)[1].split("\n\n", 1)[0]
    return re.findall(r"X\((\w+)\)", block)


def test_the_module_lists_the_declared_callbacks_in_order() -> None:
    assert list(_core.CALLBACKS) == _declared_in_cpp()
    assert len(set(_core.CALLBACKS)) == len(_core.CALLBACKS)


def test_federate_ambassador_documents_exactly_the_callbacks() -> None:
    documented = re.findall(r"``(\w+)\(", rti.FederateAmbassador.__doc__ or "")
    assert sorted(set(documented)) == sorted(_core.CALLBACKS)
