"""The standalone discrete-event director: SimPy's loop over Ptolemy II's event order.

``peek()`` gives the time of the next firing, ``step()`` performs it, ``run(until)`` repeats. No RTI is
involved: this is the director for unit tests of models and for models that run alone. The HLA-aware
director (:class:`hlacore.federates.de.hla.HlaDirector`) is this loop with a time grant in the middle.

States: *built* (actors added, ports connected) → *initialized* on the first ``initialize()``,
``peek()``, ``step()`` or ``run()`` (the dependency graph is ranked and every actor's ``initialize()``
has run; no actor can be added any more) → *wrapped up* after ``wrapup()``.
"""

from __future__ import annotations

import math
from typing import Any, Optional

from .actor import Actor, CausalityError, InputPort
from .events import EventQueue, Firing

__all__ = ["Director", "EmptySchedule"]


class EmptySchedule(LookupError):
    """:meth:`Director.step` with no event left."""


class Director:
    """Runs the actors added to it in the order of their events' tags (see :mod:`.events`).

    ``now`` and ``microstep`` are the tag of the firing in progress or last done; they start at
    ``(start_time, 0)`` and never decrease.
    """

    def __init__(self, start_time: float = 0.0) -> None:
        self.start_time = float(start_time)
        self.now = self.start_time
        self.microstep = 0
        self.actors: list[Actor] = []
        #: Number of firings performed so far.
        self.firings = 0
        self._queue = EventQueue()
        self._initialized = False
        self._wrapped_up = False
        # True once a firing has happened at the current tag: "now" then means the next microstep.
        self._fired_at_tag = False

    # ---- building ----

    def add(self, *actors: Actor) -> None:
        """Add actors to the model; raises RuntimeError once the director has initialized."""
        if self._initialized:
            raise RuntimeError("actors must be added before the director initializes")
        for actor in actors:
            if actor.director is not None and actor.director is not self:
                raise RuntimeError(f"actor {actor.name!r} already belongs to another director")
            if actor not in self.actors:
                actor.director = self
                self.actors.append(actor)

    # ---- lifecycle ----

    def initialize(self) -> None:
        """Rank the actors by zero-delay dependencies and call every actor's ``initialize()`` (once).

        Raises :class:`CausalityError` for a loop of zero-delay connections and RuntimeError for a
        connection to an actor that was not added.
        """
        if self._initialized:
            return
        self._rank()
        self._initialized = True
        self._begin()
        for actor in list(self.actors):
            actor.initialize()

    def _begin(self) -> None:
        """Hook between ranking and the actors' ``initialize()``; alone, nothing to do."""

    def wrapup(self) -> None:
        """Call every actor's ``wrapup()`` (once)."""
        if self._wrapped_up:
            return
        self._wrapped_up = True
        for actor in self.actors:
            actor.wrapup()

    # ---- the loop ----

    def peek(self) -> float:
        """Time of the next firing, or ``math.inf`` when no event is scheduled."""
        self.initialize()
        return self._queue.peek()

    def step(self) -> None:
        """Perform the next firing: one actor, one tag, every event it has there.

        Raises :class:`EmptySchedule` when no event is scheduled.
        """
        self.initialize()
        if not len(self._queue):
            raise EmptySchedule("no event is scheduled")
        self._fire(self._queue.pop())

    def run(self, until: Optional[float] = None, max_steps: Optional[int] = None) -> int:
        """Fire until no event is left, or until the next event is later than ``until``; returns the
        number of firings done.

        Events at ``until`` itself are processed; afterwards ``now`` is ``until`` (when it is later).
        ``max_steps`` bounds the number of firings (the run then stops where it is).
        """
        self.initialize()
        count = 0
        while max_steps is None or count < max_steps:
            upcoming = self.peek()
            if until is not None and upcoming > until:
                if self._reach(until):
                    continue
                break
            if upcoming == math.inf:
                break
            self.step()
            count += 1
        else:
            return count
        if until is not None and until > self.now:
            self._set_time(until)
        return count

    def _reach(self, until: float) -> bool:
        """Hook for :meth:`run` when the next event is beyond ``until``: True if it did something that
        may have scheduled events (a time advance), so the loop looks again. Alone, nothing to do."""
        return False

    def _fire(self, firing: Firing) -> None:
        if (firing.time, firing.microstep) < (self.now, self.microstep):
            raise CausalityError(
                f"firing of {firing.actor.name!r} at ({firing.time}, {firing.microstep}) is before "
                f"the current tag ({self.now}, {self.microstep})"
            )
        self.now, self.microstep = firing.time, firing.microstep
        self._fired_at_tag = True  # from here on, "now" for new events means the next microstep
        actor = firing.actor
        for port, value in firing.tokens:
            port.tokens.append(value)
        try:
            actor.fire()
        finally:
            for port in actor.inputs.values():
                port.tokens.clear()
            self.firings += 1

    def _set_time(self, time: float) -> None:
        self.now, self.microstep, self._fired_at_tag = time, 0, False

    # ---- scheduling ----

    def fire_at(self, actor: Actor, time: float) -> None:
        """Schedule a pure event for ``actor``: at ``(time, 0)`` if later than now, at the next tag
        of the current time if ``time == now``. Raises :class:`CausalityError` for a past time."""
        self._check_actor(actor)
        time = float(time)
        if not time >= self.now or math.isinf(time):
            raise CausalityError(f"{actor.name!r} asked to fire at {time}, not a finite time >= now ({self.now})")
        self._queue.schedule(actor, *self._tag_at(time), actor.depth)

    def deliver(self, port: InputPort, value: Any, time: float, microstep: int) -> None:
        """Schedule the arrival of a token at ``port`` at tag ``(time, microstep)`` (used by
        :meth:`OutputPort.send`). Raises :class:`CausalityError` for a tag before the current one."""
        self._check_actor(port.actor)
        if (time, microstep) < (self.now, self.microstep):
            raise CausalityError(f"token for {port.full_name} at ({time}, {microstep}) is in the past")
        self._queue.schedule(port.actor, time, microstep, port.actor.depth, port, value)

    def inject(self, port: InputPort, value: Any, time: float) -> tuple[float, int]:
        """Put a token coming from outside the model on ``port`` at ``time``; returns the tag used.

        A time later than now gives ``(time, 0)``. A time equal to now gives the next tag of the
        current time, and so does a time in the past: it is *clamped* to now (a late message).
        """
        self._check_actor(port.actor)
        tag = self._tag_at(max(float(time), self.now))
        self._queue.schedule(port.actor, tag[0], tag[1], port.actor.depth, port, value)
        return tag

    def _tag_at(self, time: float) -> tuple[float, int]:
        if time > self.now:
            return (time, 0)
        return (self.now, self.microstep + 1 if self._fired_at_tag else self.microstep)

    def _check_actor(self, actor: Actor) -> None:
        if actor.director is not self:
            raise RuntimeError(f"actor {actor.name!r} was not added to this director")

    # ---- the dependency graph ----

    def _rank(self) -> None:
        """Depth = longest path from a source over zero-delay connections (Kahn's algorithm)."""
        successors: dict[int, list[Actor]] = {id(a): [] for a in self.actors}
        indegree: dict[int, int] = {id(a): 0 for a in self.actors}
        for actor in self.actors:
            for out in actor.outputs.values():
                for port in out.connections:
                    if port.actor.director is not self:
                        raise RuntimeError(f"{out.full_name} is connected to {port.full_name}, "
                                           f"whose actor was not added to this director")
                    if not out.delayed:
                        successors[id(actor)].append(port.actor)
                        indegree[id(port.actor)] += 1
        depth = {id(a): 0 for a in self.actors}
        ready = [a for a in self.actors if indegree[id(a)] == 0]
        done = 0
        while ready:
            actor = ready.pop()
            done += 1
            for succ in successors[id(actor)]:
                depth[id(succ)] = max(depth[id(succ)], depth[id(actor)] + 1)
                indegree[id(succ)] -= 1
                if indegree[id(succ)] == 0:
                    ready.append(succ)
        if done != len(self.actors):
            looped = sorted(a.name for a in self.actors if indegree[id(a)] > 0)
            raise CausalityError(f"zero-delay loop through {', '.join(looped)}: put a delay in the loop "
                                 f"(an OutputPort made with delayed=True)")
        for actor in self.actors:
            actor.depth = depth[id(actor)]
