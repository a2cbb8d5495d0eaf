"""The robot world: a pymunk space stepped with a fixed dt, Stage-style differential-drive robots.

Time is counted in whole steps (``world.steps``; ``world.time == steps * dt``). Each step:

1. commands scheduled for this step take effect (:meth:`World.schedule`, or :meth:`World.command` for
   the next step); a robot whose last command is ``watchdog`` seconds old or more is stopped (as
   stageros does, but per robot);
2. every robot's kinematic body gets ``velocity = v (cos θ, sin θ)`` and ``angular_velocity = ω``
   (cmd_vel's linear.x and angular.z, clipped to the robot's bounds) and ``space.step(dt)`` moves it;
3. a robot that moved and now overlaps anything that is an obstacle is put back where it was and
   stalled (Stage's ``ModelPosition::Move``: no bounce, no push); a robot that moves freely clears its
   stall flag;
4. odometry integrates the applied velocities (with optional seeded noise), and the rangers are read
   by segment queries.

Nothing depends on wall-clock time or on set iteration order, so the same commands at the same steps
give bit-identical poses.
"""

from __future__ import annotations

import math
import random
from dataclasses import dataclass, field
from typing import Optional

import pymunk

from .worldfile import BlockSpec, RobotSpec, SensorSpec, WorldSpec

#: Shape-filter category bits: collides, seen by rangers, is a ranger ray.
OBSTACLE, VISIBLE, RAY = 1, 2, 4
_GRID_TOLERANCE = 1e-9


class GridError(ValueError):
    """A time that is not a whole number of physics steps."""


def steps_at(time: float, dt: float) -> int:
    """The number of whole steps of ``dt`` in ``time``; raises GridError if ``time`` is off the grid.

    "On the grid" allows a relative error of 1e-9, so ``3 * 0.1`` is step 30 of ``dt = 0.01``."""
    exact = time / dt
    n = round(exact)
    if abs(exact - n) > _GRID_TOLERANCE * max(1.0, abs(exact)):
        raise GridError(f"time {time!r} is not a whole number of steps of {dt!r} s")
    return int(n)


def first_step_at_or_after(time: float, dt: float) -> int:
    """The index of the first step that starts at or after ``time`` (commands take effect there)."""
    exact = time / dt
    n = round(exact)
    if abs(exact - n) <= _GRID_TOLERANCE * max(1.0, abs(exact)):
        return int(n)
    return int(math.ceil(exact))


@dataclass(frozen=True)
class Pose:
    """A planar pose: position in metres, heading in radians."""

    x: float
    y: float
    theta: float


@dataclass
class Robot:
    """One differential-drive robot: its body, its command and what it reports."""

    spec: RobotSpec
    index: int
    body: pymunk.Body
    shape: pymunk.Poly
    linear: float = 0.0
    angular: float = 0.0
    last_command_step: int = 0
    stall: bool = False
    stall_steps: int = 0  # how many steps it was blocked (each one a collision it was stopped by)
    odometry: Pose = Pose(0.0, 0.0, 0.0)
    ranges: list[float] = field(default_factory=list)
    # every beam, precomputed: sensor x, y in the robot frame, angle to the heading, min, max, noise
    beams: list[tuple[float, float, float, float, float, float]] = field(default_factory=list)
    ray_filter: pymunk.ShapeFilter = pymunk.ShapeFilter()

    @property
    def name(self) -> str:
        """The robot's name (the world file's ``name``, else ``robot_<index>``)."""
        return self.spec.name

    @property
    def pose(self) -> Pose:
        """Ground-truth pose."""
        x, y = self.body.position
        return Pose(float(x), float(y), float(self.body.angle))


