"""Best effort over UDP (docs/networking.md): which messages travel as datagrams, the counts on
both ends, the fall back to TCP, garbage on the datagram port, and a lossy link beside a reliable lockstep."""

from __future__ import annotations

import asyncio
import json
import pathlib
import random
import socket
import struct
import time
from typing import Any

import pytest

import hlacore.aio
import hlacore.status
import hlacore.rti as rti
from hlacore.link import Direction, Link
from hlacore.processes import SyncAmbassador, python_peer

from support import PEERS, ROBOT_FED, lead_peers, running_rtig, secret_file
from support.federations import pair
from support.nethosts import NetHosts
from support.wire import T, Cursor, frame, hello, raw_client, send_interaction, u32


def gateway_datagrams(address: str) -> dict[str, Any]:
    report: dict[str, Any] = hlacore.status.status(address)
    return report["datagrams"]  # type: ignore[no-any-return]


def test_best_effort_messages_travel_as_datagrams_and_the_rest_in_the_stream(tmp_path: pathlib.Path) -> None:
    """Best-effort receive-order updates and interactions go as datagrams both ways, counted on both ends and
    in rtig's status; reliable ones, timestamped ones and ones over the size limit go over TCP."""
    with running_rtig(tmp_path) as server, pair(server.address) as p:
        assert p.alice.datagram_status()["path"] and p.bob.datagram_status()["path"]
        for i in range(50):
            p.alice.sendInteraction(p.reply, {p.value: b"r%d" % i}, "")
            p.alice.updateAttributeValues(p.obj, {p.sonar: b"s%d" % i}, "")
        p.alice.sendInteraction(p.command, {p.name: b"go"}, "")                  # reliable
        p.alice.updateAttributeValues(p.obj, {p.location: b"here"}, "")          # reliable
        p.alice.updateAttributeValues(p.obj, {p.sonar: b"x", p.location: b"y"}, "")  # one reliable value
        p.alice.sendInteraction(p.reply, {p.value: bytes(2000)}, "")              # over 1400 bytes
        p.wait(lambda: len(p.bob_amb.interactions) == 52 and len(p.bob_amb.reflections) >= 52)
        alice, bob = p.alice.datagram_status(), p.bob.datagram_status()
        assert (alice["sent"], alice["oversize"], alice["send_failed"]) == (100, 1, 0), alice
        # The gateway splits the mixed update by transport: its sonar half comes as a datagram too.
        assert (bob["received"], bob["lost"], bob["duplicates"]) == (101, 0, 0), bob
        print(f"\nalice {alice}\nbob {bob}")
        report = gateway_datagrams(server.address)
        counts = {f["federate"]: f["counts"] for f in report["federates"]}
        assert report["max_datagram"] == 1400 and report["stray"] == 0
        assert counts[1]["received"] == 100 and counts[2]["sent"] == 101, counts  # alice 1, bob 2
        assert counts[2]["oversize"] == 1, counts  # the 2000-byte reply, sent to bob in the stream


def test_asyncio_wakes_for_a_datagram(tmp_path: pathlib.Path) -> None:
    """hlacore.aio waits on the datagram socket too: a best-effort interaction sent while bob awaits tick()
    wakes him (waiting on the stream alone, tick would time out)."""
    with running_rtig(tmp_path) as server, pair(server.address) as p:
        bob = hlacore.aio.AsyncAmbassador(p.bob)

        async def receive() -> bool:
            asyncio.get_running_loop().call_later(0.2, p.alice.sendInteraction, p.reply, {p.value: b"wake"}, "")
            return await bob.tick(timeout=5.0)

        assert asyncio.run(receive())
        assert [params[p.value] for _, params, _ in p.bob_amb.interactions] == [b"wake"]
        assert p.bob.datagram_status()["received"] == 1


