"""Paper 2 §6.2's parts without an RTI or ROS: the device's drive command and defective wheel, the avoid
controllers, the executed-velocity estimate, the reference model and the path metrics."""

from __future__ import annotations

import math

import pytest

from hlacore.experiments.mirror import metrics
from hlacore.experiments.mirror.reference import reference_trajectory
from hlacore.experiments.mirror.scenario import BOX_SIZE, BOX_X, HALF
from hlacore.federates.robot_driver import Body, Calibration, DeviceServer, Scenario, TxRxDriver, spawn_simulated_device
from hlacore.federates.robot_driver.avoid import AvoidParams, CorrectedAvoid, OpenLoopAvoid
from hlacore.federates.robot_driver.mirrored import MirroredRobotFederate, executed_velocity
from hlacore.federates.robot_driver.protocol import encode_drive, parse_drive, parse_reply

FLOOR = Scenario(1, 1)
DEFECTIVE = Calibration(defective_wheel=0.05)


def floor_body(calibration: Calibration = Calibration()) -> Body:
    return Body(FLOOR, calibration, heading_deg=0.0, open_floor=True)


def test_drive_request_round_trip_and_bad_arguments() -> None:
    assert encode_drive(0.2, -0.5, 0.5) == b"drive 0.2 -0.5 0.5\n"
    assert parse_drive(["0.2", "-0.5", "0.5"]) == (0.2, -0.5, 0.5)
    for words, message in ((["1", "2"], "takes linear, angular and seconds"), (["a", "0", "1"], "not numbers"),
                           (["nan", "0", "1"], "finite"), (["0", "0", "-1"], "duration"),
                           (["0", "0", "61"], "duration")):
        with pytest.raises(ValueError, match=message):
            parse_drive(words)
    with pytest.raises(ValueError, match="finite"):
        encode_drive(math.inf, 0.0, 1.0)


def test_device_server_drive_moves_and_answers_errors_without_moving() -> None:
    body = floor_body()
    server = DeviceServer(body)
    assert parse_reply(server.handle(b"drive 0.2 0 2")[:-1]).fields == (2.0,)
    assert (body.x, body.y, body.heading) == (pytest.approx(0.4), pytest.approx(0.0), pytest.approx(0.0))
    for bad in (b"drive", b"drive 1 2 x", b"drive 1 2 3 4", b"drive inf 0 1"):
        assert server.handle(bad).startswith(b"err drive"), bad
    assert body.x == pytest.approx(0.4)
    assert server.handle(b"goFront").startswith(b"ok")  # the unit moves still work on the open floor


def test_open_floor_never_blocks_and_the_grid_still_does() -> None:
    body = floor_body()
    body.drive_velocity(-0.2, 0.0, 5.0)  # backwards off the one-cell "grid"
    assert body.x == pytest.approx(-1.0)
    walled = Body(FLOOR, heading_deg=0.0)
    walled.drive_velocity(-0.2, 0.0, 5.0)
    assert walled.x > -0.17  # stopped at the border of the cell


def test_defective_wheel_curves_right_and_shortens_turns() -> None:
    straight, defective = floor_body(), floor_body(DEFECTIVE)
    straight.drive_velocity(0.2, 0.0, 5.0)
    defective.drive_velocity(0.2, 0.0, 5.0)
    assert straight.y == pytest.approx(0.0) and straight.heading == pytest.approx(0.0)
    # the right wheel at 95 %: yaw rate 0.2 * 0.05 / 2 ... = -(0.01 / 0.15) rad/s, for 5 s
    assert defective.heading == pytest.approx(-0.01 / 0.15 * 5.0, rel=1e-6)
    assert defective.y < -0.05
    turner = floor_body(DEFECTIVE)
    turner.turn(+1, 1.0)
    assert math.degrees(turner.heading) == pytest.approx(90 * 0.975, rel=1e-6)
    nominal = floor_body()
    nominal.turn(+1, 1.0)
    assert math.degrees(nominal.heading) == pytest.approx(90.0)


def test_drive_and_defective_wheel_over_the_pty() -> None:
    with spawn_simulated_device(FLOOR, DEFECTIVE, heading_deg=0.0, open_floor=True) as device:
        driver = TxRxDriver.open(device.path, transport="pty", timeout=20.0)
        try:
            assert driver.drive(0.2, 0.0, 5.0) == 5.0
            x, y, heading = driver.read_position()
            assert 0.9 < x < 0.975 and y < -0.05 and heading < -10.0  # 0.975 m travelled on an arc
            with pytest.raises(ValueError, match="duration"):
                driver.drive(0.2, 0.0, -1.0)  # refused before anything is sent
            assert driver.read_position() == (x, y, heading)
        finally:
            driver.close()


def test_open_loop_controller_plays_the_side_step_then_goes_on() -> None:
    p = AvoidParams()
    control = OpenLoopAvoid(p)
    assert control.decide((0.0, 0.0, 0.0), 1.5) == (p.speed, 0.0) and control.mode == "forward"
    plan, modes = [], []
    for k in range(14):  # the pose is ignored; the range only matters before the manoeuvre
        plan.append(control.decide((9.0, 9.0, 9.0), 0.3 if k == 0 else 2.0))
        modes.append(control.mode)
    assert modes == ["turn-left"] * 4 + ["sidestep"] * 6 + ["turn-right"] * 4 and control.avoidances == 1
    assert sum(w * p.cycle for v, w in plan[:4]) == pytest.approx(math.pi / 2)
    assert sum(w * p.cycle for v, w in plan) == pytest.approx(0.0, abs=1e-12)  # left then right
    assert sum(v * p.cycle for v, w in plan) == pytest.approx(p.sidestep)
    assert control.decide((0.0, 0.0, 0.0), 2.0) == (p.speed, 0.0) and control.mode == "forward"
    assert control.decide((0.0, 0.0, 0.0), 0.3) == (0.0, pytest.approx(math.pi / 4))  # detected again


