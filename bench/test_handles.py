"""Typed handles in the Python hot path: a reflection's ``attributes[handle]`` hashes the handle and
compares it with the key (two handle objects with one value: the callback builds new ones). Each round
does 1000 operations, so the figure per round in µs is ns per operation."""

from __future__ import annotations

import pathlib
from typing import Any, Callable, Iterator

import pytest

import hlacore
from hlacore import rti

OPERATIONS = range(1000)
ROBOT_FED = pathlib.Path(__file__).resolve().parent.parent / "tests" / "data" / "robot.fed"

pytestmark = pytest.mark.benchmark(group="handles (µs per round = ns per operation)")


@pytest.fixture(scope="module")
def handles() -> Iterator[tuple[Any, Any]]:
    """Two ``location`` handle objects of one federation, equal and distinct."""
    with hlacore.Gateway(port=0) as gw:
        rtia = rti.RTIAmbassador(gw.address)
        rtia.createFederationExecution("Handles", str(ROBOT_FED))
        rtia.joinFederationExecution("bench", "Handles", rti.FederateAmbassador())
        robot = rtia.getObjectClassHandle("robot")
        first, second = (rtia.getAttributeHandle("location", robot) for _ in range(2))
        assert first == second and first is not second
        yield first, second
        rtia.resignFederationExecution(rti.ResignAction.NoAction)


def times_1000(operation: Callable[[], object]) -> Callable[[], None]:
    def run() -> None:
        for _ in OPERATIONS:
            operation()
    return run


def test_handle_equality(benchmark: Any, handles: tuple[Any, Any]) -> None:
    first, second = handles
    benchmark(times_1000(lambda: first == second))


def test_handle_hash(benchmark: Any, handles: tuple[Any, Any]) -> None:
    _, second = handles
    benchmark(times_1000(lambda: hash(second)))


def test_dict_lookup_by_handle(benchmark: Any, handles: tuple[Any, Any]) -> None:
    first, second = handles
    attributes = {first: b"value"}
    benchmark(times_1000(lambda: attributes[second]))
