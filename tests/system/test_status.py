"""Introspection: the gateway reports each federate's time state (Python call, rtig --status, table)."""

from __future__ import annotations

import json
import math
import os
import subprocess
import sys
import time

import hlacore
import hlacore.status
import hlacore.rti as rti
from hlacore.status import status

from support import ROBOT_FED, Recorder, RtigProcess, python_subprocess, status_client


def join_timed(address: str, name: str, lookahead: float) -> tuple[rti.RTIAmbassador, Recorder]:
    rtia, amb = rti.RTIAmbassador(address), Recorder()
    rtia.joinFederationExecution(name, "TestFed", amb)
    rtia.enable_time_management(lookahead, timeout=5.0)
    return rtia, amb


def test_status_reports_each_federates_time_state(inprocess_gateway: hlacore.Gateway) -> None:
    address = inprocess_gateway.address
    creator = rti.RTIAmbassador(address)
    creator.createFederationExecution("TestFed", ROBOT_FED)
    a, _ = join_timed(address, "alpha", 1.0)
    b, _ = join_timed(address, "beta", 2.0)
    command = a.getInteractionClassHandle("command")
    value = a.getParameterHandle("value", command)
    a.publishInteractionClass(command)
    b.subscribeInteractionClass(command)
    b.queryLBTS()  # the subscription is in place
    a.sendInteraction(command, {value: b"x"}, "", 7.0)
    a.timeAdvanceRequest(3.0)  # waits: beta's bound is 2
    report = inprocess_gateway.status()
    assert report["server"] == "hlacore rtig" and report["tls"] is False
    (federation,) = report["federations"]
    assert federation["name"] == "TestFed" and federation["fed"] == ROBOT_FED
    assert federation["time_semantics"] == "exact"
    alpha, beta = federation["federates"]
    waited = alpha["pending"].pop("waiting")  # seconds since the request
    assert 0 <= waited < 5
    assert alpha == {
        "handle": 1, "name": "alpha", "type": "", "time": 0.0, "lookahead": 1.0, "regulating": True,
        "enabling_regulation": False, "constrained": True,
        "asynchronous_delivery": False, "pending": {"request": "TAR", "time": 3.0},
        "held_by": [{"handle": 2, "name": "beta", "output_bound": 2.0}], "queued_tso": 0,
        "queued_ro": 0, "regions": 0, "lbts": 2.0, "output_bound": 4.0,
        "updates_sent": 0, "interactions_sent": 1, "grants": 0, "backlog": {"memory": 0, "disk": 0},
    }
    assert beta["pending"] is None and beta["held_by"] == [] and beta["queued_tso"] == 1 and beta["lbts"] == 4.0
    assert beta["output_bound"] == 2.0
    b.timeAdvanceRequest(3.0)
    assert a.await_grant(5.0) == 3.0
    assert b.await_grant(5.0) == 3.0
    report = status(address)
    alpha, beta = report["federations"][0]["federates"]
    assert (alpha["time"], alpha["pending"], beta["time"], beta["queued_tso"]) == (3.0, None, 3.0, 1)
    assert (alpha["grants"], beta["grants"]) == (1, 1)
    for rtia in (a, b):
        rtia.resignFederationExecution(rti.ResignAction.NoAction)
    assert status(address)["federations"][0]["federates"] == []
    creator.destroyFederationExecution("TestFed")
    assert status(address)["federations"] == []


def test_infinite_bounds_are_null_on_the_wire_and_inf_in_python(rtig: RtigProcess) -> None:
    creator = rti.RTIAmbassador(rtig.address)
    creator.createFederationExecution("TestFed", ROBOT_FED)
    lone, _ = join_timed(rtig.address, "lone", 1.0)
    raw = subprocess.run([status_client(), "--status", rtig.address], capture_output=True, text=True, timeout=10)
    assert raw.returncode == 0, raw.stderr
    (federate,) = json.loads(raw.stdout)["federations"][0]["federates"]
    assert federate["name"] == "lone" and federate["lbts"] is None and federate["output_bound"] == 1.0
    assert status(rtig.address)["federations"][0]["federates"][0]["lbts"] == math.inf
    table = subprocess.run([sys.executable, "-m", "hlacore.status", rtig.address], capture_output=True, text=True,
                           timeout=10)
    assert table.returncode == 0, table.stderr
    assert "federation TestFed" in table.stdout
    row = next(line for line in table.stdout.splitlines() if line.split()[1:2] == ["lone"])
    assert row.split() == ["1", "lone", "0", "1", "RC", "-", "0", "0", "inf"]
    lone.resignFederationExecution(rti.ResignAction.NoAction)
    creator.destroyFederationExecution("TestFed")


def test_status_of_nothing_listening_is_a_clear_error() -> None:
    import socket

    with socket.socket() as s:
        s.bind(("127.0.0.1", 0))
        port = s.getsockname()[1]
    out = subprocess.run([status_client(), "--status", f"127.0.0.1:{port}"], capture_output=True, text=True,
                         timeout=10)
    assert out.returncode == 1 and "cannot connect to rtig at 127.0.0.1:" in out.stderr
    out = subprocess.run([sys.executable, "-m", "hlacore.status", f"127.0.0.1:{port}"], capture_output=True,
                         text=True, timeout=10)
    assert out.returncode == 1 and "cannot connect" in out.stderr


