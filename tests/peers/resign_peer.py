"""A federate that resigns while another of its threads keeps sending (a bridge shutting down), for
tests/transport/test_resign_while_sending.py: `python resign_peer.py ADDRESS ROUNDS`.

Each round it joins TestFed as "shutting-down", registers a robot, starts a thread that sends location
updates and command interactions as fast as it can, resigns (DeleteObjectsAndReleaseAttributes) from the
main thread after a few hundred sends, and joins the thread. Reports one JSON line per round:
{"round": k, "resign": "ok" or the exception's name, "sent": N, "sender_stopped_by": the exception's name}.
"""

from __future__ import annotations

import sys
import threading

import hlacore.rti as rti
from peerlib import say


def one_round(address: str, rtia: rti.RTIAmbassador, k: int) -> None:
    rtia.joinFederationExecution("shutting-down", "TestFed", rti.FederateAmbassador())
    robot = rtia.getObjectClassHandle("robot")
    location = rtia.getAttributeHandle("location", robot)
    command = rtia.getInteractionClassHandle("command")
    value = rtia.getParameterHandle("value", command)
    rtia.publishObjectClass(robot, [location])
    rtia.publishInteractionClass(command)
    obj = rtia.registerObjectInstance(robot, f"leaving-{k}")
    sent = 0
    started = threading.Event()
    stopped_by: list[str] = []

    def keep_sending() -> None:
        nonlocal sent
        try:
            while True:
                rtia.updateAttributeValues(obj, {location: b"%d" % sent}, "")
                rtia.sendInteraction(command, {value: b"%d" % sent}, "")
                sent += 1
                if sent == 200:
                    started.set()
        except rti.RTIexception as e:
            stopped_by.append(type(e).__name__)
            started.set()

    sender = threading.Thread(target=keep_sending)
    sender.start()
    started.wait(30)
    try:
        rtia.resignFederationExecution(rti.ResignAction.DeleteObjectsAndReleaseAttributes)
        outcome = "ok"
    except rti.RTIexception as e:
        outcome = f"{type(e).__name__}: {e}"
    sender.join(30)
    say(round=k, resign=outcome, sent=sent, sender_stopped_by=stopped_by[0] if stopped_by else None)


def main() -> None:
    address, rounds = sys.argv[1], int(sys.argv[2])
    rtia = rti.RTIAmbassador(address)  # one ambassador: it must be able to join again after each resign
    for k in range(rounds):
        one_round(address, rtia, k)


if __name__ == "__main__":
    main()
