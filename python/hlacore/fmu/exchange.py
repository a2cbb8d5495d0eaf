"""How values go between an FMU's variables and the federation: :class:`Input`, where a value received for an
attribute or parameter goes and how it is decoded and checked; :class:`Send`, what one output class sends at each
step, encoded (docs/fmu.md, "The mapping")."""

from __future__ import annotations

from typing import Any, NamedTuple, Optional

from .. import rti
from .errors import InputError
from .mapping import ENCODINGS, Endpoint
from .model import Variable


class Input(NamedTuple):
    """Where a received value goes: the input, the array element it is (None: the whole value) and the object
    instance it must come from (None: any)."""

    variable: Variable
    element: Optional[int]
    instance: Optional[str]

    @property
    def codec(self) -> Any:
        """The HLA encoding of the input's values (mapping.ENCODINGS)."""
        return ENCODINGS[self.variable.type]

    def decode(self, data: bytes, source: str) -> Any:
        """The value in ``data``; InputError when its size does not fit the encoding or the element, or the
        value does not fit the variable (an integer beyond its type, an Enumeration's value no item has)."""
        value = self._value(data, source)
        refusal = self.variable.refusal(value)
        if refusal:
            raise InputError(f"{self.variable.name}: {source} sent {value!r}, {refusal}")
        return value

    def _value(self, data: bytes, source: str) -> Any:
        size = self.codec.fixed_size
        if self.element is None:
            try:
                value, used = self.codec.unpack(data)
            except ValueError:
                used = -1
            if used != len(data):
                raise InputError(f"{self.variable.name}: {source} sent {len(data)} bytes, not one {self.codec.name}")
            return value
        if len(data) % size or len(data) < (self.element + 1) * size:
            raise InputError(f"{self.variable.name}: {source} sent {len(data)} bytes, not an array of "
                             f"{self.codec.name} with an element {self.element}")
        return self.codec.unpack(data, self.element * size)[0]


class Send:
    """What one output class sends at each step: an update of the instance this federate registered, or an
    interaction; each member (attribute or parameter) filled by its outputs, in element order, and the constants."""

    def __init__(self, rtia: rti.RTIAmbassador, endpoint: Endpoint) -> None:
        self.object_class = endpoint.object_class
        self.interaction = endpoint.interaction
        self.handle: Any = (rtia.getInteractionClassHandle if self.interaction else rtia.getObjectClassHandle)(
            endpoint.object_class)
        self.members: dict[Any, tuple[list[str], Any]] = {}  # member handle -> (outputs, their encoding)
        self.constants: dict[Any, bytes] = {}  # member handle -> its value, encoded
        self.target: Any = self.handle  # the interaction class, or the instance registered

    def member(self, rtia: rti.RTIAmbassador, name: str) -> Any:
        """The handle of the parameter or attribute ``name`` of the class."""
        return (rtia.getParameterHandle if self.interaction else rtia.getAttributeHandle)(name, self.handle)

    def publish(self, rtia: rti.RTIAmbassador, instance_name: str) -> None:
        """Publish the class (HLA 1.3 §5.2, §5.4) and, for an object class, register its instance (§6.2)."""
        if self.interaction:
            rtia.publishInteractionClass(self.handle)
            return
        rtia.publishObjectClass(self.handle, [*self.members, *self.constants])
        self.target = rtia.registerObjectInstance(self.handle, instance_name)

    def send(self, rtia: rti.RTIAmbassador, outputs: dict[str, Any], tag: str, time: float) -> None:
        """Update or send the outputs' values and the constants, stamped ``time`` (HLA 1.3 §6.4, §6.6)."""
        values = dict(self.constants)
        for handle, (names, codec) in self.members.items():
            values[handle] = b"".join(codec.pack(outputs[name]) for name in names)
        if self.interaction:
            rtia.sendInteraction(self.target, values, tag, time)
        else:
            rtia.updateAttributeValues(self.target, values, tag, time)


__all__ = ["Input", "Send"]
