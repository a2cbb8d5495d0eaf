"""Old module paths kept for one release after a move (core layer: imports nothing of hlacore).

An alias is a two-line module at the old path::

    from hlacore._deprecated import moved
    moved(__name__, "hlacore.experiments.paper1.scenario")

Imported, it warns (:class:`DeprecationWarning` naming the new path) and becomes the new module itself, so
names, private ones included, and monkeypatching are shared; run with ``python -m old.path``, it warns and
runs the new module as ``__main__``. An alias package (one whose submodules are aliases too) only warns.
"""

from __future__ import annotations

import importlib
import runpy
import sys
import warnings

__all__ = ["moved"]


def moved(name: str, new: str) -> None:
    """Make the calling module (``__name__``) a deprecated alias of module ``new`` (see the module docstring)."""
    module = sys.modules[name]
    spec = getattr(module, "__spec__", None)
    old = (spec.name if spec is not None else name).removesuffix(".__main__")
    # Blamed on the importer (shown when that is a script), or on the alias itself when it runs as __main__.
    warnings.warn(f"{old} has moved to {new.removesuffix('.__main__')}; the old path goes in the next release",
                  DeprecationWarning, stacklevel=2 if name == "__main__" else 3)
    if name == "__main__":
        runpy.run_module(new, run_name="__main__", alter_sys=True)
    elif not hasattr(module, "__path__"):
        sys.modules[name] = importlib.import_module(new)
