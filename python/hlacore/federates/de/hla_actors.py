"""Actors that map ports to the FOM: object attributes and interactions, out and in.

* :class:`ObjectPublisher` — one input port per attribute; each firing sends one
  ``updateAttributeValues`` of the attributes that got a token (the last token of a port wins: an
  attribute holds one value at a time).
* :class:`ObjectSubscriber` — one output port per attribute; a reflection becomes an event at its
  timestamp (receive order: at the current time), fired as tokens on the ports of the attributes it
  carries, plus a :class:`Received` record on ``received``.
* :class:`InteractionSender` / :class:`InteractionReceiver` — the same with interaction parameters;
  a sender sends one interaction per token index (interactions are events, none is dropped).

Values are encoded with a :data:`Codec` per attribute or parameter: an :mod:`hlacore.omt` type
(``omt.HLAfloat64BE``), a pair of functions ``(encode, decode)``, or None for raw ``bytes``.
"""

from __future__ import annotations

from dataclasses import dataclass
from typing import Any, Callable, Iterable, Mapping, Optional, TypeVar, Union

from hlacore import omt, rti

from .actor import InputPort, OutputPort
from .hla import HlaActor, HlaDirector

__all__ = [
    "Codec",
    "HlaActor",
    "ObjectPublisher",
    "ObjectSubscriber",
    "InteractionSender",
    "InteractionReceiver",
    "Received",
]

#: How a value becomes bytes and back.
Codec = Union[omt.HLAdataType, tuple[Callable[[Any], bytes], Callable[[bytes], Any]], None]

_C = TypeVar("_C")  # an object or interaction class handle
_F = TypeVar("_F")  # an attribute or parameter handle


def _encoder(codec: Codec) -> Callable[[Any], bytes]:
    if codec is None:
        return bytes
    if isinstance(codec, omt.HLAdataType):
        return codec.pack
    return codec[0]


def _decoder(codec: Codec) -> Callable[[bytes], Any]:
    if codec is None:
        return bytes
    if isinstance(codec, omt.HLAdataType):
        datatype = codec
        return lambda data: datatype.unpack(data)[0]
    return codec[1]


def _decode(values: Mapping[Any, bytes], names: Mapping[Any, str], codecs: Mapping[str, Codec]) -> dict[str, Any]:
    """The values of the handles in ``names``, by name, decoded; other handles are dropped."""
    return {names[h]: _decoder(codecs[names[h]])(data) for h, data in values.items() if h in names}


def _send_received(inbox: InputPort, ports: Mapping[str, OutputPort], received: OutputPort) -> None:
    """Fire an incoming actor: each :class:`Received` in ``inbox`` as tokens on its values' ports."""
    for record in inbox.tokens:
        for name, value in record.values.items():
            ports[name].send(value)
        received.send(record)


def _class_fields(
    class_handle: Callable[[str], _C], field_handle: Callable[[str, _C], _F], class_name: str, fields: Iterable[str]
) -> tuple[_C, dict[str, _F]]:
    """The handle of the class ``class_name`` and, by name, those of its attributes or parameters ``fields``
    (``class_handle``, ``field_handle``: the RTI's lookups, ``getObjectClassHandle`` and ``getAttributeHandle``
    or their interaction counterparts)."""
    cls = class_handle(class_name)
    return cls, {name: field_handle(name, cls) for name in fields}


def _codecs(names: Union[Mapping[str, Codec], Iterable[str]]) -> dict[str, Codec]:
    if isinstance(names, Mapping):
        return dict(names)
    return {name: None for name in names}


@dataclass(frozen=True)
class Received:
    """One reflection or interaction as the model saw it.

    ``source`` is the object instance name (reflections) or the interaction class name;
    ``values`` the decoded attributes or parameters by name; ``timestamp`` the message's timestamp
    (None when it came in receive order); ``time`` the model time it was fired at (the timestamp,
    or the current time for receive order, or the current time if it came late); ``tag`` the
    sender's user-supplied tag.
    """

    source: str
    values: dict[str, Any]
    timestamp: Optional[float]
    time: float
    tag: str


