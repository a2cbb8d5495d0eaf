"""An FMU as a time-regulating, time-constrained federate: one HLA time advance per co-simulation step.

The time mapping (docs/fmu.md): the federate's logical time is the FMU's time. At a grant of t the FMU holds
its state at t; its inputs are set to the last value reflected with a timestamp up to t (or their start
value, before any); ``doStep(t, h)``; its outputs at t + h are sent as updates stamped t + h, which the
lookahead h allows (and as interactions stamped t + h, for outputs mapped to parameters); then
``timeAdvanceRequest(t + h)``. A peer that wants an input to hold over the step
from t sends it stamped t. This is FMPy's own order (inputs at t, step, outputs at t + h), so a federated run
gives ``fmpy.simulate_fmu``'s trajectory.
"""

from __future__ import annotations

import base64
import json
import math
import pathlib
import time
from typing import Any, Optional, Union

from .. import rti
from .errors import FmuError, InputError, StepFailed
from .exchange import Input, Send
from .mapping import ENCODINGS, Mapping, constant_encoding
from .model import FmuInstance, FmuModel, check_value


#: The lookahead is the step size less this fraction of it, so that the grid times start + k h, computed without
#: drift, are always at or past the federate time plus the lookahead despite rounding.
LOOKAHEAD_MARGIN = 1e-9


class _Ambassador(rti.FederateAmbassador):
    """Keeps the last value received of each mapped input (TSO: the last is the latest), and hands save and
    restore to the federate. A value that cannot be decoded is kept in ``error`` for the next step to raise."""

    def __init__(self, federate: "FmuFederate") -> None:
        self.federate = federate
        self.instances: dict[Any, tuple[Any, str]] = {}  # object -> (its class, its name)
        self.inputs: dict[tuple[Any, Any], list[Input]] = {}  # (class, attribute) -> where its values go
        self.parameters: dict[tuple[Any, Any], list[Input]] = {}  # (interaction, parameter) -> the same
        self.received: dict[str, Any] = {}
        self.error: Optional[InputError] = None
        self.taken: Optional[float] = None  # with feedthrough: the time of the inputs last taken

    def discoverObjectInstance(self, obj: Any, objectClass: Any, name: str) -> None:
        """Note the instance's class and name, to read its reflections (HLA 1.3 §6.3)."""
        self.instances[obj] = (objectClass, name)

    def reflectAttributeValues(self, obj: Any, attributes: dict[Any, bytes], tag: str, order: Any,
                               transport: Any, time: Optional[float] = None, retraction: Any = None) -> None:
        """Keep the mapped attributes' values as the inputs' next values (HLA 1.3 §6.4)."""
        cls, name = self.instances.get(obj, (None, ""))
        for attribute, data in attributes.items():
            self._keep(self.inputs.get((cls, attribute), []), data, f"instance {name!r}", name, time)

    def receiveInteraction(self, interactionClass: Any, parameters: dict[Any, bytes], tag: str, order: Any,
                           transport: Any, time: Optional[float] = None, retraction: Any = None) -> None:
        """Keep the mapped parameters' values as the inputs' next values (HLA 1.3 §6.6)."""
        for parameter, data in parameters.items():
            self._keep(self.parameters.get((interactionClass, parameter), []), data, "an interaction", None, time)

    def _keep(self, inputs: list[Input], data: bytes, source: str, instance: Optional[str],
              time: Optional[float]) -> None:
        for target in inputs:
            if target.instance is not None and target.instance != instance:
                continue
            if time is not None and self.taken is not None and time <= self.taken:
                self.error = self.error or InputError(
                    f"{target.variable.name}: {source} sent a value stamped {time:g} after the inputs of "
                    f"{self.taken:g} were taken: from a federate with lookahead 0, such as another FMU with direct "
                    f"feedthrough; run this one with feedthrough off (docs/fmu.md)")
                continue
            try:
                self.received[target.variable.name] = target.decode(data, source)
            except InputError as error:
                self.error = self.error or error

    def initiateFederateSave(self, label: str) -> None:
        """Save the FMU's state and the federate's under ``label`` (HLA 1.3 §4.12)."""
        self.federate._save(label)

    def federationSaved(self) -> None:
        """The save is over (HLA 1.3 §4.15): stepping may go on."""
        self.federate._saving = False

    def federationNotSaved(self) -> None:
        """The save failed (HLA 1.3 §4.15): stepping may go on."""
        self.federate._saving = False

    def federationRestoreBegun(self) -> None:
        """A restore is under way (HLA 1.3 §4.18): no step until it is over."""
        self.federate._restoring = True

    def initiateFederateRestore(self, label: str, federateHandle: Any) -> None:
        """Restore the FMU's state and the federate's saved under ``label`` (HLA 1.3 §4.19)."""
        self.federate._restore(label)

    def federationRestored(self) -> None:
        """The restore is over (HLA 1.3 §4.21)."""
        self.federate._restoring = False

    def federationNotRestored(self) -> None:
        """The restore failed (HLA 1.3 §4.21)."""
        self.federate._restoring = False


