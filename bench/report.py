"""The figures of one bench run, each with its ratio to the floor measured in the same run, rendered as
the Markdown table of docs/performance.md and as JSON. Samples are seconds (latencies, parse times) or
messages per second (rates), keyed as the bench tests record them:

    grant.floor.py / grant.floor.cpp        raw TCP round trips of 8 B
    grant.floor.barrier                     the C++ barrier of 8 B: a server answers two clients once both sent
    grant.pure.K                            TAR -> TAG steps of K federates, no updates (rtig)
    grant.rtig.K, grant.inprocess.2         lockstep steps of K federates (standalone / in-process gateway)
    update.floor.py.S / update.floor.cpp.S  raw TCP round trips of S bytes
    update.floor.relay.S                    the C++ round trip through a process that passes each message on
    update.ro.S, update.tso.S               update ping-pong round trips with an S-byte payload
    throughput.floor.py / .cpp              raw TCP messages per second (one send per message)
    throughput.N                            updates per second delivered to each of N subscribers
    large.S, large.floor.py.S / .cpp.S      bytes per second of S-byte updates 1 → 1 (S = 1 MiB, 16 MiB); of a raw
                                            TCP stream of S-byte records, one send each
    large.floor.relay.S                     of the C++ stream through a process that forwards it
    cpu.32.rtig, cpu.32.federate            CPU seconds per step of the 32-federate lockstep (grant.rtig.32): the
                                            rtig's, and each peer federate process's
    fom.flat, fom.tree, fom.tree.python     parse times of the generated 1000-class FOM
    fom.10mb, fom.10mb.rtig                 a generated 10 MB FOM: parse time; createFederationExecution +
                                            destroyFederationExecution with it against rtig
    world.robot_steps.N                     robot-world robot-steps per second with N robots
    besteffort.udp.loss1 / .tcp.loss1       send-to-receive latency of a 200 Hz best-effort stream with 1 % of
                                            the gateway port's packets lost each way, over datagrams / TCP
                                            (and .delivered: the share that arrived)
    record.grant.2.off / .on                grant.rtig.2 through an rtig without / with --record, alternating
    record.throughput.1.off / .on           throughput.1 the same way
    monitor.grant.2.off / .on               grant.rtig.2 through an rtig without / with hlacore.monitor watching
    spill.throughput.1.off / .on            1 KiB updates per second to a subscriber stopped during a burst of
                                            20 000 and catching up: from memory / spilled to disk
    fedpro.grant.2.off / .on                grant.rtig.2 with the measuring federate on hlacore.rti / on
                                            hlacore.fedpro over the HLA 4 Federate Protocol (rtig --fedpro), alternating
    fedpro.update.ro.8.off / .on            update.ro.8 the same way
    busy.KEY                                KEY (grant.pure.2, grant.rtig.2, update.ro.8, update.tso.8) with
                                            every process busy polling (rtig --busy-poll, $HLACORE_BUSY_POLL_US);
                                            busy.grant.batched.2, busy.update.tso-batched.8: grant.rtig.2 and
                                            update.tso.8 with each update and the request after it in
                                            RTIAmbassador.batch(); busy.grant.cpp.2, busy.update.ro-cpp.8:
                                            grant.rtig.2 and update.ro.8 with bench/rtis's C++ program as the
                                            federates
    busy.floor.cpp / .relay / .barrier      the C++ TCP round trip of 8 B with every process polling (tcp_floor
                                            --spin): direct, through a relay, the barrier
    unix.KEY                                over a Unix socket (rtig --unix): KEY = busy.* as above, large.S,
                                            grant.rtig.32 and cpu.32.*; unix.floor.cpp (C++ round trip 8 B),
                                            unix.busy.floor.cpp / .relay / .barrier (the same polling) and
                                            unix.large.floor.cpp.S (C++ stream) over Unix socket pairs
    rtis.floor.cpp, rtis.floor.stream.cpp   the three-RTI run's floors: C++ TCP round trip 8 B, stream rate
    rtis.R.lockstep.K, rtis.R.pingpong,     the three-RTI benchmark, R = hlacore, openrti, certi (the C++
    rtis.R.throughput                       HLA 1.3 program of bench/rtis), hlacore-1516e, openrti-1516e (its
                                            IEEE 1516-2010 twin) or python (hlacore's Python federates)
"""

from __future__ import annotations

import math
import statistics
from dataclasses import dataclass
from typing import Callable, Optional

FEDERATES = (2, 4, 8, 16, 32)
RTI_LOCKSTEP = (2, 4, 8)  # the three-RTI benchmark's lockstep sizes (bench/test_three_rtis.py)
# Each RTI's columns side by side: its HLA 1.3 program, its IEEE 1516-2010 one where it has that API.
RTI_COLUMNS = (("hlacore", "hlacore, C++"), ("hlacore-1516e", "hlacore, C++ 1516e"), ("python", "hlacore, Python"),
               ("openrti", "OpenRTI, C++"), ("openrti-1516e", "OpenRTI, C++ 1516e"), ("certi", "CERTI 3.5.1, C++"))
