"""An FMU on disk and its running instance, over FMPy: what the model description says (the variables, their
causality and type, whether an output depends directly on an input), and an instance that is set, stepped and
read by variable name.

FMI 2 and FMI 3 co-simulation: an FMI 1 FMU, and one that exports model exchange only, is refused with its
reason before anything is loaded.
"""

from __future__ import annotations

import math
import pathlib
import platform
import shutil
import tempfile
import zipfile
from dataclasses import dataclass
from typing import Any, Optional, Union

from .errors import FmuError, MappingError, NotCoSimulation, StepFailed

#: The FMI types an FMU variable may have to travel through the federation (HLA encodings in mapping.py): FMI 2's
#: Real, Integer, Boolean, String and Enumeration, and FMI 3's numbers, Boolean, String, Binary and Enumeration;
#: each with the Python type of its values (FMPy's set and get methods are named after the type, except for
#: an Enumeration: :data:`_ENUMERATION_ACCESS`).
_KINDS: dict[str, type] = {"Real": float, "Float64": float, "Float32": float, "Integer": int, "Boolean": bool,
                           "String": str, "Binary": bytes, "Enumeration": int,
                           **{f"{sign}Int{bits}": int for sign in ("", "U") for bits in (8, 16, 32, 64)}}
#: How an Enumeration is set and got: as an Integer in FMI 2, an Int64 in FMI 3.
_ENUMERATION_ACCESS = {False: "Integer", True: "Int64"}
#: The values each integer type holds.
RANGES: dict[str, tuple[int, int]] = {"Integer": (-2**31, 2**31 - 1),
                                      **{f"Int{bits}": (-2**(bits - 1), 2**(bits - 1) - 1) for bits in (8, 16, 32, 64)},
                                      **{f"UInt{bits}": (0, 2**bits - 1) for bits in (8, 16, 32, 64)}}
SUPPORTED_TYPES = tuple(_KINDS)


@dataclass(frozen=True)
class Variable:
    """One scalar variable of the model description."""

    name: str
    value_reference: int
    type: str  # 'Real', 'Integer', 'Boolean', 'String', ...
    causality: str  # 'input', 'output', 'parameter', 'local', ...
    items: tuple[tuple[str, int], ...] = ()  # an Enumeration's items, (name, value), from its declared type

    def refusal(self, value: Any) -> Optional[str]:
        """Why the variable cannot take ``value`` (None: it can): a Real takes a number, an integer type an int
        in its range, an Enumeration the value of one of its items, a Boolean a bool, a String a str, a Binary
        bytes."""
        if self.type == "Enumeration" and (type(value) is not int or value not in {v for _, v in self.items}):
            return f"not one of its items ({', '.join(f'{n} = {v}' for n, v in self.items)})"
        kind = _KINDS.get(self.type)
        if kind is None or isinstance(value, bool) and kind is not bool or not (
                isinstance(value, (int, float)) if kind is float else isinstance(value, kind)):
            return f"{self.name} is of type {self.type}"
        low, high = RANGES.get(self.type, (value, value))
        if kind is int and not low <= value <= high:
            return f"beyond its type's ({low}, {high})"
        return None


def _items(variable: Any) -> tuple[tuple[str, int], ...]:
    """An Enumeration's items from its declared type in FMPy's model description; () for another type."""
    declared = variable.declaredType
    if variable.type != "Enumeration" or declared is None:
        return ()
    return tuple((str(item.name), int(item.value)) for item in declared.items)


def _platform_binary(identifier: str, version: str) -> str:
    if version.startswith("3."):
        from fmpy import platform_tuple, sharedLibraryExtension

        return f"binaries/{platform_tuple}/{identifier}{sharedLibraryExtension}"
    system = {"Linux": "linux", "Darwin": "darwin", "Windows": "win"}.get(platform.system(), platform.system())
    suffix = {"linux": ".so", "darwin": ".dylib", "win": ".dll"}.get(system, ".so")
    return f"binaries/{system}64/{identifier}{suffix}"


def check_value(model: "FmuModel", name: str, value: Any) -> Any:
    """The value to set ``model``'s variable ``name`` to for ``value``: itself, or for an Enumeration given the
    name of an item, the item's value. Raises :class:`MappingError` when the model has no such variable or it
    cannot take the value (:meth:`Variable.refusal`)."""
    variable = model.variables.get(name)
    if variable is None:
        raise MappingError(f"{name} = {value!r}: {model.path.name} has no variable {name!r}")
    if isinstance(value, str) and variable.type == "Enumeration":
        value = dict(variable.items).get(value, value)
    refusal = variable.refusal(value)
    if refusal:
        raise MappingError(f"{name} = {value!r}: {refusal}")
    return value


