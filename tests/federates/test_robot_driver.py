"""The robot driver package without an RTI: A*, commands, kinematics, the protocol and the pty device."""

from __future__ import annotations

import itertools
import sys

import pytest

from hlacore.federates.robot_driver import (
    CALIBRATED,
    CELL,
    MISCALIBRATED,
    PAPER_5X5,
    SCENARIO_6X6,
    Body,
    DeviceServer,
    ProtocolError,
    Scenario,
    TxRxDriver,
    astar,
    commands_for_move,
    mission,
    spawn_simulated_device,
)
from hlacore.federates.robot_driver.driver import SerialTransport
from hlacore.federates.robot_driver.protocol import encode_request, format_reply, parse_reply

from support import PAPER_PATH


def drive_mission(body: Body, cells: list[tuple[int, int]]) -> list[tuple[int, int]]:
    """The cells a body measures when the controller drives it along ``cells`` (cycle 0: no move)."""
    heading, measured = 1, [body.cell]
    for here, there in zip(cells, cells[1:]):
        commands, heading = commands_for_move(heading, here, there)
        for name in commands:
            {"goFront": lambda: body.drive(1, 2.0), "goBack": lambda: body.drive(-1, 2.0),
             "turnLeft": lambda: body.turn(1, 1.0), "turnRight": lambda: body.turn(-1, 1.0)}[name]()
        measured.append(body.cell)
    return measured


def test_astar_on_the_paper_grid_is_the_papers_path():
    assert astar(PAPER_5X5, (0, 0), (4, 4)) == PAPER_PATH


def test_mission_starts_with_the_path_then_patrols_back():
    cells = list(itertools.islice(mission(PAPER_5X5), 29))
    assert cells[:15] == PAPER_PATH
    assert cells[14:] == PAPER_PATH[::-1]


def test_scenario_text_round_trip_and_errors():
    assert Scenario.parse(PAPER_5X5.to_text()) == PAPER_5X5
    assert Scenario.parse(SCENARIO_6X6.to_text()) == SCENARIO_6X6
    with pytest.raises(ValueError, match="no 'grid"):
        Scenario.parse("start 0 0\n")
    with pytest.raises(ValueError, match="is a wall"):
        Scenario.parse("grid 3x3\nwalls (0,0)\nstart 0 0\n")
    with pytest.raises(ValueError, match="cannot read"):
        Scenario.parse("grid 3x3\nfly 1\n")


def test_commands_for_each_relative_direction():
    assert commands_for_move(1, (0, 0), (0, 1)) == (["goFront"], 1)
    assert commands_for_move(1, (0, 3), (1, 3)) == (["turnRight", "goFront"], 0)
    assert commands_for_move(0, (2, 0), (2, 1)) == (["turnLeft", "goFront"], 1)
    assert commands_for_move(1, (0, 1), (0, 0)) == (["goBack"], 1)
    assert commands_for_move(1, (0, 1), (0, 1)) == ([], 1)
    with pytest.raises(ValueError):
        commands_for_move(1, (0, 0), (1, 1))


def test_calibrated_body_follows_the_path_and_miscalibrated_drifts():
    assert drive_mission(Body(PAPER_5X5, CALIBRATED), PAPER_PATH) == PAPER_PATH
    drifted = drive_mission(Body(PAPER_5X5, MISCALIBRATED), PAPER_PATH)
    assert drifted[:4] == PAPER_PATH[:4]
    assert drifted[4] != PAPER_PATH[4]


def test_a_wall_stops_the_body():
    body = Body(PAPER_5X5, CALIBRATED, heading_deg=0.0)  # facing the wall at (1, 0)
    assert body.range(0.0) == pytest.approx(CELL / 2, abs=0.011)
    body.drive(1, 2.0)
    assert body.cell == (0, 0)
    assert body.x < CELL / 2


def test_protocol_lines():
    assert encode_request("goFront") == b"goFront\n"
    with pytest.raises(ValueError):
        encode_request("fly")
    assert parse_reply(format_reply((1.0, 2.5))[:-1]).fields == (1.0, 2.5)
    with pytest.raises(ProtocolError, match="device error: nope"):
        parse_reply(format_reply(error="nope")[:-1])
    with pytest.raises(ProtocolError):
        parse_reply(b"hello")


def test_device_server_sleeps_the_scaled_simulated_time():
    slept: list[float] = []
    server = DeviceServer(Body(PAPER_5X5), time_scale=0.5, sleep=slept.append)
    assert parse_reply(server.handle(b"goFront")[:-1]).fields == (2.0,)
    assert parse_reply(server.handle(b"turnLeft")[:-1]).fields == (1.0,)
    assert slept == [1.0, 0.5]
    assert server.handle(b"jump").startswith(b"err ")


def test_driver_talks_to_the_simulated_device_over_a_pty():
    with spawn_simulated_device(PAPER_5X5, CALIBRATED, time_scale=0.0) as device:
        assert device.path.startswith("/dev/")
        driver = TxRxDriver.open(device.path, transport="pty", timeout=20.0)
        try:
            assert driver.read_position() == (0.0, 0.0, 90.0)
            assert driver.go_front() == 2.0
            x, y, heading = driver.read_position()
            assert (round(x / CELL), round(y / CELL)) == (0, 1)
            assert driver.turn_right() == 1.0
            assert driver.read_position()[2] == pytest.approx(0.0, abs=1e-9)
            front, left, right = driver.read_sensors()
            assert front == pytest.approx(0.5 * CELL, abs=0.011)  # the wall (1, 1) ahead
            assert left == pytest.approx(3.5 * CELL, abs=0.011)  # (0, 2) .. (0, 4), then the border
            assert right == pytest.approx(1.5 * CELL, abs=0.011)  # (0, 0), then the border
            assert driver.go_back() == 2.0
            assert driver.turn_left() == 1.0
        finally:
            driver.close()
    assert device.process.returncode is not None


def test_serial_transport_without_pyserial_says_what_to_install(monkeypatch: pytest.MonkeyPatch) -> None:
    monkeypatch.setitem(sys.modules, "serial", None)  # as if pyserial were not installed
    with pytest.raises(RuntimeError, match="pip install pyserial"):
        SerialTransport("/dev/null")
