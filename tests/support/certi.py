"""A federate's side of CERTI 3.5.1's federate protocol, to drive hlacore-rtia as CERTI's libRTI and JCERTI do:
written here, in Python, from the protocol's published layouts, apart from the rtia's C++ (docs/certi.md).

A frame: the byte order (1: big endian, 0: little), the frame's length (32 bits, the 5 header bytes included),
the message type and exception code (32 bits each), then the exception's reason, or else the optional date,
label and tag (each a presence byte and its value), then the type's fields. CertiFederate starts the rtia
as libRTI does (``rtia -f FD``, its end of a socket pair) or as JCERTI does (``rtia -p PORT``, connecting back
to a port the federate listens on), in either byte order."""

from __future__ import annotations

import math
import os
import pathlib
import socket
import struct
import subprocess
import time
from dataclasses import dataclass, field
from typing import Any, Callable, Optional

# Each message type, in CERTI's numbering from 1, with its fields: name:kind; the last two are JCERTI's
# (its IEEE 1516-2010 ambassador's create and join, with FOM modules).
SPEC = """
OPEN_CONNEXION version_major:u32 version_minor:u32
CLOSE_CONNEXION
CREATE_FEDERATION_EXECUTION federation:str fed:str
DESTROY_FEDERATION_EXECUTION federation:str
JOIN_FEDERATION_EXECUTION federate:u32 federation:str federate_name:str
RESIGN_FEDERATION_EXECUTION resign_action:u16
REGISTER_FEDERATION_SYNCHRONIZATION_POINT handles:u32s
SYNCHRONIZATION_POINT_REGISTRATION_FAILED
SYNCHRONIZATION_POINT_REGISTRATION_SUCCEEDED
ANNOUNCE_SYNCHRONIZATION_POINT
SYNCHRONIZATION_POINT_ACHIEVED
FEDERATION_SYNCHRONIZED
REQUEST_FEDERATION_SAVE
INITIATE_FEDERATE_SAVE
FEDERATE_SAVE_BEGUN
FEDERATE_SAVE_COMPLETE
FEDERATE_SAVE_NOT_COMPLETE
FEDERATION_SAVED
FEDERATION_NOT_SAVED
REQUEST_FEDERATION_RESTORE
REQUEST_FEDERATION_RESTORE_FAILED reason:str
REQUEST_FEDERATION_RESTORE_SUCCEEDED
INITIATE_FEDERATE_RESTORE federate:u32
FEDERATE_RESTORE_COMPLETE
FEDERATE_RESTORE_NOT_COMPLETE
FEDERATION_RESTORED
FEDERATION_NOT_RESTORED
FEDERATION_RESTORE_BEGUN
PUBLISH_OBJECT_CLASS object_class:u32 handles:u32s
UNPUBLISH_OBJECT_CLASS object_class:u32
PUBLISH_INTERACTION_CLASS interaction_class:u32
UNPUBLISH_INTERACTION_CLASS interaction_class:u32
SUBSCRIBE_OBJECT_CLASS_ATTRIBUTES object_class:u32 handles:u32s flag:bool
UNSUBSCRIBE_OBJECT_CLASS object_class:u32
SUBSCRIBE_INTERACTION_CLASS interaction_class:u32
UNSUBSCRIBE_INTERACTION_CLASS interaction_class:u32
START_REGISTRATION_FOR_OBJECT_CLASS object_class:u32
STOP_REGISTRATION_FOR_OBJECT_CLASS object_class:u32
TURN_INTERACTIONS_ON interaction_class:u32
TURN_INTERACTIONS_OFF interaction_class:u32
REGISTER_OBJECT_INSTANCE object_class:u32 object:u32 name:optstr
UPDATE_ATTRIBUTE_VALUES object_class:u32 object:u32 handles:u32s values:bytes retraction:optretraction
DISCOVER_OBJECT_INSTANCE object_class:u32 object:u32 name:str retraction:optretraction
REFLECT_ATTRIBUTE_VALUES object_class:u32 object:u32 handles:u32s values:bytes retraction:optretraction
SEND_INTERACTION interaction_class:u32 handles:u32s values:bytes region:u32 retraction:optretraction
RECEIVE_INTERACTION interaction_class:u32 handles:u32s values:bytes region:u32 retraction:optretraction
DELETE_OBJECT_INSTANCE object_class:u32 object:u32 name:str retraction:optretraction
LOCAL_DELETE_OBJECT_INSTANCE object:u32
REMOVE_OBJECT_INSTANCE object_class:u32 object:u32 name:str retraction:optretraction
CHANGE_ATTRIBUTE_TRANSPORTATION_TYPE transport:u8 order:u8 object:u32 handles:u32s
CHANGE_INTERACTION_TRANSPORTATION_TYPE interaction_class:u32 transport:u8 order:u8
REQUEST_OBJECT_ATTRIBUTE_VALUE_UPDATE object:u32 handles:u32s
REQUEST_CLASS_ATTRIBUTE_VALUE_UPDATE object_class:u32 handles:u32s
PROVIDE_ATTRIBUTE_VALUE_UPDATE object:u32 handles:u32s
ATTRIBUTES_IN_SCOPE object:u32 handles:u32s
ATTRIBUTES_OUT_OF_SCOPE object:u32 handles:u32s
TURN_UPDATES_ON_FOR_OBJECT_INSTANCE object:u32 handles:u32s
TURN_UPDATES_OFF_FOR_OBJECT_INSTANCE object:u32 handles:u32s
REQUEST_ATTRIBUTE_OWNERSHIP_DIVESTITURE
REQUEST_ATTRIBUTE_OWNERSHIP_ASSUMPTION object:u32 handles:u32s
NEGOTIATED_ATTRIBUTE_OWNERSHIP_DIVESTITURE object:u32 handles:u32s
ATTRIBUTE_OWNERSHIP_DIVESTITURE_NOTIFICATION object:u32 handles:u32s
ATTRIBUTE_OWNERSHIP_ACQUISITION_NOTIFICATION object:u32 handles:u32s
REQUEST_ATTRIBUTE_OWNERSHIP_ACQUISITION object:u32 handles:u32s
REQUEST_ATTRIBUTE_OWNERSHIP_RELEASE object:u32 handles:u32s
QUERY_ATTRIBUTE_OWNERSHIP object:u32 attribute:u32
INFORM_ATTRIBUTE_OWNERSHIP object:u32 attribute:u32 federate:u32
IS_ATTRIBUTE_OWNED_BY_FEDERATE object:u32 attribute:u32
ATTRIBUTE_IS_NOT_OWNED object:u32 attribute:u32 federate:u32
ATTRIBUTE_OWNED_BY_RTI
ATTRIBUTE_OWNERSHIP_ACQUISITION_IF_AVAILABLE object:u32 handles:u32s
ATTRIBUTE_OWNERSHIP_UNAVAILABLE object:u32 handles:u32s
UNCONDITIONAL_ATTRIBUTE_OWNERSHIP_DIVESTITURE object:u32 handles:u32s
ATTRIBUTE_OWNERSHIP_ACQUISITION object:u32 handles:u32s
CANCEL_NEGOTIATED_ATTRIBUTE_OWNERSHIP_DIVESTITURE object:u32 handles:u32s
ATTRIBUTE_OWNERSHIP_RELEASE_RESPONSE object:u32 handles:u32s
CANCEL_ATTRIBUTE_OWNERSHIP_ACQUISITION object:u32 handles:u32s
CONFIRM_ATTRIBUTE_OWNERSHIP_ACQUISITION_CANCELLATION object:u32 handles:u32s
CHANGE_ATTRIBUTE_ORDER_TYPE transport:u8 order:u8 object:u32 handles:u32s
CHANGE_INTERACTION_ORDER_TYPE interaction_class:u32 transport:u8 order:u8
ENABLE_TIME_REGULATION lookahead:f64
DISABLE_TIME_REGULATION lookahead:f64
ENABLE_TIME_CONSTRAINED
DISABLE_TIME_CONSTRAINED
QUERY_LBTS
QUERY_FEDERATE_TIME
QUERY_MIN_NEXT_EVENT_TIME
MODIFY_LOOKAHEAD lookahead:f64
QUERY_LOOKAHEAD lookahead:f64
RETRACT retraction:retraction
REQUEST_RETRACTION
TIME_ADVANCE_REQUEST
TIME_ADVANCE_REQUEST_AVAILABLE
NEXT_EVENT_REQUEST
NEXT_EVENT_REQUEST_AVAILABLE
FLUSH_QUEUE_REQUEST
TIME_ADVANCE_GRANT
ENABLE_ASYNCHRONOUS_DELIVERY
DISABLE_ASYNCHRONOUS_DELIVERY
TIME_REGULATION_ENABLED
TIME_CONSTRAINED_ENABLED
DDM_CREATE_REGION space:u32 extent_count:u32 region:u32
DDM_MODIFY_REGION region:u32 extent_count:u32
DDM_DELETE_REGION region:u32
DDM_REGISTER_OBJECT object_class:u32 object:u32 name:optstr handles:u32s
DDM_ASSOCIATE_REGION object:u32 region:u32 handles:u32s
DDM_UNASSOCIATE_REGION object:u32 region:u32
DDM_SUBSCRIBE_ATTRIBUTES object_class:u32 region:u32 flag:bool handles:u32s
DDM_UNSUBSCRIBE_ATTRIBUTES object_class:u32 region:u32
DDM_SUBSCRIBE_INTERACTION interaction_class:u32 region:u32 flag:bool
DDM_UNSUBSCRIBE_INTERACTION interaction_class:u32 region:u32 flag:bool
DDM_REQUEST_UPDATE object_class:u32 region:u32 handles:u32s
GET_OBJECT_CLASS_{HANDLE,NAME} object_class:u32 name:str
GET_ATTRIBUTE_{HANDLE,NAME} object_class:u32 name:str attribute:u32
GET_INTERACTION_CLASS_{HANDLE,NAME} interaction_class:u32 name:str
GET_PARAMETER_{HANDLE,NAME} interaction_class:u32 name:str parameter:u32
GET_OBJECT_INSTANCE_{HANDLE,NAME} object:u32 name:str
GET_SPACE_{HANDLE,NAME} name:str space:u32
GET_DIMENSION_{HANDLE,NAME} name:str space:u32 dimension:u32
GET_ATTRIBUTE_SPACE_HANDLE object_class:u32 attribute:u32 space:u32
GET_OBJECT_CLASS object_class:u32 object:u32
GET_INTERACTION_SPACE_HANDLE interaction_class:u32 space:u32
GET_TRANSPORTATION_{HANDLE,NAME} name:str transport:u8
GET_ORDERING_{HANDLE,NAME} name:str order:u8
ENABLE_CLASS_RELEVANCE_ADVISORY_SWITCH
DISABLE_CLASS_RELEVANCE_ADVISORY_SWITCH
ENABLE_ATTRIBUTE_RELEVANCE_ADVISORY_SWITCH
DISABLE_ATTRIBUTE_RELEVANCE_ADVISORY_SWITCH
ENABLE_ATTRIBUTE_SCOPE_ADVISORY_SWITCH
DISABLE_ATTRIBUTE_SCOPE_ADVISORY_SWITCH
ENABLE_INTERACTION_RELEVANCE_ADVISORY_SWITCH
DISABLE_INTERACTION_RELEVANCE_ADVISORY_SWITCH
TICK_REQUEST flag:bool min_tick:f64 max_tick:f64
TICK_REQUEST_NEXT
TICK_REQUEST_STOP
RESERVE_OBJECT_INSTANCE_NAME name:str
RESERVE_OBJECT_INSTANCE_NAME_SUCCEEDED name:str
RESERVE_OBJECT_INSTANCE_NAME_FAILED name:str
CREATE_FEDERATION_EXECUTION_V4 federation:str rti_version:u8 values:bytes mim:optstr time_name:optstr
JOIN_FEDERATION_EXECUTION_V4 federate:u32 name:optstr federate_type:str rti_version:u8 federation:str values:bytes
"""
LAYOUTS: dict[str, list[tuple[str, str]]] = {}
CODES: dict[str, int] = {}
for _line in SPEC.split("\n")[1:-1]:
    _name, *_fields = _line.split()
    # GET_X_{HANDLE,NAME}: the two lookups of X, one code after the other, share a layout
    for _each in [_name.replace("{HANDLE,NAME}", w) for w in ("HANDLE", "NAME")] if "{" in _name else [_name]:
        CODES[_each] = len(CODES) + 1
        LAYOUTS[_each] = [(f.split(":")[0], f.split(":")[1]) for f in _fields]
