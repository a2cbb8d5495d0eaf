"""The Python package is layered and free of import cycles (docs/architecture.md, the layers).

The test reads python/hlacore with :mod:`ast` (nothing is imported), builds the graph of imports between
its modules (relative imports resolved; module-level and function-level imports count, those under
``if TYPE_CHECKING:`` do not: they never run), and checks:

* no import cycle;
* no import from a lower layer to a higher one. Layers, lowest first:

  ====================  ==============================================================================
  core                  ``hlacore`` and every module or package directly in it but the two below
                        (rti, _core, fed, omt, gateway, aio, status, trace, exceptions, ...)
  federates             ``hlacore.federates.*``: the reusable federates; among them, lowest first,
                        de, robot_world < robot_driver, ros_bridge < testbench (same-rank packages
                        do not import each other)
  experiments           ``hlacore.experiments.*``: the papers' scenarios and runners
  ====================  ==============================================================================

The deprecated aliases at the old paths (modules that call ``hlacore._deprecated.moved``) are the only
modules allowed to point upward; nothing in the package may import one, so they carry no dependency and
go away in the next release. The last test imports each alias and runs each runnable one.
"""

from __future__ import annotations

import ast
import importlib
import pathlib
import subprocess
import sys
import warnings
from dataclasses import dataclass, field
from typing import Iterator, Optional

import pytest

from support import ROOT

PACKAGE = ROOT / "python" / "hlacore"

#: Rank of each federates package (higher may import lower, never the reverse or a sibling of equal rank).
FEDERATE_RANKS = {"de": 0, "robot_world": 0, "robot_driver": 1, "ros_bridge": 1, "testbench": 2}


@dataclass
class Module:
    """One module of the package as the test sees it."""

    name: str
    path: pathlib.Path
    is_package: bool
    imports: dict[str, int] = field(default_factory=dict)  # imported module -> first line
    moved_to: Optional[str] = None  # the new path, when this is a deprecated alias


def _modules() -> dict[str, Module]:
    found: dict[str, Module] = {}
    for path in sorted(PACKAGE.rglob("*.py")) + sorted(PACKAGE.rglob("*.pyi")):
        parts = ("hlacore",) + path.relative_to(PACKAGE).with_suffix("").parts
        is_package = parts[-1] == "__init__"
        name = ".".join(parts[:-1] if is_package else parts)
        if name not in found:  # a .py wins over its .pyi (_core has only the stub)
            found[name] = Module(name, path, is_package)
    return found


def _type_checking(test: ast.expr) -> bool:
    return (isinstance(test, ast.Name) and test.id == "TYPE_CHECKING") or (
        isinstance(test, ast.Attribute) and test.attr == "TYPE_CHECKING")


def _runtime_nodes(tree: ast.AST) -> Iterator[ast.AST]:
    """Every node of ``tree`` except the bodies of ``if TYPE_CHECKING:`` (their ``else`` runs)."""
    stack = [tree]
    while stack:
        node = stack.pop()
        yield node
        if isinstance(node, ast.If) and _type_checking(node.test):
            stack.extend(node.orelse)
            continue
        stack.extend(ast.iter_child_nodes(node))


def _resolve(module: Module, node: ast.ImportFrom) -> str:
    if node.level == 0:
        return node.module or ""
    base = module.name.split(".") if module.is_package else module.name.split(".")[:-1]
    base = base[: len(base) - (node.level - 1)]
    return ".".join(base + ([node.module] if node.module else []))


def _moved_to(node: ast.AST) -> Optional[str]:
    """The target of a ``moved(__name__, "new.path")`` call, else None."""
    if isinstance(node, ast.Call) and len(node.args) == 2 and isinstance(node.args[1], ast.Constant):
        func = node.func
        name = func.id if isinstance(func, ast.Name) else func.attr if isinstance(func, ast.Attribute) else ""
        if name == "moved" and isinstance(node.args[1].value, str):
            return node.args[1].value
    return None


def graph() -> dict[str, Module]:
    """The package's modules with their imports of other modules of the package."""
    modules = _modules()
    for module in modules.values():
        tree = ast.parse(module.path.read_text(), str(module.path))
        for node in _runtime_nodes(tree):
            targets: list[str] = []
            if isinstance(node, ast.Import):
                targets = [alias.name for alias in node.names]
            elif isinstance(node, ast.ImportFrom):
                source = _resolve(module, node)
                for alias in node.names:
                    # `from pkg import sub` imports the submodule; `from pkg import name` runs pkg/__init__.
                    targets.append(f"{source}.{alias.name}" if f"{source}.{alias.name}" in modules else source)
            elif _moved_to(node) is not None:
                module.moved_to = _moved_to(node)
            for target in targets:
                if target in modules and target != module.name:
                    module.imports.setdefault(target, getattr(node, "lineno", 0))
    return modules


def find_cycles(modules: dict[str, Module]) -> list[list[str]]:
    """One cycle (as a closed path) through each strongly connected group of modules (Tarjan)."""
    index: dict[str, int] = {}
    low: dict[str, int] = {}
    stack: list[str] = []
    on_stack: set[str] = set()
    groups: list[list[str]] = []

    def visit(name: str) -> None:
        index[name] = low[name] = len(index)
        stack.append(name)
        on_stack.add(name)
        for target in modules[name].imports:
            if target not in index:
                visit(target)
                low[name] = min(low[name], low[target])
            elif target in on_stack:
                low[name] = min(low[name], index[target])
        if low[name] == index[name]:
            group = []
            while True:
                member = stack.pop()
                on_stack.discard(member)
                group.append(member)
                if member == name:
                    break
            if len(group) > 1:
                groups.append(sorted(group))

    for name in sorted(modules):
        if name not in index:
            visit(name)
    return [_cycle_in(modules, set(group)) for group in groups]


