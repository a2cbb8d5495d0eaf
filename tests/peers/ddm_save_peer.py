"""Federate 's2' of tests/rti/test_save_restore_ddm.py, in its own process (so its region numbers start at 1).

Usage: ddm_save_peer.py HOST:PORT first|restart.
- first: joins DdmFed as 's2', creates a Geo region with X in [20, 30], subscribes vehicle.position and
  radio through it and broadcast plainly, and prints {"ready": true, "region": N} once the gateway has them.
- restart: joins DdmFed as 's2' and prints {"ready": true}; its subscriptions come back with a restore.
Then it ticks, printing one JSON line per event: it answers initiateFederateSave and
initiateFederateRestore at once; after federationRestored it creates a region and prints its number
({"event": "federationRestored", "new_region": N, "restored": [its regions], "x": [lower, upper] of the
first}); discoveries, reflections (tag), radio interactions
(text) and the broadcast marker are printed as they come. Exits when the connection ends, or after 60 s.
"""

import sys

import hlacore.rti as rti
from peerlib import SavingAmbassador, round_trip, say, serve


class Ambassador(SavingAmbassador):
    def __init__(self, rtia):
        super().__init__(rtia)
        self.radio = None
        self.geo = None

    def answer_save(self):
        self.rtia.federateSaveComplete()  # without federateSaveBegun, which is optional

    def initiateFederateRestore(self, label, handle):
        say(event="initiateFederateRestore", label=label)
        self.rtia.federateRestoreComplete()

    def federationRestored(self):
        # A new process holds no RegionHandle of its saved regions: getRegions() hands them out.
        restored = self.rtia.getRegions()
        x_range = [list(r) for d, r in self.rtia.getRegionExtent(restored[0])[1]][0] if restored else None
        region = self.rtia.createRegion(self.geo, [])
        say(event="federationRestored", new_region=int(region), restored=[int(r) for r in restored], x=x_range)
        self.rtia.deleteRegion(region)

    def discoverObjectInstance(self, obj, cls, name):
        super().discoverObjectInstance(obj, cls, name)
        say(event="discover", name=name)

    def reflectAttributeValues(self, obj, attributes, tag, *rest):
        say(event="reflect", tag=tag.decode() if isinstance(tag, bytes) else tag)

    def receiveInteraction(self, cls, parameters, tag, *rest):
        if cls == self.radio:
            say(event="radio", text=b"".join(parameters.values()).decode())
        else:
            say(event="marker")


def main():
    address, mode = sys.argv[1], sys.argv[2]
    rtia = rti.RTIAmbassador(address)
    amb = Ambassador(rtia)
    rtia.joinFederationExecution("s2", "DdmFed", amb)
    amb.geo = rtia.getRoutingSpaceHandle("Geo")
    amb.radio = rtia.getInteractionClassHandle("radio")
    if mode == "first":
        vehicle = rtia.getObjectClassHandle("vehicle")
        region = rtia.createRegion(amb.geo, [(rtia.getDimensionHandle("X", amb.geo), (20, 30))])
        rtia.subscribeObjectClassAttributesWithRegion(vehicle, region, [rtia.getAttributeHandle("position", vehicle)])
        rtia.subscribeInteractionClassWithRegion(amb.radio, region)
        rtia.subscribeInteractionClass(rtia.getInteractionClassHandle("broadcast"))
        round_trip(rtia)  # the gateway has handled the subscriptions
        say(ready=True, region=int(region))
    else:
        say(ready=True)
    serve(rtia, 60)


if __name__ == "__main__":
    main()
