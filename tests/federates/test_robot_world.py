"""The robot world without HLA: the .world reader, kinematics, stall, watchdog, ranger, odometry, the
step grid, determinism, and the data behind the pictures."""

from __future__ import annotations

import math
import pathlib
import re
import struct
import sys
import zlib

import pytest

from hlacore.federates.robot_world import (
    GridError,
    World,
    WorldFileError,
    load_world,
    read_world,
    snapshot,
    steps_at,
    trajectories,
)
from hlacore.federates.robot_world import render
from hlacore.federates.robot_world.world import Pose

CORRIDOR = """
# a robot facing a wall 2 m ahead, and a second one behind it
define sonar ranger ( sensor( pose [0 0 0 0] range [0.02 3.0] fov 30 samples 3 ) )
define bot position ( size [0.4 0.4 0.4] drive "diff" sonar(pose [0.2 0 0 0]) )
bot( pose [ 0 0 0 0 ] name "r0" color "blue" )
bot( pose [ -2 0 0 0 ] name "r1" )
model( pose [ 2.3 0 0 0 ] size [ 0.2 4 0.5 ] color "gray30" )
"""


def corridor(**options: object) -> World:
    return World(load_world(CORRIDOR), **options)  # type: ignore[arg-type]


# ---- the .world reader ----


def test_world_file_subset_with_includes_defines_units_and_ignored_entities(tmp_path: pathlib.Path) -> None:
    (tmp_path / "robots.inc").write_text(
        'define laser ranger ( sensor( range [ 0.1 30.0 ] fov 270.25 samples 1081 noise [0.01 0 0] ) )\n'
        'define erratic position ( size [0.35 0.35 0.25] origin [-0.05 0 0 0] drive "diff" laser(pose [0.05 0 0 0]) )\n'
    )
    (tmp_path / "w.world").write_text(
        'include "robots.inc"\n'
        "interval_sim 50  # ms\n"
        "resolution 0.02\n"
        "speedup -1\n"
        "window ( size [ 745 448 ] rotate [ 0 -1.56 ] scale 28.8 )\n"
        'floorplan ( name "room" size [10 8 0.5] pose [0 0 0 0] boundary 1 )\n'
        'erratic( pose [ 1 2 0 90 ] name "era" color "blue" velocity_bounds [-0.5 0.5 0 0 0 0 -45 45] )\n'
        'erratic( pose [ -1 -2 0 180 ] )\n'
        'model( pose [ 3 0 0 0 ] size [ 0.5 0.5 0.5 ] ranger_return -1 )\n'
        'model( pose [ 4 0 0 0 ] size [ 0.5 0.5 0.5 ] obstacle_return 0 )\n'
    )
    spec = read_world(tmp_path / "w.world")
    assert spec.interval_sim == pytest.approx(0.05)
    assert [r.name for r in spec.robots] == ["era", "robot_1"]
    era = spec.robots[0]
    assert era.pose == pytest.approx((1.0, 2.0, math.pi / 2))
    assert era.size == pytest.approx((0.35, 0.35)) and era.origin == pytest.approx((-0.05, 0.0))
    assert (era.color, era.max_linear, era.max_angular) == ("blue", 0.5, pytest.approx(math.pi / 4))
    (sensor,) = era.sensors
    assert (sensor.samples, sensor.range_min, sensor.range_max) == (1081, 0.1, 30.0)
    assert sensor.fov == pytest.approx(math.radians(270.25)) and sensor.noise == 0.01
    assert sensor.pose == pytest.approx((0.05, 0.0, 0.0))
    # the boundary box is 4 walls; then the two models with their returns
    assert len(spec.blocks) == 6
    assert [(b.obstacle, b.visible) for b in spec.blocks[4:]] == [(True, False), (False, True)]