def _cycle_in(modules: dict[str, Module], group: set[str]) -> list[str]:
    start = min(group)
    paths = {start: [start]}
    frontier = [start]
    while frontier:  # breadth first, so the cycle printed is a shortest one through `start`
        name = frontier.pop(0)
        for target in sorted(modules[name].imports):
            if target == start:
                return paths[name] + [start]
            if target in group and target not in paths:
                paths[target] = paths[name] + [target]
                frontier.append(target)
    raise AssertionError(f"no cycle through {start}")


def layer(name: str) -> tuple[int, int]:
    """(layer, rank within the layer) of a module: core 0, federates 1, experiments 2."""
    parts = name.split(".")
    if len(parts) > 1 and parts[1] == "experiments":
        return (2, 0)
    if len(parts) > 1 and parts[1] == "federates":
        return (1, FEDERATE_RANKS.get(parts[2], -1) if len(parts) > 2 else -1)
    return (0, 0)


def upward_imports(modules: dict[str, Module]) -> list[str]:
    """Each import of a higher layer (or of a same-rank sibling federates package), as a readable line."""
    found = []
    for module in modules.values():
        if module.moved_to is not None:
            continue
        for target, line in module.imports.items():
            (low_layer, low_rank), (high_layer, high_rank) = layer(module.name), layer(target)
            same_package = module.name.split(".")[:3] == target.split(".")[:3]
            upward = high_layer > low_layer or (
                high_layer == low_layer == 1 and not same_package and min(low_rank, high_rank) >= 0
                and high_rank >= low_rank)
            if upward:
                found.append(f"{module.path.relative_to(ROOT)}:{line}: {module.name} imports {target}")
    return sorted(found)


def test_no_import_cycle() -> None:
    cycles = find_cycles(graph())
    assert not cycles, "import cycles:\n" + "\n".join(" -> ".join(cycle) for cycle in cycles)


def test_nothing_imports_a_higher_layer() -> None:
    found = upward_imports(graph())
    assert not found, "imports from a lower layer to a higher one:\n" + "\n".join(found)


def test_the_graph_sees_relative_function_level_and_aliased_imports() -> None:
    modules = graph()
    assert "hlacore.rti" in modules["hlacore.aio"].imports  # from .rti import RTIAmbassador
    assert "hlacore._core" in modules["hlacore.rti"].imports  # from . import _core (the stub only)
    assert "hlacore.status" in modules["hlacore.gateway"].imports  # inside a method
    assert "hlacore.federates.de.director" not in modules["hlacore.federates.de.actor"].imports  # TYPE_CHECKING
    assert layer("hlacore.federates.ros_bridge.bridge") > layer("hlacore.federates.robot_world.world")
    assert find_cycles({"a": Module("a", PACKAGE, False, {"b": 1}), "b": Module("b", PACKAGE, False, {"a": 2})}) \
        == [["a", "b", "a"]]


def aliases() -> dict[str, str]:
    """The deprecated old paths and where each moved."""
    return {m.name: m.moved_to for m in graph().values() if m.moved_to is not None}


def test_nothing_in_the_package_imports_a_deprecated_alias() -> None:
    modules, old = graph(), aliases()
    assert old, "the old paths keep working for one release"
    for module in modules.values():
        assert not set(module.imports) & set(old), f"{module.name} imports a deprecated path"
    for new in old.values():
        assert new in modules or f"{new}.__main__" in modules, new


@pytest.mark.parametrize("old", sorted(aliases()))
def test_old_path_still_imports_and_warns(old: str) -> None:
    new = aliases()[old]
    with warnings.catch_warnings():  # a deprecated parent package warns for itself, in its own case; whichever
        warnings.simplefilter("ignore", DeprecationWarning)  # case ran before in this process, it is imported now
        importlib.import_module(old.rpartition(".")[0])
    saved = {name: sys.modules.pop(name) for name in list(sys.modules) if name == old or name.startswith(old + ".")}
    try:
        with pytest.warns(DeprecationWarning, match=new.removesuffix(".__main__").replace(".", r"\.")):
            module = importlib.import_module(old)
        if not module.__spec__ or module.__spec__.submodule_search_locations is None or module.__name__ != old:
            assert module is importlib.import_module(new)  # the very module, not a copy
    finally:
        for name in [name for name in sys.modules if name == old or name.startswith(old + ".")]:
            del sys.modules[name]
        sys.modules.update(saved)


RUNNABLE = ["hlacore.demo", "hlacore.federates.mirror", "hlacore.federates.robot_world.paper1_de",
            "hlacore.federates.robot_world.stage_node", "hlacore.federates.ros_bridge.paper1"]


@pytest.mark.parametrize("old", RUNNABLE)
def test_python_m_old_path_still_runs(old: str) -> None:
    done = subprocess.run([sys.executable, "-m", old, "--help"], capture_output=True, text=True, timeout=60,
                          stdin=subprocess.DEVNULL)
    assert done.returncode == 0, done.stdout + done.stderr
    assert "usage: python -m hlacore." in done.stdout and "DeprecationWarning" in done.stderr, done.stderr
