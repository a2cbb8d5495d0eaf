"""The callback names are declared once (cpp/rti/wire/callbacks.hpp): the binding delivers those names,
Python reads them as hlacore._core.CALLBACKS, and FederateAmbassador's documentation lists exactly them."""

from __future__ import annotations

import pathlib
import re
import shutil
import subprocess

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



def _callback_messages() -> list[str]:
    block = HEADER.read_text().split("#define HLACORE_CALLBACK_MESSAGES(X)", 1)[1].split("\n\n", 1)[0]
    return re.findall(r"X\((\w+)\)", block)


def _compile_front_end(tmp_path: pathlib.Path, messages: list[str]) -> subprocess.CompletedProcess[str]:
    """Compiles (syntax only) a front end of wire::dispatch_callback with an overload for each of `messages`."""
    overloads = "\n".join(f"    int operator()(const wire::{name}&) {{ return 1; }}" for name in messages)
    source = tmp_path / "front_end.cpp"
    source.write_text(f"""#include "rti/wire/callbacks.hpp"
using namespace hlacore;
struct FrontEnd {{
{overloads}
    int unexpected() {{ return 0; }}
}};
int main() {{
    wire::Message m = wire::TimeAdvanceGrant{{}};
    FrontEnd f;
    return wire::dispatch_callback<int>(m, f);
}}
""")
    compiler = shutil.which("c++") or shutil.which("g++")
    assert compiler, "a C++ compiler is needed (./scripts/test.sh builds with one)"
    return subprocess.run([compiler, "-std=c++17", "-fsyntax-only", f"-I{ROOT / 'cpp'}", str(source)],
                          capture_output=True, text=True, timeout=120)


def test_a_front_end_without_an_overload_for_a_callback_does_not_compile(tmp_path: pathlib.Path) -> None:
    """wire::dispatch_callback's check: every message of HLACORE_CALLBACK_MESSAGES needs its overload."""
    messages = _callback_messages()
    assert "TimeAdvanceGrant" in messages and len(messages) > 30
    complete = _compile_front_end(tmp_path, messages)
    assert complete.returncode == 0, complete.stderr
    missing = _compile_front_end(tmp_path, [name for name in messages if name != "TimeAdvanceGrant"])
    assert missing.returncode != 0
    assert "a front end has no overload for a message of HLACORE_CALLBACK_MESSAGES" in missing.stderr
