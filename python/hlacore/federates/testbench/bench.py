"""The testbench federate: sequencer, reference model, checker and display on an :class:`HlaDirector`.

Model (DE actors)::

    Sequencer --scenario--> ReferenceModel --expected--> Checker --verdicts--> Display
    ObjectSubscriber(robot.location) --received-------->/

:meth:`Testbench.run` initializes the director (regulating and constrained, TAR with step 1 by default),
waits until the robot's object is discovered (the robot registers it once the testbench subscribed), then
runs the model until ``start + cycles`` and issues the verdicts of missing reports. ``pace`` (wall seconds
per unit of model time, Ptolemy's ``synchronizeToRealTime``) keeps the model in step with the wall clock
when the robot does not synchronize (best-effort mode); None runs as fast as the grants come.
"""

from __future__ import annotations

import time
from dataclasses import dataclass, field
from typing import Any, Callable, Optional

from hlacore import rti
from hlacore.federates.de import HlaDirector, ObjectSubscriber
from hlacore.federates.robot_driver.navigation import Scenario
from hlacore.federates.robot_driver.report import REPORT_CODEC, decode_report

from .checker import Checker, Verdict
from .delays import SAME_CLOCK, Stats, delay_table
from .display import Display, format_verdict
from .reference import ReferenceModel
from .sequencer import Sequencer

__all__ = ["ArrivalClock", "Testbench", "TestbenchResult"]


class ArrivalClock(rti.FederateAmbassador):
    """The director's delegate: the wall-clock time each cycle's report was reflected, and discoveries.

    Every callback also goes to ``inner`` (the delegate the director had before), when there is one.
    """

    def __init__(self, inner: Optional[rti.FederateAmbassador] = None) -> None:
        self.inner = inner
        self.reflected_at: dict[int, float] = {}
        self.discovered: list[str] = []
        #: Every reflection, in order: its timestamp (None in receive order) and values by attribute handle.
        self.reflections: list[tuple[Optional[float], tuple[tuple[int, bytes], ...]]] = []

    def __getattr__(self, name: str) -> Any:
        inner = self.__dict__.get("inner")
        if inner is None or name.startswith("_"):
            raise AttributeError(name)
        return getattr(inner, name)

    def discoverObjectInstance(self, obj: rti.ObjectHandle, cls: rti.ObjectClassHandle, name: str) -> None:
        """Note the robot's object."""
        self.discovered.append(name)
        if self.inner is not None and hasattr(self.inner, "discoverObjectInstance"):
            self.inner.discoverObjectInstance(obj, cls, name)

    def reflectAttributeValues(self, obj: Any, attributes: dict[Any, bytes], tag: str, *rest: Any) -> None:
        """Note when a report came in (the first reflection of its cycle), and what came."""
        now = time.monotonic()
        stamp = rest[2] if len(rest) > 2 else None  # order, transport, time
        self.reflections.append((None if stamp is None else float(stamp),
                                 tuple(sorted((int(h), bytes(v)) for h, v in attributes.items()))))
        for data in attributes.values():
            try:
                cycle = decode_report(data).cycle
            except ValueError:
                continue
            self.reflected_at.setdefault(cycle, now)
        if self.inner is not None and hasattr(self.inner, "reflectAttributeValues"):
            self.inner.reflectAttributeValues(obj, attributes, tag, *rest)