def test_timestamped_best_effort_stays_in_the_stream(tmp_path: pathlib.Path) -> None:
    """A best-effort update with a timestamp goes over TCP: time management needs it in order with the
    sender's time advances (docs/networking.md). To a federate that is not constrained it is a receive-order
    message again, and comes as a datagram."""
    with running_rtig(tmp_path) as server, pair(server.address) as p:
        p.alice.enable_time_management(1.0, constrained=False)
        p.alice.updateAttributeValues(p.obj, {p.sonar: b"timed"}, "", 5.0)
        p.wait(lambda: len(p.bob_amb.reflections) == 1)
        assert p.alice.datagram_status()["sent"] == 0
        assert p.bob.datagram_status()["received"] == 1
        p.bob.enable_time_management(1.0, regulating=False)
        # sonar is receive-ordered in the FED: made timestamp-ordered, it reaches constrained bob in TSO.
        p.alice.changeAttributeOrderType(p.obj, [p.sonar], p.alice.getOrderingHandle("timestamp"))
        p.alice.updateAttributeValues(p.obj, {p.sonar: b"timed"}, "", 6.0)
        p.alice.timeAdvanceRequest(10.0)  # lets bob's LBTS pass 6
        p.bob.timeAdvanceRequest(10.0)
        p.wait(lambda: len(p.bob_amb.reflections) == 2)
        assert p.alice.datagram_status()["sent"] == 0
        assert p.bob.datagram_status()["received"] == 1  # the timestamp-ordered one came in the stream


def test_changed_transport_decides_too(tmp_path: pathlib.Path) -> None:
    """changeAttributeTransportationType / changeInteractionTransportationType move a reliable attribute or
    class to datagrams and back."""
    with running_rtig(tmp_path) as server, pair(server.address) as p:
        # After each change one update and one interaction: the best-effort pair goes as 2 datagrams, the
        # reliable pair adds none.
        for step, (transport, value) in enumerate([("best_effort", b"fast"), ("reliable", b"sure")], start=1):
            handle = p.alice.getTransportationHandle(transport)
            p.alice.changeAttributeTransportationType(p.obj, [p.location], handle)
            p.alice.changeInteractionTransportationType(p.command, handle)
            p.alice.updateAttributeValues(p.obj, {p.location: value}, "")
            p.alice.sendInteraction(p.command, {p.name: value}, "")
            p.wait(lambda: len(p.bob_amb.reflections) == step and len(p.bob_amb.interactions) == step)
            assert p.alice.datagram_status()["sent"] == 2, transport
        assert p.bob.datagram_status()["received"] == 2


def test_without_datagrams_everything_goes_over_tcp(tmp_path: pathlib.Path) -> None:
    """rtig --max-datagram 0 offers none, and RTIAmbassador(datagrams=False) takes none: the same messages
    arrive over TCP, and datagram_status says why."""
    with running_rtig(tmp_path, "--max-datagram", "0") as server, pair(server.address) as p:
        assert p.alice.datagram_status() == dict(p.alice.datagram_status(), path=False,
                                                 reason="the gateway offers no datagrams")
        p.alice.sendInteraction(p.reply, {p.value: b"tcp"}, "")
        p.wait(lambda: len(p.bob_amb.interactions) == 1)
        assert gateway_datagrams(server.address)["port"] is None
    with running_rtig(tmp_path) as server, pair(server.address, datagrams=False) as p:
        assert p.alice.datagram_status()["reason"] == "datagrams turned off on this side"
        p.alice.sendInteraction(p.reply, {p.value: b"tcp"}, "")
        p.wait(lambda: len(p.bob_amb.interactions) == 1)
        assert p.bob.datagram_status()["received"] == 0


def test_when_datagrams_do_not_get_through_the_federate_falls_back_to_tcp(tmp_path: pathlib.Path,
                                                                        capfd: pytest.CaptureFixture[str]) -> None:
    """Behind a relay that passes TCP only: datagrams to its port are refused (nothing listens for UDP) or,
    where a firewall swallows them, never answered. Either way one line on stderr, and TCP carries all."""
    with running_rtig(tmp_path) as server, Link(("127.0.0.1", 0), ("127.0.0.1", server.port)) as tcp_only:
        refused = rti.RTIAmbassador(tcp_only.address)
        assert "refuses" in refused.datagram_status()["reason"]
        with socket.socket(socket.AF_INET, socket.SOCK_DGRAM) as swallow:
            swallow.bind(("127.0.0.1", tcp_only.port))  # takes the datagrams, answers nothing
            started = time.monotonic()
            silent = rti.RTIAmbassador(tcp_only.address)
            waited = time.monotonic() - started
        status = silent.datagram_status()
        assert not status["path"] and "no answer to 3 hellos" in status["reason"], status
        print(f"\nconnecting with datagrams swallowed took {waited:.2f} s")
        err = capfd.readouterr().err
        assert err.count("hlacore: no datagrams with rtig at") == 2, err
        with pair(tcp_only.address) as p:  # and the federation works
            p.alice.sendInteraction(p.reply, {p.value: b"tcp"}, "")
            p.wait(lambda: len(p.bob_amb.interactions) == 1)


