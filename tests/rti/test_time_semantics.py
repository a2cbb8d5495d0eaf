"""The time rules a federation follows (docs/time-management.md, "Two readings: exact and CERTI's"), on the
case a CERTI user meets: two federates with zero lookahead, one looping timeAdvanceRequest(queryFederateTime())
as pythonApp does, the other enabling regulation after the first one's grant at 0.0. The exact rules place the
newcomer just above 0.0 and its TAR(now) waits on the other's loop, named in the status; CERTI's place it at
0.0 and both are granted."""

from __future__ import annotations

import threading
from typing import Any

import pytest

import hlacore
import hlacore.rti as rti
from hlacore.status import format_table, status
from support import ROBOT_FED


def loop_at_now(address: str, semantics: str, stop: threading.Event, first_grant: threading.Event,
                grants: list[float]) -> None:
    """Creates the federation with `semantics`, joins as "looper" (zero lookahead) and loops TAR(now)."""
    a = rti.RTIAmbassador(address, time_semantics=semantics)
    a.createFederationExecution("TestFed", ROBOT_FED)
    a.joinFederationExecution("looper", "TestFed", rti.FederateAmbassador())
    a.enable_time_management(0.0)
    while not stop.is_set():
        grants.append(a.advance_to(a.queryFederateTime(), timeout=10.0))
        first_grant.set()
    a.resignFederationExecution(rti.ResignAction.NoAction)


def late_regulator(address: str, semantics: str) -> tuple[float, int, dict[str, Any], list[float]]:
    """The newcomer's start, its grants within 1 s of TAR(now) and the status meanwhile, and the looper's grants."""
    stop, first_grant, looper_grants = threading.Event(), threading.Event(), []
    looper = threading.Thread(target=loop_at_now, args=(address, semantics, stop, first_grant, looper_grants))
    looper.start()
    try:
        assert first_grant.wait(10)
        b = rti.RTIAmbassador(address)
        b.joinFederationExecution("newcomer", "TestFed", rti.FederateAmbassador())
        start = b.enable_time_management(0.0, timeout=10.0)
        granted = 0
        try:
            while True:
                b.advance_to(b.queryFederateTime(), timeout=1.0)
                granted += 1
                if granted == 20:
                    break
        except TimeoutError:
            pass
        report = status(address)
    finally:
        stop.set()
        looper.join(30)
    assert not looper.is_alive()
    return start, granted, report, looper_grants


@pytest.mark.parametrize("semantics", ["exact", "certi"])
def test_a_regulator_joining_a_zero_lookahead_tar_loop(rtig: Any, semantics: str) -> None:
    start, granted, report, looper_grants = late_regulator(rtig.address, semantics)
    federation = report["federations"][0]
    assert federation["time_semantics"] == semantics
    newcomer = next(f for f in federation["federates"] if f["name"] == "newcomer")
    assert looper_grants and set(looper_grants) == {0.0}
    if semantics == "exact":
        assert start == 5e-324  # just above the looper's TAR grant at 0.0: nothing may reach it at 0.0
        assert granted == 0
        assert newcomer["pending"]["request"] == "TAR" and newcomer["pending"]["time"] == 5e-324
        assert [(h["name"], h["output_bound"]) for h in newcomer["held_by"]] == [("looper", 5e-324)]
        assert "newcomer waits on looper: it may still send at 4.941e-324" in format_table(report, 120)
    else:
        assert start == 0.0 and granted == 20  # CERTI's: at the looper's time, and granted with it
        assert newcomer["pending"] is None and newcomer["held_by"] == []


def test_the_gateway_default_and_the_creators_choice(tmp_path: Any) -> None:
    """rtig --time-semantics (hlacore.Gateway(time_semantics=)) is the default; a creator's own choice
    (time_semantics=, $HLACORE_TIME_SEMANTICS) wins; a value that is neither is refused naming the option."""
    with hlacore.Gateway(port=0, time_semantics="certi") as gw:
        rti.RTIAmbassador(gw.address).createFederationExecution("ByDefault", ROBOT_FED)
        rti.RTIAmbassador(gw.address, time_semantics="exact").createFederationExecution("Chosen", ROBOT_FED)
        found = {f["name"]: f["time_semantics"] for f in status(gw.address)["federations"]}
    assert found == {"ByDefault": "certi", "Chosen": "exact"}
    with pytest.raises(rti.RTIinternalError, match="time_semantics='relaxed': must be exact or certi"):
        rti.RTIAmbassador("127.0.0.1:1", time_semantics="relaxed")
    with pytest.raises(ValueError, match="time_semantics='loose': must be exact or certi"):
        hlacore.Gateway(port=0, time_semantics="loose")
