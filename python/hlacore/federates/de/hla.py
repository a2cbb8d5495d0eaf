"""The HLA-aware director: the DE loop with an RTI time grant in the middle.

Before it fires an event at time ``t`` later than its last grant, :class:`HlaDirector` asks the RTI for
time and ticks until granted, in one of the two modes of Ptolemy II's ``HlaManager``:

* :attr:`TimeMode.NER` (event-driven): ``nextEventRequest(t)``. The grant is ``t``, or earlier when a
  timestamped message arrives first; that message became an event at its timestamp, so it is fired
  next.
* :attr:`TimeMode.TAR` (time-stepped): ``timeAdvanceRequest(start + k * step)`` for the next grid
  point, one grid point at a time, until the grant reaches ``t``; events between grid points are
  fired once the grid point after them is granted.

Either way the director fires only events at or before its last grant (``now <= granted`` always),
so it never runs ahead of the federation. Reflections and interactions received while it waits
become events at their timestamps; receive-order ones at the current time, ``max(now, granted)``.
Timestamped updates and interactions sent by the model carry ``max(now, granted) + lookahead``,
the lowest time the sending rule allows (Ptolemy's NER and TAR rules in one formula).
"""

from __future__ import annotations

import enum
import math
from typing import TYPE_CHECKING, Any, Optional, Union

from hlacore import rti

from .actor import Actor
from .director import Director, EmptySchedule

if TYPE_CHECKING:
    from .hla_actors import InteractionReceiver, ObjectSubscriber

__all__ = ["HlaActor", "HlaDirector", "TimeMode", "DirectorAmbassador"]


class TimeMode(enum.Enum):
    """How :class:`HlaDirector` asks the RTI for time (Ptolemy II ``HlaManager.timeManagementService``)."""

    NER = "NER"
    """Event-driven: ``nextEventRequest(next event time)``."""
    TAR = "TAR"
    """Time-stepped: ``timeAdvanceRequest(start + k * step)``, one grid point at a time."""


