"""Busy polling (`RTIAmbassador(busy_poll_us=...)`, `$HLACORE_BUSY_POLL_US`, `rtig --busy-poll`,
`Gateway(busy_poll_us=...)`): federates and gateway poll before they sleep. Time management is the same with it,
an idle federate still sleeps, and bad values are refused at the call. Ctrl-C and the liveness bound with it:
tests/transport/test_liveness.py runs every blocking call both ways."""

from __future__ import annotations

import pathlib
import threading
import time
from typing import Iterator

import pytest

import hlacore
from hlacore import rti

from support import Conductor, lockstep_peers, running_rtig
from support.federations import pair


@pytest.fixture(params=["rtig", "in-process"])
def busy_gateway(request: pytest.FixtureRequest, tmp_path: pathlib.Path) -> Iterator[str]:
    """The address of a gateway that busy-polls 50 µs: the rtig executable or the in-process one."""
    if request.param == "rtig":
        with running_rtig(tmp_path, "--busy-poll", "50") as server:
            yield server.address
    else:
        with hlacore.Gateway(port=0, busy_poll_us=50) as gateway:
            yield gateway.address


def test_lockstep_with_busy_polling_everywhere(busy_gateway: str, monkeypatch: pytest.MonkeyPatch) -> None:
    """Two federate processes and this one, all polling 50 µs, 500 steps: every update before its grant."""
    monkeypatch.setenv("HLACORE_BUSY_POLL_US", "50")  # for this process's federate and the peers
    conductor = Conductor(busy_gateway)
    try:
        conductor.start("lockstep.py", lockstep_peers(conductor, 500, 2))
        conductor.synchronize()
        results = [peer.read_json(60) for peer in conductor.peers.values()]
        for peer in conductor.peers.values():
            assert peer.wait(timeout=60) == 0, peer.stderr()
    finally:
        conductor.close()
    for result in results:
        assert result["errors"] == [] and result["received"] == 500, result


def test_an_idle_federate_spins_once_then_sleeps(inprocess_gateway: hlacore.Gateway) -> None:
    """A tick that waits 1 s for nothing spins 0.1 s, then sleeps: a spin that found nothing is not repeated
    until something arrives (the sleep after it is cut in slices, for Ctrl-C, without spinning again)."""
    rtia = rti.RTIAmbassador(inprocess_gateway.address, busy_poll_us=100_000)
    cpu, wall = time.thread_time(), time.monotonic()
    assert rtia.tick(1.0, 1.0) is False
    cpu, wall = time.thread_time() - cpu, time.monotonic() - wall
    print(f"\nwaited {wall:.3f} s, spinning {cpu:.3f} s of it")
    assert wall >= 1.0
    assert cpu < 0.3, cpu  # 0.5 s if each 0.1 s slice spun again


@pytest.mark.parametrize("value", [-1, 100_001, 2.5, True])
def test_a_bad_busy_poll_is_refused_at_the_call(inprocess_gateway: hlacore.Gateway, value: object) -> None:
    with pytest.raises(rti.RTIinternalError, match="busy polling must be a whole number of µs between 0 and 100000"):
        rti.RTIAmbassador(inprocess_gateway.address, busy_poll_us=value)  # type: ignore[arg-type]
    with pytest.raises(ValueError, match="busy polling must be a whole number of µs between 0 and 100000"):
        hlacore.Gateway(port=0, busy_poll_us=value)  # type: ignore[arg-type]


@pytest.mark.parametrize("text", ["fast", "-5", "100001"])
def test_a_bad_busy_poll_variable_is_refused(inprocess_gateway: hlacore.Gateway, monkeypatch: pytest.MonkeyPatch,
                                              text: str) -> None:
    monkeypatch.setenv("HLACORE_BUSY_POLL_US", text)
    with pytest.raises(rti.RTIinternalError, match="HLACORE_BUSY_POLL_US|busy polling"):
        rti.RTIAmbassador(inprocess_gateway.address)


def test_a_datagram_that_comes_during_a_spin_is_delivered_before_a_later_stream_message(tmp_path: pathlib.Path) -> None:
    """A spin reads the stream as it polls and looks at the datagram socket every few turns: a best-effort update
    that lands mid-spin is delivered first, not after the reliable one that comes 30 ms later (the spin, 100 ms,
    would otherwise find only the stream's)."""
    with running_rtig(tmp_path) as server, pair(server.address, busy_poll_us=100_000) as p:
        def send_later() -> None:
            time.sleep(0.03)
            p.alice.updateAttributeValues(p.obj, {p.sonar: b"datagram"}, "")
            time.sleep(0.03)
            p.alice.updateAttributeValues(p.obj, {p.location: b"stream"}, "")

        sender = threading.Thread(target=send_later)
        sender.start()
        deadline = time.monotonic() + 10.0
        while len(p.bob_amb.reflections) < 2 and time.monotonic() < deadline:
            p.bob.tick(1.0, 1.0)
        sender.join()
        assert [list(values.values()) for values, _ in p.bob_amb.reflections] == [[b"datagram"], [b"stream"]]
        assert p.bob.datagram_status()["received"] == 1


def test_a_busy_stream_does_not_keep_datagrams_waiting(tmp_path: pathlib.Path) -> None:
    """Best-effort and reliable updates interleaved, 100 of each (within a datagram socket's default buffer), to a
    federate that busy-polls: every one arrives, the best-effort ones as datagrams."""
    with running_rtig(tmp_path, "--busy-poll", "50") as server, pair(server.address, busy_poll_us=50) as p:
        for i in range(100):
            p.alice.updateAttributeValues(p.obj, {p.sonar: b"s%d" % i}, "")
            p.alice.updateAttributeValues(p.obj, {p.location: b"l%d" % i}, "")
        p.wait(lambda: len(p.bob_amb.reflections) == 200)
        received = [v for values, _ in p.bob_amb.reflections for v in values.values()]
        assert sorted(received) == sorted([b"s%d" % i for i in range(100)] + [b"l%d" % i for i in range(100)])
        assert p.bob.datagram_status()["received"] == 100


def test_a_gateway_that_closes_during_a_spin_is_a_lost_connection_at_the_call() -> None:
    """The spin's read finds the end of the stream: the waiting tick raises at once, naming it."""
    gateway = hlacore.Gateway(port=0)
    rtia = rti.RTIAmbassador(gateway.address, busy_poll_us=100_000)
    closer = threading.Timer(0.05, gateway.stop)
    closer.start()
    start = time.monotonic()
    try:
        with pytest.raises(rti.RTIinternalError, match="closed the connection"):
            rtia.tick(5.0, 5.0)
    finally:
        closer.join()
        gateway.stop()
    assert time.monotonic() - start < 4.0  # not the tick's 5 s: the close ended it
