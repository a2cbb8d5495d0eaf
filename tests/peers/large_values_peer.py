"""The publisher of camera-size updates for tests/transport/test_large_values.py: `python large_values_peer.py ADDRESS
COUNT MIB SHRINK`. Joins TestFed, publishes robot.location, registers "camera", sends COUNT updates (update k
of MIB MiB less k * SHRINK bytes, filled with the byte k) as fast as the gateway takes them, reports
{"sent": COUNT, "seconds": S, "slowest_call": S}, resigns and exits."""

from __future__ import annotations

import sys
import time

import hlacore.rti as rti
from peerlib import join_publisher, say


def main() -> None:
    address, count, mib, shrink = sys.argv[1], int(sys.argv[2]), int(sys.argv[3]), int(sys.argv[4])
    rtia, location, obj = join_publisher(address, "camera")
    started = time.monotonic()
    slowest = 0.0
    for k in range(count):
        value = bytes([k]) * ((mib << 20) - k * shrink)
        before = time.monotonic()
        rtia.updateAttributeValues(obj, {location: value}, "frame")
        slowest = max(slowest, time.monotonic() - before)
    say(sent=count, seconds=round(time.monotonic() - started, 3), slowest_call=round(slowest, 3))
    rtia.resignFederationExecution(rti.ResignAction.ReleaseAttributes)


if __name__ == "__main__":
    main()