class FmuModel:
    """An FMI 2 or FMI 3 co-simulation FMU read from ``path``: its model description, checked, not loaded.

    Raises :class:`FmuError` when FMPy is not installed, or the file is missing, is not an FMU (not a zip, or
    no readable ``modelDescription.xml``), is FMI 1, or carries no binary for this platform, and
    :class:`NotCoSimulation` when it exports model exchange only."""

    def __init__(self, path: Union[str, pathlib.Path]) -> None:
        try:
            import fmpy
        except ImportError as error:
            raise FmuError("hlacore.fmu needs FMPy: pip install 'hlacore[fmu]'") from error

        self.path = pathlib.Path(path)
        if not self.path.is_file():
            raise FmuError(f"{self.path}: no such FMU")
        if not zipfile.is_zipfile(self.path):
            raise FmuError(f"{self.path}: not an FMU (an FMU is a zip archive)")
        try:
            self.description: Any = fmpy.read_model_description(str(self.path), validate=False)
        except Exception as error:  # fmpy raises plain Exception, KeyError, lxml's errors ...
            raise FmuError(f"{self.path}: unreadable model description: {error}") from error
        version = self.description.fmiVersion
        if version not in ("2.0", "3.0"):
            raise FmuError(f"{self.path}: FMI {version}; hlacore.fmu runs FMI 2.0 and 3.0 co-simulation FMUs")
        if self.description.coSimulation is None:
            raise NotCoSimulation(
                f"{self.path}: exports model exchange only; hlacore.fmu runs co-simulation FMUs "
                "(export the model for co-simulation)")
        self.identifier: str = self.description.coSimulation.modelIdentifier
        binary = _platform_binary(self.identifier, version)
        with zipfile.ZipFile(self.path) as archive:
            if binary not in archive.namelist():
                raise FmuError(f"{self.path}: no binary for this platform ({binary} is missing)")
        self.variables: dict[str, Variable] = {
            v.name: Variable(v.name, int(v.valueReference), str(v.type), str(v.causality), _items(v))
            for v in self.description.modelVariables}

    @property
    def fmi3(self) -> bool:
        """Whether the FMU is FMI 3.0 (else FMI 2.0)."""
        return str(self.description.fmiVersion) == "3.0"

    @property
    def name(self) -> str:
        """The model's name (``modelName``)."""
        return str(self.description.modelName)

    @property
    def inputs(self) -> list[Variable]:
        """The variables of causality ``input``, in the model description's order."""
        return [v for v in self.variables.values() if v.causality == "input"]

    @property
    def outputs(self) -> list[Variable]:
        """The variables of causality ``output``, in the model description's order."""
        return [v for v in self.variables.values() if v.causality == "output"]

    @property
    def direct_feedthrough(self) -> bool:
        """Whether an output depends directly on an input, by ``ModelStructure``'s outputs: an output without
        a ``dependencies`` attribute depends on every input (FMI 2 §3.3.1, FMI 3 §2.4.8)."""
        inputs = {v.name for v in self.inputs}
        for unknown in self.description.outputs:
            if unknown.dependencies is None and inputs:
                return True
            if any(d.name in inputs for d in unknown.dependencies or []):
                return True
        return False

    @property
    def can_save_state(self) -> bool:
        """Whether the FMU can get, set and serialise its state (a federation save can include it)."""
        cs = self.description.coSimulation
        return bool(cs.canGetAndSetFMUstate and cs.canSerializeFMUstate)

    def instantiate(self, start_time: float, start_values: Optional[dict[str, Any]] = None) -> "FmuInstance":
        """A running instance, initialised at ``start_time`` with ``start_values`` (by variable name).

        Raises :class:`FmuError` when the binary does not load or a start value is refused."""
        return FmuInstance(self, start_time, start_values or {})


