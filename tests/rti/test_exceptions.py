"""hlacore.exceptions names every HLA 1.3 exception of the C++ list, and nothing else."""

from __future__ import annotations

import re

import hlacore.exceptions as exceptions
import hlacore.rti as rti
from hlacore import _core

from support import ROOT

HEADER = ROOT / "cpp" / "rti" / "exceptions.hpp"


def _declared_in_cpp() -> list[str]:
    block = HEADER.read_text().split("#define HLACORE_EXCEPTIONS(X)", 1)[1].split("\n\n", 1)[0]
    return re.findall(r"X\((\w+)\)", block)


def test_the_module_lists_the_cpp_exceptions_in_order() -> None:
    assert exceptions.__all__ == ["RTIexception", *_declared_in_cpp()]


def test_each_name_is_the_native_class_under_rtiexception() -> None:
    native = {n for n in dir(_core) if isinstance(getattr(_core, n), type) and issubclass(getattr(_core, n), _core.RTIexception)}
    assert set(exceptions.__all__) == native
    for name in exceptions.__all__:
        cls = getattr(exceptions, name)
        assert cls is getattr(_core, name) and issubclass(cls, exceptions.RTIexception)


def test_hlacore_rti_exposes_the_same_classes() -> None:
    for name in exceptions.__all__:
        assert getattr(rti, name) is getattr(exceptions, name)
        assert name in rti.__all__
    assert rti.RTIInternalError is exceptions.RTIinternalError  # PyHLA's spelling