class _Sender(HlaActor):
    """What both publishers share: a codec and an input port per attribute or parameter, and the time
    each message goes with."""

    def __init__(self, name: str, fields: Union[Mapping[str, Codec], Iterable[str]], timestamped: bool,
                 delay: float) -> None:
        super().__init__(name)
        self.codecs = _codecs(fields)
        self.timestamped = timestamped
        self.delay = float(delay)
        self.ports: dict[str, InputPort] = {field: self.add_input(field) for field in self.codecs}
        #: The timestamps of the messages sent (None for receive order), in order.
        self.sent: list[Optional[float]] = []
        self._handles: dict[str, Any] = {}  # attribute or parameter name -> handle

    def _send(self, director: "HlaDirector", service: Callable[..., Any], *args: Any) -> None:
        """Call the RTI service with `args`, this actor's name as tag and the message's time (send_time +
        delay when timestamped, else None), and note the time."""
        time = director.send_time(self.delay) if self.timestamped else None
        service(*args, self.name, time)
        self.sent.append(time)


class ObjectPublisher(_Sender):
    """Publishes ``attributes`` of ``object_class`` for one object instance, one input port each.

    ``attributes`` maps attribute names to codecs (or is a list of names: raw bytes). The instance is
    registered as ``instance_name`` (default: the actor's name); publishers with the same class and
    instance name share it. Updates carry :meth:`HlaDirector.send_time` (+ ``delay``) when
    ``timestamped``, else no time (receive order).
    """

    def __init__(
        self,
        name: str,
        object_class: str,
        attributes: Union[Mapping[str, Codec], Iterable[str]],
        instance_name: Optional[str] = None,
        timestamped: bool = True,
        delay: float = 0.0,
    ) -> None:
        super().__init__(name, attributes, timestamped, delay)
        self.object_class = object_class
        self.instance_name = instance_name if instance_name is not None else name
        self._class: Optional[rti.ObjectClassHandle] = None
        self._object: Optional[rti.ObjectHandle] = None

    @property
    def object(self) -> Optional[rti.ObjectHandle]:
        """The registered instance (None before the director initializes)."""
        return self._object

    def declare(self, director: "HlaDirector") -> None:
        """Look up the class and attribute handles and publish the attributes."""
        rtia = director.rtia
        object_class, self._handles = _class_fields(
            rtia.getObjectClassHandle, rtia.getAttributeHandle, self.object_class, self.codecs)
        self._class = object_class
        director.publish_attributes(object_class, set(self._handles.values()))

    def register(self, director: "HlaDirector") -> None:
        """Register the object instance (shared with the publishers of the same class and name)."""
        assert self._class is not None
        self._object = director.register_object(self._class, self.instance_name)

    def fire(self) -> None:
        """Update the attributes whose ports have a token, each port's last token encoded."""
        values = {
            self._handles[attr]: _encoder(self.codecs[attr])(port.last())
            for attr, port in self.ports.items()
            if port.has_token()
        }
        if not values:
            return
        director = self.hla()
        if self._object is None:
            raise RuntimeError(f"{self.name!r} fired before its director registered the object")
        self._send(director, director.rtia.updateAttributeValues, self._object, values)


class _Receiver(HlaActor):
    """What both subscribers share: a codec and an output port per attribute or parameter, ``received``,
    and the input port (``inbox``) through which the director schedules what arrives."""

    def __init__(self, name: str, fields: Union[Mapping[str, Codec], Iterable[str]], inbox: str) -> None:
        super().__init__(name)
        self.codecs = _codecs(fields)
        self.inbox = self.add_input(inbox)
        self.ports: dict[str, OutputPort] = {field: self.add_output(field) for field in self.codecs}
        self.received = self.add_output("received")
        self._names: dict[Any, str] = {}  # attribute or parameter handle -> name

    def _look_up(self, class_handle: Callable[[str], _C], field_handle: Callable[[str, _C], Any],
                 class_name: str) -> _C:
        """The handle of the class ``class_name`` (see :func:`_class_fields`); ``_names`` gets its fields'."""
        cls, handles = _class_fields(class_handle, field_handle, class_name, self.codecs)
        self._names = {handle: name for name, handle in handles.items()}
        return cls

    def _schedule(self, source: str, decoded: dict[str, Any], tag: str, timestamp: Optional[float], at: float) -> None:
        director = self.hla()
        director.inject(self.inbox, Received(source, decoded, timestamp, max(at, director.now), tag), at)

    def fire(self) -> None:
        """Send each received value on its port and the :class:`Received` on ``received``."""
        _send_received(self.inbox, self.ports, self.received)


