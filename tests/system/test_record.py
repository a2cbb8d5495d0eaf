"""Recording a federation and replaying federates from it (docs/record-replay.md).

The recording of a small federation is checked event by event against what its federates sent, through the
mcap library's own reader; the main job is recorded, its Robot Federate replayed against a live testbench
(same verdicts, same reflections, and a recording of the replay equal to the original), and ``diff`` names
the cycle where a miscalibrated robot first fails. Both gateways record: the in-process one and rtig.
"""

from __future__ import annotations

import base64
import contextlib
import dataclasses
import json
import os
import pathlib
import subprocess
import sys
import threading
import time
from importlib import resources
from typing import Any, Iterator

import mcap.reader
import pytest

import hlacore
from hlacore import rti
from hlacore.experiments.robot_in_the_loop.experiment import Experiment, ExperimentOptions, run_experiment
from hlacore.processes import Child
from hlacore.federates.robot_driver.report import decode_report
from hlacore.recording import Event, RecordingError, read
from hlacore.replay import ReplayError, script
from hlacore.replay.diff import compare

from support import ROBOT_FED, Federate, running_rtig, share_robot_location, tick_until, wait_for_log

CYCLES = 6
WALL_CLOCK_MEMBERS = ("t_action", "t_send", "t_cycle", "clock_offset", "clock_uncertainty")


@contextlib.contextmanager
def recording_gateway(kind: str, tmp_path: pathlib.Path, path: pathlib.Path) -> Iterator[str]:
    """A gateway of `kind` recording into `path`, which is complete once the block ends."""
    if kind == "in-process":
        with hlacore.Gateway(port=0, record=path) as gateway:
            yield gateway.address
    else:
        with running_rtig(tmp_path, "--record", str(path)) as server:
            yield server.address


def mcap_messages(path: pathlib.Path) -> list[tuple[str, int, dict[str, Any]]]:
    """(topic, sequence, JSON) of every message, read by the mcap library through the file's index."""
    with open(path, "rb") as f:
        reader = mcap.reader.make_reader(f, validate_crcs=True)
        return [(channel.topic, message.sequence, json.loads(message.data))
                for _, channel, message in reader.iter_messages(log_time_order=False)]