PAYLOADS = (8, 1024, 65536)
SUBSCRIBERS = (1, 8)
LARGE_SIZES = (1 << 20, 16 << 20)
FOMS = ("fom.flat", "fom.tree", "fom.tree.python", "fom.10mb", "fom.10mb.rtig")
WORLD_ROBOTS = (4, 50)


def p99(values: list[float]) -> float:
    """Nearest-rank 99th percentile."""
    ordered = sorted(values)
    return ordered[max(0, math.ceil(0.99 * len(ordered)) - 1)]


def size_name(size: int) -> str:
    return f"{size // 1024} KiB" if size >= 1024 else f"{size} B"


@dataclass
class Row:
    figure: str
    median: str
    p99: str
    vs_py: str
    vs_cpp: str
    target: str


class Report:
    def __init__(self) -> None:
        self.samples: dict[str, list[float]] = {}

    def add(self, key: str, values: list[float], extend: bool = False) -> None:
        self.samples[key] = (self.samples.get(key, []) if extend else []) + list(values)

    def median(self, key: str) -> Optional[float]:
        values = self.samples.get(key)
        return statistics.median(values) if values else None

    def complete(self) -> bool:
        """True when every figure of the full run is here (then the docs are rewritten)."""
        return all(k in self.samples for k in expected_keys())

    # ---- rendering ----

    def _ratio(self, key: str, floor_key: str) -> str:
        """median(key) / median(floor_key): a multiple for latencies, a fraction for rates."""
        m, f = self.median(key), self.median(floor_key)
        return f"{m / f:.2f}×" if m is not None and f else "–"

    def _latency_row(self, figure: str, key: str, floor: str, target: str) -> Optional[Row]:
        values = self.samples.get(key)
        if not values:
            return None
        return Row(figure, _us(statistics.median(values)), _us(p99(values)),
                   self._ratio(key, f"{floor}.py"), self._ratio(key, f"{floor}.cpp"), target)

    def rows(self) -> list[tuple[str, list[Row]]]:
        sections: list[tuple[str, list[Row]]] = []
        p2 = self.median("grant.pure.2")
        g2 = self.median("grant.rtig.2")
        cpp_rtt = self.median("grant.floor.cpp")
        pure = [
            self._floor_row("raw TCP round trip 8 B", "grant.floor"),
            self._cpp_floor_row("raw TCP barrier 8 B, C++: a server answers two clients once both have sent",
                                "grant.floor.barrier"),
            *[self._latency_row(f"{k} federates, rtig", f"grant.pure.{k}", "grant.floor",
                                _grant_target(k, self.median(f"grant.pure.{k}"), p2, cpp_rtt,
                                              self.median("grant.floor.barrier"))) for k in FEDERATES],
        ]
        sections.append(("Grant latency: one step of the federation, TAR t+1 and tick to TAG (no updates)",
                         _present(pure)))
        grant = [
            *[self._latency_row(f"{k} federates, rtig", f"grant.rtig.{k}", "grant.floor",
                                _anchor(k, self.median(f"grant.rtig.{k}"), g2)) for k in FEDERATES],
            self._latency_row("2 federates, in-process gateway", "grant.inprocess.2", "grant.floor",
                              f"{self._ratio('grant.inprocess.2', 'grant.rtig.2')} of rtig"),
        ]
        title = ("Lockstep with updates, the anchors' loop: one step of the federation (every federate: TSO update "
                 "at t+1, TAR t+1, tick to TAG)")
        sections.append((title, _present(grant)))
        update: list[Optional[Row]] = []
        for size in PAYLOADS:
            update.append(self._floor_row(f"raw TCP one-way {size_name(size)}", "update.floor", size, half=True,
                                          relay=True))
            update += [self._update_row(order, size) for order in ("ro", "tso")]
        sections.append(("Update latency: one-way = ping-pong round trip / 2", _present(update)))
        busy = [self._cpp_floor_row("raw TCP round trip 8 B, C++, both ends polling", "busy.floor.cpp",
                                        "grant.floor.cpp"),
                self._cpp_floor_row("the same through a polling relay", "busy.floor.relay", "update.floor.relay.8"),
                self._cpp_floor_row("the barrier of two clients, polling", "busy.floor.barrier", "grant.floor.barrier"),
                self._busy_row("pure grant, 2 federates", "grant.pure.2", "grant.floor", 1.5),
                self._busy_row("lockstep with updates, 2 federates", "grant.rtig.2", "grant.floor", 2.5),
                self._busy_row("the same, each federate's update and request in one write (RTIAmbassador.batch(), "
                               "opt-in)", "grant.batched.2", "grant.floor", 2.5,
                               without=("busy.grant.rtig.2", "the time without the batch")),
                self._busy_row("the same, bench/rtis's C++ program as both federates (no Python; the update and the "
                               "request in two writes)", "grant.cpp.2", "grant.floor", 2.5,
                               without=("busy.grant.rtig.2", "the Python federates' time")),
                self._busy_row("receive order one-way 8 B", "update.ro.8", "update.floor", 2.5, size=8),
                self._busy_row("the same, bench/rtis's C++ program as both federates (no Python)", "update.ro-cpp.8",
                               "update.floor", 2.5, size=8, without=("busy.update.ro.8", "the Python federates' time")),
                self._busy_row("TSO one-way 8 B", "update.tso.8", "update.floor", 3.5, size=8),
                self._busy_row("the same, each side's update and request in one write (RTIAmbassador.batch(), opt-in)",
                               "update.tso-batched.8", "update.floor", 3.5, size=8,
                               without=("busy.update.tso.8", "the time without the batch"))]
        sections.append(("Busy polling (opt-in): every process polls 50 µs before it sleeps (rtig --busy-poll 50, "
                         "$HLACORE_BUSY_POLL_US=50)", _present(busy)))
        throughput = [self._rate_row("raw TCP 48 B messages, one send each", "throughput.floor", "")]
        stream = self.median("throughput.floor.cpp")
        for n in SUBSCRIBERS:
            rate = self.median(f"throughput.{n}")
            if not rate:
                target = ""
            elif n == 1:  # coalescing beyond one send per message
                target = (f"≥ 3× the C++ floor: {'met' if stream and rate >= 3 * stream else 'missed'}")
            else:
                target = f"≥ 200 000/s to each: {'met' if rate >= 200_000 else 'missed'}"
            throughput.append(self._rate_row(f"8 B updates, 1 → {n} (per subscriber, all delivered)",
                                             f"throughput.{n}", target, n))
        sections.append(("Throughput: small updates through one rtig, none lost", _present(throughput)))
        large: list[Optional[Row]] = []
        for size in LARGE_SIZES:
            large += [self._bandwidth_row(size, None), self._bandwidth_row(size, f"large.{size}")]
        sections.append(("Large updates 1 → 1, every one delivered: bandwidth against a raw TCP stream of the same "
                         "sizes", _present(large)))
        sections.append(("CPU per step of the 32-federate lockstep with updates (each process's CPU clock: user + system)",
                         _present([self._cpu_row()])))
        sections.append(("Same host over a Unix socket (opt-in: rtig --unix PATH, address unix:PATH); ratios to the "
                         "TCP floors as above, the target column to the Unix socket's", _present(self._unix_rows())))
        fom = [self._fom_row(label, key, target) for label, key, target in (
            ("1000 classes × 10 attributes, flat: `_core.parse_fed`", "fom.flat", 0.020),
            ("same, 3-level tree (inherited attributes): `_core.parse_fed`", "fom.tree", 0.020),
            ("3-level tree: `hlacore.fed.parse_text` (dataclasses)", "fom.tree.python", None),
            ("10 MB: 25 classes × 10 000 attributes, `_core.parse_fed`", "fom.10mb", 1.0),
            ("same, createFederationExecution + destroy against rtig", "fom.10mb.rtig", None),
        )]
        sections.append(("FOM parse (generated .fed)", _present(fom)))
        world = [self._world_row(n) for n in WORLD_ROBOTS]
        sections.append(("Robot world: robot-steps per second (no RTI)", _present(world)))
        lossy = [self._loss_row(path) for path in ("udp", "tcp")]
        sections.append(("Best-effort stream, 200 Hz, 1 % of the gateway port's packets lost each way (loopback "
                         "in a namespace, nftables)", _present(lossy)))
        recording = [self._cost_row("lockstep of 2 federates with updates", "record.grant.2", "grant.floor",
                                    "--record"),
                     self._cost_row("throughput 1 → 1, 8 B updates", "record.throughput.1", "throughput.floor",
                                    "--record")]
        sections.append(("Recording: rtig --record against the same rtig without, alternating rounds (target: the "
                         "recorded run within 10 % of the other)", _present(recording)))
        watched = [self._cost_row("lockstep of 2 federates with updates", "monitor.grant.2", "grant.floor",
                                  "hlacore.monitor")]
        sections.append(("Monitor: the same rtig without and with `python -m hlacore.monitor` watching it (a status "
                         "query every 0.5 s, one page connected), alternating rounds (target: within 10 %)",
                         _present(watched)))
        spilled = [self._cost_row("a stopped subscriber catching up on 20 000 updates of 1 KiB", "spill.throughput.1",
                                  "throughput.floor", "its backlog spilled to disk (a 1 MiB budget)", target=None)]
        door = [self._cost_row("lockstep of 2 federates with updates", "fedpro.grant.2", "grant.floor",
                               "the Federate Protocol (hlacore.fedpro)", target=None),
                self._cost_row("update ping-pong, 8 B, receive order", "fedpro.update.ro.8", "update.floor",
                               "the Federate Protocol (hlacore.fedpro)", target=None, floor_size=".8")]
        sections.append(("The HLA 4 Federate Protocol: the measuring federate on hlacore.rti against hlacore.fedpro "
                         "(pure Python) through rtig --fedpro, the peers the same, alternating rounds", _present(door)))
        sections.append(("Spilling: the backlog of a stopped subscriber in memory against spilled to disk "
                         "(rtig --client-budget 1048576), alternating rounds", _present(spilled)))
        return sections

    def _cost_row(self, figure: str, key: str, floor: str, what: str, target: Optional[float] = 1.10,
                  floor_size: str = "") -> Optional[Row]:
        """`key`.off against `key`.on: the cost of `what` (recording, monitoring) on a figure, against `target`
        (None: none, the cost is the figure); `floor_size` ends the floors' keys (".8": update.floor.py.8)."""
        off, on = self.median(f"{key}.off"), self.median(f"{key}.on")
        if off is None or on is None:
            return None
        rate = ".throughput" in key
        cost = off / on if rate else on / off  # > 1: the run with `what` is slower
        show = _rate if rate else _us
        return Row(f"{figure}: without / with {what}", f"{show(off)} / {show(on)}", "",
                   self._ratio(f"{key}.on", f"{floor}.py{floor_size}"), self._ratio(f"{key}.on", f"{floor}.cpp{floor_size}"),
                   f"{cost:.2f}× the time of the run without"
                   + (f": {'met' if cost <= target else 'missed'}" if target is not None else ""))

    def _loss_row(self, path: str) -> Optional[Row]:
        """No floor: the figure is the comparison of the two paths under the same loss."""
        values = self.samples.get(f"besteffort.{path}.loss1")
        delivered = self.samples.get(f"besteffort.{path}.loss1.delivered")
        if not values or not delivered:
            return None
        other = "tcp" if path == "udp" else "udp"
        return Row(f"over {'datagrams' if path == 'udp' else 'TCP'}: {delivered[0]:.1%} delivered",
                   _us(statistics.median(values)), _us(p99(values)), "", "",
                   f"p99 {self._p99_ratio(path, other)} the {other.upper()} stream's")

    def _p99_ratio(self, key: str, other: str) -> str:
        mine, theirs = self.samples.get(f"besteffort.{key}.loss1"), self.samples.get(f"besteffort.{other}.loss1")
        return f"{p99(mine) / p99(theirs):.2f}×" if mine and theirs else "–"

    def _floor_row(self, figure: str, prefix: str, size: Optional[int] = None, half: bool = False,
                   relay: bool = False) -> Optional[Row]:
        """The Python and C++ floors; with `relay`, the C++ one through a relay process too."""
        suffix = f".{size}" if size is not None else ""
        py, cpp = self.samples.get(f"{prefix}.py{suffix}"), self.samples.get(f"{prefix}.cpp{suffix}")
        if not py and not cpp:
            return None
        k = 0.5 if half else 1.0
        fmt: Callable[[Optional[list[float]], Callable[[list[float]], float]], str] = (
            lambda v, stat: _us(stat(v) * k) if v else "–")
        py_vs_cpp = _python_vs_cpp(self._ratio(f"{prefix}.py{suffix}", f"{prefix}.cpp{suffix}"))
        median, worst = f"{fmt(py, statistics.median)} / {fmt(cpp, statistics.median)}", f"{fmt(py, p99)} / {fmt(cpp, p99)}"
        if relay:
            routed = self.samples.get(f"{prefix}.relay{suffix}")
            figure += " (Python / C++; C++ through a relay)"
            median += f"; {fmt(routed, statistics.median)}"
            worst += f"; {fmt(routed, p99)}"
        else:
            figure += " (Python / C++)"
        return Row(figure, median, worst, "", py_vs_cpp, "")

    def _update_row(self, order: str, size: int) -> Optional[Row]:
        """One-way = round trip / 2, for the figure and its floor alike, so the ratio is that of the RTTs."""
        key = f"update.{order}.{size}"
        values = self.samples.get(key)
        if not values:
            return None
        m, floor = statistics.median(values), self.median(f"update.floor.cpp.{size}")
        target = _meets(m / floor if floor else None, 3.5 if order == "tso" else 2.5)  # the one-way targets
        relay_ratio = self._ratio(key, f"update.floor.relay.{size}")
        if target and relay_ratio != "–":
            target += f"; {relay_ratio} of the relay"
        return Row(f"{'receive order' if order == 'ro' else 'TSO'} one-way {size_name(size)}",
                   _us(statistics.median(values) / 2), _us(p99(values) / 2),
                   self._ratio(key, f"update.floor.py.{size}"), self._ratio(key, f"update.floor.cpp.{size}"), target)

    def _busy_row(self, figure: str, key: str, floor: str, limit: float, size: Optional[int] = None,
                  prefix: str = "", without: Optional[tuple[str, str]] = None) -> Optional[Row]:
        """`key` with busy polling (PREFIXbusy.KEY): its ratios to this run's sleeping floors (the columns), and
        the busy-polling target against the floor of processes that do not sleep either, the C++ round trip with both
        ends polling (PREFIXbusy.floor.cpp, 8 B); then its ratio to the polling floor of its shape, the barrier of
        two clients for a grant, the relay for an update's round trip, and to the same loop without polling, or
        with `prefix` "unix." to the same over TCP, or to `without` = (key, its name). With `size`, a one-way
        figure: half the round trip, the
        floors' too."""
        values = self.samples.get(f"{prefix}busy.{key}")
        if not values:
            return None
        suffix, half = (f".{size}", 0.5) if size is not None else ("", 1.0)
        polling = self.median(f"{prefix}busy.floor.cpp")
        median = statistics.median(values)
        what = f"≤ {limit}× the polling C++ {'one-way' if size else 'round trip'}{' over the Unix socket' if prefix else ''}"
        target = _meets(median / polling if polling else None, limit, what)
        routed, name = ("barrier", "the polling barrier") if size is None else ("relay", "the polling relay")
        beside = self._ratio(f"{prefix}busy.{key}", f"{prefix}busy.floor.{routed}")
        if target and beside != "–":
            target += f"; {beside} {name}"
        other, name = (f"busy.{key}", "the time over TCP") if prefix else without or (key, "the time without")
        compared = self._ratio(f"{prefix}busy.{key}", other)
        if target and compared != "–":
            target += f"; {compared} {name}"
        return Row(figure, _us(median * half), _us(p99(values) * half),
                   self._ratio(f"{prefix}busy.{key}", f"{floor}.py{suffix}"),
                   self._ratio(f"{prefix}busy.{key}", f"{floor}.cpp{suffix}"), target)

    def _cpp_floor_row(self, figure: str, key: str, beside: Optional[str] = None,
                       name: str = "the sleeping one") -> Optional[Row]:
        """A C++ floor of tcp_floor alone (latency), with its ratio to the floor `beside`, called `name`, if given."""
        values = self.samples.get(key)
        if not values:
            return None
        return Row(figure, _us(statistics.median(values)), _us(p99(values)), "",
                   f"{self._ratio(key, beside)} {name}" if beside else "", "")

    def _unix_rows(self) -> list[Optional[Row]]:
        """The figures over a Unix socket: each against the TCP floors (the columns), the Unix socket's floor
        and the same figure over TCP (the target column)."""
        rows: list[Optional[Row]] = []
        rows.append(self._cpp_floor_row("raw round trip 8 B, C++ over a Unix socket", "unix.floor.cpp", "grant.floor.cpp",
                                        "TCP's"))
        rows.append(self._cpp_floor_row("raw round trip 8 B, C++ over a Unix socket, both ends polling",
                                            "unix.busy.floor.cpp", "unix.floor.cpp"))
        rows.append(self._cpp_floor_row("the same through a polling relay", "unix.busy.floor.relay"))
        rows.append(self._cpp_floor_row("the barrier of two clients, polling", "unix.busy.floor.barrier"))
        rows += [self._busy_row("pure grant, 2 federates, busy polling", "grant.pure.2", "grant.floor", 1.5, prefix="unix."),
                 self._busy_row("lockstep with updates, 2 federates, busy polling", "grant.rtig.2", "grant.floor", 2.5,
                                prefix="unix."),
                 self._busy_row("receive order one-way 8 B, busy polling", "update.ro.8", "update.floor", 2.5, 8,
                                prefix="unix."),
                 self._busy_row("TSO one-way 8 B, busy polling", "update.tso.8", "update.floor", 3.5, 8, prefix="unix.")]
        for size in LARGE_SIZES:
            floor = self.median(f"unix.large.floor.cpp.{size}")
            if floor is not None:
                rows.append(Row(f"raw stream of {size >> 20} MiB records, C++ over a Unix socket", _mbps(floor), "", "",
                                f"{self._ratio(f'unix.large.floor.cpp.{size}', f'large.floor.cpp.{size}')} TCP's", ""))
            rate = self.median(f"unix.large.{size}")
            if rate is None:
                continue
            target = f"≥ 50 % of the Unix socket's C++ floor: {'met' if floor and rate >= floor / 2 else 'missed'}"
            if floor:
                target += f" ({rate / floor:.2f}×)"
            over_tcp = self._ratio(f"unix.large.{size}", f"large.{size}")
            rows.append(Row(f"{size >> 20} MiB updates", _mbps(rate), f"slowest round {_mbps(min(self.samples[f'unix.large.{size}']))}",
                            self._ratio(f"unix.large.{size}", f"large.floor.py.{size}"),
                            self._ratio(f"unix.large.{size}", f"large.floor.cpp.{size}"),
                            target + (f"; {over_tcp} the bandwidth over TCP" if over_tcp != "–" else "")))
        rows.append(self._cpu_row("unix."))
        return rows

    def _rate_row(self, figure: str, key: str, target: str, subscribers: int = 1) -> Optional[Row]:
        """A rate row: the median rate, and the slowest round in the p99 column."""
        if key == "throughput.floor":
            py, cpp = self.median("throughput.floor.py"), self.median("throughput.floor.cpp")
            if py is None and cpp is None:
                return None
            return Row(figure + " (Python / C++)", f"{_rate(py)} / {_rate(cpp)}", "", "",
                       _python_vs_cpp(self._ratio("throughput.floor.py", "throughput.floor.cpp")), "")
        rate = self.median(key)
        if rate is None:
            return None
        total = f" ({_rate(rate * subscribers)} in all)" if subscribers > 1 else ""
        return Row(figure, _rate(rate) + total, f"slowest round {_rate(min(self.samples[key]))}",
                   self._ratio(key, "throughput.floor.py"), self._ratio(key, "throughput.floor.cpp"), target)

    def _bandwidth_row(self, size: int, key: Optional[str]) -> Optional[Row]:
        """The floors of `size` (key None) or the updates' bandwidth, in MB/s; target ≥ 50 % of the C++ floor."""
        py, cpp = self.median(f"large.floor.py.{size}"), self.median(f"large.floor.cpp.{size}")
        if key is None:
            if py is None and cpp is None:
                return None
            relay = self.median(f"large.floor.relay.{size}")
            return Row(f"raw TCP stream of {size >> 20} MiB records (Python / C++; C++ through a relay)",
                       f"{_mbps(py)} / {_mbps(cpp)}; {_mbps(relay)}", "", "",
                       _python_vs_cpp(self._ratio(f"large.floor.py.{size}", f"large.floor.cpp.{size}")), "")
        rate = self.median(key)
        if rate is None:
            return None
        target = f"≥ 50 % of the C++ floor: {'met' if cpp and rate >= cpp / 2 else 'missed'}" if cpp else ""
        relay_ratio = self._ratio(key, f"large.floor.relay.{size}")
        if relay_ratio != "–":
            target += f" ({relay_ratio} of the relay)"
        return Row(f"{size >> 20} MiB updates", _mbps(rate), f"slowest round {_mbps(min(self.samples[key]))}",
                   self._ratio(key, f"large.floor.py.{size}"), self._ratio(key, f"large.floor.cpp.{size}"), target)

    def _cpu_row(self, prefix: str = "") -> Optional[Row]:
        """The 32-federate lockstep's CPU per step; `prefix` "unix.": over the Unix socket, against TCP's."""
        rtig, federate = self.median(f"{prefix}cpu.32.rtig"), self.median(f"{prefix}cpu.32.federate")
        step = self.median(f"{prefix}grant.rtig.32")
        if rtig is None or federate is None:
            return None
        whole = rtig + 32 * federate
        share = f" ({whole / step:.2f} cores busy)" if step else ""
        target = f"{_us(whole / 32)} per federate-step in all{share}"
        tcp_rtig, tcp_federate = self.median("cpu.32.rtig"), self.median("cpu.32.federate")
        if prefix and tcp_rtig is not None and tcp_federate is not None:
            target += f"; {whole / (tcp_rtig + 32 * tcp_federate):.2f}× that over TCP"
        figure = "32-federate lockstep with updates, CPU per step: " if prefix else ""
        return Row(f"{figure}rtig / each Python federate", f"{_us(rtig)} / {_us(federate)}", "", "", "", target)

    def _world_row(self, robots: int) -> Optional[Row]:
        """No floor: the world runs in one process without the RTI."""
        values = self.samples.get(f"world.robot_steps.{robots}")
        if not values:
            return None
        return Row(f"{robots} robots, physics and rangers", _rate(statistics.median(values)),
                   f"slowest round {_rate(min(values))}", "", "", "")

    def _fom_row(self, figure: str, key: str, target_seconds: Optional[float]) -> Optional[Row]:
        values = self.samples.get(key)
        if not values:
            return None
        m = statistics.median(values)
        target = ""
        if target_seconds is not None:
            bound = f"{target_seconds:g} s" if target_seconds >= 1 else f"{target_seconds * 1e3:g} ms"
            target = f"< {bound}: {'met' if m < target_seconds else 'missed'}"
        return Row(figure, f"{m * 1e3:.1f} ms", f"{p99(values) * 1e3:.1f} ms", "", "", target)

    def markdown(self) -> str:
        out = []
        if any(k.startswith("rtis.") for k in self.samples):
            out += ["### Three RTIs: the same C++ programs (HLA 1.3; 1516e: IEEE 1516-2010) against each, and "
                    "hlacore's Python federates",
                    "", self.three_rtis_markdown(), ""]
        for title, rows in self.rows():
            if not rows:
                continue
            out += [f"### {title}", "",
                    "| figure | median | p99 | ratio to Python floor | ratio to C++ floor | target |",
                    "|---|---|---|---|---|---|"]
            out += [f"| {r.figure} | {r.median} | {r.p99} | {r.vs_py} | {r.vs_cpp} | {r.target} |" for r in rows]
            out.append("")
        return "\n".join(out)

    def three_rtis_complete(self) -> bool:
        """True when every figure of the three-RTI table is here."""
        return all(k in self.samples for k in three_rtis_keys())

    def three_rtis_markdown(self) -> str:
        """The three-RTI table: each cell the median and its ratio to this run's C++ floor (the round trip
        for latencies; for rates, the fraction of the stream floor), then the targets against OpenRTI. An RTI
        not measured in this run (no install given, bench/three_rtis.py) has no column, and a line says so."""
        rows = []
        for k in RTI_LOCKSTEP:
            rows.append((f"lockstep K = {k}, µs per step", f"lockstep.{k}", self._three_rti_lockstep_target(k)))
        rows.append(("update ping-pong round trip, 8 B, µs", "pingpong", self._speedup_target("pingpong", 2.0)))
        rows.append(("throughput 1 → 1, 8 B updates per s", "throughput", self._speedup_target("throughput", 3.0)))
        columns = [(rti, name) for rti, name in RTI_COLUMNS if any(k.startswith(f"rtis.{rti}.") for k in self.samples)]
        absent = list(dict.fromkeys(name.split(",")[0] for rti, name in RTI_COLUMNS if (rti, name) not in columns))
        out = ["| figure | " + " | ".join(name for _, name in columns) + " | targets |",
               "|---|" + "---|" * len(columns) + "---|"]
        for figure, key, target in rows:
            cells = [self._three_rti_cell(f"rtis.{rti}.{key}") for rti, _ in columns]
            out.append(f"| {figure} | " + " | ".join(cells) + f" | {target} |")
        floor, stream = self.median("rtis.floor.cpp"), self.median("rtis.floor.stream.cpp")
        out += ["", f"Floors of the same run: C++ TCP round trip 8 B {_us(floor) if floor else '–'}, "
                    f"C++ stream of 48 B messages {_rate(stream)}."]
        if absent:
            out += ["", f"Not measured in this run: {', '.join(absent)} (no install given: $HLACORE_BENCH_OPENRTI, "
                        "$HLACORE_BENCH_CERTI)."]
        return "\n".join(out)

    def _three_rti_cell(self, key: str) -> str:
        m = self.median(key)
        if m is None:
            return "–"
        if key.endswith("throughput"):
            floor = self.median("rtis.floor.stream.cpp")
            return f"{_rate(m)} = {m / floor:.2f} of the floor" if floor else _rate(m)
        floor = self.median("rtis.floor.cpp")
        return f"{m * 1e6:.0f} = {m / floor:.1f}×" if floor else f"{m * 1e6:.0f}"

    def _speedup_target(self, key: str, factor: float) -> str:
        """hlacore's C++ figure against OpenRTI's: `factor` times faster (latency) or more (rate)."""
        ours, theirs = self.median(f"rtis.hlacore.{key}"), self.median(f"rtis.openrti.{key}")
        if ours is None or theirs is None:
            return ""
        ratio = ours / theirs if key == "throughput" else theirs / ours
        return f"C++ ≥ {factor:g}× OpenRTI: {'met' if ratio >= factor else 'missed'} ({ratio:.2f}×)"

    def _three_rti_lockstep_target(self, k: int) -> str:
        speedup = self._speedup_target(f"lockstep.{k}", 2.0)
        python, openrti = self.median(f"rtis.python.lockstep.{k}"), self.median(f"rtis.openrti.lockstep.{k}")
        if python is None or openrti is None:
            return speedup
        faster = "met" if python < openrti else "missed"
        return f"{speedup}; Python faster than OpenRTI C++: {faster} ({openrti / python:.2f}×)"

    def summary(self) -> dict[str, dict[str, float]]:
        """Per key: median, p99 and the number of samples (for results.json)."""
        return {k: {"median": statistics.median(v), "p99": p99(v), "n": len(v)}
                for k, v in sorted(self.samples.items())}


