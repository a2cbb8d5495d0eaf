"""The API reference (docs/api, built by scripts/docs.sh) builds from the docstrings with Sphinx without a
warning (nitpicky: no broken cross-reference, no broken reST), and every public name of hlacore.rti and
hlacore.omt (and of hlacore.Gateway and hlacore.aio, which it documents too) has a docstring and is in it:
a name cannot fall out of the reference unnoticed. One Sphinx build: the file takes about 4 s."""

from __future__ import annotations

import inspect
import posixpath
import re
import subprocess
import sys
from types import ModuleType
from typing import Any, Iterator, NamedTuple

import pytest
from sphinx.errors import PycodeError
from sphinx.pycode import ModuleAnalyzer
from sphinx.util.inventory import InventoryFile

import hlacore
from hlacore import _core, aio, omt, rti

from support import ROOT

SOURCE = ROOT / "docs" / "api"


class Build(NamedTuple):
    returncode: int
    output: str
    documented: set[str]  # every Python object of the inventory, by full name


@pytest.fixture(scope="module")
def build(tmp_path_factory: pytest.TempPathFactory) -> Build:
    """The same build as scripts/docs.sh, into a fresh directory."""
    out = tmp_path_factory.mktemp("api-docs")
    done = subprocess.run(
        [sys.executable, "-m", "sphinx", "-n", "-W", "--keep-going", "-q", "-b", "html", str(SOURCE), str(out)],
        cwd=ROOT, capture_output=True, text=True, timeout=300, stdin=subprocess.DEVNULL)
    documented: set[str] = set()
    inventory = out / "objects.inv"
    if inventory.exists():
        with inventory.open("rb") as f:
            for kind, objects in InventoryFile.load(f, "", posixpath.join).items():
                if kind.startswith("py:"):
                    documented.update(objects)
    return Build(done.returncode, done.stdout + done.stderr, documented)


# ---- what must be documented ----

class Name(NamedTuple):
    qualified: str  # as the reference names it
    candidates: tuple[str, ...]  # the names under which it counts as documented (a member of a base class)
    doc: str  # its docstring, or the doc comment (#:) of a variable; "" if none


def _pybind11_body(doc: str, name: str) -> str:
    """A pybind11 docstring without the signature line it starts with, as autodoc shows it."""
    return re.sub(rf"^{re.escape(name)}\(.*\)(?: -> .+)?\n?", "", doc.strip()).strip()


def _attribute_docs(module: ModuleType) -> dict[tuple[str, str], str]:
    """The doc comments (``#:``) of a module's variables and class attributes, as autodoc reads them."""
    analyzer = ModuleAnalyzer.for_module(module.__name__)
    return {key: "\n".join(lines).strip() for key, lines in analyzer.find_attr_docs().items()}


def _is_variable(value: Any) -> bool:
    """Not a class, function or data descriptor (a property, or a C type's field), which carry their own docs."""
    return not (inspect.isclass(value) or inspect.isroutine(value) or isinstance(value, property)
                or inspect.isgetsetdescriptor(value))


def _doc_of(value: Any, name: str, comments: dict[tuple[str, str], str], owner: str) -> str:
    """A variable's doc comment, or its own __doc__ when that is not its type's (hlacore.omt's basic types
    carry their own: defined in a submodule, a doc comment there would not reach hlacore.omt); else the
    object's own docstring."""
    if _is_variable(value):
        own = getattr(value, "__doc__", None)
        return comments.get((owner, name), "") or (own if isinstance(own, str) and own != type(value).__doc__
                                                   else "")
    return _pybind11_body(inspect.getdoc(value) or "", name)


def _members(cls: type) -> Iterator[str]:
    """The public attributes of a class, without those of the builtin base classes (object, int, Exception)
    and of pybind11's base."""
    builtin = set()
    for base in cls.__mro__:
        if base.__module__ == "builtins":
            builtin.update(dir(base))
    for name in sorted(dir(cls)):
        if not name.startswith("_") and name not in builtin:
            yield name


def _comments_of(owner: type, comments: dict[tuple[str, str], str]) -> dict[tuple[str, str], str]:
    """The doc comments of the module that defines ``owner`` (hlacore.omt's classes are in its submodules),
    else ``comments`` (a compiled module has no source to read them from)."""
    try:
        return _attribute_docs(sys.modules[owner.__module__])
    except (KeyError, PycodeError):
        return comments


def _homes(cls: type, module: ModuleType) -> set[str]:
    """Where the reference may document ``cls``: its own module, and ``module`` if that exports it."""
    return {cls.__module__} | ({module.__name__} if getattr(module, cls.__name__, None) is cls else set())