class ObjectSubscriber(_Receiver):
    """Subscribes to ``attributes`` of ``object_class``; one output port per attribute.

    Reflections of any instance of the class (or only of ``instance_name``) become events at their
    timestamps; when fired, each reflected attribute's decoded value is sent on its port and a
    :class:`Received` on ``received``. The input port ``reflections`` is the director's way in: do
    not connect it.
    """

    def __init__(
        self,
        name: str,
        object_class: str,
        attributes: Union[Mapping[str, Codec], Iterable[str]],
        instance_name: Optional[str] = None,
    ) -> None:
        super().__init__(name, attributes, "reflections")
        self.object_class = object_class
        self.instance_name = instance_name
        self.reflections = self.inbox

    def declare(self, director: "HlaDirector") -> None:
        """Look up the class and attribute handles and subscribe to the attributes."""
        rtia = director.rtia
        object_class = self._look_up(rtia.getObjectClassHandle, rtia.getAttributeHandle, self.object_class)
        director.subscribe_attributes(object_class, set(self._names), self)

    def reflect(
        self, instance: str, values: Mapping[rti.AttributeHandle, bytes], tag: str,
        timestamp: Optional[float], at: float,
    ) -> None:
        """Called by the director for a reflection of the subscribed class: schedule it at ``at``."""
        if self.instance_name is not None and instance != self.instance_name:
            return
        decoded = _decode(values, self._names, self.codecs)
        if decoded:
            self._schedule(instance, decoded, tag, timestamp, at)


class InteractionSender(_Sender):
    """Publishes ``interaction_class`` and sends it with ``parameters`` (one input port each).

    Token ``i`` of every port that has one goes in the ``i``-th interaction of the firing. Times as
    in :class:`ObjectPublisher`.
    """

    def __init__(
        self,
        name: str,
        interaction_class: str,
        parameters: Union[Mapping[str, Codec], Iterable[str]],
        timestamped: bool = True,
        delay: float = 0.0,
    ) -> None:
        super().__init__(name, parameters, timestamped, delay)
        self.interaction_class = interaction_class
        self._class: Optional[rti.InteractionClassHandle] = None

    def declare(self, director: "HlaDirector") -> None:
        """Look up the class and parameter handles and publish the interaction class."""
        rtia = director.rtia
        interaction_class, self._handles = _class_fields(
            rtia.getInteractionClassHandle, rtia.getParameterHandle, self.interaction_class, self.codecs)
        self._class = interaction_class
        director.publish_interaction(interaction_class)

    def fire(self) -> None:
        """Send one interaction per token index, with the parameters whose ports have that many tokens."""
        director = self.hla()
        if self._class is None:
            raise RuntimeError(f"{self.name!r} fired before its director declared the interaction")
        count = max((len(port.tokens) for port in self.ports.values()), default=0)
        for i in range(count):
            values = {
                self._handles[param]: _encoder(self.codecs[param])(port.tokens[i])
                for param, port in self.ports.items()
                if i < len(port.tokens)
            }
            self._send(director, director.rtia.sendInteraction, self._class, values)


class InteractionReceiver(_Receiver):
    """Subscribes to ``interaction_class``; one output port per parameter, plus ``received``.

    Interactions of exactly that class become events at their timestamps (receive order: at the
    current time). The input port ``interactions`` is the director's way in: do not connect it.
    """

    def __init__(
        self,
        name: str,
        interaction_class: str,
        parameters: Union[Mapping[str, Codec], Iterable[str]],
    ) -> None:
        super().__init__(name, parameters, "interactions")
        self.interaction_class = interaction_class
        self.interactions = self.inbox

    def declare(self, director: "HlaDirector") -> None:
        """Look up the class and parameter handles and subscribe to the interaction class."""
        rtia = director.rtia
        interaction_class = self._look_up(rtia.getInteractionClassHandle, rtia.getParameterHandle,
                                          self.interaction_class)
        director.subscribe_interaction(interaction_class, self)

    def receive(
        self, values: Mapping[rti.ParameterHandle, bytes], tag: str, timestamp: Optional[float], at: float
    ) -> None:
        """Called by the director for an interaction of the subscribed class: schedule it at ``at``."""
        self._schedule(self.interaction_class, _decode(values, self._names, self.codecs), tag, timestamp, at)
