"""hlacore: an HLA 1.3 run-time infrastructure with a C++ gateway and a PyHLA-style Python API.

- :mod:`hlacore.rti` — the RTI ambassador, federate ambassador, handles and exceptions (PyHLA names).
- :class:`hlacore.Gateway` — the gateway run in-process; ``rtig`` is the same gateway as a server.
- :mod:`hlacore.fed` — the ``.fed`` parser; :mod:`hlacore.omt` — encoding helpers.

Three layers, nothing importing upward (tests/system/test_layers.py): this core (rti, _core, fed, omt, gateway,
aio, status, trace, ...), the reusable federates in :mod:`hlacore.federates`, and the papers' experiments
in :mod:`hlacore.experiments`.
"""

from . import aio, rti
from .gateway import Gateway

__version__ = "0.1.0"
__all__ = ["Gateway", "aio", "rti", "__version__"]