def _report(names: list[str]) -> dict:
    federates = [
        {"handle": i + 1, "name": name, "time": 1234567.25 * i, "lookahead": 0.1, "regulating": True,
         "constrained": i % 2 == 0, "pending": {"request": "TARA", "time": 1234568.5} if i else None,
         "queued_tso": 3, "queued_ro": 10000, "lbts": math.inf}
        for i, name in enumerate(names)
    ]
    return {"server": "hlacore rtig", "address": "127.0.0.1:60400", "connections": len(names),
            "federations": [{"name": "F", "fed": "robot.fed", "objects": 0, "sync_points": [], "federates": federates}]}


def test_table_fits_the_width_and_keeps_the_numbers_readable() -> None:
    text = hlacore.status.format_table(_report(["alpha", "a-federate-name-longer-than-the-terminal-allows"]), 80)
    assert max(map(len, text.splitlines())) <= 80
    assert "1234567.25" in text and "TARA 1234568.5" in text and "a-federate-n" in text
    wide = hlacore.status.format_table(_report(["alpha", "a-federate-name-longer-than-the-terminal-allows"]), 140)
    assert "a-federate-name-longer-than-the-terminal-allows" in wide


def test_watch_redraws_in_place_on_a_terminal(inprocess_gateway: hlacore.Gateway, monkeypatch, capsys) -> None:
    """--watch on a terminal clears and redraws one screenful per report; --count ends it."""
    monkeypatch.setattr(sys.stdout, "isatty", lambda: True)
    monkeypatch.setattr(hlacore.status.shutil, "get_terminal_size", lambda: os.terminal_size((60, 8)))
    creator = rti.RTIAmbassador(inprocess_gateway.address)
    creator.createFederationExecution("TestFed", ROBOT_FED)
    members = [join_timed(inprocess_gateway.address, f"federate{i}", 1.0)[0] for i in range(6)]
    assert hlacore.status.main([inprocess_gateway.address, "--watch", "0.01", "--count", "2"]) == 0
    screens = capsys.readouterr().out.split("\x1b[H\x1b[2J")[1:]
    assert len(screens) == 2
    for screen in screens:
        lines = screen.rstrip("\n").splitlines()
        assert len(lines) <= 7 and max(map(len, lines)) <= 60
        assert "more line(s)" in lines[-1]  # six federates do not fit in eight rows
    for rtia in members:
        rtia.resignFederationExecution(rti.ResignAction.NoAction)


def test_status_keeps_a_log_of_joins_resigns_and_drops_with_the_reason(rtig: RtigProcess) -> None:
    """What hlacore.monitor shows: the events numbered after the last one seen, and the gateway's process."""
    creator = rti.RTIAmbassador(rtig.address)
    creator.createFederationExecution("TestFed", ROBOT_FED)
    stayer, _ = join_timed(rtig.address, "stayer", 1.0)
    victim = python_subprocess("victim_federate.py", rtig.address)
    try:
        assert victim.read_line(30).startswith("ready ")
        client = hlacore._core.RTIAmbassadorBase(hlacore._core.client_settings({"address": rtig.address}))
        report = json.loads(client._status())
        assert [(e["kind"], e["federation"], e["name"]) for e in report["events"]] == [
            ("created", "TestFed", ROBOT_FED), ("joined", "TestFed", "stayer"), ("joined", "TestFed", "victim")]
        assert [e["sequence"] for e in report["events"]] == [1, 2, 3] and report["last_event"] == 3
        assert report["events"][1]["federate"] == 1 and report["events"][1]["time"] > 1.7e9
        process = report["process"]
        assert process["pid"] == rtig.proc.pid and process["rss_bytes"] > 1 << 20 and process["cpu_seconds"] > 0
        assert "instances" in report["federations"][0]
        assert "instances" not in json.loads(client._status(instances=False))["federations"][0]
        victim.kill()
        deadline = time.monotonic() + 10
        while not (later := json.loads(client._status(3)))["events"]:
            assert time.monotonic() < deadline, "the drop was not logged"
            time.sleep(0.05)
        (dropped,) = later["events"]
        assert (dropped["kind"], dropped["name"], dropped["federate"]) == ("dropped", "victim", 2)
        assert dropped["reason"].lower().endswith("by peer")  # "connection closed by peer", or reset with data unread
        stayer.resignFederationExecution(rti.ResignAction.NoAction)
        creator.destroyFederationExecution("TestFed")
        assert [(e["kind"], e["name"]) for e in json.loads(client._status(4))["events"]] == [
            ("resigned", "stayer"), ("destroyed", "")]
    finally:
        victim.close()


def test_the_event_log_keeps_long_names_cut_and_valid(inprocess_gateway: hlacore.Gateway) -> None:
    """Names come from clients and may be as long as a frame: the log keeps 256 bytes of them, cut between
    characters, so that it stays bounded and its JSON valid."""
    long_name = "é" * 5000  # 10 000 bytes of two-byte characters
    creator = rti.RTIAmbassador(inprocess_gateway.address)
    creator.createFederationExecution(long_name, ROBOT_FED)
    creator.destroyFederationExecution(long_name)
    created, destroyed = [e for e in inprocess_gateway.status()["events"] if e["kind"] in ("created", "destroyed")]
    for event in (created, destroyed):
        assert event["federation"] == "é" * 128 + "\u2026"
