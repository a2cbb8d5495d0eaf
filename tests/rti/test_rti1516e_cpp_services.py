"""Every IEEE 1516-2010 service of the C++ API called from C++ through rtig: tests/cpp/rti1516e/services.cpp
(built by ./scripts/test.sh) calls each entry of RTI1516E_SERVICES, overloads apart, with an asserted outcome,
and prints how many entries it called, which must be the number the header lists (so a service added to the
header and not called fails here)."""

from __future__ import annotations

import os
import subprocess

from support import RtigProcess, rti1516e_program as program
from support.rti1516e import CARS, VEHICLES, service_entries


def test_the_header_lists_151_entries_of_140_names() -> None:
    entries = service_entries()
    assert len(entries) == 151 and len(set(entries)) == 140
    assert entries[0] == "connect" and entries[-1] == "decodeRegionHandle"
    assert entries.count("joinFederationExecution") == 2 and entries.count("updateAttributeValues") == 2


def test_every_service_from_cpp(rtig: RtigProcess) -> None:
    """The gateway's address from $HLACORE_RTIG: the program connects with an empty settings designator."""
    run = subprocess.run([program("rti1516e_services"), VEHICLES, CARS], capture_output=True, text=True,
                         timeout=240, env={**os.environ, "HLACORE_RTIG": rtig.address})
    assert run.returncode == 0, run.stdout + run.stderr
    assert run.stdout == f"called {len(service_entries())} services\n"