NAMES = {code: name for name, code in CODES.items()}

# CERTI's exception codes from 1 (0: none).
EXCEPTIONS = """ArrayIndexOutOfBounds AsynchronousDeliveryAlreadyEnabled AsynchronousDeliveryAlreadyDisabled
AttributeAlreadyOwned AttributeAlreadyBeingAcquired AttributeAlreadyBeingDivested AttributeAcquisitionWasNotRequested
AttributeDivestitureWasNotRequested AttributeNotDefined AttributeNotKnown AttributeNotOwned AttributeNotPublished
AttributeNotSubscribed ConcurrentAccessAttempted CouldNotDiscover CouldNotOpenRID CouldNotOpenFED CouldNotRestore
DeletePrivilegeNotHeld ErrorReadingRID ErrorReadingFED EventNotKnown FederateAlreadyPaused
FederateAlreadyExecutionMember FederateDoesNotExist FederateInternalError FederateNameAlreadyInUse
FederateNotExecutionMember FederateNotPaused FederateNotPublishing FederateNotSubscribing FederateOwnsAttributes
FederatesCurrentlyJoined FederateWasNotAskedToReleaseAttribute FederationAlreadyPaused
FederationExecutionAlreadyExists FederationExecutionDoesNotExist FederationNotPaused FederationTimeAlreadyPassed
RegionNotKnown IDsupplyExhausted InteractionClassNotDefined InteractionClassNotKnown InteractionClassNotPublished
InteractionParameterNotDefined InteractionParameterNotKnown InvalidDivestitureCondition InvalidExtents
InvalidFederationTime InvalidFederationTimeDelta InvalidObjectHandle InvalidResignAction InvalidRetractionHandle
InvalidRoutingSpace MemoryExhausted NameNotFound NoPauseRequested NoResumeRequested ObjectClassNotDefined
ObjectClassNotKnown ObjectClassNotPublished ObjectClassNotSubscribed ObjectNotKnown ObjectAlreadyRegistered
RestoreInProgress RestoreNotRequested RTICannotRestore RTIinternalError SpaceNotDefined SaveInProgress
SaveNotInitiated SecurityError SocketNotConnected MessageNotSent MessageNotReceived SocketNotClosed
RingBufferNotCreated RingBufferNotClosed RingBufferNotDeleted RingBufferNotAttached MessageTooLong BufferFull
BufferEmpty SocketSHMNotCreated SocketSHMNotOpen SocketSHMNotDeleted SpecifiedSaveLabelDoesNotExist
TimeAdvanceAlreadyInProgress TimeAdvanceWasNotInProgress TooManyIDsRequested UnableToPerformSave
UnimplementedService UnknownLabel ValueCountExceeded ValueLengthExceeded AttributeAcquisitionWasNotCanceled
DimensionNotDefined EnableTimeConstrainedPending EnableTimeConstrainedWasNotPending EnableTimeRegulationPending
EnableTimeRegulationWasNotPending FederateLoggingServiceCalls HandleValuePairMaximumExceeded
InteractionClassNotSubscribed InvalidHandleValuePairSetContext InvalidLookahead InvalidOrderingHandle
InvalidRegionContext InvalidTransportationHandle OwnershipAcquisitionPending RegionInUse
SynchronizationPointLabelWasNotAnnounced TimeConstrainedAlreadyEnabled TimeConstrainedWasNotEnabled
TimeRegulationAlreadyEnabled TimeRegulationWasNotEnabled NetworkError NetworkSignal IllegalName""".split()
EXCEPTION_CODES = {name: code for code, name in enumerate(EXCEPTIONS, start=1)}