def test_garbage_on_the_datagram_port_is_counted_and_harms_nobody(tmp_path: pathlib.Path) -> None:
    """Random datagrams, hlacore headers with unknown tokens, and a known token from the wrong address are
    dropped and counted as stray; the federates go on."""
    with running_rtig(tmp_path) as server, pair(server.address) as p:
        rng = random.Random(7)
        with socket.socket(socket.AF_INET, socket.SOCK_DGRAM) as attacker:
            target = ("127.0.0.1", server.port)
            for size in (0, 1, 19, 20, 100, 1400, 9000):
                attacker.sendto(rng.randbytes(size), target)
            for _ in range(20):
                header = struct.pack("<IQQ", 0x44414C48, rng.getrandbits(64), rng.getrandbits(64))
                attacker.sendto(header + rng.randbytes(rng.randrange(0, 64)), target)
            p.alice.sendInteraction(p.reply, {p.value: b"still"}, "")
            p.wait(lambda: len(p.bob_amb.interactions) == 1)
        deadline = time.monotonic() + 5
        while gateway_datagrams(server.address)["stray"] < 27:
            assert time.monotonic() < deadline, gateway_datagrams(server.address)
            time.sleep(0.05)
        assert "dropped" not in server.log(), server.log()


@pytest.mark.slow
def test_a_lossy_best_effort_stream_beside_a_reliable_lockstep(nethosts: NetHosts, tmp_path: pathlib.Path) -> None:
    """Two lockstep federates (TSO, reliable), one on its own host behind a link that loses 5 % of the
    datagrams each way (TCP untouched), each streaming 200 best-effort interactions a second to the other:
    about 95 % of each stream arrives, the loss is counted by the receiving end (the gateway for what comes
    up, the federate for what goes down), and every lockstep step is whole, with and without the stream."""
    robot = nethosts.add("robot")
    one_ms = Direction(delay=0.001)
    lossy = Direction(delay=0.001, loss=0.05)
    steps = 1500
    with running_rtig(tmp_path) as server, \
            Link((robot.router, 0), ("127.0.0.1", server.port), up=one_ms, down=one_ms, seed=5) as tcp, \
            Link((robot.router, tcp.port), ("127.0.0.1", server.port), up=lossy, down=lossy, udp=True, seed=6) as udp:
        creator = rti.RTIAmbassador(server.address)
        creator.createFederationExecution("TestFed", ROBOT_FED)
        runs = {}
        for rate in (0, 200):
            runs[rate] = _run_stream_lockstep(creator, tcp.address, robot.exec_prefix(), server.address, steps, rate)
        creator.destroyFederationExecution("TestFed")
    quiet, streaming = runs[0], runs[200]
    for name in ("robot", "sim"):
        print(f"\n{name}: step median/p99 {quiet[name]['step_ms']} ms alone, {streaming[name]['step_ms']} ms with "
              f"the streams; stream sent {streaming[name]['sent']}, received of the other's "
              f"{streaming[name]['received']}, latency median/p99 {streaming[name]['latency_ms']} ms; "
              f"datagrams {streaming[name]['datagrams']}")
    print(f"link: {udp.counters['up'].lost} datagrams dropped up, {udp.counters['down'].lost} down")
    for run in (quiet, streaming):
        for name, result in run.items():
            assert result["errors"] == [], (name, result)
    robot_r, sim_r = streaming["robot"], streaming["sim"]
    for sender, receiver in ((robot_r, sim_r), (sim_r, robot_r)):
        assert 0.90 <= receiver["received"] / sender["sent"] <= 0.99, (sender["sent"], receiver["received"])
    # What the link dropped going down, the robot's client counted; what it dropped going up, the gateway. Not
    # counted: a lost hello (it has no sequence number) and a loss at the very end (no later datagram shows it).
    for counted, dropped in ((robot_r["datagrams"]["lost"], udp.counters["down"].lost),
                             (robot_r["gateway"]["lost"], udp.counters["up"].lost)):
        assert dropped - 3 <= counted <= dropped, (counted, dropped)
    assert sim_r["received"] == robot_r["gateway"]["received"]  # all the gateway got, forwarded over loopback


