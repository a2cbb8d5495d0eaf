"""IEEE 1516-2010 (HLA Evolved) for Python, with the shape of OpenRTI's ``rti1516e`` module: a script written
for it runs with its import changed to ``import hlacore.rti1516e as rti1516e``.

::

    import hlacore.rti1516e as rti1516e

    class Federate:                                  # any object; callbacks by name, positional arguments
        def timeAdvanceGrant(self, time): ...
        def reflectAttributeValues(self, obj, values, tag, sentOrder, transportation, time, receivedOrder,
                                   retraction, info): ...

    rtia = rti1516e.RTIambassador()
    rtia.connect(Federate(), "HLA_EVOKED", "127.0.0.1:60400")
    rtia.createFederationExecution("demo", ["base.xml", "robots.xml"], "HLAfloat64Time")
    me = rtia.joinFederationExecution("robot-1", "robot", "demo")
    ...
    rtia.evokeMultipleCallbacks(0.1, 1.0)

Handles are this module's types (they hash, compare within their kind, answer ``isValid()``); values, tags
and other user-supplied data are bytes; logical times and lookaheads are plain floats (ints in an
``"HLAinteger64Time"`` federation); enumerations are module-level integers (``RECEIVE``, ``TIMESTAMP``,
``NO_ACTION``, ...) or their names; exceptions are classes named as in C++, subclasses of
:class:`Exception`. The services run on hlacore's core, the same federation as HLA 1.3 federates
(:mod:`hlacore.rti`, the C++ API, CERTI's through ``hlacore-rtia``). What is not served yet raises
``RTIinternalError`` saying so (docs/rti1516e.md lists it).
"""

from __future__ import annotations

from ._ambassador import RTIambassador
from . import _enums, _exceptions
from ._enums import *  # noqa: F401,F403
from ._exceptions import *  # noqa: F401,F403
from ._handles import (AttributeHandle, DimensionHandle, FederateHandle, InteractionClassHandle,
                       MessageRetractionHandle, ObjectClassHandle, ObjectInstanceHandle, ParameterHandle, RegionHandle)

__all__ = ["RTIambassador", "Exception", "FederateHandle", "ObjectClassHandle", "ObjectInstanceHandle",
           "InteractionClassHandle", "AttributeHandle", "ParameterHandle", "DimensionHandle", "RegionHandle",
           "MessageRetractionHandle"] + _exceptions.__all__ + _enums.__all__
