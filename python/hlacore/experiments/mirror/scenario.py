"""The §6.2 scene: two lanes, each with a box ahead of a robot. Lane 0 holds the mirror of the real robot
(the real robot's own floor has no box: it senses this one through its mirror's sonar); lane 1 holds the
robot driven by a plain ROS node. The reference model drives a robot alone in a copy of lane 0.

Stage syntax (docs/robot-world.md); the figures are ours (the paper gives none).
"""

from __future__ import annotations

from hlacore.federates.robot_world import WorldSpec, load_world

MIRROR, ROSBOT, REFERENCE = "mirror", "rosbot", "reference"
#: y of each lane; the robots start at x = 0 facing +x.
LANES = {MIRROR: 0.0, ROSBOT: -2.0, REFERENCE: 0.0}
BOX_X, BOX_SIZE = 1.6, 0.4  #: the boxes' centre x and side, m
HALF = 0.33 / 2  #: the robots' half side, m
CLEAR = HALF * 2 ** 0.5  #: a robot whose centre stays farther than this from a box never touches it, m

_HEADER = """
resolution 0.02
interval_sim 100
define sonar ranger ( sensor( pose [0 0 0 0] range [0.02 2.0] fov 30 samples 5 ) )
define bot position ( size [0.33 0.33 0.40] drive "diff" gui_nose 1 sonar(pose [0.165 0 0 0]) )
define box model ( size [0.4 0.4 0.5] color "black" obstacle_return 1 ranger_return 1 )
"""
_COLOURS = {MIRROR: "red", ROSBOT: "green", REFERENCE: "blue"}


def world_text(robots: tuple[str, ...] = (MIRROR, ROSBOT)) -> str:
    """The world file with ``robots`` (names above), each on its lane with its box."""
    lines = [_HEADER]
    for name in robots:
        y = LANES[name]
        lines.append(f'bot( pose [ 0.0 {y} 0 0 ] name "{name}" color "{_COLOURS[name]}" )')
    for y in sorted({LANES[name] for name in robots}):
        lines.append(f"box( pose [ {BOX_X} {y} 0 0 ] )")
    return "\n".join(lines) + "\n"


def world_spec(robots: tuple[str, ...] = (MIRROR, ROSBOT)) -> WorldSpec:
    """The parsed world of :func:`world_text`."""
    return load_world(world_text(robots))
