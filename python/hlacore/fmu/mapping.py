"""Which FMU variable travels as which HLA attribute or parameter, and the FOM that declares them.

A mapping file is TOML with up to three tables::

    [inputs]            # set from the reflections of this attribute, of any instance
    u = "Source.u"
    gain = { parameter = "SetGain.value" }   # or from this parameter of the interactions received
    x = { attribute = "WorldRobot.pose", element = 0, instance = "bot" }   # an array's element, one instance's
    [outputs]           # published, updated at each step on one instance this federate registers
    y = "Lag.y"
    v = { parameter = "cmd_vel.linear" }     # or sent at each step as this parameter of one interaction
    [constants]         # sent with every update or interaction of that class
    "cmd_vel.robot" = "bot"

Without a file, the default maps by name: every input and output of the FMU is the attribute of the same name
of one object class named after the model (``Lag.u``, ``Lag.y``); the FMU publishes its outputs and subscribes
to its inputs, and whoever drives an input publishes that attribute of the same class. A variable left out
of the file is not exchanged. Reals (FMI 3: Float64) travel as HLAfloat64BE, Integers (Int32) and
Enumerations as HLAinteger32BE (the usual representation of an HLA enumerated type; a value no item has is
refused on receipt), Booleans as HLAboolean, Strings as HLAunicodeString, FMI 3's other types as
:data:`ENCODINGS` says; a member with ``element`` is an HLAfixedArray of that type (outputs
must then fill every element); a constant's TOML type gives its encoding (a string: HLAASCIIstring).
"""

from __future__ import annotations

import pathlib
import re
from dataclasses import dataclass, field, replace
from typing import Any, Optional, Union

from .. import omt
from .errors import FmuError, MappingError
from .model import SUPPORTED_TYPES, FmuModel

class _OctetNumber:
    """HLAoctet carrying an FMI 3 UInt8 as the number it is (hlacore.omt's HLAoctet unpacks to one byte)."""

    name, fixed_size = "HLAoctet", 1

    def pack(self, value: int) -> bytes:
        """One octet holding ``value`` (0 to 255)."""
        return omt.HLAoctet.pack(value)  # type: ignore[no-any-return]

    def unpack(self, data: bytes, offset: int = 0) -> tuple[int, int]:
        """The number in the octet at ``offset``, and its size."""
        return omt.HLAoctet.unpack(data, offset)[0][0], 1


#: The HLA encoding of each FMI type: HLA 1516.2's basic types, HLAinteger16BE for an Int8 (HLA has no signed
#: octet), its Unsignedinteger*BE for the unsigned ones.
ENCODINGS: dict[str, Any] = {"Real": omt.HLAfloat64BE, "Float64": omt.HLAfloat64BE, "Float32": omt.HLAfloat32BE,
                             "Integer": omt.HLAinteger32BE, "Int32": omt.HLAinteger32BE,
                             "Enumeration": omt.HLAinteger32BE, "Int8": omt.HLAinteger16BE,
                             "Int16": omt.HLAinteger16BE, "Int64": omt.HLAinteger64BE, "UInt8": _OctetNumber(),
                             "UInt16": omt.Unsignedinteger16BE, "UInt32": omt.Unsignedinteger32BE,
                             "UInt64": omt.Unsignedinteger64BE, "Boolean": omt.HLAboolean,
                             "String": omt.HLAunicodeString, "Binary": omt.HLAopaqueData}
#: The HLA encoding of a constant, by its TOML type (bool before int: a bool is an int in Python).
CONSTANT_ENCODINGS: list[tuple[type, Any]] = [(bool, omt.HLAboolean), (int, omt.HLAinteger32BE),
                                              (float, omt.HLAfloat64BE), (str, omt.HLAASCIIstring)]
_ENTRY_KEYS = {"attribute", "parameter", "element", "instance"}


