"""Every public name of python/hlacore has a docstring: each module, and each class, function, method and
property whose name does not start with ``_``, read from the sources with :mod:`ast` (nothing is imported).

Methods are checked in every class, private ones too: a private class's public method is reachable from a
public object (``hlacore.omt.HLAinteger32BE.pack`` is ``_IntegerType.pack``). Not checked: functions
defined inside functions, ``@overload`` declarations (the implementation carries the docstring), property
setters (the getter does), the compiled ``hlacore._core`` (its docstrings are C++'s kDocs tables, and a
public method without one fails the import) and its stub. The deprecated aliases at old module paths
(``hlacore._deprecated.moved``) are modules like the others: their docstring says where the module went.

``python tests/system/test_docstrings.py`` prints the undocumented names, one ``path:line: name`` a line.
"""

from __future__ import annotations

import ast
import pathlib
import sys
from typing import Iterator, Union

ROOT = pathlib.Path(__file__).resolve().parents[2]
PACKAGE = ROOT / "python" / "hlacore"

Definition = Union[ast.FunctionDef, ast.AsyncFunctionDef, ast.ClassDef]


def _decorator_names(node: Definition) -> set[str]:
    """The last part of each decorator's name (``overload``, ``setter``, ``property`` ...)."""
    names = set()
    for decorator in node.decorator_list:
        target = decorator.func if isinstance(decorator, ast.Call) else decorator
        if isinstance(target, ast.Attribute):
            names.add(target.attr)
        elif isinstance(target, ast.Name):
            names.add(target.id)
    return names


def _definitions(body: list[ast.stmt]) -> Iterator[Definition]:
    """The classes and functions a module or class body defines, those under ``if``/``try``/``with`` too."""
    for node in body:
        if isinstance(node, (ast.FunctionDef, ast.AsyncFunctionDef, ast.ClassDef)):
            yield node
        elif isinstance(node, (ast.If, ast.Try, ast.With)):
            blocks = [node.body, getattr(node, "orelse", []), getattr(node, "finalbody", [])]
            blocks += [handler.body for handler in getattr(node, "handlers", [])]
            for block in blocks:
                yield from _definitions(block)


def _undocumented_in(body: list[ast.stmt], prefix: str) -> Iterator[tuple[int, str]]:
    for node in _definitions(body):
        name = f"{prefix}.{node.name}"
        if isinstance(node, ast.ClassDef):
            if not node.name.startswith("_") and not ast.get_docstring(node):
                yield node.lineno, name
            yield from _undocumented_in(node.body, name)
        elif not node.name.startswith("_") and not ast.get_docstring(node):
            if not _decorator_names(node) & {"overload", "setter", "deleter"}:
                yield node.lineno, name


def module_name(path: pathlib.Path) -> str:
    """``hlacore.omt`` for python/hlacore/omt/__init__.py, ``hlacore.rti`` for python/hlacore/rti.py."""
    parts = ("hlacore",) + path.relative_to(PACKAGE).with_suffix("").parts
    return ".".join(parts[:-1] if parts[-1] == "__init__" else parts)


def undocumented() -> list[str]:
    """Every public name of the package without a docstring, as ``path:line: name``."""
    found = []
    for path in sorted(PACKAGE.rglob("*.py")):
        tree = ast.parse(path.read_text(), str(path))
        where = path.relative_to(ROOT)
        name = module_name(path)
        if not ast.get_docstring(tree):
            found.append(f"{where}:1: {name} (module)")
        found.extend(f"{where}:{line}: {qualified}" for line, qualified in _undocumented_in(tree.body, name))
    return found


def test_every_public_name_has_a_docstring() -> None:
    """No module, public class, function, method or property of the package lacks a docstring."""
    missing = undocumented()
    assert not missing, f"{len(missing)} public names without a docstring:\n  " + "\n  ".join(missing)


def test_the_check_sees_methods_properties_and_nested_definitions() -> None:
    """The walk finds a private class's public method, a property, a definition under ``if`` and a nested
    class, and skips overloads, setters, private names and functions inside functions."""
    source = '''
class _Private:
    def pack(self): pass
    @property
    def size(self): pass
    @size.setter
    def size(self, value): pass
    def _hidden(self): pass
    class Inner:
        """Documented."""
        def method(self):
            """Documented."""
            def local(): pass
if True:
    def conditional(): pass
@overload
def declared(): ...
'''
    names = [name for _, name in _undocumented_in(ast.parse(source).body, "m")]
    assert names == ["m._Private.pack", "m._Private.size", "m.conditional"]


if __name__ == "__main__":
    print("\n".join(undocumented()))
    sys.exit(1 if undocumented() else 0)
