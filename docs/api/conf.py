"""Sphinx configuration of hlacore's API reference: docs/api/*.rst arrange what the docstrings say.

Built by ``scripts/docs.sh`` into build/docs; ``tests/system/test_api_docs.py`` builds it the same way (nitpicky,
warnings are errors) and checks that every public name is documented and in the reference.
"""

from __future__ import annotations

import re
from typing import Any, Optional

project = "hlacore"
author = "hlacore"
extensions = ["sphinx.ext.autodoc"]
html_theme = "alabaster"  # Sphinx's own: no extra dependency

# Every cross-reference must resolve (sphinx-build -n does the same): a broken one is a warning, and the
# build treats warnings as errors.
nitpicky = True
nitpick_ignore = [
    # The standard library's classes in annotations. Nothing documents them here: intersphinx would need
    # docs.python.org's inventory, and the build must work offline (CI has no network).
    ("py:class", "ssl.SSLContext"),
    ("py:class", "ssl.SSLSocket"),
    ("py:class", "collections.abc.Iterable"),
    ("py:class", "collections.abc.Mapping"),
    ("py:class", "collections.abc.Sequence"),
    ("py:class", "os.PathLike"),
    ("py:class", "socket.socket"),
]

# pybind11 puts a method's signature in the first line of its docstring; autodoc reads it from there.
autodoc_docstring_signature = True
autodoc_member_order = "groupwise"
autodoc_default_options = {"members": True}
# The handles and exceptions live in hlacore._core and are documented where the API exports them,
# hlacore.rti; autodoc records the _core name as their canonical name, so the annotations of pybind11's
# signatures (hlacore._core.ObjectHandle) link to hlacore.rti.ObjectHandle. Show such a linked name's last
# part only (ObjectHandle).
python_use_unqualified_type_names = True

_PYBIND11_SELF = re.compile(r"^\(self(?:: [\w.]+)?(?:, |(?=\)))")


def _drop_pybind11_self(app: Any, what: str, name: str, obj: Any, options: Any, signature: Optional[str],
                        return_annotation: Optional[str]) -> Optional[tuple[Optional[str], Optional[str]]]:
    """Drop ``self`` from the signatures pybind11 writes for methods, as autodoc does for Python methods.

    ``(self: hlacore._core.RTIAmbassadorBase, name: str)`` becomes ``(name: str)``: the binding's base
    class is an implementation detail of :class:`hlacore.rti.RTIAmbassador`.
    """
    if what in ("method", "property") and signature and _PYBIND11_SELF.match(signature):
        return "(" + _PYBIND11_SELF.sub("", signature), return_annotation
    return None


def setup(app: Any) -> dict[str, Any]:
    app.connect("autodoc-process-signature", _drop_pybind11_self)
    return {"parallel_read_safe": True}
