"""Actors and their ports.

An :class:`Actor` reacts to events: the director calls :meth:`Actor.fire` once per tag at which the
actor has events, with the tokens that arrived at that tag waiting on its :class:`InputPort`\\ s.
During ``fire`` the actor reads them, sends tokens on its :class:`OutputPort`\\ s and may ask to be
fired again (:meth:`Actor.fire_at`).

Lifecycle: constructed → added to a director (:meth:`Director.add`) → ``initialize()`` once, when the
director initializes (schedule first events here) → ``fire()`` for each of its firings → ``wrapup()``
when the director wraps up. Tokens not read during a firing are discarded when it ends.
"""

from __future__ import annotations

import math
from typing import TYPE_CHECKING, Any, Optional

if TYPE_CHECKING:
    from .director import Director

__all__ = ["Actor", "InputPort", "OutputPort", "NoTokenError", "CausalityError"]


class NoTokenError(LookupError):
    """:meth:`InputPort.get` on a port that has no token at this firing."""


class CausalityError(ValueError):
    """An event scheduled in the model's past, or a loop of zero-delay connections."""


class _Port:
    """A named port of an actor."""

    def __init__(self, actor: "Actor", name: str) -> None:
        self.actor = actor
        self.name = name

    @property
    def full_name(self) -> str:
        """``actor.port``."""
        return f"{self.actor.name}.{self.name}"

    def __repr__(self) -> str:
        return f"<{type(self).__name__} {self.full_name}>"


class InputPort(_Port):
    """An actor's input: holds the tokens that arrived for the current firing, in arrival order."""

    def __init__(self, actor: "Actor", name: str) -> None:
        super().__init__(actor, name)
        self.tokens: list[Any] = []

    def has_token(self) -> bool:
        """True when at least one token arrived at this firing."""
        return bool(self.tokens)

    def get(self) -> Any:
        """The first token of this firing; raises :class:`NoTokenError` when there is none."""
        if not self.tokens:
            raise NoTokenError(f"no token on {self.full_name}")
        return self.tokens[0]

    def last(self) -> Any:
        """The last token of this firing; raises :class:`NoTokenError` when there is none."""
        if not self.tokens:
            raise NoTokenError(f"no token on {self.full_name}")
        return self.tokens[-1]


class OutputPort(_Port):
    """An actor's output, connected to any number of input ports.

    A ``delayed`` port promises that every token it sends has a delay (``send(value, delay=d)``):
    it does not take part in the zero-delay dependency graph, so it may close a feedback loop.
    """

    def __init__(self, actor: "Actor", name: str, delayed: bool = False) -> None:
        super().__init__(actor, name)
        self.delayed = delayed
        self.connections: list[InputPort] = []

    def connect(self, *inputs: InputPort) -> "OutputPort":
        """Connect this output to each of ``inputs``; returns self."""
        for port in inputs:
            if not isinstance(port, InputPort):
                raise TypeError(f"{self.full_name} can only be connected to an InputPort, not {port!r}")
            if port not in self.connections:
                self.connections.append(port)
        return self

    def send(self, value: Any, delay: Optional[float] = None) -> None:
        """Send ``value`` to every connected input.

        Without ``delay`` the token arrives at the current tag (the receivers fire later in the same
        tag: their depth is greater). With ``delay > 0`` it arrives at ``(now + delay, 0)``; with
        ``delay == 0`` at ``(now, microstep + 1)``, strictly after the current tag. A ``delayed``
        port requires a delay. Raises :class:`CausalityError` for a negative delay.
        """
        director = self.actor.director_or_raise()
        if delay is None:
            if self.delayed:
                raise CausalityError(f"{self.full_name} is a delayed port: send(value, delay=...) needs a delay")
            time, microstep = director.now, director.microstep
        elif not delay >= 0 or math.isinf(delay):
            raise CausalityError(f"{self.full_name}: delay must be finite and >= 0, not {delay!r}")
        elif delay == 0:
            time, microstep = director.now, director.microstep + 1
        else:
            time, microstep = director.now + delay, 0
        for port in self.connections:
            director.deliver(port, value, time, microstep)


class Actor:
    """Base class of DE actors; override :meth:`initialize`, :meth:`fire` and :meth:`wrapup`.

    Make ports in ``__init__`` with :meth:`add_input` and :meth:`add_output` (keep them as attributes)
    and connect outputs to inputs with :meth:`OutputPort.connect`.
    """

    def __init__(self, name: str) -> None:
        self.name = name
        self.director: Optional["Director"] = None
        self.inputs: dict[str, InputPort] = {}
        self.outputs: dict[str, OutputPort] = {}
        #: Rank in the zero-delay dependency graph, set by the director when it initializes.
        self.depth = 0

    def add_input(self, name: str) -> InputPort:
        """Make an input port called ``name``."""
        if name in self.inputs or name in self.outputs:
            raise ValueError(f"{self.name} already has a port named {name!r}")
        port = InputPort(self, name)
        self.inputs[name] = port
        return port

    def add_output(self, name: str, delayed: bool = False) -> OutputPort:
        """Make an output port called ``name`` (``delayed``: see :class:`OutputPort`)."""
        if name in self.inputs or name in self.outputs:
            raise ValueError(f"{self.name} already has a port named {name!r}")
        port = OutputPort(self, name, delayed)
        self.outputs[name] = port
        return port

    def director_or_raise(self) -> "Director":
        """The director this actor was added to; raises RuntimeError if none."""
        if self.director is None:
            raise RuntimeError(f"actor {self.name!r} has not been added to a director")
        return self.director

    @property
    def now(self) -> float:
        """The director's current model time."""
        return self.director_or_raise().now

    def fire_at(self, time: float) -> None:
        """Ask to be fired at ``time``: at ``(time, 0)`` if later than now, at ``(now, microstep + 1)``
        if equal to now. Raises :class:`CausalityError` for a time in the past."""
        self.director_or_raise().fire_at(self, time)

    def initialize(self) -> None:
        """Called once when the director initializes; schedule the first events here."""

    def fire(self) -> None:
        """React to the events of the current tag (tokens on the inputs, or a requested firing)."""

    def wrapup(self) -> None:
        """Called once when the director wraps up."""

    def __repr__(self) -> str:
        return f"<{type(self).__name__} {self.name!r}>"
