"""Blocking calls against a gateway the test has stopped (SIGSTOP): `python frozen_gateway.py ADDRESS RTIG_PID
MODE TIMEOUT`. TestFed exists. Everything each call needs is set up while the gateway runs; the peer reports
{"ready": true}, waits until the gateway's process is stopped, then makes the calls one after the other.

Then it lingers until the test ends it (so its connections end only where the calls closed them).

MODE "timeout": reports {"call": NAME, "raised": EXCEPTION, "after": SECONDS} for each call.
MODE "interrupt": reports {"calling": NAME} before each call, and {"call": NAME, "raised": ..., "after": ...}
once the test's SIGINT has ended it.
MODE "thread": one blocked updateAttributeValues while another thread counts 10 ms sleeps; reports
{"call": ..., "raised": ..., "after": ..., "counted": N}.
"""

from __future__ import annotations

import sys
import threading
import time
from typing import Callable

import hlacore.rti as rti
from peerlib import linger, say

FED = "TestFed"
BIG = b"\0" * (16 << 20)  # more than the socket buffers of both ends hold: the send blocks


def joined(address: str, name: str, timeout: float) -> rti.RTIAmbassador:
    rtia = rti.RTIAmbassador(address, timeout=timeout)
    rtia.joinFederationExecution(name, FED, rti.FederateAmbassador())
    return rtia


def publisher(address: str, name: str, timeout: float) -> Callable[[], object]:
    """An update of a 16 MiB value, ready to send."""
    rtia = joined(address, name, timeout)
    robot = rtia.getObjectClassHandle("robot")
    location = rtia.getAttributeHandle("location", robot)
    rtia.publishObjectClass(robot, [location])
    obj = rtia.registerObjectInstance(robot)
    return lambda: rtia.updateAttributeValues(obj, {location: BIG}, "")


def interaction_sender(address: str, name: str, timeout: float) -> Callable[[], object]:
    rtia = joined(address, name, timeout)
    command = rtia.getInteractionClassHandle("command")
    value = rtia.getParameterHandle("value", command)
    rtia.publishInteractionClass(command)
    return lambda: rtia.sendInteraction(command, {value: BIG}, "")


def blocking_calls(address: str, timeout: float) -> dict[str, Callable[[], object]]:
    """Each blocking call of a federate, on an ambassador of its own (a call that fails closes it)."""
    robot_class = lambda r: r.getObjectClassHandle("robot")  # noqa: E731
    fresh = rti.RTIAmbassador(address, timeout=timeout)
    creator = rti.RTIAmbassador(address, timeout=timeout)
    registrant = joined(address, "registrant", timeout)
    registrant.publishObjectClass(robot_class(registrant), [registrant.getAttributeHandle("location", robot_class(registrant))])
    lbts = joined(address, "lbts", timeout)
    resigner = joined(address, "resigner", timeout)
    ticker = joined(address, "ticker", timeout)
    advancer = joined(address, "advancer", timeout)
    advancer.enable_time_management(1.0, timeout=30.0)
    return {
        "RTIAmbassador": lambda: rti.RTIAmbassador(address, timeout=timeout),
        "createFederationExecution": lambda: creator.createFederationExecution("Other", "robot.fed"),
        "joinFederationExecution": lambda: fresh.joinFederationExecution("late", FED, rti.FederateAmbassador()),
        "registerObjectInstance": lambda: registrant.registerObjectInstance(robot_class(registrant)),
        "queryLBTS": lbts.queryLBTS,
        "resignFederationExecution": lambda: resigner.resignFederationExecution(rti.ResignAction.NoAction),
        "tick": lambda: ticker.tick(10 * timeout, 10 * timeout),
        "advance_to": lambda: advancer.advance_to(5.0, timeout=10 * timeout),
        "updateAttributeValues": publisher(address, "publisher", timeout),
        "sendInteraction": interaction_sender(address, "sender", timeout),
    }


def wait_until_stopped(pid: int) -> None:
    deadline = time.monotonic() + 30
    while time.monotonic() < deadline:
        with open(f"/proc/{pid}/stat") as f:
            if f.read().rsplit(")", 1)[1].split()[0] == "T":
                return
        time.sleep(0.01)
    raise SystemExit("the gateway was not stopped")


def timed(name: str, call: Callable[[], object]) -> dict[str, object]:
    start = time.monotonic()
    try:
        call()
        raised = "nothing"
    except BaseException as e:  # noqa: BLE001 - the report names what ended the call, KeyboardInterrupt included
        raised = type(e).__name__
    return {"call": name, "raised": raised, "after": round(time.monotonic() - start, 3)}


def main() -> None:
    address, rtig_pid, mode, timeout = sys.argv[1], int(sys.argv[2]), sys.argv[3], float(sys.argv[4])
    if mode == "thread":
        calls = {"updateAttributeValues": publisher(address, "publisher", timeout)}
    else:
        calls = blocking_calls(address, timeout)
    say(ready=True)
    wait_until_stopped(rtig_pid)
    counted = 0

    def count() -> None:
        nonlocal counted
        while counted >= 0:
            time.sleep(0.01)
            counted += 1

    if mode == "thread":
        threading.Thread(target=count, daemon=True).start()
    for name, call in calls.items():
        if mode == "interrupt":
            say(calling=name)
        report = timed(name, call)
        if mode == "thread":
            report["counted"], counted = counted, -1
        say(**report)
    say(done=True)
    linger(120)  # alive until the test ends it: its connections end only where a failed call closed them


if __name__ == "__main__":
    main()
