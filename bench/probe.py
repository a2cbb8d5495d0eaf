"""CPU probes for A/Bs and profiles (docs/performance.md): one workload of the bench against its rtig, with
each process's CPU read from /proc over the measured rounds. Prints one JSON line.

    python -m bench.probe fanout [SUBSCRIBERS] [BURST] [ROUNDS]   8 B updates 1 → S: each subscriber's rate,
                                                                   CPU per delivery (subscriber, rtig)
    python -m bench.probe large [MIB] [BURST] [ROUNDS]            updates of MIB MiB 1 → 1: MB/s, CPU per update
                                                                   of the sender, the rtig and the receiver
    python -m bench.probe lockstep [FEDERATES] [STEPS]            TSO update, TAR, grant: wall and CPU per step
                                                                   of the rtig and of each federate
    python -m bench.probe lockstep-cpp [FEDERATES] [STEPS]        the same with bench/rtis's C++ program (built by
                                                                   ./scripts/bench.sh) as the federates
    python -m bench.probe pingpong [SIZE] [ROUNDS]                 median round trips (µs) of SIZE bytes: raw TCP in
                                                                   C++, through a C++ relay, in Python, and hlacore's
                                                                   update ping-pong, receive order and TSO; run under
                                                                   `taskset -c 0` to see them all on one core
    python -m bench.probe busy [ROUNDS]                           busy polling (bench/test_busy_poll.py's loops):
                                                                   median µs of a 2-federate lockstep step, batched
                                                                   and plain, and of 8 B round trips, receive order
                                                                   and TSO batched

--unix runs fanout, large, lockstep and pingpong with the federates connected to the rtig over a Unix socket
(rtig --unix, docs/networking.md) instead of TCP; --batched runs lockstep with each federate's update and
request in RTIAmbassador.batch().

The rtig is bench_rtig()'s ($HLACORE_BENCH_RTIG overrides), the C++ floor program $HLACORE_TCP_FLOOR (default
build/bench/tcp_floor, built by ./scripts/bench.sh). For an A/B, run each side with its own package on
PYTHONPATH, its own rtig and its own bench code, alternating; `perf record -p PID` on the pids printed with
--pids profiles them while they run."""

from __future__ import annotations

import contextlib
import json
import os
import resource
import statistics
import sys
import time
from typing import Any, Callable, Iterator, Optional
from unittest import mock

from hlacore.processes import Rtig

from .floor import PyEcho, cpp_rtt_ns
from .lockstep import Lockstep
from .pingpong import PingPong
from .procs import BUSY_POLL_US, bench_rtig, cpu_seconds, unix_rtig
from .three_rtis import Server, run
from .throughput import Fanout


_over_unix = False  # --unix
_batched = False  # --batched


@contextlib.contextmanager
def gateway() -> Iterator[tuple[Rtig, str]]:
    """bench_rtig() and the address its federates connect to: its TCP one, or with --unix its Unix socket's."""
    if not _over_unix:
        with bench_rtig() as rtig:
            yield rtig, rtig.address
        return
    with unix_rtig() as (rtig, address):
        yield rtig, address


def spent(pids: dict[str, int], run: Callable[[], None]) -> dict[str, float]:
    """CPU seconds each process spent while `run` ran."""
    before = {name: cpu_seconds(pid) for name, pid in pids.items()}
    run()
    return {name: cpu_seconds(pid) - before[name] for name, pid in pids.items()}


def bursts(fanout: Fanout, rounds: int) -> list[float]:
    """Seconds per burst, `rounds` times."""
    times = []
    for _ in range(rounds):
        start = time.perf_counter()
        fanout.burst()
        times.append(time.perf_counter() - start)
    return times


def run_steps(federation: Lockstep, steps: int) -> None:
    for _ in range(steps):
        federation.step()


def announce(pids: dict[str, int], show_pids: bool) -> None:
    if show_pids:
        print(json.dumps({"pids": pids}), flush=True)


