"""The HLA 4 (IEEE 1516-2025) Federate Protocol in pure Python: a federate's side of the protocol.

A federate talks to an RTI over TCP with protobuf-encoded calls and callbacks (the messages of the standard's
``datatypes.proto``, ``RTIambassador.proto`` and ``FederateAmbassador.proto``, generated into
``hlacore.fedpro._proto``). Nothing here uses hlacore's native module; the ``protobuf`` package is needed.

- :class:`RTIambassador` — the HLA services by name (``rtia.joinFederationExecution(federateName=...,
  federateType=..., federationName=...)``), their results and :class:`RTIexception`\\ s; callbacks evoked
  (:meth:`RTIambassador.evokeCallback`, :meth:`RTIambassador.evokeMultipleCallbacks`) to a
  :class:`FederateAmbassador`'s methods named after them.
- :mod:`hlacore.fedpro.messages` — protobuf messages from plain values: :func:`~hlacore.fedpro.messages.float64_time`,
  :func:`~hlacore.fedpro.messages.time_value`, :func:`~hlacore.fedpro.messages.fom_module`, :func:`~hlacore.fedpro.messages.handle_values`, ...
- :class:`~hlacore.fedpro.session.Session` (:mod:`hlacore.fedpro.session`) — the session layer: the 24-byte header, the handshake,
  calls matched to responses, the callback queue, heartbeats, termination and the resume after a dropped
  connection.
"""

from .ambassador import (CALLBACKS, DEFAULT_ADDRESS, SERVICES, FederateAmbassador, NullFederateAmbassador,
                         RTIambassador, RTIexception, rti_exception)
from .messages import (float64_interval, float64_time, fom_module, handle_values, integer64_interval,
                       integer64_time, integer_time_value, time_value)
from .session import (BadMessage, CallTimeout, Header, MessageType, Session, SessionError, SessionLost,
                      SessionRefused, decode_header, encode_header, encode_message)

__all__ = [
    "BadMessage", "CALLBACKS", "CallTimeout", "DEFAULT_ADDRESS", "FederateAmbassador", "Header", "MessageType",
    "NullFederateAmbassador",
    "RTIambassador", "RTIexception", "SERVICES", "Session", "SessionError", "SessionLost", "SessionRefused",
    "decode_header", "encode_header", "encode_message", "float64_interval", "float64_time", "fom_module",
    "handle_values", "integer64_interval", "integer64_time", "integer_time_value", "rti_exception",
    "time_value",
]