def expected_keys() -> list[str]:
    keys = ["grant.floor.py", "grant.floor.cpp", "grant.inprocess.2", "throughput.floor.py", "throughput.floor.cpp"]
    keys += [f"grant.rtig.{k}" for k in FEDERATES] + [f"grant.pure.{k}" for k in FEDERATES]
    keys += [f"update.{kind}.{s}" for s in PAYLOADS for kind in ("floor.py", "floor.cpp", "floor.relay", "ro", "tso")]
    keys += [f"throughput.{n}" for n in SUBSCRIBERS]
    keys += [f"besteffort.{path}.loss1{part}" for path in ("udp", "tcp") for part in ("", ".delivered")]
    keys += [f"record.{figure}.{side}" for figure in ("grant.2", "throughput.1") for side in ("off", "on")]
    keys += [f"monitor.grant.2.{side}" for side in ("off", "on")]
    keys += [f"spill.throughput.1.{side}" for side in ("off", "on")]
    keys += [f"fedpro.{figure}.{side}" for figure in ("grant.2", "update.ro.8") for side in ("off", "on")]
    keys += [f"large.{kind}{size}" for size in LARGE_SIZES for kind in ("", "floor.py.", "floor.cpp.", "floor.relay.")]
    keys += ["cpu.32.rtig", "cpu.32.federate"]
    keys += [f"busy.{key}" for key in ("grant.pure.2", "grant.rtig.2", "grant.batched.2", "grant.cpp.2", "update.ro.8",
                                        "update.ro-cpp.8", "update.tso.8", "update.tso-batched.8")]
    keys += [f"unix.busy.{key}" for key in ("grant.pure.2", "grant.rtig.2", "update.ro.8", "update.tso.8")]
    keys += [f"unix.{kind}{size}" for size in LARGE_SIZES for kind in ("large.", "large.floor.cpp.")]
    keys += ["grant.floor.barrier", "busy.floor.cpp", "busy.floor.relay", "busy.floor.barrier", "unix.floor.cpp",
             "unix.busy.floor.cpp", "unix.busy.floor.relay", "unix.busy.floor.barrier", "unix.grant.rtig.32",
             "unix.cpu.32.rtig", "unix.cpu.32.federate"]
    return keys + list(FOMS) + [f"world.robot_steps.{n}" for n in WORLD_ROBOTS]