@dataclass(frozen=True)
class Endpoint:
    """Where a variable travels: an attribute of an object class, or (``interaction``) a parameter of an
    interaction class, then ``object_class`` names the interaction class and ``attribute`` the parameter.
    ``element``: the member is an HLAfixedArray of the variable's type and the variable is this element of it;
    ``instance`` (inputs from attributes): only the reflections of the object instance of this name count."""

    object_class: str
    attribute: str
    interaction: bool = False
    element: Optional[int] = None
    instance: Optional[str] = None

    @classmethod
    def parse(cls, text: str, where: str, interaction: bool = False, element: Optional[int] = None,
              instance: Optional[str] = None) -> "Endpoint":
        """``"Class.member"`` (the class may be dotted: ``robot.turtlebot.sonar``)."""
        object_class, dot, attribute = text.rpartition(".")
        if not dot or not object_class or not attribute:
            form = "Interaction.parameter" if interaction else "ObjectClass.attribute"
            raise MappingError(f"{where}: {text!r} is not {form}")
        return cls(object_class, attribute, interaction, element, instance)

    @classmethod
    def from_toml(cls, value: Any, where: str) -> "Endpoint":
        """A mapping file's entry: ``"ObjectClass.attribute"``, or a table of ``attribute`` or ``parameter``
        with optional ``element`` and (attributes) ``instance``."""
        if isinstance(value, str):
            return cls.parse(value, where)
        form = ('expected "ObjectClass.attribute", { parameter = "Interaction.parameter" } or '
                '{ attribute = "ObjectClass.attribute", element = N, instance = "name" }')
        if not isinstance(value, dict) or set(value) - _ENTRY_KEYS or ("attribute" in value) == ("parameter" in value):
            raise MappingError(f"{where}: {form}")
        element, instance = value.get("element"), value.get("instance")
        if element is not None and (type(element) is not int or element < 0):
            raise MappingError(f"{where}: element {element!r}: an array index, 0 or more")
        if instance is not None and (not isinstance(instance, str) or "parameter" in value):
            raise MappingError(f"{where}: instance names the object instance of an attribute, as a string")
        interaction = "parameter" in value
        text = value["parameter" if interaction else "attribute"]
        if not isinstance(text, str):
            raise MappingError(f"{where}: {form}")
        return cls.parse(text, where, interaction, element, instance)

    @property
    def member(self) -> str:
        """``Class.member``, without the element."""
        return f"{self.object_class}.{self.attribute}"

    def __str__(self) -> str:
        return self.member + ("" if self.element is None else f"[{self.element}]")


