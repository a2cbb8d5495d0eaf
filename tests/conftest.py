"""Fixtures: an in-process gateway, the real `rtig` executable on port 0, federations on them, test hosts and
ROS. The helpers they use, and that tests import, are in tests/support (a test module imports neither this
file nor another test module). Everything started here is stopped here, by pid."""

from __future__ import annotations

import pathlib
from typing import Callable, Iterator

import pytest

import hlacore
from hlacore import rti
from hlacore.federates.robot_world import FEDERATION as ROBOT_WORLD_FEDERATION
from hlacore.federates.robot_world import FOM_PATH as ROBOT_WORLD_FOM

from support import ROBOT_FED, Conductor, Federate, RtigProcess, joined_federation, running_rtig
from support.federations import Legit, legit_federation
from support.nethosts import NetHosts, namespaces_unavailable
from support.ros import require_ros, running_roscore


@pytest.fixture
def rtig(tmp_path: pathlib.Path) -> Iterator[RtigProcess]:
    """The real rtig binary on port 0."""
    with running_rtig(tmp_path) as server:
        yield server


@pytest.fixture
def inprocess_gateway() -> Iterator[hlacore.Gateway]:
    """An in-process gateway (hlacore.Gateway) on port 0."""
    with hlacore.Gateway(port=0) as gw:
        yield gw


@pytest.fixture
def world_federation(gateway_address: str) -> Iterator[str]:
    """The robot world's federation (hlacore.federates.robot_world's FOM) on each gateway; its address."""
    creator = rti.RTIAmbassador(gateway_address)
    creator.createFederationExecution(ROBOT_WORLD_FEDERATION, str(ROBOT_WORLD_FOM))
    yield gateway_address
    creator.destroyFederationExecution(ROBOT_WORLD_FEDERATION)


@pytest.fixture(params=["in-process", "rtig"])
def gateway_address(request: pytest.FixtureRequest) -> str:
    """The address of a gateway: both the in-process one and the real rtig executable."""
    if request.param == "in-process":
        return str(request.getfixturevalue("inprocess_gateway").address)
    return str(request.getfixturevalue("rtig").address)


@pytest.fixture
def federation(gateway_address: str) -> Iterator[Callable[[str], Federate]]:
    """Creates TestFed from tests/data/robot.fed; returns a function joining federates to it."""
    with joined_federation(gateway_address, "TestFed", ROBOT_FED, Federate) as join:
        yield join


@pytest.fixture
def conductor(rtig: RtigProcess) -> Iterator[Conductor]:
    """A Conductor (support.Conductor) on the test's rtig; it ends its peers and TestFed afterwards."""
    c = Conductor(rtig.address)
    yield c
    c.close()


@pytest.fixture
def legit(rtig: RtigProcess) -> Iterator[Legit]:
    """Two well-behaved federates on the test's rtig (support.federations.legit_federation), to show that
    they keep working beside hostile clients."""
    with legit_federation(rtig.address) as fed:
        yield fed


@pytest.fixture
def nethosts() -> Iterator[NetHosts]:
    """Make test hosts with ``nethosts.add(name)`` (support.nethosts); all are removed after the test."""
    why = namespaces_unavailable()
    if why:
        pytest.fail(f"test hosts need network namespaces: {why}")
    hosts = NetHosts()
    try:
        yield hosts
    finally:
        hosts.close()


@pytest.fixture
def ros() -> None:
    """Skips the test without ROS 1 (fails it under CI=true; support.ros.require_ros)."""
    require_ros()


@pytest.fixture
def roscore(ros: None, tmp_path: pathlib.Path) -> Iterator[dict[str, str]]:
    """A real roscore for the test (support.ros.running_roscore): the environment of its ROS processes."""
    with running_roscore(tmp_path / "ros") as env:
        yield env