class World:
    """A 2-D world of static boxes and differential-drive robots, stepped with a fixed ``dt``.

    ``watchdog`` (seconds, None to disable) stops a robot whose last command is that old; ``seed``
    seeds the one RNG used by ranger and odometry noise."""

    def __init__(self, spec: WorldSpec, dt: float = 0.01, watchdog: Optional[float] = 0.2, seed: int = 0) -> None:
        if not dt > 0:
            raise ValueError("dt must be positive")
        self.spec = spec
        self.dt = float(dt)
        self.steps = 0
        self.watchdog_steps = None if watchdog is None else max(1, steps_at(watchdog, dt))
        self.rng = random.Random(seed)
        self.space = pymunk.Space()
        self.space.iterations = 1
        self.robots: list[Robot] = []
        self._by_name: dict[str, Robot] = {}
        self._scheduled: dict[int, list[tuple[str, float, float]]] = {}
        for block in spec.blocks:
            self._add_block(block)
        for robot_spec in spec.robots:
            self._add_robot(robot_spec)
        for robot in self.robots:
            robot.ranges = self._read_ranges(robot)

    # ---- construction ----

    def _add_block(self, block: BlockSpec) -> None:
        x, y, a = block.pose
        sx, sy = block.size
        corners = _box(sx, sy, 0.0, 0.0)
        c, s = math.cos(a), math.sin(a)
        points = [(x + c * px - s * py, y + s * px + c * py) for px, py in corners]
        shape = pymunk.Poly(self.space.static_body, points)
        categories = (OBSTACLE if block.obstacle else 0) | (VISIBLE if block.visible else 0)
        shape.filter = pymunk.ShapeFilter(categories=categories, mask=OBSTACLE | RAY)
        self.space.add(shape)

    def _add_robot(self, spec: RobotSpec) -> None:
        index = len(self.robots)
        body = pymunk.Body(body_type=pymunk.Body.KINEMATIC)
        body.position = spec.pose[0], spec.pose[1]
        body.angle = spec.pose[2]
        shape = pymunk.Poly(body, _box(spec.size[0], spec.size[1], spec.origin[0], spec.origin[1]))
        shape.filter = pymunk.ShapeFilter(group=index + 1, categories=OBSTACLE | VISIBLE, mask=OBSTACLE | RAY)
        self.space.add(body, shape)
        beams = [(sensor.pose[0], sensor.pose[1], sensor.pose[2] + beam, sensor.range_min, sensor.range_max,
                  sensor.noise) for sensor in spec.sensors for beam in beam_angles(sensor)]
        ray_filter = pymunk.ShapeFilter(group=index + 1, categories=RAY, mask=VISIBLE)
        robot = Robot(spec, index, body, shape, odometry=Pose(*spec.pose), beams=beams, ray_filter=ray_filter)
        self.robots.append(robot)
        self._by_name[spec.name] = robot

    # ---- queries ----

    @property
    def time(self) -> float:
        """Simulated time in seconds: ``steps * dt``."""
        return self.steps * self.dt

    def robot(self, name: str) -> Robot:
        """The robot called ``name``; KeyError names the known robots."""
        try:
            return self._by_name[name]
        except KeyError:
            raise KeyError(f"no robot {name!r}; robots: {sorted(self._by_name)}") from None

    def poses(self) -> dict[str, Pose]:
        """Every robot's ground-truth pose."""
        return {r.name: r.pose for r in self.robots}

    def touching(self, name: str) -> bool:
        """Whether the robot overlaps or touches an obstacle or another robot now."""
        robot = self.robot(name)
        return any(hit.shape is not robot.shape for hit in self.space.shape_query(robot.shape))

    # ---- commands ----

    def command(self, name: str, linear: float, angular: float) -> None:
        """Set a robot's velocity (cmd_vel linear.x, angular.z) from the next step on; clipped to its bounds."""
        robot = self.robot(name)
        robot.linear = _clip(float(linear), robot.spec.max_linear)
        robot.angular = _clip(float(angular), robot.spec.max_angular)
        robot.last_command_step = self.steps

    def schedule(self, time: float, name: str, linear: float, angular: float) -> None:
        """Apply a command at ``time``: from the first step starting at or after it (at once if past)."""
        self.robot(name)
        step = max(self.steps, first_step_at_or_after(time, self.dt))
        self._scheduled.setdefault(step, []).append((name, linear, angular))

    # ---- stepping ----

    def step(self) -> None:
        """Advance one fixed step of ``dt``."""
        for name, linear, angular in self._scheduled.pop(self.steps, ()):
            self.command(name, linear, angular)
        saved = []
        for robot in self.robots:
            if self.watchdog_steps is not None and self.steps - robot.last_command_step >= self.watchdog_steps:
                robot.linear = robot.angular = 0.0
            body = robot.body
            saved.append((body.position, body.angle))
            theta = body.angle
            body.velocity = (robot.linear * math.cos(theta), robot.linear * math.sin(theta))
            body.angular_velocity = robot.angular
        self.space.step(self.dt)
        blocked = []
        for robot, (position, angle) in zip(self.robots, saved):
            moved = robot.linear != 0.0 or robot.angular != 0.0
            if moved and any(hit.shape is not robot.shape for hit in self.space.shape_query(robot.shape)):
                blocked.append((robot, position, angle))
        for robot, position, angle in blocked:
            robot.body.position = position
            robot.body.angle = angle
            self.space.reindex_shapes_for_body(robot.body)
        stalled = {id(r) for r, _, _ in blocked}
        for robot in self.robots:
            robot.body.velocity = (0.0, 0.0)
            robot.body.angular_velocity = 0.0
            if id(robot) in stalled:
                robot.stall = True
                robot.stall_steps += 1
            elif robot.linear != 0.0 or robot.angular != 0.0:
                robot.stall = False
                robot.odometry = self._integrate_odometry(robot)
        self.steps += 1
        for robot in self.robots:
            robot.ranges = self._read_ranges(robot)

    def advance(self, steps: int) -> None:
        """Advance ``steps`` whole steps."""
        for _ in range(int(steps)):
            self.step()

    def advance_to(self, time: float) -> None:
        """Advance to ``time``, which must be on the step grid (GridError otherwise) and not in the past."""
        target = steps_at(time, self.dt)
        if target < self.steps:
            raise ValueError(f"time {time!r} is before the world's time {self.time!r}")
        self.advance(target - self.steps)

    # ---- sensors ----

    def _integrate_odometry(self, robot: Robot) -> Pose:
        v, w = robot.linear, robot.angular
        nv, nw = robot.spec.odom_noise
        if nv:
            v *= 1.0 + self.rng.gauss(0.0, nv)
        if nw:
            w *= 1.0 + self.rng.gauss(0.0, nw)
        o = robot.odometry
        return Pose(o.x + v * math.cos(o.theta) * self.dt, o.y + v * math.sin(o.theta) * self.dt,
                    o.theta + w * self.dt)

    def _read_ranges(self, robot: Robot) -> list[float]:
        out: list[float] = []
        x, y = robot.body.position
        theta = robot.body.angle
        c, s = math.cos(theta), math.sin(theta)
        query = self.space.segment_query_first
        ray = robot.ray_filter
        for sx, sy, offset, range_min, range_max, noise in robot.beams:
            ox, oy = x + c * sx - s * sy, y + s * sx + c * sy
            a = theta + offset
            hit = query((ox, oy), (ox + range_max * math.cos(a), oy + range_max * math.sin(a)), 0.0, ray)
            r = range_max if hit is None else hit.alpha * range_max
            if noise:
                r += self.rng.gauss(0.0, noise)
            out.append(min(max(r, range_min), range_max))
        return out


def beam_angles(sensor: SensorSpec) -> list[float]:
    """The beams' angles relative to the sensor's heading: from -fov/2 to +fov/2 (one beam: 0)."""
    if sensor.samples == 1:
        return [0.0]
    step = sensor.fov / (sensor.samples - 1)
    return [-sensor.fov / 2 + i * step for i in range(sensor.samples)]


def _box(sx: float, sy: float, ox: float, oy: float) -> list[tuple[float, float]]:
    hx, hy = sx / 2, sy / 2
    return [(ox - hx, oy - hy), (ox + hx, oy - hy), (ox + hx, oy + hy), (ox - hx, oy + hy)]


def _clip(value: float, bound: float) -> float:
    return max(-bound, min(bound, value))
