"""The HLA 4 (IEEE 1516-2025) Federate Protocol in pure Python: a federate's side of the protocol.

A federate talks to an RTI over TCP, TLS or a WebSocket with protobuf-encoded calls and callbacks (the
messages of the standard's ``datatypes.proto``, ``RTIambassador.proto`` and ``FederateAmbassador.proto``,
generated into ``hlacore.fedpro._proto``). Nothing here uses hlacore's native module; the ``protobuf`` package
is needed.

- :class:`RTIambassador` — the HLA services by name (``rtia.joinFederationExecution(federateName=...,
  federateType=..., federationName=...)``), their results and :class:`RTIexception`\\ s; callbacks evoked
  (:meth:`RTIambassador.evokeCallback`, :meth:`RTIambassador.evokeMultipleCallbacks`) to a
  :class:`FederateAmbassador`'s methods named after them.
- :mod:`hlacore.fedpro.messages` — protobuf messages from plain values: :func:`~hlacore.fedpro.messages.float64_time`,
  :func:`~hlacore.fedpro.messages.time_value`, :func:`~hlacore.fedpro.messages.fom_module`, :func:`~hlacore.fedpro.messages.handle_values`,
  ``plain_text_password`` (credentials for connect), ...
- :class:`~hlacore.fedpro.session.Session` (:mod:`hlacore.fedpro.session`) — the session layer: the 24-byte header, the handshake,
  calls matched to responses, the callback queue, heartbeats, termination and the resume after a dropped
  connection; over the transports ``"tcp"``, ``"tls"``, ``"websocket"`` and ``"websocketsecure"``
  (``hlacore.fedpro.websocket`` is the WebSocket client).
"""

from .ambassador import (CALLBACKS, DEFAULT_ADDRESS, SERVICES, FederateAmbassador, NullFederateAmbassador,
                         RTIambassador, RTIexception, rti_exception)
from .messages import (float64_interval, float64_time, fom_module, handle_values, integer64_interval,
                       integer64_time, integer_time_value, plain_text_password, time_value, unicode_string)
from .session import (DEFAULT_PORTS, BadMessage, CallTimeout, Header, MessageType, Session, SessionError,
                      SessionLost, SessionRefused, decode_header, encode_header, encode_message)
from .websocket import WebSocketError

__all__ = [
    "BadMessage", "CALLBACKS", "CallTimeout", "DEFAULT_ADDRESS", "DEFAULT_PORTS", "FederateAmbassador", "Header",
    "MessageType", "NullFederateAmbassador",
    "RTIambassador", "RTIexception", "SERVICES", "Session", "SessionError", "SessionLost", "SessionRefused",
    "WebSocketError", "decode_header", "encode_header", "encode_message", "float64_interval", "float64_time",
    "fom_module", "handle_values", "integer64_interval", "integer64_time", "integer_time_value",
    "plain_text_password", "rti_exception", "time_value", "unicode_string",
]