class FmuFederate:
    """An FMI 2 or FMI 3 co-simulation FMU joined to a federation (the module's docstring: the time mapping).

    Everything that can be wrong with the FMU or the mapping is raised when the object is made, before joining:
    :class:`FmuError` (missing, corrupt, unsupported, no binary), :class:`NotCoSimulation`,
    :class:`MappingError`. :meth:`join` joins (creating the federation from ``fed_file`` unless it exists),
    enables time regulation with lookahead ``step_size`` (:attr:`lookahead`) and time constraint, publishes
    the outputs, registers one object instance per output class and subscribes to the inputs' attributes and
    interactions; :meth:`run` steps; :meth:`close` resigns and frees the FMU. Use it as a context manager to
    have :meth:`close` called whatever happens.
    """

    def __init__(self, fmu: Union[str, pathlib.Path], federation: str, *, step_size: float,
                 name: Optional[str] = None, address: Optional[str] = None, fed_file: Optional[str] = None,
                 mapping: Union[Mapping, str, pathlib.Path, None] = None,
                 start_values: Optional[dict[str, Any]] = None, timeout: Optional[float] = 60.0,
                 save_dir: Union[str, pathlib.Path, None] = None, feedthrough: Optional[bool] = None) -> None:
        if not (step_size > 0 and math.isfinite(step_size)):
            raise FmuError(f"step size {step_size}: a positive number of seconds")
        self.model = FmuModel(fmu)
        if mapping is None:
            self.mapping = Mapping.by_name(self.model)
        elif isinstance(mapping, Mapping):
            mapping.check(self.model)
            self.mapping = mapping
        else:
            self.mapping = Mapping.load(mapping, self.model)
        #: Whether outputs are sent at the time of the inputs they follow (lookahead 0: docs/fmu.md, "Direct
        #: feedthrough"); by default, when the model description says an output depends directly on an input.
        self.feedthrough = (bool(self.model.direct_feedthrough and self.mapping.inputs and self.mapping.outputs)
                            if feedthrough is None else bool(feedthrough))
        self.federation = federation
        self.name = name or self.model.name
        self.step_size = float(step_size)
        self.timeout = timeout
        self._address = address
        self._fed_file = fed_file
        self._start_values = {variable: check_value(self.model, variable, value)
                              for variable, value in (start_values or {}).items()}
        self._instance: Optional[FmuInstance] = None
        self._rtia: Optional[rti.RTIAmbassador] = None
        self._ambassador = _Ambassador(self)
        #: Where federation saves put this federate's state: ``<label>.<name>.fmustate`` (default: the current
        #: directory).
        self.save_dir = pathlib.Path(save_dir if save_dir is not None else ".")
        #: Why each save or restore this federate could not take part in failed, by label.
        self.save_errors: dict[str, str] = {}
        #: The labels of the saves this federate completed, and of the restores, in order.
        self.saved: list[str] = []
        self.restored: list[str] = []
        self._saving = False
        self._restoring = False
        self._sends: list[Send] = []
        self._in_flight: Optional[tuple[float, Optional[dict[str, Any]]]] = None  # a step done, not yet granted
        self._lookahead_now = 0.0
        #: (time, {output: value}) at the start and after each step, as sent.
        self.trajectory: list[tuple[float, dict[str, Any]]] = []
        self.time = 0.0
        self._start_time = 0.0
        self._steps = 0

    def __enter__(self) -> "FmuFederate":
        return self

    def __exit__(self, *exc: object) -> None:
        self.close()

    @property
    def lookahead(self) -> float:
        """The lookahead while stepping: the step size, less :data:`LOOKAHEAD_MARGIN` of it; 0 with
        :attr:`feedthrough`, which has the step's between runs (at the start time and once :meth:`run` returns:
        it sends nothing more at its time, so that others may be granted it)."""
        return 0.0 if self.feedthrough else self._step_lookahead

    @property
    def _step_lookahead(self) -> float:
        return self.step_size * (1.0 - LOOKAHEAD_MARGIN)

    def _set_lookahead(self, lookahead: float) -> None:
        if lookahead != self._lookahead_now:
            self.rtia.modifyLookahead(lookahead)
            self._lookahead_now = lookahead

    @property
    def pending(self) -> Optional[float]:
        """The time of the step done and sent whose grant has not come yet, if any."""
        return None if self._in_flight is None else self._in_flight[0]

    @property
    def rtia(self) -> rti.RTIAmbassador:
        """The RTI ambassador, once joined."""
        if self._rtia is None:
            raise rti.FederateNotExecutionMember(f"{self.name} has not joined")
        return self._rtia

    def join(self) -> None:
        """Instantiate the FMU, join, enable time management and declare the mapping (HLA 1.3 §4.4, §8.2, §8.4,
        §5.2, §5.6). Raises what those services raise (a class or attribute the FOM lacks: NameNotFound),
        after resigning and freeing the FMU."""
        outputs = [name for name in self.mapping.outputs]
        self._instance = self.model.instantiate(0.0, self._start_values)
        try:
            self._rtia = rti.RTIAmbassador(self._address)
            self._rtia.create_or_join(self.name, self.federation, self._fed_file, self._ambassador)
            # With the step's lookahead even for feedthrough (lowered by each step): a zero-lookahead newcomer would
            # start at the others' promise (docs/time-management.md), off their grid.
            self.time = self._start_time = self._rtia.enable_time_management(self._step_lookahead,
                                                                             timeout=self.timeout)
            self._lookahead_now = self._step_lookahead
            self._declare()
            self.trajectory.append((self.time, self._instance.get(outputs)))
        except BaseException:
            self.close()
            raise

    def _declare(self) -> None:
        rtia = self.rtia
        sends: dict[tuple[str, bool], Send] = {}
        for endpoint, outputs in self.mapping.members().items():
            send = sends.get((endpoint.object_class, endpoint.interaction))
            if send is None:
                send = sends[endpoint.object_class, endpoint.interaction] = Send(rtia, endpoint)
            send.members[send.member(rtia, endpoint.attribute)] = (
                outputs, ENCODINGS[self.model.variables[outputs[0]].type])
        for member, value in self.mapping.constants.items():
            object_class, _, name = member.rpartition(".")
            send = sends.get((object_class, True)) or sends[object_class, False]
            send.constants[send.member(rtia, name)] = constant_encoding(value, member).pack(value)
        for send in sends.values():
            send.publish(rtia, f"{self.name}.{send.object_class}")
        self._sends = list(sends.values())
        subscribed: dict[Any, list[Any]] = {}
        interactions: set[Any] = set()
        for variable, endpoint in self.mapping.inputs.items():
            target = Input(self.model.variables[variable], endpoint.element, endpoint.instance)
            if endpoint.interaction:
                interaction = rtia.getInteractionClassHandle(endpoint.object_class)
                parameter = rtia.getParameterHandle(endpoint.attribute, interaction)
                self._ambassador.parameters.setdefault((interaction, parameter), []).append(target)
                interactions.add(interaction)
                continue
            cls = rtia.getObjectClassHandle(endpoint.object_class)
            attribute = rtia.getAttributeHandle(endpoint.attribute, cls)
            if attribute not in subscribed.setdefault(cls, []):
                subscribed[cls].append(attribute)
            self._ambassador.inputs.setdefault((cls, attribute), []).append(target)
        for cls, attributes in subscribed.items():
            rtia.subscribeObjectClassAttributes(cls, attributes)
        for interaction in interactions:
            rtia.subscribeInteractionClass(interaction)

    def step(self) -> None:
        """One co-simulation step from the current time t: inputs, ``doStep(t, h)``, the outputs sent stamped
        t + h, ``timeAdvanceRequest(t + h)`` until granted. Raises :class:`StepFailed` or (for a value received
        that its input cannot decode) :class:`InputError`, after resigning.

        A save taken while the request waits keeps the step as done and sent; a restore while it waits
        returns at once, with the federate where that save left it; the next call resumes from there."""
        assert self._instance is not None, "join() first"
        self.settle()
        self._set_lookahead(self.lookahead)
        if self._in_flight is None:
            t, h = self.time, self.step_size
            next_time = self._start_time + (self._steps + 1) * h  # the k-th grant is start + k h: no drift
            values: Optional[dict[str, Any]] = None
            try:
                if self.feedthrough:  # inputs set and outputs sent at the grant (_exchange)
                    self._instance.do_step(t, h, [])
                else:
                    self._take_inputs()
                    values = self._instance.do_step(t, h, list(self.mapping.outputs))
            except (StepFailed, InputError):
                self.close()
                raise
            if values is not None:
                self._send(values, next_time)
            self._in_flight = (next_time, values)
        next_time, values = self._in_flight
        restores = len(self.restored)
        if self.feedthrough:  # granted "available": it may then send at the grant's time
            self.rtia.timeAdvanceRequestAvailable(next_time)
            granted = self.rtia.await_grant(timeout=self.timeout)
        else:
            granted = self.rtia.advance_to(next_time, timeout=self.timeout)
        if len(self.restored) != restores:
            return  # the restore dropped the request and put the federate back where the save found it
        self.time = granted
        self._steps += 1
        self.trajectory.append((self.time, values if values is not None else self._exchange(granted)))
        self._in_flight = None

    def _take_inputs(self) -> None:
        """Set the inputs to the values received (InputError for one that could not be decoded)."""
        if self._ambassador.error is not None:
            raise self._ambassador.error
        assert self._instance is not None
        self._instance.set(self._ambassador.received)
        self._ambassador.received = {}

    def _send(self, values: dict[str, Any], time: float) -> None:
        for send in self._sends:
            send.send(self.rtia, values, self.name, time)

    def _exchange(self, time: float) -> dict[str, Any]:
        """With :attr:`feedthrough`, at a grant: the inputs set, the outputs read and sent stamped ``time``."""
        assert self._instance is not None
        try:
            self._take_inputs()
            self._ambassador.taken = time
            values = self._instance.outputs(list(self.mapping.outputs), time)
        except (StepFailed, InputError):
            self.close()
            raise
        self._send(values, time)
        return values

    def run(self, stop_time: float) -> list[tuple[float, dict[str, Any]]]:
        """Step until ``stop_time`` (steps of the step size from the time joined; the last may end past it by
        less than a step's rounding); returns :attr:`trajectory`."""
        self.settle()
        while self.time < stop_time - 1e-9 * self.step_size:
            self.step()
        self._set_lookahead(self._step_lookahead)
        return self.trajectory

    def state_file(self, label: str) -> pathlib.Path:
        """Where the save ``label`` keeps this federate's state."""
        return self.save_dir / f"{label}.{self.name}.fmustate"

    def settle(self) -> None:
        """Deliver the callbacks that have arrived, then tick until a federation save or restore under way is over
        (HLA 1.3 §4.11-4.22; :meth:`step` and :meth:`run` do this first). Raises TimeoutError after ``timeout``."""
        while self.rtia.tick():
            pass
        deadline = None if self.timeout is None else time.monotonic() + self.timeout
        while self._saving or self._restoring:
            if deadline is not None and time.monotonic() > deadline:
                raise TimeoutError(f"{self.name}: the federation save or restore did not end "
                                   f"within {self.timeout} s")
            self.rtia.tick(0.1, 0.1)

    def _save(self, label: str) -> None:
        """The FMU's serialised state and the federate's own (time, steps, inputs received, trajectory) to
        :meth:`state_file`, then federateSaveComplete; federateSaveNotComplete, the reason in
        :attr:`save_errors`, when the FMU cannot save."""
        self._saving = True
        try:
            assert self._instance is not None
            fmu_state = self._instance.save_state()
            own = {"time": self.time, "start_time": self._start_time, "steps": self._steps,
                   "received": self._ambassador.received, "trajectory": self.trajectory, "in_flight": self._in_flight,
                   "fmu_state": base64.b64encode(fmu_state).decode()}
            self.save_dir.mkdir(parents=True, exist_ok=True)
            partial = self.state_file(label).with_suffix(".part")
            partial.write_text(json.dumps(own))
            partial.replace(self.state_file(label))
        except (FmuError, OSError) as error:
            self.save_errors[label] = str(error)
            self.rtia.federateSaveNotComplete()
            return
        self.saved.append(label)
        self.rtia.federateSaveComplete()

    def _restore(self, label: str) -> None:
        """Back to the state :meth:`_save` wrote for ``label``, then federateRestoreComplete (NotComplete,
        the reason in :attr:`save_errors`, when the file is missing or the FMU refuses it)."""
        self._restoring = True
        try:
            assert self._instance is not None
            own = json.loads(self.state_file(label).read_text())
            self._instance.restore_state(base64.b64decode(own["fmu_state"]))
        except (FmuError, OSError, ValueError, KeyError) as error:
            self.save_errors[label] = str(error)
            self.rtia.federateRestoreNotComplete()
            return
        self.time, self._start_time, self._steps = own["time"], own["start_time"], own["steps"]
        self._ambassador.received = own["received"]
        self._ambassador.taken = None
        self.trajectory = [(t, values) for t, values in own["trajectory"]]
        in_flight = own.get("in_flight")
        self._in_flight = None if in_flight is None else (in_flight[0], in_flight[1])
        self.restored.append(label)
        self.rtia.federateRestoreComplete()

    def close(self) -> None:
        """Resign (deleting the registered objects) and free the FMU; safe to call twice."""
        rtia, self._rtia = self._rtia, None
        try:
            if rtia is not None:
                try:
                    rtia.resignFederationExecution(rti.ResignAction.DeleteObjectsAndReleaseAttributes)
                except rti.FederateNotExecutionMember:
                    pass
        finally:
            instance, self._instance = self._instance, None
            if instance is not None:
                instance.close()


__all__ = ["FmuFederate"]
