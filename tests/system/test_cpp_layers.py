"""The C++ core is layered as docs/architecture.md draws it, read from the ``#include`` lines (nothing is built).

Directories under ``cpp/`` and what they may include of the project's own headers:

==================================  ==========================================================================
``fed_parser/``                     itself only: the FOM is below everything
shared (``rti/*.hpp``, ``rti/*.cpp``  the FOM and each other; never a side. What both sides use, rtig --status
but rtig_main.cpp, ``rti/wire/``,   included (``rti/net/``)
``rti/record/``, ``rti/net/``)
``rti/server/``                     the shared parts and the FOM; never the federate side
``rti/client/``                     the shared parts and the FOM; never the gateway side
``rti/rtig_main.cpp``               the gateway side, never the federate side (the Federate Protocol's door it
                                    opens through ``fedpro/server.hpp``, which names no federate side)
``hla13/``                          the federate side, never the gateway side
``rti1516e/``                       the federate side, never the gateway side (IEEE 1516-2010's API)
``certi/``                          the federate side, never the gateway side (hlacore-rtia)
``fedpro/``                         the federate side and the 1516-2010 API, never the gateway side (the HLA 4
                                    Federate Protocol's door, whose sessions are 1516-2010 federates)
``bindings/``                       anything: the Python module runs a gateway in-process too
==================================  ==========================================================================

A violation names the file, the line and the rule it breaks.
"""

from __future__ import annotations

import pathlib
import re
from typing import Iterator

import pytest

ROOT = pathlib.Path(__file__).resolve().parents[2]
CPP = ROOT / "cpp"
INCLUDE = re.compile(r'^[ \t]*#[ \t]*include[ \t]+"([^"]+)"', re.M)

SIDES = ("rti/server/", "rti/client/")
SHARED_DIRS = ("rti/wire/", "rti/record/", "rti/net/")
FRONT_ENDS = ("hla13", "rti1516e", "certi", "fedpro")  # the C++ front ends over the federate side, each a directory


def layer_of(relative: str) -> str:
    """The layer of a source file, by its path under cpp/."""
    if relative.startswith("fed_parser/"):
        return "fom"
    if relative.startswith("rti/server/"):
        return "server"
    if relative.startswith("rti/client/"):
        return "client"
    if relative == "rti/rtig_main.cpp":
        return "rtig"
    if relative.startswith(SHARED_DIRS) or (relative.startswith("rti/") and relative.count("/") == 1):
        return "shared"
    front_end = relative.split("/", 1)[0]
    return front_end if front_end in FRONT_ENDS else "free"  # bindings/, fuzz/: above both sides


#: For each layer, the include prefixes it must not use, and why.
FORBIDDEN = {
    "fom": (("rti/",), "the FOM parser is below the RTI"),
    "shared": (SIDES, "what both sides use includes neither side"),
    "server": (("rti/client/",), "the gateway side never includes the federate side"),
    "client": (("rti/server/",), "the federate side never includes the gateway side"),
    "rtig": (("rti/client/",), "rtig is the gateway: --status needs no federate side (rti/net/)"),
    "hla13": (("rti/server/",), "the HLA 1.3 API runs over the federate side only"),
    "rti1516e": (("rti/server/",), "the IEEE 1516-2010 API runs over the federate side only"),
    "certi": (("rti/server/",), "hlacore-rtia runs over the federate side only"),
    "fedpro": (("rti/server/",), "the Federate Protocol's sessions are federates: the federate side only"),
}


def sources() -> Iterator[pathlib.Path]:
    for path in sorted(CPP.rglob("*")):
        if path.suffix in (".hpp", ".cpp", ".hh", ".h") and path.is_file():
            yield path


def violations_in(relative: str, text: str) -> list[str]:
    """The includes of one file (its path under cpp/ and its text) that break its layer's rule."""
    forbidden = FORBIDDEN.get(layer_of(relative))
    if forbidden is None:
        return []
    prefixes, why = forbidden
    found = []
    for match in INCLUDE.finditer(text):
        included = match.group(1)
        if included.startswith(prefixes):
            line = text.count("\n", 0, match.start()) + 1
            found.append(f"cpp/{relative}:{line}: includes {included}: {why}")
    return found


def test_includes_follow_the_layers() -> None:
    problems = []
    for path in sources():
        relative = path.relative_to(CPP).as_posix()
        problems += violations_in(relative, path.read_text(errors="replace"))
    assert not problems, "\n".join(problems)


def test_every_layer_is_populated() -> None:
    """The rule is checked against files that exist: each layer it names holds sources."""
    layers = {layer_of(path.relative_to(CPP).as_posix()) for path in sources()}
    assert set(FORBIDDEN) <= layers, set(FORBIDDEN) - layers


@pytest.mark.parametrize("relative, include", [
    ("rti/client/reader.cpp", "rti/server/gateway.hpp"),
    ("rti/server/gateway.cpp", "rti/client/client.hpp"),
    ("rti/wire/codec.hpp", "rti/server/outbox.hpp"),
    ("rti/net/dial.cpp", "rti/client/client.hpp"),
    ("rti/time.hpp", "rti/server/time_manager.hpp"),
    ("rti/rtig_main.cpp", "rti/client/client.hpp"),
    ("hla13/ambassador.cpp", "rti/server/federation.hpp"),
    ("fed_parser/fom.hpp", "rti/wire/messages.hpp"),
])
def test_a_wrong_include_is_caught(relative: str, include: str) -> None:
    """The check itself: the same file with one include across its rule is reported, at that line."""
    text = (CPP / relative).read_text()
    assert not violations_in(relative, text)
    broken = text + f'\n#include "{include}"\n'
    [problem] = violations_in(relative, broken)
    assert problem.startswith(f"cpp/{relative}:{broken.count(chr(10))}: includes {include}")
