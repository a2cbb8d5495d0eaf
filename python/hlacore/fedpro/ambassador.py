"""The HLA 4 RTI ambassador over the Federate Protocol, in pure Python, and the federate ambassador it calls.

:class:`RTIambassador` sends each HLA service as a ``CallRequest`` on a :class:`~hlacore.fedpro.session.Session`
and returns what its ``CallResponse`` holds. A service is named as in the ``CallRequest``, less ``Request``,
and its fields are keyword arguments (values as :mod:`hlacore.fedpro.messages` builds them)::

    rtia = RTIambassador("127.0.0.1:15164")
    rtia.connect(MyAmbassador())
    rtia.createFederationExecution(federationName="Fed", fomModules=["foms/robot.xml"])
    joined = rtia.joinFederationExecution(federateName="robot", federateType="robot", federationName="Fed")
    cls = rtia.getObjectClassHandle(objectClassName="HLAobjectRoot.Robot")

The standard's overloads are separate messages (``joinFederationExecutionWithName``,
``createFederationExecutionWithModules``, ...): the plain name picks, among itself and its ``...With...``
variants, the one with the fewest fields that takes every keyword given, so the calls above send
``createFederationExecutionWithModulesRequest`` and ``joinFederationExecutionWithNameRequest``. A variant's
own name picks it alone.

Callbacks are evoked, as HLA's EVOKED callback model: :meth:`RTIambassador.evokeCallback` and
:meth:`RTIambassador.evokeMultipleCallbacks` deliver them on the caller's thread to the
:class:`FederateAmbassador`'s method named after the ``CallbackRequest`` member, with its message
(``reflectAttributeValues(self, msg)``), and answer the RTI for each.
"""

from __future__ import annotations

import difflib
import ssl
import threading
import time
from typing import Any, Callable, Dict, List, Optional, Set, Tuple, Type, Union

from . import messages
from ._proto import FederateAmbassador_pb2, RTIambassador_pb2, datatypes_pb2
from .session import Session, SessionError, SessionLost, default_port, split_address

_RTI: Any = RTIambassador_pb2
_FED: Any = FederateAmbassador_pb2
_DATATYPES: Any = datatypes_pb2

#: The address :class:`RTIambassador` dials over plain TCP when given none: the Federate Protocol's TCP port on
#: this host. (Another transport dials this host on its own default port.)
DEFAULT_ADDRESS = "127.0.0.1:15164"


def _services() -> Dict[str, Any]:
    found = {}
    for field in _RTI.CallRequest.DESCRIPTOR.oneofs_by_name["callRequest"].fields:
        if field.name.endswith("Request"):
            found[field.name[: -len("Request")]] = field.message_type
    return found


#: Each HLA service a ``CallRequest`` can carry, by name (``joinFederationExecutionWithName``), to the
#: descriptor of its request message.
SERVICES: Dict[str, Any] = _services()

#: The names of the callbacks a ``CallbackRequest`` can carry (``reflectAttributeValues``, ...): the methods a
#: :class:`FederateAmbassador` may define.
CALLBACKS: Tuple[str, ...] = tuple(
    field.name for field in _FED.CallbackRequest.DESCRIPTOR.oneofs_by_name["callbackRequest"].fields)


class RTIexception(Exception):
    """An HLA exception the RTI raised for a call (its ``ExceptionData``), or one this client raises in the
    RTI's name (``NotConnected`` when the session is lost). Each exception name has its own subclass, made on
    first use and the same class after (:func:`rti_exception`), so a federate catches one by name::

        try:
            rtia.createFederationExecution(federationName="Fed", fomModules=[...])
        except rti_exception("FederationExecutionAlreadyExists"):
            pass

    ``name`` is the exception's name as the RTI gave it, ``details`` its text.
    """

    #: The HLA exception's name (``"FederateNotExecutionMember"``); this base class's own for an unnamed one.
    name = "RTIexception"

    def __init__(self, details: str = "") -> None:
        """An exception whose text is `details`."""
        super().__init__(details)
        self.details = details

    def __str__(self) -> str:
        """The details, or the name when there are none."""
        return self.details or self.name

    @classmethod
    def from_data(cls, data: Any) -> "RTIexception":
        """The exception an ``ExceptionData`` message describes, of the class named after it."""
        return rti_exception(data.exceptionName or "RTIexception")(data.details)