@pytest.mark.parametrize("kind", ["in-process", "rtig"])
def test_recording_holds_what_the_federates_did(kind: str, tmp_path: pathlib.Path) -> None:
    path = tmp_path / "run.mcap"
    updates = [(b"\x00\xffbinary", 1.5), (b"at two and a half", 2.5)]
    with recording_gateway(kind, tmp_path, path) as address:
        creator = rti.RTIAmbassador(address)
        creator.createFederationExecution("TestFed", ROBOT_FED)
        a, b = Federate(address, "alpha"), Federate(address, "beta")
        a.enable_time(1.0)
        b.enable_time(1.0)
        robot = a.rtia.getObjectClassHandle("robot")
        location = a.rtia.getAttributeHandle("location", robot)
        a.rtia.publishObjectClass(robot, [location])
        b.rtia.subscribeObjectClassAttributes(robot, [location])
        command = a.rtia.getInteractionClassHandle("command")
        name, value = (a.rtia.getParameterHandle(p, command) for p in ("name", "value"))
        a.rtia.publishInteractionClass(command)
        b.rtia.subscribeInteractionClass(command)
        obj = a.rtia.registerObjectInstance(robot, "r1")
        for data, stamp in updates:
            a.rtia.updateAttributeValues(obj, {location: data}, "tag", stamp)
        a.rtia.sendInteraction(command, {name: b"go", value: b"\x01\x02"}, b"\xfe", 2.0)
        for f in (a, b):
            f.rtia.timeAdvanceRequest(3.0)
        tick_until(lambda: len(a.amb.named("timeAdvanceGrant")) == 1 and len(b.amb.named("timeAdvanceGrant")) == 1,
                   a.rtia, b.rtia)
        assert len(b.amb.named("reflectAttributeValues")) == 2 and len(b.amb.named("receiveInteraction")) == 1
        a.rtia.deleteObjectInstance(obj, "bye")
        b.rtia.resignFederationExecution(rti.ResignAction.NoAction)
        a.rtia.resignFederationExecution(rti.ResignAction.NoAction)
        creator.destroyFederationExecution("TestFed")

    messages = mcap_messages(path)
    assert [seq for _, seq, _ in messages] == sorted(seq for _, seq, _ in messages)
    by_topic: dict[str, list[dict[str, Any]]] = {}
    for topic, _, data in messages:
        by_topic.setdefault(topic, []).append(data)
    created, *joins = by_topic["/TestFed/federation"]
    assert created["event"] == "created" and created["fed_text"] == pathlib.Path(ROBOT_FED).read_text()
    assert [(j["event"], j["federate"]) for j in joins] == [("joined", "alpha"), ("joined", "beta")]
    objects = by_topic["/TestFed/objects/robot"]
    assert [o["kind"] for o in objects] == ["register", "update", "update", "delete"]
    assert objects[0]["object"] == "r1" and objects[0]["federate"] == "alpha"
    assert [(base64.b64decode(o["attributes"]["location"]), o["time"]) for o in objects[1:3]] == updates
    assert all(o["tag"] == "tag" and o["order"] == "timestamp" for o in objects[1:3])
    assert objects[3]["order"] == "receive" and objects[3]["time"] is None
    (interaction,) = by_topic["/TestFed/interactions/command"]
    assert interaction["time"] == 2.0 and interaction["tag"] == {"base64": base64.b64encode(b"\xfe").decode()}
    assert {k: base64.b64decode(v) for k, v in interaction["parameters"].items()} == {"name": b"go", "value": b"\x01\x02"}
    grants = by_topic["/TestFed/hlacore/grants"]
    assert sorted((g["federate"], g["time"]) for g in grants) == [("alpha", 3.0), ("beta", 3.0)]
    requests = [(r["federate"], r["request"]) for r in by_topic["/TestFed/hlacore/requests"]]
    assert requests.count(("alpha", "TimeAdvance")) == 1 and ("beta", "ResignFederation") in requests
    callbacks = {(c["federate"], c["callback"]) for c in by_topic["/TestFed/hlacore/callbacks"]}
    assert {("alpha", "TimeRegulationEnabled"), ("beta", "DiscoverObject"), ("alpha", "StartRegistration")} <= callbacks

    # hlacore's own reader yields the same events, in the same order.
    events = list(read(path))
    assert [(f"/{e.federation}/{e.topic}", e.sequence) for e in events] == [(t, s) for t, s, _ in messages]
    assert [e.values()["location"] for e in events if e.kind == "update"] == [u[0] for u in updates]


def test_a_recording_of_many_chunks_keeps_every_update_in_order(tmp_path: pathlib.Path) -> None:
    """Many more chunks than the file thread may have waiting (mcap.hpp's kQueuedChunks), into a pipe read
    slowly so that they do wait, then one value larger than a chunk: every update is in the file once, in
    the order sent, each chunk's CRC right."""
    path, pipe = tmp_path / "long.mcap", tmp_path / "pipe"
    os.mkfifo(pipe)

    def read_slowly() -> None:
        with open(pipe, "rb") as source, open(path, "wb") as out:
            while block := source.read(1 << 16):
                out.write(block)
                time.sleep(0.005)

    reader = threading.Thread(target=read_slowly, daemon=True)
    reader.start()
    values = [i.to_bytes(4, "big") * 1024 for i in range(3000)] + [b"\xab" * (3 << 20)]  # 4 KiB each, then 3 MiB
    with recording_gateway("rtig", tmp_path, pipe) as address:
        creator = rti.RTIAmbassador(address)
        creator.createFederationExecution("TestFed", ROBOT_FED)
        a, b = Federate(address, "alpha"), Federate(address, "beta")
        robot, location = share_robot_location(a, b)
        obj = a.rtia.registerObjectInstance(robot, "r1")
        for value in values:
            a.rtia.updateAttributeValues(obj, {location: value}, "")
        tick_until(lambda: len(b.amb.named("reflectAttributeValues")) == len(values), a.rtia, b.rtia)
        for f in (a, b):
            f.rtia.resignFederationExecution(rti.ResignAction.DeleteObjects)
        creator.destroyFederationExecution("TestFed")
    reader.join(timeout=60)
    assert not reader.is_alive()

    with open(path, "rb") as f:
        summary = mcap.reader.make_reader(f).get_summary()
    assert summary is not None and len(summary.chunk_indexes) > 12  # each 4 KiB value is 5.5 KiB of JSON
    updates = [data for topic, _, data in mcap_messages(path) if topic == "/TestFed/objects/robot"
               and data["kind"] == "update"]
    assert [base64.b64decode(u["attributes"]["location"]) for u in updates] == values