@dataclass
class Message:
    """One message: its type's name, the common part, and its fields by name (absent ones are zero)."""

    type: str
    exception: str = ""
    reason: str = ""
    date: Optional[float] = None
    label: Optional[str] = None
    tag: Optional[str] = None
    fields: dict[str, Any] = field(default_factory=dict)

    def __getattr__(self, name: str) -> Any:
        fields = self.__dict__.get("fields", {})
        if name in fields:
            return fields[name]
        raise AttributeError(name)


ZERO = {"u8": 0, "u16": 0, "u32": 0, "bool": False, "f64": 0.0, "str": "", "u32s": [], "bytes": [],
        "optstr": None, "optretraction": None, "retraction": (0, 0)}


def encode(m: Message, big_endian: bool) -> bytes:
    """The frame of `m` in the given byte order."""
    e = ">" if big_endian else "<"

    def string(s: str | bytes) -> bytes:
        raw = s.encode() if isinstance(s, str) else s
        return struct.pack(e + "I", len(raw)) + raw

    body = struct.pack(e + "ii", CODES[m.type], EXCEPTION_CODES.get(m.exception, 0))
    if m.exception:
        body += string(m.reason)
    else:
        body += struct.pack(e + "?", m.date is not None) + (struct.pack(e + "d", m.date) if m.date is not None else b"")
        for text in (m.label, m.tag):
            body += struct.pack(e + "?", text is not None) + (string(text) if text is not None else b"")
    for name, kind in LAYOUTS[m.type]:
        v = m.fields.get(name, ZERO[kind])
        if kind in ("u8", "u16", "u32", "bool", "f64"):
            body += struct.pack(e + {"u8": "B", "u16": "H", "u32": "I", "bool": "?", "f64": "d"}[kind], v)
        elif kind == "str":
            body += string(v)
        elif kind == "u32s":
            body += struct.pack(e + "I", len(v)) + b"".join(struct.pack(e + "I", h) for h in v)
        elif kind == "bytes":
            body += struct.pack(e + "I", len(v)) + b"".join(string(x) for x in v)
        elif kind == "optstr":
            body += struct.pack(e + "?", v is not None) + (string(v) if v is not None else b"")
        elif kind in ("optretraction", "retraction"):
            if kind == "optretraction":
                body += struct.pack(e + "?", v is not None)
            if v is not None:
                body += struct.pack(e + "IQ", *v)
    return struct.pack(e + "BI", 1 if big_endian else 0, 5 + len(body)) + body