class HlaDirector(Director):
    """A :class:`Director` for a federate: never fires past the time the RTI granted.

    ``rtia`` must be joined with :attr:`ambassador` as its federate ambassador (or use :meth:`join`,
    which does both). On :meth:`initialize` the director enables time regulation (``lookahead``, which
    must then be > 0) and time constrained as configured, waits for both callbacks, takes the
    federate's time as its start time, then lets the HLA actors publish, subscribe and register
    their objects, and then initializes every actor.

    ``grant_timeout`` (seconds, None: wait for ever) bounds each wait for a callback; on
    :class:`TimeoutError` the request stays pending and the next :meth:`step` or :meth:`run` waits
    for it again. ``delegate`` receives every callback too (after the director's handling), and the
    ones the director does not handle (synchronization points, ...).
    """

    def __init__(
        self,
        rtia: rti.RTIAmbassador,
        *,
        mode: Union[TimeMode, str] = TimeMode.NER,
        step: float = 1.0,
        lookahead: float = 0.1,
        regulating: bool = True,
        constrained: bool = True,
        grant_timeout: Optional[float] = None,
        delegate: Optional[rti.FederateAmbassador] = None,
    ) -> None:
        super().__init__(0.0)
        self.rtia = rtia
        self.mode = TimeMode(mode.upper()) if isinstance(mode, str) else mode
        if self.mode is TimeMode.TAR and not (step > 0 and math.isfinite(step)):
            raise ValueError(f"TAR mode needs a finite step > 0, not {step!r}")
        if regulating and not (lookahead > 0 and math.isfinite(lookahead)):
            raise ValueError(f"a regulating director needs a finite lookahead > 0, not {lookahead!r}")
        self.step_size = float(step)
        self.lookahead = float(lookahead)
        self.regulating = regulating
        self.constrained = constrained
        self.grant_timeout = grant_timeout
        self.ambassador = DirectorAmbassador(self, delegate)
        #: The federate's time as of the last grant (the start time before the first one).
        self.granted = 0.0
        #: Every grant received, in order.
        self.grants: list[float] = []
        self._pending: Optional[float] = None
        self._grid_index = 1
        self._timestamp_order: Optional[rti.OrderingHandle] = None
        self._published: dict[rti.ObjectClassHandle, set[rti.AttributeHandle]] = {}
        self._subscribed: dict[rti.ObjectClassHandle, set[rti.AttributeHandle]] = {}
        self._subscribers: dict[rti.ObjectClassHandle, list["ObjectSubscriber"]] = {}
        self._receivers: dict[rti.InteractionClassHandle, list["InteractionReceiver"]] = {}
        self._interactions_published: set[rti.InteractionClassHandle] = set()
        self._objects: dict[rti.ObjectHandle, tuple[rti.ObjectClassHandle, str]] = {}
        self._registered: dict[tuple[rti.ObjectClassHandle, str], rti.ObjectHandle] = {}

    @classmethod
    def join(
        cls,
        federate_name: str,
        federation_name: str,
        fed_file: Optional[str] = None,
        address: Optional[str] = None,
        **options: Any,
    ) -> "HlaDirector":
        """Connect to the RTI at ``address`` (see :class:`hlacore.rti.RTIAmbassador`), create the
        federation from ``fed_file`` if given (an existing one is fine), join it as ``federate_name``
        and return the director (``options`` go to the constructor).

        Raises what ``createFederationExecution`` and ``joinFederationExecution`` raise.
        """
        rtia = rti.RTIAmbassador(address)
        director = cls(rtia, **options)
        rtia.create_or_join(federate_name, federation_name, fed_file, director.ambassador)
        return director

    def resign(self, action: int = rti.ResignAction.DeleteObjectsAndReleaseAttributes) -> None:
        """``resignFederationExecution(action)`` (HLA 1.3 §4.5); call :meth:`wrapup` first if needed."""
        self.rtia.resignFederationExecution(action)

    # ---- the loop with the grant in the middle ----

    def step(self) -> None:
        """Perform the next firing, first asking the RTI for its time if it is beyond the last grant.

        Raises :class:`EmptySchedule` with no local event, :class:`TimeoutError` when a grant does not
        come within ``grant_timeout`` (nothing was fired; the request stays pending).
        """
        self.initialize()
        upcoming = self.peek()
        if upcoming == math.inf:
            raise EmptySchedule("no event is scheduled")
        while upcoming > self.granted:
            self._advance(upcoming, cap=None)
            upcoming = self.peek()
        super().step()

    def _reach(self, until: float) -> bool:
        if self.granted >= until:
            return False
        self._advance(until, cap=until)
        return True

    def _advance(self, target: float, cap: Optional[float]) -> None:
        """One request and its grant: NER(target), or TAR(next grid point, no later than ``cap``)."""
        if self._pending is None:
            if self.mode is TimeMode.NER:
                request = target
                self.rtia.nextEventRequest(request)
            else:
                request = self._next_grid_point()
                if cap is not None:
                    request = min(request, cap)
                self.rtia.timeAdvanceRequest(request)
            self._pending = request
        granted = self.rtia.await_grant(self.grant_timeout)
        self._pending = None
        self.granted = granted
        self.grants.append(granted)

    def _next_grid_point(self) -> float:
        while self.start_time + self._grid_index * self.step_size <= self.granted:
            self._grid_index += 1
        return self.start_time + self._grid_index * self.step_size

    @property
    def pending_request(self) -> Optional[float]:
        """The time of the request waiting for its grant, or None."""
        return self._pending

    # ---- times for what goes out and what comes in ----

    def send_time(self, extra: float = 0.0) -> float:
        """Timestamp for a message sent now: ``max(now, granted) + lookahead + extra``."""
        return max(self.now, self.granted) + self.lookahead + extra

    def receive_time(self) -> float:
        """Event time for a receive-order message arriving now: ``max(now, granted)``."""
        return max(self.now, self.granted)

    # ---- initialization ----

    def _begin(self) -> None:
        self.rtia.enable_time_management(
            self.lookahead, self.grant_timeout, regulating=self.regulating, constrained=self.constrained
        )
        start = float(self.rtia.queryFederateTime())
        self.start_time = self.granted = start
        self._set_time(start)
        self._timestamp_order = self.rtia.getOrderingHandle("Timestamp")
        hla_actors = [a for a in self.actors if isinstance(a, HlaActor)]
        for actor in hla_actors:
            actor.declare(self)
        for actor in hla_actors:
            actor.register(self)

    # ---- declarations, used by the HLA actors ----

    def publish_attributes(self, object_class: rti.ObjectClassHandle, attributes: set[rti.AttributeHandle]) -> None:
        """Add ``attributes`` to what this federate publishes of ``object_class`` (publishObjectClass
        replaces the set, so the director keeps the union)."""
        published = self._published.setdefault(object_class, set())
        published |= attributes
        self.rtia.publishObjectClass(object_class, sorted(published, key=int))

    def subscribe_attributes(
        self, object_class: rti.ObjectClassHandle, attributes: set[rti.AttributeHandle], subscriber: "ObjectSubscriber"
    ) -> None:
        """Subscribe to ``attributes`` of ``object_class`` (kept as a union) and route reflections of
        that class to ``subscriber``."""
        subscribed = self._subscribed.setdefault(object_class, set())
        subscribed |= attributes
        self._subscribers.setdefault(object_class, []).append(subscriber)
        self.rtia.subscribeObjectClassAttributes(object_class, sorted(subscribed, key=int))

    def register_object(self, object_class: rti.ObjectClassHandle, name: str) -> rti.ObjectHandle:
        """Register the instance ``name`` of ``object_class`` (once; later calls return the same handle)."""
        key = (object_class, name)
        if key not in self._registered:
            self._registered[key] = self.rtia.registerObjectInstance(object_class, name)
        return self._registered[key]

    def publish_interaction(self, interaction_class: rti.InteractionClassHandle) -> None:
        """Publish an interaction class (once)."""
        if interaction_class not in self._interactions_published:
            self.rtia.publishInteractionClass(interaction_class)
            self._interactions_published.add(interaction_class)

    def subscribe_interaction(
        self, interaction_class: rti.InteractionClassHandle, receiver: "InteractionReceiver"
    ) -> None:
        """Subscribe to an interaction class and route its interactions to ``receiver``."""
        if interaction_class not in self._receivers:
            self.rtia.subscribeInteractionClass(interaction_class)
        self._receivers.setdefault(interaction_class, []).append(receiver)

    # ---- callbacks, from DirectorAmbassador ----

    def _message_time(self, order: rti.OrderingHandle, time: Optional[float]) -> Optional[float]:
        """The timestamp of a timestamp-order message, None for a receive-order one."""
        if time is None or self._timestamp_order is None or order != self._timestamp_order:
            return None
        return float(time)

    def _on_discover(self, obj: rti.ObjectHandle, object_class: rti.ObjectClassHandle, name: str) -> None:
        self._objects[obj] = (object_class, name)

    def _on_remove(self, obj: rti.ObjectHandle) -> None:
        self._objects.pop(obj, None)

    def _on_reflect(
        self, obj: rti.ObjectHandle, values: dict[rti.AttributeHandle, bytes], tag: str,
        order: rti.OrderingHandle, time: Optional[float],
    ) -> None:
        known = self._objects.get(obj)
        if known is None:
            known = (self.rtia.getObjectClass(obj), self.rtia.getObjectInstanceName(obj))
            self._objects[obj] = known
        object_class, name = known
        timestamp = self._message_time(order, time)
        at = self.receive_time() if timestamp is None else timestamp
        for subscriber in self._subscribers.get(object_class, []):
            subscriber.reflect(name, values, tag, timestamp, at)

    def _on_interaction(
        self, interaction_class: rti.InteractionClassHandle, values: dict[rti.ParameterHandle, bytes], tag: str,
        order: rti.OrderingHandle, time: Optional[float],
    ) -> None:
        timestamp = self._message_time(order, time)
        at = self.receive_time() if timestamp is None else timestamp
        for receiver in self._receivers.get(interaction_class, []):
            receiver.receive(values, tag, timestamp, at)