def run_closed(control: OpenLoopAvoid | CorrectedAvoid, body: Body, cycles: int) -> list[tuple[float, float]]:
    """Drive ``body`` with ``control`` past a box 1.6 m ahead (front range from the geometry, centre line)."""
    path = []
    for _ in range(cycles):
        ahead = BOX_X - BOX_SIZE / 2 - (body.x + HALF)
        front = ahead if abs(body.y) < BOX_SIZE / 2 + 0.05 and ahead > 0 else 2.0
        body.drive_velocity(*control.decide((body.x, body.y, body.heading), front), control.params.cycle)
        path.append((body.x, body.y))
    return path


def test_corrected_control_keeps_its_lines_with_a_defective_wheel() -> None:
    open_path = run_closed(OpenLoopAvoid(), floor_body(DEFECTIVE), 40)
    corrected = CorrectedAvoid()
    closed_path = run_closed(corrected, floor_body(DEFECTIVE), 40)
    ideal_path = run_closed(OpenLoopAvoid(), floor_body(), 40)
    assert metrics.deviation(open_path, ideal_path) > 0.5
    assert metrics.deviation(closed_path, ideal_path) < 0.05
    assert corrected.avoidances == 1 and closed_path[-1][1] == pytest.approx(0.6, abs=0.05)


def test_executed_velocity_recovers_the_arc() -> None:
    for v, w in ((0.2, 0.0), (0.2, 0.3), (0.0, -0.7), (-0.1, 0.2)):
        body = floor_body()
        before = (body.x, body.y, body.heading)
        body.drive_velocity(v, w, 0.5)
        assert executed_velocity(before, (body.x, body.y, body.heading), 0.5) == (
            pytest.approx(v, abs=1e-5), pytest.approx(w, abs=1e-9))  # the body integrates chords


def test_mirrored_federate_rejects_bad_options() -> None:
    with pytest.raises(ValueError, match="mirror_from"):
        MirroredRobotFederate(None, OpenLoopAvoid(), mirror_from="dreams")  # type: ignore[arg-type]
    with pytest.raises(ValueError, match="lookahead"):
        MirroredRobotFederate(None, OpenLoopAvoid(), cycle=0.5, lookahead=0.0)  # type: ignore[arg-type]


def test_reference_avoids_the_box_and_keeps_the_new_lane() -> None:
    for corrected in (False, True):
        ref = reference_trajectory(40, corrected)
        assert [t for t, _ in ref][:3] == [0.5, 1.0, 1.5] and len(ref) == 41
        path = [(p[0], p[1]) for _, p in ref]
        assert metrics.box_clearance(path, (BOX_X, 0.0), BOX_SIZE) > HALF * math.sqrt(2)
        assert path[-1][0] > BOX_X + 0.5 and path[-1][1] == pytest.approx(0.6, abs=1e-3)


def test_path_metrics() -> None:
    line = [(0.0, 0.0), (2.0, 0.0)]
    assert metrics.deviation([(1.0, 0.5), (0.5, 0.0)], line) == pytest.approx(0.5)
    assert metrics.deviation([(0.0, 0.0), (1.0, 0.0)], line) == 0.0  # shorter, on the line
    assert metrics.hausdorff([(0.0, 0.0), (1.0, 0.0)], line) == pytest.approx(1.0)
    assert metrics.box_clearance([(3.0, 0.0)], (1.0, 0.0), 2.0) == pytest.approx(1.0)
    assert metrics.box_clearance([(1.0, 0.5)], (1.0, 0.0), 2.0) == pytest.approx(-0.5)
    with pytest.raises(ValueError):
        metrics.deviation([], line)


def _summary(real_strays: float, clearance: float, *, stalls: int = 0, ros_passed: bool = True,
             mirror_from: str = "commands", mirror_vs_real: float = 0.0) -> dict:
    from hlacore.experiments.mirror.scenario import CLEAR

    robot = {"vs_reference": real_strays, "box_clearance": clearance, "touched_box": clearance <= CLEAR}
    return {"real": robot, "rosbot": {"passed_box": ros_passed}, "mirror": {"vs_real": mirror_vs_real},
            "stall_steps": {"mirror": stalls, "rosbot": 0}, "mirror_from": mirror_from}


def test_the_commands_verdict_names_the_finding_and_its_exit_follows_the_set_up_checks() -> None:
    from hlacore.experiments.mirror.__main__ import checks, verdict

    defective = _summary(2.282, -0.157)
    assert all(checks(defective).values())  # a diverging real robot is the finding, not a failed run
    assert verdict(defective) == ("verdict: the real robot departs from the reference model by 2.282 m; "
                                  "it drove into the box (its centre 0.157 m inside)")
    assert verdict(_summary(0.0, 0.4)).startswith("verdict: the real robot behaves like the reference model")
    assert "touched the box" in verdict(_summary(0.0, 0.1))
    assert not checks(_summary(0.0, 0.4, stalls=3))["the lockstep never stalled"]
    assert not checks(_summary(0.0, 0.4, ros_passed=False))["the ROS robot drove around its box"]
    assert not all(checks(_summary(0.7, 0.2, mirror_from="odometry", mirror_vs_real=0.3)).values())