class Cursor:
    def __init__(self, data: bytes, big_endian: bool) -> None:
        self.data, self.at, self.e = data, 0, ">" if big_endian else "<"

    def take(self, fmt: str) -> Any:
        size = struct.calcsize(self.e + fmt)
        values = struct.unpack_from(self.e + fmt, self.data, self.at)
        self.at += size
        return values[0] if len(values) == 1 else values

    def bytes(self) -> bytes:
        n = self.take("I")
        raw = self.data[self.at:self.at + n]
        assert len(raw) == n, "truncated"
        self.at += n
        return raw


def decode(frame: bytes) -> Message:
    """The message of a whole frame."""
    big = frame[0] == 1
    c = Cursor(frame, big)
    c.at = 1
    assert c.take("I") == len(frame), "the frame's length"
    code, exception = c.take("ii")
    m = Message(NAMES[code], EXCEPTIONS[exception - 1] if exception else "")
    if exception:
        m.reason = c.bytes().decode()
    else:
        if c.take("?"):
            m.date = c.take("d")
        if c.take("?"):
            m.label = c.bytes().decode()
        if c.take("?"):
            m.tag = c.bytes().decode()
    for name, kind in LAYOUTS[m.type]:
        if kind in ("u8", "u16", "u32", "bool", "f64"):
            m.fields[name] = c.take({"u8": "B", "u16": "H", "u32": "I", "bool": "?", "f64": "d"}[kind])
        elif kind == "str":
            m.fields[name] = c.bytes().decode()
        elif kind == "u32s":
            m.fields[name] = [c.take("I") for _ in range(c.take("I"))]
        elif kind == "bytes":
            m.fields[name] = [c.bytes() for _ in range(c.take("I"))]
        elif kind == "optstr":
            m.fields[name] = c.bytes().decode() if c.take("?") else None
        elif kind == "optretraction":
            m.fields[name] = c.take("IQ") if c.take("?") else None
        elif kind == "retraction":
            m.fields[name] = c.take("IQ")
    assert c.at == len(frame), f"{m.type}: {len(frame) - c.at} bytes left over"
    return m