def measured_bursts(f: Fanout, pids: dict[str, int], rounds: int, show_pids: bool) -> tuple[list[float], dict[str, float]]:
    """Seconds per burst over `rounds` bursts and the CPU seconds each of `pids` spent meanwhile; then the
    fan-out's final check of every count."""
    announce(pids, show_pids)
    times: list[float] = []
    cpu = spent(pids, lambda: times.extend(bursts(f, rounds)))
    f.finish()
    return times, cpu


def fanout(subscribers: int = 8, burst: int = 25_000, rounds: int = 6, show_pids: bool = False) -> dict[str, Any]:
    with gateway() as (rtig, address):
        f = Fanout(address, subscribers, burst)
        try:
            f.burst()  # warm-up
            pids = {"rtig": rtig.child.pid, "sender": os.getpid()}
            pids.update({f"subscriber{i}": peer.pid for i, peer in enumerate(f.peers)})
            times, cpu = measured_bursts(f, pids, rounds, show_pids)
        finally:
            f.close()
    n = rounds * burst
    per_subscriber = [cpu[name] / n * 1e6 for name in pids if name.startswith("subscriber")]
    return {"rate_per_subscriber": burst / statistics.median(times),
            "subscriber_us_per_delivery": statistics.mean(per_subscriber),
            "rtig_us_per_delivery": cpu["rtig"] / (n * subscribers) * 1e6, "sender_us_per_update": cpu["sender"] / n * 1e6}


def large(mib: float = 16, burst: int = 4, rounds: int = 6, show_pids: bool = False) -> dict[str, Any]:
    size = int(mib * (1 << 20))
    with gateway() as (rtig, address):
        f = Fanout(address, 1, burst, payload=bytes(size))
        try:
            f.burst()
            pids = {"sender": os.getpid(), "rtig": rtig.child.pid, "receiver": f.peers[0].pid}
            times, cpu = measured_bursts(f, pids, rounds, show_pids)
        finally:
            f.close()
    n = rounds * burst
    return {"mb_per_s": burst * size / statistics.median(times) / 1e6,
            **{f"{name}_ms_per_update": cpu[name] / n * 1e3 for name in pids}}


def lockstep(federates: int = 32, steps: int = 400, show_pids: bool = False) -> dict[str, Any]:
    with gateway() as (rtig, address):
        f = Lockstep(address, federates, max_steps=steps + 60, batched=_batched)
        try:
            for _ in range(50):  # warm-up
                f.step()
            pids = {"rtig": rtig.child.pid, **{f"federate{i}": peer.pid for i, peer in enumerate(f.peers)}}
            announce(pids, show_pids)
            start = time.perf_counter()
            cpu = spent(pids, lambda: run_steps(f, steps))
            wall = time.perf_counter() - start
            f.finish()
        finally:
            f.close()
    each = statistics.mean(cpu[name] for name in pids if name != "rtig") / steps * 1e6
    return {"wall_us_per_step": wall / steps * 1e6, "rtig_us_per_step": cpu["rtig"] / steps * 1e6,
            "federate_us_per_step": each, "us_per_federate_step": cpu["rtig"] / steps * 1e6 / federates + each}


