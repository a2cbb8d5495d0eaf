"""Fixtures: an in-process gateway, the real `rtig` executable on port 0, and helpers to tick until a
condition holds. Everything started here is stopped here, by pid."""

from __future__ import annotations

import contextlib
import os
import pathlib
import re
import time
from typing import Any, Callable, Iterator, Optional, Sequence

import pytest

import hlacore
from hlacore import rti
from hlacore.federates.robot_world import FEDERATION as ROBOT_WORLD_FEDERATION
from hlacore.federates.robot_world import FOM_PATH as ROBOT_WORLD_FOM
from hlacore.processes import Child, Rtig, SyncAmbassador, python_peer, rtig_beside_python
from hlacore.processes import round_trip as barrier  # noqa: F401 (the tests' name for it)

DATA = pathlib.Path(__file__).parent / "data"
ROBOT_FED = str(DATA / "robot.fed")
# The wire protocol's version, for the tests that speak it byte by byte (cpp/rti/wire/message_list.hpp).
PROTOCOL_VERSION = int(re.search(r"kProtocolVersion = (\d+);", (pathlib.Path(__file__).parent.parent / "cpp" / "rti"
                                                                / "wire" / "message_list.hpp").read_text()).group(1))
SANITIZER_REPORT = re.compile(r"ERROR: AddressSanitizer|runtime error:|ERROR: LeakSanitizer")
# The A* path of the paper's 5x5 grid (hlacore.federates.robot_driver.PAPER_5X5) from (0, 0) to (4, 4): what the
# driver's planner must find and the robot experiment drives.
PAPER_PATH = [(0, 0), (0, 1), (0, 2), (0, 3), (1, 3), (2, 3), (2, 2), (2, 1), (2, 0), (3, 0), (4, 0), (4, 1), (4, 2),
              (4, 3), (4, 4)]
# The rover of the robot-world federate and ROS tests, as the `define` lines of a .world text (a TurtleBot-sized
# differential drive with a 5-beam, 4 m, 40-degree sonar at its nose); each test appends its robots and walls.
ROVER_MODEL = """
define sonar ranger ( sensor( pose [0 0 0 0] range [0.02 4.0] fov 40 samples 5 ) )
define bot position ( size [0.33 0.33 0.4] drive "diff" sonar(pose [0.165 0 0 0]) )"""


def rtig_executable() -> str:
    """The rtig under test: $HLACORE_TEST_RTIG (the sanitizer build), else the one installed beside Python."""
    return os.environ.get("HLACORE_TEST_RTIG") or rtig_beside_python()


def status_client() -> str:
    """The rtig that asks a gateway for its status (``rtig --status``): the one under test, which needs no federate
    side for it (cpp/rti/net/status_query.cpp)."""
    return rtig_executable()


def cpp_federate(name: str) -> str:
    """A C++ test federate of tests/cpp/hla13, built by ./scripts/test.sh against the installed package's
    HLA 1.3 API ($HLACORE_TEST_HLA13, else build/hla13-tests)."""
    default = pathlib.Path(__file__).parent.parent / "build" / "hla13-tests"
    binary = pathlib.Path(os.environ.get("HLACORE_TEST_HLA13", default)) / name
    assert binary.exists(), f"{binary} is missing: ./scripts/test.sh builds it"
    return str(binary)


class RtigProcess(Rtig):
    """The rtig under test on port 0, its log in the test's tmp_path."""

    def __init__(self, tmp_path: pathlib.Path, *args: str, executable: Optional[str] = None,
                 prefix: Sequence[str] = ()) -> None:
        log_path = tmp_path / f"rtig-{len(list(tmp_path.glob('rtig-*.log')))}.log"
        super().__init__(*args, executable=executable or rtig_executable(), log_path=log_path, prefix=prefix)


@contextlib.contextmanager
def running_rtig(tmp_path: pathlib.Path, *args: str, executable: Optional[str] = None) -> Iterator[RtigProcess]:
    """An rtig with the given arguments; fails if it exits uncleanly or reports a sanitizer error."""
    server = RtigProcess(tmp_path, *args, executable=executable)
    try:
        yield server
    finally:
        status = server.stop()
        log = server.log()
        assert not SANITIZER_REPORT.search(log), log
        assert status == 0, f"rtig exited with {status}; log:\n{log}"


def wait_for_log(server: RtigProcess, pattern: str, timeout: float = 5.0) -> str:
    """Poll the rtig log until `pattern` (a regex) matches; return the matching text."""
    deadline = time.monotonic() + timeout
    while True:
        match = re.search(pattern, server.log())
        if match:
            return match.group(0)
        if time.monotonic() > deadline:
            raise AssertionError(f"{pattern!r} not logged within {timeout} s; log:\n{server.log()}")
        time.sleep(0.02)


