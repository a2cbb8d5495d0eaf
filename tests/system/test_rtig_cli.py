"""The `rtig` command line: readiness line, signals, argument errors, --fom-path and --verbose."""

from __future__ import annotations

import contextlib
import pathlib
import shutil
import signal
import socket
import subprocess
import time
from typing import Callable, Iterator

import pytest

from hlacore import rti

from support import ROBOT_FED, SANITIZER_REPORT, Federate, RtigProcess, rtig_executable, wait_for_log


def run_rtig(*args: str) -> subprocess.CompletedProcess[str]:
    """Run rtig to completion (for the arguments that make it exit at once)."""
    return subprocess.run(
        [rtig_executable(), *args], capture_output=True, text=True, stdin=subprocess.DEVNULL, timeout=10
    )


StartRtig = Callable[..., RtigProcess]


@pytest.fixture
def server_factory(tmp_path: pathlib.Path) -> Iterator[StartRtig]:
    """start(*args): an rtig with those arguments, logging in tmp_path; at the end of the test each one
    started is stopped by pid and checked for sanitizer reports."""
    started: list[RtigProcess] = []

    def start(*args: str) -> RtigProcess:
        started.append(RtigProcess(tmp_path, *args))
        return started[-1]

    yield start
    for server in started:
        server.stop()
        assert not SANITIZER_REPORT.search(server.log()), server.log()


def test_readiness_line_is_the_only_stdout(tmp_path: pathlib.Path) -> None:
    """`--port 0` prints exactly one line `rtig listening on 127.0.0.1:<free port>` (default host) and nothing else."""
    server = RtigProcess(tmp_path)
    try:
        assert server.host == "127.0.0.1"
        assert 0 < server.port < 65536
        with socket.create_connection(("127.0.0.1", server.port), timeout=5):
            pass
        server.proc.send_signal(signal.SIGTERM)
        server.proc.wait(timeout=10)
        assert server.proc.stdout is not None
        assert server.proc.stdout.read() == b""
    finally:
        status = server.stop()
    assert status == 0, server.log()
    assert not SANITIZER_REPORT.search(server.log()), server.log()


def test_two_instances_get_different_free_ports(server_factory: StartRtig) -> None:
    """Two `--port 0` servers each report their own real port, and each accepts a federate."""
    a, b = server_factory(), server_factory()
    assert a.port != b.port
    for server in (a, b):
        rtia = rti.RTIAmbassador(server.address)
        rtia.createFederationExecution("TestFed", ROBOT_FED)
        rtia.destroyFederationExecution("TestFed")


@pytest.mark.parametrize("signum", [signal.SIGTERM, signal.SIGINT], ids=["SIGTERM", "SIGINT"])
def test_signal_stops_cleanly_with_a_joined_federate(tmp_path: pathlib.Path, signum: int) -> None:
    """SIGTERM/SIGINT stop rtig within seconds with status 0 and `rtig: stopped`, even with a federate joined."""
    server = RtigProcess(tmp_path)
    try:
        creator = rti.RTIAmbassador(server.address)
        creator.createFederationExecution("TestFed", ROBOT_FED)
        fed = Federate(server.address, "joined")
        assert int(fed.handle) > 0
        start = time.monotonic()
        server.proc.send_signal(signum)
        status = server.proc.wait(timeout=5)
        assert time.monotonic() - start < 5
    finally:
        server.stop()
    log = server.log()
    assert status == 0, log
    assert "rtig: stopped" in log
    assert not SANITIZER_REPORT.search(log), log


def test_help_prints_usage_on_stdout_and_exits_0() -> None:
    """`--help` prints the usage (naming every option) on stdout and exits 0."""
    result = run_rtig("--help")
    assert result.returncode == 0, result.stderr
    assert result.stdout.startswith("usage: rtig")
    for option in ("--host", "--port", "--fom-path", "--frame-timeout", "--client-budget", "--stall-timeout",
                   "--max-frame", "--max-datagram", "--save-dir", "--verbose", "--tls-cert", "--tls-key", "--tls-ca",
                   "--busy-poll", "--unix"):
        assert option in result.stdout
    assert "rtig listening" not in result.stdout