class FmuInstance:
    """One instance of an :class:`FmuModel`, unpacked into a temporary directory that :meth:`close` removes."""

    def __init__(self, model: FmuModel, start_time: float, start_values: dict[str, Any]) -> None:
        from fmpy import extract
        from fmpy.fmi2 import FMU2Slave
        from fmpy.fmi3 import FMU3Slave

        self.model = model
        self._directory = tempfile.mkdtemp(prefix="hlacore-fmu-")
        self._fmu: Any = None
        self._healthy = False  # instantiated and no call failed: fmi2Terminate is allowed
        try:
            extract(str(model.path), self._directory)
            slave = FMU3Slave if model.fmi3 else FMU2Slave
            self._fmu = slave(guid=model.description.guid, unzipDirectory=self._directory,
                              modelIdentifier=model.identifier, instanceName=model.identifier)
            self._fmu.instantiate()
            self._healthy = True
            if model.fmi3:
                self._fmu.enterInitializationMode(startTime=start_time)
            else:
                self._fmu.setupExperiment(startTime=start_time)
                self._fmu.enterInitializationMode()
            self.set(start_values)
            self._fmu.exitInitializationMode()
        except FmuError:
            self.close()
            raise
        except Exception as error:
            self.close()
            raise FmuError(f"{model.path}: could not instantiate: {error}") from error

    def set(self, values: dict[str, Any]) -> None:
        """Set variables by name (``fmi2SetReal``/``Integer``/``Boolean``/``String``, an Enumeration as an Integer;
        FMI 3: ``Float64``/``Int8``/..., an Enumeration as an Int64)."""
        for name, value in values.items():
            variable = self.model.variables[name]
            kind = _KINDS.get(variable.type)
            if kind is None:
                raise FmuError(f"{self.model.path}: {name} is a {variable.type}; hlacore.fmu sets "
                               f"{', '.join(SUPPORTED_TYPES)} variables")
            try:
                getattr(self._fmu, f"set{self._access(variable)}")([variable.value_reference], [kind(value)])
            except Exception as error:
                raise FmuError(f"{self.model.path}: setting {name} = {value!r} failed: {error}") from error

    def get(self, names: list[str]) -> dict[str, Any]:
        """Read variables by name (``fmi2GetReal``/``Integer``/``Boolean``/``String``; FMI 3: ``Float64``/...)."""
        values: dict[str, Any] = {}
        for name in names:
            variable = self.model.variables[name]
            value = getattr(self._fmu, f"get{self._access(variable)}")([variable.value_reference])[0]
            if variable.type == "String" and isinstance(value, bytes):  # FMI 2's getString gives bytes
                value = value.decode()
            values[name] = _KINDS[variable.type](value)
        return values

    def _access(self, variable: Variable) -> str:
        """The type in the name of FMPy's set and get methods for ``variable``."""
        return _ENUMERATION_ACCESS[self.model.fmi3] if variable.type == "Enumeration" else variable.type

    def do_step(self, time: float, step: float, outputs: list[str]) -> dict[str, Any]:
        """``fmi2DoStep``/``fmi3DoStep(time, step)``, then the ``outputs`` at ``time + step``.

        Raises :class:`StepFailed` when the step fails or an output is not finite."""
        try:
            result = self._fmu.doStep(currentCommunicationPoint=time, communicationStepSize=step)
        except Exception as error:
            self._healthy = False
            raise StepFailed(f"{self.model.path}: doStep at t = {time:g} failed: {error}") from error
        if self.model.fmi3 and result[1]:  # (eventHandlingNeeded, terminateSimulation, earlyReturn, last time)
            raise StepFailed(f"{self.model.path}: the FMU asked to terminate the simulation at t = {time + step:g}")
        return self.outputs(outputs, time + step)

    def outputs(self, names: list[str], time: float) -> dict[str, Any]:
        """The outputs ``names`` at ``time`` (:meth:`get`); :class:`StepFailed` when one is not finite, or an
        Enumeration's value no item has."""
        values = self.get(names)
        for name, value in values.items():
            if isinstance(value, float) and not math.isfinite(value):
                raise StepFailed(f"{self.model.path}: output {name} = {value} at t = {time:g}")
            refusal = self.model.variables[name].items and self.model.variables[name].refusal(value)
            if refusal:
                raise StepFailed(f"{self.model.path}: output {name} = {value} at t = {time:g}, {refusal}")
        return values

    def save_state(self) -> bytes:
        """The FMU's state, serialised (``fmi2GetFMUstate``, ``fmi2SerializeFMUstate`` or FMI 3's).

        Raises :class:`FmuError` when the FMU cannot (its model description says so, or a call fails)."""
        if not self.model.can_save_state:
            raise FmuError(f"{self.model.path.name} cannot save its state (canGetAndSetFMUstate and "
                           "canSerializeFMUstate are not both true in its model description)")
        try:
            state = self._fmu.getFMUState()
            try:
                return bytes(self._fmu.serializeFMUState(state))
            finally:
                self._fmu.freeFMUState(state)
        except Exception as error:
            raise FmuError(f"{self.model.path.name}: saving its state failed: {error}") from error

    def restore_state(self, data: bytes) -> None:
        """Put the FMU back into a state :meth:`save_state` returned (``fmi2DeSerializeFMUstate``,
        ``fmi2SetFMUstate`` or FMI 3's). Raises :class:`FmuError` when it cannot."""
        if not self.model.can_save_state:
            raise FmuError(f"{self.model.path.name} cannot restore a state")
        try:
            state = self._fmu.deserializeFMUState(data)
            try:
                self._fmu.setFMUState(state)
            finally:
                self._fmu.freeFMUState(state)
        except Exception as error:
            raise FmuError(f"{self.model.path.name}: restoring its state failed: {error}") from error

    def close(self) -> None:
        """Terminate and free the instance and remove its directory (safe to call twice)."""
        fmu, self._fmu = self._fmu, None
        if fmu is not None and self._healthy:
            try:
                fmu.terminate()
            except Exception:  # it is freed all the same
                pass
        if fmu is not None and getattr(fmu, "component", None) is not None:
            fmu.freeInstance()
        shutil.rmtree(self._directory, ignore_errors=True)