def three_rtis_keys() -> list[str]:
    keys = ["rtis.floor.cpp", "rtis.floor.stream.cpp"]
    for rti, _ in RTI_COLUMNS:
        keys += [f"rtis.{rti}.lockstep.{k}" for k in RTI_LOCKSTEP] + [f"rtis.{rti}.pingpong", f"rtis.{rti}.throughput"]
    return keys


def _grant_target(k: int, median: Optional[float], g2: Optional[float], cpp_rtt: Optional[float],
                  barrier: Optional[float] = None) -> str:
    if not median:
        return ""
    if k == 2:
        target = _meets(median / cpp_rtt if cpp_rtt else None, 2.0, "≤ 2.0× C++ RTT")
        return target + (f"; {median / barrier:.2f}× the barrier" if target and barrier else "")
    if k == 32:
        return _meets(median / g2 if g2 else None, 4.0, "≤ 4× 2-federate figure")
    return f"{median / g2:.1f}× 2-federate figure" if g2 else ""


# OpenRTI 0.10 and CERTI 3.5.1 built Release, measured on 2026-11-23 on a 2-vCPU Debian 12 VM: the same loop
# with C++ federates, medians of three repetitions (µs per step). Reference figures, not re-measured by a run.
ANCHORS = {2: (151, 398), 4: (563, 975), 8: (1631, 3617)}


