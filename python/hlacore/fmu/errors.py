"""The errors of :mod:`hlacore.fmu`: each says which file or variable is at fault, and each is raised before the
federate joins, or after a clean resign."""

from __future__ import annotations


class FmuError(Exception):
    """An FMU that cannot run as a federate: missing, corrupt, of an unsupported kind, or without a binary for
    this platform; also the base class of the other errors here."""


class NotCoSimulation(FmuError):
    """The FMU exports model exchange only: :mod:`hlacore.fmu` runs co-simulation FMUs, which step themselves."""


class MappingError(FmuError):
    """The mapping names a variable the FMU does not have, or maps one against its causality or type."""


class StepFailed(FmuError):
    """``doStep`` failed, or left an output that is not a finite number; the federate has resigned."""


class InputError(FmuError):
    """A value received for an input is not of its encoding (a wrong size, an array too short for the element
    mapped); raised by the step that would have used it, after resigning."""
