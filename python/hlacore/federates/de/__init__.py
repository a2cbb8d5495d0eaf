"""A discrete-event (DE) engine in the style of Ptolemy II's DE domain, standalone or as an HLA federate.

- :mod:`.events` — firings ordered by ``(time, microstep, depth, sequence)``;
- :mod:`.actor` — :class:`Actor`, :class:`InputPort`, :class:`OutputPort`;
- :mod:`.director` — :class:`Director`: ``peek()``, ``step()``, ``run(until)``, no RTI;
- :mod:`.hla` — :class:`HlaDirector` (NER or TAR time advance; never fires past its grant) and the base
  :class:`HlaActor` of the actors it declares and registers;
- :mod:`.hla_actors` — publishers and subscribers mapping ports to FOM attributes and interactions;
- :mod:`.library` — Clock, TimedSource, Function, Delay, Recorder.

See ``docs/de.md`` for the model of computation, the event order and the two time modes.

Federates layer (imports only the core). Inside, lowest first: events < actor < director < hla < hla_actors,
library; the few upward names (``Director`` in actor, ``Actor`` in events, the subscriber types in hla)
are annotations under ``TYPE_CHECKING`` only.
"""

from .actor import Actor, CausalityError, InputPort, NoTokenError, OutputPort
from .director import Director, EmptySchedule
from .events import EventQueue, Firing
from .hla import DirectorAmbassador, HlaDirector, TimeMode
from .hla_actors import (
    Codec,
    HlaActor,
    InteractionReceiver,
    InteractionSender,
    ObjectPublisher,
    ObjectSubscriber,
    Received,
)
from .library import Clock, Delay, Function, Record, Recorder, TimedSource

__all__ = [
    "Actor",
    "CausalityError",
    "Clock",
    "Codec",
    "Delay",
    "Director",
    "DirectorAmbassador",
    "EmptySchedule",
    "EventQueue",
    "Firing",
    "Function",
    "HlaActor",
    "HlaDirector",
    "InputPort",
    "InteractionReceiver",
    "InteractionSender",
    "NoTokenError",
    "ObjectPublisher",
    "ObjectSubscriber",
    "OutputPort",
    "Received",
    "Record",
    "Recorder",
    "TimeMode",
    "TimedSource",
]