@pytest.mark.parametrize(
    "text, message",
    [
        ("bot( pose [0 0 0 0]", "<string>:1: unclosed '(' of 'bot'"),
        ("model( pose [0 0 0 0 )", "<string>:1: unexpected ')' in a tuple"),
        ('\n\ninclude "missing.inc"', "<string>:3: cannot include 'missing.inc'"),
        ('position( name "a" )\nposition( name "a" )', "robot names are not unique: ['a']"),
    ],
)
def test_world_file_errors_name_the_line(text: str, message: str) -> None:
    with pytest.raises(WorldFileError) as info:
        load_world(text)
    assert message in str(info.value)


# ---- kinematics, stall, watchdog, grid ----


def test_diff_drive_follows_commands_and_clips_to_bounds() -> None:
    world = corridor(watchdog=None)
    world.command("r1", 0.5, 0.0)
    world.advance(100)
    assert world.robot("r1").pose.x == pytest.approx(-1.5)
    world.command("r1", 0.0, 10.0)  # clipped to pi/2 rad/s
    world.advance(100)
    assert world.robot("r1").pose.theta == pytest.approx(math.pi / 2)
    world.command("r1", 5.0, 0.0)  # clipped to 1 m/s, now heading +y
    world.advance(50)
    pose = world.robot("r1").pose
    assert (pose.x, pose.y) == (pytest.approx(-1.5), pytest.approx(0.5))
    assert world.time == pytest.approx(2.5) and world.steps == 250


def test_robot_that_hits_a_wall_stops_and_reports_stall_then_backs_off() -> None:
    world = corridor(watchdog=None)
    world.command("r0", 0.5, 0.0)
    world.advance(600)  # would reach x = 3 without the wall (face at 2.2)
    r0 = world.robot("r0")
    assert r0.stall and r0.stall_steps > 100
    assert 2.2 - 0.2 - 0.5 * world.dt <= r0.pose.x <= 2.0
    assert not world.touching("r0")  # Stage semantics: the move was undone
    world.command("r0", -0.5, 0.0)
    world.step()
    assert not r0.stall and r0.pose.x < 2.0


def test_robots_stall_against_each_other_and_a_standing_robot_does_not() -> None:
    world = corridor(watchdog=None)
    world.command("r1", 1.0, 0.0)
    world.advance(300)
    assert world.robot("r1").stall and not world.robot("r0").stall
    assert world.robot("r1").pose.x <= -0.4 + 1e-9


def test_watchdog_stops_a_robot_without_fresh_commands() -> None:
    world = corridor(watchdog=0.2)
    world.command("r1", 1.0, 0.0)
    world.advance(100)
    assert world.robot("r1").linear == 0.0
    assert world.robot("r1").pose.x == pytest.approx(-2.0 + 0.2)  # 20 steps of 0.01 s at 1 m/s


def test_step_grid_and_scheduled_commands() -> None:
    assert steps_at(3 * 0.1, 0.01) == 30 and steps_at(0.07, 0.01) == 7
    with pytest.raises(GridError):
        steps_at(0.105, 0.01)
    world = corridor(watchdog=None)
    with pytest.raises(GridError):
        world.advance_to(0.015)
    world.schedule(0.1, "r1", 1.0, 0.0)  # takes effect at step 10
    world.schedule(0.205, "r1", 0.0, 0.0)  # off the grid: from step 21
    world.advance_to(0.3)
    assert world.robot("r1").pose.x == pytest.approx(-2.0 + 0.11)
    with pytest.raises(ValueError, match="before the world's time"):
        world.advance_to(0.2)


# ---- sensors ----


def test_ranger_measures_the_wall_and_ignores_its_own_robot() -> None:
    world = corridor()
    left, centre, right = world.robot("r0").ranges
    assert centre == pytest.approx(2.2 - 0.2)  # from the sensor at the front edge to the wall face
    assert left == pytest.approx(2.0 / math.cos(math.radians(15)))
    assert right == pytest.approx(left)
    behind = world.robot("r1").ranges
    assert behind[1] == pytest.approx(2.0 - 0.2 - 0.2)  # r1 sees r0's back, not itself


