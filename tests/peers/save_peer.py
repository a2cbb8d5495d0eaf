"""Federate 'b' of the save/restore tests, in its own process.

Usage: save_peer.py HOST:PORT [--no-answer]. Joins TestFed as 'b', becomes regulating and constrained
(lookahead 1), subscribes to robot location and prints {"ready": true, "handle": H}. Then it ticks,
printing one JSON line per save/restore event: it answers initiateFederateSave with federateSaveComplete
(unless --no-answer) and initiateFederateRestore with federateRestoreComplete (printing its restored
handle, time, lookahead and the objects it knows); after federationRestored it asks to advance to 5 and
prints the reflections and the grant. Exits when the connection ends, or after 60 s as a safety net.
"""

import sys
import time

import hlacore.rti as rti
from peerlib import SavingAmbassador, say, serve


class Ambassador(SavingAmbassador):
    def __init__(self, answer):
        super().__init__()
        self.answer = answer
        self.location = None
        self.enabled = set()

    def timeRegulationEnabled(self, t):
        self.enabled.add("regulation")

    def timeConstrainedEnabled(self, t):
        self.enabled.add("constrained")

    def answer_save(self):
        if self.answer:  # else --no-answer: the save cannot complete
            super().answer_save()

    def federationNotSaved(self):
        say(event="federationNotSaved")

    def initiateFederateRestore(self, label, handle):
        # The mirrored state is the saved one from here on.
        knows = []
        for name in ("r1", "r2"):
            try:
                self.rtia.getObjectInstanceHandle(name)
                knows.append(name)
            except rti.ObjectNotKnown:
                pass
        say(event="initiateFederateRestore", label=label, handle=int(handle),
            time=self.rtia.queryFederateTime(), lookahead=self.rtia.queryLookahead(), knows=knows)
        self.rtia.federateRestoreComplete()

    def federationRestored(self):
        say(event="federationRestored")
        self.rtia.timeAdvanceRequest(5.0)

    def federationNotRestored(self):
        say(event="federationNotRestored")

    def reflectAttributeValues(self, obj, attributes, tag, order, transport, time=None, retraction=None):
        say(event="reflect", time=time, location=attributes[self.location].decode())

    def timeAdvanceGrant(self, t):
        say(event="granted", time=t)


def main():
    amb = Ambassador(answer="--no-answer" not in sys.argv[2:])
    rtia = rti.RTIAmbassador(sys.argv[1])
    amb.rtia = rtia
    handle = rtia.joinFederationExecution("b", "TestFed", amb)
    robot = rtia.getObjectClassHandle("robot")
    amb.location = rtia.getAttributeHandle("location", robot)
    rtia.enableTimeRegulation(0.0, 1.0)
    rtia.enableTimeConstrained()
    rtia.subscribeObjectClassAttributes(robot, [amb.location])
    deadline = time.monotonic() + 60
    while len(amb.enabled) < 2 and time.monotonic() < deadline:
        rtia.tick(0.05, 0.1)
    say(ready=True, handle=int(handle))
    serve(rtia, max(0.0, deadline - time.monotonic()))


if __name__ == "__main__":
    main()