_EXCEPTIONS: Dict[str, Type[RTIexception]] = {"RTIexception": RTIexception}
_EXCEPTIONS_LOCK = threading.Lock()


def rti_exception(name: str) -> Type[RTIexception]:
    """The :class:`RTIexception` subclass for the HLA exception `name` (``"FederateNotExecutionMember"``),
    made on first use: the same class every time for the same name. A dotted name's class is named after its
    last part."""
    with _EXCEPTIONS_LOCK:
        found = _EXCEPTIONS.get(name)
        if found is None:
            short = name.rpartition(".")[2]
            class_name = short if short.isidentifier() else "RTIexception"
            found = type(class_name, (RTIexception,), {
                "__doc__": f"The HLA exception {name}.", "__module__": __name__, "name": name})
            _EXCEPTIONS[name] = found
        return found


class FederateAmbassador:
    """The federate's side of the callbacks: subclass it and define a method for each callback the federate
    takes, named as the ``CallbackRequest`` member (``CALLBACKS``) and taking its protobuf message::

        class Ambassador(FederateAmbassador):
            def reflectAttributeValues(self, msg):
                values = handle_values(msg)          # {attribute handle bytes: value}
            def timeAdvanceGrant(self, msg):
                self.granted = time_value(msg)       # HLAfloat64Time

    A method that returns answers the RTI ``callbackSucceeded``; one that raises answers ``callbackFailed``
    with the exception's name and text, and the exception goes on to the caller of the evoke. A callback
    with no method answers ``callbackFailed`` too, and the evoke raises ``NotImplementedError`` naming it.
    The client delivers ``connectionLost`` itself (to the method, when there is one) when the session is
    lost.
    """


class NullFederateAmbassador(FederateAmbassador):
    """A :class:`FederateAmbassador` that takes every callback it defines no method for and does nothing with
    it (answered ``callbackSucceeded``), as 1516-2010's ``NullFederateAmbassador``: subclass it to handle only
    the callbacks the federate cares about."""

    def __getattr__(self, name: str) -> Callable[[Any], None]:
        if name not in CALLBACKS:
            raise AttributeError(name)
        return lambda msg: None


def _failure(name: str, details: str) -> bytes:
    response = _FED.CallbackResponse()
    response.callbackFailed.exceptionName = name
    response.callbackFailed.details = details
    return bytes(response.SerializeToString())


def _success() -> bytes:
    response = _FED.CallbackResponse()
    response.callbackSucceeded.SetInParent()
    return bytes(response.SerializeToString())