# The values each option refuses ("invalid --port 'abc': must be ...").
REFUSED_VALUES = [
    ("--port", ["abc", "70000", "-1", "", "80x"]),
    ("--frame-timeout", ["0", "-1", "soon", "inf"]),
    ("--client-budget", ["1000", "lots"]),
    ("--stall-timeout", ["-1", "nan"]),
    ("--max-frame", ["1000", "2000000000"]),
    ("--max-datagram", ["100", "70000", "1400.5"]),
    ("--busy-poll", ["-1", "100001", "2.5", "fast"]),
    ("--save-dir", [""]),
    ("--federation-secret", ["x", "=f", "x="]),
]
NEEDING_A_VALUE = ["--port", "--host", "--fom-path", "--frame-timeout", "--save-dir", "--tls-cert"]


@pytest.mark.parametrize(
    "args, message",
    [
        (["--bogus"], "unknown argument '--bogus'"),
        (["--port", "0", "extra"], "unknown argument 'extra'"),
        (["--tls-key", "key.pem"], "--tls-cert and --tls-key go together"),
        *[([option], f"{option} needs a value") for option in NEEDING_A_VALUE],
        *[([option, value], f"invalid {option} '{value}': ") for option, values in REFUSED_VALUES for value in values],
    ],
)
def test_bad_arguments_exit_2_with_a_message(args: list[str], message: str) -> None:
    """A bad or missing argument exits 2 with a message and the usage on stderr, nothing on stdout."""
    result = run_rtig(*args)
    assert result.returncode == 2, (result.stdout, result.stderr)
    assert message in result.stderr
    assert "usage: rtig" in result.stderr
    assert result.stdout == ""


def test_port_in_use_exits_1_naming_the_address() -> None:
    """A port already listened on makes rtig exit 1 with a message naming HOST:PORT."""
    with socket.socket(socket.AF_INET, socket.SOCK_STREAM) as taken:
        taken.bind(("127.0.0.1", 0))
        taken.listen(1)
        port = taken.getsockname()[1]
        result = run_rtig("--port", str(port))
    assert result.returncode == 1, (result.stdout, result.stderr)
    assert f"127.0.0.1:{port}" in result.stderr
    assert "rtig listening" not in result.stdout


@pytest.fixture
def fom_dir(tmp_path: pathlib.Path, monkeypatch: pytest.MonkeyPatch) -> pathlib.Path:
    """A --fom-path directory holding only-on-gateway.fed; the test runs from a directory without it."""
    foms = tmp_path / "foms"
    foms.mkdir()
    shutil.copy(ROBOT_FED, foms / "only-on-gateway.fed")
    elsewhere = tmp_path / "elsewhere"
    elsewhere.mkdir()
    monkeypatch.chdir(elsewhere)
    return foms


@contextlib.contextmanager
def joined_to_f(server: RtigProcess, fed_file: str, resign: rti.ResignAction) -> Iterator[Federate]:
    """Federation F created from `fed_file` (as the federate names it) and federate 'joiner' in it; at the end
    it resigns with `resign` and F is destroyed."""
    creator = rti.RTIAmbassador(server.address)
    creator.createFederationExecution("F", fed_file)
    fed = Federate(server.address, "joiner", federation="F")
    yield fed
    fed.rtia.resignFederationExecution(resign)
    creator.destroyFederationExecution("F")


