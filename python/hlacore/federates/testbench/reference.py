"""The reference model: the robot's A* mission as a DE actor, one expected cell per cycle."""

from __future__ import annotations

from dataclasses import dataclass
from typing import Iterator, Optional

from hlacore.federates.de import Actor
from hlacore.federates.robot_driver.navigation import Cell, Scenario, mission

__all__ = ["Expected", "ReferenceModel"]


@dataclass(frozen=True)
class Expected:
    """What the robot should report for ``cycle``: ``cell``, arriving at model time ``time``."""

    cycle: int
    cell: Cell
    time: float


class ReferenceModel(Actor):
    """On a :class:`Scenario` at ``input``, emits :class:`Expected` for cycles ``0 .. cycles - 1`` on
    ``output``, cycle ``k`` at ``start + k + latency`` (``latency``: when the robot's report of a cycle is
    due, its lookahead in stepped mode). The displacement is the desired one: the model is calibrated by
    design."""

    def __init__(self, name: str, cycles: int, latency: float = 0.5) -> None:
        super().__init__(name)
        self.cycles = cycles
        self.latency = latency
        self.input = self.add_input("input")
        self.output = self.add_output("output")
        self._cells: Optional[Iterator[Cell]] = None
        self._k = 0
        self._origin = 0.0

    def fire(self) -> None:
        """On a new scenario, start its mission; otherwise send the cycle's :class:`Expected` and schedule the
        next cycle."""
        if self.input.has_token():
            scenario: Scenario = self.input.last()
            self._cells, self._k = mission(scenario), 0
            self._origin = self.now
            if self.cycles > 0:
                self.fire_at(self._origin + self.latency)
            return
        if self._cells is None or self._k >= self.cycles:
            return
        self.output.send(Expected(self._k, next(self._cells), self.now))
        self._k += 1
        if self._k < self.cycles:
            self.fire_at(self._origin + self._k + self.latency)