@pytest.fixture
def rtig(tmp_path: pathlib.Path) -> Iterator[RtigProcess]:
    """The real rtig binary on port 0."""
    with running_rtig(tmp_path) as server:
        yield server


@pytest.fixture
def inprocess_gateway() -> Iterator[hlacore.Gateway]:
    with hlacore.Gateway(port=0) as gw:
        yield gw


@pytest.fixture
def world_federation(gateway_address: str) -> Iterator[str]:
    """The robot world's federation (hlacore.federates.robot_world's FOM) on each gateway; its address."""
    creator = rti.RTIAmbassador(gateway_address)
    creator.createFederationExecution(ROBOT_WORLD_FEDERATION, str(ROBOT_WORLD_FOM))
    yield gateway_address
    creator.destroyFederationExecution(ROBOT_WORLD_FEDERATION)


@pytest.fixture(params=["in-process", "rtig"])
def gateway_address(request: pytest.FixtureRequest) -> str:
    """The address of a gateway: both the in-process one and the real rtig executable."""
    if request.param == "in-process":
        return str(request.getfixturevalue("inprocess_gateway").address)
    return str(request.getfixturevalue("rtig").address)


class Recorder(rti.FederateAmbassador):
    """Records every callback as (name, args)."""

    def __init__(self) -> None:
        self.calls: list[tuple[str, tuple[Any, ...]]] = []

    def named(self, name: str) -> list[tuple[Any, ...]]:
        return [args for n, args in self.calls if n == name]

    def _record(name: str) -> Callable[..., None]:  # type: ignore[misc]
        def callback(self: "Recorder", *args: Any) -> None:
            self.calls.append((name, args))

        callback.__name__ = name
        return callback

    for _name in (
        "synchronizationPointRegistrationSucceeded",
        "synchronizationPointRegistrationFailed",
        "announceSynchronizationPoint",
        "federationSynchronized",
        "startRegistrationForObjectClass",
        "stopRegistrationForObjectClass",
        "turnInteractionsOn",
        "turnInteractionsOff",
        "discoverObjectInstance",
        "reflectAttributeValues",
        "receiveInteraction",
        "removeObjectInstance",
        "provideAttributeValueUpdate",
        "timeRegulationEnabled",
        "timeConstrainedEnabled",
        "timeAdvanceGrant",
        "requestRetraction",
        "requestAttributeOwnershipAssumption",
        "attributeOwnershipDivestitureNotification",
        "attributeOwnershipAcquisitionNotification",
        "attributeOwnershipUnavailable",
        "requestAttributeOwnershipRelease",
        "confirmAttributeOwnershipAcquisitionCancellation",
        "informAttributeOwnership",
        "attributeIsNotOwned",
        "attributeOwnedByRTI",
        "initiateFederateSave",
        "federationSaved",
        "federationNotSaved",
        "requestFederationRestoreSucceeded",
        "requestFederationRestoreFailed",
        "federationRestoreBegun",
        "initiateFederateRestore",
        "federationRestored",
        "federationNotRestored",
        "attributesInScope",
        "attributesOutOfScope",
        "turnUpdatesOnForObjectInstance",
        "turnUpdatesOffForObjectInstance",
    ):
        locals()[_name] = _record(_name)
    del _name, _record


def tick_until(
    predicate: Callable[[], bool], *ambassadors: rti.RTIAmbassador, timeout: float = 5.0
) -> None:
    """Tick every ambassador until predicate() holds; fail after timeout seconds."""
    deadline = time.monotonic() + timeout
    while not predicate():
        if time.monotonic() > deadline:
            raise AssertionError("condition not reached within %.1f s" % timeout)
        for amb in ambassadors:
            amb.tick(0.01, 0.05)


def settle(*ambassadors: rti.RTIAmbassador, seconds: float = 0.2) -> None:
    """Tick everyone for a while, to show that nothing more arrives."""
    deadline = time.monotonic() + seconds
    while time.monotonic() < deadline:
        for amb in ambassadors:
            amb.tick(0.01, 0.02)


class Federate:
    """One joined federate: its RTI ambassador (connected with `tls`, as RTIAmbassador takes it) and a Recorder."""

    def __init__(self, address: str, name: str, federation: str = "TestFed", tls: Any = None) -> None:
        self.rtia = rti.RTIAmbassador(address, tls=tls)
        self.amb = Recorder()
        self.handle = self.rtia.joinFederationExecution(name, federation, self.amb)

    def enable_time(self, lookahead: Optional[float] = 1.0, constrained: bool = True) -> None:
        """Enable regulation (unless lookahead is None) and/or constrained, waiting for each callback."""
        self.rtia.enable_time_management(
            lookahead or 0.0, timeout=5.0, regulating=lookahead is not None, constrained=constrained
        )