class RTIambassador:
    """An HLA 4 RTI ambassador over the Federate Protocol: one session with the RTI at `address`
    (``"host:port"``, ``"host"`` for the transport's default port, None for this host; or a
    :class:`~hlacore.fedpro.session.Session` already open).

    `protocol` is the transport, as the standard's ``connect.protocol``: ``"tcp"`` (port 15164 by default),
    ``"tls"`` (15165), ``"websocket"`` (80) or ``"websocketsecure"`` (443). Over TLS the RTI's certificate is
    checked with `ssl_context` (by default ``ssl.create_default_context()``) for `server_hostname` (by
    default the host dialed); a WebSocket requests `path`. A resume after a dropped connection dials the same
    way::

        context = ssl.create_default_context(cafile="rti-ca.pem")
        rtia = RTIambassador("rti.example", protocol="websocketsecure", ssl_context=context, path="/fedpro")

    Every HLA service is a method named as in the ``CallRequest`` less ``Request``
    (``rtia.joinFederationExecution(federateName=..., federateType=..., federationName=...)``), or
    ``rtia.call(name, **fields)``; see :meth:`call` and the module's docstring. A call waits for its response
    up to `timeout` seconds (None: no limit; :class:`~hlacore.fedpro.session.CallTimeout` after it) and may
    be made from any thread. When the session is lost, calls raise ``NotConnected``
    (:func:`rti_exception`).

    `connect_timeout` bounds the opening of the session and each dial of a resume, `resume_timeout` the time
    a dropped connection may take to resume. Use it as a context manager, or call :meth:`close`, to end the
    session.
    """

    def __init__(self, address: Union[str, Session, None] = None, *, protocol: str = "tcp",
                 ssl_context: Optional[ssl.SSLContext] = None, server_hostname: Optional[str] = None,
                 path: str = "/", timeout: Optional[float] = 60.0, connect_timeout: float = 10.0,
                 resume_timeout: float = 30.0) -> None:
        """Opens the session (the HLA connect service is :meth:`connect`). ``OSError`` when the RTI cannot be
        reached (``ssl.SSLCertVerificationError`` for a certificate not trusted, a ``ConnectionError`` for a
        refused WebSocket upgrade), :class:`~hlacore.fedpro.session.SessionRefused` when it opens no session,
        ``ValueError`` for an unknown `protocol`. The transport's arguments are unused with a session given."""
        if isinstance(address, Session):
            self.session = address
        else:
            host, port = split_address(address or "127.0.0.1", default_port(protocol))
            self.session = Session.connect(host, port, protocol=protocol, ssl_context=ssl_context,
                                           server_hostname=server_hostname, path=path, timeout=connect_timeout,
                                           resume_timeout=resume_timeout)
        self.timeout = timeout
        self.federate_ambassador: Optional[FederateAmbassador] = None
        self._in_callback = False
        self._told_lost = False

    # ---- calls ----

    def call(self, name: str, /, **fields: Any) -> Any:
        """Calls the HLA service `name` with `fields` and returns its result.

        The request is the ``CallRequest`` member ``name + "Request"``, or that of the ``name...With...``
        variant with the fewest fields that takes every keyword given. Its fields are set from `fields`
        (messages, bytes, str, numbers, lists for repeated fields, ...: :mod:`hlacore.fedpro.messages`).
        The result is the response message's one field when it has one (a handle, a ``JoinResult``, a
        ``ConfigurationResult``, ...), None when it has none, the message itself otherwise.

        Raises the call's HLA exception as an :class:`RTIexception` subclass named after it; ``NotConnected``
        when the session is lost; :class:`~hlacore.fedpro.session.CallTimeout` when no response came in
        time; ``ValueError`` for an unknown service and ``TypeError`` for a keyword no variant takes.
        """
        service = resolve(name, fields)
        request = _RTI.CallRequest()
        member = getattr(request, service + "Request")
        member.SetInParent()
        messages.fill(member, fields)
        try:
            data = self.session.call(request.SerializeToString(), self.timeout)
        except SessionLost as e:
            raise rti_exception("NotConnected")(str(e)) from e
        response = _RTI.CallResponse()
        try:
            response.ParseFromString(data)
        except Exception as e:  # protobuf's DecodeError
            raise rti_exception("RTIinternalError")(f"the RTI's response to {service} does not parse: {e}") from e
        which = response.WhichOneof("callResponse")
        if which == "exceptionData":
            raise RTIexception.from_data(response.exceptionData)
        if which != service + "Response":
            raise rti_exception("RTIinternalError")(f"the RTI answered {service} with {which or 'nothing'}")
        result = getattr(response, which)
        result_fields = result.DESCRIPTOR.fields
        if not result_fields:
            return None
        if len(result_fields) == 1:
            return getattr(result, result_fields[0].name)
        return result

    def __getattr__(self, name: str) -> Callable[..., Any]:
        """``rtia.service(**fields)`` as ``rtia.call("service", **fields)``; ``AttributeError`` naming the
        closest services for a name that is none."""
        if name.startswith("_"):
            raise AttributeError(name)
        if not variants(name):
            close = difflib.get_close_matches(name, SERVICES, n=5, cutoff=0.6)
            hint = f"; did you mean {', '.join(close)}?" if close else ""
            raise AttributeError(f"{type(self).__name__} has no HLA service {name!r}{hint}")

        def service(**fields: Any) -> Any:
            return self.call(name, **fields)

        service.__name__ = service.__qualname__ = name
        service.__doc__ = describe(name)
        return service

    def __dir__(self) -> List[str]:
        """The attributes and the HLA services (for completion)."""
        return sorted(set(super().__dir__()) | set(SERVICES))

    def connect(self, federateAmbassador: FederateAmbassador, callbackModel: Union[str, int] = "EVOKED",
                **fields: Any) -> Any:
        """HLA connect: sets the federate ambassador that evoked callbacks go to and sends ``connect`` (or
        ``connectWithConfiguration`` / ``...WithCredentials`` for ``rtiConfiguration=`` / ``credentials=``
        fields). Returns the ``ConfigurationResult``. Only the EVOKED callback model is served here:
        ``UnsupportedCallbackModel`` for another.

        ``credentials=`` takes a ``Credentials`` message, such as ``plain_text_password("secret")`` makes
        (:mod:`hlacore.fedpro.messages`: the standard's ``HLAplainTextPassword``); an RTI that does not accept
        them raises ``Unauthorized``."""
        if callbackModel not in ("EVOKED", _DATATYPES.EVOKED):
            raise rti_exception("UnsupportedCallbackModel")(
                f"callback model {callbackModel!r}: this client delivers callbacks when evoked")
        self.federate_ambassador = federateAmbassador
        return self.call("connect", **fields)

    # ---- callbacks ----

    def evokeCallback(self, approximateMinimumTimeInSeconds: float = 0.0) -> bool:
        """HLA evokeCallback: waits up to `approximateMinimumTimeInSeconds` for a callback and delivers at
        most one to the federate ambassador; returns whether more callbacks are waiting. Raises what the
        callback's method raised (the RTI was answered ``callbackFailed``), ``NotImplementedError`` for a
        callback the ambassador has no method for, ``CallNotAllowedFromWithinCallback`` from inside a callback
        and ``NotConnected`` once the session is lost (after delivering ``connectionLost`` once)."""
        self._check_evoke()
        item = self._next(approximateMinimumTimeInSeconds)
        if item is not None:
            self._deliver(*item)
        return self.session.pending_callbacks > 0

    def evokeMultipleCallbacks(self, approximateMinimumTimeInSeconds: float = 0.0,
                               approximateMaximumTimeInSeconds: float = 1.0) -> bool:
        """HLA evokeMultipleCallbacks: delivers callbacks for at least `approximateMinimumTimeInSeconds`
        (waiting for them) and stops when none is waiting after that, or when
        `approximateMaximumTimeInSeconds` has passed; returns whether more callbacks are waiting. Raises as
        :meth:`evokeCallback` (the callbacks after one that raised stay queued)."""
        self._check_evoke()
        start = time.monotonic()
        while True:
            elapsed = time.monotonic() - start
            if elapsed >= approximateMaximumTimeInSeconds:
                break
            wait = max(0.0, min(approximateMinimumTimeInSeconds, approximateMaximumTimeInSeconds) - elapsed)
            told = self._told_lost
            item = self._next(wait)
            if item is None:
                if self._told_lost != told or time.monotonic() - start >= approximateMinimumTimeInSeconds:
                    break  # none came, or connectionLost was just delivered
                continue
            self._deliver(*item)
        return self.session.pending_callbacks > 0

    def _check_evoke(self) -> None:
        if self._in_callback:
            raise rti_exception("CallNotAllowedFromWithinCallback")("an evoke from inside a callback")
        if self.federate_ambassador is None:
            raise rti_exception("NotConnected")("connect(federateAmbassador) first: callbacks go to it")

    def _next(self, timeout: float) -> Optional[Tuple[int, bytes]]:
        try:
            return self.session.next_callback(timeout)
        except SessionLost as e:
            if self._told_lost:
                raise rti_exception("NotConnected")(str(e)) from e
            self._told_lost = True
            method = getattr(self.federate_ambassador, "connectionLost", None)
            if method is not None:
                method(_FED.ConnectionLost(faultDescription=str(e)))
            return None

    def _deliver(self, sequence: int, payload: bytes) -> None:
        request = _FED.CallbackRequest()
        try:
            request.ParseFromString(payload)
        except Exception as e:  # protobuf's DecodeError
            self._answer(sequence, _failure("FederateInternalError", f"the callback does not parse: {e}"))
            raise rti_exception("RTIinternalError")(f"the RTI sent a callback that does not parse: {e}") from e
        name = request.WhichOneof("callbackRequest")
        method = getattr(self.federate_ambassador, name, None) if name else None
        if method is None:
            owner = type(self.federate_ambassador).__name__
            what = f"no method {name}(self, msg)" if name else "nothing to call for an empty CallbackRequest"
            self._answer(sequence, _failure("FederateInternalError", f"{owner} has {what}"))
            raise NotImplementedError(f"{owner} has {what} for the RTI's callback; the RTI was answered "
                                      f"callbackFailed")
        self._in_callback = True
        try:
            method(getattr(request, name))
        except BaseException as e:
            failed = e.name if isinstance(e, RTIexception) else type(e).__name__
            self._answer(sequence, _failure(failed, str(e)), quiet=True)
            raise
        finally:
            self._in_callback = False
        self._answer(sequence, _success())

    def _answer(self, sequence: int, response: bytes, quiet: bool = False) -> None:
        try:
            self.session.answer_callback(sequence, response)
        except SessionError as e:
            if not quiet:
                raise rti_exception("NotConnected")(str(e)) from e

    # ---- the session ----

    def close(self, timeout: float = 10.0) -> None:
        """Ends the session with the RTI (TerminateSession) and closes the connection; the RTI resigns and
        disconnects the federate if it had not. Nothing to do when the session is already over. Evokes after
        it raise ``NotConnected`` (no ``connectionLost``: the federate ended the session itself)."""
        self._told_lost = True
        try:
            self.session.terminate(timeout)
        except SessionError:
            pass
        finally:
            self.session.close()

    def __enter__(self) -> "RTIambassador":
        """The ambassador itself."""
        return self

    def __exit__(self, *exc: object) -> None:
        """Closes the session (:meth:`close`)."""
        self.close()