def run_main_job(tmp_path: pathlib.Path, name: str, rtig: bool, **options: Any) -> Experiment:
    """The main job for CYCLES cycles, recorded into tmp_path/<name>.mcap by the gateway of the kind asked."""
    record = tmp_path / f"{name}.mcap"
    out = tmp_path / name
    if not rtig:
        return run_experiment(ExperimentOptions(out=out, cycles=CYCLES, record=record, **options), lambda _: None)
    with running_rtig(tmp_path, "--record", str(record)) as server:
        return run_experiment(ExperimentOptions(out=out, cycles=CYCLES, rtig=server.address, **options),
                              lambda _: None)


def comparable(experiment: Experiment) -> tuple[list[Any], list[Any]]:
    """The testbench's verdicts (without the wall-clock mark of each check) and reflections."""
    verdicts = [dataclasses.replace(v, observed=0.0) for v in experiment.result.verdicts]
    return verdicts, experiment.result.reflections


@pytest.fixture(scope="module", params=["in-process", "rtig"])
def live_run(request: pytest.FixtureRequest, tmp_path_factory: pytest.TempPathFactory) -> tuple[Experiment, pathlib.Path, bool]:
    """The main job, recorded: the experiment, the recording, and whether rtig recorded it."""
    tmp_path = tmp_path_factory.mktemp(f"live-{request.param}")
    rtig = request.param == "rtig"
    experiment = run_main_job(tmp_path, "live", rtig)
    assert experiment.result.passed and experiment.robot_status == 0
    return experiment, tmp_path / "live.mcap", rtig


def test_main_job_recording_has_one_record_per_update_and_grant(live_run: tuple[Experiment, pathlib.Path, bool]) -> None:
    experiment, path, _ = live_run
    messages = mcap_messages(path)
    updates = [d for t, _, d in messages if t == "/TestFed/objects/robot" and d["kind"] == "update"]
    assert [decode_report(base64.b64decode(u["attributes"]["location"])).cycle for u in updates] == list(range(CYCLES))
    # Every reflection the testbench got is one recorded update, with its timestamp and bytes.
    assert [(u["time"], base64.b64decode(u["attributes"]["location"])) for u in updates] == \
        [(stamp, values[0][1]) for stamp, values in experiment.result.reflections]
    grants = [(d["federate"], d["time"]) for t, _, d in messages if t == "/TestFed/hlacore/grants"]
    advances = [(d["federate"], d["fields"]["time"]) for t, _, d in messages
                if t == "/TestFed/hlacore/requests" and d["request"] == "TimeAdvance"]
    assert sorted(grants) == sorted(advances)  # each request granted once, at its time
    assert sum(1 for federate, _ in grants if federate == "robot") == CYCLES


def test_replayed_robot_gives_the_testbench_the_same_run(live_run: tuple[Experiment, pathlib.Path, bool],
                                                          tmp_path: pathlib.Path) -> None:
    live, recording, rtig = live_run
    replay = run_main_job(tmp_path, "replay", rtig, replay_robot=recording)
    assert replay.robot_status == 0, (replay.out / "robot.log").read_text()
    assert "steps replayed" in (replay.out / "robot.log").read_text()
    assert comparable(replay) == comparable(live)
    # Recorded again, the replayed run is the live run: the same updates and grants in every stream.
    result = compare(recording, tmp_path / "replay.mcap")
    assert result.same, result.first.describe() if result.first else ""
    assert result.compared > 2 * CYCLES


