"""rtig at the limits of its process: out of file descriptors. (The protocol's own limits — frame size,
outbound queue, partial-frame timeout — are tested in tests/transport/test_robustness.py; all are listed in
docs/robustness.md.)"""

from __future__ import annotations

import os
import resource
import socket
import struct

import hlacore.rti as rti

from support import PROTOCOL_VERSION, ROBOT_FED, Federate, RtigProcess, wait_for_log

HELLO = struct.pack("<IHIH", 8, 1, 0x484C4143, PROTOCOL_VERSION)


def answered(sock: socket.socket) -> bool:
    """True if the gateway answers a Hello on this connection, False if it closed it."""
    try:
        sock.sendall(HELLO)
        return bool(sock.recv(64))
    except (ConnectionResetError, BrokenPipeError):
        return False


def test_out_of_file_descriptors_refuses_new_connections_without_spinning(rtig: RtigProcess) -> None:
    """With its descriptor limit lowered to 4 above what it uses, rtig accepts 4 more connections and closes
    each further one at once with one log line (`refused a connection: Too many open files`) — before, it
    spun on the listening socket logging `accept failed` hundreds of thousands of times a second. The joined
    federate keeps working, and once connections close new federates join again."""
    creator = rti.RTIAmbassador(rtig.address)
    creator.createFederationExecution("TestFed", ROBOT_FED)
    alice = Federate(rtig.address, "alice")
    pid = rtig.proc.pid
    in_use = len(os.listdir(f"/proc/{pid}/fd"))
    soft, hard = resource.prlimit(pid, resource.RLIMIT_NOFILE)
    resource.prlimit(pid, resource.RLIMIT_NOFILE, (in_use + 4, hard))
    socks = []
    try:
        for _ in range(12):
            s = socket.create_connection((rtig.host, rtig.port), timeout=5)
            socks.append(s)
        results = [answered(s) for s in socks]
        assert results == [True] * 4 + [False] * 8, results
        wait_for_log(rtig, r"(refused a connection: Too many open files[^\n]*\n(.|\n)*){8}")
        log = rtig.log()
        assert log.count("refused a connection: Too many open files") == 8, log[-2000:]
        assert "accept failed" not in log
        # The joined federate still works, over its existing connection.
        robot = alice.rtia.getObjectClassHandle("robot")
        alice.rtia.publishObjectClass(robot, [alice.rtia.getAttributeHandle("location", robot)])
        assert alice.rtia.registerObjectInstance(robot, "still-here")
    finally:
        for s in socks:
            s.close()
    resource.prlimit(pid, resource.RLIMIT_NOFILE, (soft, hard))
    bob = Federate(rtig.address, "bob")
    bob.rtia.resignFederationExecution(rti.ResignAction.NoAction)
    alice.rtia.resignFederationExecution(rti.ResignAction.DeleteObjectsAndReleaseAttributes)
    creator.destroyFederationExecution("TestFed")
