"""The event queue of the DE engine: firings ordered by tag, depth and sequence.

An *event* is either a pure event (an actor asked to be fired, :meth:`Actor.fire_at`) or a token
arriving at an input port. Events that go to the same actor at the same tag are gathered into one
:class:`Firing`, so that an actor fires once per tag and sees every token that arrived for it.

Firings are taken in the order of the key ``(time, microstep, depth, sequence)``:

``time``
    model time (a float);
``microstep``
    the index within superdense time: an event at the current time that is *strictly later*
    than the current tag (``fire_at(now)``, a zero delay, a message that arrives at the current
    time) gets the current microstep + 1; an event at a later time gets microstep 0;
``depth``
    the actor's rank in the graph of zero-delay connections (sources 0, every actor deeper than all
    the actors that feed it), so an actor fires after everything that can still send it a token
    at the same tag, as Ptolemy II's ``DEEvent.compareTo`` does;
``sequence``
    a counter that grows by one for each new firing: among the rest, first scheduled, first fired.
"""

from __future__ import annotations

import heapq
import math
from dataclasses import dataclass, field
from typing import TYPE_CHECKING, Any, Optional

if TYPE_CHECKING:
    from .actor import Actor, InputPort

__all__ = ["Tag", "Firing", "EventQueue"]

#: A superdense time stamp: (time, microstep).
Tag = tuple[float, int]


@dataclass(eq=False)
class Firing:
    """The events for one actor at one tag: one call of the actor's ``fire()``.

    ``pure`` is true when the actor asked to be fired (:meth:`Actor.fire_at`); ``tokens`` are the
    ``(port, value)`` pairs that arrive, in the order they were sent.
    """

    time: float
    microstep: int
    depth: int
    sequence: int
    actor: "Actor"
    pure: bool = False
    tokens: list[tuple["InputPort", Any]] = field(default_factory=list)

    @property
    def key(self) -> tuple[float, int, int, int]:
        """The order key ``(time, microstep, depth, sequence)``."""
        return (self.time, self.microstep, self.depth, self.sequence)

    def __lt__(self, other: "Firing") -> bool:
        return self.key < other.key


class EventQueue:
    """A heap of :class:`Firing`, one per ``(tag, actor)`` not yet taken.

    Scheduling an event for an actor at a tag where that actor already has a pending firing adds
    the event to that firing instead of making a new one (it keeps its place in the order).
    """

    def __init__(self) -> None:
        self._heap: list[Firing] = []
        self._pending: dict[tuple[float, int, int], Firing] = {}
        self._sequence = 0

    def __len__(self) -> int:
        """Number of firings waiting."""
        return len(self._heap)

    def peek(self) -> float:
        """Time of the next firing, or ``math.inf`` when the queue is empty."""
        return self._heap[0].time if self._heap else math.inf

    def peek_firing(self) -> Optional[Firing]:
        """The next firing without taking it, or None."""
        return self._heap[0] if self._heap else None

    def schedule(
        self,
        actor: "Actor",
        time: float,
        microstep: int,
        depth: int,
        port: Optional["InputPort"] = None,
        value: Any = None,
    ) -> Firing:
        """Add a pure event (``port`` None) or a token for ``port`` to the actor's firing at the tag."""
        slot = (time, microstep, id(actor))
        firing = self._pending.get(slot)
        if firing is None:
            firing = Firing(time, microstep, depth, self._sequence, actor)
            self._sequence += 1
            self._pending[slot] = firing
            heapq.heappush(self._heap, firing)
        if port is None:
            firing.pure = True
        else:
            firing.tokens.append((port, value))
        return firing

    def pop(self) -> Firing:
        """Take the next firing; raises IndexError when the queue is empty."""
        firing = heapq.heappop(self._heap)
        del self._pending[(firing.time, firing.microstep, id(firing.actor))]
        return firing
