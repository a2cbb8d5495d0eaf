"""The checker (scoreboard): pairs the robot's reports with the reference by cycle; value and time errors.

A cycle has a **value error** when the robot's measured cell differs from the reference cell, and a
**time error** when its report arrived (model time at which the testbench fired it) more than
``precision`` away from the reference time, or never arrived (``missing``).
"""

from __future__ import annotations

import time
from dataclasses import dataclass
from typing import Optional

from hlacore.federates.de import Actor, Received
from hlacore.federates.robot_driver.navigation import Cell
from hlacore.federates.robot_driver.report import LocationReport

from .reference import Expected

__all__ = ["Verdict", "Checker"]


@dataclass(frozen=True)
class Verdict:
    """The check of one cycle.

    ``arrival``: the model time the report was fired at (None: missing); ``timestamp``: its HLA timestamp
    (None: receive order or missing); ``observed``: wall clock (``time.monotonic()``) of the check.
    """

    cycle: int
    expected: Cell
    expected_time: float
    actual: Optional[Cell]
    arrival: Optional[float]
    timestamp: Optional[float]
    report: Optional[LocationReport]
    observed: float

    @property
    def value_error(self) -> bool:
        """The robot is not where the reference is (a missing report is not a value error)."""
        return self.actual is not None and self.actual != self.expected

    @property
    def missing(self) -> bool:
        """No report arrived for this cycle."""
        return self.actual is None

    def time_error(self, precision: float) -> bool:
        """Late, early or missing by more than ``precision``."""
        return self.arrival is None or abs(self.arrival - self.expected_time) > precision


class Checker(Actor):
    """Inputs ``expected`` (:class:`Expected`) and ``actual`` (:class:`Received` of a report); outputs a
    :class:`Verdict` per cycle on ``output`` as soon as both sides of a cycle are in. :meth:`finish`
    issues the verdicts of cycles whose report never came."""

    def __init__(self, name: str, precision: float = 0.25) -> None:
        super().__init__(name)
        self.precision = precision
        self.expected = self.add_input("expected")
        self.actual = self.add_input("actual")
        self.output = self.add_output("output")
        self.verdicts: list[Verdict] = []
        self._expected: dict[int, Expected] = {}
        self._actual: dict[int, Received] = {}

    def fire(self) -> None:
        """Pair the expected and the reported locations by cycle, and send a :class:`Verdict` for each pair."""
        for token in self.expected.tokens:
            self._expected[token.cycle] = token
        for record in self.actual.tokens:
            report: LocationReport = record.values["location"]
            self._actual.setdefault(report.cycle, record)
        for cycle in sorted(set(self._expected) & set(self._actual)):
            self.output.send(self._verdict(self._expected.pop(cycle), self._actual.pop(cycle)))

    def _verdict(self, expected: Expected, record: Optional[Received]) -> Verdict:
        report: Optional[LocationReport] = None if record is None else record.values["location"]
        verdict = Verdict(
            expected.cycle, expected.cell, expected.time,
            None if report is None else report.cell,
            None if record is None else record.time,
            None if record is None else record.timestamp,
            report, time.monotonic(),
        )
        self.verdicts.append(verdict)
        return verdict

    def finish(self) -> list[Verdict]:
        """Verdicts (missing reports) for the expected cycles still unpaired, after the run; returns them
        (they are not sent on ``output``: the model no longer runs)."""
        return [self._verdict(self._expected.pop(cycle), None) for cycle in sorted(self._expected)]

    @property
    def value_errors(self) -> list[Verdict]:
        """Verdicts with a value error, by cycle."""
        return sorted((v for v in self.verdicts if v.value_error), key=lambda v: v.cycle)

    @property
    def time_errors(self) -> list[Verdict]:
        """Verdicts with a time error (late, early or missing), by cycle."""
        return sorted((v for v in self.verdicts if v.time_error(self.precision)), key=lambda v: v.cycle)