def test_ranger_reports_range_max_when_nothing_is_hit_and_noise_is_seeded() -> None:
    text = 'position( name "a" ranger( sensor( range [0 1] samples 4 fov 90 noise [0.05 0 0] ) ) )'
    a, b, c = (World(load_world(text), seed=s) for s in (1, 1, 2))
    assert a.robot("a").ranges == b.robot("a").ranges != c.robot("a").ranges
    assert all(0.0 <= r <= 1.0 for r in a.robot("a").ranges)
    quiet = World(load_world(text.replace("noise [0.05 0 0]", "")))
    assert quiet.robot("a").ranges == [1.0] * 4


def test_invisible_and_non_obstacle_models() -> None:
    text = (
        'position( name "a" ranger( sensor( range [0 5] ) ) )\n'
        "model( pose [1 0 0 0] size [0.2 1 1] ranger_return -1 )\n"  # felt, not seen
        "model( pose [3 0 0 0] size [0.2 1 1] obstacle_return 0 )\n"  # seen, not felt
    )
    world = World(load_world(text), watchdog=None)
    assert world.robot("a").ranges == [pytest.approx(2.9)]
    world.command("a", 1.0, 0.0)
    world.advance(200)
    assert world.robot("a").stall and world.robot("a").pose.x == pytest.approx(0.85, abs=0.011)


def test_odometry_integrates_and_its_noise_is_seeded() -> None:
    text = 'position( name "a" localization "odom" odom_error [0.05 0.05 0 0.05] )'
    clean = World(load_world('position( name "a" )'), watchdog=None)
    noisy = [World(load_world(text), watchdog=None, seed=7) for _ in range(2)]
    for world in [clean, *noisy]:
        world.command("a", 0.5, 0.3)
        world.advance(200)
    truth, odom = clean.robot("a").pose, clean.robot("a").odometry
    assert (odom.x, odom.y, odom.theta) == pytest.approx((truth.x, truth.y, truth.theta), abs=1e-3)
    assert noisy[0].robot("a").odometry == noisy[1].robot("a").odometry != odom
    assert noisy[0].robot("a").pose == truth  # noise is in the odometry only


def test_same_commands_give_bit_identical_poses() -> None:
    def run() -> list[tuple[float, float, float]]:
        world = corridor(watchdog=None)
        out = []
        for k in range(40):
            world.command("r1", 0.8, 0.5 * math.sin(k))
            world.command("r0", 0.3, -0.4)
            world.advance(7)
            out += [(p.x, p.y, p.theta) for p in world.poses().values()]
        return out

    assert run() == run()


# ---- pictures ----


def _decode_png(data: bytes) -> tuple[int, int, bytes]:
    assert data[:8] == b"\x89PNG\r\n\x1a\n"
    width, height, depth, kind = struct.unpack(">IIBB", data[16:26])
    assert (depth, kind) == (8, 2)
    idat = data.index(b"IDAT")
    length = struct.unpack(">I", data[idat - 4:idat])[0]
    raw = zlib.decompress(data[idat + 4:idat + 4 + length])
    rows = [raw[r * (3 * width + 1):(r + 1) * (3 * width + 1)] for r in range(height)]
    assert all(row[0] == 0 for row in rows)
    return width, height, b"".join(row[1:] for row in rows)


def test_snapshot_png_shows_robots_walls_and_beams(tmp_path: pathlib.Path) -> None:
    world = corridor()
    image = snapshot(world, scale=20.0)
    width, height, pixels = _decode_png(render.write_snapshot(world, tmp_path / "s.png", scale=20.0).read_bytes())
    assert (width, height) == (image.width, image.height) and pixels == bytes(image.pixels)
    assert image.get(*image.to_pixel(-2.1, 0.1)) == render.color("red")  # r1's body (off its nose line)
    assert image.get(*image.to_pixel(-0.1, 0.1)) == render.color("blue")
    assert image.get(*image.to_pixel(2.3, 1.5)) == render.color("gray30")
    assert image.get(*image.to_pixel(1.0, 0.0)) == render.BEAM
    assert image.get(*image.to_pixel(1.0, 1.5)) == render.BACKGROUND


