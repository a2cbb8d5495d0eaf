"""The robot world: a pymunk 2-D world of Stage-style differential-drive robots, loaded from Stage
``.world`` files, stepped with a fixed dt, and joinable to a federation (docs/robot-world.md).

Federates layer: imports only the core; it knows nothing of ROS (the stageros-style node is
:mod:`hlacore.federates.ros_bridge.stage_node`). Paper 1's scenario is :mod:`hlacore.experiments.paper1`.
"""

from .codec import FEDERATION, FOM_PATH
from .federate import Command, WorldFederate
from .render import (animate_trajectories, plot_trajectories, snapshot, trajectories, write_labelled_snapshot,
                     write_snapshot)
from .world import GridError, Pose, Robot, World, beam_angles, first_step_at_or_after, steps_at
from .worldfile import BlockSpec, RobotSpec, SensorSpec, WorldFileError, WorldSpec, load_world, read_world

__all__ = [
    "FEDERATION",
    "FOM_PATH",
    "BlockSpec",
    "Command",
    "GridError",
    "Pose",
    "Robot",
    "RobotSpec",
    "SensorSpec",
    "World",
    "WorldFederate",
    "WorldFileError",
    "WorldSpec",
    "animate_trajectories",
    "beam_angles",
    "first_step_at_or_after",
    "load_world",
    "plot_trajectories",
    "read_world",
    "snapshot",
    "steps_at",
    "trajectories",
    "write_labelled_snapshot",
    "write_snapshot",
]