def test_diff_names_the_cycle_where_the_checker_first_failed(live_run: tuple[Experiment, pathlib.Path, bool],
                                                             tmp_path: pathlib.Path) -> None:
    live, recording, rtig = live_run
    miscalibrated = run_main_job(tmp_path, "miscalibrated", rtig, miscalibrated=True)
    first_failure = miscalibrated.result.value_errors[0].cycle
    other = tmp_path / "miscalibrated.mcap"

    def diff(a: pathlib.Path, b: pathlib.Path, ignore: tuple[str, ...]) -> subprocess.CompletedProcess[str]:
        return subprocess.run([sys.executable, "-m", "hlacore.replay", "diff", str(a), str(b),
                               *("--ignore=" + m for m in ignore)], capture_output=True, text=True, timeout=60)

    same = diff(recording, recording, ())
    assert same.returncode == 0 and "the recordings agree" in same.stdout
    # What the checker compares (the cells), without the wall-clock marks and the pose: the failing cycle.
    checked = WALL_CLOCK_MEMBERS + ("pose", "front")
    run = diff(recording, other, checked)
    assert run.returncode == 1, run.stderr
    assert f'"cycle":{first_failure},' in run.stdout and "first divergence at federation time" in run.stdout
    result = compare(recording, other, checked)
    assert result.first is not None and result.first.what == "attribute 'location'"
    assert result.first.a is not None and result.first.b is not None
    reports = [decode_report(e.values()["location"]) for e in (result.first.a, result.first.b)]
    assert {r.cycle for r in reports} == {first_failure} and reports[0].cell != reports[1].cell
    assert result.first.time == miscalibrated.result.value_errors[0].timestamp
    # With the pose compared too, the drift shows earlier: where the miscalibrated pose first departs.
    drift = compare(recording, other, WALL_CLOCK_MEMBERS)
    assert drift.first is not None and drift.first.a is not None and drift.first.b is not None
    early = [decode_report(e.values()["location"]) for e in (drift.first.a, drift.first.b)]
    assert early[0].cycle == early[1].cycle <= first_failure and early[0].pose != early[1].pose