def _anchor(k: int, median: Optional[float], g2: Optional[float]) -> str:
    if not median:
        return ""
    if k in ANCHORS:
        openrti, certi = ANCHORS[k]
        return f"OpenRTI {openrti} µs, CERTI {certi} µs (C++ federates)"
    return f"{median / g2:.1f}× 2-federate figure" if g2 else ""


def _meets(ratio: Optional[float], limit: float, text: str = "") -> str:
    """'TEXT: met (1.23×)' or 'TEXT: missed (...)'; the default text is the one-way update target."""
    if ratio is None:
        return ""
    return f"{text or f'≤ {limit}× C++ one-way'}: {'met' if ratio <= limit else 'missed'} ({ratio:.2f}×)"


def _python_vs_cpp(ratio: str) -> str:
    return f"Python floor = {ratio}" if ratio != "–" else ratio


def _present(rows: list[Optional[Row]]) -> list[Row]:
    return [r for r in rows if r is not None]


def _us(seconds: float) -> str:
    return f"{seconds * 1e6:.1f} µs" if seconds < 1e-3 else f"{seconds * 1e6:.0f} µs"


def _mbps(rate: Optional[float]) -> str:
    return "–" if rate is None else f"{rate / 1e6:.0f} MB/s"


def _rate(rate: Optional[float]) -> str:
    return "–" if rate is None else f"{rate / 1000:.1f} k/s"
