"""A few ready-made actors: sources, a function, a delay and a recorder."""

from __future__ import annotations

from dataclasses import dataclass
from typing import Any, Callable, Iterable, Optional

from .actor import Actor

__all__ = ["Clock", "TimedSource", "Function", "Delay", "Recorder", "Record"]


class Clock(Actor):
    """Sends the cycle index ``k`` (0, 1, 2, ...) on ``output`` at ``start + offset + k * period``.

    ``cycles`` bounds the number of ticks (None: forever). Like Ptolemy II's ``Clock``, it is the
    periodic trigger of a control loop.
    """

    def __init__(self, name: str, period: float, offset: float = 0.0, cycles: Optional[int] = None) -> None:
        super().__init__(name)
        if not period > 0:
            raise ValueError(f"Clock {name!r}: period must be > 0, not {period!r}")
        self.period = float(period)
        self.offset = float(offset)
        self.cycles = cycles
        self.output = self.add_output("output")
        self._k = 0
        self._origin = 0.0

    def initialize(self) -> None:
        """Schedule the first tick at the start time plus ``offset`` (none when ``cycles`` is 0)."""
        self._k = 0
        self._origin = self.director_or_raise().start_time + self.offset
        if self.cycles is None or self.cycles > 0:
            self.fire_at(self._origin)

    def fire(self) -> None:
        """Send the tick's number and schedule the next tick, until ``cycles``."""
        self.output.send(self._k)
        self._k += 1
        if self.cycles is None or self._k < self.cycles:
            self.fire_at(self._origin + self._k * self.period)


class TimedSource(Actor):
    """Sends each ``value`` of ``items`` (``(time, value)`` pairs) on ``output`` at its ``time``.

    Values with equal times go out in one firing, in the order given.
    """

    def __init__(self, name: str, items: Iterable[tuple[float, Any]]) -> None:
        super().__init__(name)
        self.items = sorted(((float(t), v) for t, v in items), key=lambda item: item[0])
        self.output = self.add_output("output")
        self._next = 0

    def initialize(self) -> None:
        """Schedule a firing at the first item's time."""
        self._next = 0
        if self.items:
            self.fire_at(self.items[0][0])

    def fire(self) -> None:
        """Send the values due by now and schedule a firing at the next item's time."""
        while self._next < len(self.items) and self.items[self._next][0] <= self.now:
            self.output.send(self.items[self._next][1])
            self._next += 1
        if self._next < len(self.items):
            self.fire_at(self.items[self._next][0])


class Function(Actor):
    """Sends ``function(token)`` on ``output`` for each token on ``input``, at the same tag."""

    def __init__(self, name: str, function: Callable[[Any], Any]) -> None:
        super().__init__(name)
        self.function = function
        self.input = self.add_input("input")
        self.output = self.add_output("output")

    def fire(self) -> None:
        """Send ``function(token)`` for each token on ``input``."""
        for token in self.input.tokens:
            self.output.send(self.function(token))


class Delay(Actor):
    """Sends each token of ``input`` on ``output`` ``delay`` later (0: at the next microstep).

    Its output is a delayed port, so it may close a feedback loop (Ptolemy II's ``TimedDelay``).
    """

    def __init__(self, name: str, delay: float) -> None:
        super().__init__(name)
        if not delay >= 0:
            raise ValueError(f"Delay {name!r}: delay must be >= 0, not {delay!r}")
        self.delay = float(delay)
        self.input = self.add_input("input")
        self.output = self.add_output("output", delayed=True)

    def fire(self) -> None:
        """Send each token on ``input`` ``delay`` later."""
        for token in self.input.tokens:
            self.output.send(token, delay=self.delay)


@dataclass(frozen=True)
class Record:
    """One token seen by a :class:`Recorder`: its tag and value."""

    time: float
    microstep: int
    value: Any


class Recorder(Actor):
    """Keeps every token that arrives on ``input`` (any number of connections) as a :class:`Record`."""

    def __init__(self, name: str) -> None:
        super().__init__(name)
        self.input = self.add_input("input")
        self.records: list[Record] = []

    @property
    def values(self) -> list[Any]:
        """The recorded values, in arrival order."""
        return [r.value for r in self.records]

    @property
    def times(self) -> list[float]:
        """The recorded times, in arrival order."""
        return [r.time for r in self.records]

    def fire(self) -> None:
        """Append each token on ``input`` to :attr:`records`, with the director's tag."""
        director = self.director_or_raise()
        for token in self.input.tokens:
            self.records.append(Record(director.now, director.microstep, token))
