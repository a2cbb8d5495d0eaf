"""Resigning while another thread still sends, as a bridge shutting down does (docs/robustness.md, case 6). The
resign goes out in the socket's order with the other thread's messages; from it on, that thread's updates and
interactions raise FederateNotExecutionMember at the call instead of reaching the gateway after the resign
(a protocol error that dropped the connection, lost the resign's reply and left the ambassador unusable).
Against the real rtig, the resigning federate in its own process, a watcher in the test process."""

from __future__ import annotations

import re

import hlacore.rti as rti
from hlacore.processes import python_peer

from support import PEERS, ROBOT_FED, RtigProcess, tick_until

PEER = PEERS / "resign_peer.py"
ROUNDS = 20


class Watcher(rti.FederateAmbassador):
    def __init__(self) -> None:
        self.reflected = 0
        self.interactions = 0
        self.removed: set[str] = set()
        self.names: dict[object, str] = {}

    def discoverObjectInstance(self, obj: object, cls: object, name: str) -> None:
        self.names[obj] = name

    def reflectAttributeValues(self, *args: object) -> None:
        self.reflected += 1

    def receiveInteraction(self, *args: object) -> None:
        self.interactions += 1

    def removeObjectInstance(self, obj: object, *rest: object) -> None:
        self.removed.add(self.names.get(obj, "?"))


def test_resign_while_another_thread_sends_is_clean(rtig: RtigProcess) -> None:
    rti.RTIAmbassador(rtig.address).createFederationExecution("TestFed", ROBOT_FED)
    watcher, amb = rti.RTIAmbassador(rtig.address), Watcher()
    watcher.joinFederationExecution("watcher", "TestFed", amb)
    robot = watcher.getObjectClassHandle("robot")
    watcher.subscribeObjectClassAttributes(robot, [watcher.getAttributeHandle("location", robot)])
    watcher.subscribeInteractionClass(watcher.getInteractionClassHandle("command"))
    rounds = []
    with python_peer(PEER, rtig.address, ROUNDS) as peer:
        for _ in range(ROUNDS):
            rounds.append(peer.read_json(60))
            watcher.tick(0.01, 0.05)
        assert peer.wait(30) == 0
    tick_until(lambda: len(amb.removed) == ROUNDS, watcher, timeout=10)
    watcher.resignFederationExecution(rti.ResignAction.NoAction)
    sent = [r["sent"] for r in rounds]
    print(f"\n{ROUNDS} rounds: updates+interactions sent before the resign {min(sent)}-{max(sent)} per round; "
          f"the watcher reflected {amb.reflected} updates and {amb.interactions} interactions, saw "
          f"{len(amb.removed)} objects removed")
    for r in rounds:
        assert r["resign"] == "ok", r  # its true result: it was done
        assert r["sender_stopped_by"] == "FederateNotExecutionMember", r  # at the call, not a lost connection
    assert amb.removed == {f"leaving-{k}" for k in range(ROUNDS)}  # each round's resign deleted its object
    assert not re.search(r"dropped", rtig.log()), rtig.log()  # no protocol error, nobody dropped