def corridor_run() -> tuple[World, list[dict[str, Pose]]]:
    """The corridor with r1 driving ahead for three samples of 10 steps."""
    world = corridor(watchdog=None)
    samples = []
    world.command("r1", 1.0, 0.0)
    for _ in range(3):
        world.advance(10)
        samples.append(world.poses())
    return world, samples


def test_trajectory_data_and_clear_error_without_matplotlib(monkeypatch: pytest.MonkeyPatch,
                                                           tmp_path: pathlib.Path) -> None:
    world, samples = corridor_run()
    tracks = trajectories(samples)
    assert tracks["r1"] == [(pytest.approx(-1.9), 0.0), (pytest.approx(-1.8), 0.0), (pytest.approx(-1.7), 0.0)]
    assert tracks["r0"] == [(0.0, 0.0)] * 3
    assert render.animation_frames(samples, 2) == [0, 2]
    assert render.animation_frames(samples, 60) == [0, 1, 2]
    assert render.animation_frames(samples[:1], 5) == [0] and render.animation_frames([], 5) == []
    monkeypatch.setitem(sys.modules, "matplotlib", None)
    with pytest.raises(ImportError, match="needs matplotlib: pip install matplotlib"):
        render.plot_trajectories(world, samples, tmp_path / "t.png")
    with pytest.raises(ImportError, match="needs matplotlib"):
        render.animate_trajectories(world, samples, tmp_path / "t.gif")


WILLOW_FOUR_ERRATICS = '''
define block model
(
  size [0.5 0.5 0.5]
  gui_nose 0
)

define topurg ranger
(
	sensor( 			
    range [ 0.0  30.0 ]
    fov 270.25
   samples 1081
  )

  # generic model properties
  color "black"
  size [ 0.05 0.05 0.1 ]
)

define erratic position
(
  #size [0.415 0.392 0.25]
  size [0.35 0.35 0.25]
  origin [-0.05 0 0 0]
  gui_nose 1
  drive "diff"
  topurg(pose [ 0.050 0.000 0 0.000 ])
)

define floorplan model
(
  # sombre, sensible, artistic
  color "gray30"

  # most maps will need a bounding box
  boundary 1

  gui_nose 0
  gui_grid 0

  gui_outline 0
  gripper_return 0
  fiducial_return 0
  laser_return 1
)

# set the resolution of the underlying raytrace model in meters
resolution 0.02

interval_sim 100  # simulation timestep in milliseconds


window
( 
  size [ 745.000 448.000 ] 

  rotate [ 0.000 -1.560 ]
  scale 28.806 
)

# load an environment bitmap
floorplan
( 
  name "willow"
  bitmap "willow-full.pgm"
  size [54.0 58.7 0.5]
  pose [ -29.350 27.000 0 90.000 ]
)

# throw in two robots
erratic( pose [ -11.277 23.266 0 180.000 ] name "era" color "blue")
erratic( pose [ -13.277 22.266 0 180.000 ] name "era2" color "blue")
erratic( pose [ -13.277 23.266 0 180.000 ] name "era3" color "blue")
erratic( pose [ -11.277 22.266 0 180.000 ] name "era4" color "blue")
block( pose [ -13.924 25.020 0 180.000 ] color "red")
'''


def test_stage_ros_willow_four_erratics_loads() -> None:
    """stage_ros's world/willow-four-erratics.world, verbatim (the bitmap is not read: its boundary is)."""
    spec = load_world(WILLOW_FOUR_ERRATICS)
    assert [r.name for r in spec.robots] == ["era", "era2", "era3", "era4"]
    assert spec.robots[0].pose == pytest.approx((-11.277, 23.266, math.pi))
    (laser,) = spec.robots[0].sensors
    assert (laser.samples, laser.range_max, laser.fov) == (1081, 30.0, pytest.approx(math.radians(270.25)))
    assert len(spec.blocks) == 5 and spec.blocks[-1].size == (0.5, 0.5)  # 4 boundary walls + the block
    world = World(spec)
    assert len(world.robot("era").ranges) == 1081
    assert min(world.robot("era").ranges) < 2.1  # era3 and era4 stand 1 m and 2 m away