def lockstep_cpp(federates: int = 32, steps: int = 2000, show_pids: bool = False,
                 binary: Optional[str] = None) -> dict[str, Any]:
    """The federates' CPU from RUSAGE_CHILDREN (they are this process's children, waited for): their joins,
    synchronizations and a tenth as many warm-up steps included, so slightly more than the loop's."""
    server = Server("hlacore")
    try:
        announce({"rtig": server.pid}, show_pids)
        rtig_before, children = cpu_seconds(server.pid), resource.getrusage(resource.RUSAGE_CHILDREN)
        samples = run(server, "lockstep", federates, steps, steps // 10, binary=binary)["samples_ns"]
        rtig = cpu_seconds(server.pid) - rtig_before
        after = resource.getrusage(resource.RUSAGE_CHILDREN)
    finally:
        server.close()
    total_steps = steps + steps // 10
    each = ((after.ru_utime + after.ru_stime) - (children.ru_utime + children.ru_stime)) / federates / total_steps * 1e6
    return {"wall_us_per_step": statistics.median(samples) / 1e3, "rtig_us_per_step": rtig / total_steps * 1e6,
            "federate_us_per_step": each, "us_per_federate_step": rtig / total_steps * 1e6 / federates + each}


def timed_median_us(round_trip: Callable[[], None], rounds: int) -> float:
    samples = []
    for _ in range(rounds):
        start = time.perf_counter()
        round_trip()
        samples.append(time.perf_counter() - start)
    return statistics.median(samples) * 1e6


def pingpong(size: int = 8, rounds: int = 3000, show_pids: bool = False) -> dict[str, Any]:
    binary = os.environ.get("HLACORE_TCP_FLOOR", "build/bench/tcp_floor")
    result = {"cpp_us": statistics.median(cpp_rtt_ns(binary, size, rounds)) / 1e3,
              "cpp_relay_us": statistics.median(cpp_rtt_ns(binary, size, rounds, "rtt-relay")) / 1e3}
    echo = PyEcho(size)
    try:
        timed_median_us(echo.round_trip, 200)  # warm-up
        result["python_us"] = timed_median_us(echo.round_trip, rounds)
    finally:
        echo.close()
    with gateway() as (rtig, address):
        for order in ("ro", "tso"):
            p = PingPong(address, order, size)
            try:
                announce({"rtig": rtig.child.pid, "pong": p.peer.pid}, show_pids)
                timed_median_us(p.round_trip, 200)
                result[f"hlacore_{order}_us"] = timed_median_us(p.round_trip, rounds)
                p.finish()
            finally:
                p.close()
    return result


def busy(rounds: int = 20_000, show_pids: bool = False) -> dict[str, Any]:
    """The 2-federate loops of bench/test_busy_poll.py, every process polling BUSY_POLL_US: median µs of a
    lockstep step, batched and plain, and of an 8 B round trip, receive order and TSO batched."""
    with mock.patch.dict(os.environ, {"HLACORE_BUSY_POLL_US": BUSY_POLL_US}):  # this process's federates, its peers
        return _busy_loops(rounds, show_pids)


def _busy_loops(rounds: int, show_pids: bool) -> dict[str, Any]:
    result: dict[str, Any] = {}
    with bench_rtig("--busy-poll", BUSY_POLL_US) as rtig:
        for name, batched in (("lockstep_batched_us", True), ("lockstep_us", False)):
            f = Lockstep(rtig.address, 2, max_steps=rounds + rounds // 10 + 10, batched=batched)
            try:
                announce({"rtig": rtig.child.pid, **{f"federate{i}": peer.pid for i, peer in enumerate(f.peers)}},
                         show_pids)
                timed_median_us(f.step, rounds // 10)  # warm-up
                result[name] = timed_median_us(f.step, rounds)
                f.finish()
            finally:
                f.close()
        for name, mode in (("ro_round_trip_us", "ro"), ("tso_batched_round_trip_us", "tso-batched")):
            p = PingPong(rtig.address, mode, 8)
            try:
                announce({"rtig": rtig.child.pid, "pong": p.peer.pid}, show_pids)
                timed_median_us(p.round_trip, rounds // 10)
                result[name] = timed_median_us(p.round_trip, rounds)
                p.finish()
            finally:
                p.close()
    return result


PROBES: dict[str, Callable[..., dict[str, Any]]] = {"fanout": fanout, "large": large, "lockstep": lockstep,
                                                    "lockstep-cpp": lockstep_cpp, "pingpong": pingpong, "busy": busy}


def main(argv: list[str]) -> int:
    global _over_unix, _batched
    show_pids, _over_unix, _batched = "--pids" in argv, "--unix" in argv, "--batched" in argv
    args = [a for a in argv if a not in ("--pids", "--unix", "--batched")]
    if not args or args[0] not in PROBES:
        print(__doc__, file=sys.stderr)
        return 2
    numbers = [float(a) if "." in a else int(a) for a in args[1:]]
    print(json.dumps(PROBES[args[0]](*numbers, show_pids=show_pids)), flush=True)
    return 0


if __name__ == "__main__":
    raise SystemExit(main(sys.argv[1:]))
