"""Clock offsets to the gateway (docs/networking.md): NTP-style probes on first request and when older than asked.
The estimate must hold the true offset within its uncertainty, whatever the path's asymmetry; on one host the true
offset is 0 (every process reads the same CLOCK_MONOTONIC), which is what these tests check against."""

from __future__ import annotations

import time

import hlacore.rti as rti
from hlacore.link import Direction, Link

from support import RtigProcess


def test_on_one_host_the_offset_is_zero_within_a_round_trip(rtig: RtigProcess) -> None:
    rtia = rti.RTIAmbassador(rtig.address)
    offset, uncertainty = rtia.clock_offset()
    print(f"\nloopback: offset {offset * 1e6:+.1f} µs ± {uncertainty * 1e6:.1f} µs")
    assert abs(offset) <= uncertainty
    assert uncertainty < 0.05


def test_an_asymmetric_path_widens_the_bound_but_keeps_the_truth_inside(rtig: RtigProcess) -> None:
    """20 ms towards the gateway, nothing back: a naive estimate is 10 ms off; the bound (half the round
    trip, ≥ 10 ms) still holds 0."""
    host, port = rtig.address.rsplit(":", 1)
    with Link(("127.0.0.1", 0), (host, int(port)), up=Direction(delay=0.020)) as link:
        rtia = rti.RTIAmbassador(link.address)
        offset, uncertainty = rtia.clock_offset()
    print(f"\n20 ms one way: offset {offset * 1e3:+.2f} ms ± {uncertainty * 1e3:.2f} ms")
    assert uncertainty >= 0.010
    assert abs(offset) <= uncertainty
    assert offset > 0.005  # the asymmetry shows as an offset of about half the extra delay


def test_the_estimate_is_refreshed_when_older_than_asked(rtig: RtigProcess) -> None:
    rtia = rti.RTIAmbassador(rtig.address)
    first = rtia.clock_offset()
    assert rtia.clock_offset(max_age=60.0) == first  # kept
    time.sleep(0.01)
    refreshed = rtia.clock_offset(max_age=0.0)
    assert abs(refreshed[0]) <= refreshed[1]
