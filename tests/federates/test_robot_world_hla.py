"""The robot world as a federate, against both gateways: it advances physics exactly to each grant (poses
match a standalone run with the same steps bit for bit), takes cmd_vel from a driving federate at the
commands' timestamps, and publishes poses, odometry and ranges stamped grant + lookahead."""

from __future__ import annotations

import time
from typing import Any

import pytest

import hlacore.rti as rti
from hlacore.federates.robot_world import (
    FEDERATION,
    Command,
    GridError,
    World,
    WorldFederate,
    load_world,
)
from hlacore.federates.robot_world import codec

from support import ROVER_MODEL, Federate, barrier

WORLD = ROVER_MODEL + """
bot( pose [ 0 0 0 0 ] name "rover" )
bot( pose [ 0 1 0 0 ] name "idle" )
model( pose [ 3 0 0 0 ] size [ 0.2 3 0.5 ] )
"""
DT, PERIOD, LOOKAHEAD = 0.01, 0.1, 0.1
CYCLES = 30
# the driver's command per cycle k, sent at its time + lookahead: accelerate, turn, reverse, stop
COMMANDS = [(0.6, 0.0)] * 10 + [(0.4, 0.8)] * 8 + [(-0.3, -0.5)] * 7 + [(0.0, 0.0)] * 5


class Driver:
    """A regulating and constrained federate that sends cmd_vel and records the reflected robot state."""

    def __init__(self, address: str) -> None:
        self.fed = Federate(address, "driver", FEDERATION)
        r = self.fed.rtia
        robot = r.getObjectClassHandle(codec.OBJECT_CLASS)
        self.attrs = {r.getAttributeHandle(n, robot): n for n in codec.ATTRIBUTES}
        r.subscribeObjectClassAttributes(robot, list(self.attrs))
        self.cmd = r.getInteractionClassHandle(codec.INTERACTION)
        self.params = {n: r.getParameterHandle(n, self.cmd) for n in codec.PARAMETERS}
        r.publishInteractionClass(self.cmd)
        self.fed.enable_time(LOOKAHEAD)

    def send(self, robot: str, linear: float, angular: float, stamp: float) -> None:
        p = self.params
        self.fed.rtia.sendInteraction(self.cmd, {
            p["robot"]: codec.NAME.pack(robot),
            p["linear"]: codec.SPEED.pack(linear),
            p["angular"]: codec.SPEED.pack(angular),
        }, "driver", stamp)

    def reflected(self) -> list[tuple[float, str, dict[str, Any]]]:
        """(timestamp, robot name, decoded attributes) of every reflection, in delivery order."""
        kinds = {"name": codec.NAME, "pose": codec.POSE, "odometry": codec.ODOMETRY, "ranges": codec.RANGES,
                 "stall": codec.STALL}
        out = []
        for _obj, attributes, _tag, _order, _transport, *rest in self.fed.amb.named("reflectAttributeValues"):
            values = {self.attrs[h]: codec.unpack(kinds[self.attrs[h]], v) for h, v in attributes.items()}
            name = values["name"]
            assert isinstance(name, bytes)
            out.append((float(rest[0]), name.decode("ascii"), values))
        return out


def lockstep(world: WorldFederate, driver: Driver, cycles: int) -> list[float]:
    """Both federates request the next grid point each cycle (the driver first sends its command);
    returns the world's grants. Bounded: each cycle gives up after 10 s."""
    grants = []
    for k in range(cycles):
        now = k * PERIOD
        linear, angular = COMMANDS[k]
        driver.send("rover", linear, angular, now + LOOKAHEAD)
        if k == 3:
            driver.send("ghost", 1.0, 0.0, now + LOOKAHEAD)  # no such robot: ignored, recorded
        driver.fed.rtia.timeAdvanceRequest((k + 1) * PERIOD)
        world.request()
        deadline = time.monotonic() + 10.0
        world_done = driver_done = False
        while not (world_done and driver_done):
            assert time.monotonic() < deadline, f"cycle {k} not granted"
            world_done = world_done or world.poll()
            driver_done = driver_done or driver.fed.rtia.deliver_until_granted()
            if not (world_done and driver_done):
                driver.fed.rtia.tick(0.001, 0.01)
        grants.append(world.time)
    return grants


def test_world_steps_exactly_to_grants_and_matches_a_standalone_run_bit_for_bit(world_federation: str) -> None:
    driver = Driver(world_federation)
    world = WorldFederate.join(World(load_world(WORLD), dt=DT, watchdog=0.2), world_federation,
                               period=PERIOD, lookahead=LOOKAHEAD, create=False)
    try:
        barrier(driver.fed.rtia)
        grants = lockstep(world, driver, CYCLES)
        assert grants == [(k + 1) * PERIOD for k in range(CYCLES)]
        assert world.world.steps == round(CYCLES * PERIOD / DT)
        assert world.ignored == [Command(3 * PERIOD + LOOKAHEAD, "ghost", 1.0, 0.0)]
        # the federate's poses at every grant, against a world run alone with the same commands and steps
        alone = World(load_world(WORLD), dt=DT, watchdog=0.2)
        expected = [(0.0, alone.poses())]
        for k in range(CYCLES):
            alone.schedule(k * PERIOD + LOOKAHEAD, "rover", *COMMANDS[k])
            alone.advance_to((k + 1) * PERIOD)
            expected.append(((k + 1) * PERIOD, alone.poses()))
        assert world.history == expected  # exact float equality
        rover = world.world.robot("rover").pose
        assert rover.x > 0.5 and rover.theta != 0.0  # the commands moved and turned it

        # the driver saw every published state, stamped grant + lookahead, equal to the world's (TSO
        # messages come with the grant that reaches their timestamp: nothing to wait for)
        seen = driver.reflected()
        by_stamp = {(stamp, name): values for stamp, name, values in seen}
        driver_time = driver.fed.rtia.queryFederateTime()
        delivered = [(g, poses) for g, poses in world.history if g + LOOKAHEAD <= driver_time]
        assert len(delivered) >= CYCLES - 1  # the last ones are stamped beyond the driver's time
        for granted, poses in delivered:
            values = by_stamp[(granted + LOOKAHEAD, "rover")]
            pose = poses["rover"]
            assert values["pose"] == (pose.x, pose.y, pose.theta)
            assert len(values["ranges"]) == 5 and values["stall"] is False
        assert all(stamp <= driver_time for stamp, _, _ in seen) and len(seen) == 2 * len(delivered)
    finally:
        world.resign()
        driver.fed.rtia.resignFederationExecution(rti.ResignAction.DeleteObjectsAndReleaseAttributes)


def test_grid_checks(world_federation: str) -> None:
    with pytest.raises(GridError):
        WorldFederate.join(World(load_world(WORLD), dt=DT), world_federation, period=0.015, create=False)
    with pytest.raises(ValueError, match="lookahead must be positive"):
        WorldFederate.join(World(load_world(WORLD), dt=DT), world_federation, lookahead=0.0, create=False)
