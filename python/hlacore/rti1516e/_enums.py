"""IEEE 1516-2010's enumerations as module-level integer constants (the values of OpenRTI's Python module),
and the reading of an argument given as such an integer or as its name."""

from __future__ import annotations

from typing import Dict


# OrderType
RECEIVE = 1
TIMESTAMP = 2
# TransportationType
RELIABLE = 1
BEST_EFFORT = 2
# ResignAction
UNCONDITIONALLY_DIVEST_ATTRIBUTES = 0
DELETE_OBJECTS = 1
CANCEL_PENDING_OWNERSHIP_ACQUISITIONS = 2
DELETE_OBJECTS_THEN_DIVEST = 3
CANCEL_THEN_DELETE_THEN_DIVEST = 4
NO_ACTION = 5
# SynchronizationPointFailureReason
SYNCHRONIZATION_POINT_LABEL_NOT_UNIQUE = 0
SYNCHRONIZATION_SET_MEMBER_NOT_JOINED = 1
# SaveFailureReason
RTI_UNABLE_TO_SAVE = 0
FEDERATE_REPORTED_FAILURE_DURING_SAVE = 1
FEDERATE_RESIGNED_DURING_SAVE = 2
RTI_DETECTED_FAILURE_DURING_SAVE = 3
SAVE_TIME_CANNOT_BE_HONORED = 4
SAVE_ABORTED = 5
# RestoreFailureReason
RTI_UNABLE_TO_RESTORE = 0
FEDERATE_REPORTED_FAILURE_DURING_RESTORE = 1
FEDERATE_RESIGNED_DURING_RESTORE = 2
RTI_DETECTED_FAILURE_DURING_RESTORE = 3
RESTORE_ABORTED = 4
# SaveStatus
NO_SAVE_IN_PROGRESS = 0
FEDERATE_INSTRUCTED_TO_SAVE = 1
FEDERATE_SAVING = 2
FEDERATE_WAITING_FOR_FEDERATION_TO_SAVE = 3
# RestoreStatus
NO_RESTORE_IN_PROGRESS = 0
FEDERATE_RESTORE_REQUEST_PENDING = 1
FEDERATE_WAITING_FOR_RESTORE_TO_BEGIN = 2
FEDERATE_PREPARED_TO_RESTORE = 3
FEDERATE_RESTORING = 4
FEDERATE_WAITING_FOR_FEDERATION_TO_RESTORE = 5
# ServiceGroup
FEDERATION_MANAGEMENT = 0
DECLARATION_MANAGEMENT = 1
OBJECT_MANAGEMENT = 2
OWNERSHIP_MANAGEMENT = 3
TIME_MANAGEMENT = 4
DATA_DISTRIBUTION_MANAGEMENT = 5
SUPPORT_SERVICES = 6

__all__ = [name for name, value in list(globals().items()) if name.isupper() and isinstance(value, int)]

ORDER_TYPES: Dict[str, int] = {"RECEIVE": RECEIVE, "TIMESTAMP": TIMESTAMP}
TRANSPORTATION_TYPES: Dict[str, int] = {"RELIABLE": RELIABLE, "BEST_EFFORT": BEST_EFFORT}
RESIGN_ACTIONS: Dict[str, int] = {
    "UNCONDITIONALLY_DIVEST_ATTRIBUTES": UNCONDITIONALLY_DIVEST_ATTRIBUTES, "DELETE_OBJECTS": DELETE_OBJECTS,
    "CANCEL_PENDING_OWNERSHIP_ACQUISITIONS": CANCEL_PENDING_OWNERSHIP_ACQUISITIONS,
    "DELETE_OBJECTS_THEN_DIVEST": DELETE_OBJECTS_THEN_DIVEST,
    "CANCEL_THEN_DELETE_THEN_DIVEST": CANCEL_THEN_DELETE_THEN_DIVEST, "NO_ACTION": NO_ACTION,
}
SERVICE_GROUPS: Dict[str, int] = {
    "FEDERATION_MANAGEMENT": FEDERATION_MANAGEMENT, "DECLARATION_MANAGEMENT": DECLARATION_MANAGEMENT,
    "OBJECT_MANAGEMENT": OBJECT_MANAGEMENT, "OWNERSHIP_MANAGEMENT": OWNERSHIP_MANAGEMENT,
    "TIME_MANAGEMENT": TIME_MANAGEMENT, "DATA_DISTRIBUTION_MANAGEMENT": DATA_DISTRIBUTION_MANAGEMENT,
    "SUPPORT_SERVICES": SUPPORT_SERVICES,
}


def enum_value(value: object, names: Dict[str, int], invalid: type, kind: str) -> int:
    """`value` as one of `names`' integers: the integer itself or its name (str or bytes); `invalid` (an
    exception class) for anything else."""
    if isinstance(value, bytes):
        value = value.decode("latin-1")
    if isinstance(value, str):
        if value in names:
            return names[value]
        raise invalid(f"{value!r} is not a {kind} ({', '.join(names)})")
    if isinstance(value, int) and value in names.values():
        return int(value)
    raise invalid(f"{value!r} is not a {kind} ({', '.join(f'{n}={v}' for n, v in names.items())})")