def _run_stream_lockstep(creator: rti.RTIAmbassador, robot_address: str, robot_prefix: list[str],
                         sim_address: str, steps: int, rate: int) -> dict[str, dict[str, Any]]:
    amb = SyncAmbassador()
    creator.joinFederationExecution("conductor", "TestFed", amb)
    results = lead_peers(creator, amb, {
        "robot": python_peer(PEERS / "stream_lockstep.py", robot_address, "robot", steps, rate, prefix=robot_prefix),
        "sim": python_peer(PEERS / "stream_lockstep.py", sim_address, "sim", steps, rate),
    })
    creator.resignFederationExecution(rti.ResignAction.NoAction)
    return results


def test_status_shows_the_datagram_counts(tmp_path: pathlib.Path) -> None:
    """python -m hlacore.status prints the datagram counts of each federate."""
    with running_rtig(tmp_path) as server, pair(server.address) as p:
        p.alice.sendInteraction(p.reply, {p.value: b"x"}, "")
        p.wait(lambda: len(p.bob_amb.interactions) == 1)
        text = hlacore.status.format_table(hlacore.status.status(server.address), 120)
        print("\n" + text)
        assert "datagrams" in text
        assert json.dumps(hlacore.status.status(server.address)["datagrams"])


def test_the_gateway_counts_lost_reordered_and_duplicate_datagrams(tmp_path: pathlib.Path) -> None:
    """A raw federate sends its best-effort interactions with sequence numbers 1, 2, 4, 3, 3, 6: the gateway
    forwards five (not the repeated 3) and counts 5 received, 1 lost (5; 3 was counted lost until it came),
    1 reordered and 1 duplicate."""
    with running_rtig(tmp_path) as server, pair(server.address) as p, raw_client(server.address) as raw, \
            socket.socket(socket.AF_INET, socket.SOCK_DGRAM) as datagrams:
        handle = raw.join("raw")
        raw.send(frame("PublishInteractionClass", u32(p.reply)))
        datagrams.connect(("127.0.0.1", server.port))
        datagrams.settimeout(5)
        datagrams.send(struct.pack("<IQQ", 0x44414C48, raw.datagram_token, 0) + frame("DatagramHello", u32(1)))
        datagrams.recv(512)  # the echo
        raw.send(frame("DatagramPath"))
        raw.ping()
        for serial, sequence in enumerate((1, 2, 4, 3, 3, 6), start=1):
            body = send_interaction(raw, p.reply, p.value, b"%d" % sequence, None, serial)
            datagrams.send(struct.pack("<IQQ", 0x44414C48, raw.datagram_token, sequence) + body)
        p.wait(lambda: len(p.bob_amb.interactions) == 5)
        counts = next(f["counts"] for f in gateway_datagrams(server.address)["federates"] if f["federate"] == handle)
    assert sorted(params[p.value] for _, params, _ in p.bob_amb.interactions) == [b"1", b"2", b"3", b"4", b"6"]
    assert {k: counts[k] for k in ("received", "lost", "reordered", "duplicates")} == \
        {"received": 5, "lost": 1, "reordered": 1, "duplicates": 1}, counts


def test_with_a_secret_only_an_authenticated_connection_gets_datagrams_through(tmp_path: pathlib.Path) -> None:
    """The Welcome hands out the datagram token before the challenge is met: a client that has not
    authenticated gets no echo to its hello (counted stray); authenticated federates get the path."""
    secret = secret_file(tmp_path, "datagrams need the secret too")
    with running_rtig(tmp_path, "--secret-file", str(secret)) as server:
        with socket.create_connection(("127.0.0.1", server.port), timeout=5) as stream, \
                socket.socket(socket.AF_INET, socket.SOCK_DGRAM) as datagrams:
            stream.sendall(hello())
            welcome = b""
            while len(welcome) < 4 or len(welcome) < 4 + struct.unpack_from("<I", welcome)[0]:
                welcome += stream.recv(4096)
            assert struct.unpack_from("<H", welcome, 4)[0] == T["Welcome"]
            c = Cursor(welcome[6:])
            c.take("<H"), c.string(), c.take("<I")
            assert len(c.string()) == 32  # the challenge, not answered
            token = c.take("<Q")
            datagrams.settimeout(0.5)
            datagrams.sendto(struct.pack("<IQQ", 0x44414C48, token, 0) + frame("DatagramHello", u32(1)),
                             ("127.0.0.1", server.port))
            with pytest.raises(socket.timeout):
                datagrams.recvfrom(4096)
        report = hlacore.status.status(server.address, secret)["datagrams"]
        assert report["stray"] == 1, report
        with pair(server.address, secret_file=secret) as p:
            assert p.alice.datagram_status()["path"] and p.bob.datagram_status()["path"]
