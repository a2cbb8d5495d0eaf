"""Load over the real rtig: FEDERATES federate processes × UPDATES timestamped updates each, in lockstep, every
message delivered exactly once and in order (per-sender sequence numbers, checked by each peer at every step:
tests/peers/load_peer.py); then the same with 2 federates SIGKILLed midway.

The suite runs 8 × 200; `scripts/load.sh [FEDERATES [UPDATES]]` runs the full size (32 × 10 000) and prints the
figures. Sizes come from $HLACORE_LOAD_FEDERATES and $HLACORE_LOAD_UPDATES."""

from __future__ import annotations

import os
import signal

from support import Conductor

FEDERATES = int(os.environ.get("HLACORE_LOAD_FEDERATES", "8"))
UPDATES = int(os.environ.get("HLACORE_LOAD_UPDATES", "200"))
# Functional bound on a whole run (not a performance assertion): generous for a loaded 2-core machine.
RUN_TIMEOUT = 120 + FEDERATES * UPDATES * 0.01


def peer_args(conductor: Conductor, names: list[str], *flags: str) -> dict[str, list[str]]:
    return {name: [conductor.address, name, str(UPDATES), ",".join(names), *flags] for name in names}


def check_results(conductor: Conductor, survivors: list[str], victims: list[str], die_at: int) -> None:
    results = {name: conductor.peers[name].read_json(RUN_TIMEOUT) for name in survivors}
    for name in survivors:
        peer = conductor.peers[name]
        assert peer.wait(timeout=60) == 0, peer.stderr()
    expected_last = {n: UPDATES for n in survivors} | {n: die_at for n in victims}
    for name, result in results.items():
        assert result["errors"] == [], (name, result["errors"])
        assert result["last"] == {n: k for n, k in expected_last.items() if n != name}, (name, result["last"])
        assert result["received"] == sum(k for n, k in expected_last.items() if n != name)
    delivered = sum(r["received"] for r in results.values())
    slowest = max(r["seconds"] for r in results.values())
    print(f"\n{len(survivors) + len(victims)} federates x {UPDATES} TSO updates, {len(victims)} killed at step "
          f"{die_at}: {delivered} deliveries checked, {slowest:.1f} s from the start to the last grant, "
          f"{delivered / slowest:.0f} deliveries/s")


def test_lockstep_load_every_message_once_in_order(conductor: Conductor) -> None:
    names = [f"p{i}" for i in range(FEDERATES)]
    conductor.start("load_peer.py", peer_args(conductor, names), timeout=120)
    conductor.synchronize(timeout=120)
    check_results(conductor, names, [], 0)


def test_lockstep_load_with_two_federates_killed_midway(conductor: Conductor) -> None:
    """Two federates are SIGKILLed after the grant to UPDATES/2: the others keep stepping; from every dead
    sender they got exactly its updates 1..UPDATES/2, from every living one all UPDATES."""
    names = [f"p{i}" for i in range(FEDERATES)]
    victims, die_at = names[1:3], UPDATES // 2
    conductor.start("load_peer.py", peer_args(conductor, names, "--victims", ",".join(victims), "--die-at", str(die_at)),
                    timeout=120)
    conductor.synchronize(timeout=120)
    for name in victims:
        assert conductor.peers[name].read_json(RUN_TIMEOUT) == {"dying": die_at}
        conductor.peers[name].send_signal(signal.SIGKILL)
    for name in victims:
        assert conductor.peers[name].wait(timeout=10) == -signal.SIGKILL
    check_results(conductor, [n for n in names if n not in victims], victims, die_at)
