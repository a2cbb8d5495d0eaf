"""The test suite is shaped like the code: each test module sits in the directory of its layer
(tests/<layer>/test_*.py), and the modules share code only through tests/support, never by importing one
another or conftest (whose fixtures pytest hands out by name). The files are read with :mod:`ast`."""

from __future__ import annotations

import ast
import pathlib

from support import ROOT, TESTS

LAYERS = ("rti", "transport", "federates", "experiments", "system")
NOT_TESTS = ("data", "cpp")  # FED files, OMT files, PyHLA scripts; C++ sources


def suite_files() -> list[pathlib.Path]:
    """The Python files of the suite: test modules, conftest, tests/support and tests/peers."""
    return sorted(path for path in TESTS.rglob("*.py") if path.relative_to(TESTS).parts[0] not in NOT_TESTS)


def imported_test_modules(source: str, filename: str = "<source>") -> list[tuple[int, str]]:
    """(line, name) of each import in `source` of a test module (test_*) or of conftest, at any depth."""
    found = []
    for node in ast.walk(ast.parse(source, filename)):
        if isinstance(node, ast.Import):
            names = [alias.name for alias in node.names]
        elif isinstance(node, ast.ImportFrom):
            base = node.module or ""
            names = [base] + [f"{base}.{alias.name}" for alias in node.names]
        else:
            continue
        for name in names:
            if any(part.startswith("test_") or part == "conftest" for part in name.split(".") if part):
                found.append((node.lineno, "." * getattr(node, "level", 0) + name.strip(".")))
                break
    return found


def test_no_module_of_the_suite_imports_a_test_module_or_conftest() -> None:
    found = [f"{path.relative_to(ROOT)}:{line}: imports {name}"
             for path in suite_files() for line, name in imported_test_modules(path.read_text(), str(path))]
    assert not found, "share it through tests/support instead:\n" + "\n".join(found)


def test_the_check_sees_each_form_of_import() -> None:
    source = """
import test_a
import tests.rti.test_b as b
from test_c import helper
from tests.transport import test_d
from . import test_e
from conftest import Recorder

def inside():
    from test_f import g
"""
    assert [line for line, _ in imported_test_modules(source)] == [2, 3, 4, 5, 6, 7, 10]
    assert imported_test_modules("import support\nfrom support.wire import frame\nimport pytest\n") == []


def test_each_test_module_sits_in_a_layer_directory() -> None:
    modules = [path for path in suite_files() if path.name.startswith("test_")]
    misplaced = [str(path.relative_to(ROOT)) for path in modules if path.parent.parent != TESTS
                 or path.parent.name not in LAYERS]
    assert not misplaced, f"test modules outside tests/{{{','.join(LAYERS)}}}/: {misplaced}"
    assert {path.parent.name for path in modules} == set(LAYERS)