def variants(name: str) -> List[str]:
    """The services `name` may send: itself when it is one, and its ``name + "With..."`` variants."""
    return [service for service in SERVICES if service == name or service.startswith(name + "With")]


def resolve(name: str, fields: Any) -> str:
    """The service a call of `name` with the keywords `fields` sends: among :func:`variants`, the one with
    the fewest fields that takes them all (`name` itself first on a tie). ``ValueError`` for an unknown
    name, ``TypeError`` when no variant takes every keyword or two equally small ones do."""
    candidates = variants(name)
    if not candidates:
        close = difflib.get_close_matches(name, SERVICES, n=5, cutoff=0.6)
        hint = f"; did you mean {', '.join(close)}?" if close else ""
        raise ValueError(f"no HLA service {name!r}{hint}")
    given: Set[str] = set(fields)
    fitting = [s for s in candidates if given <= set(SERVICES[s].fields_by_name)]
    if not fitting:
        raise TypeError(f"{name}() takes no keywords {sorted(given)} together; {describe(name)}")
    fitting.sort(key=lambda s: (len(SERVICES[s].fields), s != name))
    best = fitting[0]
    tied = [s for s in fitting if len(SERVICES[s].fields) == len(SERVICES[best].fields)]
    if len(tied) > 1 and best != name:
        raise TypeError(f"{name}() with {sorted(given)} may be {' or '.join(tied)}: call one by its name")
    return best


def describe(name: str) -> str:
    """The variants of the service `name` with their fields, one per line."""
    lines = [f"{s}({', '.join(f.name for f in SERVICES[s].fields)})" for s in variants(name)]
    return "the HLA service " + name + ": " + "; ".join(lines)