def _class_names(prefix: str, cls: type, comments: dict[tuple[str, str], str]) -> Iterator[Name]:
    """A documented class's members, documented under it or under the base class that defines them."""
    home = sys.modules[prefix.rpartition(".")[0]]
    for member in _members(cls):
        bases = tuple(f"{module}.{base.__qualname__}.{member}" for base in cls.__mro__[1:]
                      for module in sorted(_homes(base, home)))
        owner = next(base for base in cls.__mro__ if member in vars(base))
        value = inspect.getattr_static(cls, member)
        doc = _doc_of(value if _is_variable(value) else getattr(cls, member), member, _comments_of(owner, comments),
                      owner.__qualname__)
        yield Name(f"{prefix}.{member}", (f"{prefix}.{member}",) + bases, doc)


def public_names() -> list[Name]:
    """Every name the reference must document, with its docstring."""
    names: list[Name] = []
    for module in (rti, omt, aio):
        comments = _attribute_docs(module)
        exported = getattr(module, "__all__", [n for n in vars(module) if not n.startswith("_")])
        for name in exported:
            value = getattr(module, name)
            if inspect.ismodule(value) or (module is aio and getattr(value, "__module__", "") != aio.__name__):
                continue  # aio's imports (RTIAmbassador, asyncio) are documented where they live
            qualified = f"{module.__name__}.{name}"
            names.append(Name(qualified, (qualified,), _doc_of(value, name, comments, "")))
            if inspect.isclass(value):  # its members (those of _core's handles have their docstrings there)
                names.extend(_class_names(qualified, value, comments))
    # RTIAmbassador's services, most of them bound in C++ (RTIAmbassadorBase): the reference shows them all
    # under RTIAmbassador (:inherited-members:).
    names = [n for n in names if not n.qualified.startswith("hlacore.rti.RTIAmbassador.")]
    for member in _members(rti.RTIAmbassador):
        qualified = f"hlacore.rti.RTIAmbassador.{member}"
        doc = _pybind11_body(inspect.getdoc(getattr(rti.RTIAmbassador, member)) or "", member)
        names.append(Name(qualified, (qualified,), doc))
    # The callbacks are documented in FederateAmbassador's docstring (a subclass defines those it wants).
    for callback in _core.CALLBACKS:
        directive = re.search(rf"^ *\.\. method:: {callback}\(.*?(?=^ *\.\. |\Z)", rti.FederateAmbassador.__doc__ or "",
                              re.MULTILINE | re.DOTALL)
        qualified = f"hlacore.rti.FederateAmbassador.{callback}"
        names.append(Name(qualified, (qualified,), directive.group(0).split("\n", 1)[-1].strip() if directive else ""))
    comments = _attribute_docs(sys.modules[hlacore.Gateway.__module__])
    names.append(Name("hlacore.Gateway", ("hlacore.Gateway",), inspect.getdoc(hlacore.Gateway) or ""))
    names.extend(_class_names("hlacore.Gateway", hlacore.Gateway, comments))
    return names


NAMES = public_names()


def test_the_reference_builds_without_a_warning(build: Build) -> None:
    failed = build.returncode != 0
    assert not failed, "sphinx-build -n -W (scripts/docs.sh) warns:\n" + build.output


def test_every_public_name_has_a_docstring() -> None:
    undocumented = [name.qualified for name in NAMES if not name.doc]
    assert not undocumented, "no docstring (for a variable: no #: comment above it):\n  " + "\n  ".join(undocumented)


def test_every_public_name_is_in_the_reference(build: Build) -> None:
    assert build.documented, "no inventory: the build failed\n" + build.output
    missing = [name.qualified for name in NAMES if not set(name.candidates) & build.documented]
    assert not missing, ("not in the reference (give it a docstring; place it in docs/api/*.rst):\n  "
                         + "\n  ".join(missing))


def test_the_check_sees_the_services_and_the_callbacks() -> None:
    qualified = {name.qualified for name in NAMES}
    for service in ("updateAttributeValues", "tick", "createFederationExecution", "datagram_status"):
        assert f"hlacore.rti.RTIAmbassador.{service}" in qualified
    assert {f"hlacore.rti.FederateAmbassador.{c}" for c in _core.CALLBACKS} <= qualified
    assert {"hlacore.rti.ObjectHandle", "hlacore.rti.RTIinternalError", "hlacore.omt.HLAinteger32BE",
            "hlacore.omt.HLAfixedRecord.pack", "hlacore.Gateway.stop", "hlacore.rti.ResignAction.NoAction",
            "hlacore.rti.EventRetractionHandle.serial", "hlacore.aio.AsyncAmbassador.advance_to"} <= qualified
