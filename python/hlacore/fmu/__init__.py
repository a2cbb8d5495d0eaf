"""Any FMU a federate: an FMI 2 or FMI 3 co-simulation FMU joins an HLA federation as a time-regulating and
time-constrained federate, one time advance per step (docs/fmu.md).

``python -m hlacore.fmu MODEL.fmu --federation NAME --step-size H --stop-time T`` from the shell;
:class:`FmuFederate` from Python. Needs FMPy (the ``fmu`` extra: ``pip install hlacore[fmu]``).
"""

from __future__ import annotations

from .errors import FmuError, InputError, MappingError, NotCoSimulation, StepFailed
from .federate import FmuFederate
from .mapping import Endpoint, Mapping
from .model import FmuInstance, FmuModel, Variable

__all__ = ["Endpoint", "FmuError", "FmuFederate", "FmuInstance", "FmuModel", "InputError", "Mapping",
           "MappingError",
           "NotCoSimulation", "StepFailed", "Variable"]