@dataclass
class Mapping:
    """The FMU's inputs and outputs, the attributes and parameters they travel as, and the constants sent
    beside them (see the module's docstring)."""

    inputs: dict[str, Endpoint] = field(default_factory=dict)
    outputs: dict[str, Endpoint] = field(default_factory=dict)
    #: ``"Class.member"`` -> a value sent with every update or interaction of an output class.
    constants: dict[str, Any] = field(default_factory=dict)

    @classmethod
    def by_name(cls, model: FmuModel) -> "Mapping":
        """The default: each input and output as the attribute of its name of the class named after the model."""
        object_class = re.sub(r"\W", "_", model.name) or "Fmu"
        return cls({v.name: Endpoint(object_class, v.name) for v in model.inputs if v.type in SUPPORTED_TYPES},
                   {v.name: Endpoint(object_class, v.name) for v in model.outputs if v.type in SUPPORTED_TYPES})

    @classmethod
    def load(cls, path: Union[str, pathlib.Path], model: FmuModel) -> "Mapping":
        """The mapping of a TOML file, checked against ``model`` (:meth:`check`).

        Raises :class:`FmuError` when the file is missing or not TOML, :class:`MappingError` when it maps
        wrongly."""
        try:
            import tomllib
        except ImportError as error:  # Python 3.10
            raise FmuError("mapping files need Python 3.11 or newer (tomllib)") from error
        path = pathlib.Path(path)
        try:
            data = tomllib.loads(path.read_text())
        except OSError as error:
            raise FmuError(f"{path}: cannot read the mapping: {error.strerror}") from error
        except tomllib.TOMLDecodeError as error:
            raise FmuError(f"{path}: not TOML: {error}") from error
        unknown_tables = set(data) - {"inputs", "outputs", "constants"}
        if unknown_tables:
            raise MappingError(f"{path}: unknown table(s) {sorted(unknown_tables)}; "
                               "expected [inputs], [outputs], [constants]")
        tables: dict[str, dict[str, Any]] = {}
        for table in ("inputs", "outputs", "constants"):
            tables[table] = data.get(table, {})
            if not isinstance(tables[table], dict):
                raise MappingError(f"{path}: [{table}] is a table")
        mapping = cls({name: Endpoint.from_toml(value, f"{path}: [inputs] {name}")
                       for name, value in tables["inputs"].items()},
                      {name: Endpoint.from_toml(value, f"{path}: [outputs] {name}")
                       for name, value in tables["outputs"].items()},
                      tables["constants"])
        mapping.check(model, str(path))
        return mapping

    def check(self, model: FmuModel, where: str = "mapping") -> None:
        """Raise :class:`MappingError` for a variable the model lacks, one mapped against its causality (an
        output as an input, a parameter as either), one of a type that cannot travel, an output array with a
        missing, repeated or mixed-type element, or a constant of no output class."""
        for table, causality in (("inputs", "input"), ("outputs", "output")):
            for name in getattr(self, table):
                variable = model.variables.get(name)
                if variable is None:
                    raise MappingError(f"{where}: [{table}] {name}: {model.path.name} has no variable {name!r}")
                if variable.causality != causality:
                    raise MappingError(f"{where}: [{table}] {name}: its causality is {variable.causality}, "
                                       f"not {causality}")
                if variable.type not in SUPPORTED_TYPES:
                    raise MappingError(f"{where}: [{table}] {name}: type {variable.type} cannot travel "
                                       f"(only {', '.join(SUPPORTED_TYPES)})")
                if any(not -2**31 <= value < 2**31 for _, value in variable.items):
                    raise MappingError(f"{where}: [{table}] {name}: an item of its Enumeration is beyond "
                                       "HLAinteger32BE, the encoding it travels as")
                if getattr(self, table)[name].element is not None and ENCODINGS[variable.type].fixed_size is None:
                    raise MappingError(f"{where}: [{table}] {name}: a {variable.type} is no array element (its "
                                       f"size varies)")
                if table == "outputs" and getattr(self, table)[name].instance is not None:
                    raise MappingError(f"{where}: [outputs] {name}: outputs go to this federate's own instance")
        members = self.members()
        for member, outputs in members.items():
            elements = [self.outputs[o].element for o in outputs]
            if elements != [None] and sorted(e for e in elements if e is not None) != list(range(len(elements))):
                raise MappingError(f"{where}: [outputs] {member} gets elements {elements}: an output array "
                                   f"needs each of its elements 0..n-1 once")
            if len({ENCODINGS[model.variables[o].type] for o in outputs}) > 1:
                raise MappingError(f"{where}: [outputs] {member}: its elements are of different types")
        classes = {(e.object_class, e.interaction) for e in self.outputs.values()}
        for name, value in self.constants.items():
            endpoint = Endpoint.parse(name, f"{where}: [constants]")
            if {(endpoint.object_class, False), (endpoint.object_class, True)}.isdisjoint(classes):
                raise MappingError(f"{where}: [constants] {name}: {endpoint.object_class} is no class the "
                                   f"outputs are sent as")
            if any(m.member == name for m in members):
                raise MappingError(f"{where}: [constants] {name}: an output is mapped to it too")
            constant_encoding(value, f"{where}: [constants] {name}")

    def members(self) -> dict[Endpoint, list[str]]:
        """Each output member (its endpoint without element) and the outputs that fill it, in element order."""
        members: dict[Endpoint, list[str]] = {}
        for name, endpoint in sorted(self.outputs.items(), key=lambda item: item[1].element or 0):
            members.setdefault(replace(endpoint, element=None), []).append(name)
        return members

    def fed(self, federation: str) -> str:
        """An HLA 1.3 ``.fed`` declaring every class, attribute, interaction and parameter of the mapping
        (reliable, timestamp order)."""
        classes: dict[str, list[str]] = {}
        interactions: dict[str, list[str]] = {}
        interaction_classes = {e.object_class for e in self.outputs.values() if e.interaction}
        constants = [Endpoint.parse(m, "[constants]", m.rpartition(".")[0] in interaction_classes)
                     for m in self.constants]
        for endpoint in [*self.inputs.values(), *self.outputs.values(), *constants]:
            members = (interactions if endpoint.interaction else classes).setdefault(endpoint.object_class, [])
            if endpoint.attribute not in members:
                members.append(endpoint.attribute)
        for name in [*classes, *interactions]:
            if "." in name:
                raise MappingError(f"--write-fom writes top-level classes; {name} is nested")
        lines = [";; written by python -m hlacore.fmu --write-fom", "(FED", f" (Federation {federation})",
                 " (FEDversion v1.3)", " (spaces)", " (objects", "  (class ObjectRoot",
                 "   (attribute privilegeToDelete reliable timestamp)", "   (class RTIprivate)"]
        for name, attributes in classes.items():
            lines.append(f"   (class {name}")
            lines += [f"    (attribute {a} reliable timestamp)" for a in attributes]
            lines[-1] += ")"
        lines[-1] += "))"
        lines += [" (interactions", "  (class InteractionRoot reliable receive",
                  "   (class RTIprivate reliable receive)"]
        for name, parameters in interactions.items():
            lines.append(f"   (class {name} reliable timestamp")
            lines += [f"    (parameter {p})" for p in parameters]
            lines[-1] += ")"
        lines[-1] += ")))"
        return "\n".join(lines) + "\n"


def constant_encoding(value: Any, where: str) -> Any:
    """The HLA encoding of a constant of the mapping, by its TOML type; MappingError for another type."""
    for kind, encoding in CONSTANT_ENCODINGS:
        if isinstance(value, kind):
            return encoding
    raise MappingError(f"{where}: {value!r}: a constant is a string, a number or a Boolean")