@dataclass
class TestbenchResult:
    """What the checker found, per cycle, and the delay table."""

    verdicts: list[Verdict]
    precision: float
    delays: dict[str, Stats]
    reflected_at: dict[int, float] = field(default_factory=dict)
    #: The testbench's clock offset to the gateway's, (offset, uncertainty) in seconds.
    bench_clock: tuple[float, float] = SAME_CLOCK
    #: Every reflection received, in order: (timestamp or None, values by attribute handle).
    reflections: list[tuple[Optional[float], tuple[tuple[int, bytes], ...]]] = field(default_factory=list)

    @property
    def value_errors(self) -> list[Verdict]:
        """Cycles where the robot is not where the reference is."""
        return [v for v in self.verdicts if v.value_error]

    @property
    def time_errors(self) -> list[Verdict]:
        """Cycles whose report was late, early or missing (beyond the precision)."""
        return [v for v in self.verdicts if v.time_error(self.precision)]

    @property
    def passed(self) -> bool:
        """No value error and no time error."""
        return not self.value_errors and not self.time_errors

    def trajectory(self) -> list[Optional[tuple[int, int]]]:
        """The robot's measured cell per cycle (None where missing)."""
        return [v.actual for v in self.verdicts]


class Testbench:
    """The testbench model on ``director`` for ``cycles`` cycles of ``scenario``.

    ``latency``: when a cycle's report is due after the cycle's start (the robot's lookahead);
    ``precision``: the allowed distance, in model time, between arrival and due time; ``write``: where
    the display's lines go.
    """

    def __init__(
        self,
        director: HlaDirector,
        scenario: Scenario,
        cycles: int,
        latency: float = 0.5,
        precision: float = 0.25,
        write: Callable[[str], None] = print,
        robot_instance: str = "robot",
    ) -> None:
        if not isinstance(director.ambassador.delegate, ArrivalClock):
            director.ambassador.delegate = ArrivalClock(director.ambassador.delegate)
        self.director = director
        self.clock: ArrivalClock = director.ambassador.delegate
        self.scenario = scenario
        self.cycles = cycles
        self.precision = precision
        self.write = write
        self.sequencer = Sequencer("sequencer", scenario)
        self.reference = ReferenceModel("reference", cycles, latency)
        self.robot = ObjectSubscriber("robot", "robot", {"location": REPORT_CODEC}, instance_name=robot_instance)
        self.checker = Checker("checker", precision)
        self.display = Display("display", precision, write)
        self.sequencer.output.connect(self.reference.input)
        self.reference.output.connect(self.checker.expected)
        self.robot.received.connect(self.checker.actual)
        self.checker.output.connect(self.display.input)
        self.bench_clock = SAME_CLOCK
        director.add(self.sequencer, self.reference, self.robot, self.checker, self.display)

    def wait_for_robot(self, timeout: float) -> None:
        """Initialize the director and tick until the robot's object is discovered (TimeoutError after
        ``timeout`` seconds)."""
        self.director.initialize()
        deadline = time.monotonic() + timeout
        while not self.clock.discovered:
            if time.monotonic() > deadline:
                raise TimeoutError(f"testbench: no robot discovered within {timeout} s")
            self.director.rtia.tick(0.05, 0.05)
        self.bench_clock = self.director.rtia.clock_offset()

    def run(self, pace: Optional[float] = None, discover_timeout: float = 60.0) -> TestbenchResult:
        """Wait for the robot, run the model to ``start + cycles`` (paced if ``pace``), check, return."""
        director = self.director
        self.wait_for_robot(discover_timeout)
        until = director.start_time + self.cycles
        origin = time.monotonic()
        for _ in range(100 * self.cycles + 100):  # a bound: a few firings per cycle
            upcoming = director.peek()
            if upcoming > until:
                break
            if pace:
                delay = origin + (upcoming - director.start_time) * pace - time.monotonic()
                if delay > 0:
                    time.sleep(delay)
            director.step()
        director.run(until=until)
        for verdict in self.checker.finish():
            self.write(format_verdict(verdict, self.precision))
        director.wrapup()
        return self.result()

    def result(self) -> TestbenchResult:
        """The verdicts so far (all of them after :meth:`run`; an interrupted run's partial ones before)."""
        verdicts = sorted(self.checker.verdicts, key=lambda v: v.cycle)
        reflected = dict(self.clock.reflected_at)
        return TestbenchResult(verdicts, self.precision, delay_table(verdicts, reflected, bench_clock=self.bench_clock),
                               reflected, self.bench_clock, list(self.clock.reflections))