def share_robot_location(publisher: Federate, subscriber: Federate) -> tuple[Any, Any]:
    """`publisher` publishes robot.location and `subscriber` subscribes to it: the (robot, location) handles."""
    robot = publisher.rtia.getObjectClassHandle("robot")
    location = publisher.rtia.getAttributeHandle("location", robot)
    publisher.rtia.publishObjectClass(robot, [location])
    subscriber.rtia.subscribeObjectClassAttributes(robot, [location])
    return robot, location


@contextlib.contextmanager
def joined_federation(address: str, federation: str, fed_file: str,
                      make: Callable[[str, str], Any], tls: Any = None) -> Iterator[Callable[[str], Any]]:
    """Creates `federation` from `fed_file` (connected with `tls`); yields join(name) -> make(address, name); at
    the end every federate joined so resigns (best effort: it may be gone or mid-save) and the federation is
    destroyed."""
    creator = rti.RTIAmbassador(address, tls=tls)
    creator.createFederationExecution(federation, fed_file)
    joined: list[Any] = []

    def join(name: str) -> Any:
        fed = make(address, name)
        joined.append(fed)
        return fed

    yield join
    for fed in joined:
        try:
            fed.rtia.resignFederationExecution(rti.ResignAction.DeleteObjectsAndReleaseAttributes)
        except (rti.FederateNotExecutionMember, rti.SaveInProgress, rti.RestoreInProgress):
            pass
    creator.destroyFederationExecution(federation)


@pytest.fixture
def federation(gateway_address: str) -> Iterator[Callable[[str], Federate]]:
    """Creates TestFed from tests/data/robot.fed; returns a function joining federates to it."""
    with joined_federation(gateway_address, "TestFed", ROBOT_FED, Federate) as join:
        yield join


class Conductor:
    """The test's own federate: creates TestFed, starts peer processes (each prints {"ready": true} when
    set up) and releases them all at once with synchronization point 'start'."""

    def __init__(self, address: str) -> None:
        self.address = address
        self.rtia = rti.RTIAmbassador(address)
        self.rtia.createFederationExecution("TestFed", ROBOT_FED)
        self.amb = Recorder()
        self.rtia.joinFederationExecution("conductor", "TestFed", self.amb)
        self.peers: dict[str, Child] = {}

    def start(self, script: str, args: dict[str, list[str]], timeout: float = 30.0) -> None:
        """Start tests/peers/<script> once per name with its arguments; wait until each is ready."""
        for name, peer_args in args.items():
            self.peers[name] = python_subprocess(script, *peer_args)
        for name in args:
            assert self.peers[name].read_json(timeout) == {"ready": True}

    def synchronize(self, timeout: float = 30.0) -> None:
        self.rtia.registerFederationSynchronizationPoint("start", "")
        tick_until(lambda: bool(self.amb.named("announceSynchronizationPoint")), self.rtia)
        self.rtia.synchronizationPointAchieved("start")
        tick_until(lambda: bool(self.amb.named("federationSynchronized")), self.rtia, timeout=timeout)

    def close(self) -> None:
        for peer in self.peers.values():
            peer.close()
        self.rtia.resignFederationExecution(rti.ResignAction.NoAction)
        self.rtia.destroyFederationExecution("TestFed")


@pytest.fixture
def conductor(rtig: RtigProcess) -> Iterator[Conductor]:
    c = Conductor(rtig.address)
    yield c
    c.close()


def python_subprocess(script: str, *args: str, env: Optional[dict[str, str]] = None) -> Child:
    """tests/peers/<script> under this interpreter (hlacore.processes.Child: reports read with a deadline)."""
    return python_peer(pathlib.Path(__file__).parent / "peers" / script, *args, env=env)


def lead_peers(conductor: rti.RTIAmbassador, amb: SyncAmbassador, peers: dict[str, Child],
               timeout: float = 120.0) -> dict[str, dict[str, Any]]:
    """Conduct peers that print {"ready": true}, wait for synchronization point "start" and then print their
    report: the conductor (joined with `amb`) registers and achieves "start", then collects each report and
    checks that each peer exits 0. The peers are closed however it ends."""
    try:
        for peer in peers.values():
            assert peer.read_json(60) == {"ready": True}
        conductor.registerFederationSynchronizationPoint("start", "")
        deadline = time.monotonic() + 30
        while "start" not in amb.announced:
            assert time.monotonic() < deadline, "start was not announced"
            conductor.tick(0.05, 0.1)
        conductor.synchronizationPointAchieved("start")
        while "start" not in amb.synchronized:
            assert time.monotonic() < deadline, "the federation did not synchronize on start"
            conductor.tick(0.05, 0.1)
        results = {name: peer.read_json(timeout) for name, peer in peers.items()}
        for peer in peers.values():
            assert peer.wait(30) == 0, peer.stderr()
        return results
    finally:
        for peer in peers.values():
            peer.close()
