"""scripts/source_digest.py: what decides whether the scripts rebuild hlacore (scripts/env.sh)."""

import pathlib
import shutil
import subprocess
import sys

from support import ROOT

DIGEST = ROOT / "scripts" / "source_digest.py"


def digest(root: pathlib.Path) -> str:
    return subprocess.run([sys.executable, str(DIGEST), str(root)], check=True, capture_output=True, text=True).stdout.strip()


def test_digest_follows_sources_and_ignores_build_products(tmp_path: pathlib.Path) -> None:
    for name in ("CMakeLists.txt", "pyproject.toml"):
        shutil.copy(ROOT / name, tmp_path / name)
    (tmp_path / "cpp").mkdir()
    (tmp_path / "cpp" / "a.cpp").write_text("int a;\n")
    (tmp_path / "python" / "hlacore").mkdir(parents=True)
    (tmp_path / "python" / "hlacore" / "m.py").write_text("x = 1\n")
    first = digest(tmp_path)
    assert digest(tmp_path) == first  # nothing changed: the scripts skip the build

    (tmp_path / "python" / "hlacore" / "__pycache__").mkdir()
    (tmp_path / "python" / "hlacore" / "__pycache__" / "m.cpython-311.pyc").write_bytes(b"\0")
    (tmp_path / "python" / "hlacore" / "_core.so").write_bytes(b"\0")
    assert digest(tmp_path) == first  # what a build or an import leaves does not count

    (tmp_path / "cpp" / "a.cpp").write_text("int a = 1;\n")
    edited = digest(tmp_path)
    assert edited != first
    (tmp_path / "cpp" / "b.hpp").write_text("")
    assert digest(tmp_path) != edited  # a new file counts, even empty
