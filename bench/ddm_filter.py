"""What DDM filtering costs the gateway and saves the subscribers: rtig CPU per update and reflections
delivered, plain subscriptions against subscriptions through regions (docs/ddm.md).

    python -m bench.ddm_filter [--rtig build/rel/rtig] [--updates 200000]

One publisher in this process sends 64-byte receive-order updates of one object as fast as it can; the
subscribers are ambassadors in this process too, ticked until the one in scope has every update. rtig's
CPU time comes from /proc (10 ms ticks: use enough updates). A standalone run, not part of the pytest
bench report.
"""

from __future__ import annotations

import argparse
import time
from typing import Any, Optional

import hlacore.rti as rti
from hlacore.processes import round_trip

from .outputs import ROOT
from .procs import bench_rtig, cpu_seconds

FED = str(ROOT / "tests" / "data" / "ddm.fed")
PAYLOAD = b"x" * 64


class Counting(rti.FederateAmbassador):
    def __init__(self) -> None:
        self.reflections = 0

    def reflectAttributeValues(self, *args: Any) -> None:
        self.reflections += 1


def run(rtig: Optional[str], updates: int, subscribers: int, regions_each: int, in_scope: bool) -> str:
    """regions_each = 0: plain subscriptions. Else subscriber i subscribes through `regions_each` disjoint
    regions; the object's update region overlaps the last region of subscriber 0 (or none)."""
    with bench_rtig(executable=rtig) as server:
        pub = rti.RTIAmbassador(server.address)
        pub.create_or_join("pub", "DdmFed", FED, rti.FederateAmbassador())
        geo = pub.getRoutingSpaceHandle("Geo")
        x = pub.getDimensionHandle("X", geo)
        vehicle = pub.getObjectClassHandle("vehicle")
        position = pub.getAttributeHandle("position", vehicle)
        pub.publishObjectClass(vehicle, [position])
        subs = []
        for i in range(subscribers):
            rtia, amb = rti.RTIAmbassador(server.address), Counting()
            rtia.joinFederationExecution(f"s{i}", "DdmFed", amb)
            if regions_each == 0:
                rtia.subscribeObjectClassAttributes(vehicle, [position])
            for k in range(regions_each):
                low = 1000 * (i * regions_each + k + 1)
                region = rtia.createRegion(geo, [(x, (low, low + 10))])
                rtia.subscribeObjectClassAttributesWithRegion(vehicle, region, [position])
            round_trip(rtia)
            subs.append((rtia, amb))
        if regions_each == 0:
            obj = pub.registerObjectInstance(vehicle, "v")
        else:
            at = 1000 * regions_each + 5 if in_scope else 10**9
            obj = pub.registerObjectInstanceWithRegion(vehicle, [(position, pub.createRegion(geo, [(x, (at, at))]))], "v")
        for rtia, _ in subs:
            rtia.tick(0.05, 0.1)
        cpu0, wall0 = cpu_seconds(server.child.proc.pid), time.perf_counter()
        for _ in range(updates):
            pub.updateAttributeValues(obj, {position: PAYLOAD}, "")
        round_trip(pub)
        wanted = updates if in_scope else 0
        deadline = time.monotonic() + 300
        while subs[0][1].reflections < wanted and time.monotonic() < deadline:
            for rtia, _ in subs:
                rtia.tick(0.0, 0.05)
        for rtia, _ in subs:
            rtia.tick(0.0, 0.05)
        cpu, wall = cpu_seconds(server.child.proc.pid) - cpu0, time.perf_counter() - wall0
        delivered = sum(amb.reflections for _, amb in subs)
        for rtia, _ in subs:
            rtia.resignFederationExecution(rti.ResignAction.NoAction)
        pub.resignFederationExecution(rti.ResignAction.DeleteObjects)
        pub.destroyFederationExecution("DdmFed")
    return f"{cpu / updates * 1e6:6.2f} us rtig CPU/update, {wall:5.2f} s wall, {delivered} reflections"


def main() -> None:
    parser = argparse.ArgumentParser()
    parser.add_argument("--rtig", help="the rtig to run (default: the one installed beside Python)")
    parser.add_argument("--updates", type=int, default=200_000)
    args = parser.parse_args()
    cases = [
        ("8 plain subscribers", 8, 0, True),
        ("8 subscribers through regions, 1 in scope", 8, 1, True),
        ("8 subscribers through regions, none in scope", 8, 1, False),
        ("1 plain subscriber", 1, 0, True),
        ("1 subscriber through a region in scope", 1, 1, True),
        ("1 subscriber through 100 regions, the last in scope", 1, 100, True),
    ]
    for name, subscribers, regions_each, in_scope in cases:
        print(f"{name:<52} {run(args.rtig, args.updates, subscribers, regions_each, in_scope)}", flush=True)


if __name__ == "__main__":
    main()