def test_fom_path_finds_a_fed_file_the_federate_cannot_read(
    tmp_path: pathlib.Path, fom_dir: pathlib.Path, server_factory: StartRtig
) -> None:
    """A FED name missing from the federate's CWD is found in the gateway's --fom-path; joining resolves handles."""
    assert not pathlib.Path("only-on-gateway.fed").exists()
    server = server_factory("--fom-path", str(tmp_path / "empty-dir"), "--fom-path", str(fom_dir))
    with joined_to_f(server, "only-on-gateway.fed", rti.ResignAction.DeleteObjectsAndReleaseAttributes) as fed:
        robot = fed.rtia.getObjectClassHandle("robot")
        assert fed.rtia.getObjectClassHandle(fed.rtia.getObjectClassName(robot)) == robot
        location = fed.rtia.getAttributeHandle("location", robot)
        assert fed.rtia.getAttributeName(location, robot) == "location"
        command = fed.rtia.getInteractionClassHandle("command")
        assert fed.rtia.getParameterName(fed.rtia.getParameterHandle("value", command), command) == "value"
        fed.rtia.publishObjectClass(robot, [location])
        fed.rtia.registerObjectInstance(robot, "r1")


def test_fom_path_uses_the_base_name_of_a_relative_path(fom_dir: pathlib.Path, server_factory: StartRtig) -> None:
    """A relative FED path with directories the federate cannot read is looked up by its base name in --fom-path."""
    server = server_factory("--fom-path", str(fom_dir))
    with joined_to_f(server, "no/such/dir/only-on-gateway.fed", rti.ResignAction.NoAction) as fed:
        assert int(fed.rtia.getObjectClassHandle("robot")) > 0


def test_fom_path_name_found_nowhere_raises_could_not_open_fed(
    tmp_path: pathlib.Path, fom_dir: pathlib.Path, server_factory: StartRtig
) -> None:
    """A FED name that neither the federate nor any --fom-path directory has raises CouldNotOpenFED."""
    server = server_factory("--fom-path", str(fom_dir))
    creator = rti.RTIAmbassador(server.address)
    with pytest.raises(rti.CouldNotOpenFED, match="nowhere.fed"):
        creator.createFederationExecution("F", "nowhere.fed")
    with pytest.raises(rti.CouldNotOpenFED):
        creator.createFederationExecution("F", str(tmp_path / "absent" / "elsewhere.fed"))
    with pytest.raises(rti.FederationExecutionDoesNotExist):
        creator.destroyFederationExecution("F")


def test_without_fom_path_a_missing_fed_raises_could_not_open_fed(fom_dir: pathlib.Path,
                                                                   server_factory: StartRtig) -> None:
    """Without --fom-path the gateway does not find the file either: CouldNotOpenFED."""
    server = server_factory()
    creator = rti.RTIAmbassador(server.address)
    with pytest.raises(rti.CouldNotOpenFED):
        creator.createFederationExecution("F", "only-on-gateway.fed")


def test_verbose_logs_the_join(server_factory: StartRtig) -> None:
    """`--verbose` logs the connection, the federation's creation and a federate's join to stderr."""
    server = server_factory("--verbose")
    creator = rti.RTIAmbassador(server.address)
    creator.createFederationExecution("TestFed", ROBOT_FED)
    fed = Federate(server.address, "chatty")
    wait_for_log(server, rf"rtig: 'chatty' joined 'TestFed' as federate {int(fed.handle)}\n")
    log = server.log()
    assert "rtig: connection from 127.0.0.1:" in log
    assert "rtig: created federation 'TestFed'" in log
    fed.rtia.resignFederationExecution(rti.ResignAction.NoAction)
    creator.destroyFederationExecution("TestFed")
    wait_for_log(server, r"rtig: destroyed federation 'TestFed'")


def test_quiet_by_default(server_factory: StartRtig) -> None:
    """Without --verbose a join and an orderly disconnect are not logged."""
    server = server_factory()
    creator = rti.RTIAmbassador(server.address)
    creator.createFederationExecution("TestFed", ROBOT_FED)
    fed = Federate(server.address, "quiet")
    fed.rtia.resignFederationExecution(rti.ResignAction.NoAction)
    creator.destroyFederationExecution("TestFed")
    del fed, creator
    assert "joined" not in server.log()
