"""Which FMU variable travels as which HLA attribute, and the FOM that declares them.

A mapping file is TOML with two tables, each ``variable = "ObjectClass.attribute"``::

    [inputs]            # set from the reflections of this attribute, of any instance
    u = "Source.u"
    gain = { parameter = "SetGain.value" }   # or from this parameter of the interactions received
    [outputs]           # published, and updated at each step on one instance this federate registers
    y = "Lag.y"

Without a file, the default maps by name: every input and output of the FMU is the attribute of the same name
of one object class named after the model (``Lag.u``, ``Lag.y``); the FMU publishes its outputs and subscribes
to its inputs, and whoever drives an input publishes that attribute of the same class. A variable left out
of the file is not exchanged. Reals (FMI 3: Float64) travel as HLAfloat64BE, Integers (Int32) as
HLAinteger32BE, Booleans as HLAboolean.
"""

from __future__ import annotations

import pathlib
import re
from dataclasses import dataclass, field
from typing import Any, Union

from .. import omt
from .errors import FmuError, MappingError
from .model import SUPPORTED_TYPES, FmuModel

#: The HLA encoding of each FMI type.
ENCODINGS: dict[str, Any] = {"Real": omt.HLAfloat64BE, "Float64": omt.HLAfloat64BE, "Integer": omt.HLAinteger32BE,
                             "Int32": omt.HLAinteger32BE, "Boolean": omt.HLAboolean}


@dataclass(frozen=True)
class Endpoint:
    """Where a variable travels: an attribute of an object class, or (``interaction``) a parameter of an
    interaction class, then ``object_class`` names the interaction class and ``attribute`` the parameter."""

    object_class: str
    attribute: str
    interaction: bool = False

    @classmethod
    def parse(cls, text: str, where: str, interaction: bool = False) -> "Endpoint":
        """``"Class.member"`` (the class may be dotted: ``robot.turtlebot.sonar``)."""
        object_class, dot, attribute = text.rpartition(".")
        if not dot or not object_class or not attribute:
            form = "Interaction.parameter" if interaction else "ObjectClass.attribute"
            raise MappingError(f"{where}: {text!r} is not {form}")
        return cls(object_class, attribute, interaction)

    @classmethod
    def from_toml(cls, value: Any, where: str) -> "Endpoint":
        """A mapping file's entry: ``"ObjectClass.attribute"`` or ``{ parameter = "Interaction.parameter" }``."""
        if isinstance(value, str):
            return cls.parse(value, where)
        if isinstance(value, dict) and list(value) == ["parameter"] and isinstance(value["parameter"], str):
            return cls.parse(value["parameter"], where, interaction=True)
        raise MappingError(f"{where}: expected \"ObjectClass.attribute\" or "
                           f"{{ parameter = \"Interaction.parameter\" }}")

    def __str__(self) -> str:
        return f"{self.object_class}.{self.attribute}"


@dataclass
class Mapping:
    """The FMU's inputs and outputs and the attributes they travel as (see the module's docstring)."""

    inputs: dict[str, Endpoint] = field(default_factory=dict)
    outputs: dict[str, Endpoint] = field(default_factory=dict)

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
        unknown_tables = set(data) - {"inputs", "outputs"}
        if unknown_tables:
            raise MappingError(f"{path}: unknown table(s) {sorted(unknown_tables)}; expected [inputs], [outputs]")
        tables: dict[str, dict[str, Endpoint]] = {}
        for table in ("inputs", "outputs"):
            entries = data.get(table, {})
            if not isinstance(entries, dict):
                raise MappingError(f"{path}: [{table}] maps variable names to \"ObjectClass.attribute\"")
            tables[table] = {name: Endpoint.from_toml(value, f"{path}: [{table}] {name}")
                             for name, value in entries.items()}
        mapping = cls(tables["inputs"], tables["outputs"])
        mapping.check(model, str(path))
        return mapping

    def check(self, model: FmuModel, where: str = "mapping") -> None:
        """Raise :class:`MappingError` for a variable the model lacks, one mapped against its causality (an
        output as an input, a parameter as either), or one of a type that cannot travel."""
        for table, causality in (("inputs", "input"), ("outputs", "output")):
            for name in getattr(self, table):
                variable = model.variables.get(name)
                if variable is None:
                    raise MappingError(f"{where}: [{table}] {name}: {model.path.name} has no variable {name!r}")
                if variable.causality != causality:
                    raise MappingError(f"{where}: [{table}] {name}: its causality is {variable.causality}, "
                                       f"not {causality}")
                if table == "outputs" and getattr(self, table)[name].interaction:
                    raise MappingError(f"{where}: [outputs] {name}: outputs travel as attributes, not parameters")
                if variable.type not in SUPPORTED_TYPES:
                    raise MappingError(f"{where}: [{table}] {name}: type {variable.type} cannot travel "
                                       f"(only {', '.join(SUPPORTED_TYPES)})")

    def fed(self, federation: str) -> str:
        """An HLA 1.3 ``.fed`` declaring every class, attribute, interaction and parameter of the mapping
        (reliable, timestamp order)."""
        classes: dict[str, list[str]] = {}
        interactions: dict[str, list[str]] = {}
        for endpoint in [*self.inputs.values(), *self.outputs.values()]:
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