def test_damaged_recordings_are_refused_with_the_offset(live_run: tuple[Experiment, pathlib.Path, bool],
                                                         tmp_path: pathlib.Path) -> None:
    _, recording, _ = live_run
    data = recording.read_bytes()
    cut = tmp_path / "cut.mcap"
    cut.write_bytes(data[: len(data) // 2])
    with pytest.raises(RecordingError, match=r"cut short.*at byte offset \d+"):
        list(read(cut))
    flipped = bytearray(data)
    flipped[len(data) // 3] ^= 0xFF  # inside the data section: a chunk's CRC no longer matches
    damaged = tmp_path / "flipped.mcap"
    damaged.write_bytes(bytes(flipped))
    with pytest.raises(RecordingError, match=r"damaged chunk record: crc validation failed.*\(at byte offset \d+\)"):
        list(read(damaged))
    not_mcap = tmp_path / "text.mcap"
    not_mcap.write_text("hello")
    with pytest.raises(RecordingError, match="not an MCAP file"):
        list(read(not_mcap))
    for bad in (cut, damaged):
        run = subprocess.run([sys.executable, "-m", "hlacore.replay", "diff", str(recording), str(bad)],
                             capture_output=True, text=True, timeout=60)
        assert run.returncode == 2 and "byte offset" in run.stderr and "Traceback" not in run.stderr
        run = subprocess.run([sys.executable, "-m", "hlacore.replay", str(bad), "--as", "robot"],
                             capture_output=True, text=True, timeout=60)
        assert run.returncode == 2 and "byte offset" in run.stderr and "Traceback" not in run.stderr


def test_recorder_federate_records_what_rtig_records(tmp_path: pathlib.Path) -> None:
    by_gateway, by_recorder = tmp_path / "rtig.mcap", tmp_path / "recorder.mcap"
    fom = str(resources.files("hlacore") / "foms" / "robot.fed")
    with running_rtig(tmp_path, "--record", str(by_gateway)) as server:
        creator = rti.RTIAmbassador(server.address)
        creator.createFederationExecution("TestFed", fom)
        with Child([sys.executable, "-m", "hlacore.record", server.address, "TestFed", str(by_recorder),
                    "--until-alone"]) as recorder:
            assert recorder.read_line(timeout=30).startswith("recording TestFed into")
            experiment = run_experiment(ExperimentOptions(out=tmp_path / "run", cycles=CYCLES, rtig=server.address),
                                        lambda _: None)
            assert experiment.result.passed
            assert recorder.wait(timeout=30) == 0, recorder.stderr()
            assert recorder.read_line(timeout=5).startswith("recorded ")
        creator.destroyFederationExecution("TestFed")

    gateway_events, recorder_events = list(read(by_gateway)), list(read(by_recorder))

    def content(events: list[Any]) -> list[tuple[str, str, str, int]]:
        return [(e.federation, e.topic, json.dumps(e.data, sort_keys=True), e.wall_ns) for e in events]

    joined = next(i for i, e in enumerate(gateway_events) if e.kind == "joined" and e.federate == "hlacore-recorder")
    resigned = next(i for i, e in enumerate(gateway_events)
                    if e.federate == "hlacore-recorder" and e.message == "ResignFederation")
    # The recorder's file starts with the FOM and the federates joined when it began (itself), then has every
    # event the gateway's file has until the recorder stopped.
    assert [e.kind for e in recorder_events[:2]] == ["created", "joined"]
    assert recorder_events[0].data == gateway_events[0].data
    assert content(recorder_events[2:]) == content(gateway_events[joined + 1:resigned])
    assert sum(1 for e in recorder_events if e.kind == "update") == CYCLES
    assert compare(by_gateway, by_recorder).same


def test_replay_script_skips_refused_requests_and_refuses_what_it_cannot_replay() -> None:
    def event(sequence: int, topic: str, **data: Any) -> Event:
        return Event(sequence, sequence, "F", topic, data, 0)

    recorded = [
        event(1, "federation", event="created", fed_name="robot.fed", fed_text="(FED)"),
        event(2, "federation", event="joined", federate="robot", handle=1),
        event(3, "hlacore/requests", federate="robot", request="ResignFederation", fields={"request": 5, "action": 4}),
        event(4, "hlacore/refusals", federate="robot", answer="Reply", fields={"request": 5, "error": 1, "message": "no"}),
        event(5, "hlacore/grants", federate="robot", time=1.0),
        event(6, "hlacore/requests", federate="robot", request="ResignFederation", fields={"request": 6, "action": 3}),
    ]
    steps = script(recorded, "robot").steps
    assert [(s.event.sequence, s.waits) for s in steps] == [(6, {"TimeAdvanceGrant": 1})]
    unsupported = recorded[:2] + [event(3, "hlacore/requests", federate="robot", request="UnconditionalDivestiture",
                                        fields={"object": 1, "attributes": [1]})]
    with pytest.raises(ReplayError, match="UnconditionalDivestiture request .* replay does not support yet"):
        script(unsupported, "robot")
    with pytest.raises(ReplayError, match="no federate named 'nobody'.*'robot'"):
        script(recorded, "nobody")


def test_a_full_disk_stops_the_recording_not_the_gateway(tmp_path: pathlib.Path) -> None:
    with running_rtig(tmp_path, "--record", "/dev/full") as server:
        creator = rti.RTIAmbassador(server.address)
        creator.createFederationExecution("TestFed", ROBOT_FED)
        a, b = Federate(server.address, "alpha"), Federate(server.address, "beta")
        robot, location = share_robot_location(a, b)
        obj = a.rtia.registerObjectInstance(robot, "r1")
        for i in range(3):
            a.rtia.updateAttributeValues(obj, {location: b"before %d" % i}, "")
        # The recorder writes out within half a second, and /dev/full refuses.
        wait_for_log(server, r"recording into /dev/full stopped: cannot write the recording '/dev/full': "
                             r"No space left on device")
        for i in range(3):
            a.rtia.updateAttributeValues(obj, {location: b"after %d" % i}, "")
        tick_until(lambda: len(b.amb.named("reflectAttributeValues")) == 6, a.rtia, b.rtia)
        assert [args[1][location] for args in b.amb.named("reflectAttributeValues")][3:] == [b"after 0", b"after 1",
                                                                                               b"after 2"]
        for f in (a, b):
            f.rtia.resignFederationExecution(rti.ResignAction.DeleteObjects)
        creator.destroyFederationExecution("TestFed")


def test_several_federates_replayed_at_the_recorded_pace(tmp_path: pathlib.Path) -> None:
    """--as twice (one thread each) and --speed: an untimed publisher's updates, 0.3 s apart when recorded,
    reach a live subscriber in the same order with the same values, about 0.15 s apart at speed 2."""
    recording = tmp_path / "untimed.mcap"
    sent = [b"first", b"second", b"third"]
    with recording_gateway("in-process", tmp_path, recording) as address:
        creator = rti.RTIAmbassador(address)
        creator.createFederationExecution("TestFed", ROBOT_FED)
        pub, sub = Federate(address, "pub"), Federate(address, "sub")
        robot, location = share_robot_location(pub, sub)
        tick_until(lambda: bool(pub.amb.named("startRegistrationForObjectClass")), pub.rtia, sub.rtia)
        obj = pub.rtia.registerObjectInstance(robot, "r1")
        for value in sent:
            pub.rtia.updateAttributeValues(obj, {location: value}, "")
            time.sleep(0.3)
        tick_until(lambda: len(sub.amb.named("reflectAttributeValues")) == 3, pub.rtia, sub.rtia)
        for f in (sub, pub):
            f.rtia.resignFederationExecution(rti.ResignAction.DeleteObjects)
        creator.destroyFederationExecution("TestFed")

    with hlacore.Gateway(port=0) as gateway:
        creator = rti.RTIAmbassador(gateway.address)
        creator.createFederationExecution("TestFed", ROBOT_FED)
        watcher = Federate(gateway.address, "watcher")
        robot = watcher.rtia.getObjectClassHandle("robot")
        location = watcher.rtia.getAttributeHandle("location", robot)
        watcher.rtia.subscribeObjectClassAttributes(robot, [location])
        arrivals: list[tuple[float, bytes]] = []
        with Child([sys.executable, "-m", "hlacore.replay", str(recording), "--as", "pub", "--as", "sub",
                    "--rtig", gateway.address, "--speed", "2"]) as replay:
            deadline = time.monotonic() + 30
            while len(arrivals) < 3 and time.monotonic() < deadline:
                watcher.rtia.tick(0.01, 0.05)
                for args in watcher.amb.named("reflectAttributeValues")[len(arrivals):]:
                    arrivals.append((time.monotonic(), args[1][location]))
            assert replay.wait(timeout=30) == 0, replay.stderr()
            # pub: publish, register, three updates, resign; sub: subscribe, resign.
            assert sorted(replay.read_line(5) for _ in range(2)) == ["replay: 'pub': 6 steps replayed",
                                                                     "replay: 'sub': 2 steps replayed"]
        assert [value for _, value in arrivals] == sent
        gaps = [later - earlier for (earlier, _), (later, _) in zip(arrivals, arrivals[1:])]
        assert all(gap > 0.1 for gap in gaps), gaps  # 0.3 s recorded / 2; without --speed: milliseconds
        watcher.rtia.resignFederationExecution(rti.ResignAction.NoAction)
        creator.destroyFederationExecution("TestFed")
