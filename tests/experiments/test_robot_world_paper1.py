"""Paper 1's scenario in the robot world alone: the avatar never collides, waits for the obstacles to cross,
passes once they have gone and stops before the wall."""

from __future__ import annotations

import csv
import pathlib
import sys

import pytest

from hlacore.experiments.paper1 import scenario as paper1
from hlacore.federates.robot_world import World
from hlacore.federates.robot_world.render import trajectories

WALL_FACE = 7.0 - 0.1
HALF = 0.33 / 2


@pytest.fixture(scope="module")
def scenario() -> tuple[World, paper1.Trace]:
    return paper1.run(duration=30.0)


def test_avatar_passes_the_crossing_obstacles_without_collision_and_stops_before_the_wall(
        scenario: tuple[World, paper1.Trace]) -> None:
    world, trace = scenario
    # no collision, ever: the avatar never touched anything and no robot stalled
    assert not any(trace.touching) and not any(trace.stalled)
    tracks = trajectories(trace.poses)
    avatar = tracks["avatar"]
    for name in paper1.OBSTACLES:
        ox = world.robot(name).spec.pose[0]
        # the first cycle at which the avatar's front passes the obstacle's near side...
        k = next(i for i, (x, _) in enumerate(avatar) if x + HALF >= ox - HALF)
        # ...comes after the obstacle has left the avatar's lane (|y| beyond both half widths)
        assert abs(tracks[name][k][1]) > 2 * HALF, name
    # the controller did hold the avatar back for the obstacles (stopped or slow before passing the first)
    k1 = next(i for i, (x, _) in enumerate(avatar) if x >= world.robot("obstacle1").spec.pose[0])
    assert min(trace.avatar_speed[:k1]) < paper1.Controller().go
    # it passed them all and stopped before the wall, close to it
    final = world.robot("avatar").pose
    front = final.x + HALF
    assert final.x > world.robot("obstacle3").spec.pose[0]
    assert 0.0 < WALL_FACE - front <= paper1.Controller().stop_below
    assert trace.avatar_speed[-20:] == [0.0] * 20
    assert abs(final.y) < 1e-12 and final.theta == 0.0


def test_outputs_trace_and_snapshot_without_matplotlib(scenario: tuple[World, paper1.Trace], tmp_path: pathlib.Path,
                                                      monkeypatch: pytest.MonkeyPatch,
                                                      capsys: pytest.CaptureFixture[str]) -> None:
    world, trace = scenario
    monkeypatch.setitem(sys.modules, "matplotlib", None)
    written = paper1.write_outputs(world, trace, str(tmp_path))
    assert [pathlib.Path(p).name for p in written] == ["paper1-trace.csv", "paper1-snapshot.png"]
    assert "no trajectory plot: plotting trajectories needs matplotlib" in capsys.readouterr().out
    with open(tmp_path / "paper1-trace.csv") as f:
        rows = list(csv.reader(f))
    assert rows[0][:5] == ["time", "distance", "avatar_speed", "avatar_x", "avatar_y"]
    assert len(rows) == 1 + len(trace.times)
    assert float(rows[-1][3]) == world.robot("avatar").pose.x
    assert (tmp_path / "paper1-snapshot.png").read_bytes()[:8] == b"\x89PNG\r\n\x1a\n"
