"""Time management end to end over the real rtig, one federate per process."""

from __future__ import annotations

import signal
import time

import pytest

from support import Conductor, lockstep_peers, tick_until


def test_two_processes_in_lockstep_for_1000_steps(conductor: Conductor) -> None:
    """Paper 2's lockstep: every timestamped update arrives before the grant to its time, none lost."""
    conductor.start("lockstep.py", lockstep_peers(conductor, 1000, 2))
    conductor.synchronize()
    results = [peer.read_json(60) for peer in conductor.peers.values()]
    for peer in conductor.peers.values():
        assert peer.wait(timeout=60) == 0, peer.stderr()
    for result in results:
        assert result["errors"] == []
        assert result["received"] == 1000


def test_a_killed_regulating_federate_unblocks_the_others_within_a_second(conductor: Conductor) -> None:
    conductor.start("lockstep.py", lockstep_peers(conductor, 0, 1, "--stall"))
    me = conductor.rtia
    me.enableTimeRegulation(0.0, 1.0)
    me.enableTimeConstrained()
    tick_until(lambda: bool(conductor.amb.named("timeConstrainedEnabled")), me)
    conductor.synchronize()
    me.timeAdvanceRequest(10.0)
    with pytest.raises(TimeoutError):
        me.await_grant(timeout=0.5)  # the stalled peer (lookahead 1, at time 0) holds LBTS at 1
    conductor.peers["p0"].send_signal(signal.SIGKILL)
    killed = time.monotonic()
    assert me.await_grant(timeout=1.0) == 10.0
    print(f"granted {time.monotonic() - killed:.4f} s after SIGKILL")
