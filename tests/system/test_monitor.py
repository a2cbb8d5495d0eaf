"""hlacore.monitor (docs/monitor.md): the live web view, from the views it computes to the page in a real browser.

The browser test drives Debian's headless chromium with Selenium (scripts/test.sh installs chromium and
chromium-driver when missing) against an ASan rtig and a lockstep of federate processes.
"""

from __future__ import annotations

import json
import os
import pathlib
import shutil
import signal
import time
import urllib.request
from typing import Any, Callable, Iterator, Optional

import pytest

import hlacore
import hlacore.rti as rti
from hlacore.monitor import Monitor
from hlacore.monitor.state import MonitorState, holding_back

from support import ROBOT_FED, RtigProcess, python_subprocess, secret_file


def federate(handle: int, time_: float, *, lookahead: float = 1.0, pending: Optional[dict[str, float | str]] = None,
             lbts: Optional[float] = None, grants: int = 0, updates: int = 0,
             held_by: tuple[int, ...] = ()) -> dict[str, Any]:
    """One federate of a status report (null for an infinite time, as on the wire)."""
    return {"handle": handle, "name": f"f{handle}", "time": time_, "lookahead": lookahead, "regulating": True,
            "constrained": True, "pending": pending, "queued_tso": 0, "queued_ro": 0, "lbts": lbts,
            "output_bound": time_ + lookahead, "grants": grants, "updates_sent": updates, "interactions_sent": 0,
            "held_by": [{"handle": h, "name": f"f{h}", "output_bound": 4.0} for h in held_by]}


def report(federates: list[dict[str, Any]], *, events: Optional[list[dict[str, Any]]] = None, last_event: int = 0,
           cpu: float = 0.0) -> dict[str, Any]:
    return {"server": "hlacore rtig", "address": "127.0.0.1:1", "tls": False, "connections": len(federates),
            "federations": [{"name": "F", "fed": "robot.fed", "objects": 0, "sync_points": [],
                             "save_restore": {"state": "idle", "saves": []}, "federates": federates}],
            "process": {"pid": 1, "rss_bytes": 1 << 20, "cpu_seconds": cpu}, "events": events or [],
            "last_event": last_event}


# ---- the views (hlacore/monitor/state.py) ----

def test_a_federate_waiting_long_enough_is_held_back_by_the_ones_the_gateway_names() -> None:
    # f1 asked for 6 and waits at LBTS 4 = f2's bound (3 + 1): the gateway says f2 holds it; f3 is ahead.
    waiting = federate(1, 5.0, pending={"request": "TAR", "time": 6.0, "waiting": 2.5}, lbts=4.0, held_by=(2,))
    paused, ahead = federate(2, 3.0), federate(3, 8.0)
    assert holding_back([waiting, paused, ahead]) == {2: [(1, 2.5)]}
    # Not yet for a wait shorter than the threshold, nor when the gateway names nobody (about to be granted).
    assert holding_back([{**waiting, "pending": {"request": "TAR", "time": 6.0, "waiting": 0.5}}, paused]) == {}
    assert holding_back([{**waiting, "held_by": []}, paused]) == {}
    assert holding_back([waiting, paused], hold_seconds=3.0) == {}


