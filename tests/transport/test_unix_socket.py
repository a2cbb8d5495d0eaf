"""A gateway on the same host over a Unix socket: `rtig --unix PATH` (or `hlacore.Gateway(unix=PATH)`) also
listens there, and federates connect with the address `unix:PATH` (docs/networking.md). The same federation
as over TCP, without datagrams; the socket file is its owner's only, replaces a stale one, refuses to take
over a live one, and goes away with the gateway."""

from __future__ import annotations

import os
import pathlib
import socket
import stat
import subprocess
import tempfile
import time
from typing import Iterator

import pytest

import hlacore
import hlacore.rti as rti

from support import (DATA, ROBOT_FED, Federate, RtigProcess, cpp_federate, joined_federation, rtig_executable,
                     running_rtig, share_robot_location, tick_until, wait_for_log)
from support.federations import check_federation, run_federation


@pytest.fixture
def socket_dir() -> Iterator[pathlib.Path]:
    """A short directory for socket files: a socket's path must fit in 107 bytes, which pytest's tmp_path
    names may not."""
    with tempfile.TemporaryDirectory(prefix="hlacore-unix-") as directory:
        yield pathlib.Path(directory)


@pytest.fixture
def unix_rtig(tmp_path: pathlib.Path, socket_dir: pathlib.Path) -> Iterator[RtigProcess]:
    with running_rtig(tmp_path, "--unix", str(socket_dir / "rtig.sock")) as server:
        yield server


def test_a_federation_over_a_unix_socket(unix_rtig: RtigProcess, socket_dir: pathlib.Path) -> None:
    path = socket_dir / "rtig.sock"
    assert unix_rtig.unix_address == f"unix:{path}"
    assert stat.S_ISSOCK(path.stat().st_mode) and stat.S_IMODE(path.stat().st_mode) == 0o600
    result = run_federation(unix_rtig.unix_address, tls=None)
    check_federation(result)
    # No datagrams over a Unix socket: the best-effort interactions came over the stream.
    for side in ("alice_datagrams", "bob_datagrams"):
        assert result[side]["path"] is False
        assert "Unix socket" in result[side]["reason"]
    assert "dropped" not in unix_rtig.log()


def test_federates_over_tcp_and_over_the_unix_socket_share_a_federation(unix_rtig: RtigProcess) -> None:
    """The same gateway serves both listeners: an update crosses from a TCP federate to a Unix one and back."""
    assert unix_rtig.unix_address is not None
    addresses = {"alice": unix_rtig.address, "bob": unix_rtig.unix_address}
    with joined_federation(unix_rtig.address, "MixedFederation", ROBOT_FED,
                           lambda _address, name: Federate(addresses[name], name, "MixedFederation")) as join:
        alice, bob = join("alice"), join("bob")
        robot, location = share_robot_location(alice, bob)
        bob.rtia.publishObjectClass(robot, [location])
        alice.rtia.subscribeObjectClassAttributes(robot, [location])
        for sender, receiver, value in ((alice, bob, b"over tcp"), (bob, alice, b"over unix")):
            obj = sender.rtia.registerObjectInstance(robot)
            sender.rtia.updateAttributeValues(obj, {location: value}, "")
            tick_until(lambda: any(list(args[1].values()) == [value]
                                   for args in receiver.amb.named("reflectAttributeValues")), receiver.rtia, timeout=30)


def test_the_socket_file_goes_away_with_the_rtig(tmp_path: pathlib.Path, socket_dir: pathlib.Path) -> None:
    path = socket_dir / "rtig.sock"
    with running_rtig(tmp_path, "--unix", str(path)):
        assert path.exists()
    assert not path.exists()


def test_a_stale_socket_file_is_replaced_and_a_live_one_refused(tmp_path: pathlib.Path,
                                                                 socket_dir: pathlib.Path) -> None:
    path = socket_dir / "rtig.sock"
    stale = socket.socket(socket.AF_UNIX)
    stale.bind(str(path))
    stale.close()  # the file stays, with nothing listening: a gateway that was killed
    with running_rtig(tmp_path, "--unix", str(path)) as server:
        check_federation(run_federation(str(server.unix_address), tls=None))
        second = subprocess.run([rtig_executable(), "--port", "0", "--unix", str(path)], capture_output=True,
                                text=True, timeout=30, stdin=subprocess.DEVNULL)
        assert second.returncode == 1
        assert f"cannot listen on {path}: another process listens there" in second.stderr
        check_federation(run_federation(str(server.unix_address), tls=None))  # the first one is unharmed


def test_a_path_that_is_not_a_socket_is_left_alone(tmp_path: pathlib.Path, socket_dir: pathlib.Path) -> None:
    path = socket_dir / "notes.txt"
    path.write_text("mine")
    done = subprocess.run([rtig_executable(), "--port", "0", "--unix", str(path)], capture_output=True, text=True,
                          timeout=30, stdin=subprocess.DEVNULL)
    assert done.returncode == 1
    assert "exists and is not a socket" in done.stderr
    assert path.read_text() == "mine"


