"""python/hlacore/_core.pyi (the compiled module's type stub, scripts/stubs.sh) names everything the
module and its classes offer, so editors and type checkers see the whole API; regenerate it when this fails."""

from __future__ import annotations

import ast

from hlacore import _core

from support import ROOT

STUB = ROOT / "python" / "hlacore" / "_core.pyi"


def declared(body: list[ast.stmt]) -> set[str]:
    """The names a stub body declares: classes, functions, annotated names."""
    names = set()
    for node in body:
        if isinstance(node, (ast.ClassDef, ast.FunctionDef)):
            names.add(node.name)
        elif isinstance(node, ast.AnnAssign) and isinstance(node.target, ast.Name):
            names.add(node.target.id)
    return names


def stub_names() -> dict[str, set[str]]:
    """Module-level names (key "") and each class's members, as the stub declares them."""
    tree = ast.parse(STUB.read_text())
    names = {node.name: declared(node.body) for node in tree.body if isinstance(node, ast.ClassDef)}
    names[""] = declared(tree.body)
    return names


def public(names: list[str]) -> set[str]:
    """Without dunders and pybind11's own hooks."""
    return {n for n in names if not n.startswith("__") and not n.startswith("_pybind11")}


def test_the_stub_declares_every_name_of_the_module() -> None:
    assert sorted(public(dir(_core)) - stub_names()[""]) == []


def test_the_stub_declares_every_method_of_the_ambassador_and_the_gateway() -> None:
    stub = stub_names()
    for cls in (_core.RTIAmbassadorBase, _core.BackgroundGateway):
        assert sorted(public(list(vars(cls))) - stub[cls.__name__]) == [], cls.__name__
