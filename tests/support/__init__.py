"""What the tests share beyond their fixtures (those are in tests/conftest.py): where things are, the rtig
under test, federates that record their callbacks, waiting and ticking with a deadline, peer processes.
Topics of their own: `support.wire` (the wire protocol spoken by hand), `support.federations` (the scripted
federations several modules run), `support.ros`, `support.nethosts` (test hosts in network namespaces) and
`support.time_reference` (the reference model of time management). Test modules import from here, never from
one another nor from conftest. Everything started here is stopped here, by pid."""

from __future__ import annotations

import contextlib
import os
import pathlib
import re
import subprocess
import sys
import time
from typing import Any, Callable, Iterator, Optional, Sequence

from hlacore import rti
from hlacore.processes import Child, Rtig, SyncAmbassador, python_peer, rtig_beside_python
from hlacore.processes import round_trip as barrier  # noqa: F401 (the tests' name for it)

TESTS = pathlib.Path(__file__).resolve().parent.parent
ROOT = TESTS.parent  # the repository
DATA = TESTS / "data"
PEERS = TESTS / "peers"
ROBOT_FED = str(DATA / "robot.fed")
# The wire protocol's version, for the tests that speak it byte by byte (cpp/rti/wire/message_list.hpp).
PROTOCOL_VERSION = int(re.search(r"kProtocolVersion = (\d+);",
                                 (ROOT / "cpp" / "rti" / "wire" / "message_list.hpp").read_text()).group(1))
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


def rtia_executable() -> str:
    """hlacore-rtia under test: $HLACORE_TEST_RTIA (the sanitizer build), else the one installed beside Python."""
    beside = pathlib.Path(sys.executable).parent / "hlacore-rtia"
    return os.environ.get("HLACORE_TEST_RTIA") or str(beside)


def status_client() -> str:
    """The rtig that asks a gateway for its status (``rtig --status``): the one under test, which needs no federate
    side for it (cpp/rti/net/status_query.cpp)."""
    return rtig_executable()


def cpp_federate(name: str) -> str:
    """A C++ test federate of tests/cpp/hla13, built by ./scripts/test.sh against the installed package's
    HLA 1.3 API ($HLACORE_TEST_HLA13, else build/hla13-tests)."""
    default = ROOT / "build" / "hla13-tests"
    binary = pathlib.Path(os.environ.get("HLACORE_TEST_HLA13", default)) / name
    assert binary.exists(), f"{binary} is missing: ./scripts/test.sh builds it"
    return str(binary)


def rti1516e_program(name: str) -> str:
    """A C++ program of tests/cpp/rti1516e, built by ./scripts/test.sh with the sanitizers against the source
    tree's IEEE 1516-2010 API ($HLACORE_TEST_RTI1516E_DIR, else build/asan/rti1516e-tests)."""
    folder = pathlib.Path(os.environ.get("HLACORE_TEST_RTI1516E_DIR", ROOT / "build" / "asan" / "rti1516e-tests"))
    assert (folder / name).exists(), f"{folder / name} is missing: ./scripts/test.sh builds it"
    return str(folder / name)


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


def python_subprocess(script: str, *args: str, env: Optional[dict[str, str]] = None) -> Child:
    """tests/peers/<script> under this interpreter (hlacore.processes.Child: reports read with a deadline)."""
    return python_peer(PEERS / script, *args, env=env)


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


def wait_until(predicate: Any, timeout: float = 10.0) -> None:
    """Poll predicate() until it holds; fail after timeout seconds."""
    deadline = time.monotonic() + timeout
    while not predicate():
        assert time.monotonic() < deadline, "condition not reached within %.1f s" % timeout
        time.sleep(0.02)


def vm_rss(pid: int) -> int:
    """Resident set size of a process in bytes, from /proc/PID/status."""
    for line in pathlib.Path(f"/proc/{pid}/status").read_text().splitlines():
        if line.startswith("VmRSS:"):
            return int(line.split()[1]) * 1024
    raise AssertionError(f"no VmRSS for pid {pid}")


def release_rtig() -> Optional[str]:
    """The optimized rtig installed beside Python: the sanitizer build's allocator keeps freed memory in
    quarantine, which says nothing about rtig's own memory."""
    beside = pathlib.Path(sys.executable).parent / "rtig"
    return str(beside) if beside.exists() else None


def secret_file(directory: pathlib.Path, text: str, name: str = "secret") -> pathlib.Path:
    """A shared-secret file (`rtig --secret-file`) holding `text`, readable by its owner only."""
    path = directory / name
    path.write_text(text + "\n")
    path.chmod(0o600)
    return path


def peer_says(peer: Child) -> dict[str, Any]:
    """The next JSON line of tests/peers/save_peer.py (or ddm_save_peer.py)."""
    return peer.read_json(60.0)


def lockstep_peers(conductor: Conductor, steps: int, count: int, *flags: str) -> dict[str, list[str]]:
    """The arguments of `count` tests/peers/lockstep.py peers, p0, p1, ..., for Conductor.start."""
    return {f"p{i}": [conductor.address, f"p{i}", str(steps), str(count), *flags] for i in range(count)}


def make_certificate(directory: pathlib.Path, name: str, subject_alt_name: str) -> tuple[pathlib.Path, pathlib.Path]:
    """A self-signed certificate and its key (readable by its owner only) for `subject_alt_name` ("IP:127.0.0.1"),
    made by the `openssl` command, valid two days."""
    cert, key = directory / f"{name}.pem", directory / f"{name}.key"
    subprocess.run(["openssl", "req", "-x509", "-newkey", "ec", "-pkeyopt", "ec_paramgen_curve:prime256v1", "-nodes",
                    "-keyout", str(key), "-out", str(cert), "-days", "2", "-subj", f"/CN=hlacore test {name}",
                    "-addext", f"subjectAltName={subject_alt_name}"], check=True, capture_output=True)
    key.chmod(0o600)
    return cert, key