def test_the_in_process_gateway_listens_on_a_unix_socket(socket_dir: pathlib.Path) -> None:
    path = socket_dir / "gateway.sock"
    with hlacore.Gateway(port=0, unix=path) as gw:
        assert gw.unix_address == f"unix:{path}"
        check_federation(run_federation(gw.unix_address, tls=None))
    assert not path.exists()
    assert hlacore.Gateway(port=0).unix_address is None


def open_fds() -> set[str]:
    """This process's open descriptors, each as "number -> what it is" (a socket's inode, a file's path)."""
    seen = set()
    for fd in os.listdir("/proc/self/fd"):
        try:
            seen.add(f"{fd} -> {os.readlink(f'/proc/self/fd/{fd}')}")
        except FileNotFoundError:  # closed meanwhile (the listing's own descriptor among them)
            pass
    return seen


def settled_fds(seconds: float = 2.0) -> set[str]:
    """:func:`open_fds` once they hold for 0.2 s (other threads of the process, a background gateway among them,
    may open and close one meanwhile)."""
    deadline = time.monotonic() + seconds
    fds, since = open_fds(), time.monotonic()
    while time.monotonic() - since < 0.2 and time.monotonic() < deadline:
        time.sleep(0.02)
        now = open_fds()
        if now != fds:
            fds, since = now, time.monotonic()
    return fds


def test_a_gateway_that_cannot_listen_on_its_socket_leaks_nothing(socket_dir: pathlib.Path) -> None:
    """Three gateways refused the socket another listens on leave no descriptor open: none is there afterwards
    that was not before (what else of this test process closes meanwhile does not count)."""
    path = socket_dir / "gateway.sock"
    with hlacore.Gateway(port=0, unix=path):
        before = settled_fds()
        for _ in range(3):
            with pytest.raises(RuntimeError, match="another process listens there"):
                hlacore.Gateway(port=0, unix=path)
        assert not settled_fds() - before


def test_connection_errors_name_the_socket(socket_dir: pathlib.Path) -> None:
    missing = socket_dir / "nobody.sock"
    with pytest.raises(rti.RTIinternalError, match=f"cannot connect to rtig at unix:{missing}: No such file"):
        rti.RTIAmbassador(f"unix:{missing}")
    too_long = "unix:/" + "x" * 200
    with pytest.raises(rti.RTIinternalError, match="longer than the 107 bytes"):
        rti.RTIAmbassador(too_long)
    with pytest.raises(rti.RTIinternalError, match="names no socket"):
        rti.RTIAmbassador("unix:")
    with pytest.raises(rti.RTIinternalError, match="TLS is for TCP"):
        rti.RTIAmbassador(f"unix:{missing}", tls=True)


def test_the_environment_names_a_unix_socket(unix_rtig: RtigProcess, monkeypatch: pytest.MonkeyPatch) -> None:
    """$HLACORE_RTIG=unix:PATH, as a PyHLA script is pointed at a gateway."""
    assert unix_rtig.unix_address is not None
    monkeypatch.setenv("HLACORE_RTIG", unix_rtig.unix_address)
    rtia = rti.RTIAmbassador()
    assert "Unix socket" in rtia.datagram_status()["reason"]
    rtia.createFederationExecution("EnvFederation", ROBOT_FED)
    rtia.destroyFederationExecution("EnvFederation")


def test_a_cpp_federate_connects_over_the_unix_socket(unix_rtig: RtigProcess) -> None:
    """The HLA 1.3 C++ API reads the same address from $HLACORE_RTIG: every service through the Unix socket."""
    assert unix_rtig.unix_address is not None
    run = subprocess.run([cpp_federate("hla13_services"), str(DATA / "ddm.fed")],
                         env={**os.environ, "HLACORE_RTIG": unix_rtig.unix_address}, capture_output=True, text=True,
                         timeout=120, stdin=subprocess.DEVNULL)
    assert run.returncode == 0, run.stdout + run.stderr
    assert run.stdout == "called 102 services\n"


def test_both_ends_size_their_send_buffer_and_the_gateway_names_the_peer_by_pid(tmp_path: pathlib.Path,
                                                                                socket_dir: pathlib.Path) -> None:
    """The federate's send buffer as large as net.core.wmem_max allows (4 MiB at most; the gateway sizes its
    end with the same call): the default held back streams of small updates (docs/performance.md). The
    gateway's log names a Unix peer by its process."""
    wanted = min(4 << 20, int(pathlib.Path("/proc/sys/net/core/wmem_max").read_text()))
    with running_rtig(tmp_path, "--unix", str(socket_dir / "rtig.sock"), "--verbose") as server:
        assert server.unix_address is not None
        rtia = rti.RTIAmbassador(server.unix_address)
        with socket.socket(fileno=os.dup(rtia.fileno())) as conn:
            assert conn.family == socket.AF_UNIX
            assert conn.getsockopt(socket.SOL_SOCKET, socket.SO_SNDBUF) >= wanted  # the kernel doubles it
        wait_for_log(server, rf"connection from unix socket, pid {os.getpid()}\b")