def test_turtlebot_inc_units_and_old_range_max() -> None:
    text = (
        'unit_length "cm"\n'
        "define kinect ranger ( sensor ( range_max 650  fov 58.0  samples 640 ) color \"black\" size [ 6 15 3 ] )\n"
        "define turtlebot position ( pose [0 0 0 0] odom_error [0.03 0.03 999999 999999 999999 0.02]\n"
        '  size [ 33 33 40 ] origin [0 0 0 0] gui_nose 1 drive "diff" color "gray"\n'
        "  kinect(pose [ -10 0.0 -11 0.0 ]) )\n"
        'turtlebot( pose [ 100 50 0 45 ] name "tb" localization "odom" )\n'
    )
    (tb,) = load_world(text).robots
    assert tb.pose == pytest.approx((1.0, 0.5, math.pi / 4)) and tb.size == pytest.approx((0.33, 0.33))
    (kinect,) = tb.sensors
    assert (kinect.range_max, kinect.samples, kinect.pose[0]) == (pytest.approx(6.5), 640, pytest.approx(-0.1))
    # Stage reads odom_error's first four entries as x y z a: turtlebot.inc's yaw error is 999999 ("huge")
    assert tb.odom_noise == (0.03, 999999.0)


def test_poses_are_identical_in_another_process_with_another_hash_seed() -> None:
    import os
    import subprocess

    script = (
        "import math\n"
        "from hlacore.federates.robot_world import World, load_world\n"
        f"w = World(load_world({CORRIDOR!r}), seed=3)\n"
        "for k in range(30):\n"
        "    w.command('r1', 0.8, 0.5 * math.sin(k)); w.command('r0', 0.3, -0.4); w.advance(7)\n"
        "print(repr(sorted((n, p.x, p.y, p.theta) for n, p in w.poses().items())))\n"
    )
    here = World(load_world(CORRIDOR), seed=3)
    for k in range(30):
        here.command("r1", 0.8, 0.5 * math.sin(k))
        here.command("r0", 0.3, -0.4)
        here.advance(7)
    env = dict(os.environ, PYTHONHASHSEED="12345")
    out = subprocess.run([sys.executable, "-c", script], capture_output=True, text=True, env=env, timeout=60,
                         check=True).stdout.strip()
    assert out == repr(sorted((n, p.x, p.y, p.theta) for n, p in here.poses().items()))


def test_trajectory_plot_names_everything_it_draws(tmp_path: pathlib.Path) -> None:
    """Title, axes with units, and a legend naming the robots, the walls, start, end and the marks."""
    import matplotlib  # a test dependency (hlacore[test])

    world, samples = corridor_run()
    with matplotlib.rc_context({"svg.fonttype": "none"}):  # the texts stay text in the SVG
        svg = render.plot_trajectories(world, samples, tmp_path / "t.svg", title="a run",
                                       marks={"held back": [(0.1, 0.0)]}).read_text()
    for text in ("a run", "x (m)", "y (m)", "r0", "r1", "wall", "start", "end", "held back"):
        assert f">{text}<" in svg, text


def test_the_labelled_snapshot_names_every_box_robot_trail_and_the_beams(tmp_path: pathlib.Path) -> None:
    """The experiments' snapshot is a figure for readers: title, axes in metres, a legend of what is drawn
    (matplotlib's SVG keeps each text as a comment beside its glyphs)."""
    world = corridor(watchdog=None)
    world.command("r0", 0.5, 0.0)
    trail = []
    for _ in range(10):
        world.step()
        trail.append((world.robot("r0").pose.x, world.robot("r0").pose.y))
    out = render.write_labelled_snapshot(world, tmp_path / "s.svg", "the world", trails={"r0": trail})
    texts = set(re.findall(r"<!-- (.*?) -->", out.read_text()))
    assert {"the world", "x (m)", "y (m)", "ranger beams", "r0 trail", f"r0 at {world.time:.1f} s"} <= texts, texts
    assert {block.name or "wall" for block in world.spec.blocks} <= texts, texts
