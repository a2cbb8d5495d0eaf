"""The ambassador's conveniences beyond PyHLA: create_or_join and enable_time_management."""

from __future__ import annotations

import signal

import pytest

import hlacore.rti as rti
from support import ROBOT_FED, Recorder, RtigProcess


def test_create_or_join_creates_once_then_joins(gateway_address: str) -> None:
    first, second = rti.RTIAmbassador(gateway_address), rti.RTIAmbassador(gateway_address)
    a = first.create_or_join("a", "Conv", ROBOT_FED, rti.FederateAmbassador())
    b = second.create_or_join("b", "Conv", ROBOT_FED, rti.FederateAmbassador())  # exists: joins it
    assert a != b
    with pytest.raises(rti.FederatesCurrentlyJoined):
        first.destroyFederationExecution("Conv")
    for rtia in (first, second):
        rtia.resignFederationExecution(rti.ResignAction.NoAction)
    first.destroyFederationExecution("Conv")


def test_create_or_join_without_a_fed_file_only_joins(gateway_address: str) -> None:
    rtia = rti.RTIAmbassador(gateway_address)
    with pytest.raises(rti.FederationExecutionDoesNotExist):
        rtia.create_or_join("a", "Absent", None, rti.FederateAmbassador())


def test_create_or_join_reports_a_bad_fed_file(gateway_address: str, tmp_path) -> None:  # type: ignore[no-untyped-def]
    bad = tmp_path / "bad.fed"
    bad.write_text("(FED (Federation x)")
    with pytest.raises(rti.ErrorReadingFED):
        rti.RTIAmbassador(gateway_address).create_or_join("a", "Bad", str(bad), rti.FederateAmbassador())


def test_enable_time_management_with_an_ambassador_that_ignores_the_callbacks(gateway_address: str) -> None:
    rtia = rti.RTIAmbassador(gateway_address)
    rtia.create_or_join("plain", "Conv", ROBOT_FED, rti.FederateAmbassador())
    assert rtia.enable_time_management(2.0, timeout=30) == 0.0
    # Regulating with lookahead 2: the sending rule refuses a timestamp below 2.
    robot = rtia.getObjectClassHandle("robot")
    location = rtia.getAttributeHandle("location", robot)
    rtia.publishObjectClass(robot, [location])
    obj = rtia.registerObjectInstance(robot)
    with pytest.raises(rti.InvalidFederationTime):
        rtia.updateAttributeValues(obj, {location: b"x"}, "", 1.0)
    rtia.updateAttributeValues(obj, {location: b"x"}, "", 2.0)
    # Both enabled: enabling again is refused with the "already" exceptions.
    with pytest.raises(rti.TimeRegulationAlreadyEnabled):
        rtia.enableTimeRegulation(0.0, 1.0)
    with pytest.raises(rti.TimeConstrainedAlreadyEnabled):
        rtia.enableTimeConstrained()
    assert rtia.advance_to(1.0, timeout=30) == 1.0
    rtia.resignFederationExecution(rti.ResignAction.DeleteObjectsAndReleaseAttributes)
    rtia.destroyFederationExecution("Conv")


def test_enable_time_management_delivers_the_callbacks_to_the_ambassador(gateway_address: str) -> None:
    rtia, amb = rti.RTIAmbassador(gateway_address), Recorder()
    rtia.create_or_join("recorded", "Conv", ROBOT_FED, amb)
    rtia.enable_time_management(1.0, timeout=30)
    assert amb.named("timeRegulationEnabled") == [(0.0,)]
    assert amb.named("timeConstrainedEnabled") == [(0.0,)]
    rtia.resignFederationExecution(rti.ResignAction.NoAction)
    rtia.destroyFederationExecution("Conv")


def test_enable_time_management_can_leave_one_out(gateway_address: str) -> None:
    rtia, amb = rti.RTIAmbassador(gateway_address), Recorder()
    rtia.create_or_join("constrained-only", "Conv", ROBOT_FED, amb)
    rtia.enable_time_management(1.0, timeout=30, regulating=False)
    assert amb.named("timeConstrainedEnabled") and not amb.named("timeRegulationEnabled")
    rtia.enableTimeRegulation(0.0, 1.0)  # not enabled by the call: allowed now
    rtia.resignFederationExecution(rti.ResignAction.NoAction)
    rtia.destroyFederationExecution("Conv")


def test_enable_time_management_times_out_on_a_frozen_gateway(rtig: RtigProcess) -> None:
    rtia = rti.RTIAmbassador(rtig.address)
    rtia.create_or_join("frozen", "Conv", ROBOT_FED, rti.FederateAmbassador())
    rtig.proc.send_signal(signal.SIGSTOP)
    try:
        with pytest.raises(TimeoutError):
            rtia.enable_time_management(1.0, timeout=0.5)
    finally:
        rtig.proc.send_signal(signal.SIGCONT)
    # The requests stayed pending and complete once the gateway runs again.
    with pytest.raises(rti.EnableTimeRegulationPending):
        rtia.enableTimeRegulation(0.0, 1.0)
    rtia.resignFederationExecution(rti.ResignAction.NoAction)
    rtia.destroyFederationExecution("Conv")