def test_rates_are_averaged_over_the_last_seconds_and_the_cpu_share_comes_from_the_gateways_cpu_seconds() -> None:
    state = MonitorState()
    first = state.update(report([federate(1, 1.0, grants=10, updates=20)], cpu=1.0), wall=100.0, monotonic=5.0)
    (f,) = first["federations"][0]["federates"]
    assert (f["grants_per_second"], f["updates_per_second"], f["key"]) == (0.0, 0.0, "F/1")
    assert first["process"]["cpu_percent"] is None
    second = state.update(report([federate(1, 3.0, grants=30, updates=60)], cpu=1.5), wall=102.0, monotonic=7.0)
    (f,) = second["federations"][0]["federates"]
    assert (f["grants_per_second"], f["updates_per_second"]) == (10.0, 20.0)
    assert second["process"]["cpu_percent"] == pytest.approx(25.0)
    assert list(state.history["F/1"]) == [(100.0, 1.0), (102.0, 3.0)]
    # One grant every other report (a slow lockstep) reads as the average, not as 0 and 2 in turn.
    for k in range(1, 21):
        view = state.update(report([federate(1, 3.0, grants=30 + k // 2)]), wall=102.0 + k / 2, monotonic=7.0 + k / 2)
    assert view["federations"][0]["federates"][0]["grants_per_second"] == pytest.approx(1.0, abs=0.15)


def test_history_is_bounded_and_forgets_departed_federates() -> None:
    state = MonitorState(history_points=5)
    for k in range(20):
        state.update(report([federate(1, float(k)), federate(2, float(k))]), wall=float(k), monotonic=float(k))
    assert [t for _, t in state.history["F/1"]] == [15.0, 16.0, 17.0, 18.0, 19.0]
    state.update(report([federate(1, 20.0)]), wall=20.0, monotonic=20.0)
    assert set(state.history) == {"F/1"}


def test_events_accumulate_and_start_again_with_a_new_gateway() -> None:
    state = MonitorState()
    joined = {"sequence": 1, "time": 1.0, "kind": "joined", "federation": "F", "federate": 1, "name": "f1",
              "reason": ""}
    dropped = {**joined, "sequence": 2, "kind": "dropped", "reason": "connection closed by peer"}
    state.update(report([], events=[joined], last_event=1), 1.0, 1.0)
    view = state.update(report([], events=[dropped], last_event=2), 2.0, 2.0)
    assert view["events"] == [dropped] and list(state.events) == [joined, dropped] and state.last_event == 2
    state.update(report([], events=[joined], last_event=1), 3.0, 3.0)  # numbers went back: another gateway
    assert list(state.events) == [joined] and state.last_event == 1


def test_an_unreachable_gateway_keeps_the_last_view_marked_stale() -> None:
    state = MonitorState()
    state.update(report([federate(1, 1.0)]), 1.0, 1.0)
    view = state.unreachable("RTIinternalError: cannot connect", 2.0)
    assert view["connected"] is False and "cannot connect" in view["error"]
    assert view["federations"][0]["federates"][0]["name"] == "f1"
    hello = state.hello()
    assert hello["latest"] is view and hello["history"]["F/1"] == [(1.0, 1.0)]


# ---- the server, without a browser ----

def fetch_json(url: str) -> Any:
    with urllib.request.urlopen(url, timeout=10) as response:
        return json.loads(response.read())


def wait_for(condition: Callable[[], Any], timeout: float, what: str) -> Any:
    deadline = time.monotonic() + timeout
    while True:
        value = condition()
        if value:
            return value
        assert time.monotonic() < deadline, f"waited {timeout} s for {what}"
        time.sleep(0.1)


def test_the_monitor_serves_the_page_and_the_view_of_an_in_process_gateway() -> None:
    with hlacore.Gateway(port=0) as gateway:
        creator = rti.RTIAmbassador(gateway.address)
        creator.createFederationExecution("TestFed", ROBOT_FED)
        member = rti.RTIAmbassador(gateway.address)
        member.joinFederationExecution("watched", "TestFed", rti.FederateAmbassador())
        with gateway.monitor(interval=0.1) as monitor:
            assert monitor.url.startswith("http://127.0.0.1:") and not monitor.url.endswith(":0/")
            with urllib.request.urlopen(monitor.url, timeout=10) as page:
                assert b"hlacore monitor" in page.read()
            view = wait_for(lambda: fetch_json(monitor.url + "view.json").get("federations"), 10, "a view")
            (federation,) = view
            assert [f["name"] for f in federation["federates"]] == ["watched"]
            events = fetch_json(monitor.url + "view.json")
            kinds = [(e["kind"], e["name"]) for e in monitor.state.events]
            assert ("joined", "watched") in kinds and events["connected"] is True
        member.resignFederationExecution(rti.ResignAction.NoAction)
        creator.destroyFederationExecution("TestFed")


def test_bad_settings_are_refused_at_the_call() -> None:
    with pytest.raises(ValueError, match="interval"):
        Monitor("127.0.0.1:1", interval=5.0)
    with pytest.raises(ValueError, match="hold_seconds"):
        Monitor("127.0.0.1:1", hold_seconds=0)


def test_a_gateway_that_is_not_there_is_shown_as_unreachable() -> None:
    import socket

    with socket.socket() as s:
        s.bind(("127.0.0.1", 0))
        port = s.getsockname()[1]
    with Monitor(f"127.0.0.1:{port}", port=0, interval=0.1) as monitor:
        view = wait_for(lambda: fetch_json(monitor.url + "view.json"), 10, "a view")
        assert view["connected"] is False and "cannot connect" in view["error"]


def test_a_gateway_with_a_secret_is_watched_only_with_the_secret(tmp_path: pathlib.Path) -> None:
    """The monitor is a client like any other: without the gateway's secret it shows the refusal, with it
    (Gateway.monitor() passes the gateway's own) the federation."""
    secret = secret_file(tmp_path, "correct horse battery staple")
    with hlacore.Gateway(port=0, secret_file=secret) as gateway:
        rti.RTIAmbassador(gateway.address, secret_file=secret).createFederationExecution("TestFed", ROBOT_FED)
        with Monitor(gateway.address, port=0, interval=0.1, secret_file="") as outsider:
            view = wait_for(lambda: fetch_json(outsider.url + "view.json"), 10, "a view")
            assert view["connected"] is False and "secret" in view["error"].lower(), view
        with gateway.monitor(interval=0.1) as insider:
            view = wait_for(lambda: fetch_json(insider.url + "view.json").get("federations"), 10, "a view")
            assert [f["name"] for f in view] == ["TestFed"]
        rti.RTIAmbassador(gateway.address, secret_file=secret).destroyFederationExecution("TestFed")


# ---- the page in headless chromium ----

@pytest.fixture
def browser() -> Iterator[Any]:
    from selenium import webdriver
    from selenium.webdriver.chrome.service import Service

    chromium = shutil.which("chromium")
    driver_path = shutil.which("chromedriver")
    assert chromium and driver_path, ("Debian's chromium and chromium-driver are missing: ./scripts/test.sh "
                                      "installs them")
    options = webdriver.ChromeOptions()
    options.binary_location = chromium
    for argument in ("--headless=new", "--no-sandbox", "--disable-gpu", "--disable-dev-shm-usage",
                     "--window-size=1400,1000"):
        options.add_argument(argument)
    driver = webdriver.Chrome(service=Service(executable_path=driver_path), options=options)
    driver.set_page_load_timeout(30)
    try:
        yield driver
    finally:
        driver.quit()


def federate_rows(driver: Any) -> list[dict[str, Any]]:
    """The federates' rows as the page shows them (name, time, state, holding), read by one script: the page
    redraws at each view, so an element found by one WebDriver call may be gone at the next."""
    return list(driver.execute_script(
        "return Array.from(document.querySelectorAll('tr.federate')).map(r => ({name: r.dataset.name, "
        "time: r.querySelector('td.time').innerText, state: r.querySelector('td.state').innerText, "
        "holding: r.classList.contains('holding')}));"))


def page_texts(driver: Any, selector: str) -> list[str]:
    """The text of each element matching `selector`, read by one script (see federate_rows)."""
    return list(driver.execute_script("return Array.from(document.querySelectorAll(arguments[0])).map(e => e.innerText);",
                                      selector))


def row_times(driver: Any) -> dict[str, float]:
    """Each federate's logical time as the page shows it."""
    return {row["name"]: float(row["time"]) for row in federate_rows(driver)}


@pytest.mark.slow
def test_the_page_shows_a_lockstep_live_a_paused_federate_holding_it_back_and_a_killed_one_gone(
        rtig: RtigProcess, browser: Any, tmp_path: pathlib.Path) -> None:
    creator = rti.RTIAmbassador(rtig.address)
    creator.createFederationExecution("TestFed", ROBOT_FED)
    names = ["alpha", "bravo", "charlie"]
    peers = {name: python_subprocess("paced_federate.py", rtig.address, name, "0.05") for name in names}
    try:
        for peer in peers.values():
            assert peer.read_json(60) == {"ready": True}
        with Monitor(rtig.address, port=0, interval=0.25) as monitor:
            browser.get(monitor.url)
            # The federates are listed and their times advance on screen.
            first = wait_for(lambda: (lambda t: t if set(t) == set(names) else None)(row_times(browser)), 20,
                             "the three federates on the page")
            wait_for(lambda: all(row_times(browser)[n] > first[n] + 2 for n in names), 20, "the times advancing")
            # A paused federate (SIGSTOP, as a debugger's breakpoint) holds the others back.
            os.kill(peers["bravo"].pid, signal.SIGSTOP)
            holding = wait_for(lambda: [row for row in federate_rows(browser) if row["holding"]], 20,
                               "bravo shown as holding the others back")
            assert [row["name"] for row in holding] == ["bravo"]
            state = holding[0]["state"]
            assert state.startswith("holding back ") and "alpha" in state and "charlie" in state
            frozen = row_times(browser)
            time.sleep(1.0)
            assert row_times(browser) == frozen  # nobody advances past bravo
            browser.save_screenshot(str(tmp_path / "holding.png"))
            # Killed, it disappears; the log says why; the others go on.
            os.kill(peers["bravo"].pid, signal.SIGKILL)
            wait_for(lambda: set(row_times(browser)) == {"alpha", "charlie"}, 20, "bravo gone from the page")
            entry = wait_for(lambda: [text for text in page_texts(browser, "#log li.dropped") if "'bravo'" in text],
                             20, "bravo's drop in the log")
            assert "dropped: " in entry[0] and entry[0].lower().endswith("by peer"), entry  # closed, or reset
            after = row_times(browser)
            wait_for(lambda: all(row_times(browser)[n] > after[n] + 2 for n in ("alpha", "charlie")), 20,
                     "the others advancing again")
            assert not [row for row in federate_rows(browser) if row["holding"]]
            assert "gateway " + rtig.address in page_texts(browser, "#gateway")[0]
    finally:
        for peer in peers.values():
            peer.close()


def test_the_page_keeps_up_with_two_hundred_federates(browser: Any) -> None:
    """200 joined federates (connections of this process): the page lists them all and goes on drawing a view
    per interval."""
    with hlacore.Gateway(port=0) as gateway:
        creator = rti.RTIAmbassador(gateway.address)
        creator.createFederationExecution("TestFed", ROBOT_FED)
        members = []
        try:
            for i in range(200):
                member = rti.RTIAmbassador(gateway.address)
                member.joinFederationExecution(f"federate{i:03d}", "TestFed", rti.FederateAmbassador())
                members.append(member)
            with gateway.monitor(interval=0.25) as monitor:
                browser.get(monitor.url)
                wait_for(lambda: len(federate_rows(browser)) == 200, 30, "200 rows")
                views = browser.execute_script("return window.hlacoreViews")
                wait_for(lambda: browser.execute_script("return window.hlacoreViews") >= views + 8, 30,
                         "eight more views")
                names = {row["name"] for row in federate_rows(browser)}
                assert names == {f"federate{i:03d}" for i in range(200)}
        finally:
            for member in members:
                member.resignFederationExecution(rti.ResignAction.NoAction)
            creator.destroyFederationExecution("TestFed")


def test_the_page_shows_a_federate_protocol_session_connected_dropped_then_ended(browser: Any) -> None:
    """The door's sessions (hlacore.Gateway(fedpro=...)): a FedPro federate's session is shown connected with its
    federate's name; its link cut for good, dropped and waiting for a resume; after the resume timeout, ended
    with the reason, while its federate leaves the federation's table."""
    from hlacore import fedpro
    from hlacore.fedpro.session import split_address
    from hlacore.link import Link

    from support.fedpro import Calls
    from support.rti1516e import VEHICLES

    with hlacore.Gateway(port=0, fedpro="127.0.0.1:0", fedpro_resume_timeout=1.0) as gateway:
        link = Link(("127.0.0.1", 0), split_address(str(gateway.fedpro_address)))
        rtia = fedpro.RTIambassador(link.address, resume_timeout=0.5)
        try:
            rtia.connect(Calls())
            rtia.createFederationExecutionWithModules(federationName="Road", fomModules=[VEHICLES])
            rtia.joinFederationExecution(federateName="remote", federateType="fedpro", federationName="Road")
            with gateway.monitor(interval=0.1) as monitor:
                browser.get(monitor.url)
                sessions = lambda: page_texts(browser, "#fedpro tbody tr")  # noqa: E731
                row = wait_for(lambda: [r for r in sessions() if "remote of 'Road'" in r and "connected" in r], 20,
                               "the session, connected")
                assert "tcp on " + str(gateway.fedpro_address) in page_texts(browser, "#fedpro-door")[0], row
                link.close()  # gone for good: the client cannot resume
                wait_for(lambda: [r for r in sessions() if "waiting for a resume" in r], 20, "the session, dropped")
                wait_for(lambda: [r for r in sessions() if "ended: not resumed within 1 s" in r], 20, "the session, ended")
                wait_for(lambda: "remote" not in [row["name"] for row in federate_rows(browser)], 20,
                         "its federate gone from the federation's table")
        finally:
            rtia.close(timeout=1.0)
            link.close()
