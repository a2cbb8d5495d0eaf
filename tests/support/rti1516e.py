"""What the IEEE 1516-2010 tests share: the FOM modules of tests/data/rti1516e, the service entries of the C++
header, a recording federate ambassador and a connected federate evoking its callbacks (the C++ test
programs: support.rti1516e_program)."""

from __future__ import annotations

import re
import time
from typing import Any, Callable

import hlacore.rti1516e as rti1516e

from . import ROOT

DATA = ROOT / "tests" / "data" / "rti1516e"
VEHICLES, CARS = str(DATA / "vehicles.xml"), str(DATA / "cars.xml")
FLEET = DATA / "fleet"
HEADER = ROOT / "cpp" / "rti1516e" / "include" / "RTI" / "RTIambassador.h"


def service_entries() -> list[str]:
    """The name of each entry of RTI1516E_SERVICES in RTIambassador.h, overloads each once, in order."""
    text = HEADER.read_text()
    body = text[text.index("#define RTI1516E_SERVICES(X)"):text.index("class RTI_EXPORT RTIambassador")]
    return re.findall(r"\bX\((?:[^,()]|<[^>]*>)+,\s*(\w+),", body)


class Recorder:
    """A federate ambassador that records every callback: (name, args) in order."""

    def __init__(self) -> None:
        self.calls: list[tuple[str, tuple[Any, ...]]] = []

    def __getattr__(self, name: str) -> Callable[..., None]:
        if name.startswith("_"):
            raise AttributeError(name)
        return lambda *args: self.calls.append((name, args))

    def named(self, name: str) -> list[tuple[Any, ...]]:
        return [args for n, args in self.calls if n == name]

    def last(self, name: str) -> tuple[Any, ...] | None:
        """The arguments of the latest call of `name`."""
        return next((args for n, args in reversed(self.calls) if n == name), None)


class Federate:
    """A connected 1516-2010 ambassador and its recorder."""

    def __init__(self, address: str) -> None:
        self.amb = Recorder()
        self.rtia = rti1516e.RTIambassador()
        self.rtia.connect(self.amb, "HLA_EVOKED", address)

    def until(self, done: Callable[[], bool], seconds: float = 10.0) -> None:
        deadline = time.monotonic() + seconds
        while not done():
            assert time.monotonic() < deadline, f"not done in {seconds} s; callbacks: {self.amb.calls[-5:]}"
            self.rtia.evokeMultipleCallbacks(0.02, 0.1)

    def close(self) -> None:
        try:
            self.rtia.resignFederationExecution(rti1516e.CANCEL_THEN_DELETE_THEN_DIVEST)
        except rti1516e.FederateNotExecutionMember:
            pass
        self.rtia.disconnect()
