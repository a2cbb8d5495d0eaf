"""Run a PyHLA script unchanged: ``import hla.rti`` and ``import hla.omt`` get hlacore's modules.

::

    python -m hlacore.pyhla uav-send.py [its arguments]

runs the script as ``__main__`` (as ``python uav-send.py`` would) after :func:`install`, which makes the
module names ``hla``, ``hla.rti`` and ``hla.omt`` refer to :mod:`hlacore.rti` and :mod:`hlacore.omt`
in this process only. Nothing named ``hla`` is installed on disk, so a real PyHLA in the same
environment is untouched. CERTI's ``CERTI_HOST`` and ``CERTI_TCP_PORT`` name the gateway as they do for
CERTI when neither an address nor ``$HLACORE_RTIG`` is given. docs/pyhla.md lists where hlacore and
PyHLA differ.
"""

from __future__ import annotations

import os
import runpy
import sys
import types
from typing import Optional, Sequence

from . import omt, rti

__all__ = ["install", "main"]


def install() -> types.ModuleType:
    """Make ``import hla.rti`` and ``import hla.omt`` give :mod:`hlacore.rti` and :mod:`hlacore.omt`.

    Returns the ``hla`` package module. Raises :class:`ImportError` when another ``hla`` (a real PyHLA)
    is imported in this process already: two RTIs in one process is a mistake to report, not to hide.
    """
    present = sys.modules.get("hla")
    if present is not None and getattr(present, "__hlacore__", False):
        return present
    if present is not None:
        raise ImportError(f"hlacore.pyhla: another 'hla' package is imported already ({present!r})")
    package = types.ModuleType("hla", "PyHLA's package name, served by hlacore (hlacore.pyhla).")
    package.__path__ = []  # a package: its submodules are the two below, found in sys.modules
    package.__hlacore__ = True  # type: ignore[attr-defined]
    package.rti = rti  # type: ignore[attr-defined]
    package.omt = omt  # type: ignore[attr-defined]
    sys.modules["hla"] = package
    sys.modules["hla.rti"] = rti
    sys.modules["hla.omt"] = omt
    return package


def main(argv: Optional[Sequence[str]] = None) -> int:
    """``python -m hlacore.pyhla SCRIPT [ARGS...]``: run SCRIPT as ``__main__`` with PyHLA's names."""
    args = list(sys.argv[1:] if argv is None else argv)
    if not args or args[0] in ("-h", "--help"):
        print(__doc__.split("\n\n")[0] + "\n\nusage: python -m hlacore.pyhla SCRIPT [ARGS...]",
              file=sys.stderr if not args else sys.stdout)
        return 2 if not args else 0
    script = args[0]
    if not os.path.isfile(script):
        print(f"hlacore.pyhla: no such script: {script}", file=sys.stderr)
        return 2
    install()
    sys.argv = args
    sys.path.insert(0, os.path.dirname(os.path.abspath(script)))  # as `python script.py` does
    runpy.run_path(script, run_name="__main__")
    return 0


if __name__ == "__main__":
    sys.exit(main())