class DirectorAmbassador(rti.FederateAmbassador):
    """The federate ambassador of an :class:`HlaDirector`: turns reflections and interactions into
    events, records time callbacks, and passes every callback on to an optional ``delegate``."""

    def __init__(self, director: HlaDirector, delegate: Optional[rti.FederateAmbassador] = None) -> None:
        self.director = director
        self.delegate = delegate

    def __getattr__(self, name: str) -> Any:
        # Callbacks the director does not handle go to the delegate, if it has them.
        delegate = self.__dict__.get("delegate")
        if delegate is None or name.startswith("_"):
            raise AttributeError(name)
        return getattr(delegate, name)

    def _forward(self, name: str, *args: Any) -> None:
        method = getattr(self.delegate, name, None) if self.delegate is not None else None
        if method is not None:
            method(*args)

    def discoverObjectInstance(self, obj: rti.ObjectHandle, objectClass: rti.ObjectClassHandle, name: str) -> None:
        """Remember the object's class and name."""
        self.director._on_discover(obj, objectClass, name)
        self._forward("discoverObjectInstance", obj, objectClass, name)

    def removeObjectInstance(self, obj: rti.ObjectHandle, tag: str, *rest: Any) -> None:
        """Forget the object."""
        self.director._on_remove(obj)
        self._forward("removeObjectInstance", obj, tag, *rest)

    # `timed` is (time, retraction) for a timestamped message, empty otherwise (PyHLA's signatures).
    def reflectAttributeValues(self, obj: rti.ObjectHandle, attributes: dict[rti.AttributeHandle, bytes], tag: str,
                               order: rti.OrderingHandle, transport: rti.TransportationHandle, *timed: Any) -> None:
        """Make the reflection an event on the subscribers of the object's class."""
        self.director._on_reflect(obj, attributes, tag, order, timed[0] if timed else None)
        self._forward("reflectAttributeValues", obj, attributes, tag, order, transport, *timed)

    def receiveInteraction(self, interactionClass: rti.InteractionClassHandle,
                           parameters: dict[rti.ParameterHandle, bytes], tag: str, order: rti.OrderingHandle,
                           transport: rti.TransportationHandle, *timed: Any) -> None:
        """Make the interaction an event on the receivers of its class."""
        self.director._on_interaction(interactionClass, parameters, tag, order, timed[0] if timed else None)
        self._forward("receiveInteraction", interactionClass, parameters, tag, order, transport, *timed)

    def timeRegulationEnabled(self, time: float) -> None:
        """Passed on to the wrapped ambassador."""
        self._forward("timeRegulationEnabled", time)

    def timeConstrainedEnabled(self, time: float) -> None:
        """Passed on to the wrapped ambassador."""
        self._forward("timeConstrainedEnabled", time)

    def timeAdvanceGrant(self, time: float) -> None:
        """Passed on to the delegate (the director reads the grant from ``await_grant``)."""
        self._forward("timeAdvanceGrant", time)


class HlaActor(Actor):
    """Base class of actors that talk to the RTI through an :class:`HlaDirector`.

    The director calls :meth:`declare` on every HLA actor (publish, subscribe) and then
    :meth:`register` on every one (register object instances) before any actor's ``initialize()``.
    """

    def hla(self) -> HlaDirector:
        """The actor's director, which must be an :class:`HlaDirector` (TypeError otherwise)."""
        director = self.director_or_raise()
        if not isinstance(director, HlaDirector):
            raise TypeError(f"{type(self).__name__} {self.name!r} needs an HlaDirector, not {type(director).__name__}")
        return director

    def declare(self, director: HlaDirector) -> None:
        """Publish and subscribe (called once, after time regulation is set up)."""

    def register(self, director: HlaDirector) -> None:
        """Register object instances (called once, after every HLA actor declared)."""