class CertiError(Exception):
    """A CERTI exception in an answer: its name and reason."""

    def __init__(self, name: str, reason: str) -> None:
        super().__init__(f"{name}: {reason}")
        self.name, self.reason = name, reason


class CertiFederate:
    """A federate as CERTI's libRTI (``via="socketpair"``) or JCERTI (``via="tcp"``) is one: it starts `rtia`,
    opens the connection and makes calls, each answered by a message of its type; `tick` delivers the
    callbacks, each acknowledged. Numbers go in the byte order asked for. Every wait is bounded (`timeout`)."""

    def __init__(self, rtia: str, big_endian: bool, env: dict[str, str], via: str = "socketpair",
                 timeout: float = 30.0, stderr: Optional[pathlib.Path] = None) -> None:
        self.big_endian, self.timeout = big_endian, timeout
        self.stderr_path = stderr
        err = open(stderr, "ab") if stderr else subprocess.DEVNULL
        full_env = dict(os.environ, **env)
        if via == "socketpair":
            mine, theirs = socket.socketpair()
            self.proc = subprocess.Popen([rtia, "-f", str(theirs.fileno())], pass_fds=[theirs.fileno()], env=full_env,
                                         stdin=subprocess.DEVNULL, stdout=err, stderr=err)
            theirs.close()
        else:
            listener = socket.socket()
            listener.bind(("127.0.0.1", 0))
            listener.listen(1)
            listener.settimeout(timeout)
            self.proc = subprocess.Popen([rtia, "-p", str(listener.getsockname()[1])], env=full_env,
                                         stdin=subprocess.DEVNULL, stdout=err, stderr=err)
            mine, _ = listener.accept()
            listener.close()
        if stderr:
            err.close()  # type: ignore[union-attr]
        mine.settimeout(timeout)
        self.sock = mine
        self.backlog: list[Message] = []  # callbacks delivered beyond what tick_until was waiting for

    # ---- frames ----
    def send(self, m: Message) -> None:
        self.sock.sendall(encode(m, self.big_endian))

    def send_raw(self, frame: bytes) -> None:
        self.sock.sendall(frame)

    def receive(self) -> Message:
        header = self._exactly(5)
        length = struct.unpack((">" if header[0] == 1 else "<") + "I", header[1:5])[0]
        frame = header + self._exactly(length - 5)
        assert frame[0] == (1 if self.big_endian else 0), "the rtia answers in the federate's byte order"
        return decode(frame)

    def _exactly(self, n: int) -> bytes:
        got = b""
        while len(got) < n:
            chunk = self.sock.recv(n - len(got))
            if not chunk:
                raise ConnectionError("the rtia closed the connection")
            got += chunk
        return got

    # ---- calls ----
    def call(self, type: str, date: Optional[float] = None, label: Optional[str] = None, tag: Optional[str] = None,
             **fields: Any) -> Message:
        """One service: the request, then its answer (CertiError when it carries an exception)."""
        self.send(Message(type, date=date, label=label, tag=tag, fields=fields))
        answer = self.receive()
        assert answer.type == type, f"{type} answered by {answer.type}"
        if answer.exception:
            raise CertiError(answer.exception, answer.reason)
        return answer

    def open(self) -> Message:
        return self.call("OPEN_CONNEXION", version_major=1, version_minor=0)

    def tick(self, minimum: float = 0.0, maximum: float = math.inf, multiple: bool = True,
             on_callback: Optional[Callable[[Message], Optional[str]]] = None) -> tuple[list[Message], bool]:
        """CERTI's tick: TICK_REQUEST, then each callback until TICK_REQUEST comes back; `on_callback` may make
        calls, and return "stop" to end the tick early (TICK_REQUEST_STOP). Returns the callbacks and the
        rtia's "more pending" answer."""
        self.send(Message("TICK_REQUEST", fields={"flag": multiple, "min_tick": minimum, "max_tick": maximum}))
        got = []
        while True:
            m = self.receive()
            if m.type == "TICK_REQUEST":
                if m.exception:
                    raise CertiError(m.exception, m.reason)
                return got, bool(m.flag)
            got.append(m)
            verdict = on_callback(m) if on_callback else None
            self.send(Message("TICK_REQUEST_STOP" if verdict == "stop" else "TICK_REQUEST_NEXT"))

    def tick_until(self, done: Callable[[list[Message]], bool], seconds: float = 30.0) -> list[Message]:
        """Ticks (0.1 s at a time) until `done(the callbacks so far)`, and returns those; callbacks the same tick
        delivered after them are kept for the next call. AssertionError after `seconds`."""
        seen: list[Message] = []
        deadline = time.monotonic() + seconds
        while True:
            while self.backlog:
                seen.append(self.backlog.pop(0))
                if done(seen):
                    return seen
            assert time.monotonic() < deadline, f"not done after {seconds} s; callbacks: {[m.type for m in seen]}"
            self.backlog, _ = self.tick(0.1, 0.5)
            if not self.backlog and done(seen):
                return seen

    def close(self) -> int:
        """CLOSE_CONNEXION, then the rtia's exit status."""
        try:
            self.call("CLOSE_CONNEXION")
        finally:
            self.sock.close()
        return self.wait()

    def wait(self) -> int:
        try:
            return self.proc.wait(timeout=self.timeout)
        except subprocess.TimeoutExpired:
            self.proc.kill()
            self.proc.wait()
            raise

    def stderr(self) -> str:
        return self.stderr_path.read_text() if self.stderr_path and self.stderr_path.exists() else ""

    def __enter__(self) -> CertiFederate:
        return self

    def __exit__(self, *exc: object) -> None:
        self.sock.close()
        if self.proc.poll() is None:
            try:
                self.proc.wait(timeout=self.timeout)
            except subprocess.TimeoutExpired:
                self.proc.kill()
                self.proc.wait()
